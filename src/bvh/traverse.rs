//! The branch-and-bound walk every query shares: a stack, the nearer child
//! first, and the exam's prune `|c - q| - r >= d`, made conservative.
//!
//! All distances of one query are computed on differences scaled by a power
//! of two `s` chosen from the query and the largest coordinate of the index,
//! so that no square overflows and small differences keep their precision;
//! scaling by a power of two is exact (below `2^-1022`, off by at most
//! `2^-1075`, which the bounds absorb).

use super::sphere::UNDERFLOW_DISTANCE;
use super::{Child, Counter, LEAF, SphereBvh, sqrt};
use crate::predicates::grain::unit_pow2;
use glam::DVec3;

/// `u = 2^-53`.
const U: f64 = f64::EPSILON / 2.0;

/// The prune, without a square root: a node whose sphere has scaled radius
/// `r` and whose centre is at computed squared scaled distance `d2` holds no
/// point within the visitor's reach when `d2 (1 - 16u) > (r + reach)^2`,
/// computed. Why that is safe: the exact squared distance is at least
/// `(d2 - 2^-1071) / (1 + gamma_5)` (see `predicates::distance`); `reach`
/// exceeds the exact distance it stands for by a factor `(1 + 7u)` and by
/// `2^-529` (see [`reach_of`]), so the computed `(r + reach)^2`, after its
/// two roundings, still exceeds the exact `(r + d)^2` by `(1 + 10u)` and by
/// `2^-1058`, more than the `2^-1071` and the `gamma_5 + 16u` on the other
/// side.
const PRUNE: f64 = 1.0 - 16.0 * U;

/// `true` when the node cannot hold a point within `reach`. Neither a NaN
/// (an infinite radius from an overflowing build) nor an infinite `d2` (a
/// difference of coordinates near `f64::MAX` overflowed before scaling, so
/// the distance is unknown, not large) ever prunes.
#[inline(always)]
fn pruned(d2: f64, r: f64, reach: f64) -> bool {
    let t = r + reach;
    d2 * PRUNE > t * t && d2 < f64::INFINITY
}

/// Stack capacity. Median splits halve every subtree, so a tree over at most
/// `2^32` points is at most 28 levels deep above its leaves of 16 to 32
/// points; the walk holds at most one entry per level (the far children on
/// the current path).
const STACK: usize = 32;

/// What a query does with the points it reaches, and how far it still looks.
pub(crate) trait Visitor {
    /// Where the walk's statistics go.
    type Counter: Counter;
    fn counter(&mut self) -> &mut Self::Counter;
    /// Nodes whose lower bound (scaled units, see [`reach_of`]) exceeds this
    /// cannot hold a point the query wants.
    fn reach(&self) -> f64;
    /// Point `i` (tree order) at computed squared scaled distance `d2`.
    fn point(&mut self, tree: &SphereBvh, i: usize, d2: f64);
}

/// The bound a visitor reports for an upper bound `hi` of a squared scaled
/// distance: an upper bound of the distance, widened by the margins that
/// [`LOWER`] leaves to this side (`sqrt` rounding, the subtraction of the
/// radius, and the `2^-535` underflow term, doubled).
#[inline]
pub(crate) fn reach_of(hi: f64) -> f64 {
    sqrt(hi) * (1.0 + 8.0 * U) + 2.0 * UNDERFLOW_DISTANCE
}

/// The scale of a query at `q` (finite) in `tree`.
#[inline]
pub(crate) fn scale_of(tree: &SphereBvh, q: DVec3) -> f64 {
    unit_pow2(tree.max_abs.max(q.abs().max_element()))
}

/// Computed squared norm of `(p - q) * s`.
#[inline(always)]
fn dist2(p: DVec3, q: DVec3, s: f64) -> f64 {
    let d = (p - q) * s;
    d.x * d.x + d.y * d.y + d.z * d.z
}

/// A subtree still to visit: its sphere (centre at computed squared scaled
/// distance `d2`, scaled radius `r`) and, for points, its box bound: `off`
/// holds, per axis, the computed scaled offset of `q` from the nearest split
/// plane on the path to it that the subtree lies beyond (0 where none), and
/// `box2` their computed squared norm.
#[derive(Clone, Copy)]
struct Pending {
    link: u32,
    len: u32,
    d2: f64,
    r: f64,
    box2: f64,
    off: [f64; 3],
}

/// Walks `tree` (non-empty) from the root, handing every point of every
/// leaf that may hold a wanted point to `v`.
///
/// Two lower bounds prune a subtree: its sphere, and (for points) its box,
/// the distance from `q` to the intersection of the half-spaces of the split
/// planes between the root and it (Arya and Mount's incremental distance).
/// A subtree's points lie beyond each of those planes, so `|p - q|^2` is at
/// least the sum over axes of the squared offset of `q` from one such plane
/// per axis. That sum is computed like a squared distance, from one rounded
/// difference per axis (exact zeros elsewhere): the error bound of [`PRUNE`]
/// holds for it as it stands, with a radius of 0.
#[inline]
pub(crate) fn walk<V: Visitor>(tree: &SphereBvh, root: &Child, q: DVec3, s: f64, v: &mut V) {
    let none = Pending {
        link: 0,
        len: 0,
        d2: 0.0,
        r: 0.0,
        box2: 0.0,
        off: [0.0; 3],
    };
    let mut stack = [none; STACK];
    let mut top = 0;
    let points = tree.radii.is_empty();
    let mut next = Pending {
        link: root.link,
        len: root.len,
        d2: dist2(root.center, q, s),
        r: root.radius * s,
        ..none
    };
    loop {
        let reach = v.reach();
        if !pruned(next.d2, next.r, reach) && !pruned(next.box2, 0.0, reach) {
            v.counter().node();
            if next.len == 0 {
                let node = &tree.nodes[next.link as usize];
                // Both children at once, lane by lane (two-wide vector code).
                let lane = |k: usize| {
                    let d = [
                        (node.cx[k] - q.x) * s,
                        (node.cy[k] - q.y) * s,
                        (node.cz[k] - q.z) * s,
                    ];
                    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2], node.r[k] * s)
                };
                let ((da, ra), (db, rb)) = (lane(0), lane(1));
                // Points: the side of the split plane `q` is on comes first,
                // and the far side's box gains that plane. Balls may
                // straddle the plane: nearer centre first, no box bound.
                let axis = node.axis as usize % 3;
                let mut far_off = next.off;
                let mut far_box2 = 0.0;
                let first = if points {
                    let offset = (q[axis] - node.split) * s;
                    far_off[axis] = offset;
                    far_box2 =
                        far_off[0] * far_off[0] + far_off[1] * far_off[1] + far_off[2] * far_off[2];
                    offset <= 0.0
                } else {
                    da <= db
                };
                let (near, far) = if first { (0, 1) } else { (1, 0) };
                let (dn, rn, df, rf) = if near == 0 {
                    (da, ra, db, rb)
                } else {
                    (db, rb, da, ra)
                };
                if !pruned(df, rf, reach) && !pruned(far_box2, 0.0, reach) {
                    stack[top] = Pending {
                        link: node.link[far],
                        len: node.len[far],
                        d2: df,
                        r: rf,
                        box2: far_box2,
                        off: far_off,
                    };
                    top += 1;
                }
                next = Pending {
                    link: node.link[near],
                    len: node.len[near],
                    d2: dn,
                    r: rn,
                    ..next
                };
                continue;
            }
            leaf(tree, next.link as usize, next.len as usize, q, s, v);
        }
        if top == 0 {
            return;
        }
        top -= 1;
        next = stack[top];
    }
}

/// Hands the `len <= LEAF` points from tree position `start` to `v`, their
/// distances computed first in one pass that the compiler vectorizes.
#[inline(always)]
fn leaf<V: Visitor>(tree: &SphereBvh, start: usize, len: usize, q: DVec3, s: f64, v: &mut V) {
    v.counter().distances(len);
    // A whole leaf's worth of lanes, whatever `len`: a fixed trip count
    // vectorizes without a remainder loop. The coordinate arrays carry
    // `LEAF` points of padding, so the lanes past `len` read the next
    // leaf's points (or the padding) and are ignored.
    let end = start + LEAF;
    let (Some(xs), Some(ys), Some(zs)) = (
        tree.xs.get(start..end),
        tree.ys.get(start..end),
        tree.zs.get(start..end),
    ) else {
        return;
    };
    let mut d2 = [0.0f64; LEAF];
    for k in 0..LEAF {
        let (dx, dy, dz) = ((xs[k] - q.x) * s, (ys[k] - q.y) * s, (zs[k] - q.z) * s);
        d2[k] = dx * dx + dy * dy + dz * dz;
    }
    for (k, &d) in d2.iter().enumerate().take(len) {
        v.point(tree, start + k, d);
    }
}
