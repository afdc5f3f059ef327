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
//! its constants, and an underflowing product, off by `2^-1075 <= 2^(-1022
//! + 800) u m_x m_y`, is within `2^-222` of the rounding term the bound
//! already carries for it. Out of range, the predicates scale every input
//! by one power of two (which leaves every sign unchanged) and try again,
//! and only then go exact.

use super::any::{AnyPoint2, AnyPoint3};
use super::points::{Lpi, Ssi, Tpi};
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

/// `Tpi`'s coordinates `l = h_u c_u + h_v c_v + h_w c_w`, `h_i = n_i . (i0
/// - o)` off by `46 u M^3` (`m = 6 M^3`, as `Lpi`'s `D`): each product `h_i
/// c_i,k` by `6 M^3 80 u M^4 + 8 M^4 46 u M^3 + 48 u M^7 = 896 u M^7`;
/// summed: `1888`, then `2928 u M^7` (`m = 144 M^7`).
pub(super) const TPI_L: f64 = 2960.0 * U;

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
/// every component, `|w - w_exact| <= ew`), the point's scale `M`, and
/// whether it is explicit (`w = 1` exactly).
#[derive(Clone, Copy, Debug)]
pub(super) struct Hom<const D: usize> {
    pub(super) l: [f64; D],
    pub(super) w: f64,
    pub(super) el: f64,
    pub(super) ew: f64,
    pub(super) scale: f64,
    pub(super) explicit: bool,
}

impl Hom<3> {
    /// The projection that drops axis `drop`, keeping the axes `drop + 1`
    /// and `drop + 2` (cyclically): the bounds stay (a component's error is
    /// within the vector's).
    #[inline(always)]
    pub(super) fn project(&self, drop: usize) -> Hom<2> {
        Hom {
            l: [self.l[(drop + 1) % 3], self.l[(drop + 2) % 3]],
            w: self.w,
            el: self.el,
            ew: self.ew,
            scale: self.scale,
            explicit: self.explicit,
        }
    }
}

/// An explicit point `x` relative to `o`: the rounded difference.
#[inline(always)]
fn explicit<const D: usize>(l: [f64; D]) -> Hom<D> {
    let r = l.iter().fold(0.0, |m, x| larger(m, x.abs()));
    Hom {
        l,
        w: 1.0,
        el: EXPLICIT * r,
        ew: 0.0,
        scale: r,
        explicit: true,
    }
}

/// A point relative to `o`, rounded, with its bounds.
#[inline(always)]
pub(super) fn hom3(p: &AnyPoint3, o: DVec3) -> Hom<3> {
    match p {
        AnyPoint3::Explicit(x) => explicit((*x - o).to_array()),
        AnyPoint3::Lpi(x) => lpi(x, o),
        AnyPoint3::Tpi(x) => tpi(x, o),
    }
}

/// A point relative to `o`, rounded, with its bounds.
#[inline(always)]
pub(super) fn hom2(p: &AnyPoint2, o: DVec2) -> Hom<2> {
    match p {
        AnyPoint2::Explicit(x) => explicit((*x - o).to_array()),
        AnyPoint2::Ssi(x) => ssi(x, o),
    }
}

#[inline(always)]
fn lpi(x: &Lpi, o: DVec3) -> Hom<3> {
    let (a1, a2, e, g, h) = (x.s - x.r, x.t - x.r, x.q - x.p, x.p - x.r, x.p - o);
    let m = larger(
        larger(larger(norm3(a1), norm3(a2)), larger(norm3(e), norm3(g))),
        norm3(h),
    );
    let n = a1.cross(a2);
    let (d, p) = (n.dot(e), n.dot(g));
    let m3 = m * m * m;
    Hom {
        l: (h * d - e * p).to_array(),
        w: d,
        el: LPI_L * (m3 * m),
        ew: LPI_W * m3,
        scale: m,
        explicit: false,
    }
}

/// The normals, the offsets `h_i` and the scale of a [`Tpi`]'s planes
/// relative to `o`.
#[inline(always)]
fn tpi_normals(x: &Tpi, o: DVec3) -> ([DVec3; 3], [f64; 3], f64) {
    let mut m = 0.0;
    let mut n = [DVec3::ZERO; 3];
    let mut h = [0.0; 3];
    for (i, [p0, p1, p2]) in x.planes.iter().enumerate() {
        let (a, b, g) = (*p1 - *p0, *p2 - *p0, *p0 - o);
        m = larger(m, larger(larger(norm3(a), norm3(b)), norm3(g)));
        n[i] = a.cross(b);
        h[i] = n[i].dot(g);
    }
    (n, h, m)
}

#[inline(always)]
fn tpi(x: &Tpi, o: DVec3) -> Hom<3> {
    let (n, h, m) = tpi_normals(x, o);
    let c = [n[1].cross(n[2]), n[2].cross(n[0]), n[0].cross(n[1])];
    let m2 = m * m;
    let m6 = m2 * m2 * m2;
    Hom {
        l: (c[0] * h[0] + c[1] * h[1] + c[2] * h[2]).to_array(),
        w: n[0].dot(c[0]),
        el: TPI_L * (m6 * m),
        ew: TPI_W * m6,
        scale: m,
        explicit: false,
    }
}

#[inline(always)]
fn ssi(x: &Ssi, o: DVec2) -> Hom<2> {
    let (e, f, g, h) = (x.q - x.p, x.s - x.r, x.r - x.p, x.p - o);
    let m = larger(larger(norm2(e), norm2(f)), larger(norm2(g), norm2(h)));
    let d = e.perp_dot(f);
    let t = g.perp_dot(f);
    let m2 = m * m;
    Hom {
        l: (h * d + e * t).to_array(),
        w: d,
        el: SSI_L * (m2 * m),
        ew: SSI_W * m2,
        scale: m,
        explicit: false,
    }
}

/// The certified sign of a [`Tpi`]'s weight `W = n_u . (n_v x n_w)`,
/// `None` when the filter cannot tell (the construction's exact stage then
/// decides). Bound [`TPI_W`], with `M` over the planes' own differences.
pub(super) fn tpi_weight_sign(x: &Tpi) -> Option<Sign> {
    let mut m = 0.0;
    let n = x.planes.map(|[p0, p1, p2]| {
        let (a, b) = (p1 - p0, p2 - p0);
        m = larger(m, larger(norm3(a), norm3(b)));
        a.cross(b)
    });
    let w = n[0].dot(n[1].cross(n[2]));
    let m2 = m * m;
    // Degree 6 (the weight alone).
    let bound = TPI_W * (m2 * m2 * m2) * SAFETY;
    if in_range([(m, false)], 6) {
        certified(w, bound)
    } else {
        None
    }
}

/// Whether every scale lies in `[2^-R, 2^R]`, `R = 800 / degree` (see the
/// module docs); an explicit point's scale may also be zero (its row is
/// then exactly zero, and no bound below certifies a sign from it).
#[inline(always)]
pub(super) fn in_range<const K: usize>(scales: [(f64, bool); K], degree: u32) -> bool {
    let r = (800 / degree.max(1)) as i32;
    let (lo, hi) = (pow2(-r), pow2(r));
    scales
        .iter()
        .all(|&(s, explicit)| (lo <= s && s <= hi) || (explicit && s == 0.0))
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

impl Verdict {
    /// The verdict with `f` applied to a certified sign.
    #[inline(always)]
    pub(super) fn map(self, f: impl FnOnce(Sign) -> Sign) -> Verdict {
        match self {
            Verdict::Certain(s) => Verdict::Certain(f(s)),
            other => other,
        }
    }
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
