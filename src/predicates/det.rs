//! The 3x3 determinant kernels that orient3d, the sign of a direction
//! against a plane (`orient_dir`) and the ray–triangle test share: stage
//! 1's determinant of three rows with Shewchuk's bound and its certificate
//! ([`stage_a_rows`], [`certifies`]), and the exact determinants of
//! integer rows, in native integers ([`small_det3`]) or fixed-width ones
//! ([`det3_wide`]).

use crate::arith::exponent::{TINY, pow2};
use crate::arith::fixed_int::FixedInt;
use crate::arith::lanes::Lanes;
use crate::sign::Sign;

/// Shewchuk's `o3derrboundA = (7 + 56 eps) eps`, `eps = 2^-53`: with no
/// underflow, `|det_computed - det| <= A * permanent` (Shewchuk 1997,
/// section 4.3; our determinant is his with rows relabelled, the same
/// operations on the same kind of operands).
pub(super) const A: f64 = (7.0 + 56.0 * f64::EPSILON / 2.0) * (f64::EPSILON / 2.0);

/// Underflow, per unit of `|Bz| + |Cz| + |Dz|`: a 2x2-minor product that
/// lands below `2^-1022` is off by up to `2^-1075` absolutely; two of them
/// per minor, then multiplied by that row's z: `2 * 2^-1075 * |z|`, so
/// `2^-1074` per unit of z; `2^-1073` leaves a factor 2.
const Z_SLACK: f64 = 2.0 * TINY;

/// Underflow, absolute: the three final products (`3 * 2^-1075`), the
/// rounding of `A * permanent` and of `Z_SLACK * sum` (`2^-1075` each):
/// `5 * 2^-1075 < 2^-1072`; `2^-1071` leaves a factor 2.
const UNDERFLOW_SLACK: f64 = 8.0 * TINY;

/// `2^1000`: the slack comparison is made at this scale so that its
/// operands are normal numbers (see [`certifies`]).
const LIFT: f64 = pow2(1000);

/// Stage 1's determinant of the rows `bb`, `cc`, `dd`, expanded along z.
#[inline(always)]
pub(super) fn determinant<T: Lanes>(bb: [T; 3], cc: [T; 3], dd: [T; 3]) -> T {
    bb[2] * (cc[0] * dd[1] - dd[0] * cc[1])
        + cc[2] * (dd[0] * bb[1] - bb[0] * dd[1])
        + dd[2] * (bb[0] * cc[1] - cc[0] * bb[1])
}

/// Stage 1 (orient3d's `stage_a_lanes`, the filters of `orient_dir`
/// and the ray–triangle test) from the three rows of the determinant, each a
/// rounded difference of input coordinates or an input vector itself: the
/// bound `A` accounts for one rounding in every row entry, so a row that is
/// exact (a ray's direction) only leaves it less to cover. Underflow in a
/// difference is exact, so the slack terms hold for either kind of row.
#[inline(always)]
pub(crate) fn stage_a_rows<T: Lanes>(bb: [T; 3], cc: [T; 3], dd: [T; 3]) -> (T, T, T, T) {
    let cxdy = cc[0] * dd[1];
    let dxcy = dd[0] * cc[1];
    let dxby = dd[0] * bb[1];
    let bxdy = bb[0] * dd[1];
    let bxcy = bb[0] * cc[1];
    let cxby = cc[0] * bb[1];
    let det = determinant(bb, cc, dd);
    let (bz, cz, dz) = (bb[2].abs(), cc[2].abs(), dd[2].abs());
    let permanent = (cxdy.abs() + dxcy.abs()) * bz
        + (dxby.abs() + bxdy.abs()) * cz
        + (bxcy.abs() + cxby.abs()) * dz;
    let margin = (det.abs() - T::splat(A) * permanent) * T::splat(LIFT);
    (det, permanent, margin, bz + cz + dz)
}

/// Whether the margin of [`stage_a_rows`] certifies the sign, with
/// `extra_slack` (the scaled filter's) on top of the underflow slack.
///
/// `|det| - A * permanent > Z_SLACK * (bz + cz + dz) + UNDERFLOW_SLACK`,
/// both sides times 2^1000: the slack constants are subnormal, and
/// arithmetic on them costs a microcode assist on x86 on every call.
/// Scaling the left side by a power of two is exact (an overflow to
/// infinity only where the inequality holds anyway); the right side's
/// constants are normal and its rounding is within their factor-2 margin.
#[inline(always)]
pub(crate) fn certifies(margin: f64, zsum: f64, extra_slack: f64) -> bool {
    margin > (Z_SLACK * LIFT) * zsum + (UNDERFLOW_SLACK + extra_slack) * LIFT
}

/// Whether stage 1's error bound on [`stage_a_rows`]'s determinant `det`
/// (the slack terms of [`certifies`] included) is below `|det| / factor`,
/// for a power of two `factor >= 1`: `|det| - factor * A * permanent >
/// factor * (Z_SLACK * zsum + UNDERFLOW_SLACK)`, both sides times
/// `2^1000` as in [`certifies`]. Scaling a rounded bound by a power of two
/// is exact, so the rounding margins of the bound carry over.
#[inline(always)]
pub(crate) fn within(det: f64, permanent: f64, zsum: f64, factor: f64) -> bool {
    (det.abs() - (factor * A) * permanent) * LIFT
        > factor * ((Z_SLACK * LIFT) * zsum + UNDERFLOW_SLACK * LIFT)
}

/// The sign of `det[b, c, d]` for integer rows below `2^62` in magnitude:
/// minors in `i128`, and the 189-bit determinant as an `i128` high part and
/// a `u64` low part.
pub(crate) fn small_det3([b, c, d]: [[i64; 3]; 3]) -> Sign {
    let minor =
        |u: [i64; 3], v: [i64; 3]| u[0] as i128 * v[1] as i128 - v[0] as i128 * u[1] as i128;
    // det = sum z * m with |z| < 2^62, |m| < 2^125. Write m = hi 2^64 + lo
    // (lo in [0, 2^64)) and z * lo = q 2^64 + r: then
    // det = (sum z hi + sum q + carry(sum r)) 2^64 + low64(sum r), where the
    // high part stays below 2^126 and the low part is non-negative.
    let mut high: i128 = 0;
    let mut low: u128 = 0;
    for (z, m) in [
        (b[2], minor(c, d)),
        (c[2], minor(d, b)),
        (d[2], minor(b, c)),
    ] {
        high += z as i128 * (m >> 64);
        let zl = z as i128 * (m as u64 as i128);
        high += zl >> 64;
        low += zl as u64 as u128;
    }
    high += (low >> 64) as i128;
    if high != 0 {
        Sign::from_i8(high.signum() as i8)
    } else {
        Sign::from_i8((low as u64 != 0) as i8)
    }
}

/// `det[b, c, d]` of integer rows in `D`-limb integers, with `M`-limb
/// minors and an `R`-limb result; the caller picks the sizes from a bound
/// on the rows.
pub(crate) fn det3_wide<const D: usize, const M: usize, const R: usize>(
    [b, c, d]: &[[FixedInt<D>; 3]; 3],
) -> FixedInt<R> {
    let minor = |u: &[FixedInt<D>; 3], v: &[FixedInt<D>; 3]| {
        FixedInt::<M>::mul(&u[0], &v[1]).sub(&FixedInt::<M>::mul(&v[0], &u[1]))
    };
    FixedInt::<R>::mul(&b[2], &minor(c, d))
        .add(&FixedInt::<R>::mul(&c[2], &minor(d, b)))
        .add(&FixedInt::<R>::mul(&d[2], &minor(b, c)))
}
