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

use crate::arith::exponent::unit_pow2;
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

/// `(v . a, a . a)` with `v` and `a` both scaled by the power of two that
/// brings `a` near 1: the height of the point `v` (from the axis's base)
/// along the axis `a` against the axis's own, for the test `0 <= h <= |a|^2`
/// of a capped cylinder's side and a cone's nappe. Both scale by the same
/// `4^k`, so the comparison is the unscaled one wherever that was normal,
/// and `a . a` no longer underflows for axes below about `1e-154` (where
/// every point of the infinite surface passed as "between the caps").
#[inline]
pub(super) fn heights(v: DVec3, axis: DVec3) -> (f64, f64) {
    let s = unit_pow2(axis.abs().max_element());
    let (v, a) = (v * s, axis * s);
    (v.dot(a), a.dot(a))
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
