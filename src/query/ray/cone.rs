//! Ray against [`Cone`].

use super::point_error::{dot_error, quotient_t_error};
use super::{Hit, RayCast, unit_or};
use crate::arith::exponent::{pow2, scale_pow2, unit_scale};
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
    ///
    /// The polynomial `|a|^2 |(w + t d) x a|^2 - r^2 ((w + t d) . a)^2`
    /// (`w = o - apex`) has degree six in lengths, so it is evaluated at
    /// three powers of two: `w` scaled by `2^kw`, `d` by `2^kd` and the
    /// pair `(a, r)` by `2^ka`, each brought near 1. The polynomial is
    /// homogeneous in each (of degree 4 in `(a, r)` jointly), so its roots
    /// in `tau = t 2^(kw - kd)` are those of the unscaled one, and every
    /// rounding is the same wherever the unscaled terms were normal; only
    /// the range over which nothing underflows or overflows grows: each
    /// group may sit anywhere in `f64`'s range (before, everything beyond
    /// about `1e±51` under- or overflowed), and only terms of widely different
    /// magnitudes within one group can still underflow.
    /// The roots are scaled back exactly (unless they leave the range).
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        let line = self.scaled(ray);
        let [qa, qb, qc] = line.coefficients();
        let back = |tau: f64| scale_pow2(tau, line.back);
        match solve_quadratic(qa, 2.0 * qb, qc) {
            Roots::One(t) => Roots::One(back(t)),
            Roots::Two(t1, t2) => Roots::Two(back(t1), back(t2)),
            other => other,
        }
    }

    /// The ray and the cone at their own powers of two (see
    /// [`line_roots`](Self::line_roots)).
    fn scaled(&self, ray: &Ray) -> ScaledLine {
        let unit = |v: &[f64]| unit_scale(v).clamp(-1000, 1000);
        let (w, d, a) = (ray.origin() - self.apex, ray.direction(), self.axis);
        let (kw, kd) = (unit(&[w.x, w.y, w.z]), unit(&[d.x, d.y, d.z]));
        let ka = unit(&[a.x, a.y, a.z, self.radius]);
        ScaledLine {
            w: w * pow2(kw),
            d: d * pow2(kd),
            a: a * pow2(ka),
            r: self.radius * pow2(ka),
            back: kd - kw,
        }
    }

    /// A bound on the distance from a lateral root `t` (of the computed
    /// quadratic) to a root of the exact polynomial, by an a-posteriori
    /// bracket: the exact polynomial's sign is certified at `t - r` and
    /// `t + r` and found opposite, so exactly one exact root lies between
    /// them. Infinite where the certificate fails (near-tangent rays, where
    /// two roots are close; and, of the scaled inputs, which lie below 1,
    /// none whose magnitudes the bounds below do not cover).
    ///
    /// Each coefficient is a polynomial in the exact inputs; computed with
    /// at most `k` roundings on any term's path (`w` 1, `u = w x a` 3,
    /// `v = d x a` 2, `p = w . a` 4, `q = d . a` 3, `s = a . a` 3; `qa` 10,
    /// `qb` 13, `qc` 14), it is within `gamma(k)` of the same expression
    /// over the terms' magnitudes (Higham, §3.1). The magnitudes are
    /// themselves rounded (`k` more times), hence `gamma(2k)` of the
    /// computed ones. A product that underflows loses at most `2^-1075`,
    /// scaled by later factors below `2^300`: an absolute `SLACK` (below
    /// `2^-697`) covers them.
    ///
    /// The bracket is found on the scaled polynomial in `tau = t
    /// 2^-back` ([`line_roots`](Self::line_roots)), whose exact roots are
    /// the exact `t`'s scaled exactly, and its half-width scaled back, plus
    /// `2^-1073` for the two roundings `scale_pow2` may make there; a `t`
    /// that does not scale exactly gets no bound.
    fn lateral_t_error(&self, ray: &Ray, t: f64) -> f64 {
        let line = self.scaled(ray);
        let tau = scale_pow2(t, -line.back);
        if scale_pow2(tau, line.back) != t {
            return f64::INFINITY;
        }
        scale_pow2(Self::bracket(&line, tau), line.back) + f64::from_bits(2)
    }

    /// [`lateral_t_error`](Self::lateral_t_error) on the scaled line.
    fn bracket(line: &ScaledLine, t: f64) -> f64 {
        let (w, d, a, r) = (line.w, line.d, line.a, line.r);
        let limit = pow2(150);
        let within = |v: DVec3| v.abs().max_element() < limit;
        if !(within(w) && within(d) && within(a) && r < limit) {
            return f64::INFINITY;
        }
        let (s, rr) = (a.dot(a), r * r);
        let k = line.coefficients();
        let abs_cross = |x: DVec3, y: DVec3| {
            let (x, y) = (x.abs(), y.abs());
            DVec3::new(
                x.y * y.z + x.z * y.y,
                x.z * y.x + x.x * y.z,
                x.x * y.y + x.y * y.x,
            )
        };
        let (um, vm) = (abs_cross(w, a), abs_cross(d, a));
        let (pm, qm) = (w.abs().dot(a.abs()), d.abs().dot(a.abs()));
        const SLACK: f64 = 1.0e-210;
        let e = [
            gamma(20) * (s * vm.dot(vm) + rr * qm * qm) + SLACK,
            gamma(26) * (s * um.dot(vm) + rr * pm * qm) + SLACK,
            gamma(28) * (s * um.dot(um) + rr * pm * pm) + SLACK,
        ];
        // p(x) = (qa x + 2 qb) x + qc: Horner's roundings on the computed
        // coefficients (gamma(5) of the terms' magnitudes, the doubling
        // exact), and the coefficients' own errors, all with a margin.
        let value = |x: f64| (k[0] * x + 2.0 * k[1]) * x + k[2];
        let bound = |x: f64| {
            let x2 = x * x;
            (gamma(5) * (k[0].abs() * x2 + 2.0 * (k[1] * x).abs() + k[2].abs())
                + e[0] * x2
                + 2.0 * e[1] * x.abs()
                + e[2])
                * (1.0 + gamma(4))
                + SLACK
        };
        let slope = 2.0 * (k[0] * t + k[1]);
        let mut radius = 4.0 * bound(t) / slope.abs() + gamma(4) * t.abs();
        for _ in 0..2 {
            let (lo, hi) = ((t - radius).next_down(), (t + radius).next_up());
            let (vl, vh) = (value(lo), value(hi));
            if vl.abs() > bound(lo) && vh.abs() > bound(hi) && (vl < 0.0) != (vh < 0.0) {
                // The exact root lies in (lo, hi).
                return (t - lo).max(hi - t) * (1.0 + gamma(2));
            }
            radius *= 16.0;
        }
        f64::INFINITY
    }

    /// The outward normal of the lateral surface at `x`: the gradient of
    /// `|a|^2 |w x a|^2 - r^2 (w . a)^2`.
    ///
    /// The gradient has degree one in `w = x - apex` and four in `(a, r)`
    /// jointly, so its direction is computed with `w` and `(a, r)` each
    /// scaled by a power of two near 1 (as in [`line_roots`](Self::line_roots)),
    /// which keeps its fifth powers in range.
    fn normal_at(&self, x: DVec3, fallback: DVec3) -> DVec3 {
        let w = x - self.apex;
        let w = w * pow2(unit_scale(&[w.x, w.y, w.z]).clamp(-1000, 1000));
        let ka =
            unit_scale(&[self.axis.x, self.axis.y, self.axis.z, self.radius]).clamp(-1000, 1000);
        let (a, r) = (self.axis * pow2(ka), self.radius * pow2(ka));
        let (s, h) = (a.dot(a), w.dot(a));
        unit_or((w * s - a * h) * s - a * (r * r * h), fallback)
    }
}

/// A ray and a cone with `w = o - apex`, `d` and the pair `(a, r)` each
/// scaled by a power of two near 1; `t = tau 2^back` for the scaled
/// polynomial's roots `tau`.
struct ScaledLine {
    w: DVec3,
    d: DVec3,
    a: DVec3,
    r: f64,
    back: i32,
}

impl ScaledLine {
    /// The lateral quadratic `qa tau^2 + 2 qb tau + qc` of the scaled line.
    fn coefficients(&self) -> [f64; 3] {
        let (w, d, a) = (self.w, self.d, self.a);
        let (s, rr) = (a.dot(a), self.r * self.r);
        let (u, v) = (w.cross(a), d.cross(a));
        let (p, q) = (w.dot(a), d.dot(a));
        [
            s * v.dot(v) - rr * q * q,
            s * u.dot(v) - rr * p * q,
            s * u.dot(u) - rr * p * p,
        ]
    }
}

/// Which surface of a cone a cast's first crossing lies on.
#[derive(Clone, Copy)]
enum Crossing {
    /// The lateral surface, at `t`.
    Lateral(f64),
    /// The base disk, at `t = num / (d . a)`.
    Base { t: f64, num: f64 },
}

impl Cone {
    /// The first crossing in `range` on the cone's own nappe (below the cap
    /// for a capped cone) or on its base disk.
    fn first_crossing(&self, ray: &Ray, range: Interval) -> Option<Crossing> {
        let a = self.axis;
        let on_lateral = |t: f64| {
            // At the axis's scale (`rim.rs`).
            let (h, s) = super::rim::heights(ray.at(t) - self.apex, a);
            range.admits(t) && h >= 0.0 && (!self.capped || h <= s)
        };
        let lateral = match self.line_roots(ray) {
            Roots::One(t) => on_lateral(t).then_some(t),
            Roots::Two(t1, t2) => [t1, t2].into_iter().find(|&t| on_lateral(t)),
            Roots::None | Roots::All => None,
        };
        // The base plane's crossing with the axis at its own scale
        // (`rim.rs`): `a . â` for `|a|^2`.
        let ah = super::rim::unit_axis(a);
        let dh = ray.direction().dot(ah);
        let base = (self.capped && dh != 0.0)
            .then(|| a.dot(ah) - (ray.origin() - self.apex).dot(ah))
            .map(|num| (num / dh, num))
            .filter(|&(t, _)| {
                range.admits(t)
                    && super::rim::within_axis_radius(ray.at(t) - self.apex, a, self.radius)
            });
        match (lateral, base) {
            (Some(tl), Some((tb, num))) if tb < tl => Some(Crossing::Base { t: tb, num }),
            (Some(tl), _) => Some(Crossing::Lateral(tl)),
            (None, Some((t, num))) => Some(Crossing::Base { t, num }),
            (None, None) => None,
        }
    }
}

impl RayCast for Cone {
    /// The first hit in `range` on the cone's own nappe (`(x - apex) . axis
    /// >= 0`), below the cap for a capped cone, or on the base disk (normal
    /// `+axis`). Nappe, cap and rim membership are decided in `f64`.
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let a = self.axis;
        Some(match self.first_crossing(ray, range)? {
            Crossing::Lateral(t) => {
                let normal = self.normal_at(ray.at(t), -ray.direction());
                Hit::at(ray, t, self.lateral_t_error(ray, t), normal)
            }
            Crossing::Base { t, num } => {
                // The base plane's level |a|^2 (`a . â`) within gamma(4) of it,
                // the origin's height within its dot product's bound, and
                // `num` rounds once more.
                // All with the scaled axis `â` of `first_crossing`.
                let ah = super::rim::unit_axis(a);
                let e_h = dot_error(ray.origin() - self.apex, ah);
                let e_num = e_h + gamma(4) * a.dot(ah) + U * num.abs() * (1.0 + 2.0 * U);
                let dh = ray.direction().dot(ah);
                let et = quotient_t_error(t, e_num, dh, dot_error(ray.direction(), ah));
                Hit::at(ray, t, et, a.normalize())
            }
        })
    }

    /// [`RayCast::cast`]'s `t`, without its normal and point error (the
    /// lateral root's bracket costs as much as the cast).
    fn cast_t(&self, ray: &Ray, range: Interval) -> Option<f64> {
        Some(match self.first_crossing(ray, range)? {
            Crossing::Lateral(t) | Crossing::Base { t, .. } => t,
        })
    }
}
