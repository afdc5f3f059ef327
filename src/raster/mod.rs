//! Rasterization: one 2D triangle by edge functions, with pixel-centre
//! coverage decided exactly and a top-left fill rule
//! ([`rasterize_triangle`]); and triangles in homogeneous clip space,
//! clipped before the divide ([`clip_triangle`]) and rasterized into
//! Z-buffer fragments with depth and perspective-correct weights
//! ([`rasterize_clipped`], [`rasterize_clip_space`]).
//!
//! # Clip space
//! A clip-space point `(x, y, z, w)` is what a projection matrix makes of
//! a view-space point, in the convention of glam's depth-0-to-1
//! perspective matrices: the former `DMat4::perspective_rh` and
//! `DMat4::perspective_lh` (since glam 0.34,
//! `glam::dcamera::rh::proj::directx::perspective` and
//! `glam::dcamera::lh::proj::directx::perspective`; right- and left-handed
//! view spaces, the same clip space). A point is visible when `0 <= z <=
//! w` (near plane `z = 0`, far plane `z = w`) and `-w <= x <= w`, `-w <= y
//! <= w`. For those matrices `w` is the distance in front of the eye along
//! the view axis and `z = 0` exactly where `w = near > 0`, so the near
//! plane alone keeps the part of a triangle the divide by `w` can
//! project; a vertex behind the eye has `w < 0`. Projecting such a
//! triangle without clipping wraps it through infinity, and the
//! rasterized 2D triangle covers pixels the true triangle does not.
//!
//! [`to_screen`] maps clip space to the pixels of [`rasterize_triangle`]:
//! `x_s = (x / w * 0.5 + 0.5) * width`, `y_s = (0.5 - y / w * 0.5) *
//! height` (`y` flipped: screen `y` grows downwards), depth `z / w` (0 near,
//! 1 far).
//!
//! # Clipping
//! Sutherland–Hodgman against the near plane or all six. A vertex is
//! inside a plane when the plane's function (`z`, `w - z`, `w + x`, `w -
//! x`, `w + y`, `w - y`) as computed is `>= 0`, so a vertex on a plane is
//! inside; the sign of that rounded value is the exact sign. An edge is cut
//! from its endpoints in a canonical order (their positions' bit
//! patterns), so triangles sharing an edge get bit-identical cut points on
//! it through every plane, and their fragments cover each pixel once.
//!
//! # 2D coverage
//! - Pixel `(x, y)` is the unit square `[x, x + 1) x [y, y + 1)`; it is
//!   covered when its centre `(x + 0.5, y + 0.5)` is. `x` grows to the
//!   right and `y` downwards (screen coordinates), and only pixels with
//!   `x < width` and `y < height` are visited (a clip; vertices may lie
//!   anywhere).
//! - A centre strictly inside the triangle is covered; one outside is not;
//!   one on an edge is covered only when the edge is a **top** edge (exactly
//!   horizontal, with the triangle below it) or a **left** edge (the
//!   triangle to its right), as in Direct3D and Vulkan. A centre on a vertex
//!   is covered only when both edges through it are top or left. Two
//!   triangles sharing an edge, and a mesh tiling a region, so cover each
//!   pixel centre of the region exactly once.
//! - The vertices may come in either order; a degenerate (collinear)
//!   triangle covers nothing.
//!
//! # Exactness
//! Each edge function `(b - a) x (p - a)` is stepped incrementally over the
//! triangle's bounding box in `f64`: one addition per row, and along a row
//! its value at the `k`-th centre is the row's value plus `k` steps. A
//! bound covers the error all this stepping can accumulate; a centre whose
//! value lies within the bound of zero is decided by the exact
//! [`orient2d`] on the original coordinates. So coverage is exact for every
//! finite input: centres exactly on an edge get the fill rule, never a
//! rounding.
//!
//! # Cost
//! Along a row an edge function is monotone, so each edge covers a prefix
//! or a suffix of the row: its end is read off the stepped values (where
//! the function crosses zero) and confirmed pixel by pixel, exactly where
//! the bound requires. A triangle costs a few operations per row, not per
//! pixel, and no allocation: covered pixels are reported one span per row
//! to a callback, which fills them as it likes.

mod clip;
mod fragments;

pub use clip::{ClipPlanes, ClipVertex, ClippedPolygon, clip_triangle};
pub use fragments::{Fragment, rasterize_clip_space, rasterize_clipped, to_screen};

use crate::arith::roundoff::{U, gamma};
use crate::error::InputError;
use crate::point::IntoDVec2;
use crate::predicates::{check_finite2, orient2d};
use crate::sign::Sign;
use glam::DVec2;

/// One edge `a -> b` of a triangle whose interior lies to the left of
/// `b - a` (positive [`orient2d`]), with its function stepped over pixels.
#[derive(Clone, Copy, Debug)]
struct Edge {
    a: DVec2,
    b: DVec2,
    /// The change of the function per pixel to the right and per row down.
    step_x: f64,
    step_y: f64,
    /// Whether a centre exactly on the edge is covered: a top or left edge.
    owns: bool,
}

impl Edge {
    fn new(a: DVec2, b: DVec2) -> Edge {
        let d = b - a;
        // y grows downwards. With the interior on the left of `d` (in the
        // usual y-up sense of orient2d), an edge going up the screen (d.y
        // < 0) has the interior to its right: a left edge; a horizontal
        // edge going right has the interior below it: a top edge. The
        // rule is antisymmetric, so the reversed edge of a neighbour never
        // owns what this one owns.
        let owns = d.y < 0.0 || (d.y == 0.0 && d.x > 0.0);
        Edge {
            a,
            b,
            step_x: a.y - b.y,
            step_y: b.x - a.x,
            owns,
        }
    }

    /// The function at `p`, rounded: `(b - a) x (p - a)`.
    #[inline]
    fn at(&self, p: DVec2) -> f64 {
        let (d, q) = (self.b - self.a, p - self.a);
        d.x * q.y - d.y * q.x
    }

    /// Whether the centre `p` is covered by this edge's half-plane, exactly.
    #[inline]
    fn covers_exactly(&self, p: DVec2) -> bool {
        match orient2d(self.a, self.b, p) {
            Sign::Positive => true,
            Sign::Zero => self.owns,
            Sign::Negative => false,
        }
    }
}

/// The error bound of each edge function's stepped value, for every
/// centre of the box from `corner` to `far` (`steps` rows and columns).
///
/// The function at the first centre is within gamma(4) of its
/// permanent-like magnitude `|d| . |p - a|` (two differences, two
/// products, one difference); each of at most `y1 - y0` row steps adds `u`
/// times a value at most `max` (the largest of `|E|` at the box's corners:
/// E is affine) plus the step's own rounding error, `u |step|`; `row + k *
/// step_x` adds `k u |step_x|` (the step's rounding, `k` times), `u k
/// |step_x|` (the product) and `u max` (the sum). `4u` per step of `steps`
/// and a factor 2 cover all of it, second-order terms and the rounding of
/// the bound.
fn edge_bounds(edges: &[Edge; 3], corner: DVec2, far: DVec2, steps: f64) -> [f64; 3] {
    edges.map(|e| {
        let corners = [
            corner,
            far,
            DVec2::new(corner.x, far.y),
            DVec2::new(far.x, corner.y),
        ];
        let max = corners.iter().map(|&p| e.at(p).abs()).fold(0.0, f64::max);
        let d = (e.b - e.a).abs();
        let q = (corner - e.a).abs();
        // Two rounded differences, their product and the final difference:
        // four roundings on each product's path (Higham, Lemma 3.1).
        let direct = gamma(4) * (d.x * q.y + d.y * q.x);
        let stepping = 4.0 * U * steps * (max + e.step_x.abs() + e.step_y.abs());
        2.0 * (direct + stepping)
    })
}

/// The part `[from, to)` of a row of `n` centres that also lies inside one
/// edge, `covers(k)` its exact answer for the `k`-th centre, `row` its
/// stepped value at the row's first centre and `slope` its step along the
/// row. Along a row an edge function is monotone, so the edge's run is a
/// prefix or a suffix of the row (all or nothing for a horizontal edge):
/// its end is found from the crossing the stepped value predicts, then
/// moved a pixel at a time while the exact answer says so.
#[inline(always)]
fn edge_run(
    slope: f64,
    row: f64,
    usable: bool,
    (from, to, n): (u32, u32, u32),
    covers: impl Fn(u32) -> bool,
) -> (u32, u32) {
    if slope == 0.0 || !usable {
        // Horizontal (or too large to predict): scan the row.
        let k = (from..to).find(|&k| covers(k)).unwrap_or(to);
        let end = (k..to).find(|&k| !covers(k)).unwrap_or(to);
        return (k, end);
    }
    let guess = (-row / slope).clamp(-1.0, n as f64 + 1.0);
    let mut k = guess.max(0.0).min(n as f64) as u32;
    if slope > 0.0 {
        // A suffix: its first pixel.
        while k > 0 && covers(k - 1) {
            k -= 1;
        }
        while k < n && !covers(k) {
            k += 1;
        }
        (from.max(k), to)
    } else {
        // A prefix: one past its last pixel.
        while k < n && covers(k) {
            k += 1;
        }
        while k > 0 && !covers(k - 1) {
            k -= 1;
        }
        (from, to.min(k))
    }
}

/// Rasterizes the triangle `v0, v1, v2` into a `width` x `height` pixel
/// grid: calls `span(y, x_start, x_end)` for each row `y` with covered
/// pixels `x_start..x_end` (one span per row: a triangle's row is convex),
/// rows in increasing `y`. Returns the number of covered pixels.
///
/// Errors: [`InputError::NonFinite`] naming `"v0"`, `"v1"` or `"v2"`.
///
/// ```
/// use exactray::raster::rasterize_triangle;
/// // The two halves of a 4 x 4 square, split along its diagonal: every
/// // pixel once, the diagonal's centres to one half only.
/// let (a, b, c, d) = ([0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]);
/// let mut counts = [[0u8; 4]; 4];
/// for tri in [[a, b, c], [a, c, d]] {
///     rasterize_triangle(tri[0], tri[1], tri[2], 4, 4, |y, x0, x1| {
///         (x0..x1).for_each(|x| counts[y as usize][x as usize] += 1)
///     })
///     .unwrap();
/// }
/// assert_eq!(counts, [[1; 4]; 4]);
/// // A clip: only the visible part is reported.
/// let n = rasterize_triangle([-10.0, -10.0], [12.5, -10.0], [-10.0, 12.5], 2, 2, |_, _, _| {});
/// assert_eq!(n, Ok(3));
/// ```
pub fn rasterize_triangle(
    v0: impl IntoDVec2,
    v1: impl IntoDVec2,
    v2: impl IntoDVec2,
    width: u32,
    height: u32,
    mut span: impl FnMut(u32, u32, u32),
) -> Result<u64, InputError> {
    let (v0, v1, v2) = (v0.into_dvec2(), v1.into_dvec2(), v2.into_dvec2());
    check_finite2(&[("v0", v0), ("v1", v1), ("v2", v2)])?;
    let (v1, v2) = match orient2d(v0, v1, v2) {
        Sign::Positive => (v1, v2),
        Sign::Negative => (v2, v1),
        Sign::Zero => return Ok(0),
    };
    // The pixels whose centres the bounding box can hold, clipped.
    let lo = v0.min(v1).min(v2);
    let hi = v0.max(v1).max(v2);
    // libm: `f64::ceil` and `floor` need `std`.
    let first = |v: f64, n: u32| libm::ceil(v - 0.5).clamp(0.0, n as f64) as u32;
    let last = |v: f64, n: u32| (libm::floor(v - 0.5) + 1.0).clamp(0.0, n as f64) as u32;
    let (x0, x1) = (first(lo.x, width), last(hi.x, width));
    let (y0, y1) = (first(lo.y, height), last(hi.y, height));
    if x0 >= x1 || y0 >= y1 {
        return Ok(0);
    }
    let edges = [Edge::new(v1, v2), Edge::new(v2, v0), Edge::new(v0, v1)];
    let corner = DVec2::new(x0 as f64 + 0.5, y0 as f64 + 0.5);
    let far = DVec2::new(x1 as f64 - 0.5, y1 as f64 - 0.5);
    let steps = (x1 - x0) as f64 + (y1 - y0) as f64;
    let bound = edge_bounds(&edges, corner, far, steps);
    // Values too large for f64 (vertices near the largest floats): every
    // centre goes to the exact test.
    let usable = bound.iter().all(|b| b.is_finite());
    let n = x1 - x0;
    let mut row = edges.map(|e| e.at(corner));
    let mut covered = 0;
    for y in y0..y1 {
        let py = y as f64 + 0.5;
        // Whether edge `i` covers the `k`-th centre of the row: the stepped
        // value where its bound certifies the sign, else the exact test.
        let covers = |i: usize, k: u32| {
            let value = row[i] + k as f64 * edges[i].step_x;
            if usable && value > bound[i] {
                true
            } else if usable && value < -bound[i] {
                false
            } else {
                edges[i].covers_exactly(DVec2::new((x0 + k) as f64 + 0.5, py))
            }
        };
        // The row's span is the intersection of the three edges' runs.
        let (mut from, mut to) = (0, n);
        for i in 0..3 {
            (from, to) = edge_run(edges[i].step_x, row[i], usable, (from, to, n), |k| {
                covers(i, k)
            });
            if from >= to {
                break;
            }
        }
        if from < to {
            span(y, x0 + from, x0 + to);
            covered += (to - from) as u64;
        }
        for i in 0..3 {
            row[i] += edges[i].step_y;
        }
    }
    Ok(covered)
}
