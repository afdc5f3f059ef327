//! Largest magnitudes, as the filters' error bounds take them.

/// `a` or `b`, whichever is larger: one `maxsd`, where `f64::max` also
/// handles NaN (for finite values, or values that overflowed to
/// infinity, the same).
#[inline(always)]
pub(crate) fn larger(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// `a` or `b`, whichever is smaller: one `minsd`, as [`larger`].
#[inline(always)]
pub(crate) fn smaller(a: f64, b: f64) -> f64 {
    if a < b { a } else { b }
}
