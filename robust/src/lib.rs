//! # Exact geometric predicates with `robust`'s interface
//!
//! This crate has the public interface of [`robust`](https://docs.rs/robust)
//! 1.2 (Shewchuk's orientation and in-circle predicates: [`orient2d`],
//! [`orient3d`], [`incircle`], [`insphere`] on [`Coord`] and [`Coord3D`]
//! points), and answers with the **exact sign for every finite `f64`
//! input**, including those whose products underflow or overflow
//! (coordinates near `1e-160` or `1e+160`, `1e-300` beside `1e+300`), where
//! `robust` can return a wrong sign, a zero or NaN. It is built on
//! [`exactray`](https://docs.rs/exactray)'s predicates
//! (`exactray::predicates::robust_compat`).
//!
//! Its purpose is to replace `robust` in a whole dependency tree (geo,
//! spade, and anything else that calls it) with one entry in the
//! workspace's `Cargo.toml`:
//!
//! ```toml
//! [patch.crates-io]
//! robust = { path = "path/to/exactray/robust" }
//! ```
//!
//! `docs/drop-in.md` in exactray's repository has the git and version
//! forms and what changes.
//!
//! ```
//! use robust::{Coord, orient2d};
//!
//! let c = |x: f64, y: f64| Coord { x, y };
//! assert!(orient2d(c(0.0, 0.0), c(1.0, 0.0), c(0.0, 1.0)) > 0.0);
//! // The products underflow: robust 1.2.0 answers 0.0 ("collinear").
//! assert!(orient2d(c(0.0, 0.0), c(1e-200, 0.0), c(0.0, 1e-200)) > 0.0);
//! ```
//!
//! # Sign conventions (Shewchuk's, as `robust`'s)
//! - [`orient2d`]`(pa, pb, pc)` is positive when `pa, pb, pc` turn
//!   counterclockwise.
//! - [`orient3d`]`(pa, pb, pc, pd)` is positive when `pd` lies below the
//!   plane of `pa, pb, pc`, "below" being the side from which they appear
//!   clockwise.
//! - [`incircle`]`(pa, pb, pc, pd)` is positive when `pd` lies inside the
//!   circle through counterclockwise `pa, pb, pc`.
//! - [`insphere`]`(pa, pb, pc, pd, pe)` is positive when `pe` lies inside
//!   the sphere through `pa, pb, pc, pd`, given with [`orient3d`] positive.
//!
//! # The returned value
//! Each function returns the determinant `D` of its predicate (twice the
//! signed area for [`orient2d`], six times the signed volume for
//! [`orient3d`]):
//! - its sign is exact: `> 0.0`, `< 0.0` and `== 0.0` answer exactly for
//!   every finite input;
//! - `D == 0` gives `0.0`, positive zero (`robust` gives `-0.0` for some
//!   inputs, e.g. `orient2d` of `(0, 0)`, `(1, -1)`, `(0, 0)`; both compare
//!   equal to `0.0`);
//! - where `D` is a normal number the value is within `2^-39 |D|` of it (a
//!   relative error below `1.9e-12`): Shewchuk's first-stage evaluation
//!   where its error bound is below `2^-40` of it (then it is `robust`'s
//!   own value, to the bit: almost every ordinary input), `D` computed
//!   exactly and rounded otherwise (within `2^-52 |D|`);
//! - below the normal range the value is within `2^-1073` of `D` (two
//!   steps of the subnormal grid), and the smallest subnormal of `D`'s sign
//!   where that would round to zero; beyond `f64::MAX` it is an infinity
//!   of `D`'s sign.
//!
//! Where `robust`'s own value has the exact sign, it is within the error
//! bound of the stage that produced it, which certifies a sign, not digits:
//! it is at least `|D| / 2`, and at most `|D|` plus that bound (`3.3e-16`
//! times the sum of the products' magnitudes for orient2d's first stage).
//! So this crate's value and `robust`'s are identical where `robust`'s first
//! stage is accurate to `2^-40`, and otherwise differ by at most `robust`'s
//! own error bound plus `2^-52 |D|`.
//!
//! A NaN or infinite coordinate gives NaN, as nothing else can answer all
//! three comparisons `false`. No function panics or allocates.
//!
//! # Cost
//! Where the first stage is within its bound a call costs what `robust`'s
//! first stage costs. Elsewhere it decides the exact sign first (an exact
//! zero costs no more), then computes a non-zero `D` exactly and rounds it.
//! The crate depends on exactray's `no_std` core (and, through it, `glam`
//! and `libm`). `docs/drop-in.md` in exactray's repository has the
//! figures.
//!
//! # Features
//! - `no_std`: accepted for compatibility with `robust` 1.x; the crate is
//!   `no_std` either way.

#![no_std]

use exactray::predicates::robust_compat;

pub use exactray::predicates::robust_compat::{Coord, Coord3D};

/// Returns a positive value if the coordinates `pa`, `pb`, and `pc` occur
/// in counterclockwise order (`pc` lies to the **left** of the directed
/// line defined by `pa` and `pb`), a negative value if they occur in
/// clockwise order, and `0` if they are **collinear**: exactly, for every
/// finite input. The value is twice the triangle's signed area, within
/// `2^-39` of it where that is a normal number ([crate docs](crate#the-returned-value)).
#[inline]
pub fn orient2d<T: Into<f64>>(pa: Coord<T>, pb: Coord<T>, pc: Coord<T>) -> f64 {
    robust_compat::orient2d(pa, pb, pc)
}

/// Returns a positive value if the point `pd` lies below the plane passing
/// through `pa`, `pb`, and `pc` ("below" is defined so that `pa`, `pb`, and
/// `pc` appear in counterclockwise order when viewed from above the
/// plane), a negative value if `pd` lies above the plane, and `0` if they
/// are **coplanar**: exactly, for every finite input. The value is six
/// times the tetrahedron's signed volume, within `2^-39` of it where that
/// is a normal number ([crate docs](crate#the-returned-value)).
#[inline]
pub fn orient3d<T: Into<f64>>(
    pa: Coord3D<T>,
    pb: Coord3D<T>,
    pc: Coord3D<T>,
    pd: Coord3D<T>,
) -> f64 {
    robust_compat::orient3d(pa, pb, pc, pd)
}

/// Returns a positive value if the point `pd` lies inside the circle
/// passing through `pa`, `pb`, and `pc`, a negative value if it lies
/// outside, and `0` if the four points are **cocircular**, for `pa`, `pb`,
/// `pc` in counterclockwise order (the sign is reversed otherwise):
/// exactly, for every finite input. The value is the in-circle
/// determinant, within `2^-39` of it where that is a normal number
/// ([crate docs](crate#the-returned-value)).
#[inline]
pub fn incircle<T: Into<f64>>(pa: Coord<T>, pb: Coord<T>, pc: Coord<T>, pd: Coord<T>) -> f64 {
    robust_compat::incircle(pa, pb, pc, pd)
}

/// Returns a positive value if the point `pe` lies inside the sphere
/// passing through `pa`, `pb`, `pc`, and `pd`, a negative value if it lies
/// outside, and `0` if the five points are **cospherical**, for `pa`, `pb`,
/// `pc`, `pd` with [`orient3d`] positive (the sign is reversed otherwise):
/// exactly, for every finite input. The value is the in-sphere
/// determinant, within `2^-39` of it where that is a normal number
/// ([crate docs](crate#the-returned-value)).
#[inline]
pub fn insphere<T: Into<f64>>(
    pa: Coord3D<T>,
    pb: Coord3D<T>,
    pc: Coord3D<T>,
    pd: Coord3D<T>,
    pe: Coord3D<T>,
) -> f64 {
    robust_compat::insphere(pa, pb, pc, pd, pe)
}
