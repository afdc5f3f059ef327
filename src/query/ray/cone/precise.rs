//! The cone's polynomial along the scaled line, evaluated in working
//! precision and in double-double, each with a rigorous bound: what
//! certifies the filtered stage's roots.

use super::ScaledLine;
use super::coefficients::abs_cross;
use crate::arith::double_double::{Approximate, DoubleDouble};
use crate::arith::exponent::pow2;
use crate::arith::roundoff::{U, gamma};
use crate::arith::std_or_libm::fma;
use crate::roots::line_quadratic::{ETA, Polynomial};
use crate::roots::radial::scaled_square;
use glam::DVec3;

/// The cone's exact polynomial along the scaled line, `P(x) = s |x x a|^2
/// - r^2 (x . a)^2 = s^2 |x|^2 - (s + r^2) (x . a)^2` at `x = w + tau d`
/// (`s = |a|^2`; `|x x a|^2 = s |x|^2 - (x . a)^2`).
pub(super) struct Lateral {
    pub(super) wh: DVec3,
    pub(super) wl: DVec3,
    pub(super) d: DVec3,
    pub(super) a: DVec3,
    /// `s` and `r^2`, rounded: the working-precision evaluation's.
    pub(super) s: f64,
    pub(super) rr: f64,
    /// `s^2` and `s + r^2` as double-doubles: the double-double one's.
    pub(super) ss: Approximate,
    pub(super) sr: Approximate,
}

impl Lateral {
    /// The polynomial's inputs, with `s^2` and `s + r^2` as double-doubles:
    /// `s` from `scaled_square` (within its returned bound), `r^2` exactly
    /// as a pair (TwoProduct) unless it underflows.
    #[inline(always)]
    pub(super) fn of(line: &ScaledLine) -> Lateral {
        let (sh, sl, e_s) = scaled_square(1.0, line.a);
        let s = Approximate {
            value: DoubleDouble { hi: sh, lo: sl },
            err: e_s,
        };
        let r2 = DoubleDouble::product(line.r, line.r);
        let v = DoubleDouble::sum(sh, r2.hi);
        let sr = Approximate {
            value: DoubleDouble {
                hi: v.hi,
                lo: v.lo + (sl + r2.lo),
            },
            // The low part's two roundings, and the inputs' errors: `r^2`
            // is off by at most `2^-1074` where it underflows.
            err: gamma(2) * (v.lo.abs() + sl.abs() + r2.lo.abs()) + e_s + ETA,
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
    pub(super) fn point(&self, t: f64) -> ([DoubleDouble; 3], DVec3) {
        let component = |i: usize| {
            let p = DoubleDouble::product(t, self.d[i]);
            let s = DoubleDouble::sum(self.wh[i], p.hi);
            let tail = s.lo + p.lo;
            let x = DoubleDouble {
                hi: s.hi,
                lo: tail + self.wl[i],
            }
            .renormalized();
            (x, U * (tail.abs() + x.lo.abs()) + ETA)
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
    ///   pairs summed ([`DoubleDouble::sum3`]: TwoSum errors below `u Q`, five
    ///   low terms below `5 u Q` through three roundings): within `20 u^2
    ///   Q`, its low part below `5.1 u Q`;
    /// - `h = y . a`: each `xh_i a_i` exact as a pair, its low part below
    ///   `2 u |f_i|` rounded once, the sum's low terms below `4 u F`
    ///   through three roundings: within `15 u^2 F`, its low part below
    ///   `4.1 u F`; `h^2`: the low part below `9.4 u F^2` rounded once,
    ///   `Hl^2 <= 17 u^2 F^2` dropped, `h`'s error through `2 |h| δ + δ^2`:
    ///   within `57 u^2 F^2`;
    /// - the products with `S` and `R` ([`DoubleDouble::times`]): the low terms'
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
        let xx = DoubleDouble::sum3([x[0].square(), x[1].square(), x[2].square()]);
        let f = [
            x[0].times_f64(self.a[0]),
            x[1].times_f64(self.a[1]),
            x[2].times_f64(self.a[2]),
        ];
        let h = DoubleDouble::sum3(f);
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
