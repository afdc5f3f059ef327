//! Exact comparisons of distances to balls, for the nearest-item search
//! over spheres: the distance from `q` to the ball `(c, r)` is
//! `max(0, |c - q| - r)`, zero inside.
//!
//! Square roots are removed by squaring with case analysis, so every sign is
//! that of an integer polynomial in the inputs at their finest common bit
//! (the big-integer representation of `arith::fixed_int`; `f64` filters run before
//! these, in the callers). Inputs must be finite and radii non-negative.

use super::distance::cmp_lengths;
use crate::arith::exponent::Grain;
use crate::arith::fixed_int::{DEG1, DEG2, DEG4, FixedInt};
use crate::sign::Sign;
use glam::DVec3;

/// Limbs for a value of the inputs or a difference or sum of two: below
/// `2^2100` at the common grain (span at most 2,098 bits, see `distance.rs`).
const W1: usize = DEG1;
/// Limbs for a degree-2 value (`|c - q|^2`, `k^2`) and sums of three:
/// below `2^4204`.
const W2: usize = DEG2;
/// Limbs for a degree-4 value (`m^2`, `4 k^2 b`): below `2^8410`.
const W4: usize = DEG4;

/// The sign of `|c - q| - (r1 + r2)`, exactly (`r1, r2 >= 0`).
pub(crate) fn cmp_length_to_sum(q: DVec3, c: DVec3, r1: f64, r2: f64) -> Sign {
    let lo = grain(&[q, c], &[r1, r2]);
    let Some(lo) = lo else {
        return Sign::Zero;
    };
    let a = squared::<W2>(c, q, lo);
    let sum = FixedInt::<W1>::from_f64(r1, lo).add(&FixedInt::<W1>::from_f64(r2, lo));
    a.sub(&FixedInt::<W2>::mul(&sum, &sum)).sign()
}

/// The sign of `max(0, |c1 - q| - r1) - max(0, |c2 - q| - r2)`, exactly.
pub(crate) fn cmp_ball_distances(q: DVec3, (c1, r1): (DVec3, f64), (c2, r2): (DVec3, f64)) -> Sign {
    // Inside (or on) a ball, the distance is zero.
    let out1 = cmp_lengths(c1, q, DVec3::new(r1, 0.0, 0.0), DVec3::ZERO) == Sign::Positive;
    let out2 = cmp_lengths(c2, q, DVec3::new(r2, 0.0, 0.0), DVec3::ZERO) == Sign::Positive;
    match (out1, out2) {
        (false, false) => return Sign::Zero,
        (false, true) => return Sign::Negative,
        (true, false) => return Sign::Positive,
        (true, true) => {}
    }
    if r1 == 0.0 && r2 == 0.0 {
        return cmp_lengths(c1, q, c2, q);
    }
    let Some(lo) = grain(&[q, c1, c2], &[r1, r2]) else {
        return Sign::Zero;
    };
    // sign(sqrt(a) - sqrt(b) - k) with k = r1 - r2; for k < 0 it is minus
    // sign(sqrt(b) - sqrt(a) - (-k)), the same form with k > 0.
    let a = squared::<W2>(c1, q, lo);
    let b = squared::<W2>(c2, q, lo);
    let k = FixedInt::<W1>::from_f64(r1, lo).sub(&FixedInt::<W1>::from_f64(r2, lo));
    if k.is_negative() {
        -root_difference_sign(&b, &a, &k.neg())
    } else {
        root_difference_sign(&a, &b, &k)
    }
}

/// `sign(sqrt(a) - sqrt(b) - k)` for `a, b, k >= 0`: `sqrt(a) > sqrt(b) + k`
/// iff `a > b + 2k sqrt(b) + k^2`, i.e. `m > 2k sqrt(b)` with
/// `m = a - b - k^2`; when `m <= 0` the answer is `m`'s side (or zero when
/// `m = 0` and `k sqrt(b) = 0`), otherwise the sign of `m^2 - 4 k^2 b`.
fn root_difference_sign(a: &FixedInt<W2>, b: &FixedInt<W2>, k: &FixedInt<W1>) -> Sign {
    let k2 = FixedInt::<W2>::mul(k, k);
    let m = a.sub(b).sub(&k2);
    match m.sign() {
        Sign::Negative => Sign::Negative,
        Sign::Zero => {
            if k2.sign() == Sign::Zero || b.sign() == Sign::Zero {
                Sign::Zero
            } else {
                Sign::Negative
            }
        }
        Sign::Positive => {
            let m2 = FixedInt::<W4>::mul(&m, &m);
            let k2b = FixedInt::<W4>::mul(&k2, b);
            let four_k2b = k2b.add(&k2b).add(&k2b).add(&k2b);
            m2.sub(&four_k2b).sign()
        }
    }
}

/// The finest bit among the coordinates and radii; `None` when all are zero.
fn grain(points: &[DVec3], radii: &[f64]) -> Option<i32> {
    let mut values = [0.0f64; 11];
    let mut n = 0;
    for p in points {
        values[n..n + 3].copy_from_slice(&p.to_array());
        n += 3;
    }
    values[n..n + radii.len()].copy_from_slice(radii);
    let g = Grain::of(&values[..n + radii.len()]);
    (!g.all_zero()).then_some(g.lo_min)
}

/// `|u - v|^2` at grain `lo`, exactly.
fn squared<const N: usize>(u: DVec3, v: DVec3, lo: i32) -> FixedInt<N> {
    let mut s = FixedInt::<N>::ZERO;
    for k in 0..3 {
        let d = FixedInt::<W1>::from_f64(u[k], lo).sub(&FixedInt::<W1>::from_f64(v[k], lo));
        s = s.add(&FixedInt::<N>::mul(&d, &d));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn balls() {
        let q = DVec3::ZERO;
        let x = |v: f64| DVec3::new(v, 0.0, 0.0);
        // Distances 1 and 1: a tie.
        assert_eq!(
            cmp_ball_distances(q, (x(3.0), 2.0), (x(-2.0), 1.0)),
            Sign::Zero
        );
        // Distances 1 and 1 + 2^-51.
        let far = f64::from_bits(3f64.to_bits() + 1);
        assert_eq!(
            cmp_ball_distances(q, (x(3.0), 2.0), (x(far), 2.0)),
            Sign::Negative
        );
        // Inside both: both zero.
        assert_eq!(
            cmp_ball_distances(q, (x(1.0), 2.0), (x(0.5), 9.0)),
            Sign::Zero
        );
        // sqrt(2) - 1 against 0.5: 0.414... < 0.5.
        let diag = DVec3::new(1.0, 1.0, 0.0);
        assert_eq!(
            cmp_ball_distances(q, (diag, 1.0), (x(1.5), 1.0)),
            Sign::Negative
        );
        assert_eq!(
            cmp_length_to_sum(q, DVec3::new(3.0, 4.0, 0.0), 2.0, 3.0),
            Sign::Zero
        );
        assert_eq!(
            cmp_length_to_sum(q, DVec3::new(3.0, 4.0, 0.0), 2.0, 2.5),
            Sign::Positive
        );
    }
}
