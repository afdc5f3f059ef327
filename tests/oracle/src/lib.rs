//! The exact oracle of exactray's tests, fuzz targets and report: answers
//! in big integers and dyadics, independent of the crate's arithmetic, that
//! the crate's answers are checked against.
//!
//! - [`oracle`]: predicate signs, distance orderings and nearest points,
//!   polynomial and discriminant signs, the exact line–triangle crossing.
//! - [`line_oracle`]: lines against spheres, cylinders, cones and general
//!   quadrics: the exact root count and correctly rounded roots.
//! - [`implicit_oracle`]: predicates on constructed points (line–plane,
//!   three-plane and line–line intersections) as exact rational points.
//! - [`closest_oracle`]: the triangles of a mesh nearest to a point, by
//!   brute force with exact squared distances.
//! - [`mesh_oracle`]: rays and segments against triangle meshes by brute
//!   force (`docs/fixture-format.md`'s `ray_mesh` rule: closed triangles, a ray in a
//!   triangle's plane entering it).
//!
//! A workspace member of its own (`publish = false`), so that every user
//! depends on it by name.

pub mod closest_oracle;
pub mod implicit_oracle;
pub mod line_oracle;
pub mod mesh_oracle;
pub mod oracle;
