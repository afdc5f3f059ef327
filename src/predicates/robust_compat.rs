//! The `robust` crate's interface, exact for every finite input: a door for
//! code written against `robust` (Delaunay triangulators, mesh generators).
//!
//! Same names, same input types, same argument order, same sign conventions
//! and the same `f64` return as `robust` 1.x, so switching is one `use`
//! line. Where `robust` answers from its first stage (almost every ordinary
//! input) the value returned is bit for bit the one `robust` returns; where
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
//! assert!(robust::orient2d(c(0.0, 0.0), c(1e-200, 0.0), c(0.0, 1e-200)) == 0.0);
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
//! [`Coord`] and [`Coord3D`] are `robust`'s own types, re-exported, not
//! look-alikes: values, type annotations and function pointers written for
//! `robust` keep compiling, and code halfway through a switch can pass the
//! same points to both (no `From` conversion is needed: there is one type).
//! The price is that this module's signature follows `robust`'s major
//! version (today 1.x; Cargo unifies a user's `robust` 1.x with this
//! crate's, so the types are the same).
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
//! Its sign is the exact sign of the determinant: `> 0.0`, `< 0.0` and
//! `== 0.0` give the exact answer for every finite input. Its magnitude is
//! - `0.0` exactly (positive zero) when the determinant is zero;
//! - otherwise, Shewchuk's first-stage `f64` evaluation of the determinant
//!   (`robust`'s, same formula and order of operations) when it is finite and
//!   of the exact sign; wherever `robust` returns that evaluation with the
//!   exact sign (its first stage certified it, as it does for almost all
//!   ordinary inputs), this is its return value to the bit;
//! - otherwise (that evaluation underflowed to zero, overflowed, or has the
//!   wrong sign on a near-degenerate input) `f64::MIN_POSITIVE` with the exact
//!   sign, a value that carries the sign and nothing else.
//!
//! `robust`'s later stages return a closer estimate of the determinant on
//! near-degenerate inputs; these functions do not (the sign comes from
//! [`super`]'s exact ladder, which does not produce one).
//!
//! # Non-finite input
//! A NaN or infinite coordinate gives NaN: every comparison with it is false,
//! so a caller's `> 0.0`, `< 0.0` and `== 0.0` all decline. No function here
//! panics or allocates.
//!
//! # Performance
//! One call costs the matching predicate of [`super`] plus the first-stage
//! evaluation beside it, the `f64` determinant alone (no error bound), so
//! the sign is decided once, by the exact ladder.

use crate::sign::Sign;
use glam::{DVec2, DVec3};

#[doc(inline)]
pub use robust::{Coord, Coord3D};

/// Positive when `pa, pb, pc` occur in counterclockwise order (`pc` lies to
/// the left of the directed line `pa, pb`), negative when clockwise, `0.0`
/// when they are collinear: `robust::orient2d`, exact.
///
/// # Accuracy
/// The sign is exact for every finite input; the magnitude is described in
/// the [module docs](self#the-returned-value). A NaN or infinite coordinate
/// gives NaN.
///
/// ```
/// use exactray::predicates::robust_compat::{Coord, orient2d};
/// let c = |x: f64, y: f64| Coord { x, y };
/// assert!(orient2d(c(0.0, 0.0), c(1.0, 0.0), c(0.0, 1.0)) > 0.0);
/// // On the line y = x, whatever the rounding of 0.1, 0.2 and 0.3.
/// assert!(orient2d(c(0.1, 0.1), c(0.2, 0.2), c(0.3, 0.3)) == 0.0);
/// ```
#[inline]
pub fn orient2d<T: Into<f64>>(pa: Coord<T>, pb: Coord<T>, pc: Coord<T>) -> f64 {
    let (a, b, c) = (dvec2(pa), dvec2(pb), dvec2(pc));
    // Shewchuk's stage A, in robust's order.
    let detleft = (a.x - c.x) * (b.y - c.y);
    let detright = (a.y - c.y) * (b.x - c.x);
    let first_stage = detleft - detright;
    // A finite first stage proves every coordinate finite: each coordinate
    // enters it through sums, differences and products only, and a NaN or
    // an infinity survives every one of those (as itself or as NaN).
    // Otherwise ask the coordinates.
    if !first_stage.is_finite() && !finite2(&[a, b, c]) {
        return f64::NAN;
    }
    with_exact_sign(super::orient2d(a, b, c), first_stage)
}

/// Positive when `pd` lies below the plane through `pa, pb, pc` (the side
/// from which they appear clockwise), negative above, `0.0` when the four
/// points are coplanar: `robust::orient3d`, exact. The opposite sign of
/// [`super::orient3d`].
///
/// # Accuracy
/// The sign is exact for every finite input; the magnitude is described in
/// the [module docs](self#the-returned-value). A NaN or infinite coordinate
/// gives NaN.
///
/// ```
/// use exactray::predicates::robust_compat::{Coord3D, orient3d};
/// let p = |x: f64, y: f64, z: f64| Coord3D { x, y, z };
/// let (a, b, c) = (p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0));
/// // a, b, c are counterclockwise seen from +z: +z is above.
/// assert!(orient3d(a, b, c, p(0.0, 0.0, 1.0)) < 0.0);
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
    // Shewchuk's stage A, in robust's order.
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let first_stage = ad.z * (bd.x * cd.y - cd.x * bd.y)
        + bd.z * (cd.x * ad.y - ad.x * cd.y)
        + cd.z * (ad.x * bd.y - bd.x * ad.y);
    // Why a finite value proves finite input: see `orient2d`.
    if !first_stage.is_finite() && !finite3(&[a, b, c, d]) {
        return f64::NAN;
    }
    // Shewchuk's orientation is CGAL's with the sign flipped.
    with_exact_sign(-super::orient3d(a, b, c, d), first_stage)
}

/// Positive when `pd` lies inside the circle through `pa, pb, pc`, negative
/// outside, `0.0` when the four points are cocircular; `pa, pb, pc` must be
/// counterclockwise or the sign is reversed: `robust::incircle`, exact.
///
/// # Accuracy
/// The sign is exact for every finite input; the magnitude is described in
/// the [module docs](self#the-returned-value). A NaN or infinite coordinate
/// gives NaN.
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
    // Shewchuk's stage A, in robust's order.
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let alift = ad.x * ad.x + ad.y * ad.y;
    let blift = bd.x * bd.x + bd.y * bd.y;
    let clift = cd.x * cd.x + cd.y * cd.y;
    let first_stage = alift * (bd.x * cd.y - cd.x * bd.y)
        + blift * (cd.x * ad.y - ad.x * cd.y)
        + clift * (ad.x * bd.y - bd.x * ad.y);
    // Why a finite value proves finite input: see `orient2d`.
    if !first_stage.is_finite() && !finite2(&[a, b, c, d]) {
        return f64::NAN;
    }
    with_exact_sign(super::incircle(a, b, c, d), first_stage)
}

/// Positive when `pe` lies inside the sphere through `pa, pb, pc, pd`,
/// negative outside, `0.0` when the five points are cospherical; `pa, pb,
/// pc, pd` must have this module's [`orient3d`] positive or the sign is
/// reversed: `robust::insphere`, exact. The opposite sign of
/// [`super::insphere`].
///
/// # Accuracy
/// The sign is exact for every finite input; the magnitude is described in
/// the [module docs](self#the-returned-value). A NaN or infinite coordinate
/// gives NaN.
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
    let (a, b, c, d, e) = (dvec3(pa), dvec3(pb), dvec3(pc), dvec3(pd), dvec3(pe));
    let first_stage = insphere_first_stage(a, b, c, d, e);
    // Why a finite value proves finite input: see `orient2d`.
    if !first_stage.is_finite() && !finite3(&[a, b, c, d, e]) {
        return f64::NAN;
    }
    // Shewchuk's in-sphere assumes his orientation, CGAL's the opposite one.
    with_exact_sign(-super::insphere(a, b, c, d, e), first_stage)
}

/// Shewchuk's stage A of `insphere`, in robust's order of operations, so
/// that a value robust certifies is returned to the bit. The crate's own
/// filter computes the same expression today, but it is free to change its
/// order (or its formula) for speed; this one is pinned to robust's.
#[inline(always)]
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

/// The value to return for an exact sign, given the first-stage evaluation
/// (the rule of the [module docs](self#the-returned-value)).
#[inline(always)]
fn with_exact_sign(exact: Sign, first_stage: f64) -> f64 {
    // -1.0, 0.0 or 1.0: the product with a finite first stage is exact, and
    // positive only where their signs agree (false for NaN). Written as one
    // select rather than a match on the sign, which a random sign would
    // mispredict on every other call.
    let sign = f64::from(exact.as_i8());
    let agrees = first_stage * sign > 0.0 && first_stage.abs() < f64::INFINITY;
    // On disagreement `sign * MIN_POSITIVE` is the sign-only value, and
    // `+0.0` for an exact zero.
    if agrees {
        first_stage
    } else {
        sign * f64::MIN_POSITIVE
    }
}

#[inline(always)]
fn dvec2<T: Into<f64>>(p: Coord<T>) -> DVec2 {
    DVec2::new(p.x.into(), p.y.into())
}

#[inline(always)]
fn dvec3<T: Into<f64>>(p: Coord3D<T>) -> DVec3 {
    DVec3::new(p.x.into(), p.y.into(), p.z.into())
}

/// Whether every coordinate is finite (the cold path of a non-finite first
/// stage: overflow on finite input, or a NaN or infinite coordinate).
#[cold]
fn finite2(points: &[DVec2]) -> bool {
    points.iter().all(|p| p.is_finite())
}

/// Whether every coordinate is finite; see [`finite2`].
#[cold]
fn finite3(points: &[DVec3]) -> bool {
    points.iter().all(|p| p.is_finite())
}
