#![no_std]
#![deny(missing_docs)]
//! # exactray
//!
//! Geometric queries that are fast and right: exact orientation, in-circle,
//! in-sphere and plane-side predicates for **every** finite `f64` input
//! ([`predicates`]), an exact nearest-point index over a hierarchy of
//! bounding spheres ([`bvh`], with `alloc`), and a stable quadratic solver
//! ([`roots`]), with a measured speed-against-error report beside the crates
//! a user would otherwise pick (see the README).
//!
//! ```
//! use exactray::{orient3d, same_side, Sign, SideRelation};
//! use glam::DVec3;
//! let (x0, x1, x2) = (DVec3::ZERO, DVec3::X, DVec3::Y);
//! assert_eq!(orient3d(x0, x1, x2, DVec3::Z), Sign::Positive);
//! assert_eq!(same_side(x0, x1, x2, DVec3::Z, -DVec3::Z), SideRelation::Opposite);
//! ```
//!
//! Features: `std` (default; implies `alloc`), `rayon` (default; parallel
//! batch queries and builds of the index), `alloc` (the [`bvh`] module), `proptest`
//! (strategies for hard inputs, for users' property tests), `arbitrary`
//! (`Arbitrary` for the predicate input types, for users' fuzz targets).

#[cfg(feature = "alloc")]
extern crate alloc;
#[cfg(feature = "std")]
extern crate std;

#[cfg(feature = "alloc")]
pub mod bvh;
pub mod error;
mod extended;
mod float;
pub mod hard_inputs;
pub mod inputs;
pub mod point;
pub mod predicates;
pub mod query;
pub mod raster;
pub mod ray;
pub mod roots;
pub mod shape;
pub mod sign;
#[cfg(feature = "proptest")]
pub mod strategies;

#[cfg(feature = "alloc")]
pub use bvh::SphereBvh;
pub use error::InputError;
pub use point::{IntoDVec2, IntoDVec3};
pub use predicates::{
    SideRelation, incircle, insphere, orient2d, orient3d, same_side, side_of_plane, try_incircle,
    try_insphere, try_orient2d, try_orient3d, try_same_side, try_side_of_plane,
};
pub use sign::Sign;

// The README's examples are compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
