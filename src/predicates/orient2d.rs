//! orient2d: the sign of `(b - a) x (c - a)`, exact for every finite input.
//!
//! Stage ladder (see the [module docs](super)): 1 filtered, 2
//! small-integer exact, 3 adaptive
//! (Shewchuk's, `adaptive.rs`), 4 scaled filter, 5
//! big-integer exact. The
//! small-integer stage has a quick entry (`unit_integer`) tried first for
//! every input the filter declines: it answers almost all near-degenerate,
//! degenerate and tiny inputs before the cold path.

#![allow(
    unsafe_code,
    reason = "truncates values proven finite and below 2^62 to i64"
)]

use super::adaptive;
use super::sparse::{cross2_of, cross2_terms};
use crate::arith::exponent::{
    Grain, TINY, in_range, pow2, scale_pow2, split, to_integer_i64, unit_scale,
};
use crate::arith::fixed_int::{DEG1, DEG2, FixedInt};
use crate::arith::lanes::Lanes;
use crate::arith::scaled_float::ScaledFloat;
use crate::arith::sparse_sum::{diff, value_of_sum};
use crate::sign::Sign;
use glam::DVec2;

/// Shewchuk's `ccwerrboundA = (3 + 16 eps) eps`, `eps = 2^-53`: with no
/// underflow, `|det_computed - det| <= A * (|detleft| + |detright|)`
/// (Shewchuk 1997, section 4.3, orient2d stage A).
pub(super) const A: f64 = (3.0 + 16.0 * f64::EPSILON / 2.0) * (f64::EPSILON / 2.0);

/// Absolute term for underflow. A product that lands below `2^-1022` is off
/// by at most `2^-1075` instead of relatively; there are two products, and
/// the rounding of `A * detsum` itself can lose another `2^-1075`: in all
/// `3 * 2^-1075 < 2^-1073`; `2^-1071` leaves a factor 4 to spare. Overflow
/// needs no term: it makes `detsum` infinite (or the determinant NaN) and
/// the comparisons fail.
pub(super) const UNDERFLOW_SLACK: f64 = 8.0 * TINY;

/// Span (bits between the finest and coarsest set bit, per axis) up to which
/// the integer stage fits: coordinates are integers below `2^62`, their
/// differences below `2^63` (an `i64`), the products below `2^126` and the
/// determinant below `2^127` (an `i128`).
const SMALL_SPAN: i32 = 62;

/// Span up to which Shewchuk's adaptive stages are exact after scaling each
/// axis by a power of two so its largest coordinate is below 1: every value
/// of degree `j <= 2` they form is then a multiple of `2^(-j * span)`, and a
/// non-zero one is at least `2^-900`, so no step underflows (with 2^-100 to
/// spare for the error-bound products) and none overflows (all below 2^4).
const ADAPTIVE_SPAN: i32 = 450;

/// Extra absolute error of the scaled filter: each scaled coordinate is off
/// by at most `2^-1074` (see `scale_pow2`), each difference by `2^-1073`,
/// and with differences below 2 the determinant moves by at most
/// `2 * 2 * 2 * 2^-1073 = 2^-1070`; `2^-1068` leaves a factor 4.
const SCALED_SLACK: f64 = 64.0 * TINY;

#[inline(always)]
pub(super) fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Sign {
    match filtered(a, b, c, 0.0) {
        Ok(s) => s,
        Err(detsum) => declined(a, b, c, detsum),
    }
}

/// Stage 1: the `f64` determinant, certified by a forward error bound.
/// `Err(detsum)` when the bound cannot certify the sign (including
/// non-finite input), so the caller can tell underflow and overflow from
/// near-degeneracy.
#[inline(always)]
fn filtered(a: DVec2, b: DVec2, c: DVec2, extra_slack: f64) -> Result<Sign, f64> {
    let (det, detsum, certified) = stage_a(a, b, c, extra_slack);
    if certified {
        Ok(Sign::of_f64(det))
    } else {
        Err(detsum)
    }
}

/// Stage 1 without branches: the `f64` determinant, its permanent
/// `detsum`, and whether the bound certifies the determinant's sign
/// (`false` for non-finite input).
#[inline(always)]
fn stage_a(a: DVec2, b: DVec2, c: DVec2, extra_slack: f64) -> (f64, f64, bool) {
    let p = products(a, b, c);
    let (det, detsum, margin) = stage_a_lanes(p.x, p.y);
    (det, detsum, margin > UNDERFLOW_SLACK + extra_slack)
}

/// The two products of stage 1, `detleft` and `detright`, as one vector.
#[inline(always)]
pub(super) fn products(a: DVec2, b: DVec2, c: DVec2) -> DVec2 {
    // (a.x - c.x) * (b.y - c.y) and (a.y - c.y) * (b.x - c.x).
    let (u, v) = (a - c, b - c);
    u * DVec2::new(v.y, v.x)
}

/// The rest of stage 1 on one case (`T = f64`) or a block of them (the
/// batch variants), from its [`products`]: the determinant, `detsum`, and
/// the margin `|det| - A * detsum`, which certifies the sign when it
/// exceeds `UNDERFLOW_SLACK` (see [`certifies`]). The same operations in
/// the same order whatever `T`, so one bound covers both.
#[inline(always)]
pub(super) fn stage_a_lanes<T: Lanes>(detleft: T, detright: T) -> (T, T, T) {
    let det = detleft - detright;
    let detsum = detleft.abs() + detright.abs();
    // `|det| > A * detsum + slack`, tested as a difference: the slack is
    // subnormal, and adding it would cost a microcode assist on x86 for
    // every call. `fl(x - y) > s` implies `x - y > s` for representable `s`.
    let margin = det.abs() - T::splat(A) * detsum;
    (det, detsum, margin)
}

/// Whether a margin from `stage_a_lanes` certifies the sign on unscaled
/// input.
#[inline(always)]
pub(super) fn certifies(margin: f64) -> bool {
    margin > UNDERFLOW_SLACK
}

/// Stages 2 to 5 for an input stage 1 declined, given its `detsum`: first
/// the quick integer entry (`unit_integer`), which answers almost every
/// near-degenerate, degenerate and tiny input without leaving this
/// function, then the cold ladder.
#[inline(never)]
pub(super) fn declined(a: DVec2, b: DVec2, c: DVec2, detsum: f64) -> Sign {
    match unit_integer(a, b, c, detsum) {
        Some(sign) => sign,
        None => exact(a, b, c, in_range(detsum)),
    }
}

/// `2^61`, the fixed part of `unit_integer`'s scale.
const TWO_61: f64 = pow2(61);

/// Stage 2, quick entry, branch-light: each axis scaled by the power of two
/// `2^s` that puts its largest magnitude `m` just below `2^62`, when that
/// scaling is upwards (`m < 2^62`); then, if every scaled value is an
/// integer, the determinant in `i128` (`integer_det`). `None` when some
/// scaled value is not an integer (an axis spanning more than 62 bits) or
/// for magnitudes of `2^62` or more.
///
/// `detsum` is stage 1's: only finite when every coordinate is (each one
/// enters a difference that enters a product, and a non-finite difference
/// makes its product, hence `detsum`, infinite or NaN).
///
/// Exact: let `E <= 1084` be `m`'s exponent field (`m < 2^62`); then
/// `m < 2^(E - 1022)` for `E >= 1` and `m < 2^-1022` for `E = 0`, and
/// `g = 2^(1023 - E)` (built from its bits; its field `2046 - E >= 962` is
/// normal) gives `s = 61 + 1023 - E >= 0` with `m * 2^s < 2^62` in both
/// cases. Each value is first scaled by `2^61` (up: exact, below `2^123`)
/// and then by `g`, which leaves `x * 2^s` with `s >= 0`: exact as well,
/// since scaling up never rounds (a subnormal's significand times a power
/// of two is representable) and nothing reaches `2^62`. For a finite
/// `|y| < 2^62`, truncation to `i64` is exact and defined, and `trunc(y)`
/// is representable, so the round trip returns `y` exactly when `y` is an
/// integer (`-0.0` compares equal to `0.0`). The differences of the
/// integers are then below `2^63` and the determinant below `2^127`.
#[inline(always)]
fn unit_integer(a: DVec2, b: DVec2, c: DVec2, detsum: f64) -> Option<Sign> {
    if !detsum.is_finite() {
        return None;
    }
    let max = |p: DVec2, q: DVec2| DVec2::select(p.cmpgt(q), p, q);
    let m = max(max(a.abs(), b.abs()), c.abs());
    if !m.cmplt(DVec2::splat(pow2(62))).all() {
        return None;
    }
    const FIELD: u64 = 0x7ff << 52;
    let g = |m: f64| f64::from_bits((2046 << 52) - (m.to_bits() & FIELD));
    let g = DVec2::new(g(m.x), g(m.y));
    let y = [a, b, c].map(|p| p * TWO_61 * g);
    // SAFETY: every `y` is finite (as `detsum` is) and below `2^62` in
    // magnitude (see above), so truncating it to an `i64` is defined.
    let n = y.map(|y| unsafe { [y.x.to_int_unchecked::<i64>(), y.y.to_int_unchecked::<i64>()] });
    let back = n.map(|n| DVec2::new(n[0] as f64, n[1] as f64));
    let integer = back[0].cmpeq(y[0]) & back[1].cmpeq(y[1]) & back[2].cmpeq(y[2]);
    if !integer.all() {
        return None;
    }
    Some(integer_det(n.map(|n| n[0]), n.map(|n| n[1])))
}

/// Stages 2 to 5, for the few inputs the filter cannot certify.
#[cold]
#[inline(never)]
fn exact(a: DVec2, b: DVec2, c: DVec2, in_range: bool) -> Sign {
    if !(a.is_finite() && b.is_finite() && c.is_finite()) {
        return Sign::Zero;
    }
    let scaled = || {
        let scale = [unit_scale(&[a.x, b.x, c.x]), unit_scale(&[a.y, b.y, c.y])];
        [a, b, c].map(|p| DVec2::new(scale_pow2(p.x, scale[0]), scale_pow2(p.y, scale[1])))
    };
    // Tiny, huge and mixed inputs: most are far from degenerate once scaled.
    let scaled_filter = |s: [DVec2; 3]| filtered(s[0], s[1], s[2], SCALED_SLACK).ok();
    let mut scaled_once = None;
    if !in_range {
        let s = scaled();
        if let Some(sign) = scaled_filter(s) {
            return sign;
        }
        scaled_once = Some(s);
    }
    if let Some(sign) = same_binade_integer(a, b, c) {
        return sign;
    }
    let gx = Grain::of(&[a.x, b.x, c.x]);
    let gy = Grain::of(&[a.y, b.y, c.y]);
    if gx.all_zero() || gy.all_zero() {
        return Sign::Zero;
    }
    let span = gx.span().max(gy.span());
    if span <= SMALL_SPAN {
        return small_integer(a, b, c, gx.lo_min, gy.lo_min);
    }
    if span <= ADAPTIVE_SPAN {
        let s = scaled_once.unwrap_or_else(scaled);
        return adaptive::orient2d(s[0], s[1], s[2]);
    }
    if in_range && let Some(sign) = scaled_filter(scaled()) {
        return sign;
    }
    sparse_sign(a, b, c).unwrap_or_else(|| big_integer(a, b, c, gx.lo_min, gy.lo_min))
}

/// Stage 2, quick entry: when each axis's significands sit within 2^9 of
/// one another (the common near-degenerate case), shift them onto the
/// smallest exponent directly: integers below `2^62`, as in
/// `small_integer`, without counting trailing zeros. `None` otherwise.
#[inline]
fn same_binade_integer(a: DVec2, b: DVec2, c: DVec2) -> Option<Sign> {
    let axis = |v: [f64; 3]| -> Option<[i64; 3]> {
        let parts = v.map(split);
        let nonzero = |i: usize| parts[i].0 != 0;
        let emin = (0..3).filter(|&i| nonzero(i)).map(|i| parts[i].1).min()?;
        let emax = parts.iter().map(|p| p.1).max()?;
        (emax - emin <= 9).then(|| parts.map(|(m, e)| if m == 0 { 0 } else { m << (e - emin) }))
    };
    let x = axis([a.x, b.x, c.x])?;
    let y = axis([a.y, b.y, c.y])?;
    Some(integer_det(x, y))
}

/// The sign of `(b - a) x (c - a)` for integer coordinates below `2^62`:
/// differences below `2^63`, products below `2^126`, determinant below
/// `2^127`.
#[inline]
fn integer_det(x: [i64; 3], y: [i64; 3]) -> Sign {
    Sign::from_i8(integer_det_value(x, y).signum() as i8)
}

/// The determinant of [`integer_det`] itself.
#[inline]
fn integer_det_value(x: [i64; 3], y: [i64; 3]) -> i128 {
    (x[1] - x[0]) as i128 * (y[2] - y[0]) as i128 - (y[1] - y[0]) as i128 * (x[2] - x[0]) as i128
}

/// `(b - a) x (c - a)` within a relative `2^-52` (rounded once to 53
/// significant bits where the span is small), with an unbounded exponent,
/// for finite input: the integers of the small-integer stage (`i128`,
/// converted with one rounding), or the sparse terms of [`sparse_sign`]
/// summed from the largest down ([`value_of_sum`]), or the big-integer
/// stage's integers (rounded by [`FixedInt::as_extended`]).
pub(super) fn rounded_determinant(a: DVec2, b: DVec2, c: DVec2) -> ScaledFloat {
    let gx = Grain::of(&[a.x, b.x, c.x]);
    let gy = Grain::of(&[a.y, b.y, c.y]);
    if gx.all_zero() || gy.all_zero() {
        return ScaledFloat::ZERO;
    }
    let lo = gx.lo_min + gy.lo_min;
    if gx.span().max(gy.span()) <= SMALL_SPAN {
        let x = [a.x, b.x, c.x].map(|v| to_integer_i64(v, gx.lo_min));
        let y = [a.y, b.y, c.y].map(|v| to_integer_i64(v, gy.lo_min));
        return ScaledFloat::new(integer_det_value(x, y) as f64, lo);
    }
    sparse_value(a, b, c)
        .unwrap_or_else(|| big_integer_det(a, b, c, gx.lo_min, gy.lo_min).as_extended(lo))
}

/// Stage 2: each axis as integers at its finest bit (`span <= 62`).
fn small_integer(a: DVec2, b: DVec2, c: DVec2, lox: i32, loy: i32) -> Sign {
    let x = [a.x, b.x, c.x].map(|v| to_integer_i64(v, lox));
    let y = [a.y, b.y, c.y].map(|v| to_integer_i64(v, loy));
    integer_det(x, y)
}

/// Stage 5, first: the exact sign of `(b - a) x (c - a)` for finite input, or `None` when
/// the terms do not fit the accumulators.
pub(super) fn sparse_sign(a: DVec2, b: DVec2, c: DVec2) -> Option<Sign> {
    let b = [diff(b.x, a.x), diff(b.y, a.y)];
    let c = [diff(c.x, a.x), diff(c.y, a.y)];
    cross2_of(b, c)
}

/// `(b - a) x (c - a)` within a relative `2^-52`, from the terms of
/// [`sparse_sign`], or `None` when they do not fit.
fn sparse_value(a: DVec2, b: DVec2, c: DVec2) -> Option<ScaledFloat> {
    let b = [diff(b.x, a.x), diff(b.y, a.y)];
    let c = [diff(c.x, a.x), diff(c.y, a.y)];
    value_of_sum(&mut cross2_terms(b, c))
}

/// Stage 5: each axis as integers at its finest bit, whatever the span.
/// Coordinates are below `2^2098` (a finite `f64` over its finest possible
/// bit `2^-1074`), differences below `2^2099` (34 limbs) and the
/// determinant below `2^4199` (67 limbs).
pub(super) fn big_integer(a: DVec2, b: DVec2, c: DVec2, lox: i32, loy: i32) -> Sign {
    big_integer_det(a, b, c, lox, loy).sign()
}

/// The determinant of [`big_integer`], in units of `2^(lox + loy)`.
fn big_integer_det(a: DVec2, b: DVec2, c: DVec2, lox: i32, loy: i32) -> FixedInt<DEG2> {
    type D = FixedInt<DEG1>;
    let dx = |p: DVec2, q: DVec2| D::from_f64(p.x, lox).sub(&D::from_f64(q.x, lox));
    let dy = |p: DVec2, q: DVec2| D::from_f64(p.y, loy).sub(&D::from_f64(q.y, loy));
    let left = FixedInt::<DEG2>::mul(&dx(b, a), &dy(c, a));
    let right = FixedInt::<DEG2>::mul(&dy(b, a), &dx(c, a));
    left.sub(&right)
}

/// The big-integer stage alone, exact for every finite input: the
/// reference the other stages' tests compare with.
#[cfg(test)]
pub(super) fn dense(a: DVec2, b: DVec2, c: DVec2) -> Sign {
    let gx = Grain::of(&[a.x, b.x, c.x]);
    let gy = Grain::of(&[a.y, b.y, c.y]);
    if gx.all_zero() || gy.all_zero() {
        return Sign::Zero;
    }
    big_integer(a, b, c, gx.lo_min, gy.lo_min)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{InputClass, SplitMix64, orient2d_case, step_ulps};

    #[test]
    fn unit_integer_is_exact_or_declines() {
        let mut rng = SplitMix64::new(77);
        let mut answered = 0;
        for i in 0..120_000 {
            let [mut a, mut b, mut c] = orient2d_case(InputClass::ALL[i % 6], &mut rng);
            // Now and then, values at the edges of the quick stage's range:
            // just below and at `2^62`, subnormal, signed zeros.
            match i % 7 {
                0 => a.x = step_ulps(pow2(62), -((i / 7) as i64 % 3)),
                1 => b.y = -0.0,
                2 => c = DVec2::new(f64::from_bits(i as u64 % 5), -f64::from_bits(3)),
                _ => {}
            }
            let (detleft, detright) = (products(a, b, c).x, products(a, b, c).y);
            let (_, detsum, _) = stage_a_lanes(detleft, detright);
            if let Some(sign) = unit_integer(a, b, c, detsum) {
                answered += 1;
                assert_eq!(sign, dense(a, b, c), "{a} {b} {c}");
            }
            assert_eq!(declined(a, b, c, detsum), dense(a, b, c), "{a} {b} {c}");
        }
        assert!(answered > 50_000, "{answered}");
    }

    #[test]
    fn unit_integer_turns_away_non_finite() {
        let p = DVec2::new(1.0, 2.0);
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let q = DVec2::new(bad, 0.5);
            assert_eq!(unit_integer(p, q, p, bad), None);
            assert_eq!(orient2d(p, q, DVec2::ZERO), Sign::Zero);
        }
    }
}
