//! Certified errors of hit points: how far `ray.at(t)` may lie from the
//! exact point `ray.at(t_exact)` of the surface crossing a cast returns,
//! per axis, given a bound on `|t - t_exact|` (pbrt-v4 keeps the same
//! kind of bound beside each intersection point, `pError` in
//! `shapes.h`; the derivations here are for `f64` and for each cast's own
//! `t`).
//!
//! Every bound is computed in `f64` with rounding to nearest, so each one
//! is taken with a margin (`1 + gamma(6)` or an extra `u`) that covers the
//! few roundings of its own evaluation, and with an absolute term for
//! products that underflow (each off by at most `2^-1075`).

use super::Ray;
use crate::arith::roundoff::gamma;
use glam::DVec3;

/// Absolute slack for underflow: a bound's own products, and the
/// point's `d_k t`, may each fall below the normal range and lose up to
/// `2^-1075`; eight of them stay below `2^-1072`.
const UNDERFLOW: f64 = f64::from_bits(4); // 2^-1072

/// `|t - t_exact|` for a `t` within `4u |t_exact|` of the exact one (the
/// exact triangle's plane parameter, `EXACT_T_ULPS`): `4u |t_exact| <=
/// gamma(4) |t|`, and `2^-1073` for a subnormal `t` (documented there).
#[inline]
pub(crate) fn exact_t_error(t: f64) -> f64 {
    gamma(4) * t.abs() + f64::from_bits(2)
}

/// The error of a rounded dot product `x . n` of a vector `x` of rounded
/// differences (each within `u` of the exact difference) and an exact `n`:
/// one rounding of the difference, one of the product and two of the sum
/// on each term, `gamma(4) sum |x_k n_k|` (Higham, *Accuracy and
/// Stability*, §3.1), taken as `gamma(5)` of the computed sum for its own
/// roundings, plus underflow.
#[inline]
pub(crate) fn dot_error(x: DVec3, n: DVec3) -> f64 {
    gamma(5) * (x.abs().dot(n.abs())) + UNDERFLOW
}

/// The per-axis error of the point `p = ray.at(t)` computed as `fl(o_k +
/// fl(d_k t))`, for `|t - t_exact| <= et`:
///
/// `p_k - (o_k + d_k t_exact) = d_k (t - t_exact) + d_k t δ1 + η1 +
/// (o_k + fl(d_k t)) δ2`, with `|δ1|, |δ2| <= u` and `|η1| <= 2^-1075`
/// (an underflowed product; a sum never loses more than rounding), and
/// `|o_k + fl(d_k t)| <= |p_k| / (1 - u)`. So the error is at most `|d_k|
/// et + u |d_k t| + gamma(1) |p_k| + 2^-1075`, taken with `1 + gamma(6)`
/// for the bound's own roundings.
///
/// A coordinate computed as `fma(t, d_k, o_k)` ([`Ray::at`], where `d_k
/// t` overflows) has one rounding, `δ1 = η1 = 0`: the same bound holds.
/// Where the bound's own `|d_k t|` overflows, it is evaluated a quarter
/// scale: `|d_k| / 4` and `|p_k| / 4` rounded up (the bound grows with
/// both), the result times 4, exact or infinite.
#[inline]
pub(crate) fn point_error(ray: &Ray, t: f64, point: DVec3, et: f64) -> DVec3 {
    if !et.is_finite() {
        return DVec3::INFINITY;
    }
    let d = ray.direction().abs();
    let e = bound(d, t, point.abs(), et);
    if e.is_finite() || !point.is_finite() {
        return e;
    }
    let quarter = |x: DVec3| (x * 0.25).to_array().map(f64::next_up).into();
    bound(quarter(d), t, quarter(point.abs()), et) * 4.0
}

/// [`point_error`]'s bound for `|d|` and `|p|`.
#[inline(always)]
fn bound(d: DVec3, t: f64, p: DVec3, et: f64) -> DVec3 {
    (d * et + gamma(1) * (d * t.abs() + p)) * (1.0 + gamma(6)) + DVec3::splat(UNDERFLOW)
}
