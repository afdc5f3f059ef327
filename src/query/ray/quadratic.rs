//! The quadratic in `t` that every ray–quadric cast solves, in half form
//! `A t^2 + 2 B t + C = 0` with discriminant `B^2 - A C`, at two levels:
//!
//! - **filtered**: the coefficients in `f64` beside a running bound on
//!   their absolute errors (Wilkinson's running error analysis; N. Higham,
//!   *Accuracy and Stability of Numerical Algorithms*, 2nd ed., ch. 3).
//!   It answers when the bound certifies the sign of the discriminant (so
//!   the root count is exact) and each computed root is certified, a
//!   posteriori, to have an exact root within 3 ulps: the exact polynomial,
//!   evaluated with a rigorous error bound, changes sign across it (so each
//!   root is within 4 ulps of the correctly rounded root);
//! - **exact**: the coefficients as exact integers (`wide.rs`), the
//!   discriminant's sign exact, each coefficient rounded once to 53 bits
//!   with an unbounded exponent ([`Extended`]) and the roots from the
//!   stable formula: four more roundings (sqrt, the sum of same-sign terms,
//!   the division, and the final conversion), so each root is within
//!   `4.5u` relative of the exact root to first order (at most 5 ulps).
//!
//! Both use the stable pair `t1 = q / A`, `t2 = C / q` with
//! `q = -(B + sign(B) sqrt(B^2 - A C))`: no cancellation in `q`.

use crate::extended::Extended;
use crate::float::sqrt;
use crate::hard_inputs::step_ulps;
use crate::predicates::wide::Wide;
use crate::roots::Roots;
use crate::sign::Sign;
use glam::DVec3;

/// The unit roundoff `2^-53`.
pub(crate) const U: f64 = f64::EPSILON / 2.0;

/// The largest grain span (bits from a set's finest to its coarsest bit)
/// for which the exact stages use 2-limb inputs: a difference of two such
/// values needs at most 128 bits with its sign.
pub(crate) const SMALL_SPAN: i32 = 126;

/// Half-form coefficients, the bound `e_a` on `A`'s absolute error, and
/// the discriminant `disc ≈ B^2 - A C` with its bound `e_disc`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Coeffs {
    pub a: f64,
    pub e_a: f64,
    pub b: f64,
    pub c: f64,
    pub disc: f64,
    pub e_disc: f64,
}

/// How far, in ulps, a certified root may lie from the exact root: with
/// the correctly rounded root half an ulp further at most, every certified
/// root is within 4 ulps of it (3.5, rounded to whole ulps).
pub(crate) const CERTIFIED_ULPS: i64 = 3;

/// The roots when the running bound on the discriminant certifies the
/// count and each computed root is certified within [`CERTIFIED_ULPS`] of
/// an exact root; `None` asks for the exact stage.
///
/// A root `t` is certified when the exact polynomial, evaluated with a
/// rigorous error bound by `eval` (which returns the value and the bound),
/// has opposite signs `CERTIFIED_ULPS` ulps below and above `t`: an exact
/// root lies between. The two brackets are disjoint and the count is two,
/// so each holds exactly one root. This a-posteriori check is what makes
/// the fast path both fast and tight: an a-priori bound on the stable
/// formula costs several units of roundoff for every rounding it passes
/// through, while the actual errors are about one.
#[inline(always)]
pub(crate) fn certified_roots(k: &Coeffs, eval: impl Fn(f64) -> (f64, f64)) -> Option<Roots> {
    // The bounds are first order; the factor covers the O(u^2) terms.
    let e_disc = k.e_disc * (1.0 + 64.0 * U);
    // A NaN or infinite bound (overflow) fails the first test.
    if e_disc.is_nan() || e_disc == f64::INFINITY || k.a <= k.e_a * (1.0 + 64.0 * U) {
        return None;
    }
    if k.disc < -e_disc {
        return Some(Roots::None);
    }
    if k.disc <= e_disc {
        return None;
    }
    let s = sqrt(k.disc);
    let q = -(k.b + s.copysign(k.b));
    let (t1, t2) = (q / k.a, k.c / q);
    let (t1, t2) = if t1 <= t2 { (t1, t2) } else { (t2, t1) };
    let apart = step_ulps(t1, 2 * CERTIFIED_ULPS) < t2;
    (apart && brackets_root(t1, &eval) && brackets_root(t2, &eval)).then_some(Roots::Two(t1, t2))
}

/// Whether the polynomial certainly changes sign across
/// `[t - CERTIFIED_ULPS ulps, t + CERTIFIED_ULPS ulps]`.
#[inline(always)]
fn brackets_root(t: f64, eval: &impl Fn(f64) -> (f64, f64)) -> bool {
    let (p0, e0) = eval(step_ulps(t, -CERTIFIED_ULPS));
    let (p1, e1) = eval(step_ulps(t, CERTIFIED_ULPS));
    let slack = 1.0 + 64.0 * U;
    p0.abs() > e0 * slack && p1.abs() > e1 * slack && (p0 < 0.0) != (p1 < 0.0)
}

/// `|x|^2 - rr` at `x = w + t d` with a rigorous first-order error bound,
/// given componentwise bounds `ew`, `ed` on the errors of `w` and `d` and
/// `err` on that of `rr`: the polynomial of the sphere-like problems.
#[inline(always)]
pub(crate) fn eval_circle(
    w: DVec3,
    ew: DVec3,
    d: DVec3,
    ed: DVec3,
    rr: f64,
    err: f64,
    t: f64,
) -> (f64, f64) {
    let td = d * t;
    let x = w + td;
    // The product and the sum round once each; the inputs' errors carry.
    let ex = ew + ed * t.abs() + (td.abs() + x.abs()) * U;
    let xx = x.dot(x);
    let p = xx - rr;
    (p, 2.0 * x.abs().dot(ex) + 3.0 * U * xx + err + U * p.abs())
}

/// The roots of `A t^2 + 2 B t + C` from exact integer coefficients:
/// `A = a * 2^ea` and so on, with `2 eb = ea + ec` (each caller's scaling
/// makes the three terms of the discriminant share one exponent). `M` must
/// hold `B^2` and `A C`.
pub(crate) fn exact_roots<const N: usize, const M: usize>(
    (a, ea): (&Wide<N>, i32),
    (b, eb): (&Wide<N>, i32),
    (c, ec): (&Wide<N>, i32),
) -> Roots {
    debug_assert_eq!(2 * eb, ea + ec);
    let (xa, xb, xc) = (a.as_extended(ea), b.as_extended(eb), c.as_extended(ec));
    if xa.is_zero() {
        // Linear: 2 B t + C = 0.
        return if !xb.is_zero() {
            Roots::One(xc.div(xb.mul(Extended::new(-2.0, 0))).to_f64())
        } else if xc.is_zero() {
            Roots::All
        } else {
            Roots::None
        };
    }
    let disc = Wide::<M>::mul(b, b).sub(&Wide::<M>::mul(a, c));
    match disc.sign() {
        Sign::Negative => Roots::None,
        Sign::Zero => Roots::One(xb.neg().div(xa).to_f64()),
        Sign::Positive => {
            let s = disc.as_extended(2 * eb).sqrt();
            let q = if xb.is_negative() {
                s.add(xb.neg())
            } else {
                s.add(xb).neg()
            };
            let (t1, t2) = (q.div(xa).to_f64(), xc.div(q).to_f64());
            if t1 <= t2 {
                Roots::Two(t1, t2)
            } else {
                Roots::Two(t2, t1)
            }
        }
    }
}

/// `|v|_1`, an upper bound on the Euclidean norm that needs no square root.
#[inline(always)]
pub(crate) fn norm1(v: DVec3) -> f64 {
    v.x.abs() + v.y.abs() + v.z.abs()
}

/// The half-form coefficients of `|w + t d|^2 = rr`, the sphere-like core
/// that the sphere (`w = o - c`) and the cylinder (`w`, `d` projected
/// across the axis) share, from inputs known to within `|δw_i| <= ew_i`,
/// `|δd_i| <= ed_i` (componentwise) and `|δrr| <= err`:
///
/// `A = |d|^2` with its error bound, `B = w . d`, `C = |w|^2 - rr` (their
/// accuracy is checked on the roots, see [`certified_roots`]), and the discriminant in
/// Lagrange's form `rr |d|^2 - |w x d|^2`, which does not cancel for far
/// origins the way `B^2 - A C` does.
///
/// Error bounds (first order): a sum of `n` rounded products is within
/// `n u` of its value relative to the sum of its terms' magnitudes (Higham
/// ch. 3); an input error `δx_i` changes a product `x_i y_j` by at most
/// `|δx_i| |y_j|`. Each component of `w x d` is a difference of two
/// products: two roundings relative to the two products' magnitudes.
#[inline(always)]
pub(crate) fn circle_coeffs(w: DVec3, ew: DVec3, d: DVec3, ed: DVec3, rr: f64, err: f64) -> Coeffs {
    let ad = d.abs();
    let a = d.dot(d);
    let e_a = 2.0 * ad.dot(ed) + 3.0 * U * a;
    let b = w.dot(d);
    let c = w.dot(w) - rr;
    let cr = w.cross(d);
    // Input errors propagate into each component as |w_j| ed_k + |d_k|
    // ew_j + |w_k| ed_j + |d_j| ew_k.
    let e_cr =
        cross_magnitudes(w, ed) + cross_magnitudes(ew, d) + cross_magnitudes(w, d) * (2.0 * U);
    let x = cr.dot(cr);
    let e_x = 2.0 * cr.abs().dot(e_cr) + 3.0 * U * x;
    let disc = crate::float::fma(rr, a, -x);
    let e_disc = a * err + rr * e_a + e_x + U * disc.abs();
    Coeffs {
        a,
        e_a,
        b,
        c,
        disc,
        e_disc,
    }
}

/// `|x_j y_k| + |x_k y_j|` per component: what bounds the rounding of each
/// component of `x x y`.
#[inline(always)]
pub(crate) fn cross_magnitudes(x: DVec3, y: DVec3) -> DVec3 {
    let (x, y) = (x.abs(), y.abs());
    DVec3::new(
        x.y * y.z + x.z * y.y,
        x.z * y.x + x.x * y.z,
        x.x * y.y + x.y * y.x,
    )
}

/// Whether `v` lies where the filtered stage's bounds hold: products of the
/// magnitudes involved neither overflow nor reach the subnormal range
/// (where rounding errors become absolute rather than relative).
#[inline(always)]
pub(crate) fn in_filter_range(v: f64) -> bool {
    (1e-120..1e120).contains(&v)
}
