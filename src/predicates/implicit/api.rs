//! The public predicates on constructed points, each with its `try_` form.

use super::any::{AsAnyPoint2, AsAnyPoint3, View2, View3};
use super::{order, orient};
use crate::error::InputError;
use crate::point::{IntoDVec2, IntoDVec3};
use crate::sign::Sign;
use core::cmp::Ordering;
use glam::{DVec2, DVec3};

/// An axis of 3D space.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The first coordinate.
    X,
    /// The second coordinate.
    Y,
    /// The third coordinate.
    Z,
}

impl Axis {
    /// The three axes, in order: `Axis::ALL[k]` is coordinate `k`.
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];
}

/// An axis of the plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis2 {
    /// The first coordinate.
    X,
    /// The second coordinate.
    Y,
}

/// Whether every explicit point is finite, for the predicates that read
/// only some of its coordinates (the others take a NaN or an infinity to
/// their filter's value or bound, and so to `Zero`).
fn finite3(p: &[View3<'_>]) -> bool {
    p.iter().all(|x| match x {
        View3::Explicit(v) => v.is_finite(),
        _ => true,
    })
}

fn finite2(p: &[View2<'_>]) -> bool {
    p.iter().all(|x| match x {
        View2::Explicit(v) => v.is_finite(),
        _ => true,
    })
}

fn check3(p: &[View3<'_>], names: &[&'static str]) -> Result<(), InputError> {
    p.iter().zip(names).try_for_each(|(x, name)| x.check(name))
}

fn check2(p: &[View2<'_>], names: &[&'static str]) -> Result<(), InputError> {
    p.iter().zip(names).try_for_each(|(x, name)| x.check(name))
}

/// The ordering a sign of `x - y` means.
fn ordering(s: Sign) -> Ordering {
    s.as_i8().cmp(&0)
}

/// Exact orientation of four points, any of them constructed: the sign of
/// `det[b - a, c - a, d - a]`, as [`orient3d`](crate::predicates::orient3d)
/// (CGAL's convention), for the exact points the arguments define.
///
/// # Accuracy
/// Exact for every finite input (see [constructed points](crate::predicates#constructed-points)). With a
/// point `j` explicit, the sign of a polynomial whose degree is the sum of
/// the other three points' (`Lpi` 4, `Tpi` 7, an explicit point 1): 6 for
/// one `Lpi` beside three explicit points, 9 for one `Tpi` or two `Lpi`s;
/// with none explicit, one less than the sum of all four. The filter's
/// bound on the rounded determinant of the rows `x0, x1, x2` (the points
/// relative to the explicit one) is `6 [E0 R1 R2 + (R0 + E0) E1 R2 + (R0 +
/// E0)(R1 + E1) E2 + gamma(5) R0 R1 R2]`, over their largest components `R`
/// and the bounds `E` on those components' errors: `u |x|` for an explicit
/// point, `130 u M^4` for an `Lpi` and `2960 u M^7` for a `Tpi` (`M` the
/// largest input difference it is built from). A NaN or infinite
/// coordinate of an explicit point gives `Zero` (see
/// [`try_orient3d_implicit`]).
///
/// ```
/// use exactray::predicates::{Lpi, orient3d, orient3d_implicit};
/// use exactray::Sign;
/// // The line through 0 and (1, 3, 7) meets the plane x + y + z = 1 at
/// // (1, 3, 7) / 11, which f64 cannot hold.
/// let x = Lpi::new([0.0; 3], [1.0, 3.0, 7.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
/// // The plane 3x = y through 0, (0, 0, 1) and (1, 3, 0) holds that line.
/// let (a, b, c) = ([0.0; 3], [0.0, 0.0, 1.0], [1.0, 3.0, 0.0]);
/// assert_eq!(orient3d_implicit(a, b, c, &x), Sign::Zero);
/// // Rounding the point first gives another answer.
/// let rounded = [1.0 / 11.0, 3.0 / 11.0, 7.0 / 11.0];
/// assert_eq!(orient3d(a, b, c, rounded), Sign::Negative);
/// ```
#[inline(always)]
pub fn orient3d_implicit(
    a: impl AsAnyPoint3,
    b: impl AsAnyPoint3,
    c: impl AsAnyPoint3,
    d: impl AsAnyPoint3,
) -> Sign {
    let p = [a.view3(), b.view3(), c.view3(), d.view3()];
    orient::orient3d(p)
}

/// [`orient3d_implicit`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate of an
/// explicit point, naming the first such argument.
#[inline]
pub fn try_orient3d_implicit(
    a: impl AsAnyPoint3,
    b: impl AsAnyPoint3,
    c: impl AsAnyPoint3,
    d: impl AsAnyPoint3,
) -> Result<Sign, InputError> {
    let p = [a.view3(), b.view3(), c.view3(), d.view3()];
    check3(&p, &["a", "b", "c", "d"])?;
    Ok(orient::orient3d(p))
}

/// Exact orientation of three points in the plane, any of them an [`Ssi`](super::Ssi):
/// the sign of `(b - a) x (c - a)`, as [`orient2d`](crate::predicates::orient2d),
/// for the exact points.
///
/// # Accuracy
/// Exact for every finite input. With a point explicit, a polynomial of
/// degree the sum of the other two's (`Ssi` 3, explicit 1): 4 for one
/// `Ssi`, 6 for two; 8 for three `Ssi`s. A NaN or infinite coordinate of an
/// explicit point gives `Zero` (see [`try_orient2d_implicit`]).
///
/// ```
/// use exactray::predicates::{Ssi, orient2d_implicit};
/// use exactray::Sign;
/// // Two crossings on the line y = x / 3, neither representable.
/// let x = Ssi::new([0.0, 0.0], [3.0, 1.0], [1.0, 0.0], [1.0, 1.0]).unwrap();
/// let y = Ssi::new([0.0, 0.0], [3.0, 1.0], [2.0, 0.0], [2.0, 1.0]).unwrap();
/// assert_eq!(orient2d_implicit([0.0, 0.0], &x, &y), Sign::Zero);
/// ```
#[inline]
pub fn orient2d_implicit(a: impl AsAnyPoint2, b: impl AsAnyPoint2, c: impl AsAnyPoint2) -> Sign {
    let p = [a.view2(), b.view2(), c.view2()];
    orient::orient2d(p)
}

/// [`orient2d_implicit`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate of an
/// explicit point, naming the first such argument.
#[inline]
pub fn try_orient2d_implicit(
    a: impl AsAnyPoint2,
    b: impl AsAnyPoint2,
    c: impl AsAnyPoint2,
) -> Result<Sign, InputError> {
    let p = [a.view2(), b.view2(), c.view2()];
    check2(&p, &["a", "b", "c"])?;
    Ok(orient::orient2d(p))
}

/// Exact orientation of three 3D points, any of them constructed, projected
/// along `drop` onto the plane of the other two axes taken cyclically (`Z`:
/// `(x, y)`; `X`: `(y, z)`; `Y`: `(z, x)`): component `drop` of `(b - a) x
/// (c - a)`, so that it agrees with [`orient3d_implicit`] seen along that
/// axis. How mesh booleans triangulate a face.
///
/// # Accuracy
/// Exact for every finite input; the degrees are those of
/// [`orient3d_implicit`] with one row fewer (5 for one `Lpi` beside two
/// explicit points, 8 for a `Tpi`). A NaN or infinite coordinate of an
/// explicit point gives `Zero`.
///
/// ```
/// use exactray::predicates::{Axis, Lpi, orient2d_projected};
/// use exactray::Sign;
/// let x = Lpi::new([0.0, 0.0, -1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 0.3], [1.0, 0.0, 0.3], [0.0, 1.0, 0.3]).unwrap();
/// // (0, 0, 0.3) seen from above: on the line x = y.
/// assert_eq!(orient2d_projected([1.0, 1.0, 5.0], [2.0, 2.0, 0.0], &x, Axis::Z), Sign::Zero);
/// ```
#[inline]
pub fn orient2d_projected(
    a: impl AsAnyPoint3,
    b: impl AsAnyPoint3,
    c: impl AsAnyPoint3,
    drop: Axis,
) -> Sign {
    let p = [a.view3(), b.view3(), c.view3()];
    if !finite3(&p) {
        return Sign::Zero;
    }
    orient::orient2d_projected(p, drop as usize)
}

/// [`orient2d_projected`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate of an
/// explicit point, naming the first such argument.
#[inline]
pub fn try_orient2d_projected(
    a: impl AsAnyPoint3,
    b: impl AsAnyPoint3,
    c: impl AsAnyPoint3,
    drop: Axis,
) -> Result<Sign, InputError> {
    let p = [a.view3(), b.view3(), c.view3()];
    check3(&p, &["a", "b", "c"])?;
    Ok(orient::orient2d_projected(p, drop as usize))
}

/// Exact comparison of two points' coordinates along an axis, either point
/// constructed: the ordering of `x[axis]` against `y[axis]`. Sorts the
/// crossings along an edge.
///
/// # Accuracy
/// Exact for every finite input: the sign of `l_x w_y - l_y w_x` (degree
/// 7 for two `Lpi`s, 13 for two `Tpi`s, 4 for an `Lpi` and an explicit
/// point). The filter's bound on the rounded value is
/// `|l~_x| E_wy + (|w~_y| + E_wy) E_lx + |l~_y| E_wx + (|w~_x| + E_wx) E_ly +
/// gamma(2) (|l~_x w~_y| + |l~_y w~_x|)`, each `E` bounding a rounded
/// value's error (as for [`orient3d_implicit`]). A NaN or infinite
/// coordinate of an explicit point gives `Equal`.
///
/// ```
/// use exactray::predicates::{Axis, Lpi, cmp_on_axis};
/// use core::cmp::Ordering;
/// // Where the segment from (0,0,0) to (3,3,3) crosses x = 1 and y = 1.
/// let seg = ([0.0; 3], [3.0; 3]);
/// let at_x = Lpi::new(seg.0, seg.1, [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [1.0, 0.0, 1.0]).unwrap();
/// let at_y = Lpi::new(seg.0, seg.1, [0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 1.0]).unwrap();
/// assert_eq!(cmp_on_axis(&at_x, &at_y, Axis::Z), Ordering::Equal);
/// assert_eq!(cmp_on_axis(&at_x, [0.0, 0.0, 1.5], Axis::Z), Ordering::Less);
/// ```
#[inline]
pub fn cmp_on_axis(x: impl AsAnyPoint3, y: impl AsAnyPoint3, axis: Axis) -> Ordering {
    let p = [x.view3(), y.view3()];
    if !finite3(&p) {
        return Ordering::Equal;
    }
    ordering(order::on_axis(p, axis as usize))
}

/// [`cmp_on_axis`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate of an
/// explicit point, naming the first such argument.
#[inline]
pub fn try_cmp_on_axis(
    x: impl AsAnyPoint3,
    y: impl AsAnyPoint3,
    axis: Axis,
) -> Result<Ordering, InputError> {
    let p = [x.view3(), y.view3()];
    check3(&p, &["x", "y"])?;
    Ok(ordering(order::on_axis(p, axis as usize)))
}

/// Whether `x[axis] < y[axis]` exactly: [`cmp_on_axis`] is `Less`.
/// `false` for a NaN or infinite coordinate of an explicit point.
///
/// ```
/// use exactray::predicates::{Axis, Lpi, less_on_axis};
/// let x = Lpi::new([0.0; 3], [3.0; 3], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [1.0, 0.0, 1.0]).unwrap();
/// // x is (1, 1, 1).
/// assert!(less_on_axis(&x, [1.0, 2.0, 0.0], Axis::Y));
/// assert!(!less_on_axis(&x, [1.0, 2.0, 0.0], Axis::X));
/// ```
#[inline]
pub fn less_on_axis(x: impl AsAnyPoint3, y: impl AsAnyPoint3, axis: Axis) -> bool {
    cmp_on_axis(x, y, axis) == Ordering::Less
}

/// [`less_on_axis`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate of an
/// explicit point, naming the first such argument.
#[inline]
pub fn try_less_on_axis(
    x: impl AsAnyPoint3,
    y: impl AsAnyPoint3,
    axis: Axis,
) -> Result<bool, InputError> {
    Ok(try_cmp_on_axis(x, y, axis)? == Ordering::Less)
}

/// Exact order of two points, either constructed, along the line from `p`
/// to `q`: the ordering of `(x - p) . (q - p)` against `(y - p) . (q -
/// p)`, the points' orthogonal projections onto the line; for points on
/// the line, their order along it. `Less` when `x` comes first.
///
/// # Accuracy
/// Exact for every finite input: the sign of a polynomial one degree above
/// [`cmp_on_axis`]'s (8 for two `Lpi`s). `Equal` when `p == q` and for a
/// NaN or infinite coordinate of an explicit point (see
/// [`try_cmp_along_line`]).
///
/// ```
/// use exactray::predicates::{Lpi, cmp_along_line};
/// use core::cmp::Ordering;
/// let (p, q) = ([0.0; 3], [1.0, 2.0, 3.0]);
/// // Where the line meets the planes z = 1 and z = 1 + 2^-52.
/// let plane = |z: f64| [[0.0, 0.0, z], [1.0, 0.0, z], [0.0, 1.0, z]];
/// let [r, s, t] = plane(1.0);
/// let a = Lpi::new(p, q, r, s, t).unwrap();
/// let [r, s, t] = plane(1.0 + f64::EPSILON);
/// let b = Lpi::new(p, q, r, s, t).unwrap();
/// assert_eq!(cmp_along_line(p, q, &a, &b), Ordering::Less);
/// assert_eq!(cmp_along_line(q, p, &a, &b), Ordering::Greater);
/// ```
#[inline]
pub fn cmp_along_line(
    p: impl IntoDVec3,
    q: impl IntoDVec3,
    x: impl AsAnyPoint3,
    y: impl AsAnyPoint3,
) -> Ordering {
    let pts = along3(p.into_dvec3(), q.into_dvec3(), &x, &y);
    ordering(-order::along_line(pts))
}

fn along3<'a>(
    p: DVec3,
    q: DVec3,
    x: &'a impl AsAnyPoint3,
    y: &'a impl AsAnyPoint3,
) -> [View3<'a>; 4] {
    [View3::Explicit(p), View3::Explicit(q), x.view3(), y.view3()]
}

/// [`cmp_along_line`], checked: the same answer for finite input and `p !=
/// q`.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate of an
/// explicit point, naming the first such argument;
/// [`InputError::ZeroDirection`] when `p == q`.
#[inline]
pub fn try_cmp_along_line(
    p: impl IntoDVec3,
    q: impl IntoDVec3,
    x: impl AsAnyPoint3,
    y: impl AsAnyPoint3,
) -> Result<Ordering, InputError> {
    let (p, q) = (p.into_dvec3(), q.into_dvec3());
    let pts = along3(p, q, &x, &y);
    check3(&pts, &["p", "q", "x", "y"])?;
    if p == q {
        return Err(InputError::ZeroDirection);
    }
    Ok(ordering(-order::along_line(pts)))
}

/// Exact comparison of two points' coordinates along an axis of the plane,
/// either an [`Ssi`](super::Ssi): [`cmp_on_axis`] in 2D (degree 5 for two
/// `Ssi`s, 3 for one beside an explicit point). A NaN or infinite
/// coordinate of an explicit point gives `Equal`.
///
/// ```
/// use exactray::predicates::{Axis2, Ssi, cmp_on_axis_2d};
/// use core::cmp::Ordering;
/// let x = Ssi::new([0.0, 0.0], [3.0, 1.0], [1.0, 0.0], [1.0, 1.0]).unwrap(); // (1, 1/3)
/// assert_eq!(cmp_on_axis_2d(&x, [0.0, 1.0 / 3.0], Axis2::Y), Ordering::Greater);
/// ```
#[inline]
pub fn cmp_on_axis_2d(x: impl AsAnyPoint2, y: impl AsAnyPoint2, axis: Axis2) -> Ordering {
    let p = [x.view2(), y.view2()];
    if !finite2(&p) {
        return Ordering::Equal;
    }
    ordering(order::on_axis(p, axis as usize))
}

/// [`cmp_on_axis_2d`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate of an
/// explicit point, naming the first such argument.
#[inline]
pub fn try_cmp_on_axis_2d(
    x: impl AsAnyPoint2,
    y: impl AsAnyPoint2,
    axis: Axis2,
) -> Result<Ordering, InputError> {
    let p = [x.view2(), y.view2()];
    check2(&p, &["x", "y"])?;
    Ok(ordering(order::on_axis(p, axis as usize)))
}

/// Exact order of two points of the plane, either an [`Ssi`](super::Ssi),
/// along the line from `p` to `q`: [`cmp_along_line`] in 2D (degree 6 for
/// two `Ssi`s). Sorts the crossings along a segment. `Equal` when `p == q`
/// and for a NaN or infinite coordinate of an explicit point.
///
/// ```
/// use exactray::predicates::{Ssi, cmp_along_line_2d};
/// use core::cmp::Ordering;
/// let (p, q) = ([0.0, 0.0], [3.0, 1.0]);
/// let a = Ssi::new(p, q, [1.0, 0.0], [1.0, 1.0]).unwrap();
/// let b = Ssi::new(p, q, [2.0, 0.0], [2.0, 1.0]).unwrap();
/// assert_eq!(cmp_along_line_2d(p, q, &a, &b), Ordering::Less);
/// ```
#[inline]
pub fn cmp_along_line_2d(
    p: impl IntoDVec2,
    q: impl IntoDVec2,
    x: impl AsAnyPoint2,
    y: impl AsAnyPoint2,
) -> Ordering {
    let pts = along2(p.into_dvec2(), q.into_dvec2(), &x, &y);
    ordering(-order::along_line(pts))
}

fn along2<'a>(
    p: DVec2,
    q: DVec2,
    x: &'a impl AsAnyPoint2,
    y: &'a impl AsAnyPoint2,
) -> [View2<'a>; 4] {
    [View2::Explicit(p), View2::Explicit(q), x.view2(), y.view2()]
}

/// [`cmp_along_line_2d`], checked: the same answer for finite input and
/// `p != q`.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate of an
/// explicit point, naming the first such argument;
/// [`InputError::ZeroDirection`] when `p == q`.
#[inline]
pub fn try_cmp_along_line_2d(
    p: impl IntoDVec2,
    q: impl IntoDVec2,
    x: impl AsAnyPoint2,
    y: impl AsAnyPoint2,
) -> Result<Ordering, InputError> {
    let (p, q) = (p.into_dvec2(), q.into_dvec2());
    let pts = along2(p, q, &x, &y);
    check2(&pts, &["p", "q", "x", "y"])?;
    if p == q {
        return Err(InputError::ZeroDirection);
    }
    Ok(ordering(-order::along_line(pts)))
}
