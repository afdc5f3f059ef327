//! The exact test of a ray against a triangle's edge, on the original
//! coordinates: which side of the ray's line the edge passes
//! ([`orient_dir`]), a determinant whose rows are the ray's direction `d`
//! (an input vector) and exact differences of input points, decided by the
//! orient3d ladder on such rows (filter, double-double filter,
//! small-integer exact, sparse exact terms, big-integer exact). Where the line meets the triangle's plane is
//! the exact ray–triangle cast's plane parameter (`query::ray::triangle`).

use super::det::{certifies, det3_wide, small_det3, stage_a_rows};
use super::sparse::det3;
use crate::arith::double_double::{SLACK, cross_dd, difference, dot_dd, in_range, row};
use crate::arith::exponent::{Grain, to_integer_i64};
use crate::arith::fixed_int::{DEG1, DEG2, DEG3, FixedInt};
use crate::arith::fma_dispatch::{FmaKernel, with_fma};
use crate::arith::roundoff::U;
use crate::arith::sparse_sum::diff;
use crate::sign::Sign;
use glam::DVec3;

/// Span (per axis) of the small-integer stage, as in orient3d: values
/// below `2^61`, differences below `2^62`.
pub(crate) const SMALL_SPAN: i32 = 61;

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
        with_fma(&DoubleDouble { d, o, p, q }).unwrap_or_else(|| exact(d, o, p, q))
    }
}

/// The stage after the filter: `det[d, p - o, q - p]` in double-double
/// (`arith::double_double`), within `u |value| + 61 u^2` of its permanent,
/// so its sign is certified where `64 u^2` of the permanent and the
/// absolute slack fall below half its magnitude. Rays within a few ulps of
/// an edge, but not on its line, end here. `None` where it cannot certify
/// or a row exceeds `double_double::MAX_MAGNITUDE`.
struct DoubleDouble {
    d: DVec3,
    o: DVec3,
    p: DVec3,
    q: DVec3,
}

impl FmaKernel for DoubleDouble {
    type Output = Option<Sign>;

    #[inline(always)]
    fn run(&self) -> Option<Sign> {
        let (a, e) = (difference(self.p, self.o), difference(self.q, self.p));
        let d = row(self.d);
        if !in_range(&[a.0, e.0, d]) {
            return None;
        }
        let (det, perm) = dot_dd(d, None, &cross_dd(a, e));
        (64.0 * U * U * perm + SLACK < 0.5 * det.abs()).then(|| Sign::of_f64(det))
    }
}

/// Each axis's finest bit and the widest span, over the given values per
/// axis; `None` when some axis is all zero.
#[inline]
pub(crate) fn grains<const N: usize>(points: &[DVec3; N]) -> Option<([i32; 3], i32)> {
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
    sparse_sign(d, o, p, q).unwrap_or_else(|| {
        // `<34, 67, 100>` holds every finite input, as in orient3d.
        let int = |v: DVec3| {
            [
                FixedInt::<DEG1>::from_f64(v.x, lo[0]),
                FixedInt::from_f64(v.y, lo[1]),
                FixedInt::from_f64(v.z, lo[2]),
            ]
        };
        let oi = int(o);
        let rel = |v: DVec3| {
            let v = int(v);
            [v[0].sub(&oi[0]), v[1].sub(&oi[1]), v[2].sub(&oi[2])]
        };
        det3_wide::<DEG1, DEG2, DEG3>(&[int(d), rel(p), rel(q)]).sign()
    })
}

/// Stage 5, first: the exact sign of `det[d, p - o, q - o]` for finite input (a ray's
/// direction `d` and two points seen from its origin `o`), or `None` when
/// the terms do not fit the accumulators.
pub(super) fn sparse_sign(d: DVec3, o: DVec3, p: DVec3, q: DVec3) -> Option<Sign> {
    let rel = |p: DVec3| [diff(p.x, o.x), diff(p.y, o.y), diff(p.z, o.z)];
    // `d - 0` is the one exact term `d` (a zero difference has none).
    let dir = [diff(d.x, 0.0), diff(d.y, 0.0), diff(d.z, 0.0)];
    det3(dir, rel(p), rel(q))
}
