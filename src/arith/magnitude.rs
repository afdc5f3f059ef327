//! Largest magnitudes, as the filters' error bounds take them.

use glam::DVec3;

/// `a` or `b`, whichever is larger: one `maxsd`, where `f64::max` also
/// handles NaN (for finite values, or values that overflowed to
/// infinity, the same).
#[inline(always)]
pub(crate) fn larger(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// `u` or `v`, whichever is larger, component by component: one `maxsd`
/// each, where `DVec3::select` on a comparison may branch (and random
/// inputs mispredict half of those branches).
#[inline(always)]
pub(crate) fn larger3(u: DVec3, v: DVec3) -> DVec3 {
    DVec3::new(larger(u.x, v.x), larger(u.y, v.y), larger(u.z, v.z))
}

/// Whether every component of `m` lies in `[lo, hi]` (`false` for NaN):
/// comparisons of floats, not of glam's `BVec3` (whose operations branch).
#[inline(always)]
pub(crate) fn all_within(m: DVec3, lo: f64, hi: f64) -> bool {
    let smallest = if m.x < m.y { m.x } else { m.y };
    let smallest = if smallest < m.z { smallest } else { m.z };
    smallest >= lo && larger(larger(m.x, m.y), m.z) <= hi
}

/// `a` or `b`, whichever is smaller: one `minsd`, as [`larger`].
#[inline(always)]
pub(crate) fn smaller(a: f64, b: f64) -> f64 {
    if a < b { a } else { b }
}

/// Whether every value is zero or at least `least` in magnitude (`false`
/// for NaN): the filters' difference guards, which a zero difference
/// passes (its products are exactly zero, they cannot underflow), where
/// their quick test, the smallest magnitude, turns zeros away.
#[inline]
pub(crate) fn zero_or_at_least(values: &[f64], least: f64) -> bool {
    values
        .iter()
        .fold(true, |ok, &v| ok & ((v == 0.0) | (v.abs() >= least)))
}

/// The largest magnitude in `values` (a NaN is passed over), in four
/// independent chains of comparisons rather than one long one.
#[inline(always)]
pub(crate) fn largest_abs(values: &[f64]) -> f64 {
    let mut m = [0.0; 4];
    for (i, v) in values.iter().enumerate() {
        m[i % 4] = larger(m[i % 4], v.abs());
    }
    larger(larger(m[0], m[1]), larger(m[2], m[3]))
}
