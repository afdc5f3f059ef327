//! Queries, by what is asked: [`ray`] casts a ray against a shape.
pub mod ray;
