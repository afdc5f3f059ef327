//! Ray against [`Cone`]: exact root count, accurate roots.

use super::point_error::dot_error;
use super::{Hit, Precise, RayCast, unit_or};
use crate::arith::error_free::{exact_difference, two_prod, two_sum};
use crate::arith::exponent::{Grain, pow2, scale_pow2, unit_scale};
use crate::arith::fixed_int::{DEG1, DEG2, DEG4, FixedInt, cross3, limbs_of_degree};
use crate::arith::fma_dispatch::{FmaKernel, with_fma};
use crate::arith::roundoff::{U, gamma};
use crate::arith::std_or_libm::fma;
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::roots::bounded::{
    Place, Tier, both_bounded, certified_negative, precise, quotient_error, stable_pair,
};
use crate::roots::certified::{
    AllRoots, Coeffs, ETA, Polynomial, Question, SMALL_SPAN, exact_roots, in_filter_range, norm1,
};
use crate::roots::radial::scaled_square;
use crate::roots::{BoundedRoot, Roots};
use crate::shape::Cone;
use glam::DVec3;

/// Limbs at the common grains: an input or a difference of two (below
/// `2^2100`), then degrees 2, 4, 6 and 12.
const W1: usize = DEG1;
const W2: usize = DEG2;
const W4: usize = DEG4;
const W6: usize = limbs_of_degree(6);
/// A product of two degree-6 values takes the limbs of both.
const W12: usize = 2 * W6;

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
    /// (`roots::certified`); where it cannot (near-tangent rays,
    /// rays through or near the apex, lines near a ruling's direction,
    /// inputs whose scaling is not exact), the exact stage decides the
    /// count from the coefficients as integers.
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        let (o, d) = (ray.origin(), ray.direction());
        let filtered = self.scaled(ray).and_then(|line| {
            let roots = with_fma(&Filtered { line: &line })?;
            let back = |tau: f64| scale_pow2(tau, line.back);
            Some(match roots {
                Roots::One(t) => Roots::One(back(t)),
                Roots::Two(t1, t2) => Roots::Two(back(t1), back(t2)),
                other => other,
            })
        });
        filtered.unwrap_or_else(|| exact(o, d, self.apex, self.axis, self.radius))
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
    fn scaled(&self, ray: &Ray) -> Option<ScaledLine> {
        let unit = |v: &[f64]| unit_scale(v).clamp(-1000, 1000);
        let (wh, wl) = exact_difference(ray.origin(), self.apex);
        let (d, a) = (ray.direction(), self.axis);
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

/// A ray and a cone with `w = o - apex = wh + wl` (exactly), `d` and the
/// pair `(a, r)` each scaled exactly by a power of two that brings its
/// largest magnitude into `[1/2, 1)`; `t = tau 2^back` for the scaled
/// polynomial's roots `tau`.
struct ScaledLine {
    wh: DVec3,
    wl: DVec3,
    d: DVec3,
    a: DVec3,
    r: f64,
    back: i32,
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

/// `|x_j y_k| + |x_k y_j|` per component: the magnitudes of `x x y`'s
/// terms.
#[inline(always)]
fn abs_cross(x: DVec3, y: DVec3) -> DVec3 {
    let (x, y) = (x.abs(), y.abs());
    DVec3::new(
        x.y * y.z + x.z * y.y,
        x.z * y.x + x.x * y.z,
        x.x * y.y + x.y * y.x,
    )
}

/// `x . y` with two FMAs: at most three roundings on any term's path, as
/// the plain sum of products has, in fewer instructions.
#[inline(always)]
fn dot(x: DVec3, y: DVec3) -> f64 {
    fma(x.z, y.z, fma(x.y, y.y, x.x * y.x))
}

/// `x x y` with one FMA per component: two roundings on each term's
/// path, as `x_j y_k - x_k y_j` has.
#[inline(always)]
fn cross(x: DVec3, y: DVec3) -> DVec3 {
    DVec3::new(
        fma(x.y, y.z, -(x.z * y.y)),
        fma(x.z, y.x, -(x.x * y.z)),
        fma(x.x, y.y, -(x.y * y.x)),
    )
}

/// What the coefficients are computed from: `w` within `ew1` of the exact
/// `o - apex` in the 1-norm, `d`, `a` and `r` exact, every component below
/// [`LINE_LIMIT`] in magnitude (the scaled line's below 1, an ordinary
/// ray's by [`Cone::ordinary`]).
#[derive(Clone, Copy, Debug)]
struct Line {
    w: DVec3,
    ew1: f64,
    d: DVec3,
    a: DVec3,
    r: f64,
}

/// The largest magnitude of a [`Line`]'s components: every coefficient,
/// the discriminant and their bounds are polynomials of degree at most 12
/// in them, so nothing overflows below it, and an operation that
/// underflows (losing at most `2^-1075`) is grown by the later factors of
/// its term by less than `2^480`: under `2^-590` each, which `ETA`
/// (`2^-500`) per quantity covers however many there are.
const LINE_LIMIT: f64 = pow2(40);

/// The rounded heights the nappe, cap and base tests reuse: `p = w . a`,
/// `q = d . a` and `s = |a|^2`; along the ray `(x - apex) . a = p + t q`.
#[derive(Clone, Copy, Debug)]
struct Heights {
    p: f64,
    q: f64,
    s: f64,
}

impl Heights {
    /// Whether the point at `t` lies on the cone's own nappe (`(x - apex)
    /// . a >= 0`) and, for a capped cone, below the cap (`<= |a|^2`), in
    /// `f64`: `p + t q` with one rounding, against the rounded `s`.
    #[inline(always)]
    fn on_cone(self, t: f64, capped: bool) -> bool {
        let h = fma(t, self.q, self.p);
        h >= 0.0 && (!capped || h <= self.s)
    }
}

/// The discriminant of a [`Line`] with its bound, and what the
/// coefficients share with it: computed first, since where it certifies a
/// miss of the whole double cone the coefficients are never needed.
#[derive(Clone, Copy, Debug)]
struct Discriminant {
    /// `s = |a|^2` and `r^2`, rounded.
    s: f64,
    rr: f64,
    /// `|w|_1` and `|d|_1`.
    nw: f64,
    nd: f64,
    disc: f64,
    e_disc: f64,
}

impl Line {
    /// The coefficients with their bounds, the discriminant first
    /// ([`Line::discriminant`], [`Line::coeffs`]).
    #[inline(always)]
    fn filtered(&self) -> Option<(Coeffs, Heights)> {
        self.coeffs(&self.discriminant())
    }

    /// The lateral quadratic's half-form coefficients `A t^2 + 2 B t + C`
    /// with error bounds, and the heights; `None` where the terms'
    /// magnitudes leave the filter's range.
    ///
    /// The cone's form is `P(x) = s |x x a|^2 - r^2 (x . a)^2 = x^T M x`
    /// with `M = s^2 I - (s + r^2) a a^T` (`|x x a|^2 = s |x|^2 - (x .
    /// a)^2`), so `A = s^2 |d|^2 - (s + r^2) q^2`, `B = s^2 (w . d) - (s +
    /// r^2) p q` and `C = s^2 |w|^2 - (s + r^2) p^2`.
    ///
    /// Bounds. Each coefficient, a polynomial in `w`, `d`, `a` and `r`, is
    /// computed with at most 13 roundings on any term's path (`s` 3, `s^2`
    /// 7, times `|d|^2` 11; `s + r^2` 4, times `q` 8 and `q` 12; the
    /// difference 13), so it is within `gamma(13)` of the same expression
    /// over the terms' magnitudes (Higham, *Accuracy and Stability*, §3.1):
    /// for `A` that is `s^2 |d|^2 + (s + r^2) (|d| . |a|)^2`, for `B` it is
    /// `s^2 (|w| . |d|) + (s + r^2) (|w| . |a|) (|d| . |a|)`, for `C` it is
    /// `s^2 |w|^2 + (s + r^2) (|w| . |a|)^2`. Those are computed with at
    /// most 13 roundings, so `gamma(28)` of the computed ones covers them
    /// (`gamma(13) / (1 - gamma(13)) <= gamma(26)`) and the bound's own two
    /// roundings. `w`'s error `δ` moves `B` by `s^2 (δ . d) - (s + r^2) (δ
    /// . a) q`, at most `K |δ| |d|` with `K = s (2 s + r^2)`
    /// (Cauchy–Schwarz), and `C` by `2 w^T M δ + δ^T M δ`, at most `K |δ|
    /// (2 |w| + |δ|)` (`|x^T M y| <= K |x| |y|`), taken with `1 +
    /// gamma(16)` for the roundings of `K` and of the bound; every
    /// component below [`LINE_LIMIT`], `ETA` per coefficient covers
    /// underflows.
    #[inline(always)]
    fn coeffs(&self, k: &Discriminant) -> Option<(Coeffs, Heights)> {
        let (w, d, a) = (self.w, self.d, self.a);
        let (s, rr) = (k.s, k.rr);
        let (dd, wd, ww) = (dot(d, d), dot(w, d), dot(w, w));
        let (p, q) = (dot(w, a), dot(d, a));
        let (ss, sr) = (s * s, s + rr);
        let (wm, dm, am) = (w.abs(), d.abs(), a.abs());
        let (pm, qm) = (dot(wm, am), dot(dm, am));
        let ma = ss * dd + sr * qm * qm;
        let mb = ss * dot(wm, dm) + sr * pm * qm;
        let mc = ss * ww + sr * pm * pm;
        if !(in_filter_range(ma) && in_filter_range(mc)) {
            return None;
        }
        let ew = self.ew1;
        let moved = s * (2.0 * s + rr) * ew * (1.0 + gamma(16));
        Some((
            Coeffs {
                a: ss * dd - sr * q * q,
                e_a: gamma(28) * ma + ETA,
                b: ss * wd - sr * p * q,
                e_b: gamma(28) * mb + moved * k.nd + ETA,
                c: ss * ww - sr * p * p,
                e_c: gamma(28) * mc + moved * (2.0 * k.nw + ew) + ETA,
                disc: k.disc,
                e_disc: k.e_disc,
            },
            Heights { p, q, s },
        ))
    }

    /// The discriminant `B^2 - A C` of [`Line::coeffs`] in the form that
    /// does not cancel for far origins, from the line's moment `n = w x d`
    /// about the apex.
    ///
    /// Expanding, `B^2 - A C = -s^4 |n|^2 + s^2 (s + r^2) |p d - q w|^2`
    /// with `p d - q w = -a x n` and `|a x n|^2 = s |n|^2 - (a . n)^2`:
    /// `B^2 - A C = s^2 (s r^2 |n|^2 - (s + r^2) (a . n)^2)`. A far origin
    /// makes `B^2` and `A C` huge and nearly equal; `|n|` is `|d|` times
    /// the line's distance from the apex, of the size of the cone.
    ///
    /// The bound, with `inner(n) = n^T N n`, `N = s r^2 I - (s + r^2) a
    /// a^T` (eigenvalues `s r^2` across `a` and `-s^2` along it):
    ///
    /// - the computed `n` is off the exact moment by `Δ`, at most `E = ew1
    ///   |d|_1 + gamma(3) |w|_1 |d|_1` in the 1-norm (`w`'s error, and two
    ///   roundings per component of the cross product; `2 ETA` for its
    ///   products that underflow), which moves `inner` by `2 n^T N Δ +
    ///   Δ^T N Δ`: at most `2 (s r^2 |n|_1 + (s + r^2) |a . n| |a|_1) E +
    ///   s (s + r^2) E^2` (`|x . Δ| <= |x|_1 E`), with `|a . n| <= |a| .
    ///   |n|`;
    /// - from the computed `n`, `a` and `r`, the discriminant takes at most
    ///   21 roundings on any term's path (`|n|^2` 3, `s r^2` 5, their
    ///   product 9; `(a . n)^2` 7, `s + r^2` 4, their product 12; the
    ///   difference 13; `s^2` 7 and the product 21), so it is within
    ///   `gamma(21)` of `s^2 (s r^2 |n|^2 + (s + r^2) (|a| . |n|)^2)`
    ///   (Higham §3.1).
    ///
    /// Every factor is a sum or product of nonnegative computed values,
    /// at most 30 roundings below the exact one on any path, bound's own
    /// operations included: `1 + gamma(32)` covers them. Every component
    /// below [`LINE_LIMIT`], `ETA` covers the underflows.
    #[inline(always)]
    fn discriminant(&self) -> Discriminant {
        let (w, d, a) = (self.w, self.d, self.a);
        let (s, rr) = (dot(a, a), self.r * self.r);
        let (nw, nd) = (norm1(w), norm1(d));
        let n = cross(w, d);
        let e_n = self.ew1 * nd + gamma(3) * nw * nd + 2.0 * ETA;
        let (nn, n2, g) = (norm1(n), dot(n, n), dot(a, n));
        let (ss, sr, srr) = (s * s, s + rr, s * rr);
        let gm = dot(a.abs(), n.abs());
        let disc = ss * (srr * n2 - sr * (g * g));
        let moved = 2.0 * (srr * nn + sr * gm * norm1(a)) * e_n + s * sr * e_n * e_n;
        let rounded = gamma(21) * (srr * n2 + sr * gm * gm);
        let e_disc = (rounded + moved) * ss * (1.0 + gamma(32)) + ETA;
        Discriminant {
            s,
            rr,
            nw,
            nd,
            disc,
            e_disc,
        }
    }
}

/// The cone's exact polynomial along the scaled line, `P(x) = s |x x a|^2
/// - r^2 (x . a)^2 = s^2 |x|^2 - (s + r^2) (x . a)^2` at `x = w + tau d`
/// (`s = |a|^2`; `|x x a|^2 = s |x|^2 - (x . a)^2`).
struct Lateral {
    wh: DVec3,
    wl: DVec3,
    d: DVec3,
    a: DVec3,
    /// `s` and `r^2`, rounded: the working-precision evaluation's.
    s: f64,
    rr: f64,
    /// `s^2` and `s + r^2` as double-doubles: the double-double one's.
    ss: Near,
    sr: Near,
}

/// An unevaluated double-double `hi + lo`.
#[derive(Clone, Copy, Debug)]
struct Pair {
    hi: f64,
    lo: f64,
}

impl Pair {
    /// The square: `hi^2` exactly as a pair (TwoProduct; Higham, *Accuracy
    /// and Stability*, 2nd ed., §4.3), its low part with `2 hi lo` in one
    /// FMA; `lo^2` dropped. Not normalized.
    #[inline(always)]
    fn square(self) -> Pair {
        let (q, ql) = two_prod(self.hi, self.hi);
        Pair {
            hi: q,
            lo: fma(2.0 * self.hi, self.lo, ql),
        }
    }

    /// The product: `hi hi'` exactly as a pair, the cross terms added to
    /// its low part by two FMAs; `lo lo'` dropped. Not normalized.
    #[inline(always)]
    fn times(self, x: Pair) -> Pair {
        let (p, pl) = two_prod(self.hi, x.hi);
        Pair {
            hi: p,
            lo: fma(self.hi, x.lo, fma(self.lo, x.hi, pl)),
        }
    }

    /// The sum of three: the high parts exactly (TwoSum), the five
    /// low-order terms in a tree of depth three.
    #[inline(always)]
    fn sum3([x, y, z]: [Pair; 3]) -> Pair {
        let (s1, g1) = two_sum(x.hi, y.hi);
        let (hi, g2) = two_sum(s1, z.hi);
        Pair {
            hi,
            lo: (x.lo + y.lo) + (z.lo + (g1 + g2)),
        }
    }

    /// `self - x` rounded to one `f64`: the high parts exactly (TwoSum),
    /// the low-order terms with two roundings, the result once more.
    #[inline(always)]
    fn minus(self, x: Pair) -> f64 {
        let (f, fe) = two_sum(self.hi, -x.hi);
        f + ((self.lo - x.lo) + fe)
    }

    /// `|hi| + |lo|`.
    #[inline(always)]
    fn magnitude(self) -> f64 {
        self.hi.abs() + self.lo.abs()
    }
}

/// A double-double within `err` of the exact value it stands for: the
/// per-line constants `s^2` and `s + r^2` of [`Lateral::eval_precise`].
#[derive(Clone, Copy, Debug)]
struct Near {
    value: Pair,
    err: f64,
}

impl Near {
    /// The square ([`Pair::square`]) with its bound: the low part's one
    /// rounding (`u` of it), the dropped `lo^2`, and the error `δ` carried
    /// through `(v + δ)^2 - v^2 = δ (2 v + δ)`.
    #[inline(always)]
    fn square(self) -> Near {
        let (v, e) = (self.value, self.err);
        let sq = v.square();
        Near {
            value: sq,
            err: U * sq.lo.abs() + v.lo * v.lo + e * (2.0 * v.magnitude() + e),
        }
    }
}

impl Lateral {
    /// The polynomial's inputs, with `s^2` and `s + r^2` as double-doubles:
    /// `s` from `scaled_square` (within its returned bound), `r^2` exactly
    /// as a pair (TwoProduct) unless it underflows.
    #[inline(always)]
    fn of(line: &ScaledLine) -> Lateral {
        let (sh, sl, e_s) = scaled_square(1.0, line.a);
        let s = Near {
            value: Pair { hi: sh, lo: sl },
            err: e_s,
        };
        let (rh, rl) = two_prod(line.r, line.r);
        let (v, vl) = two_sum(sh, rh);
        let sr = Near {
            value: Pair {
                hi: v,
                lo: vl + (sl + rl),
            },
            // The low part's two roundings, and the inputs' errors: `r^2`
            // is off by at most `2^-1074` where it underflows.
            err: gamma(2) * (vl.abs() + sl.abs() + rl.abs()) + e_s + ETA,
        };
        Lateral {
            wh: line.wh,
            wl: line.wl,
            d: line.d,
            a: line.a,
            s: line.a.dot(line.a),
            rr: line.r * line.r,
            ss: s.square(),
            sr,
        }
    }

    /// `x = w + tau d` per component as a double-double `xh + xl` (`|xl|
    /// <= u |xh|`) and a bound on its distance from the exact point: `tau
    /// d_i` and its sum with `wh_i` exactly (TwoProduct, TwoSum), the two
    /// low-order terms and `wl_i` summed with two roundings, each within
    /// `u` of its result, and the pair renormalized exactly (TwoSum: for a
    /// far origin the low-order terms, of the size of `u |w|`, dwarf `u
    /// |x|`). A TwoProduct error that underflows is off by at most
    /// `2^-1075` (`ETA`).
    #[inline(always)]
    fn point(&self, t: f64) -> ([Pair; 3], DVec3) {
        let component = |i: usize| {
            let (ph, pl) = two_prod(t, self.d[i]);
            let (sh, sl) = two_sum(self.wh[i], ph);
            let tail = sl + pl;
            let lo = tail + self.wl[i];
            let (hi, lo) = two_sum(sh, lo);
            (Pair { hi, lo }, U * (tail.abs() + lo.abs()) + ETA)
        };
        // Not `array::from_fn`, whose closure may escape the FMA kernel.
        let (x, y, z) = (component(0), component(1), component(2));
        ([x.0, y.0, z.0], DVec3::new(x.1, y.1, z.1))
    }
}

/// Beyond this magnitude of the point the evaluations decline (an infinite
/// bound): below it, no product they form overflows, and an absolute error
/// of `2^-1075` from an underflow grows through their later factors (at
/// most `|x|` and three below 3) to less than `2^-760`.
const POINT_LIMIT: f64 = pow2(300);

impl Polynomial for Lateral {
    /// The working-precision bound is relative to the point's own
    /// magnitude, which for far origins (where `|tau d|` dwarfs `|x|`)
    /// certifies most roots; near the cone it rarely does.
    const TRY_FAST: bool = true;

    /// `P(x)` in the cross form at the computed `x`, with a rigorous bound
    /// on its distance from `P` at the exact `w + tau d`.
    ///
    /// `x_i = fl(fl(fma(tau, d_i, wh_i)) + wl_i)` rounds twice, so it is
    /// within `ex_i = u (|f_i| + |x_i|)` (and `2^-1075` for an underflow)
    /// of the exact point. `P` is a quadratic form in `x`, `P(x) = x^T M x`
    /// with `M = s^2 I - (s + r^2) a a^T`, so with `x` off by `δ`, `P(x +
    /// δ) - P(x) = ∇P(x) . δ + P(δ)`, with `∇P = 2 (s^2 x - (s + r^2) h a)`
    /// (`h = x . a`) bounded by the magnitudes, and `|P(δ)| <= s (s + r^2)
    /// |δ|^2` (`M`'s eigenvalues are `s^2` and `-s r^2`). `P` at the
    /// computed `x` takes at most 10 roundings on any term's path (`x x a`
    /// 2, its square and sum 5, `s` 3 and the product 9; `h` 3, `r^2` 1,
    /// `r^2 h` 5, times `h` 9; the difference 10): `gamma(10)` of its
    /// terms' magnitudes (Higham §3.1). The bound's own roundings (sums and
    /// products of nonnegative values, at most 10 on a path) take `1 +
    /// gamma(10)`. Below [`POINT_LIMIT`], an underflow inside `x`, `y` or
    /// `h` loses less than `2^-760` from any term (`16 ETA`); `s` and `r^2`
    /// that underflow (at most `2^-1074` off each) are scaled by `|y|^2`
    /// and `h^2`, which may be as large as `2^602`: `ETA` times those.
    #[inline(always)]
    fn eval_fast(&self, t: f64) -> (f64, f64) {
        let (a, s, rr) = (self.a, self.s, self.rr);
        let f = DVec3::new(
            fma(t, self.d.x, self.wh.x),
            fma(t, self.d.y, self.wh.y),
            fma(t, self.d.z, self.wh.z),
        );
        let x = f + self.wl;
        let xm = x.abs();
        if !xm.cmplt(DVec3::splat(POINT_LIMIT)).all() {
            return (0.0, f64::INFINITY);
        }
        let ex = (f.abs() + xm) * U + DVec3::splat(2.0 * ETA);
        let (y, h) = (x.cross(a), x.dot(a));
        let value = s * y.dot(y) - rr * h * h;
        let (am, ym, hm) = (a.abs(), abs_cross(x, a), xm.dot(a.abs()));
        let terms = s * ym.dot(ym) + rr * hm * hm;
        let grad = (xm * (s * s) + am * ((s + rr) * hm)) * 2.0;
        let propagated = grad.dot(ex) + s * (s + rr) * ex.dot(ex);
        let underflow = ETA * (ym.dot(ym) + hm * hm) + 16.0 * ETA;
        let e = (gamma(10) * terms + propagated) * (1.0 + gamma(10)) + underflow;
        (value, e)
    }

    /// `P(x) = s^2 |x|^2 - (s + r^2) h^2` in double-double at `x = w + tau
    /// d` ([`Lateral::point`]), `h = x . a`, with a rigorous bound.
    ///
    /// With `y = xh + xl` (`|xl_i| <= u |xh_i|`), `Q = sum_i fl(xh_i^2)`,
    /// `F = sum_i |fl(xh_i a_i)|` and the constants `S = s^2` and `R = s +
    /// r^2` as pairs within `e_S` and `e_R` (to first order throughout, the
    /// `1 + O(u)` factors kept in the constants' rounding up):
    ///
    /// - `|y|^2`: each `xh_i^2` exact as a pair, its low part `2 xh_i xl_i +
    ///   ql_i` below `3 u q_i` rounded once, `xl_i^2 <= u^2 q_i` dropped, the
    ///   pairs summed ([`Pair::sum3`]: TwoSum errors below `u Q`, five
    ///   low terms below `5 u Q` through three roundings): within `20 u^2
    ///   Q`, its low part below `5.1 u Q`;
    /// - `h = y . a`: each `xh_i a_i` exact as a pair, its low part below
    ///   `2 u |f_i|` rounded once, the sum's low terms below `4 u F`
    ///   through three roundings: within `15 u^2 F`, its low part below
    ///   `4.1 u F`; `h^2`: the low part below `9.4 u F^2` rounded once,
    ///   `Hl^2 <= 17 u^2 F^2` dropped, `h`'s error through `2 |h| δ + δ^2`:
    ///   within `57 u^2 F^2`;
    /// - the products with `S` and `R` ([`Pair::times`]): the low terms'
    ///   two roundings, the dropped `lo lo'`, and the errors through `(v +
    ///   δ)(x + ε) - v x`; the difference's two roundings of its low terms:
    ///   in all within `128 u^2 (S Q + R F^2) + 16 u (|S.lo| Q + |R.lo|
    ///   F^2) + 1.04 (e_S Q + e_R F^2)` (`S` and `R` as `|hi| + |lo|`),
    ///   and the result's rounding `u |P|`.
    ///
    /// The point's error `ε` (`|ε_i| <= ex_i`) moves the quadratic form `P =
    /// y^T M y`, `M = s^2 I - (s + r^2) a a^T`, by `2 y^T M ε + ε^T M ε`,
    /// at most `2 (S sum |xh_i| ex_i + R F sum |a_i| ex_i) (1 + 4 u)` plus
    /// `s (s + r^2) |ex|_1^2` (`M`'s eigenvalues `s^2` and `-s r^2`; `s (s +
    /// r^2)` from the rounded `s` and `r^2` with `1 + gamma(8)`). The bound's own
    /// roundings (sums and products of nonnegative values, at most 12 on a
    /// path) take `1 + gamma(12)`. Below [`POINT_LIMIT`], every factor
    /// later than a product that underflows is below 10: `4 ETA` covers
    /// those.
    #[inline(always)]
    fn eval_precise(&self, t: f64) -> (f64, f64) {
        let (x, ex) = self.point(t);
        if !(x.iter().all(|c| c.hi.abs() < POINT_LIMIT)) {
            return (0.0, f64::INFINITY);
        }
        let (ss, sr) = (self.ss, self.sr);
        let xx = Pair::sum3([x[0].square(), x[1].square(), x[2].square()]);
        let times_a = |i: usize| {
            let (p, pl) = two_prod(x[i].hi, self.a[i]);
            Pair {
                hi: p,
                lo: fma(x[i].lo, self.a[i], pl),
            }
        };
        let f = [times_a(0), times_a(1), times_a(2)];
        let h = Pair::sum3(f);
        let value = ss.value.times(xx).minus(sr.value.times(h.square()));
        let q = x[0].hi * x[0].hi + x[1].hi * x[1].hi + x[2].hi * x[2].hi;
        let fm = f[0].hi.abs() + f[1].hi.abs() + f[2].hi.abs();
        let (sm, rm) = (ss.value.magnitude(), sr.value.magnitude());
        let (qf, ff) = (q, fm * fm);
        let rounding = 128.0 * U * U * (sm * qf + rm * ff)
            + 16.0 * U * (ss.value.lo.abs() * qf + sr.value.lo.abs() * ff)
            + 1.04 * (ss.err * qf + sr.err * ff)
            + U * value.abs();
        let xm = DVec3::new(x[0].hi.abs(), x[1].hi.abs(), x[2].hi.abs());
        let along = (sm + ss.err) * xm.dot(ex) + (rm + sr.err) * fm * self.a.abs().dot(ex);
        let e1 = ex.x + ex.y + ex.z;
        let moved = 2.0 * along * (1.0 + 4.0 * U)
            + self.s * (self.s + self.rr) * e1 * e1 * (1.0 + gamma(8));
        (value, (rounding + moved) * (1.0 + gamma(12)) + 4.0 * ETA)
    }
}

/// The exact stage at three grains (`o, apex`: `lo`; `d`: `ld`; `a, r`:
/// `la`), under which the equation keeps its roots: `A = s |v|^2 - r^2
/// q^2` at `2 ld + 4 la`, `B = s (u . v) - r^2 p q` at `lo + ld + 4 la`,
/// `C = s |u|^2 - r^2 p^2` at `2 lo + 4 la` (`s = |a|^2`, `u = w x a`,
/// `v = d x a`, `p = w . a`, `q = d . a`). Small integers when every span
/// allows: inputs below `2^126` make `C` below `2^765` (13 limbs) and the
/// discriminant below `2^1529` (26 limbs).
fn exact(o: DVec3, d: DVec3, apex: DVec3, a: DVec3, r: f64) -> Roots {
    let g = Grain::of(&[o.x, o.y, o.z, apex.x, apex.y, apex.z]);
    let (gd, ga) = (Grain::of(&d.to_array()), Grain::of(&[a.x, a.y, a.z, r]));
    let lo = if g.all_zero() { 0 } else { g.lo_min };
    let grains = (lo, gd.lo_min, ga.lo_min);
    if g.span().max(gd.span()).max(ga.span()) <= SMALL_SPAN {
        exact_in::<2, 5, 9, 13, 26>([o, apex, d, a], r, grains)
    } else {
        exact_in::<W1, W2, W4, W6, W12>([o, apex, d, a], r, grains)
    }
}

fn exact_in<
    const N1: usize,
    const N2: usize,
    const N4: usize,
    const N6: usize,
    const N12: usize,
>(
    [o, apex, d, a]: [DVec3; 4],
    r: f64,
    (lo, ld, la): (i32, i32, i32),
) -> Roots {
    let int = |v: DVec3, g: i32| -> [FixedInt<N1>; 3] {
        core::array::from_fn(|k| FixedInt::from_f64(v[k], g))
    };
    let (ow, pw) = (int(o, lo), int(apex, lo));
    let w: [FixedInt<N1>; 3] = core::array::from_fn(|k| ow[k].sub(&pw[k]));
    let (dw, aw) = (int(d, ld), int(a, la));
    let rw = FixedInt::<N1>::from_f64(r, la);
    let dot = |x: &[FixedInt<N1>; 3], y: &[FixedInt<N1>; 3]| -> FixedInt<N2> {
        (0..3).fold(FixedInt::ZERO, |acc, k| {
            acc.add(&FixedInt::mul(&x[k], &y[k]))
        })
    };
    let dot2 = |x: &[FixedInt<N2>; 3], y: &[FixedInt<N2>; 3]| -> FixedInt<N4> {
        (0..3).fold(FixedInt::ZERO, |acc, k| {
            acc.add(&FixedInt::mul(&x[k], &y[k]))
        })
    };
    let (u, v) = (cross3::<N1, N2>(&w, &aw), cross3::<N1, N2>(&dw, &aw));
    let (s, rr) = (dot(&aw, &aw), FixedInt::<N2>::mul(&rw, &rw));
    let (p, q) = (dot(&w, &aw), dot(&dw, &aw));
    let coefficient = |x: FixedInt<N4>, m: &FixedInt<N2>, n: &FixedInt<N2>| -> FixedInt<N6> {
        let mn = FixedInt::<N4>::mul(m, n);
        FixedInt::<N6>::mul(&s, &x).sub(&FixedInt::mul(&rr, &mn))
    };
    let qa = coefficient(dot2(&v, &v), &q, &q);
    let qb = coefficient(dot2(&u, &v), &p, &q);
    let qc = coefficient(dot2(&u, &u), &p, &p);
    exact_roots::<N6, N12>(
        (&qa, 2 * ld + 4 * la),
        (&qb, lo + ld + 4 * la),
        (&qc, 2 * lo + 4 * la),
    )
}

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
    fn bounded_line_roots(&self, ray: &Ray) -> Option<Option<[BoundedRoot; 2]>> {
        let line = self.scaled(ray)?;
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
            let (h, s) = super::rim::heights(ray.at(t) - self.apex, a);
            h >= 0.0 && (!self.capped || h <= s)
        };
        if tier == Tier::Default
            && let Some(found) = self.bounded_line_roots(ray)
        {
            let roots = found?;
            let places = roots.map(|root| root.place(range));
            if !places.contains(&Place::Undecided) {
                return (0..2)
                    .find(|&i| places[i] == Place::Inside && on_cone(roots[i].t))
                    .map(|i| roots[i]);
            }
        }
        let lateral = |t: f64| range.admits(t) && on_cone(t);
        match self.line_roots(ray) {
            Roots::One(t) => lateral(t).then(|| precise(t)),
            Roots::Two(t1, t2) => [t1, t2].into_iter().find(|&t| lateral(t)).map(precise),
            Roots::None | Roots::All => None,
        }
    }

    /// The first crossing in `range` on the cone's own nappe (below the cap
    /// for a capped cone) or on its base disk.
    fn first_crossing(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<Crossing> {
        let a = self.axis;
        let lateral = self.lateral_first(ray, range, tier);
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
    fn first_bounded(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<(BoundedRoot, bool)> {
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
                let ah = super::rim::unit_axis(a);
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
    fn ordinary(&self, ray: &Ray) -> Option<Line> {
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
    fn cast_tier(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<Hit> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{ConeRayClass, SplitMix64, cone_ray_case, step_ulps};
    use exactray_oracle::line_oracle::{Dyadic, Quadratic};
    use std::vec::Vec;

    /// The scaled line of a cone and a ray, and its exact polynomial in
    /// `tau` (`w = wh + wl` as `wh - (-wl)`).
    fn scaled_case(o: DVec3, d: DVec3, apex: DVec3, a: DVec3, r: f64) -> (ScaledLine, Quadratic) {
        let cone = Cone::infinite(apex, a, r).unwrap();
        let line = cone.scaled(&Ray::new(o, d).unwrap()).unwrap();
        let exact = Quadratic::cone(
            line.wh.to_array(),
            line.d.to_array(),
            (-line.wl).to_array(),
            line.a.to_array(),
            line.r,
        );
        (line, exact)
    }

    /// Whether `|P(tau) - value| <= e`, decided exactly.
    fn holds(exact: &Quadratic, tau: f64, (value, e): (f64, f64)) -> bool {
        if e == f64::INFINITY {
            return true;
        }
        let t = Dyadic::from_f64(tau);
        let p = exact.a.mul(&t).add(&exact.b).mul(&t).add(&exact.c);
        let diff = p.sub(&Dyadic::from_f64(value));
        let e = Dyadic::from_f64(e);
        diff.sub(&e).sign() <= 0 && diff.add(&e).sign() >= 0
    }

    /// Whether `|exact - value| <= e`, decided exactly.
    fn within(exact: &Dyadic, value: f64, e: f64) -> bool {
        let diff = exact.sub(&Dyadic::from_f64(value));
        let e = Dyadic::from_f64(e);
        diff.sub(&e).sign() <= 0 && diff.add(&e).sign() >= 0
    }

    /// The coefficients' and the discriminant's bounds hold against the
    /// exact ones (`Quadratic::cone`'s `a t^2 + b t + c` is `A t^2 + 2 B t +
    /// C`), on ordinary lines (`w` rounded once) and scaled ones (`w` as
    /// its high part): the report's rays, grazing ones (the exact
    /// discriminant near zero), rays along the axis and across it, and
    /// components far below the largest (products that underflow).
    #[test]
    fn coefficient_bounds_hold() {
        let mut rng = SplitMix64::new(9);
        for case in 0..3000 {
            let c = cone_ray_case(ConeRayClass::ALL[case % 2], &mut rng);
            let (mut o, mut d) = (DVec3::from(c.origin), DVec3::from(c.direction));
            let (apex, a, r) = (c.apex(), c.axis(), c.radius);
            match case % 6 {
                // Along the axis, and across it through the apex.
                1 => d = a * (1.0 + rng.next_f64()),
                2 => o = apex + a.any_orthogonal_vector() * 3.0,
                // Through a point of the rim: tangent or nearly so.
                3 => d = apex + a + a.any_orthogonal_vector().normalize() * r - o,
                4 => d.y = 1e-300,
                _ => {}
            }
            let cone = Cone::new(apex, a, r).unwrap();
            let ray = Ray::new(o, d).unwrap();
            let exact = Quadratic::cone(o.into(), d.into(), apex.into(), a.into(), r);
            let scaled = cone.scaled(&ray).unwrap();
            let (_, from_scaled) = scaled_case(o, d, apex, a, r);
            let lines = [
                (cone.ordinary(&ray), &exact),
                (Some(scaled.line()), &from_scaled),
            ];
            for (line, q) in lines {
                let Some((k, _)) = line.and_then(|l| l.filtered()) else {
                    continue;
                };
                let half_b = q.b.half();
                let disc = half_b.mul(&half_b).sub(&q.a.mul(&q.c));
                assert!(within(&q.a, k.a, k.e_a), "A {case}: {k:?}");
                assert!(within(&half_b, k.b, k.e_b), "B {case}: {k:?}");
                assert!(within(&q.c, k.c, k.e_c), "C {case}: {k:?}");
                assert!(within(&disc, k.disc, k.e_disc), "D {case}: {k:?}");
            }
        }
    }

    /// Both evaluations' bounds hold at the exact roots' roundings and a
    /// few ulps off them, and at points along the line, for the report's
    /// rays, the same at scales `2^±600` per group, and needle-thin and
    /// flat cones; at the roots the double-double bound is `O(u^2)` of
    /// the terms (it certifies roots the working-precision one cannot,
    /// whose bound is `O(u)` of them).
    #[test]
    fn evaluations_bound_their_errors() {
        let mut rng = SplitMix64::new(5);
        let mut tight = 0;
        let mut roots = 0;
        for case in 0..600 {
            let c = cone_ray_case(ConeRayClass::ALL[case % 2], &mut rng);
            let (so, sd, sa) = match case % 5 {
                0 | 1 => (0, 0, 0),
                2 => (600, -600, 300),
                3 => (-600, 300, -300),
                _ => (0, 0, 0),
            };
            let thin = match case % 7 {
                0 => 1e-200,
                1 => 1e100,
                _ => 1.0,
            };
            let at = |v: DVec3, k: i32| v * 2f64.powi(k);
            let (line, exact) = scaled_case(
                at(DVec3::from(c.origin), so),
                at(DVec3::from(c.direction), sd),
                at(c.apex(), so),
                at(c.axis(), sa),
                c.radius * thin * 2f64.powi(sa),
            );
            let lateral = Lateral::of(&line);
            let answer = exact.answer();
            let mut taus: Vec<f64> = (0..3).map(|_| rng.next_f64() * 8.0 - 4.0).collect();
            for &root in &answer.roots {
                for k in [-3, 0, 2] {
                    taus.push(step_ulps(root, k));
                }
            }
            for &tau in &taus {
                let fast = lateral.eval_fast(tau);
                let precise = lateral.eval_precise(tau);
                assert!(holds(&exact, tau, fast), "fast {case} {tau}: {fast:?}");
                assert!(holds(&exact, tau, precise), "dd {case} {tau}: {precise:?}");
            }
            if thin == 1.0 && (so, sd, sa) == (0, 0, 0) {
                for &root in &answer.roots {
                    let (x, _) = lateral.point(root);
                    let xx: f64 = x.iter().map(|c| c.hi * c.hi).sum();
                    let scale = lateral.ss.value.hi * xx;
                    roots += 1;
                    // `O(u^2)` of the terms, times `|w| / |x|` (up to `2^27`
                    // for far origins) from the point's own error.
                    let limit = if case % 2 == 0 { pow2(-95) } else { pow2(-70) };
                    tight += usize::from(lateral.eval_precise(root).1 <= scale * limit);
                }
            }
        }
        assert!(tight == roots && roots > 100, "{tight} of {roots}");
    }
}
