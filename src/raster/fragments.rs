//! Z-buffer fragments of a clipped triangle: exact pixel coverage of its
//! projection, with depth and perspective-correct barycentric weights at
//! each covered pixel centre.
//!
//! # Conventions
//! Screen space is [`rasterize_triangle`]'s: `x` to the right, `y`
//! downwards, pixel `(x, y)` covered when its centre `(x + 0.5, y + 0.5)`
//! is (with the top-left rule on edges). [`to_screen`] maps clip space to
//! it, `y` flipped (clip space has `y` up): normalized device coordinates
//! `(-1, 1)` land on the top-left corner `(0, 0)`, `(1, -1)` on
//! `(width, height)`. Depth is `z / w`: 0 on the near plane, 1 on the far
//! one.
//!
//! Interpolation and error: [`rasterize_clipped`].

use super::clip::{ClipPlanes, ClipVertex, ClippedPolygon, clip_triangle};
use super::rasterize_triangle;
use crate::error::InputError;
use crate::predicates::orient2d;
use crate::sign::Sign;
use glam::{DVec2, DVec3, DVec4};

/// One covered pixel of a triangle, for a Z-buffer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// The pixel's column, `< width`.
    pub x: u32,
    /// The pixel's row, `< height` (downwards).
    pub y: u32,
    /// `z / w` at the pixel centre: 0 on the near plane, 1 on the far one
    /// (error: [`rasterize_clipped`]).
    pub depth: f64,
    /// Perspective-correct barycentric coordinates of the pixel centre in
    /// the original (unclipped) triangle, for interpolating its vertices'
    /// attributes; in `[0, 1]` and summing to 1, up to rounding.
    pub weights: DVec3,
}

/// The screen position of the clip-space point `p`: `((x / w * 0.5 + 0.5)
/// * width, (0.5 - y / w * 0.5) * height, z / w)`, `y` downwards as in
/// [`rasterize_triangle`]'s pixels, depth `z / w`.
///
/// Each coordinate is within `gamma(3) (|x / w| + 1) / 2 * width` (`y`
/// with `height`) of the exact value, and depth within `u |z / w|`. For
/// `w = 0` the result is infinite or NaN (no panic); [`rasterize_clipped`]
/// never projects such a point.
///
/// ```
/// use exactray::raster::to_screen;
/// use glam::{DVec3, DVec4};
/// assert_eq!(to_screen(DVec4::new(-2.0, 2.0, 1.0, 2.0), 640, 480), DVec3::new(0.0, 0.0, 0.5));
/// assert_eq!(to_screen(DVec4::new(1.0, -1.0, 0.0, 1.0), 640, 480), DVec3::new(640.0, 480.0, 0.0));
/// ```
pub fn to_screen(p: DVec4, width: u32, height: u32) -> DVec3 {
    let (x, y) = (p.x / p.w, p.y / p.w);
    DVec3::new(
        (x * 0.5 + 0.5) * f64::from(width),
        (0.5 - y * 0.5) * f64::from(height),
        p.z / p.w,
    )
}

/// Rasterizes a clipped polygon into a `width` x `height` grid, calling
/// `fragment` once per covered pixel, and returns how many it emitted.
///
/// The polygon is split into a fan from its first vertex and each fan
/// triangle rasterized with [`rasterize_triangle`]'s exact coverage and
/// top-left rule, so the fan's triangles cover each pixel of the polygon
/// once, and polygons clipped from triangles that share an edge (whose
/// cut points are bit-identical, [`clip_triangle`]) cover each pixel of
/// their union once. Fragments come fan triangle by fan triangle, each in
/// rows of increasing `y`.
///
/// # Interpolation
/// At a covered centre `c` of a fan triangle, the screen-space
/// barycentrics `l_k` of `c` are computed from the three edge functions
/// (`(s_j - c) x (s_l - c)`, normalized by their sum). `z / w` is affine in
/// screen space, so depth is `sum l_k z_k / w_k`; the weights are not,
/// and are interpolated as `1 / w` and `weights / w` linearly and divided
/// (the perspective-correct rule): `sum l_k W_k / w_k / sum l_k / w_k`. The
/// fan's vertices carry weights relative to the original triangle, and
/// clip space is linear in them, so the result is the pixel centre's
/// barycentric coordinates in the original triangle.
///
/// # Error
/// For a fragment of the fan triangle with computed screen vertices `s_k`
/// (`w_k`, `z_k` their clip `w` and `z`, `W_k` their weights), write `a_k
/// = s_k - c`, `A = |a_1 x a_2 + a_2 x a_0 + a_0 x a_1|` (twice the area),
/// `m_k = |a_j.x| |a_l.y| + |a_j.y| |a_l.x|` for the two others `j, l`,
/// `K = (m_0 + m_1 + m_2) / A` (the condition of the barycentrics, `>=
/// 1`), `D = sum_k (|a_k.x| + |a_k.y|)` and `rho = max w_k / min w_k`; let
/// `j` be the number of planes [`clip_triangle`] clipped against (1 or 6),
/// `V` the largest magnitude of the input coordinates,
/// `r = 10 j gamma(4) V` (the clip residual, [`ClipVertex`]) and
///
/// `delta = max over k and the axes (x with width, y with height) of
/// (1 + |x_k / w_k|) / 2 * n * (gamma(3) + r / w_k)`,
///
/// the error of a screen coordinate (three roundings in [`to_screen`],
/// and the clip residual moved through the divide). Then
///
/// - the screen barycentrics are within `beta = 3 gamma(4) K + 5 delta D
///   / A` of the exact barycentrics of the exact projection (three
///   roundings per product of an edge function, two in the sum, one in the
///   quotient; a vertex moved by `delta` changes an edge function by at
///   most `delta` times the 1-norms of the two `a`s it multiplies);
/// - each weight is within `3 rho beta + gamma(10) + r / V` of the exact
///   barycentric coordinate, in the original triangle, of the point it
///   shows at the pixel centre (an error `e` in the `l_k` moves the
///   quotient by at most `e sum_k |W_k - W| / w_k / sum l_k / w_k <= 3
///   rho e`, weights lying in `[0, 1]`; ten roundings on positive terms in
///   the quotient; the clip weights' sum, off 1 by at most `r / V`);
/// - depth is within `(3 beta + gamma(4)) max |z_k / w_k| + max r (1 +
///   |z_k / w_k|) / w_k` of the exact `z / w` there.
///
/// These are first-order bounds (second-order terms in `u` dropped, and
/// products in the edge functions neither underflowing nor overflowing); they
/// are small where the fan triangle is well shaped on screen (`K`, `D /
/// A` moderate) and its depth range moderate (`rho`). A barycentric is
/// clamped to `>= 0` (the exact one is, at a covered centre), so depth
/// stays in the range of the vertices' and the weights in `[0, 1]` up to
/// rounding.
///
/// A fan triangle with a vertex at `w <= 0`, or one whose projection is not
/// finite, is skipped. After [`ClipPlanes::Frustum`], `w >= z >= 0` at
/// every vertex (up to rounding), and `w` is 0 only at a vertex `(0, 0,
/// 0, 0)`; after [`ClipPlanes::Near`] with glam's perspective matrices, `w
/// >= near > 0`. For any finite polygon there is no panic and no NaN.
pub fn rasterize_clipped(
    polygon: &ClippedPolygon,
    width: u32,
    height: u32,
    mut fragment: impl FnMut(Fragment),
) -> u64 {
    let Some((first, rest)) = polygon.vertices().split_first() else {
        return 0;
    };
    rest.windows(2)
        .map(|pair| match pair {
            [b, c] => fan_triangle([first, b, c], width, height, &mut fragment),
            _ => 0,
        })
        .sum()
}

/// Clips the triangle `v0, v1, v2` ([`clip_triangle`]) and rasterizes what
/// is left ([`rasterize_clipped`]); returns the number of fragments.
///
/// Errors: [`InputError::NonFinite`] naming `"v0"`, `"v1"` or `"v2"`.
///
/// ```
/// use exactray::raster::{ClipPlanes, rasterize_clip_space};
/// use glam::DVec3;
/// let projection = glam::dcamera::rh::proj::directx::perspective(1.0, 1.0, 0.1, 100.0);
/// let clip = |p: [f64; 3]| projection * DVec3::from(p).extend(1.0);
/// // A floor under the eye reaching behind it: every fragment lands in
/// // depth [0, 1] (the clipped vertex on the near plane has depth 0).
/// let (a, b, c) = (clip([-5.0, -1.0, 2.0]), clip([5.0, -1.0, 2.0]), clip([0.0, -1.0, -20.0]));
/// let n = rasterize_clip_space(a, b, c, ClipPlanes::Near, 32, 32, |f| {
///     assert!((0.0..=1.0).contains(&f.depth));
///     assert!(f.weights.min_element() >= 0.0);
/// })
/// .unwrap();
/// assert!(n > 0);
/// ```
pub fn rasterize_clip_space(
    v0: DVec4,
    v1: DVec4,
    v2: DVec4,
    planes: ClipPlanes,
    width: u32,
    height: u32,
    fragment: impl FnMut(Fragment),
) -> Result<u64, InputError> {
    let polygon = clip_triangle(v0, v1, v2, planes)?;
    Ok(rasterize_clipped(&polygon, width, height, fragment))
}

/// A fan triangle's vertex on screen, with what is interpolated.
#[derive(Clone, Copy, Debug)]
struct ScreenVertex {
    /// The screen position.
    at: DVec2,
    /// `z / w`.
    depth: f64,
    /// `min w / w` of the fan triangle: `1 / w` scaled so that it neither
    /// overflows nor vanishes for the nearest vertex.
    inverse_w: f64,
    weights: DVec3,
}

fn fan_triangle(
    triangle: [&ClipVertex; 3],
    width: u32,
    height: u32,
    fragment: &mut impl FnMut(Fragment),
) -> u64 {
    let w = triangle.map(|v| v.position.w);
    // A finite polygon holds no NaN, so `<= 0` is every vertex the divide
    // cannot project.
    if w.iter().any(|&w| w <= 0.0) {
        return 0;
    }
    let nearest = w[0].min(w[1]).min(w[2]);
    let mut screen = [ScreenVertex {
        at: DVec2::ZERO,
        depth: 0.0,
        inverse_w: 0.0,
        weights: DVec3::ZERO,
    }; 3];
    for (s, v) in screen.iter_mut().zip(triangle) {
        let p = to_screen(v.position, width, height);
        if !p.is_finite() {
            return 0;
        }
        *s = ScreenVertex {
            at: p.truncate(),
            depth: p.z,
            inverse_w: nearest / v.position.w,
            weights: v.weights,
        };
    }
    let [s0, s1, s2] = screen;
    // The sign that makes every edge function non-negative at a covered
    // centre (exact, like the coverage itself).
    let orientation = match orient2d(s0.at, s1.at, s2.at) {
        Sign::Positive => 1.0,
        Sign::Negative => -1.0,
        Sign::Zero => return 0,
    };
    let covered = rasterize_triangle(s0.at, s1.at, s2.at, width, height, |y, x0, x1| {
        let py = f64::from(y) + 0.5;
        for x in x0..x1 {
            let c = DVec2::new(f64::from(x) + 0.5, py);
            fragment(shade(&screen, orientation, x, y, c));
        }
    });
    // The positions are finite (checked above): the error is impossible.
    covered.unwrap_or(0)
}

/// The fragment at the covered centre `c` of the fan triangle `screen`.
#[inline]
fn shade(screen: &[ScreenVertex; 3], orientation: f64, x: u32, y: u32, c: DVec2) -> Fragment {
    let a = screen.map(|s| s.at - c);
    // The exact barycentrics at a covered centre are >= 0: clamping a
    // rounded negative one to 0 only lowers the error. `f64::max` also
    // maps a NaN (inf - inf, for projections near the largest floats) to 0.
    let edge = [(1, 2), (2, 0), (0, 1)].map(|(j, l)| {
        let e = a[j].perp_dot(a[l]) * orientation;
        e.max(0.0)
    });
    let sum = edge[0] + edge[1] + edge[2];
    // A zero sum (every product underflowed: a triangle of area near the
    // smallest floats) or an infinite one (coordinates near the largest):
    // the centroid keeps the values in range where the bound says nothing.
    let l = if sum > 0.0 && sum.is_finite() {
        edge.map(|e| e / sum)
    } else {
        [1.0 / 3.0; 3]
    };
    let depth = l[0] * screen[0].depth + l[1] * screen[1].depth + l[2] * screen[2].depth;
    let q = [0, 1, 2].map(|k| l[k] * screen[k].inverse_w);
    let total = q[0] + q[1] + q[2];
    let weights = if total > 0.0 {
        (q[0] * screen[0].weights + q[1] * screen[1].weights + q[2] * screen[2].weights) / total
    } else {
        // Every `l_k inverse_w_k` underflowed (a depth ratio beyond
        // 2^1000): screen-linear weights rather than 0 / 0.
        l[0] * screen[0].weights + l[1] * screen[1].weights + l[2] * screen[2].weights
    };
    Fragment {
        x,
        y,
        depth,
        weights,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_covers_each_pixel_once_with_exact_weights_at_w_one() {
        // Two triangles of the square [-1, 1]^2 at w = 1: the viewport.
        let v = |x: f64, y: f64| DVec4::new(x, y, 0.5, 1.0);
        let mut counts = [[0u8; 8]; 8];
        for tri in [
            [v(-1.0, -1.0), v(1.0, -1.0), v(1.0, 1.0)],
            [v(-1.0, -1.0), v(1.0, 1.0), v(-1.0, 1.0)],
        ] {
            let n = rasterize_clip_space(tri[0], tri[1], tri[2], ClipPlanes::Frustum, 8, 8, |f| {
                counts[f.y as usize][f.x as usize] += 1;
                assert_eq!(f.depth, 0.5);
                assert!(f.weights.min_element() >= 0.0);
            })
            .unwrap();
            assert!(n > 0);
        }
        assert_eq!(counts, [[1; 8]; 8]);
    }

    #[test]
    fn zero_w_vertex_is_skipped() {
        let origin = DVec4::ZERO;
        let n = rasterize_clip_space(
            origin,
            DVec4::new(1.0, 0.0, 0.5, 1.0),
            DVec4::new(0.0, 1.0, 0.5, 1.0),
            ClipPlanes::Frustum,
            8,
            8,
            |f| assert!(f.depth.is_finite() && f.weights.is_finite()),
        );
        assert!(n.is_ok());
    }
}
