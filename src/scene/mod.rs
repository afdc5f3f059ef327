//! Ray queries over triangle meshes (with `alloc`): [`TriangleMesh`], its
//! closest hit ([`MeshHit`]) and shadow-ray queries over a bounding-volume
//! hierarchy, every crossing of a ray in exact order
//! ([`TriangleMesh::all_hits`]) and the exact side of a point against a
//! closed mesh ([`TriangleMesh::side`]); a [`Scene`] of meshes and analytic shapes, each with its
//! [`PrimitiveId`], under a two-level hierarchy ([`SceneBuilder`],
//! [`SceneHit`]; [`Scene`] says what its queries decide); batch
//! forms of both, in parallel with rayon ([`BatchQueries`]); secondary
//! rays that leave a surface without hitting it again ([`spawn_ray`],
//! [`spawn_ray_to`]), and reflections about shading normals that stay
//! above the geometric surface ([`reflect_above`]).
//!
//! ```
//! use exactray::prelude::*;
//! use exactray::scene::{TriangleMesh, spawn_ray};
//! // The unit square at z = 0, two triangles.
//! let vertices = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
//! let mesh = TriangleMesh::new(&vertices, &[[0, 1, 2], [0, 2, 3]]).unwrap();
//! let ray = Ray::new([0.25, 0.5, 1.0], [0.0, 0.0, -1.0]).unwrap();
//! let hit = mesh.closest_hit(&ray, Interval::FORWARD).unwrap();
//! assert_eq!((hit.triangle, hit.hit.t), (1, 1.0));
//! // A ray spawned back up never meets the square again.
//! let up = spawn_ray(&hit.hit, [0.3, 0.1, 1.0]).unwrap();
//! assert!(!mesh.occluded(&up, Interval::FORWARD));
//! ```
//!
//! [`TriangleMesh`] (`mesh.rs`) says what its queries decide; [`Scene`]
//! (`primitives.rs`) says what a scene's do. Both walk the box hierarchy
//! of [`crate::bvh::boxes`].

mod batch;
mod closest;
mod crossings;
mod mesh;
mod primitives;
mod shading;
mod spawn;
mod topology;

pub use batch::BatchQueries;
pub use closest::ClosestPoint;
pub use crossings::{HitCount, MeshCrossings, MeshSide};
pub use mesh::{MAX_TRIANGLES, MeshHit, TraceStats, TriangleMesh};
pub use primitives::{
    AnalyticShape, MAX_PRIMITIVES, Primitive, PrimitiveId, Scene, SceneBuilder, SceneHit,
    TrianglePoint,
};
pub use shading::{reflect, reflect_above};
pub use spawn::{spawn_ray, spawn_ray_to};
