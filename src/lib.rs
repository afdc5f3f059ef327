#![no_std]
#![deny(missing_docs)]
#![cfg_attr(docsrs, feature(doc_cfg))]
//! # exactray
//!
//! Geometric queries that are fast and right: every answer that can be
//! exact is exact, and every floating-point answer carries a certified
//! error. By floor, lowest first (ARCHITECTURE.md):
//!
//! - [`predicates`]: exact orientation, in-circle, in-sphere, plane-side
//!   and distance-comparison signs for **every** finite `f64` input;
//!   [`roots`]: real roots of quadratics, each within 4 ulps;
//!   [`interval`]: the parameter intervals of rays.
//! - [`shape`]: spheres, cylinders, cones, quadrics, planes, disks and
//!   triangles, validated at construction.
//! - [`query::ray`]: rays and where they meet each shape ([`RayCast`]),
//!   with exact hit or miss where the shape allows it; [`raster`]: 2D
//!   triangle rasterization with exact pixel coverage, and clip-space
//!   triangles clipped before the divide into Z-buffer fragments.
//! - [`bvh`] (with `alloc`): an exact nearest-point index over a hierarchy
//!   of bounding spheres.
//! - [`scene`] (with `alloc`): triangle meshes over a conservative BVH,
//!   and scenes of meshes and analytic shapes over a two-level one:
//!   closest hits, shadow rays, batches of both, secondary rays that never
//!   hit their own surface, reflections that stay above it; a mesh's
//!   closest point to a query point, its triangle chosen exactly.
//! - `testing` (with the `testing` feature): hard inputs, proptest
//!   strategies and `Arbitrary` input types for users' own tests;
//!   [`prelude`]: the vocabulary in one `use`.
//!
//! # Exact variants
//! The predicates are always exact. Ray casts come in a default tier and
//! an exact one, both in the [`prelude`]:
//!
//! - Triangles: [`Triangle::cast`](shape::Triangle), and the plain
//!   `closest_hit` of meshes and scenes, use the watertight test
//!   ([`Watertight`](query::ray::Watertight)): a ray through a shared edge
//!   never slips between its two triangles, but a ray within a few ulps
//!   of an edge may get a different answer than the exact one. The exact
//!   hit or miss is [`Exact`](query::ray::Exact) (`closest_hit_with::<Exact>`
//!   on a mesh or scene), [`Triangle::cast_exact`](shape::Triangle::cast_exact),
//!   and [`ExactRay`](query::ray::ExactRay) for one ray against many
//!   triangles.
//! - Quadrics (spheres, cylinders, cones, general quadrics): `cast`
//!   decides hit or miss exactly and bounds the root's error a priori;
//!   [`Precise`](query::ray::Precise) gives the same hits with every root
//!   within 4 ulps.
//!
//! A speed-against-error report measures all of it beside the crates a
//! user would otherwise pick (see the README).
//!
//! ```
//! use exactray::prelude::*;
//! use exactray::glam::DVec3; // the glam the API takes
//! let (x0, x1, x2) = (DVec3::ZERO, DVec3::X, DVec3::Y);
//! assert_eq!(orient3d(x0, x1, x2, DVec3::Z), Sign::Positive);
//! assert_eq!(same_side(x0, x1, x2, DVec3::Z, -DVec3::Z), SideRelation::Opposite);
//! let tri = Triangle::new(x0, x1, x2).unwrap();
//! let ray = Ray::new([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]).unwrap();
//! assert_eq!(tri.cast_exact(&ray, Interval::FORWARD).unwrap().t, 1.0);
//! ```
//!
//! Features: `std` (default; implies `alloc`), `rayon` (default; parallel
//! batch queries and builds of the index), `alloc` (the [`bvh`] and
//! [`scene`] modules), `ploc` (obvhs's PLOC builder for meshes, beside
//! the default binned SAH one), `testing` (the `testing` module's hard
//! inputs and generators, for test suites), `proptest` (its strategies;
//! implies `testing`), `arbitrary` (`Arbitrary` for its input types, for
//! fuzz targets; implies `testing`), `serde` (`Serialize` and `Deserialize` for shapes, rays,
//! intervals, hits, signs and meshes; types with invariants deserialize
//! through their validating constructors), `mint` (mint's points and
//! vectors accepted wherever glam's are).
//!
//! [`RayCast`]: query::ray::RayCast

#[cfg(feature = "alloc")]
extern crate alloc;

/// `Serialize` and `Deserialize` (with the `serde` feature) for a type with
/// invariants, as the arguments of its validating constructor: `parts`
/// gives them from a value, `build` makes the value from them, so data
/// that the constructor rejects is a deserialization error carrying its
/// [`InputError`], never an invalid value.
macro_rules! serde_by_constructor {
    (
        $ty:ident as $name:literal { $($field:ident: $fty:ty),* $(,)? },
        parts: |$this:ident| $parts:expr,
        build: |$data:ident| $build:expr $(,)?
    ) => {
        #[cfg(feature = "serde")]
        impl serde::Serialize for $ty {
            fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                #[derive(serde::Serialize)]
                #[serde(rename = $name)]
                struct Data {
                    $($field: $fty),*
                }
                let $this = self;
                #[allow(unused_parens, reason = "one field is a parenthesized pattern")]
                let ($($field),*) = $parts;
                Data { $($field),* }.serialize(serializer)
            }
        }

        #[cfg(feature = "serde")]
        impl<'de> serde::Deserialize<'de> for $ty {
            fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                #[derive(serde::Deserialize)]
                #[serde(rename = $name, deny_unknown_fields)]
                struct Data {
                    $($field: $fty),*
                }
                let $data = Data::deserialize(deserializer)?;
                $build.map_err(serde::de::Error::custom)
            }
        }
    };
}
#[cfg(feature = "std")]
extern crate std;

mod arith;
#[cfg(feature = "alloc")]
pub mod bvh;
mod error;
pub mod interval;
mod point;
pub mod predicates;
pub mod prelude;
pub mod query;
pub mod raster;
pub mod roots;
#[cfg(feature = "alloc")]
pub mod scene;
pub mod shape;
mod sign;
#[cfg(any(test, feature = "testing"))]
#[cfg_attr(docsrs, doc(cfg(feature = "testing")))]
pub mod testing;

/// The vector crate of the public API, re-exported: `exactray::glam` is
/// the glam version exactray was built with (0.34), so `DVec2` and `DVec3`
/// values made through it are always the ones the API takes, whatever
/// glam version the rest of a project depends on.
pub use glam;

pub use error::InputError;
pub use point::{IntoDVec2, IntoDVec3};
pub use sign::Sign;

// The examples of the README and of the guide and pictures pages are
// compiled and run as doctests, so that they stay true.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

#[cfg(doctest)]
#[doc = include_str!("../docs/guide.md")]
struct GuideDoctests;

#[cfg(doctest)]
#[doc = include_str!("../docs/pictures.md")]
struct PicturesDoctests;
