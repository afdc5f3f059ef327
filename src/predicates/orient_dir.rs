//! The exact tests of a ray against a triangle, on the original
//! coordinates: which side of the ray's line an edge passes
//! ([`orient_dir`]), and the parameter where the line meets the triangle's
//! plane, rounded from its exact value ([`plane_parameter`]).
//!
//! Both are determinants whose rows are a ray's direction `d` (an input
//! vector) or exact differences of input points: [`orient_dir`] runs the
//! orient3d ladder on such rows (filter, small-integer exact, sparse exact
//! terms, big-integer exact); [`plane_parameter`] evaluates its two
//! determinants exactly in integers and rounds their quotient.

use super::grain::{Grain, pow2, to_integer_i64};
use super::orient3d::{certifies, det3_wide, small_det3, stage_a_rows};
use super::sparse;
use super::wide::Wide;
use crate::sign::Sign;
use glam::DVec3;

/// Span (per axis) of the small-integer stage, as in orient3d: values
/// below `2^61`, differences below `2^62`.
const SMALL_SPAN: i32 = 61;

/// The exact sign of `det[d, p - o, q - o]`, for finite input (`Zero` for a
/// NaN or infinite coordinate).
///
/// For a ray `o + t d` and a triangle edge `p -> q`, it is positive when
/// the edge turns counterclockwise about the ray's line as seen from ahead
/// of the ray (looking back along `-d`), and zero when the line meets the
/// edge's line (or is parallel to it): the three signs for the edges
/// `v1 v2`, `v2 v0`, `v0 v1` are the signs of the barycentric coordinates
/// of the line's crossing of the plane, times the sign of `det[d, v1 - v0,
/// v2 - v0]`.
#[inline]
pub(crate) fn orient_dir(d: DVec3, o: DVec3, p: DVec3, q: DVec3) -> Sign {
    // det[d, p - o, q - o] = det[d, p - o, q - p]: a row as long as the
    // edge, not as the distance to the origin, keeps the filter's bound
    // small for far origins.
    let (det, _, margin, zsum) = stage_a_rows(d.to_array(), (p - o).to_array(), (q - p).to_array());
    if certifies(margin, zsum, 0.0) {
        Sign::of_f64(det)
    } else {
        exact(d, o, p, q)
    }
}

/// Each axis's finest bit and the widest span, over the given values per
/// axis; `None` when some axis is all zero.
#[inline]
fn grains<const N: usize>(points: &[DVec3; N]) -> Option<([i32; 3], i32)> {
    let (xs, ys, zs) = (
        points.map(|p| p.x),
        points.map(|p| p.y),
        points.map(|p| p.z),
    );
    let g = [Grain::of(&xs), Grain::of(&ys), Grain::of(&zs)];
    if g.iter().any(|g| g.all_zero()) {
        return None;
    }
    let span = g.iter().map(|g| g.span()).max().unwrap_or(0);
    Some((g.map(|g| g.lo_min), span))
}

/// The stages after the filter. Scaling every column of the determinant by
/// a power of two scales it by a positive number, so each axis can be
/// taken as integers at its own finest bit.
#[cold]
#[inline(never)]
fn exact(d: DVec3, o: DVec3, p: DVec3, q: DVec3) -> Sign {
    if ![d, o, p, q].iter().all(|v| v.is_finite()) {
        return Sign::Zero;
    }
    // An all-zero axis is a zero column.
    let Some((lo, span)) = grains(&[d, o, p, q]) else {
        return Sign::Zero;
    };
    if span <= SMALL_SPAN {
        let int = |v: DVec3| {
            [
                to_integer_i64(v.x, lo[0]),
                to_integer_i64(v.y, lo[1]),
                to_integer_i64(v.z, lo[2]),
            ]
        };
        let oi = int(o);
        let rel = |v: DVec3| {
            let v = int(v);
            [v[0] - oi[0], v[1] - oi[1], v[2] - oi[2]]
        };
        return small_det3([int(d), rel(p), rel(q)]);
    }
    sparse::orient_dir(d, o, p, q).unwrap_or_else(|| {
        // `<34, 67, 100>` holds every finite input, as in orient3d.
        let int = |v: DVec3| {
            [
                Wide::<34>::from_f64(v.x, lo[0]),
                Wide::from_f64(v.y, lo[1]),
                Wide::from_f64(v.z, lo[2]),
            ]
        };
        let oi = int(o);
        let rel = |v: DVec3| {
            let v = int(v);
            [v[0].sub(&oi[0]), v[1].sub(&oi[1]), v[2].sub(&oi[2])]
        };
        det3_wide::<34, 67, 100>(&[int(d), rel(p), rel(q)]).sign()
    })
}

/// The parameter `t` where the line `o + t d` meets the plane of `v0, v1,
/// v2`: `det[v0 - o, e1, e2] / det[d, e1, e2]` with `e1 = v1 - v0`, `e2 =
/// v2 - v0`, both determinants exact (in integers), each rounded to 53
/// bits (within `2^-53 (1 + 2^-11)`), then divided: the relative error is
/// below `4 * 2^-53` when the result is a normal number, and below
/// `2^-1073` absolutely when it is subnormal. A result that would round to zero is
/// the smallest subnormal of the exact sign instead, so the sign is always
/// exact. `NaN` when the line is parallel to the plane (or the triangle
/// degenerate), or for non-finite input.
pub(crate) fn plane_parameter(o: DVec3, d: DVec3, v0: DVec3, v1: DVec3, v2: DVec3) -> f64 {
    if ![o, d, v0, v1, v2].iter().all(|v| v.is_finite()) {
        return f64::NAN;
    }
    let Some((lo, span)) = grains(&[o, d, v0, v1, v2]) else {
        return f64::NAN;
    };
    // Values below 2^span, rows (differences) below 2^(span + 1), minors
    // below 2^(2 span + 3), determinants below 2^(3 span + 5): the sizes
    // hold them with a sign bit to spare.
    let v = [v0, v1, v2];
    if span <= SMALL_SPAN {
        small_quotient(o, d, v, lo)
    } else if span <= 125 {
        quotient::<2, 4, 6>(o, d, v, lo)
    } else if span <= 253 {
        quotient::<4, 8, 12>(o, d, v, lo)
    } else if span <= 509 {
        quotient::<8, 16, 24>(o, d, v, lo)
    } else {
        // Every finite input, as in orient3d's last stage.
        quotient::<34, 67, 100>(o, d, v, lo)
    }
}

/// [`plane_parameter`] in native integers, for values below `2^61` at
/// the finest bit of each axis: rows in `i64` (below `2^62`), the normal
/// `e1 x e2` in `i128` (below `2^125`), the determinants as 189-bit sums.
fn small_quotient(o: DVec3, d: DVec3, v: [DVec3; 3], lo: [i32; 3]) -> f64 {
    let int = |p: DVec3| {
        [
            to_integer_i64(p.x, lo[0]),
            to_integer_i64(p.y, lo[1]),
            to_integer_i64(p.z, lo[2]),
        ]
    };
    let sub = |a: [i64; 3], b: [i64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let v0 = int(v[0]);
    let (e1, e2) = (sub(int(v[1]), v0), sub(int(v[2]), v0));
    let cross = |i: usize, j: usize| e1[i] as i128 * e2[j] as i128 - e1[j] as i128 * e2[i] as i128;
    let n = [cross(1, 2), cross(2, 0), cross(0, 1)];
    let num = dot_wide(sub(v0, int(o)), n);
    let den = dot_wide(int(d), n);
    // Both within `2^-53 (1 + 2^-11)` of the exact integers, far inside the
    // range of `f64`; the column scales cancel in the quotient.
    if den == 0.0 { f64::NAN } else { num / den }
}

/// `a . n` for `|a_k| < 2^62`, `|n_k| < 2^125`, rounded to `f64` within
/// `2^-53 (1 + 2^-11)` relative: the sum is kept exactly as a high `i128`
/// and a low `u64` word, `value = high 2^64 + low` (as in orient3d's small
/// stage), then converted from its magnitude.
fn dot_wide(a: [i64; 3], n: [i128; 3]) -> f64 {
    let mut high: i128 = 0;
    let mut low: u128 = 0;
    for k in 0..3 {
        let z = a[k] as i128;
        high += z * (n[k] >> 64);
        let zl = z * (n[k] as u64 as i128);
        high += zl >> 64;
        low += zl as u64 as u128;
    }
    high += (low >> 64) as i128;
    let low = low as u64;
    // The magnitude as `h 2^64 + l`, `h >= 0`.
    let neg = high < 0;
    let (h, l) = if neg {
        ((!high + (low == 0) as i128) as u128, low.wrapping_neg())
    } else {
        (high as u128, low)
    };
    let m = if h >> 64 == 0 {
        // Below 2^128: one correctly rounded conversion.
        ((h << 64) | l as u128) as f64
    } else {
        // `l` is below half an ulp of the rounded `h 2^64`: dropping it
        // moves the result by less than `2^-64` relative.
        h as f64 * 18446744073709551616.0
    };
    if neg { -m } else { m }
}

/// [`plane_parameter`] in `D`-limb rows, `M`-limb minors, `R`-limb
/// determinants.
fn quotient<const D: usize, const M: usize, const R: usize>(
    o: DVec3,
    d: DVec3,
    v: [DVec3; 3],
    lo: [i32; 3],
) -> f64 {
    let int = |p: DVec3| {
        [
            Wide::<D>::from_f64(p.x, lo[0]),
            Wide::from_f64(p.y, lo[1]),
            Wide::from_f64(p.z, lo[2]),
        ]
    };
    let sub =
        |a: &[Wide<D>; 3], b: &[Wide<D>; 3]| [a[0].sub(&b[0]), a[1].sub(&b[1]), a[2].sub(&b[2])];
    let (oi, v0) = (int(o), int(v[0]));
    let (e1, e2) = (sub(&int(v[1]), &v0), sub(&int(v[2]), &v0));
    let num = det3_wide::<D, M, R>(&[sub(&v0, &oi), e1, e2]);
    let den = det3_wide::<D, M, R>(&[int(d), e1, e2]);
    let ((mn, en), (md, ed)) = (num.rounded_parts(), den.rounded_parts());
    if md == 0.0 {
        return f64::NAN;
    }
    // Both scaled by the same power of two (the columns'), which cancels.
    // `mn / md` lies within [2^-64, 2^64] (or is zero) and is rounded once;
    // the scaling by `2^(en - ed)` in steps of the same sign is exact
    // unless the result is subnormal or overflows.
    let q = mn / md;
    let k = (en - ed).clamp(-2400, 2400);
    let third = k / 3;
    let t = q * pow2(third) * pow2(third) * pow2(k - 2 * third);
    if t == 0.0 && mn != 0.0 {
        f64::from_bits(1).copysign(q)
    } else {
        t
    }
}
