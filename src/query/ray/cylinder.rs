//! Ray against [`Cylinder`] and [`CappedCylinder`]: exact root count for
//! the infinite side, accurate roots.

use super::point_error::dot_error;
use super::{Hit, Precise, RayCast, hit_at, unit_or};
use crate::arith::double_double::DoubleDouble;
use crate::arith::error_free::exact_difference;
use crate::arith::exponent::{Grain, unit_pow2};
use crate::arith::fixed_int::{DEG1, DEG2, DEG4, FixedInt, cross3};
use crate::arith::fma_dispatch::{FmaKernel, with_fma};
use crate::arith::roundoff::{U, gamma};
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::roots::line_quadratic::{
    Coeffs, ETA, LineQuadratic, Question, SMALL_SPAN, Tier, crossings, exact_roots, first_in,
    in_filter_range, line_roots, norm1, quotient_error,
};
use crate::roots::radial::{Circle, circle_of, rounded_circle, rounded_sphere};
use crate::roots::{BoundedRoot, Roots};
use crate::shape::{CappedCylinder, Cylinder};
use glam::DVec3;

/// Limbs at the common grains: an input or a difference of two (below
/// `2^2100`), then degrees 2, 4 and 8.
const W1: usize = DEG1;
const W2: usize = DEG2;
const W4: usize = DEG4;
/// A product of two degree-4 values takes the limbs of both.
const W8: usize = 2 * W4;

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
    /// use exactray::query::ray::Ray;
    /// use exactray::roots::Roots;
    /// // The cylinder x^2 + z^2 = 1 of question Q1.
    /// let c = Cylinder::new([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1.0).unwrap();
    /// let ray = Ray::new([0.0, 0.0, -3.0], [0.0, 1.0, 1.0]).unwrap();
    /// assert_eq!(c.line_roots(&ray), Roots::Two(2.0, 4.0));
    /// let on_surface = Ray::new([1.0, 0.0, 0.0], [0.0, 3.0, 0.0]).unwrap();
    /// assert_eq!(c.line_roots(&on_surface), Roots::All);
    /// ```
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        line_roots(self, ray.origin(), ray.direction())
    }

    /// The first root in `range` from `tier`, bounded.
    #[inline(always)]
    fn first_in(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<BoundedRoot> {
        first_in(self, ray.origin(), ray.direction(), range, tier)
    }

    /// The unit normal at `x` (on or near the surface): away from the axis.
    /// `w - a (w . a) / (a . a)` is linear in `w = x - point` and of degree
    /// zero in `a`, so both are first scaled by powers of two near 1: the
    /// dot products then neither underflow nor overflow at any scale.
    #[inline]
    fn normal_at(&self, x: DVec3, fallback: DVec3) -> DVec3 {
        let near_one = |v: DVec3| v * unit_pow2(v.abs().max_element());
        let (w, a) = (near_one(x - self.point), near_one(self.axis));
        unit_or(w - a * (w.dot(a) / a.dot(a)), fallback)
    }
}

/// The filtered stage, run with hardware FMA where the CPU has it.
struct Filtered<'a, Q> {
    o: DVec3,
    d: DVec3,
    cylinder: &'a Cylinder,
    q: Q,
}

impl<Q: Question> FmaKernel for Filtered<'_, Q> {
    type Output = Option<Q::Answer>;

    /// Projected across the axis, `|u + t v|^2 = R^2` with `u = w x a`,
    /// `v = d x a`, `R^2 = r^2 |a|^2`: a sphere-like problem in the plane
    /// normal to the axis (scaled by `|a|`), its inputs in double-double.
    /// For an axis along coordinate `k`, `|(w + t d) x a|^2 = a_k^2 sum_{i
    /// != k} (w_i + t d_i)^2`, so the problem is the circle of radius `r`
    /// in the other two coordinates, with exact inputs as for the sphere.
    #[inline(always)]
    fn run(&self) -> Option<Q::Answer> {
        let (o, d, c) = (self.o, self.d, self.cylinder);
        let (ax, p) = (c.axis, c.point);
        let (wh, wl) = exact_difference(o, p);
        if let Some(k) = c.aligned {
            let drop = |mut v: DVec3| {
                v[k] = 0.0;
                v
            };
            return circle_of(drop(wh), drop(wl), drop(d), c.radius, self.q);
        }
        let (uh, ul, eu) = cross_dd(wh, wl, ax);
        let (vh, vl, ev) = cross_dd(d, DVec3::ZERO, ax);
        let (rh, rl, err) = c.scaled_rr;
        let (nu, nv) = (norm1(uh), norm1(vh));
        let a = nv * nv;
        if !(in_filter_range(a) && in_filter_range(nu * nv) && in_filter_range(rh * a)) {
            return None;
        }
        Circle::<true> {
            wh: uh,
            wl: ul,
            ew: eu,
            dh: vh,
            dl: vl,
            ed: ev,
            rh,
            rl,
            err,
        }
        .answer(self.q)
    }
}

/// `(wh + wl) x a` as a double-double `hi + lo` per component, with a bound
/// on its error: each component `w_j a_k - w_k a_j` takes its two high
/// products and their difference by error-free transformations (Higham
/// §4.3); the five low-order terms round in at most four additions and two
/// products, each below the sum of their magnitudes.
#[inline(always)]
fn cross_dd(wh: DVec3, wl: DVec3, a: DVec3) -> (DVec3, DVec3, DVec3) {
    let (mut hi, mut lo, mut err) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let DoubleDouble { hi: p1, lo: e1 } = DoubleDouble::product(wh[i], a[j]);
        let DoubleDouble { hi: p2, lo: e2 } = DoubleDouble::product(wh[j], a[i]);
        let DoubleDouble { hi: s, lo: es } = DoubleDouble::sum(p1, -p2);
        let (l1, l2) = (wl[i] * a[j], wl[j] * a[i]);
        let tail = es + (e1 - e2) + (l1 - l2);
        hi[k] = s;
        lo[k] = tail;
        err[k] = 6.0 * U * (es.abs() + e1.abs() + e2.abs() + l1.abs() + l2.abs()) + 4.0 * ETA;
    }
    (hi, lo, err)
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
    let w: [FixedInt<N1>; 3] =
        core::array::from_fn(|k| FixedInt::from_f64(o[k], lo).sub(&FixedInt::from_f64(p[k], lo)));
    let dw: [FixedInt<N1>; 3] = core::array::from_fn(|k| FixedInt::from_f64(d[k], ld));
    let aw: [FixedInt<N1>; 3] = core::array::from_fn(|k| FixedInt::from_f64(ax[k], la));
    let u: [FixedInt<N2>; 3] = cross3(&w, &aw);
    let v: [FixedInt<N2>; 3] = cross3(&dw, &aw);
    let (mut a, mut b, mut c, mut aa) = (
        FixedInt::<N4>::ZERO,
        FixedInt::<N4>::ZERO,
        FixedInt::<N4>::ZERO,
        FixedInt::<N2>::ZERO,
    );
    for k in 0..3 {
        a = a.add(&FixedInt::mul(&v[k], &v[k]));
        b = b.add(&FixedInt::mul(&u[k], &v[k]));
        c = c.add(&FixedInt::mul(&u[k], &u[k]));
        aa = aa.add(&FixedInt::mul(&aw[k], &aw[k]));
    }
    let rw = FixedInt::<N1>::from_f64(r, lo);
    let r2 = FixedInt::<N2>::mul(&rw, &rw);
    c = c.sub(&FixedInt::mul(&r2, &aa));
    exact_roots::<N4, N8>(
        (&a, 2 * (ld + la)),
        (&b, lo + ld + 2 * la),
        (&c, 2 * (lo + la)),
    )
}

impl LineQuadratic for Cylinder {
    const ROUNDED: bool = true;

    #[inline]
    fn filtered<Q: Question>(&self, o: DVec3, d: DVec3, q: Q) -> Option<Q::Answer> {
        with_fma(&Filtered {
            o,
            d,
            cylinder: self,
            q,
        })
    }

    fn exact(&self, o: DVec3, d: DVec3) -> Roots {
        exact(o, d, self.point, self.axis, self.radius)
    }

    /// The default tier's coefficients, from rounded inputs
    /// ([`rounded_circle`]). `w = o - p` rounds once per component (`|δw|_1
    /// <= u |w|_1`). Along a coordinate axis, the circle in the other two
    /// coordinates with the sphere's inputs. Otherwise `u = w x a` and `v =
    /// d x a`: each component two products and a difference (`gamma(2)`
    /// of `|w_i a_j| + |w_j a_i|`, summed over the components at most
    /// `|w|_1 |a|_1`), `u` also carrying `w`'s error (`u |w|_1 |a|_1`);
    /// `R^2 = r^2 |a|^2` from the pair computed when the cylinder was built.
    #[inline(always)]
    fn rounded(&self, o: DVec3, d: DVec3) -> Option<Coeffs> {
        let w = o - self.point;
        if let Some(k) = self.aligned {
            let drop = |mut v: DVec3| {
                v[k] = 0.0;
                v
            };
            return rounded_sphere(drop(w), drop(d), self.radius);
        }
        let a = self.axis;
        let na = norm1(a);
        let (u, v) = (w.cross(a), d.cross(a));
        let (rh, rl, err) = self.scaled_rr;
        rounded_circle(
            u,
            gamma(3) * norm1(w) * na,
            v,
            gamma(2) * norm1(d) * na,
            (rh, err + rl.abs()),
        )
    }
}

impl RayCast for Cylinder {
    /// The first hit in `range`; the normal points away from the axis. A
    /// line lying on the surface hits at the point of `range` nearest
    /// `t = 0`.
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        hit_at(self.cast_bounded(ray, range), ray, |point| {
            self.normal_at(point, -ray.direction())
        })
    }

    /// The default tier, as [`Sphere`](crate::shape::Sphere)'s: hit or
    /// miss exact, `t` from the stable formula with an a-priori bound.
    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        self.first_in(ray, range, Tier::Default)
    }
}

impl RayCast for Precise<Cylinder> {
    /// [`Cylinder`]'s cast, its `t` within 4 ulps of the correctly rounded
    /// root ([`Cylinder::line_roots`]' accuracy).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        hit_at(self.cast_bounded(ray, range), ray, |point| {
            self.0.normal_at(point, -ray.direction())
        })
    }

    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        self.0.first_in(ray, range, Tier::Precise)
    }
}

impl CappedCylinder {
    /// The first hit in `range`, with the side's roots from `tier`.
    fn cast_tier(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<Hit> {
        let side = &self.side;
        let a = side.axis;
        let mut best: Option<Hit> = None;
        let mut consider = |t: f64, et: f64, normal: &dyn Fn(DVec3) -> DVec3| {
            if range.admits(t) && best.is_none_or(|b| t < b.t) {
                let hit = Hit::at(ray, t, et, DVec3::ZERO);
                best = Some(Hit {
                    normal: normal(hit.point),
                    ..hit
                });
            }
        };
        let on_side = |t: f64| {
            // At the axis's scale (`rim.rs`), so that tiny axes' heights
            // do not underflow to zero.
            let (h, aa) = super::rim::heights(ray.at(t) - side.point, a);
            (0.0..=aa).contains(&h)
        };
        let side_normal = |x: DVec3| side.normal_at(x, -ray.direction());
        // The side's roots inside `range` (a line on the infinite side has
        // none).
        let side_roots = crossings(side, ray.origin(), ray.direction(), range, tier);
        for root in side_roots.into_iter().flatten() {
            if on_side(root.t) {
                consider(root.t, root.error, &side_normal);
            }
        }
        // The end disks: h(t) = (o - p) . a + t d . a equals 0 or |a|^2,
        // with the axis at its own scale (`rim.rs`) so that `|a|^2` stays
        // in range: `a . â` for `|a|^2`, `â` for the other `a`s.
        let ah = super::rim::unit_axis(a);
        let (h0, dh) = ((ray.origin() - side.point).dot(ah), ray.direction().dot(ah));
        if dh != 0.0 {
            let (e_h0, e_dh) = (
                dot_error(ray.origin() - side.point, ah),
                dot_error(ray.direction(), ah),
            );
            for (level, sign) in [(0.0, -1.0), (a.dot(ah), 1.0)] {
                let num = level - h0;
                let t = num / dh;
                // At the cylinder's scale (`rim.rs`): the fourth powers
                // neither underflow nor overflow.
                if super::rim::within_axis_radius(ray.at(t) - side.point, a, side.radius) {
                    // The end plane's level |a|^2 is `aa` within gamma(3) of
                    // it (gamma(4) of the computed `aa`), `h0` within its dot
                    // product's bound, and `num` rounds once more.
                    let e_num = e_h0 + gamma(4) * level + U * num.abs() * (1.0 + 2.0 * U);
                    consider(t, quotient_error(t, e_num, dh, e_dh), &|_| {
                        a.normalize() * sign
                    });
                }
            }
        }
        best
    }
}

impl RayCast for CappedCylinder {
    /// The first hit in `range` on the side (between the end planes) or on
    /// an end disk (normal `-axis` at the base, `+axis` at the top). The
    /// side's roots come from the default tier (the stable formula's root
    /// with its a-priori bound, [`Cylinder`]'s); whether a hit near the rim
    /// belongs to the side or a disk, and whether a ray grazing the rim
    /// hits, are decided in `f64` (within a few ulps of the rim).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.cast_tier(ray, range, Tier::Default)
    }
}

impl RayCast for Precise<CappedCylinder> {
    /// [`CappedCylinder`]'s cast with the side's roots within 4 ulps of
    /// the correctly rounded ones ([`Cylinder::line_roots`]).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.0.cast_tier(ray, range, Tier::Precise)
    }
}
