//! The 8-wide hierarchy the queries walk: either builder's binary tree
//! collapsed into nodes of up to [`WIDTH`] children, each child's box
//! stored beside its siblings' (one `[f32; WIDTH]` per bound per axis,
//! in the hierarchy's frame, `frame.rs`),
//! so that the walk tests all of a node's children in one pass over
//! fixed-size arrays (`traverse.rs`).
//!
//! # The collapse
//! A binary subtree of at most [`LEAF`] triangles (a builder's leaf, or
//! an internal node over two small leaves) is taken as one leaf lane: its
//! triangles are contiguous in the leaf order (preorder puts a subtree's
//! leaves together), and its box is its root's. A wide node starts from
//! a larger binary node's two children and repeatedly replaces its
//! non-leaf child of largest surface area by that child's two children,
//! until it holds [`WIDTH`] children or only leaves (the collapse of a
//! binary SAH tree into a multi-branching one of Wald, Benthin and
//! Boulos, "Getting Rid of Packets", 2008). Each lane is then a leaf (it
//! holds the triangles) or links the wide node collapsed from its binary
//! node. A binary tree of at most [`LEAF`] triangles becomes one wide
//! node with one lane. Each lane's box is its binary node's exact box
//! rounded outward into the frame: it holds every point of that box.
//!
//! Taking small subtrees whole halved the terrain's wide nodes (leaves of
//! the binned builder hold two triangles on average, so most bottom
//! nodes held two or three lanes), for 4 to 6% more instructions per ray
//! (see ARCHITECTURE.md's design history).
//!
//! Every wide node's internal lanes link binary nodes strictly deeper
//! than the binary node it was collapsed from, so a path of wide nodes
//! from the root passes at most as many wide internal nodes as its
//! binary path had internal nodes: fewer than [`MAX_DEPTH`] (the
//! builders' bound, `build.rs` and `ploc.rs`).
//!
//! # Empty lanes
//! A node with fewer than [`WIDTH`] children fills the rest with an
//! inverted box, `min = +inf` and `max = -inf` on every axis. Whatever
//! the ray, every slab of that box computes an entry of `+inf` and an
//! exit of `-inf` (`(+inf - o) * inv` is `+inf` for `inv > 0`, and the
//! bounds swap with the sign of `inv`, `-0.0`'s too; no product is `inf
//! * 0`, as `inv` is never zero and the dividing path divides by a
//! finite direction; the world-coordinate path maps the infinite bounds
//! to infinities), so the widened entry is `inf - inf = NaN` and the
//! lane fails the walk's `<=`: culled by construction, never followed.
//!
//! [`MAX_DEPTH`]: super::MAX_DEPTH

use super::build::half_area;
use super::frame::Frame;
use super::{BinaryBvh, LEAF, Node};
use alloc::vec;
use alloc::vec::Vec;
use core::mem::size_of;
use glam::DVec3;

/// Children per wide node.
pub(crate) const WIDTH: usize = 8;

/// A wide node, 256 bytes (four cache lines): per lane `l` the child's box
/// in the hierarchy's frame, rounded outward to `f32` (`min[k][l]`,
/// `max[k][l]` on axis `k`, `frame.rs`), and `count[l] > 0` for a leaf
/// holding the items `order[link[l] .. link[l] + count[l]]`, `count[l] ==
/// 0` for an internal child `nodes[link[l]]` (or an empty lane: inverted
/// box, see the module docs).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(crate) struct WideNode {
    pub(crate) min: [[f32; WIDTH]; 3],
    pub(crate) max: [[f32; WIDTH]; 3],
    pub(crate) link: [u32; WIDTH],
    pub(crate) count: [u32; WIDTH],
}

// Six SoA bound rows of eight `f32` and two rows of eight `u32`, 32
// bytes each: 256 bytes, four 64-byte lines, each row one AVX register
// (two SSE registers without AVX2).
const _: () = assert!(size_of::<WideNode>() == 256);
const _: () = assert!(core::mem::align_of::<WideNode>() == 64);

impl WideNode {
    /// Every lane empty (see the module docs).
    pub(crate) const EMPTY: WideNode = WideNode {
        min: [[f32::INFINITY; WIDTH]; 3],
        max: [[f32::NEG_INFINITY; WIDTH]; 3],
        link: [0; WIDTH],
        count: [0; WIDTH],
    };

    /// Puts binary node `b`'s box in lane `l`, rounded outward into
    /// `frame`.
    fn set_box(&mut self, l: usize, b: &Node, frame: &Frame) {
        for k in 0..3 {
            self.min[k][l] = frame.down(b.min[k], k);
            self.max[k][l] = frame.up(b.max[k], k);
        }
    }
}

/// The wide nodes collapsed from `binary` (see the module docs), the
/// root first and each node before its children.
pub(super) fn collapse(binary: &BinaryBvh, frame: &Frame) -> Vec<WideNode> {
    let nodes = &binary.nodes;
    // About three binary internal nodes per wide node.
    let mut wide = Vec::with_capacity(nodes.len() / 6 + 1);
    if nodes.is_empty() {
        return wide;
    }
    let leaves = subtree_leaves(nodes);
    // A binary node taken as one leaf lane: a leaf, or a subtree of at
    // most LEAF triangles (contiguous in the leaf order).
    let is_leaf = |b: usize| leaves[b].1 as usize <= LEAF;
    // (binary node, the wide lane that links the node made from it).
    let mut pending = vec![(0usize, None::<(usize, usize)>)];
    while let Some((b, parent)) = pending.pop() {
        let here = wide.len();
        if let Some((p, l)) = parent {
            wide[p].link[l] = here as u32;
        }
        let mut children = [b; WIDTH];
        let mut n = 1;
        if !is_leaf(b) {
            children[..2].copy_from_slice(&[b + 1, nodes[b].link as usize]);
            n = 2;
            while n < WIDTH {
                // The non-leaf child of largest area, opened in place.
                let open = (0..n).filter(|&i| !is_leaf(children[i])).max_by(|&i, &j| {
                    area(&nodes[children[i]]).total_cmp(&area(&nodes[children[j]]))
                });
                let Some(i) = open else { break };
                let c = children[i];
                children[i] = c + 1;
                children[n] = nodes[c].link as usize;
                n += 1;
            }
        }
        let mut node = WideNode::EMPTY;
        for (l, &c) in children[..n].iter().enumerate() {
            node.set_box(l, &nodes[c], frame);
            if is_leaf(c) {
                (node.link[l], node.count[l]) = leaves[c];
            }
        }
        wide.push(node);
        // Pushed last-lane first, so that lane 0's subtree follows its
        // parent in memory.
        for (l, &c) in children[..n].iter().enumerate().rev() {
            if !is_leaf(c) {
                pending.push((c, Some((here, l))));
            }
        }
    }
    wide
}

/// Per binary node, where its subtree's triangles start in the leaf order
/// and how many there are (preorder: a subtree's leaves are contiguous,
/// its first child's first).
fn subtree_leaves(nodes: &[Node]) -> Vec<(u32, u32)> {
    let mut out: Vec<(u32, u32)> = nodes.iter().map(|n| (n.link, n.count)).collect();
    // Children follow their parents: a reverse sweep sees both first.
    for at in (0..nodes.len()).rev() {
        if nodes[at].count == 0 {
            let (a, b) = (out[at + 1], out[nodes[at].link as usize]);
            out[at] = (a.0, a.1.saturating_add(b.1));
        }
    }
    out
}

/// What the collapse opens first: a binary node's half surface area.
fn area(n: &Node) -> f64 {
    half_area(DVec3::from(n.min), DVec3::from(n.max))
}
