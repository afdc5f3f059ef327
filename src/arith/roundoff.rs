//! The unit roundoff and pbrt's `gamma(n)`: the one definition of each.
//!
//! Every rounding of a binary64 operation on finite values whose result is
//! normal has relative error at most `U = 2^-53`. A value computed with
//! `n` such roundings in sequence is within `gamma(n) |x|` of its exact
//! value, `gamma(n) = n u / (1 - n u)` (Higham, *Accuracy and Stability of
//! Numerical Algorithms*, 2nd ed., Lemma 3.1; Pharr, Jakob and Humphreys,
//! *Physically Based Rendering*, 4th ed., §6.8.1, `gamma` in pbrt-v4's
//! `util/float.h`).

/// `2^-53`, the unit roundoff of binary64 with rounding to nearest.
pub(crate) const U: f64 = f64::EPSILON / 2.0;

/// `gamma(n) = n u / (1 - n u)`, for `n u < 1`: the relative error bound of
/// `n` roundings in sequence. The quotient rounds to nearest, so for the
/// small `n` the crate uses it is within a relative `u` of the exact
/// bound; callers that need it as an upper bound multiply by `1 + 2u` or
/// add their own margin, as each says.
///
/// ```ignore
/// assert!(gamma(3) > 3.0 * U);
/// ```
pub(crate) const fn gamma(n: u32) -> f64 {
    let nu = n as f64 * U;
    nu / (1.0 - nu)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_exceeds_n_u() {
        // The exact gamma(n) is n u (1 + n u + (n u)^2 + ...); the computed
        // one is within a relative u of it. Both products below are exact.
        for n in 1..100 {
            let nu = f64::from(n) * U;
            assert!(gamma(n) > nu, "{n}");
            assert!(gamma(n) <= nu * (1.0 + 2.0 * f64::from(n + 1) * U), "{n}");
        }
    }
}
