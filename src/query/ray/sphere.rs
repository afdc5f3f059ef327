//! Ray against [`Sphere`]: exact root count, accurate roots.

use super::{Hit, Precise, RayCast, hit_at, unit_or};
use crate::arith::error_free::exact_difference;
use crate::arith::exponent::Grain;
use crate::arith::fixed_int::{DEG1, DEG2, DEG4, FixedInt};
use crate::arith::fma_dispatch::{FmaKernel, with_fma};
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::roots::line_quadratic::{
    Coeffs, LineQuadratic, Question, SMALL_SPAN, Tier, exact_roots, first_in, line_roots,
};
use crate::roots::radial::{circle_of, rounded_sphere};
use crate::roots::{BoundedRoot, Roots};
use crate::shape::Sphere;
use glam::DVec3;

/// Limbs for an input coordinate or a difference of two at a common grain
/// (below `2^2100`, as in `predicates/ball.rs`), and for degree 2 and 4.
const W1: usize = DEG1;
const W2: usize = DEG2;
const W4: usize = DEG4;

impl Sphere {
    /// Every real root of `|o + t d - center|^2 = radius^2` over the whole
    /// line (any sign of `t`), sorted. The count is exact: [`Roots::One`]
    /// exactly when the line is tangent, decided on the exact inputs. Each
    /// root is within 4 ulps of the correctly rounded root where the
    /// filtered stage certifies it (every ordinary and far-origin ray of
    /// the report's samples), and within 5 ulps of the exact root
    /// (first-order bound) where the exact stage runs: for tangent and
    /// near-tangent rays, and tiny or huge magnitudes. The report measures
    /// the actual error. NaN or infinite inputs cannot reach here (the
    /// constructors reject them); no input panics or allocates.
    ///
    /// ```
    /// use exactray::shape::Sphere;
    /// use exactray::query::ray::Ray;
    /// use exactray::roots::Roots;
    /// let s = Sphere::new([0.0, 0.0, 0.0], 1.0).unwrap();
    /// let tangent = Ray::new([-5.0, 1.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(s.line_roots(&tangent), Roots::One(5.0));
    /// // Far away and still exact about the miss by 2^-40.
    /// let graze = Ray::new([-1e8, 1.0 + 2f64.powi(-40), 0.0], [1.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(s.line_roots(&graze), Roots::None);
    /// ```
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        line_roots(self, ray.origin(), ray.direction())
    }

    /// The first root in `range` from `tier`, bounded.
    #[inline(always)]
    fn first_in(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<BoundedRoot> {
        first_in(self, ray.origin(), ray.direction(), range, tier)
    }
}

impl LineQuadratic for Sphere {
    const ROUNDED: bool = true;

    #[inline]
    fn filtered<Q: Question>(&self, o: DVec3, d: DVec3, q: Q) -> Option<Q::Answer> {
        with_fma(&Filtered {
            o,
            d,
            sphere: self,
            q,
        })
    }

    fn exact(&self, o: DVec3, d: DVec3) -> Roots {
        exact(o, d, self.center, self.radius)
    }

    /// From the rounded `w = o - c` ([`rounded_sphere`]).
    #[inline(always)]
    fn rounded(&self, o: DVec3, d: DVec3) -> Option<Coeffs> {
        rounded_sphere(o - self.center, d, self.radius)
    }
}

/// The filtered stage, run with hardware FMA where the CPU has it.
struct Filtered<'a, Q> {
    o: DVec3,
    d: DVec3,
    sphere: &'a Sphere,
    q: Q,
}

impl<Q: Question> FmaKernel for Filtered<'_, Q> {
    type Output = Option<Q::Answer>;

    #[inline(always)]
    fn run(&self) -> Option<Q::Answer> {
        let (o, d, c, r) = (self.o, self.d, self.sphere.center, self.sphere.radius);
        let (wh, wl) = exact_difference(o, c);
        circle_of(wh, wl, d, r, self.q)
    }
}

/// The exact stage: `o, c, r` at their common grain `lo` and `d` at its own
/// (the roots do not change when `d` is scaled, and `t` scales by the ratio
/// of the two grains), so `A = |d|^2` at `2 ld`, `B = (o - c) . d` at
/// `lo + ld`, `C = |o - c|^2 - r^2` at `2 lo`. Integers of 2, 5 and 9 limbs
/// suffice when every value spans at most 126 bits at its grain (ordinary
/// inputs); otherwise the widths that hold any finite input.
fn exact(o: DVec3, d: DVec3, c: DVec3, r: f64) -> Roots {
    let g = Grain::of(&[o.x, o.y, o.z, c.x, c.y, c.z, r]);
    let gd = Grain::of(&d.to_array());
    let lo = if g.all_zero() { 0 } else { g.lo_min };
    if g.span().max(gd.span()) <= SMALL_SPAN {
        exact_in::<2, 5, 9>(o, d, c, r, lo, gd.lo_min)
    } else {
        exact_in::<W1, W2, W4>(o, d, c, r, lo, gd.lo_min)
    }
}

fn exact_in<const N1: usize, const N2: usize, const N4: usize>(
    o: DVec3,
    d: DVec3,
    c: DVec3,
    r: f64,
    lo: i32,
    ld: i32,
) -> Roots {
    let (mut a, mut b, mut cc) = (
        FixedInt::<N2>::ZERO,
        FixedInt::<N2>::ZERO,
        FixedInt::<N2>::ZERO,
    );
    for k in 0..3 {
        let w = FixedInt::<N1>::from_f64(o[k], lo).sub(&FixedInt::<N1>::from_f64(c[k], lo));
        let dk = FixedInt::<N1>::from_f64(d[k], ld);
        a = a.add(&FixedInt::mul(&dk, &dk));
        b = b.add(&FixedInt::mul(&w, &dk));
        cc = cc.add(&FixedInt::mul(&w, &w));
    }
    let rw = FixedInt::<N1>::from_f64(r, lo);
    cc = cc.sub(&FixedInt::mul(&rw, &rw));
    exact_roots::<N2, N4>((&a, 2 * ld), (&b, lo + ld), (&cc, 2 * lo))
}

impl RayCast for Sphere {
    /// The first hit in `range`; the normal points away from the centre
    /// (for radius zero: against the ray).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        hit_at(self.cast_bounded(ray, range), ray, |point| {
            unit_or(point - self.center, -ray.direction())
        })
    }

    /// The default tier: hit or miss decided exactly (the discriminant's
    /// sign from its running bound, the root's place in `range` from its
    /// own bound, the precise tier and the exact stage behind both), `t`
    /// from the stable formula on `f64` coefficients with an a-priori
    /// bound (`roots/bounded.rs`), typically a few ulps and at most its
    /// condition number's worth on near-tangent rays.
    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        // No fma here, so no FMA dispatch: inlined into the caller, without
        // the dispatch's call (which cost about a fifth of a cast).
        self.first_in(ray, range, Tier::Default)
    }
}

impl RayCast for Precise<Sphere> {
    /// [`Sphere`]'s cast, its `t` within 4 ulps of the correctly rounded
    /// root ([`Sphere::line_roots`]' accuracy).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        hit_at(self.cast_bounded(ray, range), ray, |point| {
            unit_or(point - self.0.center, -ray.direction())
        })
    }

    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        self.0.first_in(ray, range, Tier::Precise)
    }
}
