//! Shapes, by what they are: each type validates itself at construction
//! (typed [`InputError`]s for non-finite coordinates, negative or NaN
//! radii, zero axes or normals, degenerate cones), so every
//! query on it can rely on finite, meaningful parameters. What can be asked
//! of a shape lives in [`query`](crate::query).

mod bounded;
mod cone;
mod cylinder;
mod plane;
mod quadric;
mod sphere;
mod triangle;

pub use bounded::{Aabb, Bounded};
pub use cone::Cone;
pub use cylinder::{CappedCylinder, Cylinder};
pub use plane::{Disk, Plane};
pub use quadric::Quadric;
pub use sphere::Sphere;
pub use triangle::Triangle;

use crate::error::InputError;
use crate::point::IntoDVec3;
use glam::DVec3;

/// `v` if every coordinate is finite, else [`InputError::NonFinite`].
fn finite(argument: &'static str, v: impl IntoDVec3) -> Result<DVec3, InputError> {
    let v = v.into_dvec3();
    if v.is_finite() {
        Ok(v)
    } else {
        Err(InputError::NonFinite { argument })
    }
}

/// A finite, non-zero vector, else [`InputError::NonFinite`] or
/// [`InputError::Degenerate`].
fn nonzero(argument: &'static str, v: impl IntoDVec3) -> Result<DVec3, InputError> {
    let v = finite(argument, v)?;
    if v == DVec3::ZERO {
        Err(InputError::Degenerate { argument })
    } else {
        Ok(v)
    }
}

/// A radius `r >= 0`: NaN or negative is [`InputError::InvalidRadius`],
/// infinite is [`InputError::NonFinite`].
fn radius(argument: &'static str, r: f64) -> Result<f64, InputError> {
    if r.is_nan() || r < 0.0 {
        Err(InputError::InvalidRadius { argument })
    } else if r.is_infinite() {
        Err(InputError::NonFinite { argument })
    } else {
        Ok(r)
    }
}

/// No box holds these: a plane, an infinite cylinder, a general quadric.
macro_rules! unbounded {
    ($($shape:ty),*) => {$(
        impl Bounded for $shape {
            /// `None`: the shape is unbounded.
            #[inline]
            fn aabb(&self) -> Option<Aabb> {
                None
            }
        }
    )*};
}
unbounded!(Plane, Cylinder, Quadric);

impl Bounded for Sphere {
    /// `center +- radius`, rounded outward.
    ///
    /// ```
    /// use exactray::shape::{Bounded, Sphere};
    /// let b = Sphere::new([1.0, 0.0, 0.0], 0.5).unwrap().aabb().unwrap();
    /// assert!(b.contains([1.5, 0.5, -0.5]) && !b.contains([1.6, 0.0, 0.0]));
    /// ```
    fn aabb(&self) -> Option<Aabb> {
        Some(Aabb::around(self.center, DVec3::splat(self.radius)))
    }
}

impl Bounded for Disk {
    /// The box of the disk's sphere (`center +- radius`), rounded outward.
    fn aabb(&self) -> Option<Aabb> {
        Some(Aabb::around(self.plane.point, DVec3::splat(self.radius)))
    }
}

impl Bounded for Triangle {
    /// The vertices' box, exact (no rounding happens). A degenerate
    /// triangle has one too, though no ray hits it.
    fn aabb(&self) -> Option<Aabb> {
        Aabb::of_points(&self.v)
    }
}

impl Bounded for CappedCylinder {
    /// The boxes of the two end disks' spheres (`base +- radius`, `base +
    /// axis +- radius`), rounded outward.
    fn aabb(&self) -> Option<Aabb> {
        let (p, a, r) = (
            self.side.point,
            self.side.axis,
            DVec3::splat(self.side.radius),
        );
        Some(Aabb::around(p, r).union(&Aabb::around_sum(p, a, r)))
    }
}

impl Bounded for Cone {
    /// A capped cone: its apex and its base disk's sphere (`apex + axis +-
    /// radius`), rounded outward. An uncapped cone is unbounded: `None`.
    fn aabb(&self) -> Option<Aabb> {
        self.capped.then(|| {
            let apex = Aabb::around(self.apex, DVec3::ZERO);
            apex.union(&Aabb::around_sum(
                self.apex,
                self.axis,
                DVec3::splat(self.radius),
            ))
        })
    }
}
