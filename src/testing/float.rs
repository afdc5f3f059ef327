//! The elementary functions the generators use: `std`'s where the crate
//! has it, so that a seed gives the cases it always gave there, and
//! `libm`'s without it. Only `sqrt`, `round` and `ceil` are correctly
//! rounded; `pow`, `ln`, `cbrt`, `sin` and `cos` of `libm` may differ from
//! the platform's in the last bit, so a seed's cases can differ between a
//! `std` and a `no_std` build (never between two runs of one build).

macro_rules! std_or_libm {
    ($($(#[$doc:meta])* fn $name:ident($($arg:ident),*) = $method:ident / $libm:ident;)*) => {$(
        $(#[$doc])*
        #[inline]
        pub(super) fn $name(x: f64 $(, $arg: f64)*) -> f64 {
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
    /// `x^y`.
    fn powf(y) = powf / pow;
    /// The natural logarithm.
    fn ln() = ln / log;
    /// The square root, correctly rounded.
    fn sqrt() = sqrt / sqrt;
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
