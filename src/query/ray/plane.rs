//! Ray against [`Plane`] and [`Disk`].

use super::point_error::dot_error;
use super::{Hit, RayCast};
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::roots::bounded::quotient_error;
use crate::shape::{Disk, Plane};

impl Plane {
    /// The parameter where the line meets the plane,
    /// `t = ((point - o) . n) / (d . n)`, or `None` when the line is
    /// parallel to it (`d . n` evaluates to zero; a line lying in the
    /// plane included). Each dot product rounds 3 times, the difference
    /// once per coordinate and the quotient once: `t` is within
    /// `(4 + 3 κ) u` relative error of the exact parameter to first order,
    /// where `κ` is the cancellation of the numerator's dot product.
    #[inline]
    pub fn line_parameter(&self, ray: &Ray) -> Option<f64> {
        let den = ray.direction().dot(self.normal);
        let t = (self.point - ray.origin()).dot(self.normal) / den;
        (den != 0.0 && t.is_finite()).then_some(t)
    }
}

impl RayCast for Plane {
    /// The hit in `range`; the normal is the plane's, normalized (not
    /// flipped towards the ray).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let t = self.line_parameter(ray).filter(|&t| range.admits(t))?;
        // `t = fl(num / den)` with both dot products' errors bounded.
        let n = self.normal;
        let et = quotient_error(
            t,
            dot_error(self.point - ray.origin(), n),
            ray.direction().dot(n),
            dot_error(ray.direction(), n),
        );
        Some(Hit::at(ray, t, et, n.normalize()))
    }
}

impl RayCast for Disk {
    /// The plane's hit, kept when `|x - center|^2 <= radius^2` in `f64`
    /// at the disk's own power-of-two scale, so that the squares neither
    /// underflow nor overflow (`rim.rs`; rays within a few ulps of the rim
    /// may go either way).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let hit = self.plane.cast(ray, range)?;
        super::rim::within_radius(hit.point - self.plane.point, self.radius).then_some(hit)
    }
}
