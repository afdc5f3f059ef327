//! Largest magnitudes, as the filters' error bounds take them.

use glam::DVec3;

/// `a` or `b`, whichever is larger: one `maxsd`, where `f64::max` also
/// handles NaN (for finite values, or values that overflowed to
/// infinity, the same).
#[inline(always)]
pub(crate) fn larger(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// The largest magnitude of a coordinate of `vs` (infinite where one
/// overflowed).
#[inline(always)]
pub(crate) fn largest_magnitude(vs: &[DVec3]) -> f64 {
    vs.iter().fold(0.0, |m, v| {
        let a = v.abs();
        larger(larger(larger(m, a.x), a.y), a.z)
    })
}
