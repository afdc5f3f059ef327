//! Deterministic triangles to rasterize, shared by the benchmarks and the
//! speed-against-error report (question Q2 of `docs/pictures.md`): right isosceles
//! triangles of a given area in pixels, rotated at random and placed at a
//! random sub-pixel offset on a grid that holds them.
//!
//! ```
//! use exactray::raster::rasterize_triangle;
//! use exactray::testing::{RASTER_AREAS, SplitMix64, raster_triangle_case};
//! let mut rng = SplitMix64::new(7);
//! let c = raster_triangle_case(&mut rng, RASTER_AREAS[1]);
//! let [a, b, d] = c.vertices;
//! let pixels = rasterize_triangle(a, b, d, c.width, c.height, |_, _, _| {}).unwrap();
//! assert!(pixels.abs_diff(128) < 40);
//! ```

use super::generators::SplitMix64;
use crate::arith::std_or_libm::{cos, sin, sqrt};
use glam::DVec2;

/// One triangle on a grid that holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterTriangle {
    /// The vertices, in pixel coordinates.
    pub vertices: [DVec2; 3],
    /// The grid's width in pixels: one pixel more than the bounding box
    /// needs on each side.
    pub width: u32,
    /// The grid's height in pixels, likewise.
    pub height: u32,
}

/// The triangles' areas in pixels that the report and benchmarks measure.
pub const RASTER_AREAS: [u32; 6] = [8, 128, 2048, 8192, 32768, 100352];

/// A right isosceles triangle of `area` pixels (legs `sqrt(2 area)`),
/// rotated at random, its bounding box shifted to start within `(1, 2)`.
pub fn raster_triangle_case(rng: &mut SplitMix64, area: u32) -> RasterTriangle {
    let leg = sqrt(2.0 * area as f64);
    let angle = rng.next_f64() * core::f64::consts::TAU;
    let (s, c) = (sin(angle), cos(angle));
    let e1 = DVec2::new(c, s) * leg;
    let e2 = DVec2::new(-s, c) * leg;
    let origin = DVec2::new(rng.next_f64(), rng.next_f64());
    let v = [origin, origin + e1, origin + e2];
    // On the grid: the bounding box shifted to start within (1, 2), and a
    // grid one pixel larger than it on each side.
    let shift = DVec2::ONE - v[0].min(v[1]).min(v[2]).floor();
    let v = v.map(|p| p + shift);
    let hi = v[0].max(v[1]).max(v[2]).ceil() + 1.0;
    RasterTriangle {
        vertices: v,
        width: hi.x as u32,
        height: hi.y as u32,
    }
}
