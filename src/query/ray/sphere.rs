//! Ray against [`Sphere`]: exact root count, accurate roots.

use super::quadratic::{U, circle_coeffs, exact_roots, filtered_roots, in_filter_range, norm1};
use super::{Hit, RayCast, first_in, unit_or};
use crate::predicates::grain::Grain;
use crate::predicates::wide::Wide;
use crate::ray::{Interval, Ray};
use crate::roots::Roots;
use crate::shape::Sphere;
use glam::DVec3;

/// Limbs for an input coordinate or a difference of two at a common grain
/// (below `2^2100`, as in `predicates/ball.rs`), and for degree 2 and 4.
const W1: usize = 34;
const W2: usize = 67;
const W4: usize = 133;

impl Sphere {
    /// Every real root of `|o + t d - center|^2 = radius^2` over the whole
    /// line (any sign of `t`), sorted. The count is exact: [`Roots::One`]
    /// exactly when the line is tangent, decided on the exact inputs. Each
    /// root is within 16 ulps of the exact root (the filtered stage's
    /// certified bound; within 5 ulps when the exact stage runs, which it
    /// does for grazing rays, far origins, origins near the surface and
    /// tiny or huge magnitudes; the report measures the actual error).
    ///
    /// ```
    /// use exactray::shape::Sphere;
    /// use exactray::ray::Ray;
    /// use exactray::roots::Roots;
    /// let s = Sphere::new([0.0, 0.0, 0.0], 1.0).unwrap();
    /// let tangent = Ray::new([-5.0, 1.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(s.line_roots(&tangent), Roots::One(5.0));
    /// // Far away and still exact about the miss by 2^-40.
    /// let graze = Ray::new([-1e8, 1.0 + 2f64.powi(-40), 0.0], [1.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(s.line_roots(&graze), Roots::None);
    /// ```
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        let (o, d) = (ray.origin(), ray.direction());
        let w = o - self.center;
        let rr = self.radius * self.radius;
        let (nw, nd) = (norm1(w), norm1(d));
        let a = nd * nd;
        if in_filter_range(a) && in_filter_range(nw * nd) && in_filter_range(rr * a) {
            // w = o - c rounds once per coordinate: |δw_i| <= u |w_i|; r^2
            // rounds once.
            let k = circle_coeffs(w, w.abs() * U, d, DVec3::ZERO, rr, U * rr);
            if let Some(roots) = filtered_roots(&k) {
                return roots;
            }
        }
        exact(o, d, self.center, self.radius)
    }
}

/// The exact stage: `o, c, r` at their common grain `lo` and `d` at its own
/// (the roots do not change when `d` is scaled, and `t` scales by the ratio
/// of the two grains), so `A = |d|^2` at `2 ld`, `B = (o - c) . d` at
/// `lo + ld`, `C = |o - c|^2 - r^2` at `2 lo`.
fn exact(o: DVec3, d: DVec3, c: DVec3, r: f64) -> Roots {
    let g = Grain::of(&[o.x, o.y, o.z, c.x, c.y, c.z, r]);
    let lo = if g.all_zero() { 0 } else { g.lo_min };
    let ld = Grain::of(&d.to_array()).lo_min;
    let (mut a, mut b, mut cc) = (Wide::<W2>::ZERO, Wide::<W2>::ZERO, Wide::<W2>::ZERO);
    for k in 0..3 {
        let w = Wide::<W1>::from_f64(o[k], lo).sub(&Wide::<W1>::from_f64(c[k], lo));
        let dk = Wide::<W1>::from_f64(d[k], ld);
        a = a.add(&Wide::mul(&dk, &dk));
        b = b.add(&Wide::mul(&w, &dk));
        cc = cc.add(&Wide::mul(&w, &w));
    }
    let rw = Wide::<W1>::from_f64(r, lo);
    cc = cc.sub(&Wide::mul(&rw, &rw));
    exact_roots::<W2, W4>((&a, 2 * ld), (&b, lo + ld), (&cc, 2 * lo))
}

impl RayCast for Sphere {
    /// The first hit in `range`; the normal points away from the centre
    /// (for radius zero: against the ray).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let t = first_in(self.line_roots(ray), range)?;
        let point = ray.at(t);
        Some(Hit {
            t,
            point,
            normal: unit_or(point - self.center, -ray.direction()),
        })
    }

    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        first_in(self.line_roots(ray), range).is_some()
    }
}
