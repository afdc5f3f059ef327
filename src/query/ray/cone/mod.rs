//! Ray against [`Cone`]: exact root count, accurate roots.
//!
//! - `mod.rs`: the line's roots (the filtered stage at the ray's and the
//!   cone's own powers of two, the exact stage behind it), the lateral
//!   normal, and the casts;
//! - `coefficients.rs`: the lateral quadratic's coefficients and its
//!   discriminant, from the line's moment about the apex, with their
//!   a-priori bounds;
//! - `precise.rs`: the polynomial's two evaluations along the line, in
//!   working precision and in double-double, each with its bound, which
//!   certify the roots;
//! - `exact.rs`: the exact stage, the coefficients as integers;
//! - `first_crossing.rs`: the casts' first crossing, in either tier: the
//!   ordinary path at the inputs' own magnitudes, the scaled line, the
//!   nappe and cap tests and the base disk.

use super::{Hit, Precise, RayCast, unit_or};
use crate::arith::error_free::exact_difference;
use crate::arith::exponent::{pow2, scale_pow2, unit_scale};
use crate::arith::fma_dispatch::{FmaKernel, with_fma};
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::roots::line_quadratic::{AllRoots, LineQuadratic, Question, Tier, line_roots, norm1};
use crate::roots::{BoundedRoot, Roots};
use crate::shape::Cone;
use coefficients::Line;
use exact::exact;
use glam::DVec3;
use precise::Lateral;

mod coefficients;
mod exact;
mod first_crossing;
mod precise;
#[cfg(test)]
mod tests;

impl Cone {
    /// Every real root of the double cone's equation
    /// `|w x a|^2 |a|^2 = r^2 (w . a)^2`, `w = o + t d - apex`, over the whole
    /// line, sorted (both nappes; [`RayCast::cast`] keeps the cone's own).
    ///
    /// The count is exact: a line through the apex (off the cone's
    /// rulings) gives its double root [`Roots::One`], a line parallel to a
    /// ruling (the leading coefficient zero) its one linear root or none,
    /// and a ruling [`Roots::All`]. Roots carry the accuracy of
    /// [`Sphere::line_roots`](crate::shape::Sphere::line_roots): within 4
    /// ulps of the correctly rounded root where the filtered stage
    /// certifies them, correctly rounded from the exact stage, for roots in
    /// the normal range.
    ///
    /// The discriminant has degree 12 in the inputs. The filtered stage
    /// evaluates the polynomial's coefficients with the ray and the cone at
    /// their own powers of two, bounds their errors
    /// a priori and certifies each root a posteriori, as the quadrics do
    /// (`roots::line_quadratic`); where it cannot (near-tangent rays,
    /// rays through or near the apex, lines near a ruling's direction,
    /// inputs whose scaling is not exact), the exact stage decides the
    /// count from the coefficients as integers.
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        line_roots(self, ray.origin(), ray.direction())
    }

    /// The ray and the cone at their own powers of two, or `None` where a
    /// scaling would not be exact (a component leaving the normal range).
    ///
    /// The polynomial `|a|^2 |(w + t d) x a|^2 - r^2 ((w + t d) . a)^2`
    /// (`w = o - apex`) has degree six in lengths, so it is evaluated with
    /// `w` scaled by `2^kw`, `d` by `2^kd` and the pair `(a, r)` by
    /// `2^ka`, each brought to a largest magnitude in `[1/2, 1)`. It is
    /// homogeneous in each (of degree 4 in `(a, r)` jointly), so its roots
    /// in `tau = t 2^(kw - kd)` are those of the unscaled one scaled
    /// exactly, and nothing overflows wherever in `f64`'s range each group
    /// sits.
    fn scaled(&self, o: DVec3, d: DVec3) -> Option<ScaledLine> {
        let unit = |v: &[f64]| unit_scale(v).clamp(-1000, 1000);
        let (wh, wl) = exact_difference(o, self.apex);
        let a = self.axis;
        let (kw, kd) = (unit(&[wh.x, wh.y, wh.z]), unit(&[d.x, d.y, d.z]));
        let ka = unit(&[a.x, a.y, a.z, self.radius]);
        let (fw, fd, fa) = (pow2(kw), pow2(kd), pow2(ka));
        let exact = |v: DVec3, f: f64, k: i32| (v * f) * pow2(-k) == v;
        let r = self.radius * fa;
        let all_exact = exact(wh, fw, kw)
            && exact(wl, fw, kw)
            && exact(d, fd, kd)
            && exact(a, fa, ka)
            && r * pow2(-ka) == self.radius;
        all_exact.then(|| ScaledLine {
            wh: wh * fw,
            wl: wl * fw,
            d: d * fd,
            a: a * fa,
            r,
            back: kd - kw,
        })
    }

    /// The outward normal of the lateral surface at `x`: the gradient of
    /// `|a|^2 |w x a|^2 - r^2 (w . a)^2`.
    ///
    /// The gradient has degree one in `w = x - apex` and four in `(a, r)`
    /// jointly, so its direction is computed with `w` and `(a, r)` each
    /// scaled by a power of two near 1 (as in [`Cone::scaled`]), which
    /// keeps its fifth powers in range.
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

/// The lateral surface's quadratic, on the scaled line ([`Cone::scaled`]);
/// the driver's questions are answered from the certified roots scaled
/// back (exactly: the scaling is exact unless a root is subnormal, within
/// the precise tier's bound then too).
impl LineQuadratic for Cone {
    #[inline]
    fn filtered<Q: Question>(&self, o: DVec3, d: DVec3, q: Q) -> Option<Q::Answer> {
        let line = self.scaled(o, d)?;
        let roots = with_fma(&Filtered { line: &line })?;
        let back = |tau: f64| scale_pow2(tau, line.back);
        Some(q.exact_answer(match roots {
            Roots::One(t) => Roots::One(back(t)),
            Roots::Two(t1, t2) => Roots::Two(back(t1), back(t2)),
            other => other,
        }))
    }

    fn exact(&self, o: DVec3, d: DVec3) -> Roots {
        exact(o, d, self.apex, self.axis, self.radius)
    }

    #[inline]
    fn bounded_pair(&self, o: DVec3, d: DVec3) -> Option<Option<[BoundedRoot; 2]>> {
        self.bounded_line_roots(o, d)
    }
}

/// A ray and a cone with `w = o - apex = wh + wl` (exactly), `d` and the
/// pair `(a, r)` each scaled exactly by a power of two that brings its
/// largest magnitude into `[1/2, 1)`; `t = tau 2^back` for the scaled
/// polynomial's roots `tau`.
struct ScaledLine {
    pub(super) wh: DVec3,
    pub(super) wl: DVec3,
    pub(super) d: DVec3,
    pub(super) a: DVec3,
    pub(super) r: f64,
    pub(super) back: i32,
}

impl ScaledLine {
    /// The coefficients' inputs: `w` as its high part, within `|wl|_1`.
    #[inline(always)]
    fn line(&self) -> Line {
        Line {
            w: self.wh,
            ew1: norm1(self.wl),
            d: self.d,
            a: self.a,
            r: self.r,
        }
    }
}

/// The filtered stage, run with hardware FMA where the CPU has it.
struct Filtered<'a> {
    line: &'a ScaledLine,
}

impl FmaKernel for Filtered<'_> {
    type Output = Option<Roots>;

    #[inline(always)]
    fn run(&self) -> Option<Roots> {
        let (k, _) = self.line.line().filtered()?;
        AllRoots.answer(&k, &Lateral::of(self.line))
    }
}

impl RayCast for Cone {
    /// The first hit in `range` on the cone's own nappe (`(x - apex) . axis
    /// >= 0`), below the cap for a capped cone, or on the base disk (normal
    /// `+axis`). The lateral roots come from the default tier (exact count,
    /// the stable formula's root with its a-priori bound, its place in
    /// `range` certified); nappe, cap and rim membership, and the base
    /// plane's parameter against `range`, are decided in `f64`, so a
    /// crossing within a few ulps of the apex, the rim or an end of `range`
    /// may go either way. The base disk's `t` comes with its own certified
    /// bound ([`Hit::t_error`]).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.cast_tier(ray, range, Tier::Default)
    }

    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        Some(self.first_bounded(ray, range, Tier::Default)?.0)
    }
}

impl RayCast for Precise<Cone> {
    /// [`Cone`]'s cast, its lateral `t` within 4 ulps of the correctly
    /// rounded root ([`Cone::line_roots`]' accuracy).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.0.cast_tier(ray, range, Tier::Precise)
    }

    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        Some(self.0.first_bounded(ray, range, Tier::Precise)?.0)
    }
}
