//! The box hierarchy of triangle meshes and scenes: axis-aligned boxes
//! over items (a mesh's triangles, a scene's primitives), built as a
//! binary tree and walked as a wide one.
//!
//! Built once with a binned surface-area heuristic (12 bins, leaves of up
//! to [`LEAF`] items, depth at most [`MAX_DEPTH`]; `build.rs`), or by
//! obvhs's PLOC builder under the `ploc` feature (`ploc.rs`), then
//! collapsed into an 8-wide tree whose nodes hold up to eight children's
//! boxes side by side (`wide.rs`). The builders' boxes are the exact
//! minimum and maximum of their items' boxes; the wide nodes store them
//! rounded outward to `f32`, relative to a centre and a power-of-two
//! scale of the hierarchy's own (`frame.rs`), so that they keep `f32`'s
//! precision for the mesh's size wherever it lies and at every scale. The
//! slab test, run on a node's eight children at once in `f32`, is widened
//! by a derived bound that also covers the rounding of the ray into the
//! frame, so that it never culls a box that the ray's exact segment
//! meets (`traverse.rs`), and a query walks with a fixed stack of `7 *
//! MAX_DEPTH` entries: no query allocates.

mod build;
mod frame;
#[cfg(feature = "ploc")]
mod ploc;
mod point_walk;
mod traverse;
mod wide;

pub(crate) use build::Item;
#[cfg(feature = "ploc")]
pub use ploc::PlocQuality;
pub(crate) use point_walk::{PointVisitor, box_distance_below, walk_point};
pub(crate) use traverse::{Visitor, walk, walk_halved_segment};
#[cfg(test)]
pub(crate) use wide::WIDTH;
pub(crate) use wide::WideNode;

use alloc::vec::Vec;
use core::mem::size_of;
use frame::Frame;
use glam::DVec3;
use wide::collapse;

/// Most items (triangles, primitives) in a leaf.
pub const LEAF: usize = 4;

/// The deepest a leaf of the builders' binary trees lies below the root,
/// plus one (the binned builder's bound is 63, see `build.rs`; the PLOC
/// builder declines deeper trees): a query's stack holds `7 * MAX_DEPTH`
/// entries, seven pending children per level of the 8-wide tree walked
/// (`traverse.rs`).
pub const MAX_DEPTH: usize = 64;

/// A node of the builders' binary tree, 56 bytes: its box (`min`, `max`,
/// exact), and `count > 0` for a leaf holding the triangles `order[link ..
/// link + count]`, or `count == 0` for an internal node whose first child
/// is the next node (preorder) and whose second is `nodes[link]`. The
/// queries walk it collapsed into 8-wide nodes (`wide.rs`).
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub(crate) struct Node {
    min: [f64; 3],
    max: [f64; 3],
    link: u32,
    count: u32,
}

const _: () = assert!(size_of::<Node>() == 56);

/// What the PLOC builder (`ploc.rs`, with `ploc`) writes nodes with.
#[cfg(feature = "ploc")]
impl Node {
    /// A box holding nothing (`min` above `max`), to grow.
    const EMPTY: Node = Node {
        min: [f64::INFINITY; 3],
        max: [f64::NEG_INFINITY; 3],
        link: 0,
        count: 0,
    };

    /// Widens the box to hold `[min, max]` (exact: min and max round
    /// nothing).
    #[inline]
    fn grow(&mut self, min: DVec3, max: DVec3) {
        self.min = DVec3::from(self.min).min(min).to_array();
        self.max = DVec3::from(self.max).max(max).to_array();
    }
}

/// How a triangle mesh or a scene builds its hierarchy. Either way the boxes are
/// exact and the queries' answers the same; the builders differ in the
/// tree's shape, so in build and query time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum BvhBuilder {
    /// The crate's own binned surface-area-heuristic builder (`build.rs`),
    /// available without `std`.
    BinnedSah,
    /// obvhs's PLOC builder with reinsertion and leaf collapse (the
    /// `ploc` feature),
    /// run on a thread of its own with a stack sized for its recursion,
    /// falling back to [`BvhBuilder::BinnedSah`] for a tree deeper than
    /// the walk's stack, or where that thread cannot start or obvhs
    /// panics (see `ploc.rs`).
    #[cfg(feature = "ploc")]
    Ploc(PlocQuality),
}

impl Default for BvhBuilder {
    /// The builder whose trees measured fastest to query (the report's
    /// `closest_hit` family): see the README.
    fn default() -> Self {
        BvhBuilder::BinnedSah
    }
}

/// A builder's binary tree: nodes in preorder and the triangle indices in
/// leaf order.
#[derive(Clone, Debug)]
pub(crate) struct BinaryBvh {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

/// The hierarchy the queries walk: the builder's tree collapsed into 8-wide
/// nodes (`wide.rs`) whose boxes are rounded outward to `f32` in the
/// hierarchy's frame (`frame.rs`), the root first, the item indices in
/// leaf order (the binary tree's, unchanged), and the exact box of every
/// item.
#[derive(Clone, Debug)]
pub(crate) struct BoxBvh {
    pub(crate) nodes: Vec<WideNode>,
    pub(crate) order: Vec<u32>,
    pub(crate) frame: Frame,
    bounds: Option<(DVec3, DVec3)>,
}

impl From<BinaryBvh> for BoxBvh {
    /// The collapse runs after either builder.
    fn from(binary: BinaryBvh) -> BoxBvh {
        let bounds = binary
            .nodes
            .first()
            .map(|n| (DVec3::from(n.min), DVec3::from(n.max)));
        let frame = bounds.map_or(Frame::EMPTY, |(lo, hi)| Frame::of(lo, hi));
        BoxBvh {
            nodes: collapse(&binary, &frame),
            order: binary.order,
            frame,
            bounds,
        }
    }
}

impl BoxBvh {
    /// The hierarchy over no item.
    pub(crate) const EMPTY: BoxBvh = BoxBvh {
        nodes: Vec::new(),
        order: Vec::new(),
        frame: Frame::EMPTY,
        bounds: None,
    };

    /// The hierarchy over `items` (possibly none), built by `builder`.
    pub(crate) fn build(items: Vec<Item>, builder: BvhBuilder) -> BoxBvh {
        let binary = match builder {
            BvhBuilder::BinnedSah => build::build(items),
            #[cfg(feature = "ploc")]
            BvhBuilder::Ploc(quality) => {
                ploc::build(&items, quality).unwrap_or_else(|| build::build(items))
            }
        };
        binary.into()
    }

    /// The exact box of every item in the hierarchy, `None` when it holds
    /// none.
    pub(crate) fn bounds(&self) -> Option<(DVec3, DVec3)> {
        self.bounds
    }

    /// The bytes its nodes and leaf order take.
    pub(crate) fn bytes(&self) -> usize {
        self.nodes.len() * size_of::<WideNode>() + self.order.len() * size_of::<u32>()
    }
}
