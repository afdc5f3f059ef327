//! Ray against [`Cylinder`] and [`CappedCylinder`]: exact root count for
//! the infinite side, accurate roots.

use super::quadratic::{
    SMALL_SPAN, U, certified_roots, circle_coeffs, cross_magnitudes, eval_circle, exact_roots,
    in_filter_range, norm1,
};
use super::{Hit, RayCast, first_hit, first_in, unit_or};
use crate::predicates::grain::Grain;
use crate::predicates::wide::Wide;
use crate::ray::{Interval, Ray};
use crate::roots::Roots;
use crate::shape::{CappedCylinder, Cylinder};
use glam::DVec3;

/// Limbs at the common grains: an input or a difference of two (below
/// `2^2100`), then degrees 2, 4 and 8.
const W1: usize = 34;
const W2: usize = 67;
const W4: usize = 133;
const W8: usize = 266;

impl Cylinder {
    /// Every real root of `|(o + t d - point) x axis|^2 = radius^2 |axis|^2`
    /// over the whole line, sorted. The count is exact: tangent lines give
    /// [`Roots::One`]; a line parallel to the axis gives [`Roots::None`]
    /// (off the surface) or [`Roots::All`] (on it), decided exactly. Roots
    /// carry the accuracy of
    /// [`Sphere::line_roots`](crate::shape::Sphere::line_roots).
    ///
    /// ```
    /// use exactray::shape::Cylinder;
    /// use exactray::ray::Ray;
    /// use exactray::roots::Roots;
    /// // The exam's cylinder x^2 + z^2 = 1 (Q1).
    /// let c = Cylinder::new([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1.0).unwrap();
    /// let ray = Ray::new([0.0, 0.0, -3.0], [0.0, 1.0, 1.0]).unwrap();
    /// assert_eq!(c.line_roots(&ray), Roots::Two(2.0, 4.0));
    /// let on_surface = Ray::new([1.0, 0.0, 0.0], [0.0, 3.0, 0.0]).unwrap();
    /// assert_eq!(c.line_roots(&on_surface), Roots::All);
    /// ```
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        let (o, d, ax) = (ray.origin(), ray.direction(), self.axis);
        let w = o - self.point;
        // Project across the axis: |u + t v|^2 = R^2 with u = w x a,
        // v = d x a, R^2 = r^2 |a|^2, a sphere-like problem in the plane
        // normal to the axis (scaled by |a|).
        let (u, v) = (w.cross(ax), d.cross(ax));
        let rr = self.radius * self.radius * ax.dot(ax);
        let (nu, nv) = (norm1(u), norm1(v));
        if in_filter_range(nv * nv) && in_filter_range(nu * nv) && in_filter_range(rr * nv * nv) {
            // Per component, u = w x a carries w's rounding (u |w_i|) and
            // two roundings of its own, each relative to the magnitudes of
            // its two products: 3 u (|w_j a_k| + |w_k a_j|); v = d x a only
            // its own two. R^2 carries r^2 (1 rounding), |a|^2 (3) and their
            // product (1).
            let eu = cross_magnitudes(w, ax) * (3.0 * U);
            let ev = cross_magnitudes(d, ax) * (2.0 * U);
            let err = 5.0 * U * rr;
            let k = circle_coeffs(u, eu, v, ev, rr, err);
            let eval = |t| eval_circle(u, eu, v, ev, rr, err, t);
            if let Some(roots) = certified_roots(&k, eval) {
                return roots;
            }
        }
        exact(o, d, self.point, ax, self.radius)
    }

    /// The unit normal at `x` (on or near the surface): away from the axis.
    #[inline]
    fn normal_at(&self, x: DVec3, fallback: DVec3) -> DVec3 {
        let w = x - self.point;
        let a = self.axis;
        unit_or(w - a * (w.dot(a) / a.dot(a)), fallback)
    }
}

/// The exact stage, at three grains (`o, p, r`: `lo`; `d`: `ld`; `a`:
/// `la`), under which the equation keeps its roots: `A = |v|^2` at
/// `2 ld + 2 la`, `B = u . v` at `lo + ld + 2 la`, `C = |u|^2 - r^2 |a|^2`
/// at `2 lo + 2 la`. Small integers for ordinary spans, as for the sphere.
fn exact(o: DVec3, d: DVec3, p: DVec3, ax: DVec3, r: f64) -> Roots {
    let g = Grain::of(&[o.x, o.y, o.z, p.x, p.y, p.z, r]);
    let (gd, ga) = (Grain::of(&d.to_array()), Grain::of(&ax.to_array()));
    let lo = if g.all_zero() { 0 } else { g.lo_min };
    let grains = (lo, gd.lo_min, ga.lo_min);
    if g.span().max(gd.span()).max(ga.span()) <= SMALL_SPAN {
        exact_in::<2, 5, 9, 18>(o, d, p, ax, r, grains)
    } else {
        exact_in::<W1, W2, W4, W8>(o, d, p, ax, r, grains)
    }
}

fn exact_in<const N1: usize, const N2: usize, const N4: usize, const N8: usize>(
    o: DVec3,
    d: DVec3,
    p: DVec3,
    ax: DVec3,
    r: f64,
    (lo, ld, la): (i32, i32, i32),
) -> Roots {
    let w: [Wide<N1>; 3] =
        core::array::from_fn(|k| Wide::from_f64(o[k], lo).sub(&Wide::from_f64(p[k], lo)));
    let dw: [Wide<N1>; 3] = core::array::from_fn(|k| Wide::from_f64(d[k], ld));
    let aw: [Wide<N1>; 3] = core::array::from_fn(|k| Wide::from_f64(ax[k], la));
    let u: [Wide<N2>; 3] = cross(&w, &aw);
    let v: [Wide<N2>; 3] = cross(&dw, &aw);
    let (mut a, mut b, mut c, mut aa) = (
        Wide::<N4>::ZERO,
        Wide::<N4>::ZERO,
        Wide::<N4>::ZERO,
        Wide::<N2>::ZERO,
    );
    for k in 0..3 {
        a = a.add(&Wide::mul(&v[k], &v[k]));
        b = b.add(&Wide::mul(&u[k], &v[k]));
        c = c.add(&Wide::mul(&u[k], &u[k]));
        aa = aa.add(&Wide::mul(&aw[k], &aw[k]));
    }
    let rw = Wide::<N1>::from_f64(r, lo);
    let r2 = Wide::<N2>::mul(&rw, &rw);
    c = c.sub(&Wide::mul(&r2, &aa));
    exact_roots::<N4, N8>(
        (&a, 2 * (ld + la)),
        (&b, lo + ld + 2 * la),
        (&c, 2 * (lo + la)),
    )
}

/// `x x y`, exactly.
fn cross<const N1: usize, const N2: usize>(x: &[Wide<N1>; 3], y: &[Wide<N1>; 3]) -> [Wide<N2>; 3] {
    core::array::from_fn(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        Wide::<N2>::mul(&x[i], &y[j]).sub(&Wide::mul(&x[j], &y[i]))
    })
}
impl RayCast for Cylinder {
    /// The first hit in `range`; the normal points away from the axis. A
    /// line lying on the surface hits at the point of `range` nearest
    /// `t = 0`.
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        first_hit(self.line_roots(ray), ray, range, |point| {
            self.normal_at(point, -ray.direction())
        })
    }

    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        first_in(self.line_roots(ray), range).is_some()
    }
}

impl RayCast for CappedCylinder {
    /// The first hit in `range` on the side (between the end planes) or on
    /// an end disk (normal `-axis` at the base, `+axis` at the top). The
    /// side's roots carry [`Cylinder::line_roots`]' guarantees; whether a
    /// hit near the rim belongs to the side or a disk, and whether a ray
    /// grazing the rim hits, are decided in `f64` (within a few ulps of the
    /// rim).
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let side = &self.side;
        let (a, aa) = (side.axis, side.axis.dot(side.axis));
        let height = |x: DVec3| (x - side.point).dot(a);
        let mut best: Option<Hit> = None;
        let mut consider = |t: f64, normal: &dyn Fn(DVec3) -> DVec3| {
            if range.contains(t) && best.is_none_or(|b| t < b.t) {
                let point = ray.at(t);
                best = Some(Hit {
                    t,
                    point,
                    normal: normal(point),
                });
            }
        };
        let on_side = |t: f64| {
            let h = height(ray.at(t));
            (0.0..=aa).contains(&h)
        };
        let side_normal = |x: DVec3| side.normal_at(x, -ray.direction());
        match side.line_roots(ray) {
            Roots::One(t) if on_side(t) => consider(t, &side_normal),
            Roots::Two(t1, t2) => {
                for t in [t1, t2] {
                    if on_side(t) {
                        consider(t, &side_normal);
                    }
                }
            }
            _ => {}
        }
        // The end disks: h(t) = (o - p) . a + t d . a equals 0 or |a|^2.
        let (h0, dh) = (height(ray.origin()), ray.direction().dot(a));
        if dh != 0.0 {
            let rr = side.radius * side.radius * aa;
            for (level, sign) in [(0.0, -1.0), (aa, 1.0)] {
                let t = (level - h0) / dh;
                let radial = (ray.at(t) - side.point).cross(a);
                if radial.dot(radial) <= rr {
                    consider(t, &|_| a.normalize() * sign);
                }
            }
        }
        best
    }
}
