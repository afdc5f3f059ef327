use super::{finite, nonzero, radius};
use crate::error::InputError;
use crate::point::IntoDVec3;
use glam::DVec3;

/// The infinite cylinder of points at distance `radius` from the line
/// through `point` along `axis` (any non-zero length):
/// `|(x - point) x axis|^2 = radius^2 |axis|^2`.
///
/// The cylinder `x^2 + z^2 = 1` of question Q1 (`docs/pictures.md`):
/// ```
/// use exactray::shape::Cylinder;
/// use exactray::query::ray::RayCast;
/// use exactray::interval::Interval;
/// use exactray::query::ray::Ray;
/// let cyl = Cylinder::new([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1.0).unwrap();
/// let ray = Ray::new([-3.0, 5.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
/// let hit = cyl.cast(&ray, Interval::FORWARD).unwrap();
/// assert_eq!((hit.t, hit.normal.to_array()), (2.0, [-1.0, 0.0, 0.0]));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Cylinder {
    pub(crate) point: DVec3,
    pub(crate) axis: DVec3,
    pub(crate) radius: f64,
    /// `radius^2 |axis|^2` as a double-double with an error bound, for the
    /// ray cast's filter: computed once here rather than per ray.
    pub(crate) scaled_rr: (f64, f64, f64),
    /// The coordinate axis the axis lies along, if it does (the other two
    /// coordinates zero): the ray cast then drops that coordinate, which
    /// is exact, and solves a circle problem in the other two.
    pub(crate) aligned: Option<usize>,
}

/// Equal when the point, axis and radius are: what the cylinder caches
/// from them may hold NaN (an overflowed `radius^2 |axis|^2`, which only
/// sends its casts to the exact stage), and must not make a cylinder
/// unequal to itself.
impl PartialEq for Cylinder {
    fn eq(&self, other: &Cylinder) -> bool {
        (self.point, self.axis, self.radius) == (other.point, other.axis, other.radius)
    }
}

impl Cylinder {
    /// An infinite cylinder.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] (`"point"`,
    /// `"axis"`, `"radius"`), [`InputError::Degenerate`] for a zero axis,
    /// [`InputError::InvalidRadius`] for a negative or NaN radius. Radius
    /// zero is the axis line itself.
    pub fn new(
        point: impl IntoDVec3,
        axis: impl IntoDVec3,
        radius_: f64,
    ) -> Result<Cylinder, InputError> {
        let (point, axis, radius) = (
            finite("point", point)?,
            nonzero("axis", axis)?,
            radius("radius", radius_)?,
        );
        Ok(Cylinder {
            point,
            axis,
            radius,
            scaled_rr: crate::roots::radial::scaled_square(radius, axis),
            aligned: (0..3).find(|&k| axis[(k + 1) % 3] == 0.0 && axis[(k + 2) % 3] == 0.0),
        })
    }

    /// A point on the axis.
    #[inline]
    pub fn point(&self) -> DVec3 {
        self.point
    }

    /// The axis direction, as given.
    #[inline]
    pub fn axis(&self) -> DVec3 {
        self.axis
    }

    /// The radius.
    #[inline]
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

/// A solid cylinder's surface: the side of [`Cylinder`] between `base`
/// and `base + axis`, closed by the two end disks.
///
/// ```
/// use exactray::shape::CappedCylinder;
/// use exactray::query::ray::RayCast;
/// use exactray::interval::Interval;
/// use exactray::query::ray::Ray;
/// let can = CappedCylinder::new([0.0, 0.0, 0.0], [0.0, 2.0, 0.0], 1.0).unwrap();
/// // Down the axis: the top disk at y = 2.
/// let ray = Ray::new([0.0, 5.0, 0.0], [0.0, -1.0, 0.0]).unwrap();
/// let hit = can.cast(&ray, Interval::FORWARD).unwrap();
/// assert_eq!((hit.t, hit.normal.to_array()), (3.0, [0.0, 1.0, 0.0]));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CappedCylinder {
    pub(crate) side: Cylinder,
}

impl CappedCylinder {
    /// The capped cylinder from `base` to `base + axis`. Errors as for
    /// [`Cylinder::new`] (with `"base"` for the first argument).
    pub fn new(
        base: impl IntoDVec3,
        axis: impl IntoDVec3,
        radius_: f64,
    ) -> Result<CappedCylinder, InputError> {
        let base = finite("base", base)?;
        Ok(CappedCylinder {
            side: Cylinder::new(base, axis, radius_)?,
        })
    }

    /// The infinite cylinder its side lies on.
    #[inline]
    pub fn side(&self) -> Cylinder {
        self.side
    }
}

serde_by_constructor!(
    Cylinder as "Cylinder" { point: DVec3, axis: DVec3, radius: f64 },
    parts: |c| (c.point, c.axis, c.radius),
    build: |d| Cylinder::new(d.point, d.axis, d.radius),
);

serde_by_constructor!(
    CappedCylinder as "CappedCylinder" { base: DVec3, axis: DVec3, radius: f64 },
    parts: |c| (c.side.point, c.side.axis, c.side.radius),
    build: |d| CappedCylinder::new(d.base, d.axis, d.radius),
);
