//! The `robust` crate's interface, exact for every finite input: a door for
//! code written against `robust` (Delaunay triangulators, mesh generators).
//!
//! Same names, point types declared as `robust`'s, same argument order,
//! same sign conventions and the same `f64` return as `robust` 1.x, so
//! switching is one `use` line. Where `robust`'s first stage is accurate to
//! `2^-40` of itself (almost every ordinary input) the value returned is
//! bit for bit the one `robust` returns; where
//! its products underflow or overflow (coordinates near `1e-160` or
//! `1e+160`, `1e-300` beside `1e+300`) `robust` can return a wrong sign, a
//! zero or NaN, and these functions still return the exact sign.
//!
//! ```
//! // Before:
//! // use robust::{Coord, incircle, orient2d};
//! use exactray::predicates::robust_compat::{Coord, incircle, orient2d};
//!
//! let c = |x: f64, y: f64| Coord { x, y };
//! assert!(orient2d(c(0.0, 0.0), c(1.0, 0.0), c(0.0, 1.0)) > 0.0);
//! assert!(incircle(c(1.0, 0.0), c(0.0, 1.0), c(-1.0, 0.0), c(0.0, -1.0)) == 0.0);
//! // The products underflow: robust's answer is 0.0 ("collinear").
//! let r = |x: f64, y: f64| robust::Coord { x, y };
//! assert!(robust::orient2d(r(0.0, 0.0), r(1e-200, 0.0), r(0.0, 1e-200)) == 0.0);
//! assert!(orient2d(c(0.0, 0.0), c(1e-200, 0.0), c(0.0, 1e-200)) > 0.0);
//! ```
//!
//! Code that calls `robust::orient2d(..)` by its full path swaps with one
//! line in the module too, which shadows the crate's name there:
//!
//! ```
//! use exactray::predicates::robust_compat as robust;
//!
//! let c = |x: f64, y: f64| robust::Coord { x, y };
//! // 1e-300 above the line through -1e300 and 1e300: robust's own gives NaN.
//! assert!(robust::orient2d(c(-1e300, -1e300), c(1e300, 1e300), c(0.0, 1e-300)) > 0.0);
//! ```
//!
//! # The types
//! [`Coord`] and [`Coord3D`] are this crate's own, declared as `robust`
//! 1.2 declares its: the same public fields, the same `T: Into<f64>`
//! bound, the same derives (`Copy`, `Clone`, `Debug`, `PartialEq`) and no
//! other trait. Code written against `robust`'s types compiles against
//! these unchanged; they are distinct types, though, so a program that
//! keeps both crates converts between them field by field. To make every
//! `robust` call of a whole dependency tree exact, with one `Coord` type,
//! the `robust` drop-in crate of this repository replaces `robust` itself
//! (`docs/drop-in.md`).
//!
//! # Sign conventions (Shewchuk's)
//! - [`orient2d`]`(pa, pb, pc)` is positive when `pa, pb, pc` turn
//!   counterclockwise: the same sign as [`super::orient2d`].
//! - [`orient3d`]`(pa, pb, pc, pd)` is positive when `pd` lies *below* the
//!   plane of `pa, pb, pc`, "below" being the side from which they appear
//!   clockwise: the **opposite** of [`super::orient3d`] (CGAL's).
//! - [`incircle`]`(pa, pb, pc, pd)` is positive when `pd` lies inside the
//!   circle through counterclockwise `pa, pb, pc`: the same sign as
//!   [`super::incircle`].
//! - [`insphere`]`(pa, pb, pc, pd, pe)` is positive when `pe` lies inside the
//!   sphere through `pa, pb, pc, pd` given with [`orient3d`] (this module's)
//!   positive: the **opposite** of [`super::insphere`].
//!
//! `tests/robust_compat.rs` checks each against `robust` itself.
//!
//! # The returned value
//! Its sign is the exact sign of the determinant `D`: `> 0.0`, `< 0.0` and
//! `== 0.0` give the exact answer for every finite input. Its magnitude:
//! - `D == 0`: `0.0` (positive zero; `robust` sometimes returns `-0.0`);
//! - `D` a normal number: within `2^-39 |D|` of `D` (a relative error below
//!   `1.9e-12`). Where Shewchuk's first-stage `f64` evaluation (`robust`'s,
//!   same formula and order of operations) has an error bound below `2^-40`
//!   of itself, that evaluation is returned: wherever `robust` returns it
//!   too, the two agree to the bit (almost every ordinary input). Elsewhere
//!   it is `D` computed exactly and rounded: correctly where the
//!   coordinates span at most about 125 bits (orient2d: 62), within
//!   `2^-52 |D|` otherwise;
//! - `D` below the normal range: within `2^-1073` of `D` (two steps of the
//!   subnormal grid), and never zero (the smallest subnormal, with `D`'s
//!   sign, where `D` rounds to zero);
//! - `|D|` beyond `f64::MAX`: an infinity of `D`'s sign.
//!
//! Where `robust`'s own value has the exact sign, it is within its stage's
//! error bound of `D` (for its first stage, `3.3e-16` times the sum of the
//! magnitudes of the products, e.g. `|detleft| + |detright|` for
//! orient2d); its stages certify a sign, not digits, so that bound can
//! exceed `|D|`: `robust`'s value is then at least `|D| / 2` but may be
//! several times `|D|`. Where the two differ, these functions' value is
//! `D` rounded, within `2^-52 |D|`.
//!
//! # Non-finite input
//! A NaN or infinite coordinate gives NaN: every comparison with it is false,
//! so a caller's `> 0.0`, `< 0.0` and `== 0.0` all decline. No function here
//! panics or allocates.
//!
//! # Performance
//! Where the first-stage value is within its bound (almost every ordinary
//! input), a call costs that evaluation and its bound, as `robust`'s
//! first stage does. Elsewhere it first decides the exact sign with
//! [`super`]'s predicates, and an exact zero costs no more; a non-zero `D`
//! is then computed exactly: as integers at the coordinates' finest bits
//! (one or two limbs each) where they span at most about 125 bits
//! (orient2d: 62), otherwise as its exact terms
//! summed from the largest down until the rest is below `2^-60` of the
//! sum. `docs/drop-in.md` has the figures.

use super::det;
use super::incircle as circle;
use super::insphere as sphere;
use super::orient2d as o2;
use super::orient3d as o3;
use crate::arith::exponent::{TINY, pow2};
use crate::arith::scaled_float::ScaledFloat;
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// `2^40`: a first-stage value is returned when its error bound is below
/// `2^-40` of it; then `|value - D| < 2^-40 |value|`, so `|D| > (1 -
/// 2^-40) |value|` and `|value - D| < 2^-40 / (1 - 2^-40) |D| < 2^-39 |D|`.
const RELATIVE: f64 = pow2(40);

/// A two-dimensional point, as `robust::Coord`: its coordinates convert
/// to `f64` exactly for `f64`, `f32` and the integer types `Into<f64>`
/// accepts.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Coord<T: Into<f64>> {
    /// The first coordinate.
    pub x: T,
    /// The second coordinate.
    pub y: T,
}

/// A three-dimensional point, as `robust::Coord3D`.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Coord3D<T: Into<f64>> {
    /// The first coordinate.
    pub x: T,
    /// The second coordinate.
    pub y: T,
    /// The third coordinate.
    pub z: T,
}

/// Positive when `pa, pb, pc` occur in counterclockwise order (`pc` lies to
/// the left of the directed line `pa, pb`), negative when clockwise, `0.0`
/// when they are collinear: `robust::orient2d`, exact.
///
/// # Accuracy
/// The sign is exact for every finite input; the magnitude is within
/// `2^-39` of the determinant's where that is a normal number (the [module
/// docs](self#the-returned-value) say the rest). A NaN or infinite
/// coordinate gives NaN.
///
/// ```
/// use exactray::predicates::robust_compat::{Coord, orient2d};
/// let c = |x: f64, y: f64| Coord { x, y };
/// assert_eq!(orient2d(c(0.0, 0.0), c(2.0, 0.0), c(0.0, 3.0)), 6.0);
/// // On the line y = x, whatever the rounding of 0.1, 0.2 and 0.3.
/// assert!(orient2d(c(0.1, 0.1), c(0.2, 0.2), c(0.3, 0.3)) == 0.0);
/// // The products overflow: twice the area, 2^301, all the same.
/// let (a, b) = (c(-2f64.powi(600), -2f64.powi(600)), c(2f64.powi(600), 2f64.powi(600)));
/// assert_eq!(orient2d(a, b, c(0.0, 2f64.powi(-300))), 2f64.powi(301));
/// ```
#[inline]
pub fn orient2d<T: Into<f64>>(pa: Coord<T>, pb: Coord<T>, pc: Coord<T>) -> f64 {
    let (a, b, c) = (dvec2(pa), dvec2(pb), dvec2(pc));
    // Shewchuk's stage A, in robust's order, and its bound `A detsum +
    // UNDERFLOW_SLACK`, compared as stage A compares it (no subnormal
    // operand on this path).
    let p = o2::products(a, b, c);
    let (first, detsum, _) = o2::stage_a_lanes(p.x, p.y);
    if first.abs() - (RELATIVE * o2::A) * detsum > RELATIVE * o2::UNDERFLOW_SLACK {
        return first;
    }
    rounded(
        finite2(&[a, b, c]),
        || o2::orient2d(a, b, c),
        || o2::rounded_determinant(a, b, c),
    )
}

/// Positive when `pd` lies below the plane through `pa, pb, pc` (the side
/// from which they appear clockwise), negative above, `0.0` when the four
/// points are coplanar: `robust::orient3d`, exact. The opposite sign of
/// [`super::orient3d`].
///
/// # Accuracy
/// As [`orient2d`]'s: the exact sign, and the magnitude within `2^-39` of
/// the determinant's where that is a normal number. A NaN or infinite
/// coordinate gives NaN.
///
/// ```
/// use exactray::predicates::robust_compat::{Coord3D, orient3d};
/// let p = |x: f64, y: f64, z: f64| Coord3D { x, y, z };
/// let (a, b, c) = (p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0));
/// // a, b, c are counterclockwise seen from +z: +z is above.
/// assert_eq!(orient3d(a, b, c, p(0.0, 0.0, 1.0)), -1.0);
/// assert!(orient3d(a, b, c, p(0.0, 0.0, -1.0)) > 0.0);
/// assert!(orient3d(a, b, c, p(0.3, 0.7, 0.0)) == 0.0);
/// ```
#[inline]
pub fn orient3d<T: Into<f64>>(
    pa: Coord3D<T>,
    pb: Coord3D<T>,
    pc: Coord3D<T>,
    pd: Coord3D<T>,
) -> f64 {
    let (a, b, c, d) = (dvec3(pa), dvec3(pb), dvec3(pc), dvec3(pd));
    // Shewchuk's stage A with `d` as the origin, in robust's order.
    let rows = [a - d, b - d, c - d].map(|v| v.to_array());
    let (first, permanent, _, zsum) = det::stage_a_rows(rows[0], rows[1], rows[2]);
    if det::within(first, permanent, zsum, RELATIVE) {
        return first;
    }
    // Shewchuk's orientation is CGAL's with the sign flipped.
    rounded(
        finite3(&[a, b, c, d]),
        || o3::orient3d(a, b, c, d),
        || o3::rounded_determinant(&[a, b, c, d]).neg(),
    )
}

/// Positive when `pd` lies inside the circle through `pa, pb, pc`, negative
/// outside, `0.0` when the four points are cocircular; `pa, pb, pc` must be
/// counterclockwise or the sign is reversed: `robust::incircle`, exact.
///
/// # Accuracy
/// As [`orient2d`]'s: the exact sign, and the magnitude within `2^-39` of
/// the determinant's where that is a normal number. A NaN or infinite
/// coordinate gives NaN.
///
/// ```
/// use exactray::predicates::robust_compat::{Coord, incircle};
/// let c = |x: f64, y: f64| Coord { x, y };
/// let (a, b, d) = (c(1.0, 0.0), c(0.0, 1.0), c(-1.0, 0.0));
/// assert!(incircle(a, b, d, c(0.0, 0.0)) > 0.0);
/// assert!(incircle(a, b, d, c(0.0, -1.0)) == 0.0);
/// assert!(incircle(a, b, d, c(2.0, 0.0)) < 0.0);
/// ```
#[inline]
pub fn incircle<T: Into<f64>>(pa: Coord<T>, pb: Coord<T>, pc: Coord<T>, pd: Coord<T>) -> f64 {
    let (a, b, c, d) = (dvec2(pa), dvec2(pb), dvec2(pc), dvec2(pd));
    // Shewchuk's stage A, in robust's order; NaN where its guard declines.
    let (first, bound) = circle::first_stage(a, b, c, d);
    if first.abs() > RELATIVE * bound {
        return first;
    }
    rounded(
        finite2(&[a, b, c, d]),
        || circle::incircle(a, b, c, d),
        || circle::rounded_determinant(&[a, b, c, d]),
    )
}

/// Positive when `pe` lies inside the sphere through `pa, pb, pc, pd`,
/// negative outside, `0.0` when the five points are cospherical; `pa, pb,
/// pc, pd` must have this module's [`orient3d`] positive or the sign is
/// reversed: `robust::insphere`, exact. The opposite sign of
/// [`super::insphere`].
///
/// # Accuracy
/// As [`orient2d`]'s: the exact sign, and the magnitude within `2^-39` of
/// the determinant's where that is a normal number. A NaN or infinite
/// coordinate gives NaN.
///
/// ```
/// use exactray::predicates::robust_compat::{Coord3D, insphere, orient3d};
/// let p = |x: f64, y: f64, z: f64| Coord3D { x, y, z };
/// // d below the counterclockwise a, b, c: a positive tetrahedron here.
/// let (a, b, c, d) = (p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0), p(0.0, 0.0, -1.0));
/// assert!(orient3d(a, b, c, d) > 0.0);
/// assert!(insphere(a, b, c, d, p(0.25, 0.25, -0.25)) > 0.0);
/// assert!(insphere(a, b, c, d, p(1.0, 1.0, -1.0)) == 0.0);
/// assert!(insphere(a, b, c, d, p(2.0, 2.0, -2.0)) < 0.0);
/// ```
#[inline]
pub fn insphere<T: Into<f64>>(
    pa: Coord3D<T>,
    pb: Coord3D<T>,
    pc: Coord3D<T>,
    pd: Coord3D<T>,
    pe: Coord3D<T>,
) -> f64 {
    let p = [dvec3(pa), dvec3(pb), dvec3(pc), dvec3(pd), dvec3(pe)];
    // Shewchuk's stage A, in robust's order (positive inside under his
    // orientation); NaN where its guard declines.
    let (first, bound) = sphere::first_stage(&p);
    if first.abs() > RELATIVE * bound {
        return first;
    }
    rounded(
        finite3(&p),
        || sphere::insphere(p[0], p[1], p[2], p[3], p[4]),
        || sphere::rounded_determinant(&p),
    )
}

/// Shewchuk's stage A of `insphere`, in robust's order of operations: the
/// reference `insphere`'s paired filter is checked against, so that the
/// value returned is robust's to the bit.
#[cfg(test)]
pub(super) fn insphere_first_stage(a: DVec3, b: DVec3, c: DVec3, d: DVec3, e: DVec3) -> f64 {
    let (ae, be, ce, de) = (a - e, b - e, c - e, d - e);
    let ab = ae.x * be.y - be.x * ae.y;
    let bc = be.x * ce.y - ce.x * be.y;
    let cd = ce.x * de.y - de.x * ce.y;
    let da = de.x * ae.y - ae.x * de.y;
    let ac = ae.x * ce.y - ce.x * ae.y;
    let bd = be.x * de.y - de.x * be.y;

    let abc = ae.z * bc - be.z * ac + ce.z * ab;
    let bcd = be.z * cd - ce.z * bd + de.z * bc;
    let cda = ce.z * da + de.z * ac + ae.z * cd;
    let dab = de.z * ab + ae.z * bd + be.z * da;

    let alift = ae.x * ae.x + ae.y * ae.y + ae.z * ae.z;
    let blift = be.x * be.x + be.y * be.y + be.z * be.z;
    let clift = ce.x * ce.x + ce.y * ce.y + ce.z * ce.z;
    let dlift = de.x * de.x + de.y * de.y + de.z * de.z;

    (dlift * abc - clift * dab) + (blift * cda - alift * bcd)
}

/// The value for an input the first stage could not answer within
/// `2^-40`: NaN for non-finite input, `0.0` where the predicate's exact
/// sign (`sign()`, the crate's ladder: cheaper than the value) is zero,
/// otherwise the exact determinant `exact()` rounded to `f64` (the rule of
/// the [module docs](self#the-returned-value)), never zero.
#[cold]
#[inline(never)]
fn rounded(finite: bool, sign: impl FnOnce() -> Sign, exact: impl FnOnce() -> ScaledFloat) -> f64 {
    if !finite {
        return f64::NAN;
    }
    if sign() == Sign::Zero {
        return 0.0;
    }
    let d = exact();
    let v = d.to_f64();
    if v == 0.0 && !d.is_zero() {
        return if d.is_negative() { -TINY } else { TINY };
    }
    v
}

#[inline(always)]
fn dvec2<T: Into<f64>>(p: Coord<T>) -> DVec2 {
    DVec2::new(p.x.into(), p.y.into())
}

#[inline(always)]
fn dvec3<T: Into<f64>>(p: Coord3D<T>) -> DVec3 {
    DVec3::new(p.x.into(), p.y.into(), p.z.into())
}

/// Whether every coordinate is finite.
fn finite2(points: &[DVec2]) -> bool {
    points.iter().all(|p| p.is_finite())
}

/// Whether every coordinate is finite.
fn finite3(points: &[DVec3]) -> bool {
    points.iter().all(|p| p.is_finite())
}
