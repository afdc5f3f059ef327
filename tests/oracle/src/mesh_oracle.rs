//! Rays and segments against triangle meshes, exactly (`docs/fixture-format.md`'s
//! `ray_mesh` rule): the closed triangles' common points with a line, as
//! parameter intervals in big-integer fractions, by brute force over every
//! triangle. Independent of the crate's arithmetic and of its method: the
//! coplanar case is taken in 3D, with the plane's normal, where the crate
//! projects to 2D.
//!
//! All coordinates of one query (the ray or segment and every vertex) are
//! integers at their common exponent, which scales every point alike and
//! keeps parameters along the line unchanged.

use crate::oracle::common_integers;
use core::cmp::Ordering;
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

pub(crate) type V = [BigInt; 3];

pub(crate) fn sub(a: &V, b: &V) -> V {
    core::array::from_fn(|k| &a[k] - &b[k])
}

pub(crate) fn dot(a: &V, b: &V) -> BigInt {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn cross(a: &V, b: &V) -> V {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

/// A parameter `num / den` with `den > 0`, not reduced: equal fractions
/// compare equal by value (`2k / k == 2 / 1`), as their order does.
#[derive(Clone, Debug)]
pub struct Frac {
    /// The numerator.
    pub num: BigInt,
    /// The denominator, positive.
    pub den: BigInt,
}

impl Frac {
    /// `num / den` for `den != 0`.
    pub fn new(num: BigInt, den: BigInt) -> Frac {
        if den.is_negative() {
            Frac {
                num: -num,
                den: -den,
            }
        } else {
            Frac { num, den }
        }
    }

    fn int(v: i64) -> Frac {
        Frac::new(BigInt::from(v), BigInt::from(1))
    }
}

impl PartialEq for Frac {
    fn eq(&self, other: &Frac) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Frac {}

impl PartialOrd for Frac {
    fn partial_cmp(&self, other: &Frac) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Frac {
    fn cmp(&self, other: &Frac) -> Ordering {
        (&self.num * &other.den).cmp(&(&other.num * &self.den))
    }
}

/// The parameters `[t_in, t_out]` at which the line `o + t d` lies on the
/// closed triangle `v` (one point for a crossing), or `None` when it
/// misses it. A degenerate triangle (zero normal) is never met, as the
/// crate's meshes leave such triangles out.
fn line_span(o: &V, d: &V, v: &[V; 3]) -> Option<(Frac, Frac)> {
    let n = cross(&sub(&v[1], &v[0]), &sub(&v[2], &v[0]));
    if n.iter().all(|x| x.is_zero()) {
        return None;
    }
    let den = dot(d, &n);
    let off = dot(&sub(&v[0], o), &n);
    if !den.is_zero() {
        // The crossing o + t d, t = off / den, is in the closed triangle
        // when it is on the inner side of (or on) each edge:
        // n . (E_i x (x - v_j)) >= 0 for the edge v_j -> v_m, times den.
        let t = Frac::new(off, den.clone());
        for i in 0..3 {
            let (j, m) = ((i + 1) % 3, (i + 2) % 3);
            let e = sub(&v[m], &v[j]);
            // x - v_j = (den (o - v_j) + off d) / den.
            let rel: V = core::array::from_fn(|k| &t.den * (&o[k] - &v[j][k]) + &t.num * &d[k]);
            if dot(&n, &cross(&e, &rel)).is_negative() {
                return None;
            }
        }
        return Some((t.clone(), t));
    }
    if !off.is_zero() {
        return None;
    }
    // In the plane: the point at t is inside edge i when A_i + t B_i >= 0,
    // A_i = n . (E_i x (o - v_j)), B_i = n . (E_i x d) (the third vertex
    // gives n . n > 0).
    let (mut lower, mut upper): (Option<Frac>, Option<Frac>) = (None, None);
    for i in 0..3 {
        let (j, m) = ((i + 1) % 3, (i + 2) % 3);
        let e = sub(&v[m], &v[j]);
        let a = dot(&n, &cross(&e, &sub(o, &v[j])));
        let b = dot(&n, &cross(&e, d));
        if b.is_zero() {
            if a.is_negative() {
                return None;
            }
            continue;
        }
        let bound = Frac::new(-a, b.clone());
        if b.is_positive() {
            if lower.as_ref().is_none_or(|l| bound > *l) {
                lower = Some(bound);
            }
        } else if upper.as_ref().is_none_or(|u| bound < *u) {
            upper = Some(bound);
        }
    }
    let (lo, hi) = (lower?, upper?);
    (lo <= hi).then_some((lo, hi))
}

/// The points of one query and of a mesh as integers at their common
/// exponent: the query's two points (a ray's origin and direction, or a
/// segment's ends), then the vertices.
fn integers(a: [f64; 3], b: [f64; 3], vertices: &[[f64; 3]]) -> (V, V, Vec<V>) {
    let mut all = Vec::with_capacity(3 * vertices.len() + 6);
    all.extend(a);
    all.extend(b);
    for v in vertices {
        all.extend(v);
    }
    let ints = common_integers(&all);
    let p = |i: usize| -> V { core::array::from_fn(|k| ints[3 * i + k].clone()) };
    let verts = (0..vertices.len()).map(|i| p(i + 2)).collect();
    (p(0), p(1), verts)
}

/// The closest hit of the ray `o + t d`, `t >= 0`, on the mesh: the exact
/// first parameter `t* = min { t >= 0 : o + t d on some triangle }` and,
/// ascending, every triangle containing the point at `t*`; `None` for a
/// miss. `triangles` index `vertices` (every index in range).
pub fn ray_mesh(
    o: [f64; 3],
    d: [f64; 3],
    vertices: &[[f64; 3]],
    triangles: &[[usize; 3]],
) -> Option<(Frac, Vec<usize>)> {
    let (o, d, verts) = integers(o, d, vertices);
    let zero = Frac::int(0);
    let spans: Vec<Option<(Frac, Frac)>> = triangles
        .iter()
        .map(|t| {
            let (lo, hi) = line_span(&o, &d, &t.map(|i| verts[i].clone()))?;
            (hi >= zero).then(|| (lo.max(zero.clone()), hi))
        })
        .collect();
    let first = spans.iter().flatten().map(|(lo, _)| lo).min()?.clone();
    let on = spans
        .iter()
        .enumerate()
        .filter(|(_, s)| {
            s.as_ref()
                .is_some_and(|(lo, hi)| *lo <= first && first <= *hi)
        })
        .map(|(i, _)| i)
        .collect();
    Some((first, on))
}

/// Whether the closed segment from `p` to `q` meets some triangle of the
/// mesh: the line `p + t (q - p)` (the difference exact) on a triangle for
/// some `t` in `[0, 1]`.
pub fn segment_mesh(
    p: [f64; 3],
    q: [f64; 3],
    vertices: &[[f64; 3]],
    triangles: &[[usize; 3]],
) -> bool {
    let (p, q, verts) = integers(p, q, vertices);
    let d = sub(&q, &p);
    let (zero, one) = (Frac::int(0), Frac::int(1));
    if d.iter().all(|x| x.is_zero()) {
        // A point: on a triangle when a line through it along any
        // non-zero vector meets the triangle at t = 0.
        return triangles.iter().any(|t| {
            let v = t.map(|i| verts[i].clone());
            let e = sub(&v[1], &v[0]);
            let e = if e.iter().all(|x| x.is_zero()) {
                sub(&v[2], &v[0])
            } else {
                e
            };
            line_span(&p, &e, &v).is_some_and(|(lo, hi)| lo <= zero && zero <= hi)
        });
    }
    triangles.iter().any(|t| {
        line_span(&p, &d, &t.map(|i| verts[i].clone()))
            .is_some_and(|(lo, hi)| lo <= one && hi >= zero)
    })
}

/// The crossing of the line `o + t d` with the plane of a non-degenerate
/// triangle `v` (normal `n`) when the line is not parallel to it: `t` and
/// the signs of the point's three edge values `n . (E_i x (x - v_j))`
/// (all positive inside, a zero on an edge's line).
fn plane_crossing(o: &V, d: &V, v: &[V; 3], n: &V) -> Option<(Frac, [i8; 3])> {
    let den = dot(d, n);
    if den.is_zero() {
        return None;
    }
    let t = Frac::new(dot(&sub(&v[0], o), n), den);
    let signs = core::array::from_fn(|i| {
        let (j, m) = ((i + 1) % 3, (i + 2) % 3);
        let e = sub(&v[m], &v[j]);
        let rel: V = core::array::from_fn(|k| &t.den * (&o[k] - &v[j][k]) + &t.num * &d[k]);
        let s = dot(n, &cross(&e, &rel));
        if s.is_positive() {
            1
        } else if s.is_negative() {
            -1
        } else {
            0
        }
    });
    Some((t, signs))
}

/// Whether `p` lies on the closed triangle `v`: in its plane and on the
/// inner side of (or on) its edges; for a degenerate one, on one of its
/// three closed segments (`p - a` parallel to `b - a`, between the ends).
fn on_triangle(p: &V, v: &[V; 3]) -> bool {
    let n = cross(&sub(&v[1], &v[0]), &sub(&v[2], &v[0]));
    if n.iter().all(|x| x.is_zero()) {
        return (0..3).any(|i| {
            let (a, b) = (&v[i], &v[(i + 1) % 3]);
            let (ab, ap, bp) = (sub(b, a), sub(p, a), sub(p, b));
            if ab.iter().all(|x| x.is_zero()) {
                return ap.iter().all(|x| x.is_zero());
            }
            cross(&ab, &ap).iter().all(|x| x.is_zero())
                && !dot(&ap, &ab).is_negative()
                && !dot(&bp, &ab).is_positive()
        });
    }
    if !dot(&sub(p, &v[0]), &n).is_zero() {
        return false;
    }
    (0..3).all(|i| {
        let (j, m) = ((i + 1) % 3, (i + 2) % 3);
        !dot(&n, &cross(&sub(&v[m], &v[j]), &sub(p, &v[j]))).is_negative()
    })
}

/// The winding number of the closed mesh around `p`, or `None` when `p`
/// lies on a triangle (closed sets, degenerate ones as segments). The
/// signed crossings (`+1` where the ray leaves through a triangle's front,
/// `n . d > 0`) of a ray from `p` along `d = (1, k, k^2)` for the first
/// `k = 0, 1, ...` whose ray passes through no edge of a non-degenerate
/// triangle and lies in none's plane: an independent method, with
/// directions on the moment curve, any three of them linearly independent,
/// so at most two lie in each of the `4 T` planes of bad directions (an
/// edge's plane with `p`, a plane through `p`) and `8 T + 1` tries always
/// find one.
pub fn winding_number(p: [f64; 3], vertices: &[[f64; 3]], triangles: &[[usize; 3]]) -> Option<i64> {
    let (p, _, verts) = integers(p, [0.0; 3], vertices);
    let tris: Vec<[V; 3]> = triangles
        .iter()
        .map(|t| t.map(|i| verts[i].clone()))
        .collect();
    if tris.iter().any(|v| on_triangle(&p, v)) {
        return None;
    }
    'direction: for k in 0..=(8 * tris.len() as i64 + 1) {
        let d: V = [BigInt::from(1), BigInt::from(k), BigInt::from(k * k)];
        let mut winding = 0;
        for v in &tris {
            let n = cross(&sub(&v[1], &v[0]), &sub(&v[2], &v[0]));
            if n.iter().all(|x| x.is_zero()) {
                continue;
            }
            let Some((t, signs)) = plane_crossing(&p, &d, v, &n) else {
                if dot(&sub(&v[0], &p), &n).is_zero() {
                    continue 'direction;
                }
                continue;
            };
            if !t.num.is_positive() || signs.contains(&-1) {
                continue;
            }
            if signs.contains(&0) {
                continue 'direction;
            }
            winding += if dot(&d, &n).is_positive() { 1 } else { -1 };
        }
        return Some(winding);
    }
    unreachable!("a generic direction among 8 T + 2")
}

/// Every point where the ray `o + t d`, `t >= 0`, crosses a
/// non-degenerate triangle whose plane it is not parallel to: the exact
/// `t`, the triangle, and whether the point is inside the triangle (not
/// on an edge), in the order of `t` and then of the triangle; and whether
/// the ray's line lies in some such triangle's plane.
pub fn ray_crossings(
    o: [f64; 3],
    d: [f64; 3],
    vertices: &[[f64; 3]],
    triangles: &[[usize; 3]],
) -> (Vec<(Frac, usize, bool)>, bool) {
    let (o, d, verts) = integers(o, d, vertices);
    let mut in_plane = false;
    let mut out = Vec::new();
    for (index, t) in triangles.iter().enumerate() {
        let v = t.map(|i| verts[i].clone());
        let n = cross(&sub(&v[1], &v[0]), &sub(&v[2], &v[0]));
        if n.iter().all(|x| x.is_zero()) {
            continue;
        }
        match plane_crossing(&o, &d, &v, &n) {
            None => in_plane |= dot(&sub(&v[0], &o), &n).is_zero(),
            Some((t, signs)) => {
                if !t.num.is_negative() && !signs.contains(&-1) {
                    out.push((t, index, !signs.contains(&0)));
                }
            }
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.cmp(&b.1)));
    (out, in_plane)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two triangles of the unit square: a ray through the shared diagonal
    /// lists both; a ray in the plane enters through an edge; a segment
    /// ending just short of the square is not blocked.
    #[test]
    fn square() {
        let v = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let t = [[0, 1, 2], [0, 2, 3]];
        let (first, on) = ray_mesh([0.5, 0.5, 2.0], [0.0, 0.0, -1.0], &v, &t).unwrap();
        assert_eq!((first, on), (Frac::int(2), vec![0, 1]));
        let (first, on) = ray_mesh([-1.0, 0.25, 0.0], [2.0, 0.0, 0.0], &v, &t).unwrap();
        assert_eq!((first, on), (Frac::new(1.into(), 2.into()), vec![1]));
        let (first, on) = ray_mesh([0.75, 0.25, 0.0], [1.0, 1.0, 0.0], &v, &t).unwrap();
        assert_eq!((first, on), (Frac::int(0), vec![0]));
        assert!(ray_mesh([0.5, 0.5, 2.0], [0.0, 0.0, 1.0], &v, &t).is_none());
        assert!(segment_mesh([0.5, 0.5, 2.0], [0.5, 0.5, 0.0], &v, &t));
        let above = 5e-324;
        assert!(!segment_mesh([0.5, 0.5, 2.0], [0.5, 0.5, above], &v, &t));
        assert!(segment_mesh([2.0, 0.5, 0.0], [1.0, 0.5, 0.0], &v, &t));
        assert!(!segment_mesh(
            [2.0, 0.5, 0.0],
            [1.0 + 2e-16, 0.5, 0.0],
            &v,
            &t
        ));
    }
}
