//! The crate's vocabulary in one `use`: `use exactray::prelude::*;`.
//!
//! Every item here has one other path, its home module; nothing else
//! re-exports it.
//!
//! The exact variants are here beside the defaults: [`Exact`] (the exact
//! ray–triangle test, for [`TriangleMesh::closest_hit_with`] and
//! [`Scene::closest_hit_with`], whose plain `closest_hit` uses
//! [`Watertight`]), [`ExactRay`] (a ray prepared once for exact tests
//! against many triangles) and [`Precise`] (quadric casts whose roots are
//! within 4 ulps).
//!
//! ```
//! use exactray::prelude::*;
//! let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
//! let ray = Ray::new([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]).unwrap();
//! assert_eq!(tri.cast(&ray, Interval::FORWARD).unwrap().t, 1.0);
//! assert_eq!(tri.cast_exact(&ray, Interval::FORWARD).unwrap().t, 1.0);
//! assert_eq!(ExactRay::new(&ray).cast(&tri, Interval::FORWARD).unwrap().t, 1.0);
//! assert_eq!(orient2d([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]), Sign::Positive);
//! ```
//!
//! [`TriangleMesh::closest_hit_with`]: crate::scene::TriangleMesh::closest_hit_with
//! [`Scene::closest_hit_with`]: crate::scene::Scene::closest_hit_with

#[cfg(feature = "alloc")]
pub use crate::bvh::SphereBvh;
pub use crate::interval::Interval;
pub use crate::predicates::{
    SideRelation, compare_distance, incircle, insphere, orient2d, orient3d, same_side,
    side_of_plane, try_incircle, try_insphere, try_orient2d, try_orient3d, try_same_side,
    try_side_of_plane,
};
pub use crate::query::ray::{
    Exact, ExactRay, Hit, LineRoots, Precise, Ray, RayCast, TriangleHit, Watertight,
};
pub use crate::roots::{Roots, solve_quadratic, try_solve_quadratic};
#[cfg(feature = "alloc")]
pub use crate::scene::{
    BatchQueries, MeshHit, PrimitiveId, Scene, SceneBuilder, SceneHit, TriangleMesh, spawn_ray,
    spawn_ray_to,
};
pub use crate::shape::{
    Aabb, Bounded, CappedCylinder, Cone, Cylinder, Disk, Plane, Quadric, Sphere, Triangle,
};
pub use crate::{InputError, IntoDVec2, IntoDVec3, Sign};
