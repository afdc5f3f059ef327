//! The exact answers the closed-triangle rule needs beyond the crossing
//! of a plane, all in integers (`arith::fixed_int`), for the exact variant
//! only (cold paths: the watertight test never reaches them):
//!
//! - **coplanar entry** ([`coplanar_hit`]): a ray lying in the triangle's
//!   plane touches the closed triangle along a segment of parameters
//!   `[t_in, t_out]`; its hit is where it enters, `max(range.min, t_in)`;
//! - **exact order** ([`exact_order`]): which of two triangles a ray meets
//!   first, from their exact parameters (the crossing's `det[v0 - o, e1,
//!   e2] / det[d, e1, e2]`, or the coplanar entry), cross-multiplied;
//! - **segments** ([`segment_meets`]): whether the closed segment `p q`
//!   (its exact end, not `p + fl(q - p)`) meets the closed triangle.
//!
//! # The coplanar span
//! For a line `o + t d` in the plane of `v0 v1 v2`, drop an axis `k` whose
//! normal coordinate `n_k` (of `n = (v1 - v0) x (v2 - v0)`) is exactly
//! non-zero: the projection onto the other two axes `(p, q)` is a
//! bijection of the plane that keeps parameters along the line. With
//! `cross2(a, b) = a_p b_q - a_q b_p` and, for edge `i` (from `v_j` to
//! `v_m`, `j = i + 1`, `m = i + 2` modulo 3), `E_i = v_m - v_j`, the point
//! at `t` is on the triangle's side of edge `i` when `s (A_i + t B_i) >=
//! 0`, `A_i = cross2(E_i, o - v_j)`, `B_i = cross2(E_i, d)`, `s` the sign
//! of `n_k` (`cross2(E_i, v_i - v_j) = n_k` for every `i`). So the closed
//! triangle is the `t` where all three hold: each `B_i` with `s B_i > 0`
//! bounds `t >= -A_i / B_i`, each with `s B_i < 0` bounds it from above, a
//! zero `B_i` (the line parallel to edge `i`) excludes every `t` when `s
//! A_i < 0` and nothing otherwise. The `B_i` sum to `cross2(0, d) = 0` and
//! not all vanish (the projected `d` is not zero, and no non-zero vector
//! is parallel to all three edges of a non-degenerate triangle), so there
//! is at least one bound of each kind: `t_in` is the largest lower bound,
//! `t_out` the least upper one, and the line touches the triangle exactly
//! when `t_in <= t_out`. Every comparison is a sign of integers.
//!
//! # Sizes
//! Coordinates are integers at each axis's finest bit over the points
//! involved (scaling an axis scales every `A_i`, `B_i` or determinant
//! column alike and leaves parameters unchanged), so they and their
//! differences fit `DEG1`; `A_i`, `B_i` and `n_k` are degree 2 (`DEG2`),
//! determinants degree 3 (`DEG3`); parameters are kept as fractions of
//! `DEG3` integers and compared in `DEG6` (products of two degree-3
//! values).

use super::TriangleHit;
use super::plane_parameter::round_quotient;
use crate::arith::exponent::{Grain, split};
use crate::arith::fixed_int::{DEG1, DEG2, DEG3, FixedInt, limbs_of_degree};
use crate::interval::Interval;
use crate::predicates::det::det3_wide;
use crate::predicates::orient3d;
use crate::query::ray::Ray;
use crate::shape::Triangle;
use crate::sign::Sign;
use core::cmp::Ordering;
use glam::DVec3;

/// Degree 6: the cross-multiplied comparison of two parameters.
const DEG6: usize = limbs_of_degree(6);

type W1 = FixedInt<DEG1>;
type W3 = FixedInt<DEG3>;
type W6 = FixedInt<DEG6>;
type V1 = [W1; 3];

/// A parameter `num / den`, `den > 0`.
#[derive(Clone, Copy)]
struct Fraction {
    num: W3,
    den: W3,
}

impl Fraction {
    /// `num / den` for `den != 0`, its sign moved to the numerator.
    fn new(num: W3, den: W3) -> Fraction {
        if den.is_negative() {
            Fraction {
                num: num.neg(),
                den: den.neg(),
            }
        } else {
            Fraction { num, den }
        }
    }

    /// The exact value of the finite `x`: `m 2^e` as `m 2^e / 1` or `m /
    /// 2^-e` (`|m| < 2^53`, `-1074 <= e <= 971`).
    fn of_f64(x: f64) -> Fraction {
        let (m, e) = split(x);
        if e >= 0 {
            Fraction {
                num: W3::from_i64_shifted(m, e as u32),
                den: W3::from_i64_shifted(1, 0),
            }
        } else {
            Fraction {
                num: W3::from_i64_shifted(m, 0),
                den: W3::from_i64_shifted(1, (-e) as u32),
            }
        }
    }

    /// The exact order of the two values.
    fn order(&self, other: &Fraction) -> Ordering {
        let lhs = W6::mul(&self.num, &other.den);
        let rhs = W6::mul(&other.num, &self.den);
        match lhs.sub(&rhs).sign() {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        }
    }

    /// The value rounded: within `4u` of it when normal, `2^-1073` when
    /// subnormal (`round_quotient`), with its exact sign.
    fn round(&self) -> f64 {
        round_quotient(self.num.rounded_parts(), self.den.rounded_parts())
    }
}

/// Each axis's finest bit over `points` (finite), `0` for an all-zero axis
/// (any grain holds zeros).
fn lows(points: &[DVec3]) -> [i32; 3] {
    let mut lo = [0; 3];
    for (k, l) in lo.iter_mut().enumerate() {
        let mut g = Grain::of(&[]);
        for p in points {
            let one = Grain::of(&[p[k]]);
            g.lo_min = g.lo_min.min(one.lo_min);
        }
        *l = if g.all_zero() { 0 } else { g.lo_min };
    }
    lo
}

/// `p` as integers at the grains `lo`.
fn int(p: DVec3, lo: [i32; 3]) -> V1 {
    [
        W1::from_f64(p.x, lo[0]),
        W1::from_f64(p.y, lo[1]),
        W1::from_f64(p.z, lo[2]),
    ]
}

fn sub(a: &V1, b: &V1) -> V1 {
    [a[0].sub(&b[0]), a[1].sub(&b[1]), a[2].sub(&b[2])]
}

/// A line `o + t d` and a triangle `v`, in integers at common grains.
struct Line {
    o: V1,
    d: V1,
    v: [V1; 3],
}

impl Line {
    /// The ray's line and `tri`, at the grains of all their coordinates.
    fn of_ray(o: DVec3, d: DVec3, tri: &[DVec3; 3], lo: [i32; 3]) -> Line {
        Line {
            o: int(o, lo),
            d: int(d, lo),
            v: tri.map(|p| int(p, lo)),
        }
    }

    /// `det[d, e1, e2]` (zero: the line is parallel to the plane) and
    /// `det[v0 - o, e1, e2]`: the crossing is at their quotient.
    fn crossing(&self) -> (W3, W3) {
        let (e1, e2) = (sub(&self.v[1], &self.v[0]), sub(&self.v[2], &self.v[0]));
        let den = det3_wide::<DEG1, DEG2, DEG3>(&[self.d, e1, e2]);
        let num = det3_wide::<DEG1, DEG2, DEG3>(&[sub(&self.v[0], &self.o), e1, e2]);
        (den, num)
    }

    /// The coplanar span (module docs) of a line in the triangle's plane,
    /// `None` when the line misses the triangle, or when no `n_k` is
    /// non-zero (a degenerate triangle).
    fn span(&self) -> Option<Span> {
        let (e1, e2) = (sub(&self.v[1], &self.v[0]), sub(&self.v[2], &self.v[0]));
        let cross2 = |a: &V1, b: &V1, p: usize, q: usize| {
            FixedInt::<DEG2>::mul(&a[p], &b[q]).sub(&FixedInt::<DEG2>::mul(&a[q], &b[p]))
        };
        let k =
            (0..3).find(|&k| cross2(&e1, &e2, (k + 1) % 3, (k + 2) % 3).sign() != Sign::Zero)?;
        let (p, q) = ((k + 1) % 3, (k + 2) % 3);
        let nk = cross2(&e1, &e2, p, q).widen::<DEG3>();
        let s = nk.sign();
        // A_i and B_i of edge i, from v_(i+1) to v_(i+2).
        let edge = |i: usize| sub(&self.v[(i + 2) % 3], &self.v[(i + 1) % 3]);
        let a: [W3; 3] = core::array::from_fn(|i| {
            cross2(&edge(i), &sub(&self.o, &self.v[(i + 1) % 3]), p, q).widen()
        });
        let b: [W3; 3] = core::array::from_fn(|i| cross2(&edge(i), &self.d, p, q).widen());
        let (mut lower, mut upper): (Option<Fraction>, Option<Fraction>) = (None, None);
        for (ai, bi) in a.iter().zip(&b) {
            // The bound -A_i / B_i.
            let bound = Fraction::new(ai.neg(), *bi);
            match bi.sign().product(s) {
                Sign::Zero if ai.sign().product(s) == Sign::Negative => return None,
                Sign::Zero => {}
                Sign::Positive => {
                    if lower.is_none_or(|l| bound.order(&l) == Ordering::Greater) {
                        lower = Some(bound);
                    }
                }
                Sign::Negative => {
                    if upper.is_none_or(|u| bound.order(&u) == Ordering::Less) {
                        upper = Some(bound);
                    }
                }
            }
        }
        // Both exist (module docs); `?` only guards that proof.
        let (t_in, t_out) = (lower?, upper?);
        (t_in.order(&t_out) != Ordering::Greater).then_some(Span {
            t_in,
            t_out,
            a,
            b,
            nk,
        })
    }
}

/// A coplanar line's parameters on the closed triangle, `[t_in, t_out]`,
/// with the edge values `A_i`, `B_i` and `n_k` the barycentrics come from.
struct Span {
    t_in: Fraction,
    t_out: Fraction,
    a: [W3; 3],
    b: [W3; 3],
    nk: W3,
}

impl Span {
    /// The first parameter of the span at or after `min` (finite or
    /// `-inf`), with `Some(min)` when it is `min` itself; `None` when the
    /// span ends before `min`.
    fn entry(&self, min: f64) -> Option<(Fraction, Option<f64>)> {
        if min == f64::NEG_INFINITY {
            return Some((self.t_in, None));
        }
        let m = Fraction::of_f64(min);
        if self.t_out.order(&m) == Ordering::Less {
            None
        } else if self.t_in.order(&m) == Ordering::Less {
            Some((m, Some(min)))
        } else {
            Some((self.t_in, None))
        }
    }

    /// The barycentric coordinates `(u, v)` of the point at `t`, rounded
    /// from exact fractions: `lambda_i = s (A_i + t B_i) / |n_k|` (the
    /// module docs' edge values sum to `n_k` everywhere in the plane), in
    /// `[0, 1]` and exactly zero on the edges the point lies on.
    fn barycentrics(&self, t: &Fraction) -> (f64, f64) {
        let den = W6::mul(&t.den, &self.nk);
        let lambda = |i: usize| {
            let num = W6::mul(&self.a[i], &t.den).add(&W6::mul(&t.num, &self.b[i]));
            round_quotient(num.rounded_parts(), den.rounded_parts()).clamp(0.0, 1.0)
        };
        (lambda(1), lambda(2))
    }
}

fn all_finite(points: &[DVec3]) -> bool {
    points.iter().all(|p| p.is_finite())
}

/// The hit of a ray lying in the plane of `tri` (all three edge signs
/// exactly zero) under the closed-triangle rule: where it enters the
/// closed triangle within `range`, `max(range.min, t_in)`, decided
/// exactly; its `t` is `range.min` itself where the ray's point there is
/// in the triangle, otherwise `t_in` rounded (within `4u`, `round_quotient`)
/// and kept inside `range` (moving it towards the exact value, which is
/// inside). `None` when the ray misses the triangle in `range`, for a
/// degenerate triangle, or when the entry's `t` is not finite.
#[cold]
#[inline(never)]
pub(super) fn coplanar_hit(tri: &Triangle, ray: &Ray, range: Interval) -> Option<TriangleHit> {
    let (o, d) = (ray.origin(), ray.direction());
    let pts = [o, d, tri.v[0], tri.v[1], tri.v[2]];
    if tri.degenerate || !all_finite(&pts) || range.min() == f64::INFINITY {
        return None;
    }
    let line = Line::of_ray(o, d, &tri.v, lows(&pts));
    let span = line.span()?;
    let (entry, at_min) = span.entry(range.min())?;
    if range.max() != f64::INFINITY
        && entry.order(&Fraction::of_f64(range.max())) == Ordering::Greater
    {
        return None;
    }
    let t = at_min.unwrap_or_else(|| entry.round().clamp(range.min(), range.max()));
    if !range.admits(t) {
        return None;
    }
    let (u, v) = span.barycentrics(&entry);
    Some(TriangleHit { t, u, v })
}

/// The exact first parameter in `range` at which the ray meets `tri`, for
/// a triangle the exact test hit: the crossing of its plane, or for a ray
/// in its plane the coplanar entry. `None` where there is none (not a
/// hit after all).
fn first_parameter(line: &Line, min: f64) -> Option<Fraction> {
    let (den, num) = line.crossing();
    if den.sign() != Sign::Zero {
        return Some(Fraction::new(num, den));
    }
    line.span()?.entry(min).map(|(t, _)| t)
}

/// The exact order of the first parameters in `range` at which `ray`
/// meets `a` and `b` (two triangles the exact test hit): `Less` when `a`'s
/// comes first, `Equal` for the same exact parameter. A triangle that
/// turns out not to be met sorts last.
#[cold]
#[inline(never)]
pub(super) fn exact_order(ray: &Ray, range: Interval, a: &Triangle, b: &Triangle) -> Ordering {
    let (o, d) = (ray.origin(), ray.direction());
    let pts = [o, d, a.v[0], a.v[1], a.v[2], b.v[0], b.v[1], b.v[2]];
    if !all_finite(&pts) || range.min() == f64::INFINITY {
        return Ordering::Equal;
    }
    let lo = lows(&pts);
    let ta = first_parameter(&Line::of_ray(o, d, &a.v, lo), range.min());
    let tb = first_parameter(&Line::of_ray(o, d, &b.v, lo), range.min());
    match (ta, tb) {
        (Some(x), Some(y)) => x.order(&y),
        (Some(_), None) => Ordering::Less,
        (None, Some(_)) => Ordering::Greater,
        (None, None) => Ordering::Equal,
    }
}

/// Whether the closed segment from `p` to `q` meets the closed triangle,
/// exactly: `p` and `q` not strictly on one side of its plane
/// (`orient3d`), and then, off the plane, the crossing inside the triangle
/// (the signs of `orient3d(p, q, v_j, v_m)` over the three edges not
/// mixed: they are the signs of the crossing's barycentric coordinates,
/// times one common sign), or, with both ends in the plane, the coplanar
/// span meeting `[0, 1]` (the line `p + t (q - p)`, `q - p` exact in
/// integers). A degenerate triangle is never met; `p == q` is met when
/// that point lies on the triangle.
pub(super) fn segment_meets(tri: &Triangle, p: DVec3, q: DVec3) -> bool {
    let [v0, v1, v2] = tri.v;
    if tri.degenerate || !all_finite(&[p, q, v0, v1, v2]) {
        return false;
    }
    let sp = orient3d(v0, v1, v2, p);
    let sq = orient3d(v0, v1, v2, q);
    if sp == sq && sp != Sign::Zero {
        return false;
    }
    if sp == Sign::Zero && sq == Sign::Zero {
        return coplanar_segment(tri, p, q);
    }
    let s = [(1, 2), (2, 0), (0, 1)].map(|(j, m)| orient3d(p, q, tri.v[j], tri.v[m]));
    !(s.contains(&Sign::Positive) && s.contains(&Sign::Negative))
}

/// [`segment_meets`] for a segment in the triangle's plane.
#[cold]
#[inline(never)]
fn coplanar_segment(tri: &Triangle, p: DVec3, q: DVec3) -> bool {
    let lo = lows(&[p, q, tri.v[0], tri.v[1], tri.v[2]]);
    let o = int(p, lo);
    if p == q {
        // A point: in the closed triangle when every edge value has the
        // triangle's sign or vanishes; the span of a zero direction is
        // not defined, so take the direction along an edge (any non-zero
        // vector of the plane): the point is met when the span holds 0.
        let line = Line {
            o,
            d: sub(&int(tri.v[1], lo), &int(tri.v[0], lo)),
            v: tri.v.map(|x| int(x, lo)),
        };
        return line.span().is_some_and(|s| {
            s.entry(0.0)
                .is_some_and(|(t, _)| t.order(&Fraction::of_f64(0.0)) == Ordering::Equal)
        });
    }
    let line = Line {
        o,
        d: sub(&int(q, lo), &o),
        v: tri.v.map(|x| int(x, lo)),
    };
    line.span().is_some_and(|s| {
        s.entry(0.0)
            .is_some_and(|(t, _)| t.order(&Fraction::of_f64(1.0)) != Ordering::Greater)
    })
}
