//! Shewchuk's adaptive middle stages of the four classic predicates, on
//! inputs each predicate has scaled by powers of two (Shewchuk 1997,
//! "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
//! Predicates", *Discrete & Computational Geometry* 18, section 6 and its
//! `predicates.c`).
//!
//! Each predicate's stage A (its own filter, in its file) has declined
//! before these run. Then, in order:
//! - **rounded differences**: the determinant of the rounded coordinate
//!   differences, computed exactly as an expansion; it differs from the
//!   true determinant only through the differences' rounding, which a
//!   bound `B * permanent` covers;
//! - **exact differences**: when no difference rounded, that expansion *is*
//!   the determinant, and its sign is exact;
//! - **first-order tails**: the estimate plus the first-order terms of the
//!   differences' rounding errors, with the bound `C * permanent +
//!   RESULT * |det|` on what remains;
//! - orient2d only, **exact**: the three tail products added exactly, the
//!   sign of the full expansion.
//!
//! Every bound assumes no underflow or overflow. The callers guarantee
//! more: they run these stages only on inputs whose axes were scaled so
//! their largest coordinate is below 1 and whose span (the bits between
//! the finest and the coarsest set bit of an axis) is small enough that
//! every non-zero value these stages form is at least `2^-900` (each
//! predicate's `ADAPTIVE_SPAN`). Every operation here is then exact where
//! it claims to be. `None` means "not decided here": the caller's exact
//! stages follow.

use crate::arith::error_free::two_sum;
use crate::arith::expansion::Expansion;
use crate::arith::roundoff::U;
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// Shewchuk's `resulterrbound = (3 + 8 eps) eps`: the first-order stage
/// adds its correction to the stage B estimate, which is itself within
/// `eps |det|` of the expansion it sums (the estimate of a nonoverlapping
/// expansion), and the addition rounds once more; `3 eps` covers these
/// and the rounding of the bound, relative to `|det|` (Shewchuk 1997,
/// section 6, "resulterrbound").
const RESULT: f64 = (3.0 + 8.0 * U) * U;

// Stage B bounds. Each difference rounded to `f64` is within `eps` of
// itself (`eps = 2^-53`, no underflow), so a product of `k` of them is
// within `(1 + eps)^k - 1 = k eps + O(eps^2)` of the product of the exact
// differences; the expansion of the rounded differences is computed
// exactly, so the determinant's error is at most that times the permanent
// (the sum of its terms' magnitudes). The `O(eps^2)` coefficient also
// covers the rounding of the permanent and of the estimate (Shewchuk
// 1997, section 6: `ccwerrboundB`, `o3derrboundB`, `iccerrboundB`,
// `isperrboundB`).

/// orient2d's stage B, degree 2: Shewchuk's `ccwerrboundB = (2 + 12 eps)
/// eps`.
const O2_B: f64 = (2.0 + 12.0 * U) * U;
/// orient3d's stage B, degree 3: `o3derrboundB = (3 + 28 eps) eps`.
const O3_B: f64 = (3.0 + 28.0 * U) * U;
/// incircle's stage B, degree 4: `iccerrboundB = (4 + 48 eps) eps`.
const IC_B: f64 = (4.0 + 48.0 * U) * U;
/// insphere's stage B, degree 5: `isperrboundB = (5 + 72 eps) eps`.
const IS_B: f64 = (5.0 + 72.0 * U) * U;

// First-order stage bounds. Writing each exact difference as its rounded
// value plus its tail (`|tail| <= eps |rounded|`), the determinant is the
// stage B expansion, plus the terms linear in the tails (the correction,
// evaluated in `f64`), plus the terms of degree two and more in the tails.
// The latter are at most `C(k, 2) eps^2` (and higher powers) times the
// permanent; the correction's own rounding errors are `eps` times
// first-order terms, also `O(eps^2)` times the permanent. Shewchuk's
// constants sum both (Shewchuk 1997, section 6: `ccwerrboundC`,
// `o3derrboundC`, `iccerrboundC`, `isperrboundC`); the estimate's error is
// `RESULT |det|`, added at the use.

/// orient2d's first-order stage: `ccwerrboundC = (9 + 64 eps) eps^2`.
const O2_C: f64 = (9.0 + 64.0 * U) * U * U;
/// orient3d's first-order stage: `o3derrboundC = (26 + 288 eps) eps^2`.
const O3_C: f64 = (26.0 + 288.0 * U) * U * U;
/// incircle's first-order stage: `iccerrboundC = (44 + 576 eps) eps^2`.
const IC_C: f64 = (44.0 + 576.0 * U) * U * U;
/// insphere's first-order stage: `isperrboundC = (71 + 1408 eps) eps^2`.
const IS_C: f64 = (71.0 + 1408.0 * U) * U * U;

/// The sign of a value computed within `bound` of the determinant, when
/// the bound certifies it.
#[inline(always)]
fn certified(det: f64, bound: f64) -> Option<Sign> {
    (det.abs() > bound).then(|| Sign::of_f64(det))
}

/// `p - o` on each axis, rounded, and the rounding errors (`two_sum`'s,
/// exact without overflow).
#[inline(always)]
fn differences<const D: usize>(p: [f64; D], o: [f64; D]) -> ([f64; D], [f64; D]) {
    let d: [(f64, f64); D] = core::array::from_fn(|k| two_sum(p[k], -o[k]));
    (d.map(|x| x.0), d.map(|x| x.1))
}

/// Whether every rounding error is zero: the differences are exact.
#[inline(always)]
fn exact_differences<const D: usize>(tails: &[[f64; D]]) -> bool {
    tails.iter().flatten().all(|&t| t == 0.0)
}

/// The sign of `(b - a) x (c - a)` (orient2d) on scaled input, exact:
/// Shewchuk's `orient2dadapt`, with `c` as the origin.
pub(super) fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Sign {
    let ([acx, acy], [acxt, acyt]) = differences(a.to_array(), c.to_array());
    let ([bcx, bcy], [bcxt, bcyt]) = differences(b.to_array(), c.to_array());
    let detsum = (acx * bcy).abs() + (acy * bcx).abs();
    // Rounded differences.
    let rounded = Expansion::product_difference(acx, bcy, acy, bcx);
    let det = rounded.estimate();
    if let Some(sign) = certified(det, O2_B * detsum) {
        return sign;
    }
    if exact_differences(&[[acxt, acyt, bcxt, bcyt]]) {
        return rounded.sign();
    }
    // First-order tails.
    let bound = O2_C * detsum + RESULT * det.abs();
    let corrected = det + ((acx * bcyt + bcy * acxt) - (acy * bcxt + bcx * acyt));
    if let Some(sign) = certified(corrected, bound) {
        return sign;
    }
    // Exact: (acx + acxt)(bcy + bcyt) - (acy + acyt)(bcx + bcxt), the
    // rounded part above plus three exact tail parts.
    let tail1 = Expansion::product_difference(acxt, bcy, acyt, bcx);
    let tail2 = Expansion::product_difference(acx, bcyt, acy, bcxt);
    let tail3 = Expansion::product_difference(acxt, bcyt, acyt, bcxt);
    let sum: Expansion<8> = rounded.sum(&tail1);
    let sum: Expansion<12> = sum.sum(&tail2);
    let sum: Expansion<16> = sum.sum(&tail3);
    sum.sign()
}

/// The sign of `det[b - a, c - a, d - a]` (orient3d, CGAL's convention:
/// minus Shewchuk's) on scaled input, or `None`: Shewchuk's
/// `orient3dadapt` up to its first-order stage, with `d` as the origin.
pub(super) fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Option<Sign> {
    let o = d.to_array();
    let ([adx, ady, adz], at) = differences(a.to_array(), o);
    let ([bdx, bdy, bdz], bt) = differences(b.to_array(), o);
    let ([cdx, cdy, cdz], ct) = differences(c.to_array(), o);
    let permanent = ((bdx * cdy).abs() + (cdx * bdy).abs()) * adz.abs()
        + ((cdx * ady).abs() + (adx * cdy).abs()) * bdz.abs()
        + ((adx * bdy).abs() + (bdx * ady).abs()) * cdz.abs();
    // Rounded differences: Shewchuk's determinant, expanded along z.
    let bc = Expansion::product_difference(bdx, cdy, cdx, bdy);
    let ca = Expansion::product_difference(cdx, ady, adx, cdy);
    let ab = Expansion::product_difference(adx, bdy, bdx, ady);
    let (adet, bdet, cdet): (Expansion<8>, Expansion<8>, Expansion<8>) =
        (bc.scaled(adz), ca.scaled(bdz), ab.scaled(cdz));
    let abdet: Expansion<16> = adet.sum(&bdet);
    let rounded: Expansion<24> = abdet.sum(&cdet);
    let det = rounded.estimate();
    let shewchuk = certified(det, O3_B * permanent).or_else(|| {
        if exact_differences(&[at, bt, ct]) {
            return Some(rounded.sign());
        }
        // First-order tails.
        let bound = O3_C * permanent + RESULT * det.abs();
        let first = |u: [f64; 3], ut: [f64; 3], v: [f64; 3], vt: [f64; 3], w: [f64; 3], wt: f64| {
            // w_z (u_x v_y - v_x u_y), differentiated.
            let [wz, wzt]: [f64; 2] = [w[2], wt];
            wz * ((u[0] * vt[1] + v[1] * ut[0]) - (u[1] * vt[0] + v[0] * ut[1]))
                + wzt * (u[0] * v[1] - u[1] * v[0])
        };
        let (a3, b3, c3) = ([adx, ady, adz], [bdx, bdy, bdz], [cdx, cdy, cdz]);
        let corrected = det
            + first(b3, bt, c3, ct, a3, at[2])
            + first(c3, ct, a3, at, b3, bt[2])
            + first(a3, at, b3, bt, c3, ct[2]);
        certified(corrected, bound)
    });
    shewchuk.map(|s| -s)
}

/// The sign of the in-circle determinant (`incircle`'s convention, which
/// is Shewchuk's) on scaled input, or `None`: Shewchuk's `incircleadapt`
/// up to its first-order stage, with `d` as the origin.
pub(super) fn incircle(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Option<Sign> {
    let o = d.to_array();
    let (ad, at) = differences(a.to_array(), o);
    let (bd, bt) = differences(b.to_array(), o);
    let (cd, ct) = differences(c.to_array(), o);
    let lift = |p: [f64; 2]| p[0] * p[0] + p[1] * p[1];
    let minor_abs = |u: [f64; 2], v: [f64; 2]| (u[0] * v[1]).abs() + (v[0] * u[1]).abs();
    let permanent =
        minor_abs(bd, cd) * lift(ad) + minor_abs(cd, ad) * lift(bd) + minor_abs(ad, bd) * lift(cd);
    // Rounded differences: sum over (u, v, w) cyclic of lift(u) (v x w).
    let lifted = |u: [f64; 2], v: [f64; 2], w: [f64; 2]| -> Expansion<32> {
        let minor = Expansion::product_difference(v[0], w[1], w[0], v[1]);
        let ux: Expansion<8> = minor.scaled(u[0]);
        let uy: Expansion<8> = minor.scaled(u[1]);
        let uxx: Expansion<16> = ux.scaled(u[0]);
        let uyy: Expansion<16> = uy.scaled(u[1]);
        uxx.sum(&uyy)
    };
    let ab: Expansion<64> = lifted(ad, bd, cd).sum(&lifted(bd, cd, ad));
    let rounded: Expansion<96> = ab.sum(&lifted(cd, ad, bd));
    let det = rounded.estimate();
    certified(det, IC_B * permanent).or_else(|| {
        if exact_differences(&[at, bt, ct]) {
            return Some(rounded.sign());
        }
        // First-order tails.
        let bound = IC_C * permanent + RESULT * det.abs();
        let first =
            |u: [f64; 2], ut: [f64; 2], v: [f64; 2], vt: [f64; 2], w: [f64; 2], wt: [f64; 2]| {
                let [vx, vy, vxt, vyt, wx, wy, wxt, wyt]: [f64; 8] =
                    [v[0], v[1], vt[0], vt[1], w[0], w[1], wt[0], wt[1]];
                lift(u) * ((vx * wyt + wy * vxt) - (vy * wxt + wx * vyt))
                    + 2.0 * (u[0] * ut[0] + u[1] * ut[1]) * (vx * wy - vy * wx)
            };
        let corrected = det
            + first(ad, at, bd, bt, cd, ct)
            + first(bd, bt, cd, ct, ad, at)
            + first(cd, ct, ad, at, bd, bt);
        certified(corrected, bound)
    })
}

/// The sign of the in-sphere determinant (`insphere`'s convention, CGAL's:
/// minus Shewchuk's) on scaled input, or `None`: Shewchuk's
/// `insphereadapt` up to its first-order stage, with `e` as the origin.
pub(super) fn insphere(p: &[DVec3; 5]) -> Option<Sign> {
    let o = p[4].to_array();
    let dt: [([f64; 3], [f64; 3]); 4] = core::array::from_fn(|i| differences(p[i].to_array(), o));
    let (d, t) = (dt.map(|x| x.0), dt.map(|x| x.1));
    let permanent = insphere_permanent(&d);
    // Shewchuk's determinant: sum over i of (-1)^(i + 1) lift_i M_i, M_i
    // the 3x3 determinant of the other three rows in order.
    let rounded = insphere_rounded(&d);
    let det = rounded.estimate();
    let shewchuk = certified(det, IS_B * permanent).or_else(|| {
        if exact_differences(&t) {
            return Some(rounded.sign());
        }
        // First-order tails: each term lift_i M_i differentiated.
        let bound = IS_C * permanent + RESULT * det.abs();
        let corrected = det
            + (0..4)
                .map(|i| {
                    let sign = if i % 2 == 1 { 1.0 } else { -1.0 };
                    let rows = others(i);
                    let lift = d[i].iter().map(|x| x * x).sum::<f64>();
                    let lift_tail: f64 = (0..3).map(|k| d[i][k] * t[i][k]).sum();
                    let minor = det3_rounded(rows.map(|r| d[r]));
                    let minor_tail = det3_first_order(rows.map(|r| (d[r], t[r])));
                    sign * (lift * minor_tail + 2.0 * lift_tail * minor)
                })
                .sum::<f64>();
        certified(corrected, bound)
    });
    shewchuk.map(|s| -s)
}

/// The three rows other than `i`, in order.
#[inline(always)]
fn others(i: usize) -> [usize; 3] {
    core::array::from_fn(|j| j + (j >= i) as usize)
}

/// The exact in-sphere determinant of rounded differences `d` (Shewchuk's
/// convention), as an expansion.
fn insphere_rounded(d: &[[f64; 3]; 4]) -> Expansion<1152> {
    let term = |i: usize| -> Expansion<288> {
        let [u, v, w] = others(i).map(|r| d[r]);
        let minor = det3_exact(u, v, w);
        let minor = if i % 2 == 1 { minor } else { minor.negated() };
        let x: Expansion<48> = minor.scaled(d[i][0]);
        let y: Expansion<48> = minor.scaled(d[i][1]);
        let z: Expansion<48> = minor.scaled(d[i][2]);
        let (xx, yy, zz): (Expansion<96>, Expansion<96>, Expansion<96>) =
            (x.scaled(d[i][0]), y.scaled(d[i][1]), z.scaled(d[i][2]));
        let xy: Expansion<192> = xx.sum(&yy);
        xy.sum(&zz)
    };
    let ab: Expansion<576> = term(0).sum(&term(1));
    let cd: Expansion<576> = term(2).sum(&term(3));
    ab.sum(&cd)
}

/// `det[u, v, w]` exactly, expanded along z.
fn det3_exact(u: [f64; 3], v: [f64; 3], w: [f64; 3]) -> Expansion<24> {
    let vw = Expansion::product_difference(v[0], w[1], w[0], v[1]);
    let wu = Expansion::product_difference(w[0], u[1], u[0], w[1]);
    let uv = Expansion::product_difference(u[0], v[1], v[0], u[1]);
    let (a, b, c): (Expansion<8>, Expansion<8>, Expansion<8>) =
        (vw.scaled(u[2]), wu.scaled(v[2]), uv.scaled(w[2]));
    let ab: Expansion<16> = a.sum(&b);
    ab.sum(&c)
}

/// `det[u, v, w]` in `f64`, expanded along z.
#[inline(always)]
fn det3_rounded([u, v, w]: [[f64; 3]; 3]) -> f64 {
    u[2] * (v[0] * w[1] - w[0] * v[1])
        + v[2] * (w[0] * u[1] - u[0] * w[1])
        + w[2] * (u[0] * v[1] - v[0] * u[1])
}

/// The first-order change of `det[u, v, w]` when each row `r` moves by its
/// tail `rt`, in `f64`.
#[inline(always)]
fn det3_first_order(rows: [([f64; 3], [f64; 3]); 3]) -> f64 {
    let [(u, ut), (v, vt), (w, wt)] = rows;
    let minor = |a: [f64; 3], b: [f64; 3]| a[0] * b[1] - b[0] * a[1];
    let minor_first = |a: [f64; 3], at: [f64; 3], b: [f64; 3], bt: [f64; 3]| {
        (a[0] * bt[1] + b[1] * at[0]) - (a[1] * bt[0] + b[0] * at[1])
    };
    (u[2] * minor_first(v, vt, w, wt) + ut[2] * minor(v, w))
        + (v[2] * minor_first(w, wt, u, ut) + vt[2] * minor(w, u))
        + (w[2] * minor_first(u, ut, v, vt) + wt[2] * minor(u, v))
}

/// Stage A's permanent of the in-sphere determinant of differences `d`
/// (the bound's scale: each term's product of absolute values).
fn insphere_permanent(d: &[[f64; 3]; 4]) -> f64 {
    (0..4)
        .map(|i| {
            let [u, v, w] = others(i).map(|r| d[r]);
            let m = |a: [f64; 3], b: [f64; 3]| (a[0] * b[1]).abs() + (b[0] * a[1]).abs();
            let minor = m(v, w) * u[2].abs() + m(w, u) * v[2].abs() + m(u, v) * w[2].abs();
            minor * d[i].iter().map(|x| x * x).sum::<f64>()
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::super::incircle::dense as incircle_dense;
    use super::super::insphere::dense as insphere_dense;
    use super::super::{orient2d as o2, orient3d as o3};
    use super::*;
    use crate::arith::exponent::{Grain, pow2, scale_pow2, unit_scale};
    use crate::testing::SplitMix64;

    /// A coordinate in `(-1, 1)` whose finest bit lies up to `span` bits
    /// below `2^-1`: full significands at scattered exponents, short ones,
    /// and zero.
    fn coord(rng: &mut SplitMix64, span: u64) -> f64 {
        let e = -((rng.next_u64() % (span - 52)) as i32) - 1;
        let m = match rng.next_u64() % 4 {
            0 => 0.0,
            1 => (rng.next_u64() % 16) as f64 / 16.0,
            _ => rng.next_f64(),
        };
        if rng.next_u64().is_multiple_of(2) {
            m * pow2(e)
        } else {
            -m * pow2(e)
        }
    }

    /// Points of `N` coordinates near-degenerate by construction: the
    /// last is a rounded affine combination of the others, moved now and
    /// then by a small power of two; every axis scaled as the predicates
    /// scale it before these stages.
    fn points<const N: usize, const D: usize>(rng: &mut SplitMix64, span: u64) -> [[f64; D]; N] {
        let mut p: [[f64; D]; N] = [[0.0; D]; N].map(|_| [(); D].map(|_| coord(rng, span)));
        let w: [f64; N] = core::array::from_fn(|_| rng.next_f64());
        let total: f64 = w[..N - 1].iter().sum();
        p[N - 1] = core::array::from_fn(|k| {
            let mix: f64 = (0..N - 1).map(|i| w[i] * p[i][k]).sum::<f64>() / total;
            match rng.next_u64() % 3 {
                0 => mix,
                1 => mix + pow2(-((rng.next_u64() % span) as i32) - 1),
                _ => p[N - 1][k],
            }
        });
        let scale: [i32; D] = core::array::from_fn(|k| unit_scale(&p.map(|q| q[k])));
        p.map(|q| core::array::from_fn(|k| scale_pow2(q[k], scale[k])))
    }

    /// Each stage against the dense integers, on scaled inputs whose spans
    /// stay within the predicates' `ADAPTIVE_SPAN`; every predicate decides
    /// a good share of them here.
    #[test]
    fn stages_match_dense_integers() {
        let mut rng = SplitMix64::new(1997);
        let mut decided = [0u32; 4];
        for _ in 0..20_000 {
            let p = points::<3, 2>(&mut rng, 440).map(DVec2::from_array);
            assert_eq!(
                orient2d(p[0], p[1], p[2]),
                o2::dense(p[0], p[1], p[2]),
                "{p:?}"
            );
            decided[0] += 1;
            let p = points::<4, 3>(&mut rng, 290).map(DVec3::from_array);
            if let Some(s) = orient3d(p[0], p[1], p[2], p[3]) {
                assert_eq!(s, o3::dense(p), "{p:?}");
                decided[1] += 1;
            }
            let p = points::<4, 2>(&mut rng, 220).map(DVec2::from_array);
            assert!(Grain::of(&p.map(|v| [v.x, v.y]).concat()).span() <= 225);
            if let Some(s) = super::incircle(p[0], p[1], p[2], p[3]) {
                assert_eq!(s, incircle_dense(p), "{p:?}");
                decided[2] += 1;
            }
            let p = points::<5, 3>(&mut rng, 175).map(DVec3::from_array);
            if let Some(s) = super::insphere(&p) {
                assert_eq!(s, insphere_dense(p), "{p:?}");
                decided[3] += 1;
            }
        }
        assert!(decided.iter().all(|&n| n > 10_000), "{decided:?}");
    }
}
