//! The lateral quadratic's half-form coefficients and its discriminant,
//! with a-priori bounds, from a [`Line`].

use crate::arith::exponent::pow2;
use crate::arith::roundoff::gamma;
use crate::arith::std_or_libm::fma;
use crate::roots::line_quadratic::{Coeffs, ETA, in_filter_range, norm1};
use glam::DVec3;

/// `|x_j y_k| + |x_k y_j|` per component: the magnitudes of `x x y`'s
/// terms.
#[inline(always)]
pub(super) fn abs_cross(x: DVec3, y: DVec3) -> DVec3 {
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
pub(super) fn dot(x: DVec3, y: DVec3) -> f64 {
    fma(x.z, y.z, fma(x.y, y.y, x.x * y.x))
}

/// `x x y` with one FMA per component: two roundings on each term's
/// path, as `x_j y_k - x_k y_j` has.
#[inline(always)]
pub(super) fn cross(x: DVec3, y: DVec3) -> DVec3 {
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
pub(super) struct Line {
    pub(super) w: DVec3,
    pub(super) ew1: f64,
    pub(super) d: DVec3,
    pub(super) a: DVec3,
    pub(super) r: f64,
}

/// The largest magnitude of a [`Line`]'s components: every coefficient,
/// the discriminant and their bounds are polynomials of degree at most 12
/// in them, so nothing overflows below it, and an operation that
/// underflows (losing at most `2^-1075`) is grown by the later factors of
/// its term by less than `2^480`: under `2^-590` each, which `ETA`
/// (`2^-500`) per quantity covers however many there are.
pub(super) const LINE_LIMIT: f64 = pow2(40);

/// The rounded heights the nappe, cap and base tests reuse: `p = w . a`,
/// `q = d . a` and `s = |a|^2`; along the ray `(x - apex) . a = p + t q`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Heights {
    pub(super) p: f64,
    pub(super) q: f64,
    pub(super) s: f64,
}

impl Heights {
    /// Whether the point at `t` lies on the cone's own nappe (`(x - apex)
    /// . a >= 0`) and, for a capped cone, below the cap (`<= |a|^2`), in
    /// `f64`: `p + t q` with one rounding, against the rounded `s`.
    #[inline(always)]
    pub(super) fn on_cone(self, t: f64, capped: bool) -> bool {
        let h = fma(t, self.q, self.p);
        h >= 0.0 && (!capped || h <= self.s)
    }
}

/// The discriminant of a [`Line`] with its bound, and what the
/// coefficients share with it: computed first, since where it certifies a
/// miss of the whole double cone the coefficients are never needed.
#[derive(Clone, Copy, Debug)]
pub(super) struct Discriminant {
    /// `s = |a|^2` and `r^2`, rounded.
    pub(super) s: f64,
    pub(super) rr: f64,
    /// `|w|_1` and `|d|_1`.
    pub(super) nw: f64,
    pub(super) nd: f64,
    pub(super) disc: f64,
    pub(super) e_disc: f64,
}

impl Line {
    /// The coefficients with their bounds, the discriminant first
    /// ([`Line::discriminant`], [`Line::coeffs`]).
    #[inline(always)]
    pub(super) fn filtered(&self) -> Option<(Coeffs, Heights)> {
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
    pub(super) fn coeffs(&self, k: &Discriminant) -> Option<(Coeffs, Heights)> {
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
    pub(super) fn discriminant(&self) -> Discriminant {
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
