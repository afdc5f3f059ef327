//! orient3d: the sign of `det[b - a, c - a, d - a]`, exact for every finite
//! input (CGAL's convention, minus Shewchuk's).
//!
//! Stage ladder (see the [module docs](super)): 0 semi-static filter, 1
//! filtered, 2 small-integer exact (and the lattice stage), 3 adaptive
//! (Shewchuk's, `adaptive.rs`), 4 scaled filter, 5 big-integer exact.

use super::adaptive;
use super::det::{A, certifies, det3_wide, determinant, small_det3, stage_a_rows};
use super::sparse::{det3, det3_terms};
use crate::arith::exponent::{
    Grain, TINY, below_lattice, in_range, lowest_bit, pow2, scale_pow2, unit_integers, unit_scale,
};
use crate::arith::fixed_int::{DEG1, DEG2, DEG3, FixedInt};
use crate::arith::lanes::Lanes;
use crate::arith::magnitude::{all_within, larger, larger3};
use crate::arith::scaled_float::ScaledFloat;
use crate::arith::sparse_sum::{diff, value_of_sum};
use crate::sign::Sign;
use glam::DVec3;

/// Span (per axis) of the small-integer stage: coordinates below `2^61`,
/// differences below `2^62` (one limb), 2x2 minors below `2^125` (two),
/// the determinant below `3 * 2^187 < 2^189` (three).
const SMALL_SPAN: i32 = 61;

/// Span (per axis) up to which [`rounded_determinant`] uses two-limb
/// differences: coordinates below `2^125`, differences below `2^126` (two
/// limbs, signed), minors below `2^253` (four), the determinant below `3 *
/// 2^379 < 2^381` (six).
const MEDIUM_SPAN: i32 = 125;

/// Span (per axis) up to which Shewchuk's adaptive stages are exact once
/// each axis is scaled below 1: every non-zero value of degree `j <= 3`
/// they form is a multiple of `2^(-j * span)`, hence at least `2^-900`, so
/// nothing underflows (2^-100 to spare for the error-bound products).
const ADAPTIVE_SPAN: i32 = 300;

/// Extra absolute error of the scaled filter: scaled coordinates are off by
/// at most `2^-1074`, differences (below 2) by `2^-1073`; each of the six
/// triple products moves by at most `3 * 4 * 2^-1073`, in all
/// `72 * 2^-1073 < 2^-1066`. `2^-1064` leaves a factor 4.
const SCALED_SLACK: f64 = 1024.0 * TINY;

/// Factor of the semi-static bound, `6 A (1 + 2^-40)` (see `semi_static`).
const SEMI_STATIC: f64 = 6.0 * A * (1.0 + 1.0 / (1u64 << 40) as f64);

/// Range of the per-axis largest differences within which the semi-static
/// filter runs: `[2^-290, 2^290]` (see `semi_static`).
const SEMI_STATIC_MIN: f64 = pow2(-290);
const SEMI_STATIC_MAX: f64 = pow2(290);

#[inline(always)]
pub(super) fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Sign {
    match semi_static(a, b, c, d) {
        Ok(s) => s,
        Err(semi) => semi_declined(a.to_array(), b.to_array(), c.to_array(), d.to_array(), semi),
    }
}

/// Stages 1 to 5 for an input the semi-static filter declined: a computed
/// determinant of exactly zero (in range), which stage 1 cannot certify
/// either, goes straight to the exact stages.
#[inline(never)]
fn semi_declined(
    a: [f64; 3],
    b: [f64; 3],
    c: [f64; 3],
    d: [f64; 3],
    semi: Option<[f64; 3]>,
) -> Sign {
    let [a, b, c, d] = [a, b, c, d].map(DVec3::from_array);
    let permanent = match semi {
        Some([0.0, permanent, bound]) => {
            // The lattice stage: every term of the determinant is a
            // product of one difference per axis, each a multiple of that
            // axis's finest bit, so the determinant is a multiple of
            // `2^lattice`; the semi-static bound held (in range), and one
            // below a lattice step proves the zero (`below_lattice`).
            let lattice = [
                [a.x, b.x, c.x, d.x],
                [a.y, b.y, c.y, d.y],
                [a.z, b.z, c.z, d.z],
            ]
            .iter()
            .fold(0i32, |l, axis| l.saturating_add(lowest_bit(axis)));
            if below_lattice(bound, lattice) {
                return Sign::Zero;
            }
            permanent
        }
        _ => match filtered(a, b, c, d, 0.0) {
            Ok(s) => return s,
            Err(permanent) => permanent,
        },
    };
    stages_2_to_5(&[a, b, c, d], permanent)
}

/// Stages 2 to 5 for an input stage 1 declined, given its permanent, out
/// of line (the batch variant's entry for lanes whose determinant is not
/// zero).
#[inline(never)]
pub(super) fn declined(p: &[DVec3; 4], permanent: f64) -> Sign {
    stages_2_to_5(p, permanent)
}

/// The whole ladder, out of line (the batch variant's entry for lanes whose
/// determinant stage 1 computed as zero: the lattice stage takes those).
#[inline(never)]
pub(super) fn from_the_start(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Sign {
    orient3d(a, b, c, d)
}

/// Stages 2 to 5: the quick integer entry (`unit_integer`), which answers
/// almost every in-range input that reaches it, then the cold ladder.
#[inline(always)]
fn stages_2_to_5(p: &[DVec3; 4], permanent: f64) -> Sign {
    if in_range(permanent)
        && let Some(sign) = unit_integer(p)
    {
        return sign;
    }
    exact(p, in_range(permanent))
}

/// Stage 0, the semi-static filter: stage 1's determinant with a bound
/// from the largest difference on each axis, `X`, `Y`, `Z`, rather than
/// from the permanent. When it cannot certify the sign: `Err(Some([det,
/// 6 X Y Z, bound]))` in range, `Err(None)` out of range.
///
/// Bound. Each 2x2 permanent `|x y'| + |x' y|` is at most `2 X Y`, so the
/// permanent of stage 1 is at most `3 Z 2 X Y = 6 X Y Z` exactly, and as
/// computed at most `(1 + gamma(6))` times that; stage 1's bound `A` times
/// it is at most `6 A (1 + gamma(6)) X Y Z`. `SEMI_STATIC`'s `2^-40`
/// covers `gamma(6)`, the three roundings of `fl(SEMI_STATIC X Y Z)` and
/// the underflow below many times over.
///
/// Range. With every per-axis largest difference in `[2^-290, 2^290]`
/// nothing overflows (terms below `2^871`), `6 X Y Z` lies in `[2^-870,
/// 2^873]` (within `in_range`), and a product that underflows is off by
/// `2^-1075` absolutely: a minor's, times a `z` of at most `Z`, is below
/// `2^-400` of the bound, a final one below `2^-150` of it (the bound is
/// at least `2^-48 * 2^-870`).
#[inline(always)]
fn semi_static(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Result<Sign, Option<[f64; 3]>> {
    let [a, b, c, d] = [a, b, c, d].map(|p| p.to_array());
    let rel = |p: [f64; 3]| DVec3::new(p[0] - a[0], p[1] - a[1], p[2] - a[2]);
    let (bb, cc, dd) = (rel(b), rel(c), rel(d));
    let m = larger3(larger3(bb.abs(), cc.abs()), dd.abs());
    let in_range = all_within(m, SEMI_STATIC_MIN, SEMI_STATIC_MAX);
    let det = determinant(bb.to_array(), cc.to_array(), dd.to_array());
    let permanent = m.x * m.y * m.z;
    let bound = SEMI_STATIC * permanent;
    if !in_range {
        Err(None)
    } else if det > bound {
        Ok(Sign::Positive)
    } else if -det > bound {
        Ok(Sign::Negative)
    } else {
        Err(Some([det, 6.0 * permanent, bound]))
    }
}

/// Stage 1: the `f64` determinant expanded along z, certified by a forward
/// error bound. `Err(permanent)` when the bound cannot certify the sign.
#[inline(always)]
fn filtered(a: DVec3, b: DVec3, c: DVec3, d: DVec3, extra_slack: f64) -> Result<Sign, f64> {
    let (det, permanent, certified) = stage_a(a, b, c, d, extra_slack);
    if certified {
        Ok(Sign::of_f64(det))
    } else {
        Err(permanent)
    }
}

/// Stage 1 without branches: the `f64` determinant, its permanent, and
/// whether the bound certifies the determinant's sign (`false` for
/// non-finite input).
#[inline(always)]
fn stage_a(a: DVec3, b: DVec3, c: DVec3, d: DVec3, extra_slack: f64) -> (f64, f64, bool) {
    let [a, b, c, d] = [a, b, c, d].map(|p| p.to_array());
    let (det, permanent, margin, zsum) = stage_a_lanes(a, b, c, d);
    (det, permanent, certifies(margin, zsum, extra_slack))
}

/// Stage 1 on one case (`T = f64`) or a block of them (the batch
/// variants): the determinant expanded along z, its permanent, the margin
/// `(|det| - A * permanent) * 2^1000` and `|Bz| + |Cz| + |Dz|`, for
/// [`certifies`]. The same operations in the same order whatever `T`, so
/// one bound covers both.
#[inline(always)]
pub(super) fn stage_a_lanes<T: Lanes>(a: [T; 3], b: [T; 3], c: [T; 3], d: [T; 3]) -> (T, T, T, T) {
    let rel = |p: [T; 3]| [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    stage_a_rows(rel(b), rel(c), rel(d))
}

/// Stage 2: each axis as integers below `2^SMALL_SPAN` at its own scale,
/// found without counting bits (`unit_integers`), the determinant in
/// `small_det3`; `None` when an axis spans more bits.
#[inline(always)]
fn unit_integer(p: &[DVec3; 4]) -> Option<Sign> {
    let axis = |v: [f64; 4]| {
        let max = larger(
            larger(v[0].abs(), v[1].abs()),
            larger(v[2].abs(), v[3].abs()),
        );
        unit_integers(&v, max, SMALL_SPAN)
    };
    let (x, _) = axis(p.map(|v| v.x))?;
    let (y, _) = axis(p.map(|v| v.y))?;
    let (z, _) = axis(p.map(|v| v.z))?;
    let rel = |i: usize| [x[i] - x[0], y[i] - y[0], z[i] - z[0]];
    Some(small_det3([rel(1), rel(2), rel(3)]))
}

/// Stages 2 to 5, for the few inputs the filter cannot certify.
#[cold]
#[inline(never)]
fn exact(points: &[DVec3; 4], in_range: bool) -> Sign {
    let [a, b, c, d] = *points;
    if !points.iter().all(|p| p.is_finite()) {
        return Sign::Zero;
    }
    let axis = |k: usize| [a[k], b[k], c[k], d[k]];
    let scaled = || {
        let scale = [
            unit_scale(&axis(0)),
            unit_scale(&axis(1)),
            unit_scale(&axis(2)),
        ];
        let s = |p: DVec3| {
            DVec3::new(
                scale_pow2(p.x, scale[0]),
                scale_pow2(p.y, scale[1]),
                scale_pow2(p.z, scale[2]),
            )
        };
        [s(a), s(b), s(c), s(d)]
    };
    // Tiny, huge and mixed inputs: most are far from degenerate once scaled.
    let scaled_filter = |s: [DVec3; 4]| filtered(s[0], s[1], s[2], s[3], SCALED_SLACK).ok();
    if !in_range && let Some(sign) = scaled_filter(scaled()) {
        return sign;
    }
    // (In range, `declined` has tried it.)
    if !in_range && let Some(sign) = unit_integer(points) {
        return sign;
    }
    let grains = [
        Grain::of(&axis(0)),
        Grain::of(&axis(1)),
        Grain::of(&axis(2)),
    ];
    if grains.iter().any(|g| g.all_zero()) {
        return Sign::Zero;
    }
    let lo = grains.map(|g| g.lo_min);
    // Every span is more than `SMALL_SPAN` here (`unit_integer` declined).
    let span = grains.iter().map(|g| g.span()).max().unwrap_or(0);
    let s = scaled();
    if span <= ADAPTIVE_SPAN
        && let Some(sign) = adaptive::orient3d(s[0], s[1], s[2], s[3])
    {
        return sign;
    }
    if in_range && let Some(sign) = scaled_filter(s) {
        return sign;
    }
    sparse_sign(a, b, c, d).unwrap_or_else(|| integer::<DEG1, DEG2, DEG3>(points, lo))
}

/// Stage 5, first: the exact sign of `det[b - a, c - a, d - a]` for finite input, or `None`
/// when the terms do not fit the accumulators.
pub(super) fn sparse_sign(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Option<Sign> {
    let rel = |p: DVec3| [diff(p.x, a.x), diff(p.y, a.y), diff(p.z, a.z)];
    det3(rel(b), rel(c), rel(d))
}

/// `det[b - a, c - a, d - a]` within a relative `2^-52`, from the terms of
/// [`sparse_sign`], or `None` when they do not fit.
fn sparse_value([a, b, c, d]: &[DVec3; 4]) -> Option<ScaledFloat> {
    let rel = |p: DVec3| [diff(p.x, a.x), diff(p.y, a.y), diff(p.z, a.z)];
    value_of_sum(&mut det3_terms(rel(*b), rel(*c), rel(*d)))
}

/// Stage 5: each axis as integers at its finest bit `lo[axis]`, the
/// determinant in `D`-limb differences, `M`-limb minors and an `R`-limb
/// result. `<34, 67, 100>` holds every finite input: coordinates below `2^2098` (a finite `f64` over its
/// finest possible bit `2^-1074`), differences below `2^2099`, minors below
/// `2^4199`, the determinant below `2^6300`.
pub(super) fn integer<const D: usize, const M: usize, const R: usize>(
    p: &[DVec3; 4],
    lo: [i32; 3],
) -> Sign {
    integer_det::<D, M, R>(p, lo).sign()
}

/// `det[b - a, c - a, d - a]` within a relative `2^-52`, with an unbounded
/// exponent, for finite input: where every span is within `SMALL_SPAN`,
/// the integers of [`integer`] at each axis's finest bit in one limb per
/// difference (two within `MEDIUM_SPAN`), rounded once by
/// [`FixedInt::as_extended`]; otherwise the
/// sparse terms of [`sparse_sign`] ([`value_of_sum`]), or the wide
/// integers where those do not fit.
pub(super) fn rounded_determinant(p: &[DVec3; 4]) -> ScaledFloat {
    let axis = |k: usize| [p[0][k], p[1][k], p[2][k], p[3][k]];
    let grains = [0, 1, 2].map(|k| Grain::of(&axis(k)));
    if grains.iter().any(|g| g.all_zero()) {
        return ScaledFloat::ZERO;
    }
    let lo = grains.map(|g| g.lo_min);
    let unit = lo[0] + lo[1] + lo[2];
    if grains.iter().all(|g| g.span() <= SMALL_SPAN) {
        integer_det::<1, 2, 3>(p, lo).as_extended(unit)
    } else if grains.iter().all(|g| g.span() <= MEDIUM_SPAN) {
        integer_det::<2, 4, 6>(p, lo).as_extended(unit)
    } else {
        sparse_value(p).unwrap_or_else(|| integer_det::<DEG1, DEG2, DEG3>(p, lo).as_extended(unit))
    }
}

/// The determinant of [`integer`], in units of `2^(lo[0] + lo[1] + lo[2])`.
fn integer_det<const D: usize, const M: usize, const R: usize>(
    p: &[DVec3; 4],
    lo: [i32; 3],
) -> FixedInt<R> {
    let int = |v: DVec3| {
        [
            FixedInt::<D>::from_f64(v.x, lo[0]),
            FixedInt::from_f64(v.y, lo[1]),
            FixedInt::from_f64(v.z, lo[2]),
        ]
    };
    let a = int(p[0]);
    let rel = |v: DVec3| {
        let q = int(v);
        [q[0].sub(&a[0]), q[1].sub(&a[1]), q[2].sub(&a[2])]
    };
    det3_wide::<D, M, R>(&[rel(p[1]), rel(p[2]), rel(p[3])])
}

/// The big-integer stage alone, exact for every finite input: the
/// reference the other stages' tests compare with.
#[cfg(test)]
pub(super) fn dense(p: [DVec3; 4]) -> Sign {
    let axis = |k: usize| [p[0][k], p[1][k], p[2][k], p[3][k]];
    let g = [0, 1, 2].map(|k| Grain::of(&axis(k)));
    if g.iter().any(|g| g.all_zero()) {
        return Sign::Zero;
    }
    integer::<DEG1, DEG2, DEG3>(&p, g.map(|g| g.lo_min))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{InputClass, SplitMix64, orient3d_case};

    /// Inputs whose per-axis largest differences sit at the edges of the
    /// semi-static filter's range (`2^-290`, `2^290`), some with a
    /// coordinate so small that its products underflow, against the dense
    /// integers.
    #[test]
    fn semi_static_range_edges() {
        let mut rng = SplitMix64::new(41);
        for i in 0..40_000 {
            let mut p = orient3d_case(InputClass::ALL[i % 3], &mut rng);
            for k in 0..3 {
                let e = if i % 2 == 0 { -291 } else { 288 } + (rng.next_u64() % 4) as i32;
                p.iter_mut().for_each(|v| v[k] = scale_pow2(v[k], e));
            }
            if i % 5 == 0 {
                let (j, k) = ((rng.next_u64() % 4) as usize, (rng.next_u64() % 3) as usize);
                p[j][k] = scale_pow2(p[j][k], -700);
            }
            assert_eq!(orient3d(p[0], p[1], p[2], p[3]), dense(p), "{p:?}");
        }
    }
}
