//! A bounding-sphere hierarchy over points or balls, for exact nearest-item
//! queries (question Q8 of `docs/pictures.md`): [`SphereBvh`].
//!
//! Every node holds a sphere that encloses its points; a query keeps the best
//! distance `d` found so far and never descends into a node whose sphere
//! cannot hold a closer point, `|c - q| - r >= d` (the prune), visiting
//! the nearer child first. For points, a second lower bound prunes too: the
//! distance to the node's box, the intersection of the half-spaces of the
//! median split planes above it (Arya and Mount's incremental distance).
//!
//! # Exactness
//! Squared distances are computed in `f64` with a proven relative error bound
//! (see `predicates::distance`). When two candidates' computed squared
//! distances are within that bound of each other, an exact comparison
//! ([`compare_distance`](crate::predicates::compare_distance)) decides, and
//! exact ties go to the smaller index. The prune is made conservative by the
//! same bound, so rounding never discards a true nearest point: the answer is
//! always a true nearest point (the one with the smallest index among exact
//! ties), for every finite input, including coordinates whose squares
//! underflow or overflow.
//!
//! An index built with [`SphereBvh::from_spheres`] holds balls and measures
//! the distance from the query to each ball, `max(0, |c - q| - r)`; near-ties
//! are decided exactly there too (`predicates::ball`: the square roots are
//! squared away with case analysis, leaving integer polynomials of degree 4).
//!
//! # Spheres, memory and build
//! Built top-down by median splits along the widest axis (the first half
//! rounded to a multiple of 8 points, so that every leaf starts on a cache
//! line of each coordinate array; in parallel with rayon above 32,768
//! points under the `rayon` feature), into leaves of 16 to 32 points. A leaf's sphere is centred on its points' bounding box and
//! encloses them. A parent's sphere encloses every point below it: it is the
//! smaller of the smallest sphere around its two children's spheres and the
//! sphere around its own points' bounding-box centre; the second is usually
//! the smaller (the measurements behind this and the other choices here are
//! in ARCHITECTURE.md, "Design history"). Every radius is rounded up with a
//! proven margin (`sphere.rs`), so it bounds the exact distances.
//!
//! # The walk
//! (`traverse.rs`.) A query first descends along the side of each split
//! plane that holds `q`, testing no sphere (nothing can be pruned before the
//! first leaf) and stacking every far child with its box. Afterwards a
//! popped child is tested against the best so far by its box, then by its
//! sphere, and on the way down only the near child's sphere is tested (its
//! box is its parent's). A leaf's distances are computed in one vector pass
//! over all `LEAF` (32) lanes; the nearest-point query rejects a leaf whose
//! least distance is certainly beyond the best, and otherwise only looks at
//! the lanes near that least distance. At 10^6 uniform points a query visits
//! 21.6 nodes and computes 71 distances (the report's `nearest` notes).
//!
//! The nodes are laid out for memory, which bounds query time at 10^6
//! points more than instructions do: 16 bytes each (split, second child,
//! axis) in preorder, every child's point range derived from its subtree's
//! size, the children's spheres apart (64 bytes per node, read only
//! when tested), each record aligned to its size, and the points in blocks
//! of 8 per coordinate with every leaf starting on a block, so a leaf's 32
//! lanes are 4 whole cache lines per coordinate.
//!
//! Tightness, from `cargo test --test bvh leaf_spheres -- --nocapture`: leaf
//! radii average 1.07x (uniform points) and 1.07x (clustered points) the
//! radius of the minimal enclosing sphere of the same points.
//!
//! Memory ([`SphereBvh::memory_bytes`]): 28 bytes per point (coordinates and
//! original index, the coordinates in cache-line blocks of 8 and padded by
//! `LEAF` (32) points) plus, per
//! internal node (one per 16 to 32 points), 16 bytes of node and 64 of
//! spheres: 30.6 to 31.9 bytes per point in all (the report's
//! `nearest_build`).

mod batch;
pub mod boxes;
mod build;
mod nearest;
mod radius;
mod sphere;
mod traverse;

use crate::arith::exponent::unit_pow2;
use crate::error::InputError;
use crate::point::IntoDVec3;
use alloc::vec::Vec;
use core::mem::{align_of, size_of};
use glam::DVec3;

/// Most points a leaf holds. Leaf distances are computed in one vectorized
/// pass, so bigger leaves cost little; 32 measured fastest against 8, 16
/// and 64 (ARCHITECTURE.md, "Design history").
pub(crate) const LEAF: usize = 32;

/// Points in the first child of a subtree of `count > LEAF` points: half,
/// rounded to a multiple of 8, so that every leaf starts on a multiple of 8
/// points, a cache line of each coordinate array (see [`CacheLine`]). The build
/// splits by it and the walk derives the children's ranges from it.
#[inline(always)]
pub(crate) fn first_part(count: usize) -> usize {
    (count / 2 + 4) & !7
}

/// Eight consecutive values of one coordinate, aligned to a cache line: a
/// leaf (which starts on a multiple of 8 points, see [`first_part`]) reads
/// whole lines, four per coordinate for its 32 lanes.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(crate) struct CacheLine(pub [f64; 8]);

/// Points per index the tree can hold: indices are `u32`.
pub const MAX_POINTS: usize = u32::MAX as usize;

/// One answer of a nearest-point query.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Nearest {
    /// The point's position in the slice the index was built from.
    pub index: usize,
    /// The point (for an index built from spheres, the ball's centre).
    pub point: DVec3,
    /// Its Euclidean distance to the query, within 4 ulps of the exact
    /// distance (relative error below `3.5 * 2^-53`), unless that distance
    /// is subnormal or above `f64::MAX` (then it is `inf`). For an index
    /// built from spheres, the distance to the ball, `max(0, |c - q| - r)`,
    /// computed from that distance to the centre (so within 4 ulps of
    /// `|c - q|`, absolutely). Which item is returned never depends on this
    /// rounding.
    pub distance: f64,
}

/// Work done by one query, for tests and tuning: see
/// [`SphereBvh::nearest_with_stats`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QueryStats {
    /// Nodes whose children (or, for a leaf, whose points) were examined.
    pub nodes_visited: u64,
    /// Point distances computed.
    pub distances_computed: u64,
    /// Near-ties decided by an exact comparison.
    pub exact_comparisons: u64,
}

/// Where query statistics go: nowhere for ordinary queries, so that their
/// code has no counters at all.
pub(crate) trait Counter {
    fn node(&mut self) {}
    fn distances(&mut self, _n: usize) {}
    fn exact(&mut self) {}
}

impl Counter for () {}

impl Counter for QueryStats {
    #[inline]
    fn node(&mut self) {
        self.nodes_visited += 1;
    }
    #[inline]
    fn distances(&mut self, n: usize) {
        self.distances_computed += n as u64;
    }
    #[inline]
    fn exact(&mut self) {
        self.exact_comparisons += 1;
    }
}

/// A child of a node (or the root): its bounding sphere and where it lives.
/// `len > 0`: a leaf holding points `link .. link + len`; `len == 0`: the
/// internal node `nodes[link]`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Child {
    pub center: DVec3,
    /// An upper bound on the distance from `center` to every point below.
    pub radius: f64,
    pub link: u32,
    pub len: u32,
}

/// An internal node as the walk reads it at every step: the plane that
/// split its points and where its second child is. Nodes are in preorder,
/// so an internal first child is the next node; and a subtree's points are
/// a range whose split is fixed by its size (the first child takes
/// [`first_part`]; a subtree of at most [`LEAF`] points is a leaf), so the
/// walk derives every child's range and kind as it goes. Its children's spheres
/// live apart, in [`Spheres`]: the first descent of a query reads no
/// sphere, and 16-byte nodes keep the path it walks small.
#[derive(Clone, Copy, Debug)]
#[repr(align(16))]
pub(crate) struct Node {
    /// The median split: child 0's points have coordinate `axis` at most
    /// `split`, child 1's at least `split`.
    pub split: f64,
    /// The node index of the second child when it is internal (unused for
    /// a leaf).
    pub right: u32,
    pub axis: u32,
}

/// The spheres of an internal node's two children side by side, so that
/// one fetch serves either.
#[derive(Clone, Copy, Debug)]
#[repr(align(64))]
pub(crate) struct Spheres {
    pub cx: [f64; 2],
    pub cy: [f64; 2],
    pub cz: [f64; 2],
    pub r: [f64; 2],
}

// The layouts the module docs promise: 16-byte nodes, 64-byte sphere pairs
// and coordinate blocks, each aligned to its size.
const _: () = assert!(size_of::<Node>() == 16 && align_of::<Node>() == 16);
const _: () = assert!(size_of::<Spheres>() == 64 && align_of::<Spheres>() == 64);
const _: () = assert!(size_of::<CacheLine>() == 64 && align_of::<CacheLine>() == 64);

/// A bounding-sphere hierarchy over a set of points, answering nearest,
/// k-nearest and within-radius queries exactly (see the [module
/// docs](self)). Queries never allocate.
///
/// ```
/// use exactray::bvh::SphereBvh;
/// let points = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
/// let bvh = SphereBvh::from_points(&points).unwrap();
/// let hit = bvh.nearest([0.9, 0.2, 0.0]).unwrap();
/// assert_eq!(hit.index, 1);
/// // (0.5, 0, 0) is exactly as far from points 0 and 1: the smaller index wins.
/// assert_eq!(bvh.nearest([0.5, 0.0, 0.0]).unwrap().index, 0);
/// ```
#[derive(Clone, Debug)]
pub struct SphereBvh {
    /// The points, reordered so that every leaf is a contiguous range.
    pub(crate) xs: Vec<CacheLine>,
    pub(crate) ys: Vec<CacheLine>,
    pub(crate) zs: Vec<CacheLine>,
    /// The original index of each reordered point.
    pub(crate) index: Vec<u32>,
    /// Item radii in tree order, for an index built from spheres; empty for
    /// points.
    pub(crate) radii: Vec<f64>,
    pub(crate) nodes: Vec<Node>,
    /// `spheres[i]`: the spheres of `nodes[i]`'s children.
    pub(crate) spheres: Vec<Spheres>,
    /// The root's sphere and link; `None` for an empty index.
    pub(crate) root: Option<Child>,
    /// The largest coordinate magnitude of any point.
    pub(crate) max_abs: f64,
}

impl SphereBvh {
    /// Builds the index over `points` (any [`IntoDVec3`]: `DVec3`, `Vec3`,
    /// `[f64; 3]`, ...; `f32` coordinates widen exactly). Duplicates are kept.
    ///
    /// An empty slice gives an empty index, whose queries return `None`.
    /// Errors: [`InputError::NonFinite`] (argument `"points"`) when a
    /// coordinate is NaN or infinite; [`InputError::TooManyItems`] above
    /// [`MAX_POINTS`] points.
    ///
    /// ```
    /// use exactray::prelude::*;
    /// assert!(SphereBvh::from_points::<[f64; 3]>(&[]).unwrap().nearest([0.0; 3]).is_none());
    /// let err = SphereBvh::from_points(&[[0.0, f64::NAN, 0.0]]).unwrap_err();
    /// assert_eq!(err, InputError::NonFinite { argument: "points" });
    /// ```
    pub fn from_points<P: IntoDVec3>(points: &[P]) -> Result<SphereBvh, InputError> {
        if points.len() > MAX_POINTS {
            return Err(InputError::TooManyItems { max: MAX_POINTS });
        }
        let mut max_abs = 0.0f64;
        let mut entries = Vec::with_capacity(points.len());
        for (i, p) in points.iter().enumerate() {
            let p = p.into_dvec3();
            if !p.is_finite() {
                return Err(InputError::NonFinite { argument: "points" });
            }
            max_abs = max_abs.max(p.abs().max_element());
            entries.push(build::Entry {
                p,
                r: 0.0,
                index: i as u32,
            });
        }
        Ok(build::build(entries, max_abs, false))
    }

    /// Builds the index over balls `(centre, radius)`: queries then measure
    /// the distance from the query to each ball, `max(0, |c - q| - r)` (zero
    /// inside), and compare those exactly; [`Nearest::point`] is the centre.
    ///
    /// Errors: [`InputError::NonFinite`] (argument `"spheres"`) for a NaN or
    /// infinite centre coordinate or an infinite radius;
    /// [`InputError::InvalidRadius`] (argument `"spheres"`) for a negative
    /// or NaN radius; [`InputError::TooManyItems`] above [`MAX_POINTS`].
    ///
    /// ```
    /// use exactray::bvh::SphereBvh;
    /// let balls = [([0.0, 0.0, 0.0], 1.0), ([5.0, 0.0, 0.0], 3.0)];
    /// let bvh = SphereBvh::from_spheres(&balls).unwrap();
    /// // 2.5 from the first ball's surface, 0.5 from the second's.
    /// let hit = bvh.nearest([3.5, 0.0, 0.0]).unwrap();
    /// assert_eq!((hit.index, hit.distance), (1, 0.0));
    /// let hit = bvh.nearest([-2.0, 0.0, 0.0]).unwrap();
    /// assert_eq!((hit.index, hit.distance), (0, 1.0));
    /// ```
    pub fn from_spheres<P: IntoDVec3>(spheres: &[(P, f64)]) -> Result<SphereBvh, InputError> {
        if spheres.len() > MAX_POINTS {
            return Err(InputError::TooManyItems { max: MAX_POINTS });
        }
        let argument = "spheres";
        let mut max_abs = 0.0f64;
        let mut entries = Vec::with_capacity(spheres.len());
        for (i, &(c, r)) in spheres.iter().enumerate() {
            let p = c.into_dvec3();
            if r.is_nan() || r < 0.0 {
                return Err(InputError::InvalidRadius { argument });
            }
            if !p.is_finite() || r.is_infinite() {
                return Err(InputError::NonFinite { argument });
            }
            max_abs = max_abs.max(p.abs().max_element()).max(r);
            entries.push(build::Entry {
                p,
                r,
                index: i as u32,
            });
        }
        Ok(build::build(entries, max_abs, true))
    }

    /// The number of points.
    #[inline]
    pub fn len(&self) -> usize {
        self.index.len()
    }

    /// `true` when the index holds no point.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.index.is_empty()
    }

    /// Heap bytes held: coordinates (24 per point), original indices (4 per
    /// point) and internal nodes (80 each with their children's spheres, one
    /// per 16 to 32 points).
    pub fn memory_bytes(&self) -> usize {
        (self.xs.capacity() + self.ys.capacity() + self.zs.capacity()) * 64
            + self.index.capacity() * 4
            + self.radii.capacity() * 8
            + self.nodes.capacity() * core::mem::size_of::<Node>()
            + self.spheres.capacity() * core::mem::size_of::<Spheres>()
    }

    /// Every leaf's bounding sphere (centre, radius) and the original indices
    /// of the points it holds, for inspection and tests. Each radius bounds
    /// the exact distance from the centre to each of the leaf's points.
    ///
    /// ```
    /// use exactray::bvh::SphereBvh;
    /// let bvh = SphereBvh::from_points(&[[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]).unwrap();
    /// let (center, radius, indices) = bvh.leaf_spheres().next().unwrap();
    /// assert_eq!((center.x, indices), (1.0, &[0u32, 1][..]));
    /// assert!(radius >= 1.0 && radius < 1.0 + 1e-15);
    /// ```
    pub fn leaf_spheres(&self) -> impl Iterator<Item = (DVec3, f64, &[u32])> + '_ {
        self.leaves().map(|c| {
            let range = c.link as usize..(c.link + c.len) as usize;
            (c.center, c.radius, &self.index[range])
        })
    }

    /// Every leaf as a [`Child`], depth first.
    pub(crate) fn leaves(&self) -> impl Iterator<Item = Child> + '_ {
        // Subtrees to go: node (or leaf), first point, size, sphere. Depth
        // first, at most one pending entry per level (see `traverse`).
        let mut stack = [(0u32, 0u32, 0u32, DVec3::ZERO, 0.0f64); 64];
        let mut top = 0;
        if let Some(root) = self.root {
            stack[0] = (root.link, 0, self.len() as u32, root.center, root.radius);
            top = 1;
        }
        core::iter::from_fn(move || {
            loop {
                if top == 0 {
                    return None;
                }
                top -= 1;
                let (at, start, count, center, radius) = stack[top];
                if count as usize <= LEAF {
                    return Some(Child {
                        center,
                        radius,
                        link: start,
                        len: count,
                    });
                }
                let (Some(node), Some(sp)) =
                    (self.nodes.get(at as usize), self.spheres.get(at as usize))
                else {
                    continue;
                };
                let half = first_part(count as usize) as u32;
                let sphere = |k: usize| (DVec3::new(sp.cx[k], sp.cy[k], sp.cz[k]), sp.r[k]);
                let ((c1, r1), (c0, r0)) = (sphere(1), sphere(0));
                if top + 2 <= stack.len() {
                    stack[top] = (node.right, start + half, count - half, c1, r1);
                    stack[top + 1] = (at + 1, start, half, c0, r0);
                    top += 2;
                }
            }
        })
    }

    /// The `i`-th point in tree order.
    #[inline(always)]
    pub(crate) fn point(&self, i: usize) -> DVec3 {
        let (b, k) = (i / 8, i % 8);
        DVec3::new(self.xs[b].0[k], self.ys[b].0[k], self.zs[b].0[k])
    }

    /// The answer for tree position `i` and query `q`.
    #[inline]
    pub(crate) fn answer(&self, i: usize, q: DVec3) -> Nearest {
        let point = self.point(i);
        let to_centre = distance(point, q);
        Nearest {
            index: self.index[i] as usize,
            point,
            distance: match self.radii.get(i) {
                Some(&r) => (to_centre - r).max(0.0),
                None => to_centre,
            },
        }
    }
}

/// `|p - q|` within 4 ulps for finite input, unless the result is
/// subnormal or beyond `f64::MAX` (`inf`). The difference is scaled by the
/// power of two that brings its largest coordinate near 1, so no square
/// under- or overflows: the difference, squares, sums and the `sqrt` round
/// once each, a relative error below `3.5u` (Higham 2002, Lemma 3.1).
pub(crate) fn distance(p: DVec3, q: DVec3) -> f64 {
    let mut d = p - q;
    let mut unscale = 1.0;
    if !d.is_finite() {
        // The difference overflowed; halves cannot.
        d = p * 0.5 - q * 0.5;
        unscale = 2.0;
    }
    let s = unit_pow2(d.abs().max_element());
    let v = d * s;
    sqrt(v.x * v.x + v.y * v.y + v.z * v.z) / s * unscale
}

pub(crate) use crate::arith::std_or_libm::sqrt;
