//! Rim tests (a disk, a capped cylinder's end caps, a cone's base): whether
//! a point of the shape's plane lies within its radius, compared in `f64`
//! at the shape's own power-of-two scale.
//!
//! The tests square lengths (`|v|^2 <= r^2`) or raise them to the fourth
//! power (`|v x a|^2 <= r^2 |a|^2`). In plain `f64` those powers underflow
//! for shapes below about `1e-77` (every point looks inside) and overflow
//! above about `1e77` (`inf <= inf`: again inside), so casts reported hits
//! far outside the shape. Scaling each factor by a power of two first
//! (`unit_pow2`: the radius, and separately the axis, brought to `[1/2,
//! 1)`) leaves every rounding of the comparison as it was wherever the
//! unscaled values were normal, since the inequalities are homogeneous in
//! each factor; only the range changes. A point far outside may overflow
//! after scaling: `inf` (or NaN from `inf * 0`) compares false, outside,
//! which is right there (the point lies more than `2^1000` radii away).
//! What stays approximate is what was: a point within a few ulps of the
//! rim may go either way.

use crate::arith::exponent::{pow2, scale_pow2, unit_pow2, unit_scale};
use glam::DVec3;

/// Whether `|v| <= radius`, computed as `|v s|^2 <= (radius s)^2` at the
/// radius's scale `s`.
#[inline]
pub(super) fn within_radius(v: DVec3, radius: f64) -> bool {
    let s = unit_pow2(radius);
    let (v, r) = (v * s, radius * s);
    v.dot(v) <= r * r
}

/// Whether the point `v` (from a point of the axis line) lies within
/// `radius` of the axis line of direction `axis`: `|v x a|^2 <= r^2
/// |a|^2`, with `v` and `r` at the radius's scale and `a` at its own.
#[inline]
pub(super) fn within_axis_radius(v: DVec3, axis: DVec3, radius: f64) -> bool {
    let s = unit_pow2(radius);
    let a = axis * unit_pow2(axis.abs().max_element());
    let (v, r) = (v * s, radius * s);
    let radial = v.cross(a);
    radial.dot(radial) <= r * r * a.dot(a)
}

/// `(h, s)` with `0 <= h <= s` exactly when `0 <= v . a <= a . a`: the
/// height of the point `v` (from the axis's base) along the axis `a`
/// against the axis's own, for the test of a capped cylinder's side and a
/// cone's nappe. `v` and `a` are each brought near 1 by their own power of
/// two, `h = (v 2^kv) . (a 2^ka)` and `s = |a 2^ka|^2 2^(kv - ka)`: both
/// are the unscaled ones times `2^(kv + ka)`, so the comparisons are the
/// unscaled ones wherever those were normal. Scaled by the axis's power
/// alone, a point far nearer the base than the axis is long underflowed
/// to `h = 0` (a fuzz-like finding of the capped cone's test: a point
/// `1e-147` below a cone's apex along an axis of length `1e177` passed as
/// on its nappe); `a . a` no longer underflows for axes below about
/// `1e-154` (where every point of the infinite surface passed as
/// "between the caps"). `s` overflows to infinity only where `|a|` exceeds
/// `|v|` by more than `2^1023`, and underflows only where `|v|` exceeds
/// `|a|` by as much: the comparison is right there at `f64`'s resolution.
#[inline]
pub(super) fn heights(v: DVec3, axis: DVec3) -> (f64, f64) {
    let unit = |v: DVec3| unit_scale(&v.to_array()).clamp(-1000, 1000);
    let (kv, ka) = (unit(v), unit(axis));
    let (v, a) = (v * pow2(kv), axis * pow2(ka));
    (v.dot(a), scale_pow2(a.dot(a), kv - ka))
}

/// The axis `a` scaled by the power of two that brings it near 1, `â`:
/// an end plane's crossing `t = (level - (o - p) . a) / (d . a)` (level 0
/// or `|a|^2`) is the same with every `a` on the right replaced by `â`
/// (numerator and denominator both scale once), and `a . â` is about `|a|`
/// where `|a|^2` overflowed above about `1e154` or underflowed below
/// `1e-154`. The dot products' error bounds hold for `â` as for `a`.
#[inline]
pub(super) fn unit_axis(axis: DVec3) -> DVec3 {
    axis * unit_pow2(axis.abs().max_element())
}
