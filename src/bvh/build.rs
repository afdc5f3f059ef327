//! Top-down construction: median splits along the widest axis of a
//! conservative box, leaves of at most [`LEAF`] points, spheres fitted
//! bottom-up (a leaf's around its points, a parent's around its children's).

use super::sphere::{merge, norm2_root_up, sum_up, unscale_up};
use super::{CacheLine, Child, LEAF, Node, SphereBvh, Spheres, first_part};
use crate::arith::exponent::unit_pow2;
use alloc::vec;
use alloc::vec::Vec;
use glam::DVec3;

/// A point and its original index, moved around while building.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Entry {
    pub p: DVec3,
    /// The item's radius: 0 for a point.
    pub r: f64,
    pub index: u32,
}

/// Below this many points a subtree is built on the calling thread: smaller
/// tasks cost more to hand over than they take.
#[cfg(feature = "rayon")]
const PARALLEL_MIN: usize = 1 << 15;

/// Builds the index; `entries` are finite.
/// `balls`: keep the radii (an index of spheres).
pub(crate) fn build(mut entries: Vec<Entry>, max_abs: f64, balls: bool) -> SphereBvh {
    let scale = unit_pow2(max_abs);
    let mut nodes = Vec::with_capacity(entries.len() / 4 + 1);
    let root = if entries.is_empty() {
        None
    } else {
        Some(subtree(&mut entries, 0, scale, &mut nodes))
    };
    let (nodes, spheres) = nodes.into_iter().unzip();
    SphereBvh {
        xs: padded(entries.iter().map(|e| e.p.x)),
        ys: padded(entries.iter().map(|e| e.p.y)),
        zs: padded(entries.iter().map(|e| e.p.z)),
        index: entries.iter().map(|e| e.index).collect(),
        radii: if balls {
            entries.iter().map(|e| e.r).collect()
        } else {
            Vec::new()
        },
        nodes,
        spheres,
        root,
        max_abs,
    }
}

/// One coordinate of every point in blocks of 8, then [`LEAF`] points of
/// zeros, so that a leaf's distances can be computed over a whole leaf's
/// worth of lanes (see `traverse::leaf`).
fn padded(coordinates: impl ExactSizeIterator<Item = f64>) -> Vec<CacheLine> {
    let mut v = vec![CacheLine([0.0; 8]); coordinates.len().div_ceil(8) + LEAF / 8];
    for (i, c) in coordinates.enumerate() {
        v[i / 8].0[i % 8] = c;
    }
    v
}

/// The bounding box of a non-empty set.
fn bounds(entries: &[Entry]) -> (DVec3, DVec3) {
    entries.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), e| (lo.min(e.p), hi.max(e.p)),
    )
}

/// Builds the subtree over `entries` (non-empty; they sit at `offset` in
/// tree order) into `nodes`, splitting at the median of the widest axis of
/// their bounding box.
fn subtree(
    entries: &mut [Entry],
    offset: u32,
    scale: f64,
    nodes: &mut Vec<(Node, Spheres)>,
) -> Child {
    let (lo, hi) = bounds(entries);
    if entries.len() <= LEAF {
        let (center, radius) = points_sphere(entries, (lo, hi), scale);
        return Child {
            center,
            radius,
            link: offset,
            len: entries.len() as u32,
        };
    }
    // Halves of the extent: `hi - lo` could overflow.
    let axis = (hi * 0.5 - lo * 0.5).max_position();
    let mid = first_part(entries.len());
    entries.select_nth_unstable_by(mid, |a, b| a.p[axis].total_cmp(&b.p[axis]));
    let split = entries[mid].p[axis];
    let (left, right) = entries.split_at_mut(mid);
    let right_offset = offset + mid as u32;

    #[cfg(feature = "rayon")]
    if left.len() + right.len() >= PARALLEL_MIN {
        let ((lc, ln), (rc, rn)) = rayon::join(
            || owned_subtree(left, offset, scale),
            || owned_subtree(right, right_offset, scale),
        );
        let me = nodes.len();
        nodes.push(placeholder());
        let lc = append(nodes, ln, lc);
        let rc = append(nodes, rn, rc);
        let around = points_sphere(entries, (lo, hi), scale);
        return parent(nodes, me, [lc, rc], (axis, split), around, scale);
    }

    let me = nodes.len();
    nodes.push(placeholder());
    let lc = subtree(left, offset, scale, nodes);
    let rc = subtree(right, right_offset, scale, nodes);
    let around = points_sphere(entries, (lo, hi), scale);
    parent(nodes, me, [lc, rc], (axis, split), around, scale)
}

/// A subtree in a vector of its own (for a parallel task).
#[cfg(feature = "rayon")]
fn owned_subtree(entries: &mut [Entry], offset: u32, scale: f64) -> (Child, Vec<(Node, Spheres)>) {
    let mut nodes = Vec::with_capacity(entries.len() / 4 + 1);
    let child = subtree(entries, offset, scale, &mut nodes);
    (child, nodes)
}

/// Appends a subtree built on its own, moving its node links by where it
/// lands; returns its root with the moved link.
#[cfg(feature = "rayon")]
fn append(nodes: &mut Vec<(Node, Spheres)>, sub: Vec<(Node, Spheres)>, mut root: Child) -> Child {
    let base = nodes.len() as u32;
    // A leaf's `right` is unused: moving every one is harmless.
    nodes.extend(sub.into_iter().map(|(mut n, sp)| {
        n.right += base;
        (n, sp)
    }));
    if root.len == 0 {
        root.link += base;
    }
    root
}

fn placeholder() -> (Node, Spheres) {
    (
        Node {
            split: 0.0,
            right: 0,
            axis: 0,
        },
        Spheres {
            cx: [0.0; 2],
            cy: [0.0; 2],
            cz: [0.0; 2],
            r: [0.0; 2],
        },
    )
}

/// Fills in node `me` from its children and returns it as a child. Its
/// sphere is the smaller of the one around its children's spheres and
/// `around`, the one around its points: either encloses every point below.
fn parent(
    nodes: &mut [(Node, Spheres)],
    me: usize,
    [l, r]: [Child; 2],
    (axis, split): (usize, f64),
    around: (DVec3, f64),
    scale: f64,
) -> Child {
    nodes[me] = (
        Node {
            split,
            right: if r.len == 0 { r.link } else { 0 },
            axis: axis as u32,
        },
        Spheres {
            cx: [l.center.x, r.center.x],
            cy: [l.center.y, r.center.y],
            cz: [l.center.z, r.center.z],
            r: [l.radius, r.radius],
        },
    );
    let (mut center, mut radius) = merge(l.center, l.radius, r.center, r.radius, scale);
    if around.1 < radius {
        (center, radius) = around;
    }
    Child {
        center,
        radius,
        link: me as u32,
        len: 0,
    }
}

/// The sphere around the centre of the points' bounding box `lo..hi`, with
/// a radius that bounds every point's exact distance from that centre.
fn points_sphere(entries: &[Entry], (lo, hi): (DVec3, DVec3), scale: f64) -> (DVec3, f64) {
    let center = lo * 0.5 + hi * 0.5;
    let squared = |e: &Entry| {
        let d = (e.p - center) * scale;
        d.x * d.x + d.y * d.y + d.z * d.z
    };
    if entries.iter().all(|e| e.r == 0.0) {
        let far = entries.iter().map(squared).fold(0.0f64, f64::max);
        return (center, unscale_up(norm2_root_up(far), scale));
    }
    // Balls: the farthest surface point, `|c_i - center| + r_i`, bounded above.
    let radius = entries
        .iter()
        .map(|e| sum_up(unscale_up(norm2_root_up(squared(e)), scale), e.r))
        .fold(0.0f64, f64::max);
    (center, radius)
}
