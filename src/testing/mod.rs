//! Hard inputs for tests, benchmarks and fuzz targets: the crate's own and
//! its users'. One door for four kinds of thing:
//!
//! - deterministic generators of uniform, near-degenerate, degenerate,
//!   tiny, huge and mixed-magnitude cases ([`InputClass`], [`SplitMix64`],
//!   [`orient2d_case`], ...), the same on every platform for a seed;
//! - deterministic hard rays: against one triangle ([`ray_triangle_case`]),
//!   at the shared edges of a tiled mesh (`TiledMesh`, with `alloc`), and
//!   against spheres, cylinders, cones and quadrics ([`sphere_ray_case`],
//!   ...); point sets and queries for nearest-point searches
//!   ([`nearest_points`]); planar point sets for triangulations, uniform,
//!   a cocircular grid and extreme magnitudes ([`plane_points`]);
//!   triangles to rasterize
//!   ([`raster_triangle_case`]); small scenes of meshes and every analytic
//!   shape, rays for them and secondary rays spawned from their hits
//!   (`random_scene`, `scene_ray`, `spawned_ray`, with `alloc`); large
//!   generated meshes for scene benchmarks, a displaced sphere, a terrain
//!   and a room, with camera rays (`displaced_sphere`, `terrain`, `room`,
//!   `camera_rays`, with `alloc`);
//! - one predicate call as a struct ([`Orient2dInput`], ...), with
//!   `arbitrary::Arbitrary` under the `arbitrary` feature, every coordinate
//!   a finite `f64` from a raw bit pattern ([`finite_f64_from_bits`]);
//! - proptest strategies over both (`orient2d_inputs`, `finite_dvec3`,
//!   `small_scenes`, `spawned_rays`, ...) under the `proptest` feature.
//!
//! The ray, point-set and raster generators also call `pow`, `ln`, `cbrt`,
//! `sin` or `cos`: `std`'s (the platform's) with the `std` feature,
//! `libm`'s without it. Those need not round alike, so for those
//! generators a seed names the same cases wherever those functions agree
//! (every `std` build on one platform), and may differ in the last bit
//! elsewhere.
//!
//! On the side of the floors: nothing in the library's queries imports it.
//!
//! ```
//! use exactray::prelude::*;
//! use exactray::testing::{orient3d_case, InputClass, SplitMix64};
//! let mut rng = SplitMix64::new(7);
//! for class in InputClass::ALL {
//!     let [a, b, c, d] = orient3d_case(class, &mut rng);
//!     let _ = orient3d(a, b, c, d);
//! }
//! ```

mod cases;
mod generators;
mod implicit;
#[cfg(feature = "alloc")]
mod meshes;
mod pixels;
mod plane_points;
mod points;
mod rays;
#[cfg(feature = "alloc")]
mod scenes;
#[cfg(feature = "proptest")]
mod strategies;

pub use cases::*;
pub use generators::*;
pub use implicit::*;
#[cfg(feature = "alloc")]
pub use meshes::*;
pub use pixels::*;
pub use plane_points::*;
pub use points::*;
pub use rays::*;
#[cfg(feature = "alloc")]
pub use scenes::*;
#[cfg(feature = "proptest")]
pub use strategies::*;
