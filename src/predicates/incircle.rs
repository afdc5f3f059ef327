//! incircle: the sign of `det[[a-d, |a-d|^2], [b-d, |b-d|^2], [c-d, |c-d|^2]]`,
//! positive when `d` is inside the circle through counterclockwise `a, b, c`.
//! Exact for every finite input.
//!
//! Stage ladder (see the [module docs](super)): 1 filtered, 2
//! small-integer exact, 3 adaptive
//! (Shewchuk's, `adaptive.rs`), 4 scaled filter, 5
//! big-integer exact.

use super::adaptive;
use super::sparse::{
    Either, Expansion, Monomials, lifted_monomials, lifted_sign, lifted_value, product_terms,
    reference,
};
use crate::arith::exponent::{
    Grain, SmallInteger, TINY, in_range, pow2, scale_pow2, small_integer, unit_scale,
};
use crate::arith::fixed_int::{DEG1, DEG2, DEG4, FixedInt};
use crate::arith::magnitude::{largest_abs, zero_or_at_least};
use crate::arith::scaled_float::ScaledFloat;
use crate::arith::sparse_sum::{Diff, diff};
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

/// Span up to which [`rounded_determinant`] uses two-limb differences:
/// coordinates below `2^125`, differences below `2^126` (two limbs,
/// signed), lifts and minors below `2^253` (four), the determinant below
/// `3 * 2^506 < 2^508` (eight).
const MEDIUM_SPAN: i32 = 125;

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
        Err(declined) => exact(a, b, c, d, declined),
    }
}

/// What a filter that declined computed: its permanent and its error bound
/// `A * permanent + slack`, both NaN when the difference guard declined.
#[derive(Clone, Copy)]
struct Declined {
    permanent: f64,
    bound: f64,
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
/// forward error bound. `Err` when the bound cannot certify the sign, with
/// NaN in it when the difference guard declined.
#[inline(always)]
fn filtered(a: DVec2, b: DVec2, c: DVec2, d: DVec2, guard: Guard) -> Result<Sign, Declined> {
    let (det, declined) = stage_a(a, b, c, d, guard);
    if det > declined.bound {
        Ok(Sign::Positive)
    } else if -det > declined.bound {
        Ok(Sign::Negative)
    } else {
        Err(declined)
    }
}

/// Stage 1 on unscaled input, for `robust_compat`: Shewchuk's stage A
/// determinant (robust's value, same operations in the same order) and its
/// error bound, both NaN where the difference guard declines.
#[inline(always)]
pub(super) fn first_stage(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> (f64, f64) {
    let (det, declined) = stage_a(a, b, c, d, Guard::MinDifference);
    (det, declined.bound)
}

/// Stage 1's determinant, its permanent and its bound `A * permanent +
/// slack`; all NaN when the difference guard declined.
#[inline(always)]
fn stage_a(a: DVec2, b: DVec2, c: DVec2, d: DVec2, guard: Guard) -> (f64, Declined) {
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let slack = match guard {
        Guard::MinDifference => {
            let m = ad.abs().min(bd.abs()).min(cd.abs()).min_element();
            let diffs = [ad.x, ad.y, bd.x, bd.y, cd.x, cd.y];
            if (m < GUARD_MIN_DIFF || m.is_nan()) && !zero_or_at_least(&diffs, GUARD_MIN_DIFF) {
                let nan = Declined {
                    permanent: f64::NAN,
                    bound: f64::NAN,
                };
                return (f64::NAN, nan);
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
    (det, Declined { permanent, bound })
}

/// Stages 2 to 5, for the few inputs the filter cannot certify.
#[cold]
#[inline(never)]
fn exact(a: DVec2, b: DVec2, c: DVec2, d: DVec2, stage1: Declined) -> Sign {
    let points = [a, b, c, d];
    let in_range = in_range(stage1.permanent);
    let coords = [a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y];
    let max = largest_abs(&coords);
    let scaled = || {
        let k = unit_scale(&[max]);
        points.map(|p| DVec2::new(scale_pow2(p.x, k), scale_pow2(p.y, k)))
    };
    // Stage 2, and the lattice stage (`small_integer`), which needs stage
    // 1's bound: where that is NaN (its difference guard declined: tiny
    // inputs) or infinite, the scaled filter comes first.
    let small = stage1
        .bound
        .is_finite()
        .then(|| small_integer(&coords, max, SMALL_SPAN, 4, stage1.bound));
    if let Some(SmallInteger::Zero) = small {
        return Sign::Zero;
    }
    // (Non-finite input is never `SmallInteger::Zero`.)
    if !points.iter().all(|p| p.is_finite()) {
        return Sign::Zero;
    }
    // Tiny, huge and mixed inputs: most are far from degenerate once scaled.
    let scaled_filter =
        |s: [DVec2; 4]| filtered(s[0], s[1], s[2], s[3], Guard::Slack(SCALED_SLACK)).ok();
    if !in_range && let Some(sign) = scaled_filter(scaled()) {
        return sign;
    }
    let small = small.unwrap_or_else(|| small_integer(&coords, max, SMALL_SPAN, 4, f64::NAN));
    if let SmallInteger::Zero = small {
        return Sign::Zero;
    }
    if let SmallInteger::Integers(ints) = small {
        return integer::<1, 2, 4>(|i| {
            [
                FixedInt::from_i64(ints[2 * i]),
                FixedInt::from_i64(ints[2 * i + 1]),
            ]
        });
    }
    let grain = Grain::of(&coords);
    if grain.all_zero() {
        return Sign::Zero;
    }
    let s = scaled();
    if grain.span() <= ADAPTIVE_SPAN
        && let Some(sign) = adaptive::incircle(s[0], s[1], s[2], s[3])
    {
        return sign;
    }
    if in_range && let Some(sign) = scaled_filter(s) {
        return sign;
    }
    sparse_sign(points)
        .unwrap_or_else(|| integer::<DEG1, DEG2, DEG4>(at_grain(&points, grain.lo_min)))
}

/// Point `i`'s coordinates as integers in units of `2^lo`, for `integer`.
fn at_grain<const D: usize>(p: &[DVec2; 4], lo: i32) -> impl Fn(usize) -> [FixedInt<D>; 2] {
    move |i| {
        [
            FixedInt::from_f64(p[i].x, lo),
            FixedInt::from_f64(p[i].y, lo),
        ]
    }
}

/// Stage 5, first: the exact sign of the in-circle determinant of `p` (as
/// `predicates::incircle`), for finite input, or `None` when its terms do
/// not fit the accumulators.
///
/// `incircle` is the sign of the lifted determinant `det4` of the rows `(x,
/// y, x^2 + y^2, 1)` (with `d` as the origin, below, this is its own
/// formula). Two expansions, whichever has fewer terms:
/// - `det4` is translation invariant; with point `k` as the origin its row
///   is `(0, 0, 0, 1)`, so `det4 = (-1)^(k + 1) det3` (0-based `k`,
///   expanded along that row), `det3` the lifted 3x3 determinant of the
///   other points minus point `k`, in order: 12 products of 4 differences,
///   each difference one or two terms (the `k` whose differences have the
///   fewest two-term parts is taken);
/// - `det4` over the coordinates themselves, one term each: 24
///   permutations, times 2 for the lift, 48 products.
pub(super) fn sparse_sign(p: [DVec2; 4]) -> Option<Sign> {
    let (expansion, negate) = sparse_expansion(&p);
    lifted_sign::<48, 4, 4>(expansion, negate)
}

/// The in-circle determinant within a relative `2^-52`, from the terms of
/// [`sparse_sign`], or `None` when they do not fit.
fn sparse_value(p: &[DVec2; 4]) -> Option<ScaledFloat> {
    let (expansion, negate) = sparse_expansion(p);
    lifted_value::<48, 4, 4>(expansion, negate)
}

/// The expansion [`sparse_sign`] sums, and whether its sum is negated.
fn sparse_expansion(p: &[DVec2; 4]) -> (Either<IncircleTranslated, Monomials<4, 2>>, bool) {
    let coords = p.map(|v| [v.x, v.y]);
    let k = reference(&coords);
    let translated = incircle_translated(&coords, k);
    if product_terms(&translated) <= 48 {
        (Either::First(translated), k % 2 == 0)
    } else {
        (Either::Second(lifted_monomials::<4, 2>(&coords)), false)
    }
}

/// The products of `det3` with point `k` as the origin (see [`sparse_sign`]):
/// the lifted 3x3 determinant expanded along the lift column, `lift_u (x_v
/// y_w - y_v x_w)` over `(u, v, w)` cyclic, `lift_u = x_u^2 + y_u^2`.
pub(super) fn incircle_translated(p: &[[f64; 2]; 4], k: usize) -> IncircleTranslated {
    IncircleTranslated(core::array::from_fn(|i| {
        let q = p[i + (i >= k) as usize];
        [diff(q[0], p[k][0]), diff(q[1], p[k][1])]
    }))
}

/// The rows of [`incircle_translated`].
pub(super) struct IncircleTranslated([[Diff; 2]; 3]);

impl Expansion<4> for IncircleTranslated {
    fn products(&self, push: &mut impl FnMut(bool, [Diff; 4])) {
        let rows = &self.0;
        for (u, v, w) in [(0, 1, 2), (1, 2, 0), (2, 0, 1)] {
            for c in 0..2 {
                let (sq, v, w) = (rows[u][c], rows[v], rows[w]);
                push(false, [sq, sq, v[0], w[1]]);
                push(true, [sq, sq, v[1], w[0]]);
            }
        }
    }
}

/// Stages 2 and 5: point `i`'s coordinates as integers `int(i)` (all at
/// one scale), with `D`-limb differences, `M`-limb lifts and minors, an
/// `R`-limb result. Stage 2: `<1, 2, 4>` (see `SMALL_SPAN`). Stage 5:
/// `<34, 67, 133>`: differences below `2^2099`, lifts and minors below
/// `2^4199`, the determinant below `3 * 2^8398 < 2^8400`.
fn integer<const D: usize, const M: usize, const R: usize>(
    int: impl Fn(usize) -> [FixedInt<D>; 2],
) -> Sign {
    integer_det::<D, M, R>(int).sign()
}

/// The in-circle determinant of `p` within a relative `2^-52`, with an
/// unbounded exponent, for finite input: where the span is within
/// `SMALL_SPAN`, the integers of [`integer`] at the coordinates' finest bit
/// in one limb per difference (two within `MEDIUM_SPAN`), rounded once by
/// [`FixedInt::as_extended`]; otherwise the sparse terms of [`sparse_sign`] ([`lifted_value`]), or
/// the wide integers where those do not fit.
pub(super) fn rounded_determinant(p: &[DVec2; 4]) -> ScaledFloat {
    let grain = Grain::of(p.map(|v| [v.x, v.y]).as_flattened());
    if grain.all_zero() {
        return ScaledFloat::ZERO;
    }
    let unit = 4 * grain.lo_min;
    if grain.span() <= SMALL_SPAN {
        integer_det::<1, 2, 4>(at_grain(p, grain.lo_min)).as_extended(unit)
    } else if grain.span() <= MEDIUM_SPAN {
        integer_det::<2, 4, 8>(at_grain(p, grain.lo_min)).as_extended(unit)
    } else {
        sparse_value(p).unwrap_or_else(|| {
            integer_det::<DEG1, DEG2, DEG4>(at_grain(p, grain.lo_min)).as_extended(unit)
        })
    }
}

/// The determinant of [`integer`], in units of the fourth power of the
/// integers' unit.
fn integer_det<const D: usize, const M: usize, const R: usize>(
    int: impl Fn(usize) -> [FixedInt<D>; 2],
) -> FixedInt<R> {
    let d = int(3);
    let rel = |i: usize| {
        let q = int(i);
        [q[0].sub(&d[0]), q[1].sub(&d[1])]
    };
    let (a, b, c) = (rel(0), rel(1), rel(2));
    let lift =
        |u: &[FixedInt<D>; 2]| FixedInt::<M>::mul(&u[0], &u[0]).add(&FixedInt::mul(&u[1], &u[1]));
    let minor = |u: &[FixedInt<D>; 2], v: &[FixedInt<D>; 2]| {
        FixedInt::<M>::mul(&u[0], &v[1]).sub(&FixedInt::mul(&v[0], &u[1]))
    };
    FixedInt::<R>::mul(&lift(&a), &minor(&b, &c))
        .add(&FixedInt::mul(&lift(&b), &minor(&c, &a)))
        .add(&FixedInt::mul(&lift(&c), &minor(&a, &b)))
}

/// The big-integer stage alone, exact for every finite input: the
/// reference the other stages' tests compare with.
#[cfg(test)]
pub(super) fn dense(p: [DVec2; 4]) -> Sign {
    let grain = Grain::of(&p.map(|v| [v.x, v.y]).concat());
    if grain.all_zero() {
        return Sign::Zero;
    }
    integer::<DEG1, DEG2, DEG4>(at_grain(&p, grain.lo_min))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{InputClass, SplitMix64, incircle_case, step_ulps};

    /// Cocircular lattice points (`3^2 + 4^2 = 5^2` and its symmetries,
    /// around a lattice centre), scaled by `2^k` over the whole exponent
    /// range, and the same with one coordinate moved by one lattice step or
    /// one ulp: zeros the lattice stage must certify, and non-zeros it must
    /// leave alone.
    #[test]
    fn lattice_zeros_and_their_neighbours() {
        let on = [
            (5, 0),
            (3, 4),
            (0, 5),
            (-4, 3),
            (-5, 0),
            (-3, -4),
            (4, -3),
            (0, -5),
        ];
        let mut rng = SplitMix64::new(17);
        let (mut zeros, mut cases) = (0, 0);
        for i in 0..20_000 {
            let centre = [rng.next_u64() % 64, rng.next_u64() % 64].map(|c| c as f64 - 32.0);
            let mut p = [(); 4].map(|_| {
                let (x, y) = on[(rng.next_u64() % 8) as usize];
                DVec2::new(centre[0] + x as f64, centre[1] + y as f64)
            });
            let k = (rng.next_u64() % 2000) as i32 - 1000;
            let scale = |v: f64| v * pow2(k / 2) * pow2(k - k / 2);
            p = p.map(|v| DVec2::new(scale(v.x), scale(v.y)));
            let (j, c) = ((rng.next_u64() % 4) as usize, (rng.next_u64() % 2) as usize);
            match i % 3 {
                1 => p[j][c] += scale(1.0),
                2 => p[j][c] = step_ulps(p[j][c], 1),
                _ => {}
            }
            let exact = dense(p);
            assert_eq!(incircle(p[0], p[1], p[2], p[3]), exact, "{p:?}");
            zeros += (exact == Sign::Zero) as u32;
            cases += 1;
        }
        assert!(zeros > cases / 4, "{zeros} of {cases}");
    }

    #[test]
    fn every_class_matches_dense_integers() {
        let mut rng = SplitMix64::new(5);
        for i in 0..30_000 {
            let p = incircle_case(InputClass::ALL[i % 6], &mut rng);
            assert_eq!(incircle(p[0], p[1], p[2], p[3]), dense(p), "{p:?}");
        }
    }
}
