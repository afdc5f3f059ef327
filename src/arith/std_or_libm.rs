//! The elementary functions, `std`'s where the crate has it and `libm`'s
//! without it. The crate's numerics use only the two IEEE 754 requires to
//! round correctly, `sqrt` and `fma` (`std` uses the hardware
//! instructions, `libm` the same instructions where the target has them:
//! x86-64 has `sqrtsd`; `fma` in software where FMA is not enabled); so do
//! `round` and `ceil`. The others (`powf`, `ln`, `cbrt`, `sin`, `cos`)
//! serve only `testing`'s generators: `libm`'s may differ from the
//! platform's in the last bit, so a seed's cases can differ between a
//! `std` and a `no_std` build (never between two runs of one build).

macro_rules! std_or_libm {
    ($($(#[$doc:meta])* fn $name:ident($($arg:ident),*) = $method:ident / $libm:ident;)*) => {$(
        $(#[$doc])*
        #[inline(always)]
        #[allow(dead_code, reason = "some serve only the testing module")]
        pub(crate) fn $name(x: f64 $(, $arg: f64)*) -> f64 {
            #[cfg(feature = "std")]
            {
                x.$method($($arg),*)
            }
            #[cfg(not(feature = "std"))]
            {
                libm::$libm(x $(, $arg)*)
            }
        }
    )*};
}

std_or_libm! {
    /// `sqrt(x)`, correctly rounded.
    fn sqrt() = sqrt / sqrt;
    /// `x * y + z` with one rounding.
    fn fma(y, z) = mul_add / fma;
    /// `x^y`.
    fn powf(y) = powf / pow;
    /// The natural logarithm.
    fn ln() = ln / log;
    /// The cube root.
    fn cbrt() = cbrt / cbrt;
    /// The sine.
    fn sin() = sin / sin;
    /// The cosine.
    fn cos() = cos / cos;
    /// To the nearest integer, ties away from zero.
    fn round() = round / round;
    /// Up to an integer.
    fn ceil() = ceil / ceil;
}
