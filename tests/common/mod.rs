pub mod oracle;
pub mod ray_cases;
