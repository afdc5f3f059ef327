//! Exact geometric predicates for every finite `f64` input.
//!
//! Each predicate returns the exact [`Sign`] of a polynomial in its input
//! coordinates, taking every coordinate as the exact number its bits denote.
//! There is no input range restriction: subnormals, values whose products
//! underflow (|x| around 1e-160), values whose products overflow (around
//! 1e+160) and mixed magnitudes (1e-300 beside 1e+300) are all exact.
//!
//! # Sign conventions
//! - [`orient2d`]`(a, b, c)` is the sign of `(b - a) x (c - a)`: positive when
//!   `a, b, c` turn counterclockwise (CGAL `LEFT_TURN`; same as Shewchuk's).
//! - [`orient3d`]`(a, b, c, d)` is the sign of `det[b - a, c - a, d - a]`
//!   (CGAL `orientation`). It is positive when `d` lies on the side of the
//!   plane through `a, b, c` that their counterclockwise order, seen from `d`,
//!   faces. This is the **opposite** of Shewchuk's `orient3d` (and of the
//!   `robust` crate's), which is positive when `d` lies *below* the plane of
//!   counterclockwise `a, b, c`: `orient3d(a, b, c, d) == -sign(robust::orient3d(a, b, c, d))`.
//! - [`incircle`]`(a, b, c, d)` is positive when `d` lies inside the circle
//!   through `a, b, c` and `a, b, c` are counterclockwise (the sign flips with
//!   their order); CGAL `side_of_oriented_circle`, same as Shewchuk's.
//! - [`insphere`]`(a, b, c, d, e)` is positive when `e` lies inside the sphere
//!   through `a, b, c, d` and `orient3d(a, b, c, d)` is positive (CGAL
//!   `side_of_oriented_sphere`). Shewchuk's `insphere` assumes his opposite
//!   orientation, so it equals `-sign(robust::insphere(a, b, c, d, e))`.
//!
//! So **`orient3d` and `insphere` here have the opposite sign of
//! `robust`'s**; `orient2d` and `incircle` have the same. Code written
//! against the `robust` crate (Shewchuk's conventions, `f64` returns) can
//! use [`robust_compat`] instead: `robust`'s interface and signs on these
//! exact answers, switched with one `use` line.
//!
//! The two cannot be mixed up by accident: these functions return a
//! [`Sign`], which does not compare with an `f64`, so `robust`'s
//! `orient3d(..) > 0.0` does not compile on them, and converting `robust`'s
//! value is a visible step ([`Sign::of_f64`], negated for `orient3d` and
//! `insphere`):
//!
//! ```
//! use exactray::Sign;
//! use exactray::predicates::{orient3d, robust_compat};
//!
//! let (a, b, c, d) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
//! let p = |[x, y, z]: [f64; 3]| robust_compat::Coord3D { x, y, z };
//! let shewchuk = robust_compat::orient3d(p(a), p(b), p(c), p(d));
//! assert!(shewchuk < 0.0);
//! assert_eq!(orient3d(a, b, c, d), Sign::Positive);
//! assert_eq!(orient3d(a, b, c, d), -Sign::of_f64(shewchuk));
//! ```
//!
//! ```compile_fail,E0308
//! use exactray::predicates::orient3d;
//! // Shewchuk's test on CGAL's sign: a type error, not a silent flip.
//! let above = orient3d([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]) > 0.0;
//! ```
//!
//! # Non-finite input
//! The plain functions never panic. On a NaN or infinite coordinate they
//! return [`Sign::Zero`], which means "no answer" there; the `try_` variants
//! return [`InputError::NonFinite`] naming the first bad argument instead.
//!
//! # How exactness is kept cheap
//! Every predicate runs a ladder of stages, each named for what it
//! guarantees, and stops at the first one that can certify the sign. The
//! stages, numbered as in each predicate's file:
//! 0. **semi-static filter** (orient3d and insphere): stage 1's
//!    determinant with a bound from the largest difference on each axis
//!    instead of the permanent, where those lie in a range that keeps the
//!    bound valid. Answers almost every ordinary input for the price of the
//!    determinant alone.
//! 1. **filtered**: the plain `f64` determinant and an error bound computed
//!    beside it (Shewchuk's stage A bound, widened by an absolute term so
//!    that it holds under underflow too; overflow makes the bound infinite
//!    and the stage declines).
//! 2. **small-integer exact**: when each input coordinate is an integer
//!    multiple of a common power of two that leaves it 62 bits or fewer, the
//!    determinant is evaluated exactly in 64/128/256/320-bit integers.
//!    Answers degenerate and near-degenerate inputs, and tiny or huge ones.
//!    The **lattice** stage comes with it: the determinant is a multiple of
//!    `2^(degree * lo)`, `2^lo` the inputs' finest bit, and when stage 1's
//!    (or stage 0's) error bound lies below that step, the value it could
//!    not tell from zero is zero. Answers exactly degenerate inputs with
//!    short significands at the cost of the filter and a pass over the
//!    coordinates.
//! 3. **adaptive**: Shewchuk's adaptive stages (the `robust` crate) on inputs
//!    scaled by a power of two, only when the exponent spread proves that no
//!    step of that arithmetic underflows or overflows.
//! 4. **scaled filter**: inputs scaled by powers of two so that the largest
//!    is near 1, with an absolute term in the error bound for what the
//!    scaling flushed towards zero. Tried right after stage 1 when stage 1
//!    declined on range (underflow or overflow: tiny, huge and mixed
//!    magnitudes that are not near-degenerate), else after stage 3.
//! 5. **big-integer exact**: always exact, used only when every other stage
//!    declined. First sparse exact terms: each coordinate difference as at
//!    most two `f64` significands with explicit exponents (or, for incircle
//!    and insphere when that makes fewer terms, the coordinates themselves),
//!    the determinant as exact products of them (at most 48 for orient2d,
//!    orient3d and incircle, 360 for insphere), summed from the largest
//!    down until the rest cannot change the sign. Where they do not fit,
//!    fixed-capacity integers on the stack (no allocation) hold every
//!    coordinate at the finest common binary exponent; their products skip
//!    zero limbs.
//!
//! # Constructed points
//! [`Lpi`] (where a line meets a plane), [`Tpi`] (where three planes meet)
//! and [`Ssi`] (where two lines meet, in the plane) are points kept as the
//! input points that define them, never rounded. Their construction
//! decides exactly that they define one point
//! ([`InputError::NoUniqueIntersection`] otherwise). [`orient3d_implicit`],
//! [`orient2d_implicit`], [`orient2d_projected`], [`cmp_on_axis`],
//! [`less_on_axis`] and [`cmp_along_line`] (and the 2D orders) take them,
//! or explicit points, wherever they take a point ([`AsAnyPoint3`],
//! [`AsAnyPoint2`]), and give the exact answer for the exact point.
//!
//! Relative to an input point `o`, a constructed point's homogeneous
//! coordinates `w (X - o)` and its weight `w` are polynomials in the input
//! coordinates: of degrees 4 and 3 for an `Lpi`, 7 and 6 for a `Tpi`, 3 and
//! 2 for an `Ssi`. Each predicate is the sign of a determinant or a product
//! of those, its degree stated with it (6 for `orient3d` of a triangle and
//! an `Lpi`, 9 with a `Tpi`), times the weights' signs. The same ladder as
//! above: a filter (the points' coordinates in `f64`, each within an
//! a-priori bound `c u M^d`, `M` the largest input difference it is built
//! from and `c` derived per construction, then the predicate with a bound
//! on its error computed from those), run where nothing overflows and
//! underflow is negligible (every `M` in `[2^-R, 2^R]`, `R = 800 / degree`);
//! the filter again on the inputs scaled by a power of two; then the exact
//! stage, every input an integer at its axis's finest bit and the
//! polynomial in stack integers as wide as its degree and the inputs' span
//! need. Nothing allocates; the exact stage's stack is under 16 KiB at
//! ordinary scales and, in release builds, about 256 KiB for a line–plane
//! point whose inputs span the whole `f64` range (320 KiB for four
//! three-plane points that do).
//!
//! # Many cases at once
//! [`orient2d_many`] and [`orient3d_many`] are the way to evaluate many
//! predicates: they answer a slice of cases with the same results as the
//! scalar functions, running the filter over blocks of cases in vector
//! instructions (AVX2 when the CPU has it and `std` is enabled).
//!
//! References: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic
//! and Fast Robust Geometric Predicates", Discrete & Computational Geometry
//! 18 (1997); A. Meyer and S. Pion, "FPG: A code generator for fast and
//! certified geometric predicates", RNC 2008.

mod adaptive;
#[cfg(feature = "alloc")]
pub(crate) mod ball;
mod batch;
pub(crate) mod det;
pub(crate) mod distance;
mod implicit;
mod incircle;
mod insphere;
pub(crate) mod orient2d;
pub(crate) mod orient3d;
pub(crate) mod orient_dir;
mod plane_side;
pub mod robust_compat;
mod sparse;

use crate::error::InputError;
use crate::point::{IntoDVec2, IntoDVec3};
use crate::sign::Sign;
use core::cmp::Ordering;
use glam::{DVec2, DVec3};

pub(crate) use distance::cmp_lengths;

pub use crate::arith::lanes::BLOCK;
pub use batch::{orient2d_many, orient3d_many};
pub use implicit::{
    AnyPoint2, AnyPoint3, AsAnyPoint2, AsAnyPoint3, Axis, Axis2, Lpi, Ssi, Tpi, cmp_along_line,
    cmp_along_line_2d, cmp_on_axis, cmp_on_axis_2d, less_on_axis, orient2d_implicit,
    orient2d_projected, orient3d_implicit, try_cmp_along_line, try_cmp_along_line_2d,
    try_cmp_on_axis, try_cmp_on_axis_2d, try_less_on_axis, try_orient2d_implicit,
    try_orient2d_projected, try_orient3d_implicit,
};
pub use plane_side::{SideRelation, same_side, side_of_plane, try_same_side, try_side_of_plane};

/// Checks that every coordinate of every named point is finite.
#[inline]
pub(crate) fn check_finite2(points: &[(&'static str, DVec2)]) -> Result<(), InputError> {
    for &(argument, p) in points {
        if !p.is_finite() {
            return Err(InputError::NonFinite { argument });
        }
    }
    Ok(())
}

/// Checks that every coordinate of every named point is finite.
#[inline]
pub(crate) fn check_finite3(points: &[(&'static str, DVec3)]) -> Result<(), InputError> {
    for &(argument, p) in points {
        if !p.is_finite() {
            return Err(InputError::NonFinite { argument });
        }
    }
    Ok(())
}

/// Exact orientation of three 2D points: the sign of `(b - a) x (c - a)`.
///
/// `Positive` when `a, b, c` turn counterclockwise, `Negative` when
/// clockwise, `Zero` when they are collinear.
///
/// # Accuracy
/// Exact for every finite input. A NaN or infinite coordinate gives `Zero`
/// (see [`try_orient2d`]).
///
/// ```
/// use exactray::prelude::*;
/// use glam::DVec2;
/// assert_eq!(orient2d(DVec2::ZERO, DVec2::X, DVec2::Y), Sign::Positive);
/// // Points on the line y = x are exactly collinear, whatever their rounding.
/// let s = orient2d(DVec2::new(0.1, 0.1), DVec2::new(0.2, 0.2), DVec2::new(0.3, 0.3));
/// assert_eq!(s, Sign::Zero);
/// ```
#[inline]
pub fn orient2d(a: impl IntoDVec2, b: impl IntoDVec2, c: impl IntoDVec2) -> Sign {
    orient2d::orient2d(a.into_dvec2(), b.into_dvec2(), c.into_dvec2())
}

/// [`orient2d`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming the first such argument.
#[inline]
pub fn try_orient2d(
    a: impl IntoDVec2,
    b: impl IntoDVec2,
    c: impl IntoDVec2,
) -> Result<Sign, InputError> {
    let (a, b, c) = (a.into_dvec2(), b.into_dvec2(), c.into_dvec2());
    check_finite2(&[("a", a), ("b", b), ("c", c)])?;
    Ok(orient2d::orient2d(a, b, c))
}

/// Exact orientation of four 3D points: the sign of `det[b - a, c - a, d - a]`
/// (CGAL's convention; the opposite of Shewchuk's, see the [module docs](self)).
///
/// `Zero` when the four points are coplanar.
///
/// # Accuracy
/// Exact for every finite input. A NaN or infinite coordinate gives `Zero`
/// (see [`try_orient3d`]).
///
/// # Performance
/// A filtered `f64` evaluation answers almost every input; the exact stages
/// run only where its certified bound cannot (the README's figures).
///
/// ```
/// use exactray::prelude::*;
/// use glam::DVec3;
/// // d above the counterclockwise triangle a, b, c (seen from +z): positive.
/// assert_eq!(orient3d(DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z), Sign::Positive);
/// assert_eq!(orient3d(DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::new(0.3, 0.7, 0.0)), Sign::Zero);
/// ```
#[inline(always)]
pub fn orient3d(
    a: impl IntoDVec3,
    b: impl IntoDVec3,
    c: impl IntoDVec3,
    d: impl IntoDVec3,
) -> Sign {
    orient3d::orient3d(
        a.into_dvec3(),
        b.into_dvec3(),
        c.into_dvec3(),
        d.into_dvec3(),
    )
}

/// [`orient3d`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming the first such argument.
#[inline]
pub fn try_orient3d(
    a: impl IntoDVec3,
    b: impl IntoDVec3,
    c: impl IntoDVec3,
    d: impl IntoDVec3,
) -> Result<Sign, InputError> {
    let (a, b, c, d) = (
        a.into_dvec3(),
        b.into_dvec3(),
        c.into_dvec3(),
        d.into_dvec3(),
    );
    check_finite3(&[("a", a), ("b", b), ("c", c), ("d", d)])?;
    Ok(orient3d::orient3d(a, b, c, d))
}

/// Exact in-circle test: `Positive` when `d` lies inside the circle through
/// `a, b, c` given counterclockwise, `Negative` outside, `Zero` on it. The
/// sign flips when `a, b, c` are clockwise; it is `Zero`-free information only
/// when they are not collinear.
///
/// It is the sign of `det[[ax-dx, ay-dy, |a-d|²], [bx-dx, ...], [cx-dx, ...]]`.
///
/// # Accuracy
/// Exact for every finite input; a NaN or infinite coordinate gives `Zero`
/// (see [`try_incircle`]).
///
/// ```
/// use exactray::prelude::*;
/// let (a, b, c) = ([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]);
/// assert_eq!(incircle(a, b, c, [0.0, 0.0]), Sign::Positive);
/// assert_eq!(incircle(a, b, c, [0.0, -1.0]), Sign::Zero);
/// assert_eq!(incircle(a, b, c, [2.0, 0.0]), Sign::Negative);
/// ```
#[inline]
pub fn incircle(
    a: impl IntoDVec2,
    b: impl IntoDVec2,
    c: impl IntoDVec2,
    d: impl IntoDVec2,
) -> Sign {
    incircle::incircle(
        a.into_dvec2(),
        b.into_dvec2(),
        c.into_dvec2(),
        d.into_dvec2(),
    )
}

/// [`incircle`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming the first such argument.
#[inline]
pub fn try_incircle(
    a: impl IntoDVec2,
    b: impl IntoDVec2,
    c: impl IntoDVec2,
    d: impl IntoDVec2,
) -> Result<Sign, InputError> {
    let (a, b, c, d) = (
        a.into_dvec2(),
        b.into_dvec2(),
        c.into_dvec2(),
        d.into_dvec2(),
    );
    check_finite2(&[("a", a), ("b", b), ("c", c), ("d", d)])?;
    Ok(incircle::incircle(a, b, c, d))
}

/// Exact in-sphere test: `Positive` when `e` lies inside the sphere through
/// `a, b, c, d` and `orient3d(a, b, c, d)` is `Positive`; `Negative` outside;
/// `Zero` on the sphere. The sign flips with the orientation of `a, b, c, d`.
///
/// It is the sign of `-det[[a-e, |a-e|²], [b-e, |b-e|²], [c-e, |c-e|²], [d-e, |d-e|²]]`
/// (CGAL `side_of_oriented_sphere`).
///
/// # Accuracy
/// Exact for every finite input; a NaN or infinite coordinate gives `Zero`
/// (see [`try_insphere`]).
///
/// ```
/// use exactray::prelude::*;
/// let (a, b, c, d) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
/// assert_eq!(orient3d(a, b, c, d), Sign::Positive);
/// assert_eq!(insphere(a, b, c, d, [0.25, 0.25, 0.25]), Sign::Positive);
/// assert_eq!(insphere(a, b, c, d, [1.0, 1.0, 1.0]), Sign::Zero);
/// assert_eq!(insphere(a, b, c, d, [2.0, 2.0, 2.0]), Sign::Negative);
/// ```
#[inline]
pub fn insphere(
    a: impl IntoDVec3,
    b: impl IntoDVec3,
    c: impl IntoDVec3,
    d: impl IntoDVec3,
    e: impl IntoDVec3,
) -> Sign {
    insphere::insphere(
        a.into_dvec3(),
        b.into_dvec3(),
        c.into_dvec3(),
        d.into_dvec3(),
        e.into_dvec3(),
    )
}

/// [`insphere`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming the first such argument.
#[inline]
pub fn try_insphere(
    a: impl IntoDVec3,
    b: impl IntoDVec3,
    c: impl IntoDVec3,
    d: impl IntoDVec3,
    e: impl IntoDVec3,
) -> Result<Sign, InputError> {
    let (a, b, c, d, e) = (
        a.into_dvec3(),
        b.into_dvec3(),
        c.into_dvec3(),
        d.into_dvec3(),
        e.into_dvec3(),
    );
    check_finite3(&[("a", a), ("b", b), ("c", c), ("d", d), ("e", e)])?;
    Ok(insphere::insphere(a, b, c, d, e))
}

/// Exact comparison of distances: the ordering of `|p - q|` against
/// `|r - q|`, for every finite input (CGAL's `compare_distance_to_point`).
///
/// `Less` when `p` is strictly closer to `q` than `r` is, `Equal` on an exact
/// tie.
///
/// # Accuracy
/// Exact: squared distances that underflow or overflow in `f64` are
/// compared exactly all the same. A NaN or infinite coordinate gives
/// `Equal` (see [`try_compare_distance`]).
///
/// ```
/// use exactray::predicates::compare_distance;
/// use core::cmp::Ordering;
/// let q = [0.0, 0.0, 0.0];
/// assert_eq!(compare_distance(q, [3.0, 4.0, 0.0], [0.0, 0.0, 5.0]), Ordering::Equal);
/// // One ulp farther: f64 squares would tie, the exact comparison does not.
/// assert_eq!(compare_distance(q, [1.0 + f64::EPSILON, 0.0, 0.0], [0.0, 1.0, 0.0]), Ordering::Greater);
/// ```
#[inline]
pub fn compare_distance(q: impl IntoDVec3, p: impl IntoDVec3, r: impl IntoDVec3) -> Ordering {
    let q = q.into_dvec3();
    cmp_lengths(p.into_dvec3(), q, r.into_dvec3(), q)
        .as_i8()
        .cmp(&0)
}

/// [`compare_distance`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming the first such argument.
#[inline]
pub fn try_compare_distance(
    q: impl IntoDVec3,
    p: impl IntoDVec3,
    r: impl IntoDVec3,
) -> Result<Ordering, InputError> {
    let (q, p, r) = (q.into_dvec3(), p.into_dvec3(), r.into_dvec3());
    check_finite3(&[("q", q), ("p", p), ("r", r)])?;
    Ok(compare_distance(q, p, r))
}
