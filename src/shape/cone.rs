use super::{finite, nonzero, radius};
use crate::error::InputError;
use crate::point::IntoDVec3;
use glam::DVec3;

/// A circular cone with its apex at `apex`, opening along `axis`, of
/// radius `radius` at `apex + axis` (so the half-angle is
/// `atan(radius / |axis|)`): the points `x` with
/// `|w x axis|^2 |axis|^2 = radius^2 (w . axis)^2` and `w . axis >= 0`,
/// `w = x - apex` (one nappe). [`Cone::new`] caps it at `apex + axis` with
/// the base disk; [`Cone::infinite`] leaves the nappe unbounded.
///
/// ```
/// use exactray::shape::Cone;
/// use exactray::query::ray::RayCast;
/// use exactray::interval::Interval;
/// use exactray::query::ray::Ray;
/// let cone = Cone::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0).unwrap();
/// let ray = Ray::new([-2.0, 0.0, 0.5], [1.0, 0.0, 0.0]).unwrap();
/// assert_eq!(cone.cast(&ray, Interval::FORWARD).unwrap().t, 1.5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone {
    pub(crate) apex: DVec3,
    pub(crate) axis: DVec3,
    pub(crate) radius: f64,
    pub(crate) capped: bool,
}

impl Cone {
    /// The capped cone (lateral surface and base disk). Errors:
    /// [`InputError::NonFinite`] (`"apex"`, `"axis"`, `"radius"`),
    /// [`InputError::Degenerate`] for a zero axis or a zero radius (a
    /// half-angle of zero), [`InputError::InvalidRadius`] for a negative or
    /// NaN radius.
    pub fn new(
        apex: impl IntoDVec3,
        axis: impl IntoDVec3,
        radius_: f64,
    ) -> Result<Cone, InputError> {
        let apex = finite("apex", apex)?;
        let axis = nonzero("axis", axis)?;
        let radius = radius("radius", radius_)?;
        if radius == 0.0 {
            return Err(InputError::Degenerate { argument: "radius" });
        }
        Ok(Cone {
            apex,
            axis,
            radius,
            capped: true,
        })
    }

    /// The unbounded nappe with the same apex, axis and angle; errors as
    /// for [`Cone::new`].
    pub fn infinite(
        apex: impl IntoDVec3,
        axis: impl IntoDVec3,
        radius_: f64,
    ) -> Result<Cone, InputError> {
        Ok(Cone {
            capped: false,
            ..Cone::new(apex, axis, radius_)?
        })
    }

    /// Whether the cone is capped at `apex + axis`.
    #[inline]
    pub fn is_capped(&self) -> bool {
        self.capped
    }
}

serde_by_constructor!(
    Cone as "Cone" { apex: DVec3, axis: DVec3, radius: f64, capped: bool },
    parts: |c| (c.apex, c.axis, c.radius, c.capped),
    build: |d| if d.capped {
        Cone::new(d.apex, d.axis, d.radius)
    } else {
        Cone::infinite(d.apex, d.axis, d.radius)
    },
);
