//! Which side of a triangle's plane a point lies on, and whether two points
//! lie on the same side (question Q7 of `docs/pictures.md`), decided exactly with
//! [`orient3d`](super::orient3d).

use super::{check_finite3, orient3d::orient3d};
use crate::error::InputError;
use crate::point::IntoDVec3;
use crate::sign::Sign;

/// How two points lie with respect to a plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum SideRelation {
    /// Both strictly on the same side.
    Same,
    /// Strictly on opposite sides: the segment between them crosses the plane
    /// at an interior point of the segment.
    Opposite,
    /// At least one of them lies on the plane, or the triangle is degenerate
    /// (its three vertices are collinear, so it spans no plane).
    OnPlane,
}

impl SideRelation {
    /// The relation as the fixture format writes it: `1` same, `-1` opposite,
    /// `0` on the plane.
    #[inline]
    pub const fn as_i8(self) -> i8 {
        match self {
            SideRelation::Same => 1,
            SideRelation::Opposite => -1,
            SideRelation::OnPlane => 0,
        }
    }
}

/// The side of the plane through triangle `x0, x1, x2` that `p` lies on:
/// `orient3d(x0, x1, x2, p)`. `Positive` on the side from which `x0, x1, x2`
/// appear counterclockwise; `Zero` on the plane or for a degenerate triangle.
///
/// # Accuracy
/// Exact for every finite input; a NaN or infinite coordinate gives `Zero`.
///
/// ```
/// use exactray::prelude::*;
/// let tri = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// assert_eq!(side_of_plane(tri.0, tri.1, tri.2, [5.0, 5.0, 1e-300]), Sign::Positive);
/// ```
#[inline]
pub fn side_of_plane(
    x0: impl IntoDVec3,
    x1: impl IntoDVec3,
    x2: impl IntoDVec3,
    p: impl IntoDVec3,
) -> Sign {
    orient3d(
        x0.into_dvec3(),
        x1.into_dvec3(),
        x2.into_dvec3(),
        p.into_dvec3(),
    )
}

/// [`side_of_plane`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming the first such argument.
#[inline]
pub fn try_side_of_plane(
    x0: impl IntoDVec3,
    x1: impl IntoDVec3,
    x2: impl IntoDVec3,
    p: impl IntoDVec3,
) -> Result<Sign, InputError> {
    let (x0, x1, x2, p) = (
        x0.into_dvec3(),
        x1.into_dvec3(),
        x2.into_dvec3(),
        p.into_dvec3(),
    );
    check_finite3(&[("x0", x0), ("x1", x1), ("x2", x2), ("p", p)])?;
    Ok(orient3d(x0, x1, x2, p))
}

/// Whether `p` and `q` lie on the same side of the plane through triangle
/// `x0, x1, x2`, on strictly opposite sides, or (at least one) on it. Exact.
/// A NaN or infinite coordinate gives `OnPlane` (see [`try_same_side`]).
///
/// ```
/// use exactray::prelude::*;
/// let (x0, x1, x2) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// assert_eq!(same_side(x0, x1, x2, [0.2, 0.2, 1.0], [9.0, -3.0, 2.0]), SideRelation::Same);
/// assert_eq!(same_side(x0, x1, x2, [0.2, 0.2, 1.0], [0.0, 0.0, -1e-320]), SideRelation::Opposite);
/// assert_eq!(same_side(x0, x1, x2, [0.2, 0.2, 0.0], [0.0, 0.0, 1.0]), SideRelation::OnPlane);
/// ```
#[inline]
pub fn same_side(
    x0: impl IntoDVec3,
    x1: impl IntoDVec3,
    x2: impl IntoDVec3,
    p: impl IntoDVec3,
    q: impl IntoDVec3,
) -> SideRelation {
    let (x0, x1, x2) = (x0.into_dvec3(), x1.into_dvec3(), x2.into_dvec3());
    let sp = orient3d(x0, x1, x2, p.into_dvec3());
    if sp == Sign::Zero {
        return SideRelation::OnPlane;
    }
    match sp.product(orient3d(x0, x1, x2, q.into_dvec3())) {
        Sign::Positive => SideRelation::Same,
        Sign::Negative => SideRelation::Opposite,
        Sign::Zero => SideRelation::OnPlane,
    }
}

/// [`same_side`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming the first such argument.
#[inline]
pub fn try_same_side(
    x0: impl IntoDVec3,
    x1: impl IntoDVec3,
    x2: impl IntoDVec3,
    p: impl IntoDVec3,
    q: impl IntoDVec3,
) -> Result<SideRelation, InputError> {
    let (x0, x1, x2, p, q) = (
        x0.into_dvec3(),
        x1.into_dvec3(),
        x2.into_dvec3(),
        p.into_dvec3(),
        q.into_dvec3(),
    );
    check_finite3(&[("x0", x0), ("x1", x1), ("x2", x2), ("p", p), ("q", q)])?;
    Ok(same_side(x0, x1, x2, p, q))
}
