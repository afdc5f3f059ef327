//! incircle: the sign of `det[[a-d, |a-d|^2], [b-d, |b-d|^2], [c-d, |c-d|^2]]`,
//! positive when `d` is inside the circle through counterclockwise `a, b, c`.
//! Exact for every finite input.
//!
//! Stage ladder (see the [module docs](super)): filtered, small-integer
//! exact, adaptive (`robust`), scaled filter, big-integer exact.

use crate::arith::exponent::{Grain, TINY, in_range, pow2, scale_pow2, unit_scale};
use crate::arith::fixed_int::{DEG1, DEG2, DEG4, FixedInt};
use crate::sign::Sign;
use glam::DVec2;

/// Shewchuk's `iccerrboundA = (10 + 96 eps) eps`, `eps = 2^-53`: with no
/// underflow, `|det_computed - det| <= A * permanent` (Shewchuk 1997,
/// incircle stage A), plus `2^-60` relative for the underflow that the
/// difference guard below admits.
const A: f64 = (10.0 + 96.0 * f64::EPSILON / 2.0) * (f64::EPSILON / 2.0) + GUARD_RELATIVE;

/// The filter on unscaled input runs only when every coordinate difference
/// is 0 or at least `2^-250` in magnitude. Then every product of two to four
/// differences is at least `2^-1000` or exactly 0, and a product that still
/// underflows (a lift times a minor that cancelled to below `2^-750`) is
/// off by at most `2^-1075`, which is below `2^-75` times the permanent term
/// it belongs to (at least `2^-1000`). Ten such terms at most: `2^-60`
/// relative covers them.
const GUARD_MIN_DIFF: f64 = pow2(-250);
const GUARD_RELATIVE: f64 = pow2(-60);

/// Span of the small-integer stage (both axes share one grain, since the
/// lift adds x^2 and y^2): coordinates below `2^60`, differences below
/// `2^61` (one limb), lifts and minors below `2^123` (two), the determinant
/// below `3 * 2^246 < 2^248` (four).
const SMALL_SPAN: i32 = 60;

/// Span up to which Shewchuk's adaptive stages are exact once scaled below
/// 1: non-zero values of degree `j <= 4` are at least `2^-900`.
const ADAPTIVE_SPAN: i32 = 225;

/// Absolute error of the filter on inputs scaled below 1 (no difference
/// guard there). Differences are below 2, lifts and minors below 8.
/// Underflowed products: 6 minor products and 6 squares, each off by
/// `2^-1075` and multiplied by at most 8, plus 3 final products: under
/// `2^-1068`. Scaling error: each difference is off by `2^-1073`, and the
/// determinant's derivative in one difference is at most `2*2*8 + 8*2*2 =
/// 64`; six differences: `384 * 2^-1073 < 2^-1064`. `2^-1058` leaves a
/// factor over 30.
const SCALED_SLACK: f64 = 65536.0 * TINY;

#[inline(always)]
pub(super) fn incircle(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
    match filtered(a, b, c, d, Guard::MinDifference) {
        Ok(s) => s,
        Err(permanent) => exact(a, b, c, d, in_range(permanent)),
    }
}

/// What makes the filter's bound hold under underflow.
#[derive(Clone, Copy)]
enum Guard {
    /// Decline unless every difference is 0 or at least `GUARD_MIN_DIFF`.
    MinDifference,
    /// Inputs are scaled below 1: add this absolute slack.
    Slack(f64),
}

/// Stage 1 (and 4, on scaled input): the `f64` determinant, certified by a
/// forward error bound. `Err(permanent)` when the bound cannot certify the
/// sign, `Err(NaN)` when the difference guard declined.
#[inline(always)]
fn filtered(a: DVec2, b: DVec2, c: DVec2, d: DVec2, guard: Guard) -> Result<Sign, f64> {
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let slack = match guard {
        Guard::MinDifference => {
            let m = ad.abs().min(bd.abs()).min(cd.abs()).min_element();
            if m < GUARD_MIN_DIFF || m.is_nan() {
                return Err(f64::NAN);
            }
            0.0
        }
        Guard::Slack(s) => s,
    };
    let bxcy = bd.x * cd.y;
    let cxby = cd.x * bd.y;
    let cxay = cd.x * ad.y;
    let axcy = ad.x * cd.y;
    let axby = ad.x * bd.y;
    let bxay = bd.x * ad.y;
    let alift = ad.length_squared();
    let blift = bd.length_squared();
    let clift = cd.length_squared();
    let det = alift * (bxcy - cxby) + blift * (cxay - axcy) + clift * (axby - bxay);
    let permanent = (bxcy.abs() + cxby.abs()) * alift
        + (cxay.abs() + axcy.abs()) * blift
        + (axby.abs() + bxay.abs()) * clift;
    let bound = A * permanent + slack;
    if det > bound {
        Ok(Sign::Positive)
    } else if -det > bound {
        Ok(Sign::Negative)
    } else {
        Err(permanent)
    }
}

/// Stages 2 to 5, for the few inputs the filter cannot certify.
#[cold]
#[inline(never)]
fn exact(a: DVec2, b: DVec2, c: DVec2, d: DVec2, in_range: bool) -> Sign {
    let points = [a, b, c, d];
    if !points.iter().all(|p| p.is_finite()) {
        return Sign::Zero;
    }
    let coords = [a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y];
    let scaled = || {
        let k = unit_scale(&coords);
        points.map(|p| DVec2::new(scale_pow2(p.x, k), scale_pow2(p.y, k)))
    };
    // Tiny, huge and mixed inputs: most are far from degenerate once scaled.
    let scaled_filter =
        |s: [DVec2; 4]| filtered(s[0], s[1], s[2], s[3], Guard::Slack(SCALED_SLACK)).ok();
    if !in_range && let Some(sign) = scaled_filter(scaled()) {
        return sign;
    }
    let grain = Grain::of(&coords);
    if grain.all_zero() {
        return Sign::Zero;
    }
    if grain.span() <= SMALL_SPAN {
        return integer::<1, 2, 4>(&points, grain.lo_min);
    }
    let s = scaled();
    if grain.span() <= ADAPTIVE_SPAN {
        let p = |v: DVec2| robust::Coord { x: v.x, y: v.y };
        return Sign::of_f64(robust::incircle(p(s[0]), p(s[1]), p(s[2]), p(s[3])));
    }
    if in_range && let Some(sign) = scaled_filter(s) {
        return sign;
    }
    integer::<DEG1, DEG2, DEG4>(&points, grain.lo_min)
}

/// Stages 2 and 5: coordinates as integers at the finest bit `lo`, with
/// `D`-limb differences, `M`-limb lifts and minors, an `R`-limb result.
/// Stage 2: `<1, 2, 4>` (see `SMALL_SPAN`). Stage 5: `<34, 67, 133>`:
/// differences below `2^2099`, lifts and minors below `2^4199`, the
/// determinant below `3 * 2^8398 < 2^8400`.
fn integer<const D: usize, const M: usize, const R: usize>(p: &[DVec2; 4], lo: i32) -> Sign {
    let int = |v: DVec2| {
        [
            FixedInt::<D>::from_f64(v.x, lo),
            FixedInt::from_f64(v.y, lo),
        ]
    };
    let d = int(p[3]);
    let rel = |v: DVec2| {
        let q = int(v);
        [q[0].sub(&d[0]), q[1].sub(&d[1])]
    };
    let (a, b, c) = (rel(p[0]), rel(p[1]), rel(p[2]));
    let lift =
        |u: &[FixedInt<D>; 2]| FixedInt::<M>::mul(&u[0], &u[0]).add(&FixedInt::mul(&u[1], &u[1]));
    let minor = |u: &[FixedInt<D>; 2], v: &[FixedInt<D>; 2]| {
        FixedInt::<M>::mul(&u[0], &v[1]).sub(&FixedInt::mul(&v[0], &u[1]))
    };
    let det = FixedInt::<R>::mul(&lift(&a), &minor(&b, &c))
        .add(&FixedInt::mul(&lift(&b), &minor(&c, &a)))
        .add(&FixedInt::mul(&lift(&c), &minor(&a, &b)));
    det.sign()
}
