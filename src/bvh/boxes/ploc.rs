//! The `ploc` feature's builder of [`BinaryBvh`] through obvhs: PLOC (Meister and
//! Bittner, "Parallel Locally-Ordered Clustering for Bounding Volume
//! Hierarchy Construction", 2018) with reinsertion and leaf collapse, as
//! obvhs's [`BvhBuildParams`] presets configure them.
//!
//! obvhs builds over `f32` boxes; here they only choose the tree's shape.
//! Each triangle's exact `f64` box is first moved by the boxes' centre and
//! scaled by a power of two that brings their half extent into `[1/2, 1)`,
//! so that `f32`'s rounding is relative to the mesh's size rather than to
//! its distance from the origin (a mesh at `1e8` keeps its shape). The
//! nodes are then written out in the binned builder's preorder layout with
//! the exact boxes of their triangles, recomputed from the `f64` items,
//! and collapsed into the walk's 8-wide tree as the binned builder's are
//! (`wide.rs`): the queries are exactly as conservative as with the binned
//! builder.
//!
//! The walk's stack is sized from [`MAX_DEPTH`] levels of the binary tree
//! (`traverse.rs`). PLOC bounds no depth, so
//! a tree deeper than that, or with a leaf of more than [`LEAF`]
//! triangles, is declined (`None`) and the caller builds with the binned
//! builder instead.

use super::build::{Item, bounds};
use super::{BinaryBvh, LEAF, MAX_DEPTH, Node};
use crate::arith::exponent::{scale_pow2, unit_scale};
use alloc::vec;
use alloc::vec::Vec;
use core::time::Duration;
use glam::{DVec3, Vec3A};
use obvhs::aabb::Aabb;
use obvhs::bvh2::Bvh2;
use obvhs::bvh2::builder::build_bvh2;
use obvhs::{Boundable, BvhBuildParams};

/// How much work obvhs spends on the tree: its presets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PlocQuality {
    /// `BvhBuildParams::very_fast_build`.
    Fast,
    /// `BvhBuildParams::medium_build`.
    #[default]
    Medium,
    /// `BvhBuildParams::slow_build`.
    Slow,
}

impl PlocQuality {
    fn params(self) -> BvhBuildParams {
        let mut params = match self {
            PlocQuality::Fast => BvhBuildParams::very_fast_build(),
            PlocQuality::Medium => BvhBuildParams::medium_build(),
            PlocQuality::Slow => BvhBuildParams::slow_build(),
        };
        params.max_prims_per_leaf = LEAF as u32;
        params
    }
}

/// One triangle's box as obvhs sees it.
struct Proxy(Aabb);

impl Boundable for Proxy {
    #[inline]
    fn aabb(&self) -> Aabb {
        self.0
    }
}

/// The tree over `items` built by obvhs, or `None` where it would not fit
/// the walk (see the module docs).
pub(super) fn build(items: &[Item], quality: PlocQuality) -> Option<BinaryBvh> {
    if items.is_empty() {
        return Some(BinaryBvh {
            nodes: Vec::new(),
            order: Vec::new(),
        });
    }
    let proxies = proxies(items);
    // obvhs recurses once per level of its tree (in its passes, and in a
    // debug build in its validation), and PLOC bounds no depth: on many
    // identical boxes the tree can be a chain, one level per triangle,
    // which overflowed a test thread's 2 MiB stack. It builds on a thread
    // of its own whose stack holds STACK_PER_ITEM per triangle (address
    // space only: pages are committed as they are touched); where that
    // thread cannot start, or obvhs panics, the binned builder builds.
    let stack = STACK_BASE.saturating_add(proxies.len().saturating_mul(STACK_PER_ITEM));
    let bvh2 = std::thread::scope(|scope| {
        std::thread::Builder::new()
            .stack_size(stack)
            .spawn_scoped(scope, || {
                build_bvh2(&proxies, quality.params(), &mut Duration::default())
            })
            .ok()?
            .join()
            .ok()
    })?;
    convert(&bvh2, items)
}

/// The builder thread's stack: a base, and room per triangle for one
/// level of obvhs's recursion (a debug build's frames are the larger).
const STACK_BASE: usize = 8 << 20;
const STACK_PER_ITEM: usize = 4 << 10;

/// The items' boxes, centred and scaled (halves first, so that nothing
/// overflows), in `f32`. Any rounding only moves the tree's shape.
fn proxies(items: &[Item]) -> Vec<Proxy> {
    let (lo, hi) = bounds(items);
    let centre = lo * 0.5 + hi * 0.5;
    let half_extent = (hi * 0.5 - lo * 0.5).max_element();
    let k = unit_scale(&[half_extent]);
    let frame = |p: DVec3| {
        let q = p * 0.5 - centre * 0.5;
        // `|q| <= half_extent` (up to rounding), so `2^(k+1) q` lies
        // within about 2 and converts to a finite `f32`.
        Vec3A::new(
            scale_pow2(q.x, k + 1) as f32,
            scale_pow2(q.y, k + 1) as f32,
            scale_pow2(q.z, k + 1) as f32,
        )
    };
    items
        .iter()
        .map(|it| Proxy(Aabb::new(frame(it.min), frame(it.max))))
        .collect()
}

/// obvhs's nodes in the binned builder's preorder layout (first child next, second
/// at `link`), with exact boxes; `None` for a tree deeper than
/// [`MAX_DEPTH`] or a leaf above [`LEAF`].
fn convert(bvh2: &Bvh2, items: &[Item]) -> Option<BinaryBvh> {
    let mut nodes: Vec<Node> = Vec::with_capacity(bvh2.nodes.len());
    let mut order = Vec::with_capacity(items.len());
    // (obvhs node, depth, the parent whose `link` is this node).
    let mut pending = vec![(0usize, 0usize, None::<usize>)];
    while let Some((at, depth, parent)) = pending.pop() {
        if depth >= MAX_DEPTH {
            return None;
        }
        let here = nodes.len();
        if let Some(p) = parent {
            nodes[p].link = here as u32;
        }
        let node = bvh2.nodes.get(at)?;
        let (first, count) = (node.first_index as usize, node.prim_count as usize);
        if count == 0 {
            nodes.push(Node::EMPTY);
            pending.push((first + 1, depth + 1, Some(here)));
            pending.push((first, depth + 1, None));
            continue;
        }
        if count > LEAF {
            return None;
        }
        let start = order.len();
        let mut leaf = Node::EMPTY;
        for &p in bvh2.primitive_indices.get(first..first + count)? {
            let it = items.get(p as usize)?;
            leaf.grow(it.min, it.max);
            order.push(it.index);
        }
        leaf.link = start as u32;
        leaf.count = count as u32;
        nodes.push(leaf);
    }
    // Children follow their parents in preorder: a reverse sweep sees
    // both children's boxes before the parent's.
    for at in (0..nodes.len()).rev() {
        if nodes[at].count == 0 {
            let (a, b) = (nodes[at + 1], nodes[nodes[at].link as usize]);
            nodes[at].grow(a.min.into(), a.max.into());
            nodes[at].grow(b.min.into(), b.max.into());
        }
    }
    (order.len() == items.len()).then_some(BinaryBvh { nodes, order })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid_items(n: u32, offset: f64) -> Vec<Item> {
        (0..n * n)
            .map(|k| {
                let p = DVec3::new(f64::from(k % n), f64::from(k / n), 0.0) + DVec3::splat(offset);
                Item {
                    min: p,
                    max: p + DVec3::new(1.0, 1.0, 0.5),
                    index: k,
                }
            })
            .collect()
    }

    /// On ordinary meshes PLOC's tree is used, not declined: every item in
    /// one leaf of at most `LEAF`, and every internal box the exact union
    /// of its children's; also where `f32` could not tell the items apart
    /// without the rescaling (a mesh at `1e12`, spacing 1).
    #[test]
    fn trees_are_kept_with_exact_boxes() {
        for offset in [0.0, 1e12] {
            let items = grid_items(40, offset);
            let bvh = build(&items, PlocQuality::Medium).expect("a shallow tree");
            let mut order = bvh.order.clone();
            order.sort_unstable();
            assert_eq!(order, (0..1600).collect::<Vec<u32>>());
            for (at, node) in bvh.nodes.iter().enumerate() {
                let mut want = Node::EMPTY;
                if node.count > 0 {
                    assert!(node.count as usize <= LEAF);
                    let start = node.link as usize;
                    for &i in &bvh.order[start..start + node.count as usize] {
                        want.grow(items[i as usize].min, items[i as usize].max);
                    }
                } else {
                    for c in [at + 1, node.link as usize] {
                        want.grow(bvh.nodes[c].min.into(), bvh.nodes[c].max.into());
                    }
                }
                assert_eq!((node.min, node.max), (want.min, want.max));
            }
        }
    }
}
