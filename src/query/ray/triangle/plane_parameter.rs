//! The parameter `t` where the line `o + t d` meets the plane of a
//! triangle `v0 v1 v2`: `det[v0 - o, e1, e2] / det[d, e1, e2]` with `e1 =
//! v1 - v0`, `e2 = v2 - v0` (Cramer's rule on `o + t d = v0 + β e1 + γ
//! e2`), rounded from its exact value. Two stages:
//!
//! - **filtered** ([`FilteredParameter`]): both determinants in
//!   double-double from error-free transformations, each certified within
//!   `1.45 u` of its value by a bound computed beside it;
//! - **exact** ([`exact_parameter`]): both determinants as integers.
//!
//! Either way the quotient is within `4 u` (`u = 2^-53`) of the exact `t`.

use crate::arith::double_double::{SLACK, cross_dd, difference, dot_dd, in_range, row};
use crate::arith::exponent::{pow2, to_integer_i64};
use crate::arith::fixed_int::{DEG1, DEG2, DEG3, FixedInt};
use crate::arith::fma_dispatch::{FmaKernel, with_fma};
use crate::arith::roundoff::U;
use crate::predicates::det::det3_wide;
use crate::predicates::orient_dir::{SMALL_SPAN, grains};
use crate::query::ray::Ray;
use glam::DVec3;

/// The parameter `t` where the line `o + t d` of `ray` meets the plane of
/// `v`: the relative error is below `4 * 2^-53` when the result is a
/// normal number, and below `2^-1073` absolutely when it is subnormal. A
/// result that would round to zero is the smallest subnormal of the exact
/// sign instead, so the sign is always exact. `NaN` when the line is
/// parallel to the plane (or the triangle degenerate), or for non-finite
/// input.
///
/// The filtered stage answers first, with hardware FMA where the CPU has
/// it; the exact stage where it cannot certify.
#[inline]
pub(crate) fn plane_parameter(ray: &Ray, v: &[DVec3; 3]) -> f64 {
    with_fma(&FilteredParameter { ray, v }).unwrap_or_else(|| {
        let [v0, v1, v2] = *v;
        exact_parameter(ray.origin(), ray.direction(), v0, v1, v2)
    })
}

/// The filtered stage: both determinants in double-double, each certified
/// within `1.45 u` of its value, then divided, so that the quotient is
/// within `(1.45 + 1.45 + 1) u < 4 u` of the exact one to first order (the
/// second-order terms are below `2^-100`). `None` where a bound does not
/// certify (a determinant below about `2^-45` of its permanent: a ray
/// nearly parallel to the plane, or an origin nearly on it), where a
/// magnitude exceeds `2^300` (below that no product of three overflows),
/// or where the quotient is not a normal number.
///
/// Each determinant `x . (e1 x e2)` is within `u |value| + 61 u^2 Σ |x_i|
/// P_i` of its value (`arith::double_double`); the certificate allows
/// `128 u^2` of the permanent, which also covers the rounding of the
/// permanents themselves, and the absolute slack for underflow.
struct FilteredParameter<'a> {
    ray: &'a Ray,
    v: &'a [DVec3; 3],
}

impl FmaKernel for FilteredParameter<'_> {
    type Output = Option<f64>;

    #[inline(always)]
    fn run(&self) -> Option<f64> {
        let [v0, v1, v2] = *self.v;
        let (o, d) = (self.ray.origin(), self.ray.direction());
        let (w, e1, e2) = (difference(v0, o), difference(v1, v0), difference(v2, v0));
        if !in_range(&[w.0, e1.0, e2.0, row(d)]) {
            return None;
        }
        let n = cross_dd(e1, e2);
        let (den, den_perm) = dot_dd(row(d), None, &n);
        let (num, num_perm) = dot_dd(w.0, Some(w.1), &n);
        // Each determinant within 1.45 u of its value: the u^2 terms and
        // the slack within 0.45 u of its magnitude.
        let certified = |v: f64, perm: f64| 128.0 * U * U * perm + SLACK <= 0.45 * U * v.abs();
        let t = num / den;
        (certified(den, den_perm) && certified(num, num_perm) && t.is_normal()).then_some(t)
    }
}

/// [`plane_parameter`]'s exact stage: both determinants exact in integers.
#[cold]
#[inline(never)]
fn exact_parameter(o: DVec3, d: DVec3, v0: DVec3, v1: DVec3, v2: DVec3) -> f64 {
    if ![o, d, v0, v1, v2].iter().all(|v| v.is_finite()) {
        return f64::NAN;
    }
    let Some((lo, span)) = grains(&[o, d, v0, v1, v2]) else {
        return f64::NAN;
    };
    // Values below 2^span, rows (differences) below 2^(span + 1), minors
    // below 2^(2 span + 3), determinants below 2^(3 span + 5): the sizes
    // hold them with a sign bit to spare.
    let v = [v0, v1, v2];
    if span <= SMALL_SPAN {
        small_quotient(o, d, v, lo)
    } else if span <= 125 {
        quotient::<2, 4, 6>(o, d, v, lo)
    } else if span <= 253 {
        quotient::<4, 8, 12>(o, d, v, lo)
    } else if span <= 509 {
        quotient::<8, 16, 24>(o, d, v, lo)
    } else {
        // Every finite input, as in orient3d's last stage.
        quotient::<DEG1, DEG2, DEG3>(o, d, v, lo)
    }
}

/// [`plane_parameter`] in native integers, for values below `2^61` at
/// the finest bit of each axis: rows in `i64` (below `2^62`), the normal
/// `e1 x e2` in `i128` (below `2^125`), the determinants as 189-bit sums.
fn small_quotient(o: DVec3, d: DVec3, v: [DVec3; 3], lo: [i32; 3]) -> f64 {
    let int = |p: DVec3| {
        [
            to_integer_i64(p.x, lo[0]),
            to_integer_i64(p.y, lo[1]),
            to_integer_i64(p.z, lo[2]),
        ]
    };
    let sub = |a: [i64; 3], b: [i64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let v0 = int(v[0]);
    let (e1, e2) = (sub(int(v[1]), v0), sub(int(v[2]), v0));
    let cross = |i: usize, j: usize| e1[i] as i128 * e2[j] as i128 - e1[j] as i128 * e2[i] as i128;
    let n = [cross(1, 2), cross(2, 0), cross(0, 1)];
    let num = dot_wide(sub(v0, int(o)), n);
    let den = dot_wide(int(d), n);
    // Both within `2^-53 (1 + 2^-11)` of the exact integers, far inside the
    // range of `f64`; the column scales cancel in the quotient.
    if den == 0.0 { f64::NAN } else { num / den }
}

/// `a . n` for `|a_k| < 2^62`, `|n_k| < 2^125`, rounded to `f64` within
/// `2^-53 (1 + 2^-11)` relative: the sum is kept exactly as a high `i128`
/// and a low `u64` word, `value = high 2^64 + low` (as in orient3d's small
/// stage), then converted from its magnitude.
fn dot_wide(a: [i64; 3], n: [i128; 3]) -> f64 {
    let mut high: i128 = 0;
    let mut low: u128 = 0;
    for k in 0..3 {
        let z = a[k] as i128;
        high += z * (n[k] >> 64);
        let zl = z * (n[k] as u64 as i128);
        high += zl >> 64;
        low += zl as u64 as u128;
    }
    high += (low >> 64) as i128;
    let low = low as u64;
    // The magnitude as `h 2^64 + l`, `h >= 0`.
    let neg = high < 0;
    let (h, l) = if neg {
        ((!high + (low == 0) as i128) as u128, low.wrapping_neg())
    } else {
        (high as u128, low)
    };
    let m = if h >> 64 == 0 {
        // Below 2^128: one correctly rounded conversion.
        ((h << 64) | l as u128) as f64
    } else {
        // `l` is below half an ulp of the rounded `h 2^64`: dropping it
        // moves the result by less than `2^-64` relative.
        h as f64 * 18446744073709551616.0
    };
    if neg { -m } else { m }
}

/// [`plane_parameter`] in `D`-limb rows, `M`-limb minors, `R`-limb
/// determinants.
fn quotient<const D: usize, const M: usize, const R: usize>(
    o: DVec3,
    d: DVec3,
    v: [DVec3; 3],
    lo: [i32; 3],
) -> f64 {
    let int = |p: DVec3| {
        [
            FixedInt::<D>::from_f64(p.x, lo[0]),
            FixedInt::from_f64(p.y, lo[1]),
            FixedInt::from_f64(p.z, lo[2]),
        ]
    };
    let sub = |a: &[FixedInt<D>; 3], b: &[FixedInt<D>; 3]| {
        [a[0].sub(&b[0]), a[1].sub(&b[1]), a[2].sub(&b[2])]
    };
    let (oi, v0) = (int(o), int(v[0]));
    let (e1, e2) = (sub(&int(v[1]), &v0), sub(&int(v[2]), &v0));
    let num = det3_wide::<D, M, R>(&[sub(&v0, &oi), e1, e2]);
    let den = det3_wide::<D, M, R>(&[int(d), e1, e2]);
    let (num, den) = (num.rounded_parts(), den.rounded_parts());
    if den.0 == 0.0 {
        return f64::NAN;
    }
    // Both scaled by the same power of two (the columns'), which cancels.
    round_quotient(num, den)
}

/// `(mn 2^en) / (md 2^ed)` for two values rounded to 53 bits by
/// `FixedInt::rounded_parts` (`md != 0`), within `(1 + u)^2 / (1 - u) - 1
/// < 4u` of the exact quotient of the unrounded values when the result is
/// a normal number, and within `2^-1073` absolutely when it is subnormal;
/// a non-zero quotient that would round to zero is the smallest subnormal
/// of its sign, so the sign is always exact.
pub(super) fn round_quotient((mn, en): (f64, i32), (md, ed): (f64, i32)) -> f64 {
    // `mn / md` lies within [2^-64, 2^64] (or is zero) and is rounded once;
    // the scaling by `2^(en - ed)` in steps of the same sign is exact
    // unless the result is subnormal or overflows.
    let q = mn / md;
    let k = (en - ed).clamp(-2400, 2400);
    let third = k / 3;
    let t = q * pow2(third) * pow2(third) * pow2(k - 2 * third);
    if t == 0.0 && mn != 0.0 {
        f64::from_bits(1).copysign(q)
    } else {
        t
    }
}
