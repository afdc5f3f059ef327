use super::{finite, nonzero, radius};
use crate::arith::exponent::unit_pow2;
use crate::error::InputError;
use crate::point::IntoDVec3;
use glam::DVec3;

/// The plane through `point` with normal `normal` (any non-zero length):
/// `(x - point) . normal = 0`. Hits report the normal as given, normalized.
/// The normal is kept multiplied by the power of two that brings its
/// largest coordinate near 1 (exactly the same direction), so that a
/// cast's dot products neither overflow nor underflow however long it was
/// given.
///
/// ```
/// use exactray::shape::Plane;
/// use exactray::query::ray::RayCast;
/// use exactray::interval::Interval;
/// use exactray::query::ray::Ray;
/// let floor = Plane::new([0.0, 0.0, 0.0], [0.0, 0.0, 2.0]).unwrap();
/// let ray = Ray::new([1.0, 1.0, 4.0], [0.0, 0.0, -2.0]).unwrap();
/// assert_eq!(floor.cast(&ray, Interval::FORWARD).unwrap().t, 2.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    pub(crate) point: DVec3,
    pub(crate) normal: DVec3,
}

impl Plane {
    /// A plane.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] (`"point"`, `"normal"`),
    /// [`InputError::Degenerate`] for a zero normal.
    pub fn new(point: impl IntoDVec3, normal: impl IntoDVec3) -> Result<Plane, InputError> {
        let normal = nonzero("normal", normal)?;
        Ok(Plane {
            point: finite("point", point)?,
            normal: normal * unit_pow2(normal.abs().max_element()),
        })
    }
}

/// The disk of radius `radius` around `center` in the plane with normal
/// `normal`: a cylinder's cap, or an area light.
///
/// ```
/// use exactray::shape::Disk;
/// use exactray::query::ray::RayCast;
/// use exactray::interval::Interval;
/// use exactray::query::ray::Ray;
/// let disk = Disk::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0).unwrap();
/// let down = |x: f64| Ray::new([x, 0.0, 1.0], [0.0, 0.0, -1.0]).unwrap();
/// assert!(disk.hits(&down(0.5), Interval::FORWARD));
/// assert!(!disk.hits(&down(1.5), Interval::FORWARD));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disk {
    pub(crate) plane: Plane,
    pub(crate) radius: f64,
}

impl Disk {
    /// A disk.
    ///
    /// # Errors
    /// as for [`Plane::new`] (`"center"` for the first
    /// argument), and [`InputError::InvalidRadius`] for a negative or NaN
    /// radius.
    pub fn new(
        center: impl IntoDVec3,
        normal: impl IntoDVec3,
        radius_: f64,
    ) -> Result<Disk, InputError> {
        let center = finite("center", center)?;
        Ok(Disk {
            plane: Plane::new(center, normal)?,
            radius: radius("radius", radius_)?,
        })
    }
}

serde_by_constructor!(
    Plane as "Plane" { point: DVec3, normal: DVec3 },
    parts: |p| (p.point, p.normal),
    build: |d| Plane::new(d.point, d.normal),
);

serde_by_constructor!(
    Disk as "Disk" { center: DVec3, normal: DVec3, radius: f64 },
    parts: |k| (k.plane.point, k.plane.normal, k.radius),
    build: |d| Disk::new(d.center, d.normal, d.radius),
);
