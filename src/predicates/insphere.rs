//! insphere: the sign of `-det[[a-e, |a-e|^2], ..., [d-e, |d-e|^2]]`,
//! positive when `e` is inside the sphere through `a, b, c, d` with
//! `orient3d(a, b, c, d) > 0` (CGAL's convention, minus Shewchuk's).
//! Exact for every finite input.
//!
//! Stage ladder (see the [module docs](super)): 0 semi-static filter, 1
//! filtered, 2 small-integer exact (and the lattice stage), 3 adaptive
//! (Shewchuk's, `adaptive.rs`), 4 scaled filter, 5 big-integer exact.

use super::adaptive;
use super::sparse::{
    Either, Expansion, Monomials, lifted_monomials, lifted_sign, lifted_value, product_terms,
    reference,
};
use crate::arith::exponent::{
    Grain, SmallInteger, TINY, below_lattice, in_range, lowest_bit, pow2, scale_pow2,
    small_integer, unit_scale,
};
use crate::arith::fixed_int::{DEG1, DEG2, DEG3, DEG5, FixedInt};
use crate::arith::lanes::Pair;
use crate::arith::magnitude::{all_within, larger, largest_abs, zero_or_at_least};
use crate::arith::scaled_float::ScaledFloat;
use crate::arith::sparse_sum::{Diff, diff};
use crate::sign::Sign;
use glam::DVec3;

/// Shewchuk's `isperrboundA = (16 + 224 eps) eps`, `eps = 2^-53`: with no
/// underflow, `|det_computed - det| <= A * permanent` (Shewchuk 1997,
/// insphere stage A), plus `2^-60` relative for the underflow that the
/// difference guard below admits.
const A: f64 = (16.0 + 224.0 * f64::EPSILON / 2.0) * (f64::EPSILON / 2.0) + GUARD_RELATIVE;

/// The filter on unscaled input runs only when every coordinate difference
/// is 0 or at least `2^-200`: every product of up to five differences is
/// then 0 or at least `2^-1000`, and a product that still underflows (after
/// a minor cancelled) is off by at most `2^-1075`, below `2^-75` of the
/// permanent term it belongs to. Fewer than 32 such terms: `2^-60`
/// relative covers them.
const GUARD_MIN_DIFF: f64 = pow2(-200);
const GUARD_RELATIVE: f64 = pow2(-60);

/// Span of the small-integer stage (one grain for all axes, since the lift
/// mixes them): coordinates below `2^60`, differences below `2^61` (one
/// limb), 2x2 minors below `2^123` and lifts below `2^124` (two), 3x3
/// minors below `2^186` (three), the determinant below `2^312` (five).
const SMALL_SPAN: i32 = 60;

/// Span up to which [`rounded_determinant`] uses two-limb differences:
/// coordinates below `2^125`, differences below `2^126` (two limbs,
/// signed), 2x2 minors below `2^253` and lifts below `3 * 2^252 < 2^254`
/// (four), 3x3 minors below `3 * 2^379 < 2^381` (six), the determinant
/// below `4 * 2^254 * 2^381 = 2^637` (ten).
const MEDIUM_SPAN: i32 = 125;

/// Span up to which Shewchuk's adaptive stages are exact once scaled below
/// 1: non-zero values of degree `j <= 5` are at least `2^-900`.
const ADAPTIVE_SPAN: i32 = 180;

/// Absolute error of the filter on inputs scaled below 1 (no difference
/// guard there). Differences are below 2, 2x2 minors below 8, 3x3 minors
/// below 48, lifts below 12. Underflowed products (each off by `2^-1075`):
/// 12 in 2x2 minors (then times a z below 2 and a lift below 12), 12 in 3x3
/// minors (times a lift), 12 squares (times a 3x3 minor below 48), 4 final:
/// about `1012 * 2^-1075 < 2^-1065`. Scaling error: differences off by
/// `2^-1073`, the determinant's derivative in one of them below 768; twelve
/// of them: `9216 * 2^-1073 < 2^-1059`. `2^-1050` leaves a factor over 300.
const SCALED_SLACK: f64 = 16777216.0 * TINY;

/// Factor of the semi-static bound, `24 A (1 + 2^-40)` (see
/// `semi_static`).
const SEMI_STATIC: f64 = 24.0 * A * (1.0 + 1.0 / (1u64 << 40) as f64);

/// Range of the per-axis largest differences within which the semi-static
/// filter runs: `[2^-190, 2^190]` (see `semi_static`).
const SEMI_STATIC_MIN: f64 = pow2(-190);
const SEMI_STATIC_MAX: f64 = pow2(190);

#[inline(always)]
pub(super) fn insphere(a: DVec3, b: DVec3, c: DVec3, d: DVec3, e: DVec3) -> Sign {
    match semi_static(a, b, c, d, e) {
        Ok(s) => s,
        Err(semi) => declined(&[a, b, c, d, e], semi),
    }
}

/// Stages 1 to 5 for an input the semi-static filter declined. A computed
/// determinant of exactly zero (in range) goes straight to the exact
/// stages, with the semi-static bound: stage 1 could not certify it
/// either.
#[inline(never)]
fn declined(p: &[DVec3; 5], semi: Option<(f64, Declined)>) -> Sign {
    if let Some((det, semi)) = semi
        && det == 0.0
    {
        // The lattice stage as in `small_integer`, with the finest bit of
        // the coordinates found directly: the determinant (degree 5) is a
        // multiple of `2^(5 lo)`, and the semi-static bound held.
        let coords = p.map(|v| v.to_array());
        let lo = lowest_bit(coords.as_flattened());
        if below_lattice(semi.bound, lo.saturating_mul(5)) {
            return Sign::Zero;
        }
        return exact(p[0], p[1], p[2], p[3], p[4], semi);
    }
    match filtered(p, None) {
        Ok(s) => s,
        Err(declined) => exact(p[0], p[1], p[2], p[3], p[4], declined),
    }
}

/// Stage 0, the semi-static filter: Shewchuk's stage A determinant with a
/// bound from the largest difference on each axis, `X`, `Y`, `Z`, rather
/// than from the permanent: fewer operations, a slightly larger bound.
/// When it cannot certify the sign: `Err(Some((det, declined)))` in range
/// (`declined` with the bound below and, as the permanent, the bound on it
/// `24 X Y Z S`), `Err(None)` out of range.
///
/// Bound. With `S = X^2 + Y^2 + Z^2`, each lift is at most `S`, each 2x2
/// permanent `|x y'| + |x' y|` at most `2 X Y`, each 3x3 permanent at most
/// `3 Z 2 X Y`, so the permanent of stage 1 (four lifts times 3x3
/// permanents) is at most `24 X Y Z S` exactly, and as computed at most
/// `(1 + gamma(12))` times that. Stage 1's bound, `A` times the permanent,
/// is then at most `24 A (1 + gamma(12)) X Y Z S`; `SEMI_STATIC`'s `2^-40`
/// covers `gamma(12)`, the seven roundings of `fl(SEMI_STATIC X Y Z S)`
/// and the underflow below, many times over.
///
/// Range. With every per-axis largest difference in `[2^-190, 2^190]`
/// nothing overflows (every term is below `24 * 2^950`), and a product
/// that underflows is off by `2^-1075` absolutely; carried to the
/// determinant by the factors after it (at most `Z S`, `S`, `6 X Y Z` or
/// 1), the worst, a final product's, is below `2^-78` of `24 A X Y Z S >=
/// 2^-44 * 2^-950`, the others far smaller, and fewer than 64 of them sum
/// below `2^-70` of the bound.
#[inline(always)]
fn semi_static(
    a: DVec3,
    b: DVec3,
    c: DVec3,
    d: DVec3,
    e: DVec3,
) -> Result<Sign, Option<(f64, Declined)>> {
    let rows = row_pairs(a - e, b - e, c - e, d - e);
    // The per-axis largest difference, `X`, `Y` and `Z`.
    let largest = |ac: Pair, bd: Pair| {
        let m = ac.abs().larger(bd.abs());
        larger(m.lo(), m.hi())
    };
    let m = DVec3::new(
        largest(rows[0], rows[1]),
        largest(rows[2], rows[3]),
        largest(rows[4], rows[5]),
    );
    let in_range = all_within(m, SEMI_STATIC_MIN, SEMI_STATIC_MAX);
    let det = lifted_det(rows);
    let permanent = (m.x * m.y * m.z) * m.length_squared();
    let bound = SEMI_STATIC * permanent;
    if !in_range {
        Err(None)
    } else if det > bound {
        Ok(Sign::Negative)
    } else if -det > bound {
        Ok(Sign::Positive)
    } else {
        let permanent = 24.0 * permanent;
        Err(Some((det, Declined { permanent, bound })))
    }
}

/// The rows `ae`, `be`, `ce`, `de` (each point minus `e`) as pairs: the x
/// of `ae` and `ce`, the x of `be` and `de`, then the same for y and z.
#[inline(always)]
fn row_pairs(ae: DVec3, be: DVec3, ce: DVec3, de: DVec3) -> [Pair; 6] {
    [
        Pair::new(ae.x, ce.x),
        Pair::new(be.x, de.x),
        Pair::new(ae.y, ce.y),
        Pair::new(be.y, de.y),
        Pair::new(ae.z, ce.z),
        Pair::new(be.z, de.z),
    ]
}

/// Shewchuk's stage A in-sphere determinant of the rows (as `row_pairs`),
/// expanded along the lift column, positive for "inside" under his
/// orientation convention, the opposite of ours; two lanes at a time (rows
/// `a`, `c` in one lane and `b`, `d` in the other, so SSE2 does two
/// operations in one), with the same operations on the same operands in
/// the same order as Shewchuk's scalar formula (robust's order, kept in
/// `robust_compat::insphere_first_stage`), so the same
/// value and the same error bound.
#[inline(always)]
fn lifted_det([xac, xbd, yac, ybd, zac, zbd]: [Pair; 6]) -> f64 {
    // [ab, cd], [bc, da], [ac, bd].
    let ab_cd = xac * ybd - xbd * yac;
    let bc_da = xbd * yac.swap() - xac.swap() * ybd;
    let ac_bd = xac.lows(xbd) * yac.highs(ybd) - xac.highs(xbd) * yac.lows(ybd);
    // [abc, cda] and [bcd, dab]; `[-ac, ac]` and `[-bd, bd]`.
    let (ac, bd) = (ac_bd.lo(), ac_bd.hi());
    let abc_cda = zac * bc_da + zbd * Pair::new(-ac, ac) + zac.swap() * ab_cd;
    let bcd_dab = zbd * ab_cd.swap() + zac.swap() * Pair::new(-bd, bd) + zbd.swap() * bc_da;
    // [al, cl] and [bl, dl].
    let (l_ac, l_bd) = (
        xac * xac + yac * yac + zac * zac,
        xbd * xbd + ybd * ybd + zbd * zbd,
    );
    // [dl abc - cl dab, bl cda - al bcd].
    let t = l_bd.swap() * abc_cda - l_ac.swap() * bcd_dab.swap();
    t.lo() + t.hi()
}

/// What a filter that declined computed: its permanent and its error bound
/// `A * permanent + slack`, both NaN when the difference guard declined.
#[derive(Clone, Copy)]
struct Declined {
    permanent: f64,
    bound: f64,
}

/// Stage 1 (and 4, on scaled input with `Some(slack)`): Shewchuk's stage A
/// determinant, certified by a forward error bound. With `None`, the
/// difference guard makes the bound hold under underflow instead.
#[inline(always)]
fn filtered(p: &[DVec3; 5], scaled_slack: Option<f64>) -> Result<Sign, Declined> {
    let (det, declined) = stage_a(p, scaled_slack);
    // Shewchuk's determinant is positive for "inside" under his opposite
    // orientation convention: ours is its negation.
    if det > declined.bound {
        Ok(Sign::Negative)
    } else if -det > declined.bound {
        Ok(Sign::Positive)
    } else {
        Err(declined)
    }
}

/// Stage 1 on unscaled input, for `robust_compat`: Shewchuk's stage A
/// determinant (robust's value: see [`lifted_det`]) and its error bound,
/// both NaN where the difference guard declines.
#[inline(always)]
pub(super) fn first_stage(p: &[DVec3; 5]) -> (f64, f64) {
    let (det, declined) = stage_a(p, None);
    (det, declined.bound)
}

/// Stage 1's determinant (Shewchuk's), its permanent and its bound `A *
/// permanent + slack`; all NaN when the difference guard declined.
#[inline(always)]
fn stage_a(p: &[DVec3; 5], scaled_slack: Option<f64>) -> (f64, Declined) {
    let e = p[4];
    let (ae, be, ce, de) = (p[0] - e, p[1] - e, p[2] - e, p[3] - e);
    let slack = match scaled_slack {
        None => {
            let m = ae
                .abs()
                .min(be.abs())
                .min(ce.abs())
                .min(de.abs())
                .min_element();
            let diffs = [ae, be, ce, de].map(|v| v.to_array());
            if (m < GUARD_MIN_DIFF || m.is_nan())
                && !zero_or_at_least(diffs.as_flattened(), GUARD_MIN_DIFF)
            {
                let nan = Declined {
                    permanent: f64::NAN,
                    bound: f64::NAN,
                };
                return (f64::NAN, nan);
            }
            0.0
        }
        Some(s) => s,
    };
    let det = lifted_det(row_pairs(ae, be, ce, de));
    let (al, bl, cl, dl) = (
        ae.length_squared(),
        be.length_squared(),
        ce.length_squared(),
        de.length_squared(),
    );
    let pm = |u: DVec3, v: DVec3| (u.x * v.y).abs() + (v.x * u.y).abs();
    let (abp, bcp, cdp, dap, acp, bdp) = (
        pm(ae, be),
        pm(be, ce),
        pm(ce, de),
        pm(de, ae),
        pm(ae, ce),
        pm(be, de),
    );
    let (az, bz, cz, dz) = (ae.z.abs(), be.z.abs(), ce.z.abs(), de.z.abs());
    let permanent = (cdp * bz + bdp * cz + bcp * dz) * al
        + (dap * cz + acp * dz + cdp * az) * bl
        + (abp * dz + bdp * az + dap * bz) * cl
        + (bcp * az + acp * bz + abp * cz) * dl;
    let bound = A * permanent + slack;
    (det, Declined { permanent, bound })
}

/// Stages 2 to 5, for the few inputs the filter cannot certify.
#[cold]
#[inline(never)]
fn exact(a: DVec3, b: DVec3, c: DVec3, d: DVec3, e: DVec3, stage1: Declined) -> Sign {
    let points = [a, b, c, d, e];
    let in_range = in_range(stage1.permanent);
    let coords: [f64; 15] = core::array::from_fn(|i| points[i / 3][i % 3]);
    let max = largest_abs(&coords);
    let scaled = || {
        let k = unit_scale(&[max]);
        points.map(|p| DVec3::new(scale_pow2(p.x, k), scale_pow2(p.y, k), scale_pow2(p.z, k)))
    };
    // Stage 2, and the lattice stage (`small_integer`), which needs stage
    // 1's bound: where that is NaN (its difference guard declined: tiny
    // inputs) or infinite, the scaled filter comes first.
    let small = stage1
        .bound
        .is_finite()
        .then(|| small_integer(&coords, max, SMALL_SPAN, 5, stage1.bound));
    if let Some(SmallInteger::Zero) = small {
        return Sign::Zero;
    }
    // (Non-finite input is never `SmallInteger::Zero`.)
    if !points.iter().all(|p| p.is_finite()) {
        return Sign::Zero;
    }
    // Tiny, huge and mixed inputs: most are far from degenerate once scaled.
    let scaled_filter = |s: [DVec3; 5]| filtered(&s, Some(SCALED_SLACK)).ok();
    if !in_range && let Some(sign) = scaled_filter(scaled()) {
        return sign;
    }
    let small = small.unwrap_or_else(|| small_integer(&coords, max, SMALL_SPAN, 5, f64::NAN));
    if let SmallInteger::Zero = small {
        return Sign::Zero;
    }
    if let SmallInteger::Integers(ints) = small {
        return integer::<1, 2, 3, 5>(|i| {
            [
                FixedInt::from_i64(ints[3 * i]),
                FixedInt::from_i64(ints[3 * i + 1]),
                FixedInt::from_i64(ints[3 * i + 2]),
            ]
        });
    }
    let grain = Grain::of(&coords);
    if grain.all_zero() {
        return Sign::Zero;
    }
    let s = scaled();
    if grain.span() <= ADAPTIVE_SPAN
        && let Some(sign) = adaptive::insphere(&s)
    {
        return sign;
    }
    if in_range && let Some(sign) = scaled_filter(s) {
        return sign;
    }
    sparse_sign(points)
        .unwrap_or_else(|| integer::<DEG1, DEG2, DEG3, DEG5>(at_grain(&points, grain.lo_min)))
}

/// Point `i`'s coordinates as integers in units of `2^lo`, for `integer`.
fn at_grain<const D: usize>(p: &[DVec3; 5], lo: i32) -> impl Fn(usize) -> [FixedInt<D>; 3] {
    move |i| {
        [
            FixedInt::from_f64(p[i].x, lo),
            FixedInt::from_f64(p[i].y, lo),
            FixedInt::from_f64(p[i].z, lo),
        ]
    }
}

/// Stage 5, first: the exact sign of the in-sphere determinant of `p` (as
/// `predicates::insphere`), for finite input, or `None` when its terms do
/// not fit the accumulators.
///
/// As for incircle's, with `det5` the lifted determinant of the rows `(x,
/// y, z, |.|^2, 1)`: `insphere` is minus its sign (CGAL's convention, minus
/// Shewchuk's), and it is either `(-1)^k det4`, `det4` the lifted 4x4
/// determinant of the other points minus point `k`, in order (72 products
/// of 5 differences), or expanded over the coordinates (120 permutations
/// times 3, 360 products), whichever has fewer terms.
pub(super) fn sparse_sign(p: [DVec3; 5]) -> Option<Sign> {
    let (expansion, negate) = sparse_expansion(&p);
    lifted_sign::<360, 5, 5>(expansion, negate).map(|s| -s)
}

/// `det5` (Shewchuk's in-sphere determinant: minus ours) within a relative
/// `2^-52`, from the terms of [`sparse_sign`], or `None` when they do not
/// fit.
fn sparse_value(p: &[DVec3; 5]) -> Option<ScaledFloat> {
    let (expansion, negate) = sparse_expansion(p);
    lifted_value::<360, 5, 5>(expansion, negate)
}

/// The expansion of `det5` [`sparse_sign`] sums, and whether its sum is
/// negated.
fn sparse_expansion(p: &[DVec3; 5]) -> (Either<InsphereTranslated, Monomials<5, 3>>, bool) {
    let coords = p.map(|v| [v.x, v.y, v.z]);
    let k = reference(&coords);
    let translated = insphere_translated(&coords, k);
    if product_terms(&translated) <= 360 {
        (Either::First(translated), k % 2 == 1)
    } else {
        (Either::Second(lifted_monomials::<5, 3>(&coords)), false)
    }
}

/// The products of `det4` with point `k` as the origin (see [`sparse_sign`]):
/// the lifted 4x4 determinant expanded along the lift column, the sum over
/// rows `i` of `(-1)^(i + 1) lift_i M(i)`, `M(i)` the 3x3 determinant of
/// the other three rows in order, each expanded along z as in `det3`.
pub(super) fn insphere_translated(p: &[[f64; 3]; 5], k: usize) -> InsphereTranslated {
    InsphereTranslated(core::array::from_fn(|i| {
        let q = p[i + (i >= k) as usize];
        core::array::from_fn(|c| diff(q[c], p[k][c]))
    }))
}

/// The rows of [`insphere_translated`].
pub(super) struct InsphereTranslated([[Diff; 3]; 4]);

impl Expansion<5> for InsphereTranslated {
    fn products(&self, push: &mut impl FnMut(bool, [Diff; 5])) {
        let rows = &self.0;
        for i in 0..4 {
            let o: [usize; 3] = core::array::from_fn(|j| j + (j >= i) as usize);
            for c in 0..3 {
                let sq = rows[i][c];
                for (u, v, w) in [(o[0], o[1], o[2]), (o[1], o[2], o[0]), (o[2], o[0], o[1])] {
                    let (u, v, w) = (rows[u], rows[v], rows[w]);
                    push(i % 2 == 0, [sq, sq, u[2], v[0], w[1]]);
                    push(i % 2 == 1, [sq, sq, u[2], w[0], v[1]]);
                }
            }
        }
    }
}

/// Stages 2 and 5: point `i`'s coordinates as integers `int(i)` (all at
/// one scale), with `D`-limb differences, `M`-limb 2x2 minors and lifts,
/// `T`-limb 3x3 minors, an `R`-limb result. Stage 2: `<1, 2, 3, 5>` (see
/// `SMALL_SPAN`). Stage 5: `<34, 67, 100, 166>`: differences below
/// `2^2099`, 2x2 minors and lifts below `2^4200`, 3x3 minors below
/// `2^6300`, the determinant below `2^10502`.
fn integer<const D: usize, const M: usize, const T: usize, const R: usize>(
    int: impl Fn(usize) -> [FixedInt<D>; 3],
) -> Sign {
    -integer_det::<D, M, T, R>(int).sign()
}

/// Shewchuk's in-sphere determinant of `p` (minus ours: positive for
/// "inside" under his orientation) within a relative `2^-52`, with an
/// unbounded exponent, for finite input: where the span is within
/// `SMALL_SPAN`, the integers of [`integer`] at the coordinates' finest
/// bit in one limb per difference (two within `MEDIUM_SPAN`), rounded once
/// by [`FixedInt::as_extended`]; otherwise the sparse terms of
/// [`sparse_sign`] ([`lifted_value`]), or the wide integers where those do
/// not fit.
pub(super) fn rounded_determinant(p: &[DVec3; 5]) -> ScaledFloat {
    let grain = Grain::of(p.map(|v| v.to_array()).as_flattened());
    if grain.all_zero() {
        return ScaledFloat::ZERO;
    }
    let unit = 5 * grain.lo_min;
    if grain.span() <= SMALL_SPAN {
        integer_det::<1, 2, 3, 5>(at_grain(p, grain.lo_min)).as_extended(unit)
    } else if grain.span() <= MEDIUM_SPAN {
        integer_det::<2, 4, 6, 10>(at_grain(p, grain.lo_min)).as_extended(unit)
    } else {
        sparse_value(p).unwrap_or_else(|| {
            integer_det::<DEG1, DEG2, DEG3, DEG5>(at_grain(p, grain.lo_min)).as_extended(unit)
        })
    }
}

/// `det[[r_i, lift_i]]` (Shewchuk's determinant) of [`integer`], in units
/// of the fifth power of the integers' unit.
fn integer_det<const D: usize, const M: usize, const T: usize, const R: usize>(
    int: impl Fn(usize) -> [FixedInt<D>; 3],
) -> FixedInt<R> {
    let e = int(4);
    let rel = |i: usize| {
        let q = int(i);
        [q[0].sub(&e[0]), q[1].sub(&e[1]), q[2].sub(&e[2])]
    };
    let r = [rel(0), rel(1), rel(2), rel(3)];
    let m2 = |i: usize, j: usize| {
        FixedInt::<M>::mul(&r[i][0], &r[j][1]).sub(&FixedInt::mul(&r[j][0], &r[i][1]))
    };
    // 3x3 minor of rows i, j, k expanded along z.
    let m3 = |i: usize, j: usize, k: usize| {
        FixedInt::<T>::mul(&r[i][2], &m2(j, k))
            .add(&FixedInt::mul(&r[j][2], &m2(k, i)))
            .add(&FixedInt::mul(&r[k][2], &m2(i, j)))
    };
    let lift = |i: usize| {
        FixedInt::<M>::mul(&r[i][0], &r[i][0])
            .add(&FixedInt::mul(&r[i][1], &r[i][1]))
            .add(&FixedInt::mul(&r[i][2], &r[i][2]))
    };
    // det[[r_i, lift_i]] expanded along the lift column.
    FixedInt::<R>::mul(&lift(1), &m3(0, 2, 3))
        .add(&FixedInt::mul(&lift(3), &m3(0, 1, 2)))
        .sub(&FixedInt::mul(&lift(0), &m3(1, 2, 3)))
        .sub(&FixedInt::mul(&lift(2), &m3(0, 1, 3)))
}

/// The big-integer stage alone, exact for every finite input: the
/// reference the other stages' tests compare with.
#[cfg(test)]
pub(super) fn dense(p: [DVec3; 5]) -> Sign {
    let grain = Grain::of(&p.map(|v| v.to_array()).concat());
    if grain.all_zero() {
        return Sign::Zero;
    }
    integer::<DEG1, DEG2, DEG3, DEG5>(at_grain(&p, grain.lo_min))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::predicates::robust_compat::insphere_first_stage;
    use crate::testing::{InputClass, SplitMix64, insphere_case, step_ulps};

    /// Cospherical lattice points (`2^2 + 3^2 + 6^2 = 7^2` and its
    /// permutations and signs, around a lattice centre), scaled by `2^k`
    /// over the whole exponent range, and the same with one coordinate
    /// moved by one lattice step or one ulp: zeros the lattice stage must
    /// certify, and non-zeros it must leave alone.
    #[test]
    fn lattice_zeros_and_their_neighbours() {
        let mut rng = SplitMix64::new(23);
        let (mut zeros, mut cases) = (0, 0);
        for i in 0..10_000 {
            let centre: [f64; 3] = core::array::from_fn(|_| (rng.next_u64() % 64) as f64 - 32.0);
            let mut p = [(); 5].map(|_| {
                let mut v =
                    [2.0, 3.0, 6.0, 7.0].map(|x| if rng.next_u64() & 1 == 0 { x } else { -x });
                // A point on the sphere of radius 7: a permutation of
                // (2, 3, 6), or (7, 0, 0).
                let r = (rng.next_u64() % 4) as usize;
                let w = if r == 3 {
                    [v[3], 0.0, 0.0]
                } else {
                    [v[0], v[1], v[2]]
                };
                v = [w[r % 3], w[(r + 1) % 3], w[(r + 2) % 3], 0.0];
                DVec3::new(centre[0] + v[0], centre[1] + v[1], centre[2] + v[2])
            });
            let k = (rng.next_u64() % 1600) as i32 - 800;
            let scale = |v: f64| v * pow2(k / 2) * pow2(k - k / 2);
            p = p.map(|v| DVec3::new(scale(v.x), scale(v.y), scale(v.z)));
            let (j, c) = ((rng.next_u64() % 5) as usize, (rng.next_u64() % 3) as usize);
            match i % 3 {
                1 => p[j][c] += scale(1.0),
                2 => p[j][c] = step_ulps(p[j][c], 1),
                _ => {}
            }
            let exact = dense(p);
            assert_eq!(insphere(p[0], p[1], p[2], p[3], p[4]), exact, "{p:?}");
            zeros += (exact == Sign::Zero) as u32;
            cases += 1;
        }
        assert!(zeros > cases / 4, "{zeros} of {cases}");
    }

    /// The paired determinant is the scalar formula's, to the bit.
    #[test]
    fn paired_determinant_is_the_scalar_one() {
        let mut rng = SplitMix64::new(8);
        for i in 0..60_000 {
            let [a, b, c, d, e] = insphere_case(InputClass::ALL[i % 6], &mut rng);
            let (ae, be, ce, de) = (a - e, b - e, c - e, d - e);
            let paired = lifted_det(row_pairs(ae, be, ce, de));
            let scalar = insphere_first_stage(a, b, c, d, e);
            // (NaN where something overflowed, its sign bit unspecified.)
            let same = paired.to_bits() == scalar.to_bits() || paired.is_nan() && scalar.is_nan();
            assert!(same, "{paired} {scalar}: {a} {b} {c} {d} {e}");
        }
    }

    #[test]
    fn every_class_matches_dense_integers() {
        let mut rng = SplitMix64::new(6);
        for i in 0..6_000 {
            let p = insphere_case(InputClass::ALL[i % 6], &mut rng);
            assert_eq!(insphere(p[0], p[1], p[2], p[3], p[4]), dense(p), "{p:?}");
        }
    }

    /// Inputs whose per-axis largest differences sit at the edges of the
    /// semi-static filter's range (`2^-190`, `2^190`), some with a
    /// coordinate so small that its products underflow, against the dense
    /// integers.
    #[test]
    fn semi_static_range_edges() {
        let mut rng = SplitMix64::new(43);
        for i in 0..6_000 {
            let mut p = insphere_case(InputClass::ALL[i % 3], &mut rng);
            let e = if i % 2 == 0 { -191 } else { 188 } + (rng.next_u64() % 4) as i32;
            p = p.map(|v| DVec3::new(scale_pow2(v.x, e), scale_pow2(v.y, e), scale_pow2(v.z, e)));
            if i % 5 == 0 {
                let (j, k) = ((rng.next_u64() % 5) as usize, (rng.next_u64() % 3) as usize);
                p[j][k] = scale_pow2(p[j][k], -700);
            }
            assert_eq!(insphere(p[0], p[1], p[2], p[3], p[4]), dense(p), "{p:?}");
        }
    }
}
