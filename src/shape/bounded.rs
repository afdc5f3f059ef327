//! Boxes around shapes: [`Aabb`] and the [`Bounded`] trait, what a
//! hierarchy over shapes is built from.
//!
//! A shape's box is computed in `f64` and rounded outward: every bound
//! that comes out of an inexact operation is moved one step away from the
//! shape (`next_down` for a lower bound, `next_up` for an upper one), so
//! the box holds every point of the exact shape. Why one step is enough: a
//! sum or difference rounded to nearest is within half an ulp of its exact
//! value, and the neighbouring double is a whole ulp away (at a power of
//! two, the ulp below is half the ulp above, and the exact value below it
//! is within a quarter of the upper ulp: still inside). An overflow gives
//! an infinite bound, which holds everything.

use crate::error::InputError;
use crate::point::IntoDVec3;
use glam::DVec3;

/// An axis-aligned box `[min, max]` in each coordinate; the bounds may be
/// infinite.
///
/// ```
/// use exactray::shape::Aabb;
/// let b = Aabb::new([0.0, 0.0, 0.0], [1.0, 2.0, 3.0]).unwrap();
/// assert!(b.contains([1.0, 2.0, 3.0]) && !b.contains([1.5, 0.0, 0.0]));
/// let u = b.union(&Aabb::new([-1.0, 0.0, 0.0], [0.0, 0.0, 0.0]).unwrap());
/// assert_eq!(u.min().to_array(), [-1.0, 0.0, 0.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    min: DVec3,
    max: DVec3,
}

impl Aabb {
    /// The box `[min, max]`.
    ///
    /// # Errors
    /// A NaN coordinate is [`InputError::NotANumber`]; `min > max` on some
    /// axis is [`InputError::ReversedInterval`]. Infinite bounds are
    /// allowed.
    pub fn new(min: impl IntoDVec3, max: impl IntoDVec3) -> Result<Aabb, InputError> {
        let (min, max) = (min.into_dvec3(), max.into_dvec3());
        if min.is_nan() {
            return Err(InputError::NotANumber { argument: "min" });
        }
        if max.is_nan() {
            return Err(InputError::NotANumber { argument: "max" });
        }
        if min.cmpgt(max).any() {
            return Err(InputError::ReversedInterval);
        }
        Ok(Aabb { min, max })
    }

    /// The box of finite points, with no rounding: `None` for an empty
    /// slice or a NaN coordinate.
    ///
    /// ```
    /// use exactray::shape::Aabb;
    /// let b = Aabb::of_points(&[[1.0, 5.0, 0.0], [-2.0, 0.5, 4.0]]).unwrap();
    /// assert_eq!((b.min().to_array(), b.max().to_array()), ([-2.0, 0.5, 0.0], [1.0, 5.0, 4.0]));
    /// assert!(Aabb::of_points::<[f64; 3]>(&[]).is_none());
    /// ```
    pub fn of_points<P: IntoDVec3>(points: &[P]) -> Option<Aabb> {
        let (first, rest) = points.split_first()?;
        let p = first.into_dvec3();
        let (min, max) = rest.iter().fold((p, p), |(lo, hi), q| {
            let q = q.into_dvec3();
            (lo.min(q), hi.max(q))
        });
        Aabb::new(min, max).ok()
    }

    /// The lower corner.
    #[inline]
    pub fn min(&self) -> DVec3 {
        self.min
    }

    /// The upper corner.
    #[inline]
    pub fn max(&self) -> DVec3 {
        self.max
    }

    /// The smallest box holding both.
    #[inline]
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Whether the closed box holds `p` (exact comparisons; `false` for a
    /// NaN coordinate).
    #[inline]
    pub fn contains(&self, p: impl IntoDVec3) -> bool {
        let p = p.into_dvec3();
        self.min.cmple(p).all() && p.cmple(self.max).all()
    }

    /// `center +- extent` rounded outward, for an exact `center` and
    /// `extent >= 0`.
    pub(crate) fn around(center: DVec3, extent: DVec3) -> Aabb {
        Aabb {
            min: down(center - extent),
            max: up(center + extent),
        }
    }

    /// `(a + b) +- extent` rounded outward: the sum's own rounding first
    /// (its exact value lies between the neighbours of the rounded sum),
    /// then the extent's.
    pub(crate) fn around_sum(a: DVec3, b: DVec3, extent: DVec3) -> Aabb {
        let sum = a + b;
        Aabb {
            min: down(down(sum) - extent),
            max: up(up(sum) + extent),
        }
    }
}

/// Each coordinate one step towards `-inf` (a lower bound of the exact
/// value that rounded to it).
fn down(v: DVec3) -> DVec3 {
    DVec3::new(v.x.next_down(), v.y.next_down(), v.z.next_down())
}

/// Each coordinate one step towards `+inf`.
fn up(v: DVec3) -> DVec3 {
    DVec3::new(v.x.next_up(), v.y.next_up(), v.z.next_up())
}

/// A shape that may be enclosed in a box.
pub trait Bounded {
    /// A box holding every point of the exact shape (rounded outward), or
    /// `None` for a shape that no box holds: a plane, an infinite cylinder
    /// or cone, a general quadric.
    fn aabb(&self) -> Option<Aabb>;
}

serde_by_constructor!(
    Aabb as "Aabb" { min: DVec3, max: DVec3 },
    parts: |b| (b.min, b.max),
    build: |d| Aabb::new(d.min, d.max),
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outward_rounding_holds_the_exact_extent() {
        // 0.1 + 0.2 rounds up to 0.30000000000000004 and 1 - 2^-60 rounds
        // to 1: the bounds step past both.
        let b = Aabb::around(DVec3::splat(0.1), DVec3::splat(0.2));
        assert!(b.max().x > 0.30000000000000004 && b.min().x < -0.1);
        let b = Aabb::around(DVec3::ONE, DVec3::splat(2f64.powi(-60)));
        assert!(b.min().x < 1.0 && b.max().x > 1.0);
        let huge = Aabb::around(DVec3::splat(f64::MAX), DVec3::splat(f64::MAX));
        assert_eq!(huge.max().x, f64::INFINITY);
        // 1e16 + 1 rounds to 1e16; minus 1e16 (the extent) the exact 1
        // must stay inside, though the rounded sum gives 0.
        let b = Aabb::around_sum(DVec3::splat(1e16), DVec3::ONE, DVec3::splat(1e16));
        assert!(b.min().x <= 1.0 && b.max().x >= 2e16 + 1.0);
    }

    #[test]
    fn bad_boxes_are_typed_errors() {
        assert_eq!(
            Aabb::new([0.0, f64::NAN, 0.0], [1.0; 3]),
            Err(InputError::NotANumber { argument: "min" })
        );
        assert_eq!(
            Aabb::new([0.0; 3], [1.0, -1.0, 1.0]),
            Err(InputError::ReversedInterval)
        );
        assert!(Aabb::new([f64::NEG_INFINITY; 3], [f64::INFINITY; 3]).is_ok());
        assert!(Aabb::of_points(&[[0.0, f64::NAN, 0.0]]).is_none());
    }
}
