//! The branch-and-bound walk every query shares: a stack, the nearer child
//! first, and the prune `|c - q| - r >= d` with a box bound beside
//! it, both made conservative.
//!
//! All distances of one query are computed on differences scaled by a power
//! of two `s` chosen from the query and the largest coordinate of the index,
//! so that no square overflows and small differences keep their precision;
//! scaling by a power of two is exact (below `2^-1022`, off by at most
//! `2^-1075`, which the bounds absorb).

use super::sphere::UNDERFLOW_DISTANCE;
use super::{CacheLine, Child, Counter, LEAF, Node, SphereBvh, Spheres, first_part, sqrt};
use crate::arith::exponent::unit_pow2;
use crate::arith::roundoff::U;
use glam::DVec3;

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

/// Stack capacity. Median splits halve every subtree (to within 4 points),
/// so a tree over at most `2^32` points is at most 28 levels deep above its
/// leaves of 16 to 32 points; the walk holds at most one entry per level (the far children on
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
    /// The `len` points of a leaf from tree position `start`, at computed
    /// squared scaled distances `d2[..len]` (the lanes past `len` hold
    /// anything); `least` is the smallest of them.
    #[inline(always)]
    fn leaf(&mut self, tree: &SphereBvh, start: usize, d2: &[f64; LEAF], len: usize, least: f64) {
        let _ = least;
        for (k, &d) in d2.iter().enumerate().take(len) {
            self.point(tree, start + k, d);
        }
    }
}

/// The bound a visitor reports for an upper bound `hi` of a squared scaled
/// distance: an upper bound of the distance, widened by the margins that
/// [`PRUNE`] leaves to this side (`sqrt` rounding, the subtraction of the
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

/// A far child still to visit: child `k` of node `parent` (where its
/// sphere is), the subtree it is, and its box bound: `off` holds, per axis, the computed scaled offset of `q` from the
/// last split plane on that axis between the root and the child that the
/// child lies beyond (0 where none), and `box2` their computed squared norm.
/// Its sphere is read from the parent when it is popped, against the reach
/// of that moment.
#[derive(Clone, Copy)]
struct Pending {
    parent: u32,
    k: u32,
    child: Subtree,
    box2: f64,
    off: [f64; 3],
}

/// A subtree: its node (when internal), its first point in tree order and
/// its number of points, which makes it a leaf when at most [`LEAF`] (see
/// [`Node`](super::Node)).
#[derive(Clone, Copy)]
struct Subtree {
    at: u32,
    start: u32,
    count: u32,
}

impl Subtree {
    /// The two children of this internal subtree, `node` its node: the
    /// first part of its points in the next node, the rest at
    /// `node.right`.
    #[inline(always)]
    fn children(self, node: &Node) -> [Subtree; 2] {
        let half = first_part(self.count as usize) as u32;
        [
            Subtree {
                at: self.at + 1,
                start: self.start,
                count: half,
            },
            Subtree {
                at: node.right,
                start: self.start + half,
                count: self.count - half,
            },
        ]
    }
}

/// Computed squared scaled distance from `q` to the centre of child `k` of
/// `node`, and the child's scaled radius.
#[inline(always)]
fn child_sphere(node: &Spheres, k: usize, q: DVec3, s: f64) -> (f64, f64) {
    let (dx, dy, dz) = (
        (node.cx[k] - q.x) * s,
        (node.cy[k] - q.y) * s,
        (node.cz[k] - q.z) * s,
    );
    (dx * dx + dy * dy + dz * dz, node.r[k] * s)
}

/// An empty stack slot of [`walk`].
const NO_PENDING: Pending = Pending {
    parent: 0,
    k: 0,
    child: Subtree {
        at: 0,
        start: 0,
        count: 0,
    },
    box2: 0.0,
    off: [0.0; 3],
};

/// The spheres of a node [`walk`] finds none for (never: `spheres` has an
/// entry per node): they prune nothing.
const NO_SPHERES: Spheres = Spheres {
    cx: [0.0; 2],
    cy: [0.0; 2],
    cz: [0.0; 2],
    r: [f64::INFINITY; 2],
};

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
///
/// Points descend to the side of each split plane that holds `q`, whose box
/// is the parent's, so only its sphere is tested; the far side is pushed
/// when its box cannot be pruned yet, and its sphere tested when popped.
/// Balls may straddle a split plane: both children's spheres are measured
/// and the nearer centre goes first, with no box bound.
#[inline]
pub(crate) fn walk<V: Visitor>(tree: &SphereBvh, root: &Child, q: DVec3, s: f64, v: &mut V) {
    let none = NO_PENDING;
    let mut stack = [none; STACK];
    let mut top = 0;
    let points = tree.radii.is_empty();
    let qs = [q.x, q.y, q.z];
    let spheres = |i: u32| tree.spheres.get(i as usize).unwrap_or(&NO_SPHERES);
    // The subtree being entered, which has passed both prunes, and its
    // box's offsets.
    let mut cur = Subtree {
        at: root.link,
        start: 0,
        count: tree.len() as u32,
    };
    let mut off = [0.0; 3];
    loop {
        v.counter().node();
        let descend = if cur.count as usize > LEAF {
            let here = cur.at;
            let node = &tree.nodes[here as usize];
            let children = cur.children(node);
            let reach = v.reach();
            // Until the first leaf, nothing is pruned: no sphere is tested.
            let open = reach == f64::INFINITY;
            let near = if points {
                let axis = (node.axis as usize).min(2);
                let offset = (qs[axis] - node.split) * s;
                let near = (offset > 0.0) as usize;
                let mut far_off = off;
                far_off[axis] = offset;
                let far_box2 =
                    far_off[0] * far_off[0] + far_off[1] * far_off[1] + far_off[2] * far_off[2];
                if open || !pruned(far_box2, 0.0, reach) {
                    stack[top] = Pending {
                        parent: here,
                        k: 1 - near as u32,
                        child: children[1 - near],
                        box2: far_box2,
                        off: far_off,
                    };
                    top += 1;
                }
                near
            } else {
                let ((da, ra), (db, rb)) = (
                    child_sphere(spheres(here), 0, q, s),
                    child_sphere(spheres(here), 1, q, s),
                );
                let (near, df, rf) = if da <= db { (0, db, rb) } else { (1, da, ra) };
                if !pruned(df, rf, reach) {
                    stack[top] = Pending {
                        parent: here,
                        k: 1 - near as u32,
                        child: children[1 - near],
                        ..none
                    };
                    top += 1;
                }
                near
            };
            cur = children[near];
            open || {
                let (dn, rn) = child_sphere(spheres(here), near, q, s);
                !pruned(dn, rn, reach)
            }
        } else {
            leaf(tree, cur.start as usize, cur.count as usize, q, s, v);
            false
        };
        if descend {
            continue;
        }
        loop {
            if top == 0 {
                return;
            }
            top -= 1;
            let p = &stack[top];
            let reach = v.reach();
            if pruned(p.box2, 0.0, reach) {
                continue;
            }
            let k = p.k as usize & 1;
            let (d2, r) = child_sphere(spheres(p.parent), k, q, s);
            if pruned(d2, r, reach) {
                continue;
            }
            (cur, off) = (p.child, p.off);
            break;
        }
    }
}

/// Hands the `len <= LEAF` points from tree position `start` to `v`, their
/// distances computed first in one pass that the compiler vectorizes.
#[inline(always)]
fn leaf<V: Visitor>(tree: &SphereBvh, start: usize, len: usize, q: DVec3, s: f64, v: &mut V) {
    v.counter().distances(len);
    // A whole leaf's worth of lanes, whatever `len`: a fixed trip count
    // vectorizes without a remainder loop. A leaf starts on a block of 8
    // (see `first_part`), and the coordinate arrays carry `LEAF` points of
    // padding, so the lanes past `len` read the next leaf's points (or the
    // padding) and are ignored.
    let b = start / 8;
    fn block(a: &[CacheLine], b: usize) -> Option<&[CacheLine; LEAF / 8]> {
        a.get(b..b + LEAF / 8)?.try_into().ok()
    }
    let (Some(xs), Some(ys), Some(zs)) =
        (block(&tree.xs, b), block(&tree.ys, b), block(&tree.zs, b))
    else {
        return;
    };
    if !start.is_multiple_of(8) {
        // Never: every leaf starts on a block. Correct, if slow, all the same.
        for i in start..start + len.min(LEAF) {
            let d = (tree.point(i) - q) * s;
            v.point(tree, i, d.x * d.x + d.y * d.y + d.z * d.z);
        }
        return;
    }
    let len = len.min(LEAF);
    // 0 for the leaf's lanes, `inf` past them.
    let mask = &LANE_MASK[LEAF - len..][..LEAF];
    let mut d2 = [0.0f64; LEAF];
    // The smallest distance of the leaf too, in four running minima that
    // stay in vector registers (`<`, not `f64::min`: no NaN here).
    let mut least = [f64::INFINITY; 4];
    for (blk, ((bx, by), bz)) in xs.iter().zip(ys).zip(zs).enumerate() {
        for j in 0..8 {
            let k = 8 * blk + j;
            let (dx, dy, dz) = (
                (bx.0[j] - q.x) * s,
                (by.0[j] - q.y) * s,
                (bz.0[j] - q.z) * s,
            );
            let d = dx * dx + dy * dy + dz * dz;
            d2[k] = d;
            let (m, x) = (&mut least[j % 4], d + mask[k]);
            *m = if x < *m { x } else { *m };
        }
    }
    let least = least[0].min(least[1]).min(least[2].min(least[3]));
    v.leaf(tree, start, &d2, len, least);
}

/// Added to a leaf's lanes: the lanes of `LANE_MASK[LEAF - len..][..LEAF]`
/// are 0 for the `len` points of the leaf and `inf` past them.
static LANE_MASK: [f64; 2 * LEAF] = {
    let mut m = [0.0; 2 * LEAF];
    let mut k = LEAF;
    while k < 2 * LEAF {
        m[k] = f64::INFINITY;
        k += 1;
    }
    m
};
