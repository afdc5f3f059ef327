//! Ray against [`Cone`].

use super::point_error::{dot_error, quotient_t_error};
use super::{Hit, RayCast, unit_or};
use crate::arith::roundoff::{U, gamma};
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::roots::{Roots, solve_quadratic};
use crate::shape::Cone;
use glam::DVec3;

impl Cone {
    /// Every real root of the double cone's equation
    /// `|w x a|^2 |a|^2 = r^2 (w . a)^2`, `w = o + t d - apex`, over the whole
    /// line, sorted (both nappes; [`RayCast::cast`] keeps the cone's own).
    ///
    /// The coefficients are evaluated in `f64` and solved by
    /// [`solve_quadratic`]: unlike the sphere and the cylinder, the count is
    /// not exact (the discriminant has degree 12 in the inputs), and the
    /// roots carry the coefficients' rounding errors (about `10 u` relative
    /// each, amplified where they cancel) on top of the solver's 4 ulps.
    /// The report measures the error against an exact oracle.
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        let (w, d, a) = (ray.origin() - self.apex, ray.direction(), self.axis);
        let s = a.dot(a);
        let rr = self.radius * self.radius;
        let (u, v) = (w.cross(a), d.cross(a));
        let (p, q) = (w.dot(a), d.dot(a));
        let qa = s * v.dot(v) - rr * q * q;
        let qb = s * u.dot(v) - rr * p * q;
        let qc = s * u.dot(u) - rr * p * p;
        solve_quadratic(qa, 2.0 * qb, qc)
    }

    /// The outward normal of the lateral surface at `x`: the gradient of
    /// `|a|^2 |w x a|^2 - r^2 (w . a)^2`.
    fn normal_at(&self, x: DVec3, fallback: DVec3) -> DVec3 {
        let (w, a) = (x - self.apex, self.axis);
        let (s, h) = (a.dot(a), w.dot(a));
        unit_or(
            (w * s - a * h) * s - a * (self.radius * self.radius * h),
            fallback,
        )
    }
}

impl RayCast for Cone {
    /// The first hit in `range` on the cone's own nappe (`(x - apex) . axis
    /// >= 0`), below the cap for a capped cone, or on the base disk (normal
    /// `+axis`). Nappe, cap and rim membership are decided in `f64`.
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let a = self.axis;
        let s = a.dot(a);
        let height = |t: f64| (ray.at(t) - self.apex).dot(a);
        let on_lateral = |t: f64| {
            let h = height(t);
            range.admits(t) && h >= 0.0 && (!self.capped || h <= s)
        };
        let lateral = match self.line_roots(ray) {
            Roots::One(t) => on_lateral(t).then_some(t),
            Roots::Two(t1, t2) => [t1, t2].into_iter().find(|&t| on_lateral(t)),
            Roots::None | Roots::All => None,
        };
        let dh = ray.direction().dot(a);
        let base = (self.capped && dh != 0.0)
            .then(|| s - (ray.origin() - self.apex).dot(a))
            .map(|num| (num / dh, num))
            .filter(|&(t, _)| {
                let radial = (ray.at(t) - self.apex).cross(a);
                range.admits(t) && radial.dot(radial) <= self.radius * self.radius * s
            });
        // The base plane's level |a|^2 is `s` within gamma(4) of it, the
        // origin's height within its dot product's bound, and `num` rounds
        // once more. The lateral roots carry no certified bound yet.
        let base_error = |t: f64, num: f64| {
            let e_h = dot_error(ray.origin() - self.apex, a);
            let e_num = e_h + gamma(4) * s + U * num.abs() * (1.0 + 2.0 * U);
            quotient_t_error(t, e_num, dh, dot_error(ray.direction(), a))
        };
        let (t, et, normal) = match (lateral, base) {
            (Some(tl), Some((tb, num))) if tb < tl => (tb, base_error(tb, num), a.normalize()),
            (Some(tl), _) => (
                tl,
                f64::INFINITY,
                self.normal_at(ray.at(tl), -ray.direction()),
            ),
            (None, Some((tb, num))) => (tb, base_error(tb, num), a.normalize()),
            (None, None) => return None,
        };
        Some(Hit::at(ray, t, et, normal))
    }
}
