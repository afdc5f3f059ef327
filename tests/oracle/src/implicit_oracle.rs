//! Exact answers for predicates on constructed points: line–plane,
//! three-plane and line–line intersections as exact rational points, and
//! orientation and order of those, in big integers.
//!
//! Every input coordinate of one call is brought to the smallest exponent
//! among them (a common positive factor, which no predicate's sign sees).
//! A constructed point is then a rational point `num / den` over the
//! integers: the line–plane point from the line's parameter `t = n . (r -
//! p) / n . (q - p)`, the three-plane and line–line points by Cramer's
//! rule. The predicates take differences of those rationals, so they
//! share no formula with the crate's homogeneous coordinates beyond the
//! constructions' definitions.

use crate::oracle::common_integers;
use core::cmp::Ordering;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// A 3D point of a predicate: explicit, or constructed from its inputs.
#[derive(Clone, Copy, Debug)]
pub enum Pt3 {
    /// An input point.
    E([f64; 3]),
    /// The line through the first two points meets the plane through the
    /// other three.
    Lpi([[f64; 3]; 5]),
    /// The common point of the planes through each three points.
    Tpi([[[f64; 3]; 3]; 3]),
}

/// A 2D point of a predicate: explicit, or the line through the first two
/// points meets the line through the other two.
#[derive(Clone, Copy, Debug)]
pub enum Pt2 {
    /// An input point.
    E([f64; 2]),
    /// The intersection of two lines.
    Ssi([[f64; 2]; 4]),
}

/// A rational point `num / den`, `den != 0`.
#[derive(Clone, Debug)]
pub struct Rational<const D: usize> {
    pub num: [BigInt; D],
    pub den: BigInt,
}

type V3 = [BigInt; 3];

fn sub<const D: usize>(a: &[BigInt; D], b: &[BigInt; D]) -> [BigInt; D] {
    core::array::from_fn(|k| &a[k] - &b[k])
}

fn cross(a: &V3, b: &V3) -> V3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot(a: &V3, b: &V3) -> BigInt {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn det3(r: [&V3; 3]) -> BigInt {
    dot(r[0], &cross(r[1], r[2]))
}

fn sign(v: &BigInt) -> i8 {
    if v.is_zero() {
        0
    } else if v.is_positive() {
        1
    } else {
        -1
    }
}

/// Integers of one call: its flattened inputs at their common exponent,
/// taken in order.
struct Ints(Vec<BigInt>, usize);

impl Ints {
    fn new(values: &[f64]) -> Self {
        Ints(common_integers(values), 0)
    }

    fn take<const D: usize>(&mut self) -> [BigInt; D] {
        let v = core::array::from_fn(|k| self.0[self.1 + k].clone());
        self.1 += D;
        v
    }
}

fn flat3(points: &[Pt3]) -> Vec<f64> {
    let mut out = Vec::new();
    for p in points {
        match p {
            Pt3::E(v) => out.extend(v),
            Pt3::Lpi(v) => out.extend(v.as_flattened()),
            Pt3::Tpi(v) => out.extend(v.as_flattened().as_flattened()),
        }
    }
    out
}

fn flat2(points: &[Pt2]) -> Vec<f64> {
    let mut out = Vec::new();
    for p in points {
        match p {
            Pt2::E(v) => out.extend(v),
            Pt2::Ssi(v) => out.extend(v.as_flattened()),
        }
    }
    out
}

/// The rational point of `p` (its inputs next in `ints`); `None` for a
/// construction that is not one point.
fn rational3(p: &Pt3, ints: &mut Ints) -> Option<Rational<3>> {
    match p {
        Pt3::E(_) => Some(Rational {
            num: ints.take(),
            den: BigInt::one(),
        }),
        Pt3::Lpi(_) => {
            let [p, q, r, s, t] = [(); 5].map(|_| ints.take::<3>());
            let n = cross(&sub(&s, &r), &sub(&t, &r));
            let e = sub(&q, &p);
            let (den, tn) = (dot(&n, &e), dot(&n, &sub(&r, &p)));
            // X = p + (tn / den) e.
            (!den.is_zero()).then(|| Rational {
                num: core::array::from_fn(|k| &p[k] * &den + &e[k] * &tn),
                den,
            })
        }
        Pt3::Tpi(_) => {
            let planes = [(); 3].map(|_| [(); 3].map(|_| ints.take::<3>()));
            // Row i: n_i . X = d_i.
            let n = planes
                .each_ref()
                .map(|[a, b, c]| cross(&sub(b, a), &sub(c, a)));
            let d: V3 = core::array::from_fn(|i| dot(&n[i], &planes[i][0]));
            let den = det3([&n[0], &n[1], &n[2]]);
            // Cramer: column k of the matrix replaced by d.
            let num = core::array::from_fn(|k| {
                let m: [V3; 3] = core::array::from_fn(|i| {
                    core::array::from_fn(|j| {
                        if j == k {
                            d[i].clone()
                        } else {
                            n[i][j].clone()
                        }
                    })
                });
                det3([&m[0], &m[1], &m[2]])
            });
            (!den.is_zero()).then_some(Rational { num, den })
        }
    }
}

fn rational2(p: &Pt2, ints: &mut Ints) -> Option<Rational<2>> {
    match p {
        Pt2::E(_) => Some(Rational {
            num: ints.take(),
            den: BigInt::one(),
        }),
        Pt2::Ssi(_) => {
            let [p, q, r, s] = [(); 4].map(|_| ints.take::<2>());
            // Lines a . X = c: a = (y2 - y1, x1 - x2), c = a . (x1, y1).
            let line = |u: &[BigInt; 2], v: &[BigInt; 2]| {
                let a = [&v[1] - &u[1], &u[0] - &v[0]];
                let c = &a[0] * &u[0] + &a[1] * &u[1];
                (a, c)
            };
            let ((a1, c1), (a2, c2)) = (line(&p, &q), line(&r, &s));
            let den = &a1[0] * &a2[1] - &a1[1] * &a2[0];
            let num = [&c1 * &a2[1] - &a1[1] * &c2, &a1[0] * &c2 - &c1 * &a2[0]];
            (!den.is_zero()).then_some(Rational { num, den })
        }
    }
}

fn rationals3<const K: usize>(points: &[Pt3; K]) -> Option<[Rational<3>; K]> {
    let mut ints = Ints::new(&flat3(points));
    let r: Vec<_> = points.iter().map(|p| rational3(p, &mut ints)).collect();
    r.into_iter().collect::<Option<Vec<_>>>()?.try_into().ok()
}

fn rationals2<const K: usize>(points: &[Pt2; K]) -> Option<[Rational<2>; K]> {
    let mut ints = Ints::new(&flat2(points));
    let r: Vec<_> = points.iter().map(|p| rational2(p, &mut ints)).collect();
    r.into_iter().collect::<Option<Vec<_>>>()?.try_into().ok()
}

/// `B - A` as `(num, den)` with `den = den_A den_B`.
fn difference<const D: usize>(a: &Rational<D>, b: &Rational<D>) -> ([BigInt; D], BigInt) {
    (
        core::array::from_fn(|k| &b.num[k] * &a.den - &a.num[k] * &b.den),
        &a.den * &b.den,
    )
}

/// Whether the construction is one point: `Some(sign of its weight)`
/// (the denominator above), `0` when it is not.
pub fn weight_sign3(p: &Pt3) -> i8 {
    rationals3(&[*p]).map_or(0, |[r]| sign(&r.den))
}

/// [`weight_sign3`] in the plane.
pub fn weight_sign2(p: &Pt2) -> i8 {
    rationals2(&[*p]).map_or(0, |[r]| sign(&r.den))
}

/// `det[b - a, c - a, d - a]` of the exact points; `None` when a
/// construction is not one point.
pub fn orient3d(p: [Pt3; 4]) -> Option<i8> {
    let [a, b, c, d] = rationals3(&p)?;
    let rows = [b, c, d].map(|x| difference(&a, &x));
    let s = sign(&det3([&rows[0].0, &rows[1].0, &rows[2].0]));
    Some(rows.iter().fold(s, |s, r| s * sign(&r.1)))
}

fn det2(x: &[BigInt; 2], y: &[BigInt; 2]) -> BigInt {
    &x[0] * &y[1] - &x[1] * &y[0]
}

/// `(b - a) x (c - a)` of the exact points.
pub fn orient2d(p: [Pt2; 3]) -> Option<i8> {
    let [a, b, c] = rationals2(&p)?;
    let rows = [b, c].map(|x| difference(&a, &x));
    let s = sign(&det2(&rows[0].0, &rows[1].0));
    Some(rows.iter().fold(s, |s, r| s * sign(&r.1)))
}

/// Component `drop` of `(b - a) x (c - a)` of the exact points: orient2d
/// of their projections onto the axes `drop + 1`, `drop + 2` (cyclically).
pub fn orient2d_projected(p: [Pt3; 3], drop: usize) -> Option<i8> {
    let [a, b, c] = rationals3(&p)?;
    let rows = [b, c].map(|x| difference(&a, &x));
    let pr = |v: &V3| [v[(drop + 1) % 3].clone(), v[(drop + 2) % 3].clone()];
    let s = sign(&det2(&pr(&rows[0].0), &pr(&rows[1].0)));
    Some(rows.iter().fold(s, |s, r| s * sign(&r.1)))
}

fn ordering(s: i8) -> Ordering {
    s.cmp(&0)
}

/// `x[axis]` against `y[axis]` for exact points.
pub fn cmp_on_axis3(x: Pt3, y: Pt3, axis: usize) -> Option<Ordering> {
    let [x, y] = rationals3(&[x, y])?;
    let (d, den) = difference(&y, &x);
    Some(ordering(sign(&d[axis]) * sign(&den)))
}

/// `x[axis]` against `y[axis]` for exact points of the plane.
pub fn cmp_on_axis2(x: Pt2, y: Pt2, axis: usize) -> Option<Ordering> {
    let [x, y] = rationals2(&[x, y])?;
    let (d, den) = difference(&y, &x);
    Some(ordering(sign(&d[axis]) * sign(&den)))
}

/// `(x - p) . (q - p)` against `(y - p) . (q - p)`: `Less` when `x` comes
/// first along the line from `p` to `q`.
pub fn cmp_along3(p: [f64; 3], q: [f64; 3], x: Pt3, y: Pt3) -> Option<Ordering> {
    let [p, q, x, y] = rationals3(&[Pt3::E(p), Pt3::E(q), x, y])?;
    let (dir, _) = difference(&p, &q);
    let (xy, den) = difference(&x, &y);
    // (y - x) . dir > 0: x first.
    Some(ordering(-sign(&dot(&xy, &dir)) * sign(&den)))
}

/// [`cmp_along3`] in the plane.
pub fn cmp_along2(p: [f64; 2], q: [f64; 2], x: Pt2, y: Pt2) -> Option<Ordering> {
    let [p, q, x, y] = rationals2(&[Pt2::E(p), Pt2::E(q), x, y])?;
    let (dir, _) = difference(&p, &q);
    let (xy, den) = difference(&x, &y);
    let d = &xy[0] * &dir[0] + &xy[1] * &dir[1];
    Some(ordering(-sign(&d) * sign(&den)))
}
