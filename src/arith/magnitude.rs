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

/// Whether every value is zero or at least `least` in magnitude (`false`
/// for NaN): the filters' difference guards, which a zero difference
/// passes (its products are exactly zero, they cannot underflow), where
/// their quick test, the smallest magnitude, turns zeros away.
#[inline]
pub(crate) fn zero_or_at_least(values: &[f64], least: f64) -> bool {
    values.iter().all(|&v| v == 0.0 || v.abs() >= least)
}
