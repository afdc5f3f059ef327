//! Rays and parameter intervals, validated once at construction so that
//! every query taking them can rely on finite values.

use crate::error::InputError;
use crate::point::IntoDVec3;
use glam::DVec3;

/// The half-line (or line) `origin + t * direction`. The direction need not
/// be unit length: queries report `t` in units of it, and their exactness
/// never depends on normalizing it.
///
/// ```
/// use exactray::ray::Ray;
/// use exactray::InputError;
/// let ray = Ray::new([0.0, 1.0, 0.0], [2.0, 0.0, 0.0]).unwrap();
/// assert_eq!(ray.at(0.5).to_array(), [1.0, 1.0, 0.0]);
/// assert_eq!(Ray::new([0.0; 3], [0.0; 3]).unwrap_err(), InputError::ZeroDirection);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    origin: DVec3,
    direction: DVec3,
}

impl Ray {
    /// A ray from `origin` along `direction` (any [`IntoDVec3`]; `f32`
    /// widens exactly).
    ///
    /// Errors: [`InputError::NonFinite`] naming `"origin"` or `"direction"`
    /// for a NaN or infinite coordinate; [`InputError::ZeroDirection`] for a
    /// zero direction. A direction with a tiny non-zero coordinate (even a
    /// subnormal one) is accepted: every query on it stays defined.
    pub fn new(origin: impl IntoDVec3, direction: impl IntoDVec3) -> Result<Ray, InputError> {
        let (origin, direction) = (origin.into_dvec3(), direction.into_dvec3());
        if !origin.is_finite() {
            return Err(InputError::NonFinite { argument: "origin" });
        }
        if !direction.is_finite() {
            return Err(InputError::NonFinite {
                argument: "direction",
            });
        }
        if direction == DVec3::ZERO {
            return Err(InputError::ZeroDirection);
        }
        Ok(Ray { origin, direction })
    }

    /// The origin.
    #[inline]
    pub fn origin(&self) -> DVec3 {
        self.origin
    }

    /// The direction, as given.
    #[inline]
    pub fn direction(&self) -> DVec3 {
        self.direction
    }

    /// The point at parameter `t`, `origin + t * direction`, rounded
    /// (each coordinate within one rounding of a product and one of a sum).
    #[inline]
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + self.direction * t
    }
}

/// A closed parameter interval `[min, max]`; either bound may be infinite.
///
/// ```
/// use exactray::ray::Interval;
/// use exactray::InputError;
/// let forward = Interval::new(0.0, f64::INFINITY).unwrap();
/// assert!(forward.contains(1e300) && !forward.contains(-1e-300));
/// assert_eq!(Interval::new(2.0, 1.0).unwrap_err(), InputError::ReversedInterval);
/// assert_eq!(Interval::new(f64::NAN, 1.0).unwrap_err(), InputError::NotANumber { argument: "min" });
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    min: f64,
    max: f64,
}

impl Interval {
    /// Every `t >= 0`: the usual range of a ray.
    pub const FORWARD: Interval = Interval {
        min: 0.0,
        max: f64::INFINITY,
    };

    /// `[min, max]`. Errors: [`InputError::NotANumber`] naming `"min"` or
    /// `"max"`; [`InputError::ReversedInterval`] when `min > max`. `min ==
    /// max` is allowed (a single parameter).
    pub fn new(min: f64, max: f64) -> Result<Interval, InputError> {
        if min.is_nan() {
            return Err(InputError::NotANumber { argument: "min" });
        }
        if max.is_nan() {
            return Err(InputError::NotANumber { argument: "max" });
        }
        if min > max {
            return Err(InputError::ReversedInterval);
        }
        Ok(Interval { min, max })
    }

    /// The lower bound.
    #[inline]
    pub fn min(&self) -> f64 {
        self.min
    }

    /// The upper bound.
    #[inline]
    pub fn max(&self) -> f64 {
        self.max
    }

    /// Whether `min <= t <= max` (`false` for NaN).
    #[inline]
    pub fn contains(&self, t: f64) -> bool {
        self.min <= t && t <= self.max
    }

    /// Whether a cast may report a hit at the computed parameter `t`: `t`
    /// is finite and inside the interval. Every cast of the crate reports
    /// only such hits, so a crossing whose parameter lies beyond `f64`'s
    /// range (it rounds to an infinity) is no hit, and the cast looks on to
    /// a later crossing; one within the cast's stated error of `f64::MAX`
    /// may go either way. A NaN `t` is not admitted.
    ///
    /// ```
    /// use exactray::ray::Interval;
    /// assert!(Interval::FORWARD.admits(1e308));
    /// assert!(!Interval::FORWARD.admits(f64::INFINITY));
    /// assert!(Interval::FORWARD.contains(f64::INFINITY));
    /// ```
    #[inline]
    pub fn admits(&self, t: f64) -> bool {
        self.contains(t) && t.is_finite()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation() {
        let nan = f64::NAN;
        assert_eq!(
            Ray::new([nan, 0.0, 0.0], [1.0, 0.0, 0.0]),
            Err(InputError::NonFinite { argument: "origin" })
        );
        assert_eq!(
            Ray::new([0.0; 3], [0.0, f64::INFINITY, 0.0]),
            Err(InputError::NonFinite {
                argument: "direction"
            })
        );
        assert_eq!(
            Ray::new([0.0; 3], [-0.0, 0.0, -0.0]),
            Err(InputError::ZeroDirection)
        );
        let tiny = Ray::new([0.0; 3], [f64::from_bits(1), 0.0, 0.0]).unwrap();
        assert_eq!(tiny.direction().x, f64::from_bits(1));
        assert_eq!(
            Interval::new(0.0, nan),
            Err(InputError::NotANumber { argument: "max" })
        );
        let point = Interval::new(3.0, 3.0).unwrap();
        assert!(point.contains(3.0) && !point.contains(nan));
        assert!(
            Interval::new(f64::NEG_INFINITY, f64::INFINITY)
                .unwrap()
                .contains(-1e308)
        );
    }
}
