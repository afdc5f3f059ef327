//! spade's Delaunay triangulation (`DelaunayTriangulation::bulk_load`, its
//! fast path), as the report's `delaunay` family times it and the
//! triangulator's tests compare against it: triangles as input indices.

use glam::DVec2;
use spade::{DelaunayTriangulation, HasPosition, InsertionError, Point2, Triangulation};

/// A point that remembers its input index through spade's reordering.
struct Indexed {
    position: Point2<f64>,
    index: u32,
}

impl HasPosition for Indexed {
    type Scalar = f64;

    fn position(&self) -> Point2<f64> {
        self.position
    }
}

/// spade's Delaunay triangles of `points`, counterclockwise, as indices
/// into `points` (of duplicates, spade keeps one). spade refuses a
/// coordinate whose magnitude is nonzero and below `2^-142`, or above
/// `2^201`, or NaN: that is its error.
#[inline]
pub fn spade_triangles(points: &[DVec2]) -> Result<Vec<[u32; 3]>, InsertionError> {
    let vertices = points
        .iter()
        .zip(0u32..)
        .map(|(p, index)| Indexed {
            position: Point2::new(p.x, p.y),
            index,
        })
        .collect();
    let t = DelaunayTriangulation::<Indexed>::bulk_load(vertices)?;
    Ok(t.inner_faces()
        .map(|f| f.vertices().map(|v| v.data().index))
        .collect())
}
