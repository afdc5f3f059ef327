//! Correctly rounded `sqrt` and `fma` with or without `std`: IEEE 754
//! requires both to round correctly; `std` uses the hardware instructions,
//! `libm` the same instructions where the target has them (x86-64 has
//! `sqrtsd`; `fma` in software where FMA is not enabled).

/// `sqrt(x)`, correctly rounded.
#[inline(always)]
pub(crate) fn sqrt(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrt(x)
    }
}

/// `x * y + z` with one rounding.
#[inline(always)]
pub(crate) fn fma(x: f64, y: f64, z: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.mul_add(y, z)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::fma(x, y, z)
    }
}
