//! The nearest-point peers: `kiddo`'s immutable k-d tree and `rstar`'s
//! R*-tree, built and queried as their documentation shows.

use kiddo::{ImmutableKdTree, SquaredEuclidean};
use rstar::RTree;

/// A point as the indexes take it.
pub type Point = [f64; 3];

/// kiddo's index.
pub type KiddoTree = ImmutableKdTree<f64, 3>;

/// kiddo's tree of the points.
#[inline]
pub fn kiddo_build(points: &[Point]) -> KiddoTree {
    KiddoTree::new_from_slice(points).expect("fewer than 2^32 points")
}

/// The index of the point kiddo finds nearest to `q`.
#[inline]
pub fn kiddo_nearest(tree: &KiddoTree, q: &Point) -> usize {
    tree.query(q)
        .nearest_one::<SquaredEuclidean<f64>>()
        .execute()
        .item as usize
}

/// rstar's tree of the points, bulk loaded.
#[inline]
pub fn rstar_build(points: &[Point]) -> RTree<Point> {
    RTree::bulk_load(points.to_vec())
}
