pub mod ray_cases;
