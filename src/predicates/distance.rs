//! Exact comparison of two squared Euclidean lengths,
//! `sign(|a - b|^2 - |c - d|^2)`, for every finite input: the predicate
//! behind [`compare_distance`](super::compare_distance) and the exact
//! tie-breaking of the nearest-point index.
//!
//! Stage ladder: filtered (`f64` sums of squares with a forward error
//! bound), small-integer exact (`i64` differences, `u128` squares), big
//! integer exact (fixed-capacity stack integers).

use crate::arith::exponent::{Grain, TINY, to_integer_i64};
use crate::arith::fixed_int::FixedInt;
use crate::sign::Sign;
use glam::DVec3;

/// Relative error of `fl(|a - b|^2)`: the difference, the square and two
/// additions each round once, so each of the three terms carries at most five
/// factors `(1 + d)`, `|d| <= u = 2^-53`, and the sum is off by at most
/// `gamma_5 = 5u / (1 - 5u)` relative (Higham, *Accuracy and Stability of
/// Numerical Algorithms*, 2nd ed., Lemma 3.1). Two such sums are compared:
/// their difference is off by at most `gamma_5 (s1 + s2)`, measured on the
/// exact sums; in terms of the computed ones `gamma_5 / (1 - gamma_5)`. The
/// bound's own product and sum round twice more. `8u` covers all of it.
pub(crate) const REL: f64 = 8.0 * (f64::EPSILON / 2.0);

/// Absolute term for underflow: a square below `2^-1022` is off by up to
/// `2^-1075` instead of relatively (a difference or a sum in that range is
/// exact), three squares per sum and two sums: `6 * 2^-1075 < 2^-1072`.
/// `2^-1071` leaves a factor 2.
pub(crate) const UNDERFLOW_SLACK: f64 = 8.0 * TINY;

/// Span (bits between the finest and coarsest set bit over all inputs) up to
/// which the integer stage is native: values below `2^62` as integers, their
/// differences below `2^63` (`i64`), squares below `2^126` and a sum of three
/// below `3 * 2^126 < 2^128` (`u128`).
const SMALL_SPAN: i32 = 62;

/// `fl(|v|^2)`.
#[inline(always)]
pub(crate) fn norm2(v: DVec3) -> f64 {
    v.x * v.x + v.y * v.y + v.z * v.z
}

/// The sign of `|a - b|^2 - |c - d|^2`, exact for finite input. A NaN or
/// infinite coordinate gives `Zero`.
#[inline]
pub(crate) fn cmp_lengths(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Sign {
    let s1 = norm2(a - b);
    let s2 = norm2(c - d);
    match filtered(s1, s2) {
        Some(sign) => sign,
        None => exact(a, b, c, d),
    }
}

/// Stage 1: the sign of `s1 - s2` for computed sums of squares, when the
/// error bound certifies it. `None` on overflow (the difference is NaN or the
/// bound infinite) and on near-ties.
#[inline(always)]
pub(crate) fn filtered(s1: f64, s2: f64) -> Option<Sign> {
    let diff = s1 - s2;
    // Tested as a difference so that the subnormal slack takes no part in
    // arithmetic (an x86 microcode assist): `fl(x - y) > s` implies `x > y + s`.
    if diff.abs() - REL * (s1 + s2) > UNDERFLOW_SLACK {
        Some(Sign::of_f64(diff))
    } else {
        None
    }
}

/// Stages 2 and 3: every coordinate as an integer multiple of the finest bit
/// among all twelve, then exact integer sums of squares.
#[cold]
#[inline(never)]
pub(crate) fn exact(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Sign {
    if !(a.is_finite() && b.is_finite() && c.is_finite() && d.is_finite()) {
        return Sign::Zero;
    }
    let values = [a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z];
    let grain = Grain::of(&values);
    if grain.all_zero() {
        return Sign::Zero;
    }
    let lo = grain.lo_min;
    if grain.span() <= SMALL_SPAN {
        let sum = |u: DVec3, v: DVec3| -> u128 {
            [(u.x, v.x), (u.y, v.y), (u.z, v.z)]
                .iter()
                .map(|&(s, t)| {
                    let diff = to_integer_i64(s, lo) - to_integer_i64(t, lo);
                    (diff.unsigned_abs() as u128).pow(2)
                })
                .sum()
        };
        let (s1, s2) = (sum(a, b), sum(c, d));
        return Sign::from_i8(s1.cmp(&s2) as i8);
    }
    big_integer(a, b, c, d, lo)
}

/// Stage 3. Every value is `X * 2^lo` with `|X| < 2^2098` (the span from
/// `2^-1074` to `2^1024`); differences need 2,099 bits and a sign (33 limbs),
/// squares 4,198 bits and a sum of three 4,200 bits (66 limbs).
fn big_integer(a: DVec3, b: DVec3, c: DVec3, d: DVec3, lo: i32) -> Sign {
    let sum = |u: DVec3, v: DVec3| {
        let mut s = FixedInt::<66>::ZERO;
        for k in 0..3 {
            let diff = FixedInt::<33>::from_f64(u[k], lo).sub(&FixedInt::<33>::from_f64(v[k], lo));
            s = s.add(&FixedInt::<66>::mul(&diff, &diff));
        }
        s
    };
    sum(a, b).sub(&sum(c, d)).sign()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ties_and_near_ties() {
        let q = DVec3::ZERO;
        let x = DVec3::new(1.0, 0.0, 0.0);
        let y = DVec3::new(0.0, 1.0, 0.0);
        assert_eq!(cmp_lengths(x, q, y, q), Sign::Zero);
        let x1 = DVec3::new(1.0 + f64::EPSILON, 0.0, 0.0);
        assert_eq!(cmp_lengths(x1, q, y, q), Sign::Positive);
        // Squares overflow: 1e300^2.
        let big = DVec3::new(1e300, 0.0, 0.0);
        let big1 = DVec3::new(0.0, 1e300 * (1.0 + f64::EPSILON), 0.0);
        assert_eq!(cmp_lengths(big, q, big1, q), Sign::Negative);
        // Squares underflow to zero: 1e-300^2.
        let t = DVec3::new(1e-300, 0.0, 0.0);
        let t2 = DVec3::new(0.0, 0.0, 2e-300);
        assert_eq!(cmp_lengths(t, q, t2, q), Sign::Negative);
        assert_eq!(cmp_lengths(t, q, -t, q), Sign::Zero);
    }
}
