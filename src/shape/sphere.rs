use super::{finite, radius};
use crate::error::InputError;
use crate::point::IntoDVec3;
use glam::DVec3;

/// The sphere `|x - center| = radius`.
///
/// ```
/// use exactray::shape::Sphere;
/// use exactray::InputError;
/// let s = Sphere::new([0.0, 0.0, 0.0], 1.0).unwrap();
/// assert_eq!(s.radius(), 1.0);
/// assert_eq!(Sphere::new([0.0; 3], -1.0).unwrap_err(), InputError::InvalidRadius { argument: "radius" });
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    pub(crate) center: DVec3,
    pub(crate) radius: f64,
}

impl Sphere {
    /// A sphere.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] (`"center"`, or
    /// `"radius"` when infinite), [`InputError::InvalidRadius`] for a
    /// negative or NaN radius. Radius zero is a point, which only tangent
    /// rays (those through it) meet.
    pub fn new(center: impl IntoDVec3, radius_: f64) -> Result<Sphere, InputError> {
        Ok(Sphere {
            center: finite("center", center)?,
            radius: radius("radius", radius_)?,
        })
    }

    /// The centre.
    #[inline]
    pub fn center(&self) -> DVec3 {
        self.center
    }

    /// The radius.
    #[inline]
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

serde_by_constructor!(
    Sphere as "Sphere" { center: DVec3, radius: f64 },
    parts: |s| (s.center, s.radius),
    build: |d| Sphere::new(d.center, d.radius),
);
