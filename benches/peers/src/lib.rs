//! What exactray's speed-against-error report and its criterion benchmarks
//! (both in `exactray-bench`, `benches/`) measure besides exactray's own
//! calls, in one copy: the textbook `f64` formulas (`naive`), the peer
//! crates' calls in exactray's sign conventions, and the per-pixel ray
//! cast of the rasterizing family. A workspace member of its own
//! (`publish = false`). Every function is `#[inline]`, so that it inlines
//! into the callers' timed loops as a closure written there would.
//!
//! - [`signs`]: the predicates' signs, textbook and by the `robust` crate;
//! - [`raster`]: the textbook rasterizer and one ray per pixel;
//! - [`nearest`]: building and querying `kiddo`'s and `rstar`'s indexes;
//! - [`scene`]: obvhs's and parry3d's ray casts over a triangle mesh;
//! - [`delaunay`]: spade's Delaunay triangulation.

// `apfp_signum!` expands the in-sphere determinant by recursive macros.
#![recursion_limit = "512"]

pub mod delaunay;
pub mod nearest;
pub mod raster;
pub mod scene;
#[cfg(feature = "embree")]
pub mod scene_embree;
pub mod signs;
