//! Exact oracle for the predicates, independent of the crate's arithmetic.
//!
//! Every finite f64 is exactly `m * 2^e` with integer `m`. All coordinates of
//! one predicate call are brought to the smallest exponent among them, which
//! multiplies every coordinate by the same power of two; the predicates are
//! homogeneous polynomials in the coordinates, so the sign of the integer
//! polynomial is the sign of the exact real one. Integers are `num_bigint`.

use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// `v = m * 2^e` exactly, for finite `v`.
pub fn exact_parts(v: f64) -> (BigInt, i32) {
    assert!(v.is_finite(), "the oracle takes finite values only");
    let bits = v.to_bits();
    let exp_field = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    let (m, e) = if exp_field == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp_field - 1075)
    };
    let m = BigInt::from(m);
    (if bits >> 63 == 1 { -m } else { m }, e)
}

/// The values as integers at their common (smallest) exponent.
pub fn common_integers(values: &[f64]) -> Vec<BigInt> {
    common_integers_at(values).0
}

/// The values as integers at their common (smallest) exponent `e`, and
/// `e`: value `i` is `integers[i] * 2^e`.
pub fn common_integers_at(values: &[f64]) -> (Vec<BigInt>, i32) {
    let parts: Vec<_> = values.iter().map(|&v| exact_parts(v)).collect();
    let emin = parts.iter().map(|p| p.1).min().unwrap_or(0);
    let ints = parts
        .into_iter()
        .map(|(m, e)| m << ((e - emin) as usize))
        .collect();
    (ints, emin)
}

/// A predicate's determinant exactly, as `(n, e)`: the value `n * 2^e`.
pub type ExactValue = (BigInt, i32);

fn sign(v: &BigInt) -> i8 {
    if v.is_zero() {
        0
    } else if v.is_positive() {
        1
    } else {
        -1
    }
}

fn det2(a: &BigInt, b: &BigInt, c: &BigInt, d: &BigInt) -> BigInt {
    a * d - b * c
}

fn det3(m: &[[BigInt; 3]; 3]) -> BigInt {
    &m[0][0] * det2(&m[1][1], &m[1][2], &m[2][1], &m[2][2])
        - &m[0][1] * det2(&m[1][0], &m[1][2], &m[2][0], &m[2][2])
        + &m[0][2] * det2(&m[1][0], &m[1][1], &m[2][0], &m[2][1])
}

fn det4(m: &[[BigInt; 4]; 4]) -> BigInt {
    let mut total = BigInt::zero();
    for col in 0..4 {
        let minor: [[BigInt; 3]; 3] = core::array::from_fn(|r| {
            core::array::from_fn(|c| m[r + 1][if c < col { c } else { c + 1 }].clone())
        });
        let term = &m[0][col] * det3(&minor);
        if col % 2 == 0 {
            total += term;
        } else {
            total -= term;
        }
    }
    total
}

/// Sign of `(b - a) x (c - a)`.
pub fn orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> i8 {
    sign(&orient2d_value(a, b, c).0)
}

/// `(b - a) x (c - a)` exactly (degree 2 in the common integers).
pub fn orient2d_value(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> ExactValue {
    let (v, e) = common_integers_at(&[a[0], a[1], b[0], b[1], c[0], c[1]]);
    let (bx, by) = (&v[2] - &v[0], &v[3] - &v[1]);
    let (cx, cy) = (&v[4] - &v[0], &v[5] - &v[1]);
    (det2(&bx, &by, &cx, &cy), 2 * e)
}

/// Sign of `det[b - a, c - a, d - a]` (CGAL's orientation).
pub fn orient3d(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> i8 {
    sign(&orient3d_value(a, b, c, d).0)
}

/// `det[b - a, c - a, d - a]` exactly (degree 3).
pub fn orient3d_value(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> ExactValue {
    let (v, e) = common_integers_at(&[a, b, c, d].concat());
    let row = |p: usize| -> [BigInt; 3] { core::array::from_fn(|k| &v[3 * p + k] - &v[k]) };
    (det3(&[row(1), row(2), row(3)]), 3 * e)
}

/// Sign of `det[[a-d, |a-d|^2], [b-d, |b-d|^2], [c-d, |c-d|^2]]`: positive
/// when `d` is inside the circle through counterclockwise `a, b, c`.
pub fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> i8 {
    sign(&incircle_value(a, b, c, d).0)
}

/// The in-circle determinant of [`incircle`] exactly (degree 4).
pub fn incircle_value(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> ExactValue {
    let (v, e) = common_integers_at(&[a, b, c, d].concat());
    let row = |p: usize| -> [BigInt; 3] {
        let x = &v[2 * p] - &v[6];
        let y = &v[2 * p + 1] - &v[7];
        let lift = &x * &x + &y * &y;
        [x, y, lift]
    };
    (det3(&[row(0), row(1), row(2)]), 4 * e)
}

/// Sign of `-det[[a-e, |a-e|^2], ..., [d-e, |d-e|^2]]`: positive when `e` is
/// inside the sphere through `a, b, c, d` with `orient3d(a, b, c, d) > 0`.
pub fn insphere(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3], e: [f64; 3]) -> i8 {
    sign(&insphere_value(a, b, c, d, e).0)
}

/// The in-sphere determinant of [`insphere`] exactly, with its sign
/// (`-det[...]`, degree 5).
pub fn insphere_value(
    a: [f64; 3],
    b: [f64; 3],
    c: [f64; 3],
    d: [f64; 3],
    e: [f64; 3],
) -> ExactValue {
    let (v, exp) = common_integers_at(&[a, b, c, d, e].concat());
    let row = |p: usize| -> [BigInt; 4] {
        let x = &v[3 * p] - &v[12];
        let y = &v[3 * p + 1] - &v[13];
        let z = &v[3 * p + 2] - &v[14];
        let lift = &x * &x + &y * &y + &z * &z;
        [x, y, z, lift]
    };
    (-det4(&[row(0), row(1), row(2), row(3)]), 5 * exp)
}

/// `sign(orient3d(x0, x1, x2, p)) * sign(orient3d(x0, x1, x2, q))`: `1` same
/// side, `-1` opposite sides, `0` on the plane or degenerate triangle.
pub fn plane_side(x0: [f64; 3], x1: [f64; 3], x2: [f64; 3], p: [f64; 3], q: [f64; 3]) -> i8 {
    orient3d(x0, x1, x2, p) * orient3d(x0, x1, x2, q)
}

/// The exact ordering of `|p - q|` and `|r - q|` (of their squares, which
/// order alike): `Less` when `p` is strictly nearer to `q` than `r` is.
pub fn compare_distance(q: [f64; 3], p: [f64; 3], r: [f64; 3]) -> core::cmp::Ordering {
    let v = common_integers(&[q, p, r].concat());
    let squared = |o: usize| -> BigInt {
        (0..3)
            .map(|k| {
                let d = &v[o + k] - &v[k];
                &d * &d
            })
            .sum()
    };
    squared(3).cmp(&squared(6))
}

/// `v = m * 2^e` exactly with `m` odd; `None` for zero.
fn odd_parts(v: f64) -> Option<(BigInt, i32)> {
    let (m, e) = exact_parts(v);
    let zeros = m.trailing_zeros()?;
    Some((m >> zeros, e + zeros as i32))
}

/// `v * 2^-exp`, which must be an integer.
fn integer_at(v: f64, exp: i32) -> BigInt {
    match odd_parts(v) {
        None => BigInt::zero(),
        Some((m, e)) => m << usize::try_from(e - exp).expect("exp is at most v's exponent"),
    }
}

/// The smallest exponent among the nonzero values (`None` if all are zero).
fn min_exponent(values: &[f64]) -> Option<i32> {
    values
        .iter()
        .filter_map(|&v| odd_parts(v))
        .map(|p| p.1)
        .min()
}

/// One point set for exact nearest-point answers to many queries: every
/// coordinate is an integer at the set's smallest exponent, converted once.
/// Zeros and trailing zero bits do not lower that exponent, so a set of small
/// integers stays small integers.
pub struct ExactPointSet {
    /// The coordinates times `2^-exp`.
    coords: Vec<[BigInt; 3]>,
    exp: i32,
}

impl ExactPointSet {
    pub fn new(points: &[[f64; 3]]) -> Self {
        let exp = min_exponent(points.as_flattened()).unwrap_or(0);
        let coords = points
            .iter()
            .map(|p| p.map(|v| integer_at(v, exp)))
            .collect();
        ExactPointSet { coords, exp }
    }

    /// Every index whose point is at exactly the smallest distance from `q`,
    /// ascending; empty for an empty set.
    pub fn nearest(&self, q: [f64; 3]) -> Vec<usize> {
        // The query's coordinates may need a smaller exponent than the set's:
        // then the points' integers are shifted up by the difference.
        let exp = min_exponent(&q).map_or(self.exp, |e| e.min(self.exp));
        let up = (self.exp - exp) as usize;
        let q = q.map(|v| integer_at(v, exp));
        let mut best = Vec::new();
        let mut best_d = BigInt::zero();
        'points: for (i, p) in self.coords.iter().enumerate() {
            let mut d = BigInt::zero();
            for k in 0..3 {
                let x = if up == 0 {
                    &p[k] - &q[k]
                } else {
                    (&p[k] << up) - &q[k]
                };
                // |x| >= 2^(bits - 1), so x^2 >= 2^(2 bits - 2); when that is
                // at least 2^best_d.bits() > best_d, the point is farther
                // than the best one: skip the multiplications.
                if !best.is_empty() && 2 * x.bits() >= best_d.bits() + 2 {
                    continue 'points;
                }
                d += &x * &x;
            }
            match (best.is_empty(), d.cmp(&best_d)) {
                (true, _) | (false, core::cmp::Ordering::Less) => {
                    best.clear();
                    best.push(i);
                    best_d = d;
                }
                (false, core::cmp::Ordering::Equal) => best.push(i),
                (false, core::cmp::Ordering::Greater) => {}
            }
        }
        best
    }
}

/// Whether `|p - q| <= r`, exactly: a ball of radius 0.
pub fn within(q: [f64; 3], p: [f64; 3], r: f64) -> bool {
    ball_within(q, (p, 0.0), r)
}

/// The exact ordering of the distances from `q` to two balls,
/// `max(0, |c - q| - r)`, by squaring out the roots: for both outside,
/// `sqrt(a) - r1` against `sqrt(b) - r2` is the sign of
/// `sqrt(a) - sqrt(b) - k` with `k = r1 - r2`.
pub fn compare_ball_distance(
    q: [f64; 3],
    (c1, r1): ([f64; 3], f64),
    (c2, r2): ([f64; 3], f64),
) -> core::cmp::Ordering {
    use core::cmp::Ordering::*;
    let v = common_integers(&[&q[..], &c1[..], &c2[..], &[r1, r2]].concat());
    let sq = |o: usize| -> BigInt {
        (0..3)
            .map(|k| (&v[o + k] - &v[k]) * (&v[o + k] - &v[k]))
            .sum()
    };
    let (a, b, r1, r2) = (sq(3), sq(6), v[9].clone(), v[10].clone());
    let (in1, in2) = (a <= &r1 * &r1, b <= &r2 * &r2);
    match (in1, in2) {
        (true, true) => return Equal,
        (true, false) => return Less,
        (false, true) => return Greater,
        _ => {}
    }
    // sign(sqrt(x) - sqrt(y) - k), k >= 0.
    let cmp = |x: &BigInt, y: &BigInt, k: &BigInt| {
        let m = x - y - k * k;
        if m.is_negative() {
            Less
        } else if m.is_zero() {
            if k.is_zero() || y.is_zero() {
                Equal
            } else {
                Less
            }
        } else {
            (&m * &m).cmp(&(BigInt::from(4) * k * k * y))
        }
    };
    let k = &r1 - &r2;
    if k.is_negative() {
        cmp(&b, &a, &-k).reverse()
    } else {
        cmp(&a, &b, &k)
    }
}

/// Whether the ball `(c, rc)` comes within `r` of `q`: `|c - q| <= r + rc`.
pub fn ball_within(q: [f64; 3], (c, rc): ([f64; 3], f64), r: f64) -> bool {
    let v = common_integers(&[&q[..], &c[..], &[r, rc]].concat());
    let d2: BigInt = (0..3)
        .map(|k| (&v[3 + k] - &v[k]) * (&v[3 + k] - &v[k]))
        .sum();
    let sum = &v[6] + &v[7];
    d2 <= &sum * &sum
}

/// The exact sign of `sum_k coeffs[k] x^(d - k)`, `d = coeffs.len() - 1`.
/// Over the smallest exponent `e` every number is `N 2^e`, and term `k` is
/// `C_k X^(d-k) 2^(e (1 + d - k))`. Divided by the positive `2^(e (1 + d))`
/// (for `e <= 0`) or `2^e` (for `e > 0`), each term is an integer:
/// `C_k X^(d-k) 2^(-e k)` or `C_k X^(d-k) 2^(e (d - k))`.
pub fn polynomial_sign(coeffs: &[f64], x: f64) -> i8 {
    weighted_polynomial_sign(coeffs, &vec![1; coeffs.len()], x)
}

/// [`polynomial_sign`] with each coefficient multiplied by an integer
/// weight first (so that `2a` cannot overflow).
pub fn weighted_polynomial_sign(coeffs: &[f64], weights: &[i64], x: f64) -> i8 {
    let values: Vec<f64> = coeffs.iter().copied().chain([x]).collect();
    let e = values.iter().map(|&v| exact_parts(v).1).min().unwrap() as i64;
    let v = common_integers(&values);
    let d = coeffs.len() as i64 - 1;
    let x = &v[coeffs.len()];
    let total: BigInt = (0..=d)
        .map(|k| {
            let term = &v[k as usize] * weights[k as usize] * x.pow((d - k) as u32);
            let shift = if e <= 0 { -e * k } else { e * (d - k) };
            term << shift as usize
        })
        .sum();
    sign(&total)
}

/// The exact sign of `b^2 - 4ac`.
pub fn discriminant_sign(a: f64, b: f64, c: f64) -> i8 {
    let v = common_integers(&[a, b, c]);
    sign(&(&v[1] * &v[1] - BigInt::from(4) * &v[0] * &v[2]))
}

/// `t` moved by `k` ulps (finite results only; the caller keeps away from
/// the largest values).
fn ulps_from(t: f64, k: i64) -> f64 {
    // Order-preserving map of the bits to integers, stepped, mapped back.
    let bits = t.to_bits() as i64;
    let ordered = if bits < 0 { i64::MIN - bits } else { bits };
    let moved = ordered + k;
    f64::from_bits((if moved < 0 { i64::MIN - moved } else { moved }) as u64)
}

/// Whether `a t^2 + b t + c` (`a != 0`) has an exact root within `k` ulps
/// of `t`: it changes sign across `[t - k ulps, t + k ulps]`, or its vertex
/// (where `2a x + b` changes sign) lies there and the discriminant is not
/// negative.
pub fn quadratic_root_near(a: f64, b: f64, c: f64, t: f64, k: i64) -> bool {
    let (lo, hi) = (ulps_from(t, -k), ulps_from(t, k));
    let value = |x: f64| polynomial_sign(&[a, b, c], x);
    if value(lo) * value(hi) <= 0 {
        return true;
    }
    let slope = |x: f64| weighted_polynomial_sign(&[a, b], &[2, 1], x);
    slope(lo) * slope(hi) <= 0 && discriminant_sign(a, b, c) >= 0
}

/// The exact meeting of the line `o + t d` with the closed triangle `v`:
/// `None` when the line misses it, or lies in its plane (`coplanar`);
/// otherwise the parameter `t = num / den` (`den > 0`) of the crossing.
pub struct LineTriangle {
    /// The line lies in the triangle's plane (the three signs are zero).
    pub coplanar: bool,
    /// `(num, den)` of the crossing's parameter, when the line meets the
    /// triangle off its plane.
    pub t: Option<(BigInt, BigInt)>,
    /// The line meets the triangle's front: `det[d, v1 - v0, v2 - v0] < 0`,
    /// the direction against the normal of the counterclockwise order.
    pub front: bool,
}

/// The signs of `det[d, v_j - o, v_k - o]` over the edges `(1, 2), (2, 0),
/// (0, 1)` decide whether the line crosses the triangle (all `>= 0` or all
/// `<= 0`, not all zero); `t = det[v0 - o, v1 - v0, v2 - v0] / det[d, v1 -
/// v0, v2 - v0]`. All in integers at the values' common exponent, which
/// scales both determinants by the same power of two.
pub fn line_triangle(o: [f64; 3], d: [f64; 3], v: [[f64; 3]; 3]) -> LineTriangle {
    let all = common_integers(&[o, d, v[0], v[1], v[2]].concat());
    let p = |i: usize| -> [BigInt; 3] { core::array::from_fn(|k| all[3 * i + k].clone()) };
    let sub = |a: &[BigInt; 3], b: &[BigInt; 3]| -> [BigInt; 3] {
        core::array::from_fn(|k| &a[k] - &b[k])
    };
    let (oi, di) = (p(0), p(1));
    let vi = [p(2), p(3), p(4)];
    let a = [sub(&vi[0], &oi), sub(&vi[1], &oi), sub(&vi[2], &oi)];
    let w = [(1, 2), (2, 0), (0, 1)]
        .map(|(j, k)| sign(&det3(&[di.clone(), a[j].clone(), a[k].clone()])));
    let coplanar = w == [0, 0, 0];
    let crosses = !coplanar && (w.iter().all(|&s| s >= 0) || w.iter().all(|&s| s <= 0));
    if !crosses {
        return LineTriangle {
            coplanar,
            t: None,
            front: false,
        };
    }
    let (e1, e2) = (sub(&vi[1], &vi[0]), sub(&vi[2], &vi[0]));
    let num = det3(&[a[0].clone(), e1.clone(), e2.clone()]);
    let den = det3(&[di, e1, e2]);
    let front = den.is_negative();
    let t = if front { (-num, -den) } else { (num, den) };
    LineTriangle {
        coplanar,
        t: Some(t),
        front,
    }
}

/// The exact ordering of `num / den` (`den > 0`) against the finite `x`.
pub fn cmp_ratio(num: &BigInt, den: &BigInt, x: f64) -> core::cmp::Ordering {
    let (m, e) = exact_parts(x);
    // num / den against m 2^e: num 2^-e against m den, shifted to integers.
    if e >= 0 {
        num.cmp(&((m * den) << e as usize))
    } else {
        (num << (-e) as usize).cmp(&(m * den))
    }
}

/// Whether `num / den` (`den > 0`) lies in `[min, max]` (infinite bounds
/// allowed).
pub fn ratio_in(num: &BigInt, den: &BigInt, min: f64, max: f64) -> bool {
    use core::cmp::Ordering::*;
    let above = min == f64::NEG_INFINITY || cmp_ratio(num, den, min) != Less;
    let below = max == f64::INFINITY || cmp_ratio(num, den, max) != Greater;
    above && below
}

/// The crate's policy for a crossing at the exact parameter `num / den`
/// in `[min, max]`, for a cast whose `t` is within `k` units of rounding of
/// the exact one: `Some(true)` where it must be a hit, `Some(false)` where
/// it must not (outside the range, or so far beyond `f64`'s range that any
/// `t` within `k` units overflows: a cast reports only finite `t`,
/// `Interval::admits`), `None` where either is right (the exact `|t|`
/// within `2k` ulps of `f64::MAX` on either side, where the cast's `t` may
/// or may not overflow).
pub fn hit_policy(num: &BigInt, den: &BigInt, min: f64, max: f64, k: u32) -> Option<bool> {
    if !ratio_in(num, den, min, max) {
        return Some(false);
    }
    // f64::MAX is (2^53 - 1) 2^971; `j` ulps of it away, (2^53 - 1 + j) 2^971.
    let beyond = |j: i64| {
        let edge = (BigInt::from((1i64 << 53) - 1 + j)) << 971usize;
        num.abs() > edge * den.abs()
    };
    let band = 2 * i64::from(k);
    if !beyond(-band) {
        Some(true)
    } else if beyond(band) {
        Some(false)
    } else {
        None
    }
}

/// Whether `|t - num / den| <= k 2^-53 |num / den|` (`den > 0`), exactly:
/// `|t den - num| 2^53 <= k |num|`.
pub fn within_units(t: f64, num: &BigInt, den: &BigInt, k: u32) -> bool {
    let (m, e) = exact_parts(t);
    // t den - num at the scale 2^min(e, 0).
    let (lhs, rhs) = if e >= 0 {
        ((m * den) << e as usize, num.clone())
    } else {
        (m * den, num << (-e) as usize)
    };
    let diff = (lhs - &rhs).abs() << 53usize;
    diff <= rhs.abs() * BigInt::from(k)
}

/// `num / den` (`den > 0`) rounded to the nearest `f64` (ties to even), for
/// results in the normal range; in the subnormal range the result is
/// within one subnormal step.
pub fn ratio_to_f64(num: &BigInt, den: &BigInt) -> f64 {
    if num.is_zero() {
        return 0.0;
    }
    let neg = num.is_negative();
    let n = num.abs();
    // A quotient of 64 to 65 bits, with a sticky bit for the remainder.
    let shift = 64 + den.bits() as i64 - n.bits() as i64;
    let (scaled_n, scaled_d) = if shift >= 0 {
        (n << shift as usize, den.clone())
    } else {
        (n, den << (-shift) as usize)
    };
    let q = &scaled_n / &scaled_d;
    let sticky = !(&scaled_n - &q * &scaled_d).is_zero();
    let (_, digits) = q.to_u64_digits();
    let mut value: u128 = digits
        .iter()
        .rev()
        .fold(0u128, |acc, &d| (acc << 64) | d as u128);
    // Keep 64 significant bits; fold lost bits into the sticky bit.
    let bits = 128 - value.leading_zeros() as i64;
    let mut exp = -shift;
    let mut lost = sticky;
    if bits > 64 {
        let drop = bits - 64;
        lost |= value & ((1u128 << drop) - 1) != 0;
        value >>= drop;
        exp += drop;
    }
    let v = ((value as u64) | lost as u64) as f64;
    let r = scale2(v, exp);
    if neg { -r } else { r }
}

/// `v 2^k`, stepping so that no intermediate result overflows early.
fn scale2(mut v: f64, mut k: i64) -> f64 {
    while k > 1000 {
        v *= 2f64.powi(1000);
        k -= 1000;
    }
    while k < -1000 {
        v *= 2f64.powi(-1000);
        k += 1000;
    }
    v * 2f64.powi(k as i32)
}

/// The number of `f64` steps between `a` and `b` (both finite).
pub fn ulps_between(a: f64, b: f64) -> u64 {
    let ordered = |x: f64| {
        let bits = x.to_bits() as i64;
        if bits < 0 { i64::MIN - bits } else { bits }
    };
    (ordered(a) as i128 - ordered(b) as i128).unsigned_abs() as u64
}
