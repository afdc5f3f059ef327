//! The exact stage: the squared distance from a point to a closed triangle
//! as a fraction of integers, for the near ties the filter
//! (`bounds.rs`) cannot order.
//!
//! Every coordinate of the query (the point, the triangles' vertices, a
//! distance bound) is an integer multiple of the finest bit among them,
//! `2^lo` ([`Grain`]); the squared distance, scaled by `2^(-2 lo)`, is
//! then the least of the seven candidates of `bounds.rs` whose condition
//! holds, each a fraction `num / den` with `den > 0`: a vertex `|p -
//! a|^2 / 1`, an edge's line `|(p - a) x (b - a)|^2 / |b - a|^2`, the
//! plane `((p - v0) . n)^2 / |n|^2`. Conditions are signs of integer
//! polynomials, fractions are compared by cross multiplication, all in
//! fixed-size stack integers ([`FixedInt`]): no rounding anywhere.
//!
//! Degrees, in coordinate differences of up to `2^2099` units
//! ([`limbs_of_degree`]): numerators up to 6 (the plane's), denominators
//! up to 4, cross products of two fractions 10.

use crate::arith::exponent::Grain;
use crate::arith::fixed_int::{DEG1, DEG2, DEG4, FixedInt, cross3, limbs_of_degree};
use crate::sign::Sign;
use glam::DVec3;

const DEG6: usize = limbs_of_degree(6);
const DEG10: usize = limbs_of_degree(10);

type Coord = [FixedInt<DEG1>; 3];

/// A squared distance `num / den`, `den > 0`.
struct Ratio {
    num: FixedInt<DEG6>,
    den: FixedInt<DEG4>,
}

impl Ratio {
    /// The sign of `self - other`.
    fn cmp(&self, other: &Ratio) -> Sign {
        let a = FixedInt::<DEG10>::mul(&self.num, &other.den);
        let b = FixedInt::<DEG10>::mul(&other.num, &self.den);
        a.sub(&b).sign()
    }
}

fn diff(a: &Coord, b: &Coord) -> Coord {
    core::array::from_fn(|k| a[k].sub(&b[k]))
}

fn dot<const A: usize, const B: usize, const R: usize>(
    x: &[FixedInt<A>; 3],
    y: &[FixedInt<B>; 3],
) -> FixedInt<R> {
    (0..3).fold(FixedInt::<R>::ZERO, |s, k| {
        s.add(&FixedInt::<R>::mul(&x[k], &y[k]))
    })
}

fn vertex(p: &Coord, v: &Coord) -> Ratio {
    let pv = diff(p, v);
    Ratio {
        num: dot::<DEG1, DEG1, DEG2>(&pv, &pv).widen(),
        den: FixedInt::from_i64(1),
    }
}

/// The edge from `a` to `b`'s line, where the projection of `p` falls
/// inside the edge (`a != b`).
fn edge(p: &Coord, a: &Coord, b: &Coord) -> Option<Ratio> {
    let e = diff(b, a);
    let pa = diff(p, a);
    let len2: FixedInt<DEG2> = dot(&e, &e);
    let from_a: FixedInt<DEG2> = dot(&pa, &e);
    let from_b: FixedInt<DEG2> = dot(&diff(p, b), &diff(a, b));
    if len2.sign() != Sign::Positive || from_a.is_negative() || from_b.is_negative() {
        return None;
    }
    let c: [FixedInt<DEG2>; 3] = cross3(&pa, &e);
    Some(Ratio {
        num: dot::<DEG2, DEG2, DEG4>(&c, &c).widen(),
        den: len2.widen(),
    })
}

/// The plane, where the projection of `p` falls inside the triangle.
fn face(p: &Coord, v: &[Coord; 3]) -> Option<Ratio> {
    let n: [FixedInt<DEG2>; 3] = cross3(&diff(&v[1], &v[0]), &diff(&v[2], &v[0]));
    let nn: FixedInt<DEG4> = dot(&n, &n);
    if nn.sign() != Sign::Positive {
        return None;
    }
    for i in 0..3 {
        let j = (i + 1) % 3;
        let c: [FixedInt<DEG2>; 3] = cross3(&diff(&v[j], &v[i]), &diff(p, &v[i]));
        if dot::<DEG2, DEG2, DEG4>(&c, &n).is_negative() {
            return None;
        }
    }
    let height: FixedInt<DEG4> = dot(&diff(p, &v[0]), &n);
    Some(Ratio {
        num: FixedInt::mul(&height, &height),
        den: nn,
    })
}

/// The exact squared distance from `p` to the closed triangle `v`.
fn least(p: &Coord, v: &[Coord; 3]) -> Ratio {
    let mut best = vertex(p, &v[0]);
    let mut take = |c: Ratio| {
        if c.cmp(&best) == Sign::Negative {
            best = c;
        }
    };
    take(vertex(p, &v[1]));
    take(vertex(p, &v[2]));
    for (i, j) in [(0, 1), (1, 2), (2, 0)] {
        if let Some(c) = edge(p, &v[i], &v[j]) {
            take(c);
        }
    }
    if let Some(c) = face(p, v) {
        take(c);
    }
    best
}

/// Every coordinate as an integer multiple of the finest bit of all of
/// `values` (finite), `2^lo`; `None` when all are zero.
fn grain_of(values: &[f64]) -> Option<i32> {
    let grain = Grain::of(values);
    (!grain.all_zero()).then_some(grain.lo_min)
}

fn coord(v: DVec3, lo: i32) -> Coord {
    core::array::from_fn(|k| FixedInt::from_f64(v[k], lo))
}

fn triangle(t: &[DVec3; 3], lo: i32) -> [Coord; 3] {
    t.map(|v| coord(v, lo))
}

fn values_of(p: DVec3, triangles: &[&[DVec3; 3]]) -> ([f64; 21], usize) {
    let mut values = [0.0; 21];
    values[..3].copy_from_slice(&p.to_array());
    let mut n = 3;
    for t in triangles {
        for v in t.iter() {
            values[n..n + 3].copy_from_slice(&v.to_array());
            n += 3;
        }
    }
    (values, n)
}

/// The exact sign of `d(p, s)^2 - d(p, t)^2` for closed triangles `s` and
/// `t`, every coordinate finite.
#[cold]
#[inline(never)]
pub(super) fn compare(p: DVec3, s: &[DVec3; 3], t: &[DVec3; 3]) -> Sign {
    let (values, n) = values_of(p, &[s, t]);
    let Some(lo) = grain_of(&values[..n]) else {
        return Sign::Zero;
    };
    let q = coord(p, lo);
    least(&q, &triangle(s, lo)).cmp(&least(&q, &triangle(t, lo)))
}

/// Whether `d(p, t) <= max` exactly, for a finite `max >= 0` and finite
/// coordinates.
#[cold]
#[inline(never)]
pub(super) fn within(p: DVec3, t: &[DVec3; 3], max: f64) -> bool {
    let (mut values, n) = values_of(p, &[t]);
    values[n] = max;
    let Some(lo) = grain_of(&values[..n + 1]) else {
        return true;
    };
    let d = least(&coord(p, lo), &triangle(t, lo));
    let m = FixedInt::<DEG1>::from_f64(max, lo);
    let m2 = FixedInt::<DEG2>::mul(&m, &m);
    let bound = FixedInt::<DEG10>::mul(&m2, &d.den);
    d.num.widen::<DEG10>().sub(&bound).sign() != Sign::Positive
}
