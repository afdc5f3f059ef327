//! A triangle in space, given by its three vertices.

use crate::arith::exponent::unit_pow2;
use crate::error::InputError;
use crate::point::IntoDVec3;
use crate::predicates::{check_finite3, orient2d};
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// The triangle `v0, v1, v2`, with finite coordinates. Its front side is
/// the one its counterclockwise order faces: the side
/// `(v1 - v0) x (v2 - v0)` points to.
///
/// A degenerate triangle (collinear or coincident vertices) is a valid
/// value: every ray cast of every variant misses it (see
/// [`Triangle::is_degenerate`]).
///
/// ```
/// use exactray::shape::Triangle;
/// use exactray::InputError;
/// let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
/// assert_eq!(tri.normal().to_array(), [0.0, 0.0, 1.0]);
/// let bad = Triangle::new([0.0; 3], [f64::NAN, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// assert_eq!(bad.unwrap_err(), InputError::NonFinite { argument: "v1" });
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    pub(crate) v: [DVec3; 3],
    /// [`Triangle::is_degenerate`], decided once at construction so that
    /// every cast can miss a degenerate triangle for the price of a branch.
    pub(crate) degenerate: bool,
}

impl Triangle {
    /// The triangle `v0, v1, v2` (any [`IntoDVec3`]; `f32` widens exactly).
    ///
    ///
    ///
    /// # Errors
    /// [`InputError::NonFinite`] naming `"v0"`, `"v1"` or `"v2"`
    /// for a NaN or infinite coordinate.
    pub fn new(
        v0: impl IntoDVec3,
        v1: impl IntoDVec3,
        v2: impl IntoDVec3,
    ) -> Result<Triangle, InputError> {
        let v = [v0.into_dvec3(), v1.into_dvec3(), v2.into_dvec3()];
        check_finite3(&[("v0", v[0]), ("v1", v[1]), ("v2", v[2])])?;
        Ok(Triangle {
            v,
            degenerate: collinear(&v),
        })
    }

    /// The vertices `[v0, v1, v2]`.
    #[inline]
    pub fn vertices(&self) -> [DVec3; 3] {
        self.v
    }

    /// Whether the vertices are exactly collinear (or coincide): then
    /// `(v1 - v0) x (v2 - v0)` is exactly zero, which is the case exactly
    /// when its three projections on the coordinate planes are.
    ///
    /// ```
    /// use exactray::shape::Triangle;
    /// // 0.1, 0.2 and 0.3 are rounded, but the points lie exactly on x = y = z.
    /// let line = Triangle::new([0.1; 3], [0.2; 3], [0.3; 3]).unwrap();
    /// assert!(line.is_degenerate());
    /// ```
    #[inline]
    pub fn is_degenerate(&self) -> bool {
        self.degenerate
    }

    /// The unit normal `(v1 - v0) x (v2 - v0) / |...|`, or zero when the
    /// cross product computes as zero (a degenerate triangle, or one so
    /// thin that the cross product of its rounded edges cancels). No
    /// overflow for any finite vertices: the edges, and their cross
    /// product, are scaled by powers of two before it is normalized.
    pub fn normal(&self) -> DVec3 {
        let [v0, v1, v2] = self.v;
        // Halved first, so that the differences cannot overflow.
        let (e1, e2) = (v1 * 0.5 - v0 * 0.5, v2 * 0.5 - v0 * 0.5);
        // Each edge scaled to a largest coordinate near 1, then the cross
        // product: scaling by positive numbers keeps its direction, and
        // its products stay in range unless the edges are disparate or
        // nearly parallel, where the second scaling keeps the length normal.
        let unit = |v: DVec3| v * unit_pow2(v.abs().max_element());
        unit(unit(e1).cross(unit(e2))).normalize_or_zero()
    }
}

/// Whether the points are exactly collinear: the cross product of their
/// differences is zero exactly when its three projections on the
/// coordinate planes are.
fn collinear(v: &[DVec3; 3]) -> bool {
    let plane = |i: usize, j: usize| {
        let p = v.map(|v| DVec2::new(v[i], v[j]));
        orient2d(p[0], p[1], p[2])
    };
    plane(0, 1) == Sign::Zero && plane(1, 2) == Sign::Zero && plane(2, 0) == Sign::Zero
}

serde_by_constructor!(
    Triangle as "Triangle" { vertices: [DVec3; 3] },
    parts: |t| t.v,
    build: |d| Triangle::new(d.vertices[0], d.vertices[1], d.vertices[2]),
);
