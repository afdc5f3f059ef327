//! The filter: the squared distance from a point to a closed triangle, and
//! the closest point, enclosed in intervals of `f64`.
//!
//! # Why the intervals hold the exact values
//! Every operation rounds to nearest, so its result is within half a
//! float step of the exact result of its operands (Higham, *Accuracy and
//! Stability of Numerical Algorithms*, 2nd ed., §2.1, subnormal results
//! included, whose step is `2^-1074`); one step down (`next_down`) and one
//! step up (`next_up`) of the result enclose it. An overflow to `inf`
//! steps down to `f64::MAX`, below the exact value, and stays `inf` above
//! it. So each operation on two intervals holding exact values gives an
//! interval holding the exact result (Moore's interval arithmetic with
//! outward rounding), with no bound to derive per formula. The inputs
//! are the coordinates scaled by the query's power of two, exact where
//! the scale is up (the largest scaled magnitude is below 1, so nothing
//! overflows) and within one step, so stepped out twice, where it is down
//! ([`scale_pow2`]). Products of operands below 2 in magnitude stay far
//! from overflow, and no operation meets `0 * inf` or `inf - inf` but a
//! division by an interval that holds zero, handled apart.
//!
//! # The squared distance to a closed triangle
//! It is the least of seven candidates, each the squared distance to an
//! actual point of the triangle where its condition holds: the three
//! vertices (always), the three edges' lines where the projection of `p`
//! falls inside the edge (`(p - a) . (b - a) >= 0` and
//! `(p - b) . (a - b) >= 0`, with `a != b`), and the plane where the projection of `p` falls
//! inside the triangle (the three edge sides `((b - a) x (p - a)) . n >= 0`
//! with `n = (v1 - v0) x (v2 - v0) != 0`). The closest point is a vertex,
//! inside an edge, or inside the face, and there the matching condition
//! holds; every candidate whose condition holds is the distance to a point
//! of the triangle, so at least the least one. With intervals, a condition
//! is certainly true, certainly false or unsure: the exact squared distance
//! lies between the least lower end over the candidates not certainly
//! false and the least upper end over those certainly true.

use crate::arith::exponent::scale_pow2;
use glam::DVec3;

/// A closed interval `[lo, hi]` of `f64` holding an exact real value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Bounds {
    pub(super) lo: f64,
    pub(super) hi: f64,
}

/// Three coordinates' intervals.
pub(super) type Vec3Bounds = [Bounds; 3];

impl Bounds {
    const ZERO: Bounds = Bounds { lo: 0.0, hi: 0.0 };
    const EVERYTHING: Bounds = Bounds {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// The interval of the exact `x 2^s`: `x` itself scaled where `s >= 0`
    /// (exact, the caller keeps the result below 1), stepped out twice
    /// where `s < 0` (see [`scale_pow2`]).
    #[inline(always)]
    pub(super) fn scaled(x: f64, s: i32) -> Bounds {
        let v = scale_pow2(x, s);
        if s >= 0 {
            Bounds { lo: v, hi: v }
        } else {
            Bounds {
                lo: v.next_down().next_down(),
                hi: v.next_up().next_up(),
            }
        }
    }

    /// The rounded result `lo` and `hi` stepped out.
    #[inline(always)]
    fn out(lo: f64, hi: f64) -> Bounds {
        Bounds {
            lo: lo.next_down(),
            hi: hi.next_up(),
        }
    }

    #[inline(always)]
    pub(super) fn add(self, o: Bounds) -> Bounds {
        Bounds::out(self.lo + o.lo, self.hi + o.hi)
    }

    #[inline(always)]
    pub(super) fn sub(self, o: Bounds) -> Bounds {
        Bounds::out(self.lo - o.hi, self.hi - o.lo)
    }

    #[inline(always)]
    pub(super) fn mul(self, o: Bounds) -> Bounds {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        let lo = p.iter().fold(f64::INFINITY, |m, &v| m.min(v));
        let hi = p.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v));
        Bounds::out(lo, hi)
    }

    /// The square, at least zero.
    #[inline(always)]
    pub(super) fn square(self) -> Bounds {
        let (l, h) = (self.lo * self.lo, self.hi * self.hi);
        if self.lo >= 0.0 {
            Bounds::out(l, h).floor_zero()
        } else if self.hi <= 0.0 {
            Bounds::out(h, l).floor_zero()
        } else {
            Bounds::out(0.0, l.max(h)).floor_zero()
        }
    }

    /// `self / d` for an exact divisor known positive where `d.lo > 0`;
    /// everything when `d` may be zero.
    #[inline(always)]
    pub(super) fn div(self, d: Bounds) -> Bounds {
        if d.lo <= 0.0 {
            return Bounds::EVERYTHING;
        }
        let q = [
            self.lo / d.lo,
            self.lo / d.hi,
            self.hi / d.lo,
            self.hi / d.hi,
        ];
        let lo = q.iter().fold(f64::INFINITY, |m, &v| m.min(v));
        let hi = q.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v));
        Bounds::out(lo, hi)
    }

    /// A squared length `n` over a squared length `d`, at least zero:
    /// `[0, inf]` where `d` may be zero.
    #[inline(always)]
    fn ratio(self, d: Bounds) -> Bounds {
        if d.lo <= 0.0 {
            return Bounds {
                lo: 0.0,
                hi: f64::INFINITY,
            };
        }
        Bounds::out(self.lo / d.hi, self.hi / d.lo).floor_zero()
    }

    #[inline(always)]
    fn floor_zero(self) -> Bounds {
        Bounds {
            lo: self.lo.max(0.0),
            hi: self.hi,
        }
    }

    /// The smallest interval holding both.
    #[inline(always)]
    pub(super) fn hull(self, o: Bounds) -> Bounds {
        Bounds {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }
}

/// Whether an exact condition `x >= 0` (or `x > 0`, `strict`) holds, on
/// the interval `x` lies in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Holds {
    Surely,
    Maybe,
    Never,
}

impl Holds {
    #[inline(always)]
    fn of(x: Bounds, strict: bool) -> Holds {
        let sure = if strict { x.lo > 0.0 } else { x.lo >= 0.0 };
        let never = if strict { x.hi <= 0.0 } else { x.hi < 0.0 };
        if sure {
            Holds::Surely
        } else if never {
            Holds::Never
        } else {
            Holds::Maybe
        }
    }

    #[inline(always)]
    fn and(self, o: Holds) -> Holds {
        match (self, o) {
            (Holds::Never, _) | (_, Holds::Never) => Holds::Never,
            (Holds::Surely, Holds::Surely) => Holds::Surely,
            _ => Holds::Maybe,
        }
    }
}

#[inline(always)]
pub(super) fn vsub(a: &Vec3Bounds, b: &Vec3Bounds) -> Vec3Bounds {
    [a[0].sub(b[0]), a[1].sub(b[1]), a[2].sub(b[2])]
}

#[inline(always)]
pub(super) fn dot(a: &Vec3Bounds, b: &Vec3Bounds) -> Bounds {
    a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]))
}

#[inline(always)]
fn norm2(a: &Vec3Bounds) -> Bounds {
    a[0].square().add(a[1].square()).add(a[2].square())
}

#[inline(always)]
pub(super) fn cross(a: &Vec3Bounds, b: &Vec3Bounds) -> Vec3Bounds {
    // Written out rather than built by index: the hot loop of a query.
    [
        a[1].mul(b[2]).sub(a[2].mul(b[1])),
        a[2].mul(b[0]).sub(a[0].mul(b[2])),
        a[0].mul(b[1]).sub(a[1].mul(b[0])),
    ]
}

/// One of the seven candidates: its condition, its squared distance and
/// its point.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    holds: Holds,
    d2: Bounds,
    point: Vec3Bounds,
}

/// A triangle's squared distance from the query and its closest point,
/// enclosed (see the module docs).
#[derive(Clone, Copy, Debug)]
pub(super) struct TriangleBounds {
    pub(super) d2: Bounds,
    pub(super) point: Vec3Bounds,
    /// The candidate that alone may be the least (`0..3` a vertex, `3..6`
    /// the edges `v0 v1`, `v1 v2`, `v2 v0`, `6` the plane), or `None`
    /// when several may be. The exact least one is among those not
    /// certainly false whose lower end is at most `d2.hi` (its exact value
    /// is at most `d2.hi`); when that is one candidate, the triangle's
    /// exact squared distance is that candidate's exact value.
    pub(super) sole: Option<u8>,
}

/// The candidate of vertex `v`.
#[inline(always)]
fn vertex(p: &Vec3Bounds, v: &Vec3Bounds) -> Candidate {
    Candidate {
        holds: Holds::Surely,
        d2: norm2(&vsub(p, v)),
        point: *v,
    }
}

/// The candidate of the edge from `a` to `b`'s line.
#[inline(always)]
fn edge<const POINT: bool>(p: &Vec3Bounds, a: &Vec3Bounds, b: &Vec3Bounds) -> Candidate {
    let e = vsub(b, a);
    let (pa, pb) = (vsub(p, a), vsub(p, b));
    let len2 = norm2(&e);
    let from_a = dot(&pa, &e);
    let from_b = dot(&pb, &vsub(a, b));
    let holds = Holds::of(from_a, false)
        .and(Holds::of(from_b, false))
        .and(Holds::of(len2, true));
    let point = if POINT {
        let t = from_a.div(len2);
        [0, 1, 2].map(|k| a[k].add(e[k].mul(t)))
    } else {
        [Bounds::ZERO; 3]
    };
    Candidate {
        holds,
        d2: norm2(&cross(&pa, &e)).ratio(len2),
        point,
    }
}

/// The candidate of the triangle's plane.
#[inline(always)]
fn face<const POINT: bool>(p: &Vec3Bounds, v: &[Vec3Bounds; 3]) -> Candidate {
    let n = cross(&vsub(&v[1], &v[0]), &vsub(&v[2], &v[0]));
    let nn = norm2(&n);
    let mut holds = Holds::of(nn, true);
    for i in 0..3 {
        let j = (i + 1) % 3;
        let side = dot(&cross(&vsub(&v[j], &v[i]), &vsub(p, &v[i])), &n);
        holds = holds.and(Holds::of(side, false));
    }
    let height = dot(&vsub(p, &v[0]), &n);
    let point = if POINT {
        let along = height.div(nn);
        [0, 1, 2].map(|k| p[k].sub(n[k].mul(along)))
    } else {
        [Bounds::ZERO; 3]
    };
    Candidate {
        holds,
        d2: height.square().ratio(nn),
        point,
    }
}

/// The enclosures of the squared distance from `p` to the closed triangle
/// `v` and, with `POINT`, of its closest point (every point whose
/// candidate may be the least one; zero without `POINT`, which a query
/// wants of its answer only).
pub(super) fn triangle_bounds<const POINT: bool>(
    p: &Vec3Bounds,
    v: &[Vec3Bounds; 3],
) -> TriangleBounds {
    let candidates = [
        vertex(p, &v[0]),
        vertex(p, &v[1]),
        vertex(p, &v[2]),
        edge::<POINT>(p, &v[0], &v[1]),
        edge::<POINT>(p, &v[1], &v[2]),
        edge::<POINT>(p, &v[2], &v[0]),
        face::<POINT>(p, v),
    ];
    let mut d2 = Bounds {
        lo: f64::INFINITY,
        hi: f64::INFINITY,
    };
    for c in &candidates {
        if c.holds != Holds::Never {
            d2.lo = d2.lo.min(c.d2.lo);
        }
        if c.holds == Holds::Surely {
            d2.hi = d2.hi.min(c.d2.hi);
        }
    }
    let mut point: Option<Vec3Bounds> = None;
    let mut sole = None;
    for (i, c) in candidates.iter().enumerate() {
        if c.holds != Holds::Never && c.d2.lo <= d2.hi {
            (point, sole) = match point {
                None => (Some(c.point), Some(i as u8)),
                Some(q) => (Some([0, 1, 2].map(|k| q[k].hull(c.point[k]))), None),
            };
        }
    }
    TriangleBounds {
        d2,
        // The candidate whose upper end is `d2.hi` holds surely (a vertex
        // always does) and its lower end is at most `d2.hi`: never empty.
        point: point.unwrap_or([Bounds::ZERO; 3]),
        sole,
    }
}

/// The world coordinates of `v` scaled by `2^s`, enclosed.
#[inline(always)]
pub(super) fn scaled_point(v: DVec3, s: i32) -> Vec3Bounds {
    [0, 1, 2].map(|k| Bounds::scaled(v[k], s))
}
