//! Clipping of one triangle in homogeneous clip space, before the divide
//! (conventions, inside and outside, watertightness: the `raster` module
//! docs). Cut points are interpolated from their edge's endpoints in the
//! order of the endpoints' bit patterns and then put exactly on the plane.

use crate::error::InputError;
use glam::{DVec3, DVec4};

/// The most vertices a clipped triangle has: Sutherland–Hodgman clips a
/// convex polygon by one plane into a convex polygon with at most one
/// vertex more (an edge entering and an edge leaving the half-space each
/// add a cut point, and the vertices between them on the outside, at
/// least one, are dropped), so 3 + 6 planes = 9.
const CAPACITY: usize = 9;

/// One vertex of a clipped triangle.
///
/// `position` is in clip space; `weights` are its barycentric coordinates
/// with respect to the input triangle `v0, v1, v2` (`weights.x` for `v0`),
/// for interpolating the input vertices' attributes.
///
/// # Error of the weights
/// An input vertex keeps its position and has exactly a unit weight
/// vector. A cut point is made by `j` cuts in sequence (`j <= 1` with
/// [`ClipPlanes::Near`], `j <= 6` with [`ClipPlanes::Frustum`]); with `V`
/// the largest magnitude of the input triangle's twelve coordinates,
///
/// - each coordinate of `weights.x v0 + weights.y v1 + weights.z v2` is
///   within `10 j gamma(4) V` of the same coordinate of `position`, and
/// - `weights.x + weights.y + weights.z` is within `10 j gamma(4)` of 1,
///
/// `gamma(n) = n u / (1 - n u)`, `u = 2^-53` (Higham, *Accuracy and
/// Stability of Numerical Algorithms*, Lemma 3.1). Derivation: a cut at
/// the computed parameter `t` in `[0, 1]` interpolates both the position
/// and the weights as `a + t (b - a)`, three roundings: within `gamma(3)
/// (|a| + |b - a|)`, at most `3 gamma(3) V` for a position coordinate (the
/// interpolants stay in the input's coordinate range, see below) and, as
/// the weights are in `[0, 1]` and sum to about 1, at most `3 gamma(3) V`
/// after the weights' errors are multiplied by the input coordinates and
/// summed; setting the coordinate along the plane moves it by at most
/// `|t - t*| |d_b - d_a| <= gamma(4) 4 V` (the parameter `d_a / (d_a -
/// d_b)` has four roundings, the plane functions at most `2 V` each);
/// `6 gamma(3) + 4 gamma(4) <= 10 gamma(4)`. A cut point is a convex
/// combination of its edge's endpoints, so the differences from the
/// endpoints' own residuals add up over the `j` cuts.
///
/// Every interpolated value is clamped to the interval of its two
/// endpoints (the exact value lies there, so this only lowers the error),
/// so weights lie in `[0, 1]` and coordinates within the range of the
/// input's: no overflow, for any finite input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// The position in clip space `(x, y, z, w)`.
    pub position: DVec4,
    /// Barycentric coordinates with respect to the input triangle (they sum
    /// to 1 up to rounding; see the type's docs for the bound).
    pub weights: DVec3,
}

/// The part of a triangle inside the clip planes: a convex polygon of at
/// most 9 vertices, stored inline (no allocation), in the input
/// triangle's winding order.
///
/// Empty when nothing of the triangle is inside. A triangle touching a
/// plane only at a vertex or along an edge gives a polygon of zero area
/// (coincident or collinear vertices), which rasterizes to nothing.
#[derive(Clone, Copy, Debug)]
pub struct ClippedPolygon {
    vertices: [ClipVertex; CAPACITY],
    len: usize,
}

impl ClippedPolygon {
    const EMPTY: ClippedPolygon = ClippedPolygon {
        vertices: [ClipVertex {
            position: DVec4::ZERO,
            weights: DVec3::ZERO,
        }; CAPACITY],
        len: 0,
    };

    /// The polygon's vertices, in order around it.
    pub fn vertices(&self) -> &[ClipVertex] {
        &self.vertices[..self.len]
    }

    /// The number of vertices, 0 to 9.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether nothing of the triangle is inside the planes.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Appends a vertex. In exact arithmetic the capacity always suffices
    /// (see [`CAPACITY`]); rounding could in principle let a polygon of
    /// near-zero area, whose vertices lie within rounding of a plane,
    /// alternate sides more than twice, and a vertex beyond the ninth is
    /// then dropped instead of overflowing.
    fn push(&mut self, vertex: ClipVertex) {
        if let Some(slot) = self.vertices.get_mut(self.len) {
            *slot = vertex;
            self.len += 1;
        }
    }
}

/// Which planes [`clip_triangle`] clips against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClipPlanes {
    /// The near plane `z = 0` only: enough to make the divide by `w` safe
    /// for glam's matrices; the rasterizer clips to the viewport itself.
    Near,
    /// All six planes of the view frustum: `0 <= z <= w`, `-w <= x, y <= w`.
    Frustum,
}

/// One clip plane, with its function (inside where it is `>= 0`).
#[derive(Clone, Copy, Debug)]
enum Plane {
    Near,
    Far,
    Left,
    Right,
    Bottom,
    Top,
}

/// The near plane first, so that [`ClipPlanes::Near`] is a prefix.
const FRUSTUM: [Plane; 6] = [
    Plane::Near,
    Plane::Far,
    Plane::Left,
    Plane::Right,
    Plane::Bottom,
    Plane::Top,
];

impl Plane {
    /// The plane's function at `p`, rounded once (or exact, for `z`).
    #[inline]
    fn distance(self, p: DVec4) -> f64 {
        match self {
            Plane::Near => p.z,
            Plane::Far => p.w - p.z,
            Plane::Left => p.w + p.x,
            Plane::Right => p.w - p.x,
            Plane::Bottom => p.w + p.y,
            Plane::Top => p.w - p.y,
        }
    }

    /// Puts a cut point exactly on the plane: afterwards [`Plane::distance`]
    /// is exactly zero (`w - w`, `w + (-w)`), so later planes and the
    /// depth see the point where it belongs.
    #[inline]
    fn snap(self, p: &mut DVec4) {
        match self {
            Plane::Near => p.z = 0.0,
            Plane::Far => p.z = p.w,
            Plane::Left => p.x = -p.w,
            Plane::Right => p.x = p.w,
            Plane::Bottom => p.y = -p.w,
            Plane::Top => p.y = p.w,
        }
    }
}

/// Clips the triangle `v0, v1, v2` (clip-space positions, the module's
/// conventions) against the near plane or the whole view frustum, before
/// the perspective divide, by Sutherland–Hodgman.
///
/// The result keeps the input's winding; each vertex carries its
/// barycentric weights with respect to the input (see [`ClipVertex`] for
/// their error). Two triangles sharing an edge get bit-identical cut
/// points on it (the [module docs](super)). A triangle entirely outside gives an
/// empty polygon; one entirely inside gives its three vertices unchanged.
///
/// Errors: [`InputError::NonFinite`] naming `"v0"`, `"v1"` or `"v2"` when
/// a coordinate is NaN or infinite. Every finite input is clipped without
/// panic, overflow to infinity or NaN.
///
/// ```
/// use exactray::raster::{ClipPlanes, clip_triangle};
/// use glam::DVec4;
/// // One vertex behind the eye (w < 0, z < 0; z = w - 0.5 as for a near
/// // plane at w = 0.5): the near plane cuts the two edges leaving it, and
/// // the triangle becomes a quadrilateral.
/// let (a, b) = (DVec4::new(-1.0, 0.0, 0.5, 1.0), DVec4::new(1.0, 0.0, 0.5, 1.0));
/// let behind = DVec4::new(0.0, 1.0, -1.5, -1.0);
/// let polygon = clip_triangle(a, b, behind, ClipPlanes::Near).unwrap();
/// assert_eq!(polygon.len(), 4);
/// assert!(polygon.vertices().iter().all(|v| v.position.z >= 0.0 && v.position.w > 0.0));
/// // Entirely behind: nothing.
/// let gone = clip_triangle(-a, -b, behind, ClipPlanes::Near).unwrap();
/// assert!(gone.is_empty());
/// ```
pub fn clip_triangle(
    v0: DVec4,
    v1: DVec4,
    v2: DVec4,
    planes: ClipPlanes,
) -> Result<ClippedPolygon, InputError> {
    for (argument, v) in [("v0", v0), ("v1", v1), ("v2", v2)] {
        if !v.is_finite() {
            return Err(InputError::NonFinite { argument });
        }
    }
    let mut polygon = ClippedPolygon::EMPTY;
    for (position, weights) in [(v0, DVec3::X), (v1, DVec3::Y), (v2, DVec3::Z)] {
        polygon.push(ClipVertex { position, weights });
    }
    let planes: &[Plane] = match planes {
        ClipPlanes::Near => &FRUSTUM[..1],
        ClipPlanes::Frustum => &FRUSTUM,
    };
    for &plane in planes {
        if polygon.is_empty() {
            break;
        }
        // A plane every vertex is inside leaves the polygon as it is (the
        // pass would push each vertex and cut nothing): skip the copy. Most
        // triangles of a frame are inside every plane.
        let inside = |v: &ClipVertex| plane.distance(v.position) >= 0.0;
        if polygon.vertices().iter().all(inside) {
            continue;
        }
        polygon = clip_polygon(&polygon, plane);
    }
    Ok(polygon)
}

/// One Sutherland–Hodgman pass: the part of `polygon` inside `plane`.
fn clip_polygon(polygon: &ClippedPolygon, plane: Plane) -> ClippedPolygon {
    let vertices = polygon.vertices();
    let mut out = ClippedPolygon::EMPTY;
    let nexts = vertices.iter().cycle().skip(1);
    for (current, next) in vertices.iter().zip(nexts) {
        let inside = plane.distance(current.position) >= 0.0;
        let next_inside = plane.distance(next.position) >= 0.0;
        if inside {
            out.push(*current);
        }
        if inside != next_inside {
            out.push(cut(plane, current, next));
        }
    }
    out
}

/// The point where the edge `a`-`b` (one endpoint inside `plane`, the
/// other outside) crosses it, computed from the endpoints in the order of
/// their positions' bit patterns, so that `cut(a, b)` and `cut(b, a)` are
/// the same bits.
fn cut(plane: Plane, a: &ClipVertex, b: &ClipVertex) -> ClipVertex {
    let bits = |p: DVec4| p.to_array().map(f64::to_bits);
    let (p, q) = if bits(a.position) <= bits(b.position) {
        (a, b)
    } else {
        (b, a)
    };
    let t = crossing(plane, p.position, q.position);
    let (pp, qp) = (p.position, q.position);
    let mut position = DVec4::new(
        lerp(pp.x, qp.x, t),
        lerp(pp.y, qp.y, t),
        lerp(pp.z, qp.z, t),
        lerp(pp.w, qp.w, t),
    );
    plane.snap(&mut position);
    let (pw, qw) = (p.weights, q.weights);
    let weights = DVec3::new(
        lerp(pw.x, qw.x, t),
        lerp(pw.y, qw.y, t),
        lerp(pw.z, qw.z, t),
    );
    ClipVertex { position, weights }
}

/// The parameter `t` in `[0, 1]` where the plane's function, affine along
/// the edge from `p` to `q`, is zero: `d_p / (d_p - d_q)`.
///
/// The functions have opposite signs (one `>= 0`, one `< 0`), so the exact
/// `|d_p - d_q| = |d_p| + |d_q|` is at least `|d_p|` and positive; rounding
/// is monotone and `d_p` is a float, so the rounded difference is too and
/// the quotient lies in `[0, 1]`. Four roundings (the two functions, the
/// difference, the quotient) with no cancellation: `t` is within
/// `gamma(4) t` of the exact parameter of the rounded-coordinate edge.
fn crossing(plane: Plane, p: DVec4, q: DVec4) -> f64 {
    let (dp, dq) = (plane.distance(p), plane.distance(q));
    let denominator = dp - dq;
    if denominator.is_finite() {
        return dp / denominator;
    }
    // Coordinates near the largest floats: a function or the difference
    // overflowed. The functions of the quartered points are quarters
    // (exactly, coordinates that large are far from subnormal; the small
    // ones round monotonically, keeping the signs), at most `f64::MAX / 2`
    // each, so neither they nor their difference overflow; and one of
    // them exceeds `f64::MAX / 8`, so the difference is not zero.
    let (dp, dq) = (plane.distance(p * 0.25), plane.distance(q * 0.25));
    let t = dp / (dp - dq);
    // In [0, 1] by the argument above; kept so no input can make a NaN.
    if (0.0..=1.0).contains(&t) { t } else { 0.5 }
}

/// `a + t (b - a)` for `t` in `[0, 1]`, clamped to the interval of `a` and
/// `b` (where the exact value lies, so clamping only lowers the error, and
/// keeps the result finite). Where `b - a` overflows, the halves are
/// interpolated instead and doubled (exact scalings: such values are far
/// from the subnormals).
#[inline]
fn lerp(a: f64, b: f64, t: f64) -> f64 {
    let d = b - a;
    let v = if d.is_finite() {
        a + t * d
    } else {
        2.0 * (0.5 * a + t * (0.5 * b - 0.5 * a))
    };
    v.clamp(a.min(b), a.max(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn polygon(v: [DVec4; 3], planes: ClipPlanes) -> ClippedPolygon {
        clip_triangle(v[0], v[1], v[2], planes).unwrap()
    }

    #[test]
    fn inside_triangle_is_unchanged() {
        let v = [
            DVec4::new(-0.5, -0.5, 0.2, 1.0),
            DVec4::new(0.5, -0.5, 0.3, 1.0),
            DVec4::new(0.0, 0.5, 0.4, 1.0),
        ];
        let p = polygon(v, ClipPlanes::Frustum);
        assert_eq!(p.len(), 3);
        for (k, vertex) in p.vertices().iter().enumerate() {
            assert_eq!(vertex.position, v[k]);
            assert_eq!(vertex.weights, [DVec3::X, DVec3::Y, DVec3::Z][k]);
        }
    }

    #[test]
    fn cut_is_symmetric_in_its_endpoints() {
        let a = ClipVertex {
            position: DVec4::new(0.1, 0.3, 0.7, 1.3),
            weights: DVec3::X,
        };
        let b = ClipVertex {
            position: DVec4::new(-3.0, 0.2, -0.9, -0.7),
            weights: DVec3::Y,
        };
        for plane in FRUSTUM {
            if (plane.distance(a.position) >= 0.0) != (plane.distance(b.position) >= 0.0) {
                let (ab, ba) = (cut(plane, &a, &b), cut(plane, &b, &a));
                assert_eq!(
                    ab.position.to_array().map(f64::to_bits),
                    ba.position.to_array().map(f64::to_bits)
                );
                assert_eq!(plane.distance(ab.position), 0.0);
            }
        }
    }

    #[test]
    fn huge_coordinates_stay_finite() {
        let m = f64::MAX;
        let v = [
            DVec4::new(-m, m, m, m),
            DVec4::new(m, -m, -m, -m),
            DVec4::new(0.0, m, 0.5 * m, m),
        ];
        for planes in [ClipPlanes::Near, ClipPlanes::Frustum] {
            let p = polygon(v, planes);
            for vertex in p.vertices() {
                assert!(vertex.position.is_finite() && vertex.weights.is_finite());
                assert!(vertex.weights.min_element() >= 0.0 && vertex.weights.max_element() <= 1.0);
            }
        }
    }

    #[test]
    fn nine_vertices_at_most() {
        // A large triangle around the frustum: every plane cuts it.
        let v = [
            DVec4::new(-7.0, -5.0, -3.0, 1.0),
            DVec4::new(9.0, -6.0, 4.0, 1.0),
            DVec4::new(0.5, 8.0, 0.5, 1.0),
        ];
        let p = polygon(v, ClipPlanes::Frustum);
        assert!(p.len() <= CAPACITY && p.len() >= 3, "{}", p.len());
    }
}
