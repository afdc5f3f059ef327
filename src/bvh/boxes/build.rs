//! The no_std binned-SAH builder of the binary [`BinaryBvh`] (collapsed
//! into the walk's 8-wide tree afterwards, `wide.rs`): top-down, 12 bins
//! per split along the widest axis of the triangles' box centres, leaves
//! of up to [`LEAF`] triangles.
//!
//! # The depth bound
//! Below depth [`SAH_DEPTH`] (32) the split is the cheapest of the 11 bin
//! boundaries by the surface area heuristic; from there on, and wherever
//! the bins cannot split (every centre in one bin, or a box too large for
//! its area to be finite), it is the median along that axis, which halves
//! the triangles. A subtree of at most `2^32` triangles reaches leaves of
//! at most [`LEAF`] after 31 halvings, so no leaf lies deeper than `32 +
//! 31 = 63` levels, below [`MAX_DEPTH`] (64): the walk of the 8-wide tree
//! collapsed from it, whose fixed stack holds `7 * MAX_DEPTH` entries
//! (seven pending children per wide level, `traverse.rs`), never overflows.
//!
//! The heuristic only chooses the tree's shape: boxes are exact, whichever
//! split is chosen, and so are the queries.

use super::{BinaryBvh, LEAF, MAX_DEPTH, Node};
use alloc::vec::Vec;
use glam::DVec3;

/// Bins per split.
const BINS: usize = 12;

/// Depth from which every split is a median split (see the module docs).
const SAH_DEPTH: usize = 32;

/// One item as the builder sees it (a mesh's triangle, or a scene's
/// primitive): its box, its centre (rounded: only the split choice reads
/// it) and its index in the mesh (its id in the scene).
#[derive(Clone, Copy)]
pub(crate) struct Item {
    pub(crate) min: DVec3,
    pub(crate) max: DVec3,
    pub(crate) index: u32,
}

impl Item {
    #[inline]
    fn center(&self) -> DVec3 {
        self.min * 0.5 + self.max * 0.5
    }
}

/// The union of the items' boxes (exact: min and max round nothing).
pub(super) fn bounds(items: &[Item]) -> (DVec3, DVec3) {
    items
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), it| {
            (lo.min(it.min), hi.max(it.max))
        })
}

/// Half the surface area of a box (what the heuristic compares, and what
/// the 8-wide collapse opens first, `wide.rs`).
pub(super) fn half_area(min: DVec3, max: DVec3) -> f64 {
    let e = (max - min).max(DVec3::ZERO);
    e.x * e.y + e.y * e.z + e.z * e.x
}

/// The tree over `items` (possibly empty).
pub(super) fn build(mut items: Vec<Item>) -> BinaryBvh {
    let mut nodes = Vec::with_capacity((2 * items.len() / LEAF + 1).max(1));
    if !items.is_empty() {
        subtree(&mut items, 0, 0, &mut nodes);
    }
    BinaryBvh {
        order: items.iter().map(|it| it.index).collect(),
        nodes,
    }
}

/// Appends the subtree over `items` (which start at `first` in the final
/// order) to `nodes` in preorder.
fn subtree(items: &mut [Item], first: usize, depth: usize, nodes: &mut Vec<Node>) {
    let (min, max) = bounds(items);
    let at = nodes.len();
    nodes.push(Node {
        min: min.to_array(),
        max: max.to_array(),
        link: first as u32,
        count: items.len() as u32,
    });
    let Some(mid) = split(items, min, max, depth) else {
        return;
    };
    debug_assert!(depth + 1 < MAX_DEPTH);
    nodes[at].count = 0;
    let (left, right) = items.split_at_mut(mid);
    subtree(left, first, depth + 1, nodes);
    nodes[at].link = nodes.len() as u32;
    subtree(right, first + mid, depth + 1, nodes);
}

/// Reorders `items` into two non-empty parts and returns the first's
/// length, or `None` for a leaf.
fn split(items: &mut [Item], min: DVec3, max: DVec3, depth: usize) -> Option<usize> {
    let n = items.len();
    if n <= 1 {
        return None;
    }
    let (cmin, cmax) = items
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), it| {
            (lo.min(it.center()), hi.max(it.center()))
        });
    let extent = cmax - cmin;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let (lo, width) = (cmin[axis], extent[axis]);
    if depth < SAH_DEPTH && width > 0.0 && width.is_finite() {
        let bin = |it: &Item| {
            let k = ((it.center()[axis] - lo) / width * BINS as f64) as usize;
            k.min(BINS - 1)
        };
        let mut count = [0usize; BINS];
        let mut boxes = [(DVec3::INFINITY, DVec3::NEG_INFINITY); BINS];
        for it in items.iter() {
            let k = bin(it);
            count[k] += 1;
            boxes[k] = (boxes[k].0.min(it.min), boxes[k].1.max(it.max));
        }
        // Sweep: the cost of splitting after bin k is A(left) n(left) +
        // A(right) n(right).
        let mut right_area = [0.0; BINS];
        let mut acc = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for k in (1..BINS).rev() {
            acc = (acc.0.min(boxes[k].0), acc.1.max(boxes[k].1));
            right_area[k] = half_area(acc.0, acc.1);
        }
        let mut best: Option<(f64, usize)> = None;
        let (mut left, mut nl) = ((DVec3::INFINITY, DVec3::NEG_INFINITY), 0);
        for k in 0..BINS - 1 {
            left = (left.0.min(boxes[k].0), left.1.max(boxes[k].1));
            nl += count[k];
            if nl == 0 || nl == n {
                continue;
            }
            let cost = half_area(left.0, left.1) * nl as f64 + right_area[k + 1] * (n - nl) as f64;
            if cost.is_finite() && best.is_none_or(|(c, _)| cost < c) {
                best = Some((cost, k));
            }
        }
        if let Some((cost, k)) = best {
            // A leaf when it costs no more than the split (one box test
            // counted as one triangle test).
            if n <= LEAF && half_area(min, max) * (n as f64 - 1.0) <= cost {
                return None;
            }
            let mut mid = 0;
            for i in 0..n {
                if bin(&items[i]) <= k {
                    items.swap(i, mid);
                    mid += 1;
                }
            }
            return Some(mid);
        }
    }
    if n <= LEAF {
        return None;
    }
    let mid = n / 2;
    items.select_nth_unstable_by(mid, |a, b| a.center()[axis].total_cmp(&b.center()[axis]));
    Some(mid)
}
