//! Ray casts: where a ray `origin + t * direction` first meets a shape for
//! `t` in a parameter [`Interval`], and whether it meets it at all.
//!
//! Every shape implements [`RayCast`]. Quadrics also give all the roots of
//! the whole line against their surface.

use crate::ray::{Interval, Ray};
use glam::DVec3;

pub mod triangle;

pub use triangle::TriangleHit;

/// Where a ray meets a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The ray parameter: the hit point is `origin + t * direction`.
    pub t: f64,
    /// The hit point, `ray.at(t)`.
    pub point: DVec3,
    /// The unit geometric normal of the surface at the hit point, on the
    /// outside of a closed shape (for a plane, a disk or a triangle: the
    /// side its definition names; see each shape).
    pub normal: DVec3,
}

/// A shape a ray can be cast against.
pub trait RayCast {
    /// The hit with the smallest `t` inside `range`, or `None`.
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit>;

    /// Whether the ray meets the shape for some `t` inside `range` (a shadow
    /// ray's question); may be cheaper than [`RayCast::cast`].
    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        self.cast(ray, range).is_some()
    }
}
