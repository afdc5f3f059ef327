//! Floating-point values with an `i32` exponent beside an `f64`
//! significand: they carry the big-integer results of the exact stages
//! (whose magnitudes reach far beyond `f64`'s range) through the few
//! rounded operations that turn exact polynomial coefficients into roots.
//!
//! Each operation rounds once, like the `f64` operation it wraps (the
//! significand stays in `[1, 2)`, so nothing underflows or overflows before
//! [`ScaledFloat::to_f64`]).

use crate::arith::exponent::{pow2, split};
use crate::arith::std_or_libm::sqrt;

/// `m * 2^e`, with `m` zero or `1 <= |m| < 2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ScaledFloat {
    m: f64,
    e: i32,
}

impl ScaledFloat {
    /// Zero.
    pub(crate) const ZERO: ScaledFloat = ScaledFloat { m: 0.0, e: 0 };

    /// `m * 2^e` for a finite `m` (normalized; exact).
    #[inline]
    pub(crate) fn new(m: f64, e: i32) -> ScaledFloat {
        if m == 0.0 {
            return ScaledFloat::ZERO;
        }
        let (mant, ex) = split(m);
        // |mant| < 2^53 holds the bits of m = mant * 2^ex exactly.
        let top = 63 - mant.unsigned_abs().leading_zeros() as i32;
        ScaledFloat {
            m: mant as f64 * pow2(-top),
            e: e.saturating_add(ex + top),
        }
    }

    /// Whether the value is zero.
    #[inline]
    pub(crate) fn is_zero(self) -> bool {
        self.m == 0.0
    }

    /// Whether the value is negative.
    #[inline]
    pub(crate) fn is_negative(self) -> bool {
        self.m < 0.0
    }

    /// `-self`, exactly.
    #[inline]
    pub(crate) fn neg(self) -> ScaledFloat {
        ScaledFloat {
            m: -self.m,
            e: self.e,
        }
    }

    /// `self * other`, rounded once.
    #[inline]
    pub(crate) fn mul(self, other: ScaledFloat) -> ScaledFloat {
        ScaledFloat::new(self.m * other.m, self.e.saturating_add(other.e))
    }

    /// `self / other` (`other` non-zero), rounded once.
    #[inline]
    pub(crate) fn div(self, other: ScaledFloat) -> ScaledFloat {
        ScaledFloat::new(self.m / other.m, self.e.saturating_sub(other.e))
    }

    /// `sqrt(self)` for `self >= 0`, rounded once.
    #[inline]
    pub(crate) fn sqrt(self) -> ScaledFloat {
        let (m, e) = if self.e % 2 == 0 {
            (self.m, self.e)
        } else {
            (self.m * 2.0, self.e - 1)
        };
        ScaledFloat::new(sqrt(m), e / 2)
    }

    /// `self + other`, rounded once when the exponents differ by less than
    /// 1,000; otherwise the smaller term lies below half an ulp of the
    /// larger and the result is the larger (a rounding error below `2^-900`
    /// relative).
    #[inline]
    pub(crate) fn add(self, other: ScaledFloat) -> ScaledFloat {
        let (big, small) = if self.is_zero() || (!other.is_zero() && other.e > self.e) {
            (other, self)
        } else {
            (self, other)
        };
        let gap = big.e - small.e;
        if small.is_zero() || gap > 1000 {
            return big;
        }
        ScaledFloat::new(big.m + small.m * pow2(-gap), big.e)
    }

    /// The nearest `f64` (overflow gives an infinity; values below the
    /// normal range round a second time, to the subnormal grid).
    #[inline]
    pub(crate) fn to_f64(self) -> f64 {
        if self.is_zero() {
            return 0.0;
        }
        if self.e > 1023 {
            return f64::INFINITY.copysign(self.m);
        }
        if self.e < -1100 {
            return 0.0f64.copysign(self.m);
        }
        let half = self.e / 2;
        self.m * pow2(half) * pow2(self.e - half)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operations_round_like_f64() {
        let x = |v: f64| ScaledFloat::new(v, 0);
        assert_eq!(x(3.0).mul(x(0.1)).to_f64(), 3.0 * 0.1);
        assert_eq!(x(1.0).div(x(3.0)).to_f64(), 1.0 / 3.0);
        assert_eq!(x(2.0).sqrt().to_f64(), 2f64.sqrt());
        assert_eq!(x(0.1).add(x(0.2)).to_f64(), 0.1 + 0.2);
        assert_eq!(x(0.1).add(x(-0.1)).to_f64(), 0.0);
        // Beyond f64's range and back.
        let huge = ScaledFloat::new(1.5, 3000);
        assert_eq!(
            huge.mul(ScaledFloat::new(1.0, -2990)).to_f64(),
            1.5 * 1024.0
        );
        assert_eq!(
            huge.sqrt().mul(ScaledFloat::new(1.0, -1500)).to_f64(),
            1.5f64.sqrt()
        );
        assert_eq!(huge.to_f64(), f64::INFINITY);
        assert_eq!(ScaledFloat::new(-1.0, -1074).to_f64(), -f64::from_bits(1));
    }
}
