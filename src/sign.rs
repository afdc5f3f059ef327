//! The answer of a predicate: a sign.

/// The sign of a predicate's determinant: negative, zero or positive.
///
/// ```
/// use exactray::Sign;
/// assert_eq!(Sign::from_i8(-3), Sign::Negative);
/// assert_eq!(Sign::Positive.as_i8(), 1);
/// assert_eq!(-Sign::Positive, Sign::Negative);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[repr(i8)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Sign {
    /// The determinant is negative.
    Negative = -1,
    /// The determinant is exactly zero: the points are degenerate (collinear,
    /// coplanar, cocircular or cospherical).
    Zero = 0,
    /// The determinant is positive.
    Positive = 1,
}

impl Sign {
    /// The sign as `-1`, `0` or `1`.
    #[inline]
    pub const fn as_i8(self) -> i8 {
        self as i8
    }

    /// The sign of an integer.
    #[inline]
    pub const fn from_i8(v: i8) -> Sign {
        if v > 0 {
            Sign::Positive
        } else if v < 0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }

    /// The sign of a float; `NaN` gives `Zero`.
    #[inline]
    pub fn of_f64(v: f64) -> Sign {
        if v > 0.0 {
            Sign::Positive
        } else if v < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }

    /// The sign of a product: `Positive` when both are non-zero and equal.
    #[inline]
    pub const fn product(self, other: Sign) -> Sign {
        Sign::from_i8(self.as_i8() * other.as_i8())
    }

    /// `true` for `Positive`.
    #[inline]
    pub const fn is_positive(self) -> bool {
        matches!(self, Sign::Positive)
    }

    /// `true` for `Negative`.
    #[inline]
    pub const fn is_negative(self) -> bool {
        matches!(self, Sign::Negative)
    }

    /// `true` for `Zero`.
    #[inline]
    pub const fn is_zero(self) -> bool {
        matches!(self, Sign::Zero)
    }
}

impl core::ops::Neg for Sign {
    type Output = Sign;
    #[inline]
    fn neg(self) -> Sign {
        Sign::from_i8(-self.as_i8())
    }
}

impl From<Sign> for i8 {
    #[inline]
    fn from(s: Sign) -> i8 {
        s.as_i8()
    }
}
