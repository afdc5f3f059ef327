//! The casts' first crossing, in either tier: the ordinary path at the
//! inputs' own magnitudes, the scaled line, the nappe and cap tests and
//! the base disk.

use super::ScaledLine;
use super::coefficients::{Heights, LINE_LIMIT, Line, dot};
use crate::arith::exponent::{pow2, scale_pow2};
use crate::arith::fma_dispatch::{FmaKernel, with_fma};
use crate::arith::roundoff::{U, gamma};
use crate::arith::std_or_libm::fma;
use crate::interval::Interval;
use crate::query::ray::point_error::dot_error;
use crate::query::ray::rim;
use crate::query::ray::{Hit, Ray};
use crate::roots::BoundedRoot;
// The cone's own default tier: its ordinary path works on the stable
// pair directly (`bounded.rs`'s pieces), before the driver's crossings.
use crate::roots::bounded::{Place, both_bounded, certified_negative, stable_pair};
use crate::roots::line_quadratic::{Tier, crossings, norm1, quotient_error};
use crate::shape::Cone;
use glam::DVec3;

/// Which surface of a cone a cast's first crossing lies on.
#[derive(Clone, Copy)]
enum Crossing {
    /// The lateral surface, at a bounded root.
    Lateral(BoundedRoot),
    /// The base disk, at `t = num / (d . a)`.
    Base { t: f64, num: f64 },
}

/// The default tier's lateral roots: both, bounded, in exact order
/// (`Some(None)`: no real root), computed with hardware FMA where the CPU
/// has it; `None` where the precise tier decides.
struct BoundedLateral<'a> {
    line: &'a ScaledLine,
}

impl FmaKernel for BoundedLateral<'_> {
    type Output = Option<Option<[BoundedRoot; 2]>>;

    #[inline(always)]
    fn run(&self) -> Self::Output {
        both_bounded(&self.line.line().filtered()?.0)
    }
}

impl Cone {
    /// Both lateral roots of the line in the default tier, bounded and in
    /// exact order, scaled back from the scaled line: `t` and its bound by
    /// the same power of two, exact unless the result is subnormal, where
    /// each loses at most `2^-1074` (`scale_pow2`), added to the bound.
    /// `None` where the precise tier decides.
    pub(super) fn bounded_line_roots(
        &self,
        o: DVec3,
        d: DVec3,
    ) -> Option<Option<[BoundedRoot; 2]>> {
        let line = self.scaled(o, d)?;
        let found = with_fma(&BoundedLateral { line: &line })?;
        Some(found.map(|roots| {
            roots.map(|BoundedRoot { t, error }| BoundedRoot {
                t: scale_pow2(t, line.back),
                error: scale_pow2(error, line.back) + f64::from_bits(2),
            })
        }))
    }

    /// The first lateral crossing in `range` on the cone's own nappe (below
    /// the cap for a capped cone): in the default tier, the first bounded
    /// root certified inside `range` where every root's place is decided;
    /// otherwise the precise tier's first root that `range` admits.
    fn lateral_first(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<BoundedRoot> {
        let a = self.axis;
        let on_cone = |t: f64| {
            // At the axis's scale (`rim.rs`).
            let (h, s) = rim::heights(ray.at(t) - self.apex, a);
            h >= 0.0 && (!self.capped || h <= s)
        };
        crossings(self, ray.origin(), ray.direction(), range, tier)
            .into_iter()
            .flatten()
            .find(|root| on_cone(root.t))
    }

    /// The first crossing in `range` on the cone's own nappe (below the cap
    /// for a capped cone) or on its base disk.
    fn first_crossing(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<Crossing> {
        let a = self.axis;
        let lateral = self.lateral_first(ray, range, tier);
        // The base plane's crossing with the axis at its own scale
        // (`rim.rs`): `a . â` for `|a|^2`.
        let ah = rim::unit_axis(a);
        let dh = ray.direction().dot(ah);
        let base = (self.capped && dh != 0.0)
            .then(|| a.dot(ah) - (ray.origin() - self.apex).dot(ah))
            .map(|num| (num / dh, num))
            .filter(|&(t, _)| {
                range.admits(t) && rim::within_axis_radius(ray.at(t) - self.apex, a, self.radius)
            });
        match (lateral, base) {
            (Some(root), Some((tb, num))) if tb < root.t => Some(Crossing::Base { t: tb, num }),
            (Some(root), _) => Some(Crossing::Lateral(root)),
            (None, Some((t, num))) => Some(Crossing::Base { t, num }),
            (None, None) => None,
        }
    }

    /// The first crossing in `range`, bounded, and whether it lies on the
    /// base disk: from the ordinary path where the inputs allow
    /// ([`Cone::ordinary`]) and it decides (in the precise tier only a
    /// certified miss), else at the cone's own scales.
    #[inline(always)]
    pub(super) fn first_bounded(
        &self,
        ray: &Ray,
        range: Interval,
        tier: Tier,
    ) -> Option<(BoundedRoot, bool)> {
        let ordinary = OrdinaryFirst {
            cone: self,
            ray,
            range,
            tier,
        };
        let tier = match (tier, with_fma(&ordinary)) {
            (_, Ordinary::Found(found)) => return found,
            // Undecided here, so at the scaled line too.
            (_, Ordinary::Undecided) => Tier::Precise,
            (tier, Ordinary::Beyond) => tier,
        };
        self.scaled_first(ray, range, tier)
    }

    /// [`Cone::first_bounded`] at the cone's own scales (`rim.rs` and
    /// [`Cone::scaled`]), for every tier and input.
    #[inline(never)]
    fn scaled_first(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<(BoundedRoot, bool)> {
        Some(match self.first_crossing(ray, range, tier)? {
            Crossing::Lateral(root) => (root, false),
            Crossing::Base { t, num } => {
                // The base plane's level |a|^2 (`a . â`) within gamma(4) of it,
                // the origin's height within its dot product's bound, and
                // `num` rounds once more.
                // All with the scaled axis `â` of `first_crossing`.
                let a = self.axis;
                let ah = rim::unit_axis(a);
                let e_h = dot_error(ray.origin() - self.apex, ah);
                let e_num = e_h + gamma(4) * a.dot(ah) + U * num.abs() * (1.0 + 2.0 * U);
                let dh = ray.direction().dot(ah);
                let error = quotient_error(t, e_num, dh, dot_error(ray.direction(), ah));
                (BoundedRoot { t, error }, true)
            }
        })
    }

    /// The ray and the cone as they are, without scaling, where the largest
    /// magnitude of each group, `w = o - apex` (rounded), `d`, `a`, and `r`
    /// itself, lies in `[2^-40, 2^40)`: below [`LINE_LIMIT`] the
    /// coefficients' bounds hold ([`Line`]); the lower end keeps their
    /// `ETA` slack far below the values it is added to (the filter would
    /// decline there) and `r^2` and `|a|^2` normal for the rim and cap
    /// tests. `w`'s rounding errs by at most `u |w_k|` per component.
    #[inline(always)]
    pub(super) fn ordinary(&self, ray: &Ray) -> Option<Line> {
        let w = ray.origin() - self.apex;
        let (d, a, r) = (ray.direction(), self.axis, self.radius);
        // `maxsd`, `minsd`: the inputs are finite and `w` at most infinite,
        // so the comparisons need no NaN handling.
        let max = |x: f64, y: f64| if x > y { x } else { y };
        let min = |x: f64, y: f64| if x < y { x } else { y };
        let largest = |v: DVec3| max(max(v.x.abs(), v.y.abs()), v.z.abs());
        let (mw, md, ma) = (largest(w), largest(d), largest(a));
        let high = max(max(mw, md), max(ma, r));
        let low = min(min(mw, md), min(ma, r));
        // False for an overflowed `w` too.
        let ordinary = high < LINE_LIMIT && low >= pow2(-40);
        ordinary.then(|| Line {
            w,
            ew1: U * norm1(w),
            d,
            a,
            r,
        })
    }

    /// The first hit in `range` from `tier`'s lateral roots.
    pub(super) fn cast_tier(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<Hit> {
        let (root, on_base) = self.first_bounded(ray, range, tier)?;
        let normal = if on_base {
            self.axis.normalize()
        } else {
            self.normal_at(ray.at(root.t), -ray.direction())
        };
        Some(Hit::at(ray, root.t, root.error, normal))
    }
}

/// The default tier's first crossing for a ray at ordinary magnitudes
/// ([`Cone::ordinary`]), computed with hardware FMA where the CPU has it.
struct OrdinaryFirst<'a> {
    cone: &'a Cone,
    ray: &'a Ray,
    range: Interval,
    /// In the precise tier, only a certified miss of the whole double
    /// cone is an answer: the line's roots carry this tier's bounds.
    tier: Tier,
}

/// What the ordinary path found.
enum Ordinary {
    /// The first crossing and whether it lies on the base disk, or none.
    Found(Option<(BoundedRoot, bool)>),
    /// A root's count or place the bounds cannot decide: the precise tier's.
    Undecided,
    /// Inputs beyond the ordinary magnitudes: the scaled line's.
    Beyond,
}

impl FmaKernel for OrdinaryFirst<'_> {
    type Output = Ordinary;

    #[inline(always)]
    fn run(&self) -> Ordinary {
        let Some(line) = self.cone.ordinary(self.ray) else {
            return Ordinary::Beyond;
        };
        match self.first(line) {
            Some(found) => Ordinary::Found(found),
            None => Ordinary::Undecided,
        }
    }
}

impl OrdinaryFirst<'_> {
    /// The lateral roots from the stable pair in exact order, the smaller
    /// first and the larger only where the smaller is not the answer;
    /// each root's place in `range` certified by its bound, its nappe and
    /// cap in `f64` ([`Heights::on_cone`]).
    ///
    /// The base disk is computed only where it can be the answer. A
    /// certified miss of the whole double cone misses the disk: the disk
    /// lies in the closed solid cone `P <= 0`, and a line through a point
    /// with `P <= 0` meets the surface (with `A > 0` the quadratic grows
    /// on both sides; with `A < 0` the line runs from one nappe to the
    /// other, crossing the apex's plane where `P >= 0`). A lateral root on
    /// the nappe where the ray enters the solid (`P` falling: the smaller
    /// root for `A > 0`, the larger for `A < 0`, whose sign is certified)
    /// is the first crossing: the solid is convex, so its line meets it in
    /// one segment, entered once; any base crossing is its exit, later.
    #[inline(always)]
    fn first(&self, line: Line) -> Option<Option<(BoundedRoot, bool)>> {
        let capped = self.cone.capped;
        let k = line.discriminant();
        if certified_negative(k.disc, k.e_disc) {
            return Some(None);
        }
        if self.tier == Tier::Precise {
            return None;
        }
        let (k, heights) = line.coeffs(&k)?;
        let Some(pair) = stable_pair(&k)? else {
            return Some(None);
        };
        let mut lateral = None;
        for larger in [false, true] {
            let root = if larger {
                pair.larger(&k)
            } else {
                pair.smaller(&k)
            };
            match root.place(self.range) {
                Place::Undecided => return None,
                Place::Above => break,
                Place::Below => {}
                Place::Inside => {
                    if heights.on_cone(root.t, capped) {
                        lateral = Some((root, (k.a > 0.0) != larger));
                        break;
                    }
                }
            }
        }
        if let Some((root, true)) = lateral {
            return Some(Some((root, false)));
        }
        let base = if capped {
            self.base(line, heights)
        } else {
            None
        };
        Some(match (lateral, base) {
            (Some((root, _)), Some(b)) if b.t < root.t => Some((b, true)),
            (Some((root, _)), _) => Some((root, false)),
            (None, b) => b.map(|b| (b, true)),
        })
    }

    /// The base disk's crossing `t = (|a|^2 - w . a) / (d . a)` where
    /// `range` admits it and the point lies within the radius of the
    /// axis, both in `f64` (`|x - a| <= r` at `x = w + t d`, on the base
    /// plane), with its bound: the level `s` within `gamma(4)` of `|a|^2`,
    /// `p` within its dot product's bound (`w` rounded once), the
    /// numerator rounding once more, and the quotient's error.
    #[inline(always)]
    fn base(&self, line: Line, h: Heights) -> Option<BoundedRoot> {
        let Line { w, d, a, r, .. } = line;
        let num = h.s - h.p;
        let t = num / h.q;
        // False for NaN (`q` zero) and beyond f64's range.
        if !self.range.admits(t) {
            return None;
        }
        let radial = DVec3::new(fma(t, d.x, w.x), fma(t, d.y, w.y), fma(t, d.z, w.z)) - a;
        // False for NaN (an overflowed point) too.
        let within = dot(radial, radial) <= r * r;
        if !within {
            return None;
        }
        let e_num = dot_error(w, a) + gamma(4) * h.s + U * num.abs() * (1.0 + 2.0 * U);
        let error = quotient_error(t, e_num, h.q, dot_error(d, a));
        Some(BoundedRoot { t, error })
    }
}
