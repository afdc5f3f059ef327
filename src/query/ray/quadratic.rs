//! The quadratic in `t` that every ray–quadric cast solves, in half form
//! `A t^2 + 2 B t + C = 0` with discriminant `B^2 - A C`, at two levels:
//!
//! - **filtered**: the coefficients in `f64` beside a running bound on
//!   their absolute errors (Wilkinson's running error analysis; N. Higham,
//!   *Accuracy and Stability of Numerical Algorithms*, 2nd ed., ch. 3).
//!   It answers when the bound certifies the sign of the discriminant (so
//!   the root count is exact) and bounds each root's relative error by
//!   [`FAST_ROOT_ULPS`] units of roundoff (so each root is within that many
//!   ulps of the exact root);
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
use crate::predicates::wide::Wide;
use crate::roots::Roots;
use crate::sign::Sign;
use glam::DVec3;

/// The unit roundoff `2^-53`.
pub(crate) const U: f64 = f64::EPSILON / 2.0;

/// The largest first-order relative error bound, in units of `U`, that the
/// filtered stage accepts for a root; above it the exact stage runs. One
/// unit of `U` is at most one ulp, so an accepted root is within this many
/// ulps of the exact root.
pub(crate) const FAST_ROOT_ULPS: f64 = 16.0;

/// Half-form coefficients with absolute error bounds (`e_*`), and the
/// discriminant `disc ≈ B^2 - A C` with its own bound.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Coeffs {
    pub a: f64,
    pub e_a: f64,
    pub b: f64,
    pub e_b: f64,
    pub c: f64,
    pub e_c: f64,
    pub disc: f64,
    pub e_disc: f64,
}

/// The roots when the running bounds certify the count and the accuracy;
/// `None` asks for the exact stage. Non-finite bounds (overflow) decline.
#[inline]
pub(crate) fn filtered_roots(k: &Coeffs) -> Option<Roots> {
    // Every bound below is first order; the factor covers the neglected
    // O(u^2) terms with room to spare.
    let slack = 1.0 + 64.0 * U;
    let e_disc = k.e_disc * slack;
    if !(e_disc < f64::INFINITY) || k.a <= k.e_a * slack {
        return None;
    }
    if k.disc < -e_disc {
        return Some(Roots::None);
    }
    if k.disc <= e_disc {
        return None;
    }
    let s = sqrt(k.disc);
    // sqrt halves the relative error of its argument and rounds once.
    let e_s = s * (0.5 * e_disc / k.disc + U);
    let q = -(k.b + s.copysign(k.b));
    // Same signs: the sum rounds once and adds the two errors.
    let rel_q = (k.e_b + e_s) / q.abs() + U;
    let rel_1 = rel_q + k.e_a / k.a + U;
    let rel_2 = rel_q + k.e_c / k.c.abs() + U;
    let limit = FAST_ROOT_ULPS * U / slack;
    if !(rel_1 <= limit && rel_2 <= limit) {
        return None;
    }
    let (t1, t2) = (q / k.a, k.c / q);
    Some(if t1 <= t2 {
        Roots::Two(t1, t2)
    } else {
        Roots::Two(t2, t1)
    })
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
    let (xa, xb, xc) = (a.to_extended(ea), b.to_extended(eb), c.to_extended(ec));
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
            let s = disc.to_extended(2 * eb).sqrt();
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
/// `A = |d|^2`, `B = w . d`, `C = |w|^2 - rr`, and the discriminant in
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
    let (aw, ad) = (w.abs(), d.abs());
    let a = d.dot(d);
    let e_a = 2.0 * ad.dot(ed) + 3.0 * U * a;
    let b = w.dot(d);
    let e_b = aw.dot(ed) + ad.dot(ew) + 3.0 * U * aw.dot(ad);
    let ww = w.dot(w);
    let c = ww - rr;
    let e_c = 2.0 * aw.dot(ew) + 3.0 * U * ww + err + U * c.abs();
    let cr = w.cross(d);
    // Input errors propagate into each component as |w_j| ed_k + |d_k|
    // ew_j + |w_k| ed_j + |d_j| ew_k.
    let e_cr = cross_magnitudes(w, ed) + cross_magnitudes(ew, d) + cross_magnitudes(w, d) * (2.0 * U);
    let x = cr.dot(cr);
    let e_x = 2.0 * cr.abs().dot(e_cr) + 3.0 * U * x;
    let disc = crate::float::fma(rr, a, -x);
    let e_disc = a * err + rr * e_a + e_x + U * disc.abs();
    Coeffs {
        a,
        e_a,
        b,
        e_b,
        c,
        e_c,
        disc,
        e_disc,
    }
}

/// `|x_j y_k| + |x_k y_j|` per component: what bounds the rounding of each
/// component of `x x y`.
#[inline(always)]
pub(crate) fn cross_magnitudes(x: DVec3, y: DVec3) -> DVec3 {
    let (x, y) = (x.abs(), y.abs());
    DVec3::new(x.y * y.z + x.z * y.y, x.z * y.x + x.x * y.z, x.x * y.y + x.y * y.x)
}

/// Whether `v` lies where the filtered stage's bounds hold: products of the
/// magnitudes involved neither overflow nor reach the subnormal range
/// (where rounding errors become absolute rather than relative).
#[inline(always)]
pub(crate) fn in_filter_range(v: f64) -> bool {
    (1e-120..1e120).contains(&v)
}
