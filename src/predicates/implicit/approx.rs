//! The filters' arithmetic: each point's homogeneous coordinates relative
//! to an origin, in `f64`, with a-priori bounds on their errors, and the
//! certified determinants and products the predicates take of them.
//!
//! # The error model
//! Every operation on finite values rounds to nearest: `fl(x op y) = (x op
//! y)(1 + e)`, `|e| <= u = 2^-53`, plus an absolute `2^-1075` for a product
//! that underflows (sums and differences that underflow are exact). An
//! input difference is rounded once; `M` below is the largest magnitude of
//! the rounded differences a point is built from (its `scale`). For a
//! computed `x` with `|x - x_exact| <= e_x` and `|x_exact| <= m_x`, to
//! first order a product is off by `m_x e_y + m_y e_x + u m_x m_y` and a
//! sum by `e_x + e_y + u (m_x + m_y)`. Each point constant below is that
//! calculus applied step by step in the order the code evaluates, rounded
//! up by at least 1%, which covers the second-order terms (relatively
//! `O(100 u)`).
//!
//! # Range
//! A point's bounds hold as stated while nothing overflows and underflow
//! stays negligible: [`in_range`] asks every point's `M` to lie in `[2^-R,
//! 2^R]` with `R = 800 / degree`, `degree` that of the predicate's whole
//! polynomial. Then every product of the computation (at most `degree`
//! factors, each bounded by a power of some `M`) lies below `2^820` with
//! its constants, and an underflowing product, off by `2^-1075`, at most
//! `2^(800 - 1022) u m_x m_y`, is within `2^-222` of the rounding term the
//! bound already carries for it. Out of range, the predicates scale every input
//! by one power of two (which leaves every sign unchanged) and try again,
//! and only then go exact.

use crate::arith::exponent::{pow2, unit_scale};
use crate::arith::magnitude::larger;
use crate::arith::roundoff::U;
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// Factor on every certified bound, `1 + 2^-30`. It covers the rounding of
/// the bound's own evaluation (fewer than `2^8` operations, each within a
/// relative `u`: below `2^-44`), the `gamma(n) - n u` parts of the
/// rounding terms (relatively `O(n u)`), and the underflow terms in range
/// (relatively below `2^-200`).
pub(super) const SAFETY: f64 = 1.0 + pow2(-30);

/// An explicit point's row `x - o`, rounded once: `|x~ - x| <= u |x| <= u
/// |x~| / (1 - u)`; `1 + 2^-50` covers the `1 / (1 - u)`.
const EXPLICIT: f64 = U * (1.0 + pow2(-50));

/// `Lpi`'s weight `D = n . e`, `n = a1 x a2`, `a1 = s - r`, `a2 = t - r`,
/// `e = q - p`, the rows rounded differences (`m = M`, `e = u M`). Each
/// product `a1_j a2_k`: `m = M^2`, `e = 3 u M^2`; each `n_k`: `8 u M^2`,
/// `m = 2 M^2`; each `n_k e_k`: `(2 + 8 + 2) u M^3 = 12 u M^3`, `m = 2
/// M^3`; summed `(x + y) + z`: `28 u M^3`, then `46 u M^3`. (Shewchuk's
/// `o3derrboundA` times the permanent `6 M^3` gives `42 u M^3`.) The same
/// bound holds for `P = n . (p - r)`.
pub(super) const LPI_W: f64 = 47.0 * U;

/// `Lpi`'s coordinates `l = h D - e P`, `h = p - o`: each product `h_k D`
/// is off by `M 46 u M^3 + 6 M^3 u M + u 6 M^4 = 58 u M^4` (`m = 6 M^4`),
/// as is `e_k P`; their difference by `116 u M^4 + 12 u M^4 = 128 u M^4`.
pub(super) const LPI_L: f64 = 130.0 * U;

/// `Ssi`'s weight `D = e x f`, `e = q - p`, `f = s - r`: each product `3 u
/// M^2`, their difference `8 u M^2` (`m = 2 M^2`); `T = g x f`, `g = r -
/// p`, the same.
pub(super) const SSI_W: f64 = 9.0 * U;

/// `Ssi`'s coordinates `l = h D + e T`, `h = p - o`: `h_k D` is off by `M 8
/// u M^2 + 2 M^2 u M + u 2 M^3 = 12 u M^3`, as is `e_k T`; the sum by `24 u
/// M^3 + 4 u M^3 = 28 u M^3`.
pub(super) const SSI_L: f64 = 29.0 * U;

/// `Tpi`'s weight `W = n_u . c_u`, `c_u = n_v x n_w`, each normal `n_i =
/// a_i x b_i` off by `8 u M^2` (`m = 2 M^2`, as `Lpi`'s `n`). A product of
/// two normals' components: `2 M^2 8 u M^2 * 2 + u 4 M^4 = 36 u M^4`; each
/// `c_k`: `80 u M^4`, `m = 8 M^4`; each `n_k c_k`: `2 M^2 80 u M^4 + 8 M^4
/// 8 u M^2 + 16 u M^6 = 240 u M^6`; summed: `512`, then `800 u M^6` (`m =
/// 48 M^6`).
pub(super) const TPI_W: f64 = 808.0 * U;

/// `Tpi`'s coordinates `l = h_u c_u + h_v c_v + h_w c_w`, with
/// `h_i = n_i . (i0 - o)` off by `46 u M^3` (`m = 6 M^3`, as `Lpi`'s `D`):
/// each product `h_i c_i,k` by `6 M^3 80 u M^4 + 8 M^4 46 u M^3 + 48 u M^7 = 896 u M^7`;
/// summed: `1888`, then `2928 u M^7` (`m = 144 M^7`).
pub(super) const TPI_L: f64 = 2960.0 * U;

/// `1 + 2^-10`: the margin on the a-priori magnitudes `m` of the point
/// constants above (`|l| <= 12 M^4` for an `Lpi`, `144 M^7` for a `Tpi`,
/// `4 M^3` for an `Ssi`, to first order), which covers their `O(u)`
/// corrections, the errors `el` (below `3000 u` of them) and the roundings
/// of `lmax` itself.
const MARGIN: f64 = 1.0 + pow2(-10);

/// The largest magnitude of a vector's components.
#[inline(always)]
pub(super) fn norm3(v: DVec3) -> f64 {
    larger(larger(v.x.abs(), v.y.abs()), v.z.abs())
}

/// The largest magnitude of a vector's components.
#[inline(always)]
pub(super) fn norm2(v: DVec2) -> f64 {
    larger(v.x.abs(), v.y.abs())
}

/// A point relative to an origin `o`: rounded homogeneous coordinates `l
/// ~ w (X - o)` and weight `w`, their bounds (`|l - l_exact| <= el` in
/// every component, `|w - w_exact| <= ew`), the point's scale `M` (over
/// its differences and its offset from `o`) and the construction's own
/// (`least`, over its differences only: its weight's bound uses that one),
/// and whether it is explicit (`w = 1` exactly).
#[derive(Clone, Copy, Debug)]
pub(super) struct Hom<const D: usize> {
    pub(super) l: [f64; D],
    pub(super) w: f64,
    pub(super) el: f64,
    pub(super) ew: f64,
    pub(super) scale: f64,
    pub(super) least: f64,
    /// An upper bound on `|l~|` (largest component) from the scale: the
    /// first-order magnitude `m` of the point constants above, times
    /// `1 + 2^-10`, which covers their error terms and the rounding.
    pub(super) lmax: f64,
    pub(super) explicit: bool,
}

impl<const D: usize> Hom<D> {
    /// The point's coordinates on the axes `axes` (a projection): the
    /// bounds stay (a component's error is within the vector's).
    #[inline(always)]
    pub(super) fn select(&self, axes: [usize; 2]) -> Hom<2> {
        Hom {
            l: [self.l[axes[0]], self.l[axes[1]]],
            w: self.w,
            el: self.el,
            ew: self.ew,
            scale: self.scale,
            least: self.least,
            lmax: self.lmax,
            explicit: self.explicit,
        }
    }
}

/// An explicit point `x` relative to `o`: the rounded difference.
#[inline(always)]
pub(super) fn explicit<const D: usize>(l: [f64; D]) -> Hom<D> {
    let r = l.iter().fold(0.0, |m, x| larger(m, x.abs()));
    Hom {
        l,
        w: 1.0,
        el: EXPLICIT * r,
        ew: 0.0,
        scale: r,
        least: r,
        lmax: r,
        explicit: true,
    }
}

/// The part of an `Lpi`'s filter that does not depend on the origin,
/// computed once at construction: `n = (s - r) x (t - r)`, `D = n . (q -
/// p)` and `P = n . (p - r)` rounded, and the scale `M` of the rounded
/// differences `s - r`, `t - r`, `q - p`, `p - r`.
#[derive(Clone, Copy, Debug)]
pub(super) struct LpiCache {
    d: f64,
    p: f64,
    pub(super) m: f64,
}

/// [`LpiCache`] of the inputs.
pub(super) fn lpi_cache(p: DVec3, q: DVec3, r: DVec3, s: DVec3, t: DVec3) -> LpiCache {
    let (a1, a2, e, g) = (s - r, t - r, q - p, p - r);
    let m = larger(larger(norm3(a1), norm3(a2)), larger(norm3(e), norm3(g)));
    let n = a1.cross(a2);
    LpiCache {
        d: n.dot(e),
        p: n.dot(g),
        m,
    }
}

impl LpiCache {
    /// The certified sign of `D`, if the filter can tell.
    pub(super) fn weight_sign(&self) -> Option<Sign> {
        let m3 = self.m * self.m * self.m;
        weight_in_range(self.m, 3)
            .then(|| certified(self.d, LPI_W * m3 * SAFETY))
            .flatten()
    }
}

/// Whether a construction's own scale lies where its weight's bound holds
/// (degree `degree`, see [`in_range`]).
fn weight_in_range(m: f64, degree: i32) -> bool {
    (pow2(-800 / degree)..=pow2(800 / degree)).contains(&m)
}

/// An `Lpi` (its line `p`, `q` and its cache) relative to `o`: `h = p - o`
/// and `l = h D - e P`, with `M` raised to cover `h` (every bound above
/// holds with the larger `M`).
#[inline(always)]
pub(super) fn lpi(p: DVec3, q: DVec3, c: &LpiCache, o: DVec3) -> Hom<3> {
    let (e, h) = (q - p, p - o);
    let m = larger(c.m, norm3(h));
    let m2 = m * m;
    Hom {
        l: (h * c.d - e * c.p).to_array(),
        w: c.d,
        el: LPI_L * (m2 * m2),
        ew: LPI_W * (c.m * c.m * c.m),
        scale: m,
        least: c.m,
        lmax: (12.0 * MARGIN) * (m2 * m2),
        explicit: false,
    }
}

/// The part of a `Tpi`'s filter that does not depend on the origin: the
/// rounded normals `n_i`, their cross products `c_u = n_v x n_w`, ..., the
/// weight `W = n_u . c_u`, and the scale `M` of the planes' differences
/// `i1 - i0`, `i2 - i0`.
#[derive(Clone, Copy, Debug)]
pub(super) struct TpiCache {
    n: [DVec3; 3],
    c: [DVec3; 3],
    w: f64,
    pub(super) m: f64,
}

/// [`TpiCache`] of the planes.
pub(super) fn tpi_cache(planes: &[[DVec3; 3]; 3]) -> TpiCache {
    let mut m = 0.0;
    let n = planes.map(|[p0, p1, p2]| {
        let (a, b) = (p1 - p0, p2 - p0);
        m = larger(m, larger(norm3(a), norm3(b)));
        a.cross(b)
    });
    let c = [n[1].cross(n[2]), n[2].cross(n[0]), n[0].cross(n[1])];
    TpiCache {
        n,
        c,
        w: n[0].dot(c[0]),
        m,
    }
}

impl TpiCache {
    /// The certified sign of `W`, if the filter can tell.
    pub(super) fn weight_sign(&self) -> Option<Sign> {
        let m2 = self.m * self.m;
        weight_in_range(self.m, 6)
            .then(|| certified(self.w, TPI_W * (m2 * m2 * m2) * SAFETY))
            .flatten()
    }
}

/// A `Tpi` (its planes and its cache) relative to `o`: `h_i = n_i . (i0 -
/// o)` and `l = sum h_i c_i`, `M` raised to cover the `i0 - o`.
#[inline(always)]
pub(super) fn tpi(planes: &[[DVec3; 3]; 3], c: &TpiCache, o: DVec3) -> Hom<3> {
    let mut m = c.m;
    let h: [f64; 3] = core::array::from_fn(|i| {
        let g = planes[i][0] - o;
        m = larger(m, norm3(g));
        c.n[i].dot(g)
    });
    let m2 = m * m;
    let m6 = m2 * m2 * m2;
    let w2 = c.m * c.m;
    Hom {
        l: (c.c[0] * h[0] + c.c[1] * h[1] + c.c[2] * h[2]).to_array(),
        w: c.w,
        el: TPI_L * (m6 * m),
        ew: TPI_W * (w2 * w2 * w2),
        scale: m,
        least: c.m,
        lmax: (144.0 * MARGIN) * (m6 * m),
        explicit: false,
    }
}

/// The part of an `Ssi`'s filter that does not depend on the origin:
/// `D = e x f`, `T = (r - p) x f` rounded, and the scale `M` of `e = q -
/// p`, `f = s - r`, `r - p`.
#[derive(Clone, Copy, Debug)]
pub(super) struct SsiCache {
    d: f64,
    t: f64,
    pub(super) m: f64,
}

/// [`SsiCache`] of the inputs.
pub(super) fn ssi_cache(p: DVec2, q: DVec2, r: DVec2, s: DVec2) -> SsiCache {
    let (e, f, g) = (q - p, s - r, r - p);
    SsiCache {
        d: e.perp_dot(f),
        t: g.perp_dot(f),
        m: larger(larger(norm2(e), norm2(f)), norm2(g)),
    }
}

impl SsiCache {
    /// The certified sign of `D`, if the filter can tell.
    pub(super) fn weight_sign(&self) -> Option<Sign> {
        weight_in_range(self.m, 2)
            .then(|| certified(self.d, SSI_W * (self.m * self.m) * SAFETY))
            .flatten()
    }
}

/// An `Ssi` (its first line `p`, `q` and its cache) relative to `o`: `l =
/// h D + e T`, `h = p - o`.
#[inline(always)]
pub(super) fn ssi(p: DVec2, q: DVec2, c: &SsiCache, o: DVec2) -> Hom<2> {
    let (e, h) = (q - p, p - o);
    let m = larger(c.m, norm2(h));
    Hom {
        l: (h * c.d + e * c.t).to_array(),
        w: c.d,
        el: SSI_L * (m * m * m),
        ew: SSI_W * (c.m * c.m),
        scale: m,
        least: c.m,
        lmax: (4.0 * MARGIN) * (m * m * m),
        explicit: false,
    }
}

/// Whether every point's scale lies in `[2^-R, 2^R]`, `R = 800 /
/// degree` (see the module docs); an explicit point's scale may also be
/// zero (its row is then exactly zero, and no bound below certifies a sign
/// from it).
#[inline(always)]
pub(super) fn in_range<const D: usize>(h: &[Hom<D>], degree: u32) -> bool {
    let r = (800 / degree.max(1)) as i32;
    let (lo, hi) = (pow2(-r), pow2(r));
    h.iter()
        .all(|x| (lo <= x.least && x.scale <= hi) | (x.explicit & (x.scale == 0.0)))
}

/// [`in_range`] for the smallest and the largest scale of a filter's
/// points (false for NaN).
#[inline(always)]
pub(super) fn scales_in_range(least: f64, scale: f64, degree: u32) -> bool {
    let r = (800 / degree) as i32;
    pow2(-r) <= least && scale <= pow2(r)
}

/// What a filter made of its input.
pub(super) enum Verdict {
    /// The certified sign.
    Certain(Sign),
    /// A scale was out of range; the largest scale (`inf` where a
    /// difference overflowed).
    OutOfRange(f64),
    /// In range but too close to zero to certify.
    Uncertain,
}

/// The exponent `k` to scale every input by, `2^k`, for the second try of
/// a filter whose scales were out of range: the one that brings the largest
/// scale into `[1/2, 1)`, or where a difference overflowed, the largest
/// input coordinate. `None` when that is no scaling at all.
pub(super) fn rescaling(largest: f64, largest_coordinate: impl FnOnce() -> f64) -> Option<i32> {
    let k = if largest.is_finite() && largest > 0.0 {
        unit_scale(&[largest])
    } else {
        unit_scale(&[largest_coordinate()])
    };
    (k != 0).then_some(k.clamp(-2046, 2046))
}

/// `det[x0, x1, x2] = x0 . (x1 x x2)` of rounded rows, each given with a
/// bound on its components' errors, and a bound on the error of the
/// result.
///
/// By multilinearity, `det[x~] - det[x]` is `det[d0, x~1, x~2] + det[x0,
/// d1, x~2] + det[x0, x1, d2]` (`d_i = x~i - x_i`), and `|det[a, b, c]| <=
/// 6 |a| |b| |c|` in the largest-component norm; with `R_i = |x~i|`,
/// `|x_i| <= R_i + E_i`. The evaluation rounds each of its six terms at
/// most five times (a product, the minor's difference, the product with
/// `x0`, two sums): within `gamma(5)` of the permanent, itself at most `6
/// R0 R1 R2`. So the error is at most `6 [E0 R1 R2 + (R0 + E0) E1 R2 +
/// (R0 + E0)(R1 + E1) E2 + gamma(5) R0 R1 R2]`.
#[inline(always)]
pub(super) fn det3_bounded(rows: [([f64; 3], f64); 3]) -> (f64, f64) {
    let [(x0, e0), (x1, e1), (x2, e2)] = rows.map(|(x, e)| (DVec3::from_array(x), e));
    let det = x0.dot(x1.cross(x2));
    let (r0, r1, r2) = (norm3(x0), norm3(x1), norm3(x2));
    let bound = 6.0
        * (e0 * r1 * r2
            + (r0 + e0) * e1 * r2
            + (r0 + e0) * (r1 + e1) * e2
            + 5.0 * U * r0 * r1 * r2);
    (det, bound * SAFETY)
}

/// `det[x0, x1] = x0.x x1.y - x0.y x1.x` of rounded rows with their
/// bounds, and a bound on its error: as [`det3_bounded`], with `|det[a,
/// b]| <= 2 |a| |b|` and two roundings per term (`gamma(2)`): `2 [E0 R1 +
/// (R0 + E0) E1 + gamma(2) R0 R1]`.
#[inline(always)]
pub(super) fn det2_bounded(rows: [([f64; 2], f64); 2]) -> (f64, f64) {
    let [(x0, e0), (x1, e1)] = rows.map(|(x, e)| (DVec2::from_array(x), e));
    let det = x0.perp_dot(x1);
    let (r0, r1) = (norm2(x0), norm2(x1));
    let bound = 2.0 * (e0 * r1 + (r0 + e0) * e1 + 2.0 * U * r0 * r1);
    (det, bound * SAFETY)
}

/// `a b - c d` of rounded values with their bounds (`(value, error)`), and
/// a bound on its error: `|a~| E_b + (|b~| + E_b) E_a` for each product
/// (as in the module docs, exactly rather than to first order), and
/// `gamma(2) (|a~ b~| + |c~ d~|)` for the two products' and the
/// difference's roundings.
#[inline(always)]
pub(super) fn cross_products_bounded(
    (a, ea): (f64, f64),
    (b, eb): (f64, f64),
    (c, ec): (f64, f64),
    (d, ed): (f64, f64),
) -> (f64, f64) {
    let (ab, cd) = (a * b, c * d);
    let bound = a.abs() * eb
        + (b.abs() + eb) * ea
        + c.abs() * ed
        + (d.abs() + ed) * ec
        + 2.0 * U * (ab.abs() + cd.abs());
    (ab - cd, bound * SAFETY)
}

/// The certified sign of `value` with error bound `bound`, if any.
#[inline(always)]
pub(super) fn certified(value: f64, bound: f64) -> Option<Sign> {
    (value.abs() > bound).then(|| Sign::of_f64(value))
}
