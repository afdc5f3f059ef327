pub mod line_oracle;
pub mod oracle;
pub mod ray_cases;
