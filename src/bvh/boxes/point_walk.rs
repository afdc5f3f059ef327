//! The nearest-first walk for point queries: a lower bound of the squared
//! distance from a query point to each child box of a wide node, never
//! above the exact one, and a depth-first walk that visits the nearer
//! children first and skips a child whose bound exceeds what the query
//! still wants.
//!
//! # The lower bound
//! A lane's `f32` bounds are taken back into world coordinates outward
//! ([`Frame::world_down`], [`Frame::world_up`]): below and above the exact
//! box of the items under it, so the distance to that wider box is at most
//! the distance to any item. On axis `k` the gap is `b_lo - q_k` (query
//! below the box), `q_k - b_hi` (above) or zero; each difference is
//! computed in `f64` and stepped two floats down, below the exact one (one
//! rounding to nearest, at most half a step; an overflow rounds to `inf`
//! and steps down to `f64::MAX`, below the exact difference too), then
//! scaled by the query's power of two `2^s` (exact unless it falls below
//! `2^-1022`, there off by at most `2^-1074`, [`scale_pow2`]) and stepped
//! two floats down again, then floored at zero. Each square and each of
//! the two sums rounds once more and steps down once more. Every step
//! keeps the value at most the exact scaled squared distance to the box.
//! An empty lane (`min = +inf`, `max = -inf`, so `min > max`) gets an
//! infinite bound: never visited (its link, zero, is no child).

use super::frame::Frame;
use super::wide::WIDTH;
use super::{BoxBvh, MAX_DEPTH};
use crate::arith::exponent::scale_pow2;
use glam::DVec3;

/// What a point query does with the walk.
pub(crate) trait PointVisitor {
    /// The largest scaled squared box distance still wanted: a box whose
    /// lower bound exceeds it holds no wanted item.
    fn reach(&self) -> f64;
    /// Looks at a leaf's items.
    fn leaf(&mut self, items: &[u32]);
}

/// A child still to visit: its lower bound, and its lane's `link` and
/// `count` (`count > 0`: a leaf).
#[derive(Clone, Copy)]
struct Pending {
    bound: f64,
    link: u32,
    count: u32,
}

/// Pending children at most: a node pushes up to [`WIDTH`] and its visit
/// popped one, along a path of fewer than [`MAX_DEPTH`] wide nodes.
const STACK: usize = (WIDTH - 1) * MAX_DEPTH + WIDTH;

/// A value at most the exact `x` of which `fl` is the rounding to nearest
/// or a scaling by [`scale_pow2`] (both within one float step).
#[inline(always)]
fn below(fl: f64) -> f64 {
    fl.next_down().next_down()
}

/// A lower bound of `(gap 2^s)^2` for an exact gap at least `gap`.
#[inline(always)]
fn scaled_square_below(gap: f64, s: i32) -> f64 {
    let g = below(scale_pow2(below(gap), s)).max(0.0);
    (g * g).next_down().max(0.0)
}

/// A lower bound of the squared distance, scaled by `2^(2s)`, from `q` to
/// the box `[lo, hi]` (exact bounds, `lo <= hi`), rounded down as the
/// lanes' (see the module docs).
#[inline(always)]
pub(crate) fn box_distance_below(lo: DVec3, hi: DVec3, q: DVec3, s: i32) -> f64 {
    let mut sum = 0.0f64;
    for k in 0..3 {
        let gap = if q[k] < lo[k] {
            lo[k] - q[k]
        } else if q[k] > hi[k] {
            q[k] - hi[k]
        } else {
            0.0
        };
        sum = (sum + scaled_square_below(gap, s)).next_down().max(0.0);
    }
    sum
}

/// The lower bound of the squared distance, scaled by `2^(2s)`, from `q`
/// to each lane's box of `node` (see the module docs).
#[inline]
fn lane_bounds(node: &super::WideNode, frame: &Frame, q: DVec3, s: i32) -> [f64; WIDTH] {
    core::array::from_fn(|l| {
        let lo = DVec3::from_array(core::array::from_fn(|k| {
            frame.world_down(node.min[k][l], k)
        }));
        let hi = DVec3::from_array(core::array::from_fn(|k| frame.world_up(node.max[k][l], k)));
        if !lo.cmple(hi).all() {
            // An empty lane (stepping its infinite gap down would make it
            // finite).
            return f64::INFINITY;
        }
        box_distance_below(lo, hi, q, s)
    })
}

/// Walks `bvh` for the point `q`, scaled by `2^s` (`|s| <= 1075`), nearer
/// children first, skipping every box whose lower bound exceeds
/// `v.reach()` at the time it would be visited.
pub(crate) fn walk_point<V: PointVisitor>(bvh: &BoxBvh, q: DVec3, s: i32, v: &mut V) {
    if bvh.nodes.is_empty() {
        return;
    }
    let mut stack = [Pending {
        bound: 0.0,
        link: 0,
        count: 0,
    }; STACK];
    let mut len = 1;
    while len > 0 {
        len -= 1;
        let top = stack[len];
        if top.bound > v.reach() {
            continue;
        }
        if top.count > 0 {
            let start = top.link as usize;
            // The range lies inside `order` by construction; `get` keeps
            // the walk panic-free regardless.
            if let Some(items) = bvh.order.get(start..start + top.count as usize) {
                v.leaf(items);
            }
            continue;
        }
        let Some(node) = bvh.nodes.get(top.link as usize) else {
            continue;
        };
        let bounds = lane_bounds(node, &bvh.frame, q, s);
        let reach = v.reach();
        let mut lanes = [0usize; WIDTH];
        let mut n = 0;
        for (l, &b) in bounds.iter().enumerate() {
            if b <= reach {
                lanes[n] = l;
                n += 1;
            }
        }
        // Farthest pushed first, so the nearest is visited next.
        lanes[..n].sort_unstable_by(|&a, &b| bounds[b].total_cmp(&bounds[a]));
        for &l in &lanes[..n] {
            if len < STACK {
                stack[len] = Pending {
                    bound: bounds[l],
                    link: node.link[l],
                    count: node.count[l],
                };
                len += 1;
            }
        }
    }
}
