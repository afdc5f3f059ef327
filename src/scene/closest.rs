//! The closest point of a [`TriangleMesh`] to a query point
//! ([`TriangleMesh::closest_point`]): the nearest triangle chosen exactly,
//! the closest point on it and the squared distance with certified errors.
//!
//! # What is exact and what is certified
//! The triangles are closed sets (vertices, edges and face). The triangle
//! returned is exactly the nearest one of the mesh: no other has a
//! smaller exact (real-number) distance to the query, and among triangles
//! at exactly the same distance it has the smallest index. Each
//! candidate's squared distance is first enclosed in an interval of `f64`
//! (`bounds.rs`: outward-rounded interval arithmetic on the coordinates
//! scaled by a power of two that brings the largest magnitude of the
//! query and the mesh into `[1/2, 1)`, so that nothing overflows at any
//! finite scale). Two candidates whose intervals overlap are ordered
//! exactly: as a tie when each one's distance is certainly that of the
//! same vertex or edge (neighbours sharing the feature nearest to the
//! query, the common case, see `same_feature`), otherwise as fractions
//! of integers in fixed-size stack integers (`exact.rs`, the slow path:
//! tens of microseconds). A distance bound
//! ([`TriangleMesh::closest_point_within`]) is applied exactly too.
//!
//! The point and the squared distance returned are certified, not exact:
//! each coordinate of [`ClosestPoint::point`] is within
//! [`ClosestPoint::error`] of the exact closest point on the chosen
//! triangle, and [`ClosestPoint::squared_distance`] within
//! [`ClosestPoint::squared_distance_error`] of the exact squared distance.
//! The errors are those of the intervals: a few units of rounding of the
//! values in play for a query near the mesh, larger (but still bounding)
//! where the distance is tiny next to the coordinates' magnitudes (the
//! scaled values underflow) or where the closest point lies on the
//! border between two of a triangle's features.
//!
//! # Which triangles count
//! Every triangle of the mesh, degenerate ones too (their vertices
//! collinear or equal, exactly): such a triangle is the segment or point
//! it spans, and has a distance. The hierarchy leaves them out, as it does
//! triangles so thin that their rounded normal vanishes (see
//! [`TriangleMesh`]); the query looks at each of those after its walk,
//! and, as their intervals reach down to zero, orders each of them
//! against the best so far exactly: a mesh with many of them makes every
//! query slower by as many exact comparisons.
//!
//! # The walk
//! The hierarchy is walked nearer boxes first (`bvh::boxes::point_walk`),
//! skipping a box whose lower bound of the squared distance (rounded
//! down) exceeds the upper end of the best triangle's interval: a
//! triangle exactly as near as the best is never skipped, so ties are
//! seen and ordered by index. No query allocates.

mod bounds;
mod exact;

use super::TriangleMesh;
use super::batch::each_into;
use super::crossings::on_closed_triangle;
use crate::arith::exponent::{scale_pow2, unit_scale};
use crate::bvh::boxes::{PointVisitor, box_distance_below, walk_point};
use crate::error::InputError;
use crate::point::IntoDVec3;
use crate::sign::Sign;
use bounds::{Bounds, TriangleBounds, Vec3Bounds, scaled_point, triangle_bounds};
use glam::DVec3;

/// The closest point of a [`TriangleMesh`] to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ClosestPoint {
    /// The index of the nearest triangle, in the slice the mesh was built
    /// from: exactly the nearest, the smallest index among exact ties.
    pub triangle: u32,
    /// The closest point on that triangle, each coordinate within
    /// [`error`](Self::error) of the exact one.
    pub point: DVec3,
    /// The certified per-axis error of [`point`](Self::point).
    pub error: DVec3,
    /// The squared distance from the query to the triangle, within
    /// [`squared_distance_error`](Self::squared_distance_error) of the
    /// exact one: exactly `0.0` (no error) for a query on the triangle;
    /// `inf` (with an infinite error) where the exact one exceeds
    /// `f64::MAX` (points beyond about `2^511` apart), and where the
    /// coordinates exceed about `2^511`, so that the certified error of a
    /// non-zero distance, which grows with their squares, would.
    pub squared_distance: f64,
    /// The certified error of [`squared_distance`](Self::squared_distance).
    pub squared_distance_error: f64,
}

impl TriangleMesh {
    /// The closest point of the mesh to `point`: the exactly nearest
    /// triangle (the smallest index among exact ties), the point on it and
    /// the squared distance with certified errors (see [`ClosestPoint`]).
    /// Never allocates.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] (argument `"point"`) for a NaN or
    /// infinite coordinate. `Ok(None)` when the mesh has no triangle.
    ///
    /// ```
    /// use exactray::scene::TriangleMesh;
    /// let mesh = TriangleMesh::new(
    ///     &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 5.0]],
    ///     &[[0, 1, 2], [3, 1, 2]],
    /// )
    /// .unwrap();
    /// let c = mesh.closest_point([0.25, 0.25, -2.0]).unwrap().unwrap();
    /// assert_eq!(c.triangle, 0);
    /// assert!((c.point.z).abs() <= c.error.z);
    /// assert!((c.squared_distance - 4.0).abs() <= c.squared_distance_error);
    /// ```
    pub fn closest_point<P: IntoDVec3>(
        &self,
        point: P,
    ) -> Result<Option<ClosestPoint>, InputError> {
        self.closest_point_within(point, f64::INFINITY)
    }

    /// [`closest_point`](Self::closest_point) among the triangles at exact
    /// distance at most `max_distance` from `point` (`Ok(None)` when there
    /// is none); the walk skips every box beyond it, so a small bound
    /// makes the query cheaper. `f64::INFINITY` takes every triangle.
    ///
    /// # Errors
    /// As [`closest_point`](Self::closest_point), and
    /// [`InputError::InvalidRadius`] (argument `"max_distance"`) for a
    /// negative or NaN bound.
    ///
    /// ```
    /// use exactray::scene::TriangleMesh;
    /// let mesh = TriangleMesh::new(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], &[[0, 1, 2]])
    ///     .unwrap();
    /// // Exactly at distance 3: inside a bound of 3, outside one just below.
    /// assert!(mesh.closest_point_within([0.0, 0.0, 3.0], 3.0).unwrap().is_some());
    /// assert!(mesh.closest_point_within([0.0, 0.0, 3.0], 3.0f64.next_down()).unwrap().is_none());
    /// ```
    pub fn closest_point_within<P: IntoDVec3>(
        &self,
        point: P,
        max_distance: f64,
    ) -> Result<Option<ClosestPoint>, InputError> {
        let q = point.into_dvec3();
        if !q.is_finite() {
            return Err(InputError::NonFinite { argument: "point" });
        }
        if max_distance.is_nan() || max_distance < 0.0 {
            return Err(InputError::InvalidRadius {
                argument: "max_distance",
            });
        }
        Ok(self.closest_in(q, max_distance))
    }

    /// `out[i] = closest_point(points[i])` for every `i`, on the calling
    /// thread; never allocates.
    ///
    /// # Errors
    /// [`InputError::LengthMismatch`] (`expected` = `points.len()`) when
    /// `out` has another length, [`InputError::NonFinite`] (argument
    /// `"points"`) when a point has a NaN or infinite coordinate; nothing
    /// is written then.
    pub fn closest_points<P: IntoDVec3 + Copy>(
        &self,
        points: &[P],
        out: &mut [Option<ClosestPoint>],
    ) -> Result<(), InputError> {
        check_batch(points, out)?;
        each_into(points, out, |&p| self.closest_unbounded(p))
    }

    /// [`closest_points`](Self::closest_points) spread over rayon's
    /// thread pool (the `rayon` feature).
    ///
    /// # Errors
    /// As [`closest_points`](Self::closest_points).
    #[cfg(feature = "rayon")]
    pub fn par_closest_points<P: IntoDVec3 + Copy + Sync>(
        &self,
        points: &[P],
        out: &mut [Option<ClosestPoint>],
    ) -> Result<(), InputError> {
        check_batch(points, out)?;
        super::batch::par_each_into(points, out, |&p| self.closest_unbounded(p))
    }

    /// The query for a finite `p`, every triangle counted.
    #[inline]
    fn closest_unbounded<P: IntoDVec3>(&self, p: P) -> Option<ClosestPoint> {
        self.closest_in(p.into_dvec3(), f64::INFINITY)
    }

    /// The query for a finite `q` and a `max` at least zero.
    fn closest_in(&self, q: DVec3, max: f64) -> Option<ClosestPoint> {
        let s = unit_scale(&[self.largest_magnitude(q)]);
        let max = (max < f64::INFINITY).then(|| (max, scaled_square(max, s)));
        let mut nearest = NearestTriangle {
            mesh: self,
            q,
            s,
            scaled: scaled_point(q, s),
            max,
            best: None,
            reach: max.map_or(f64::INFINITY, |(_, m2)| m2.hi),
        };
        walk_point(&self.bvh, q, s, &mut nearest);
        for &t in &self.topology.left_out {
            nearest.consider(t);
        }
        let (triangle, _) = nearest.best?;
        let corners = self.corners(triangle);
        let scaled = corners.map(|v| scaled_point(v, s));
        let found = triangle_bounds::<true>(&nearest.scaled, &scaled);
        // A query exactly on the triangle is its own closest point, at
        // distance zero, with no error: decided exactly, since the
        // enclosures' widths follow the squares of the coordinates, which
        // leave `f64`'s range beyond about `2^511`.
        let degenerate = self
            .triangle(triangle as usize)
            .is_none_or(|t| t.degenerate);
        if found.d2.lo <= 0.0 && on_closed_triangle(q, &corners, degenerate) {
            return Some(ClosestPoint {
                triangle,
                point: q,
                error: DVec3::ZERO,
                squared_distance: 0.0,
                squared_distance_error: 0.0,
            });
        }
        Some(answer(triangle, &found, &corners, s))
    }

    /// The largest coordinate magnitude of `q`, the hierarchy's box and
    /// the triangles left out of it: the query's scale brings it into
    /// `[1/2, 1)`.
    fn largest_magnitude(&self, q: DVec3) -> f64 {
        let mut largest = q.abs().max_element();
        if let Some((lo, hi)) = self.bvh.bounds() {
            largest = largest.max(lo.abs().max(hi.abs()).max_element());
        }
        for &t in &self.topology.left_out {
            for v in self.corners(t) {
                largest = largest.max(v.abs().max_element());
            }
        }
        largest
    }
}

/// Equal lengths and every point finite, or the batch's error.
fn check_batch<P: IntoDVec3 + Copy>(
    points: &[P],
    out: &[Option<ClosestPoint>],
) -> Result<(), InputError> {
    InputError::check_lengths(points.len(), out.len())?;
    if points.iter().all(|&p| p.into_dvec3().is_finite()) {
        Ok(())
    } else {
        Err(InputError::NonFinite { argument: "points" })
    }
}

/// The interval of the exact `(max 2^s)^2`, `max` finite (scaling and
/// squaring may overflow: the interval then ends at `f64::MAX` and `inf`).
fn scaled_square(max: f64, s: i32) -> Bounds {
    let v = scale_pow2(max, s);
    Bounds {
        lo: v.next_down().next_down().max(0.0),
        hi: v.next_up().next_up(),
    }
    .square()
}

/// The walk's visitor: the best triangle so far and its enclosure.
struct NearestTriangle<'m> {
    mesh: &'m TriangleMesh,
    q: DVec3,
    s: i32,
    scaled: Vec3Bounds,
    /// The distance bound and its scaled square, when finite.
    max: Option<(f64, Bounds)>,
    best: Option<(u32, TriangleBounds)>,
    /// The upper end of the best's interval, or of the bound's square.
    reach: f64,
}

impl NearestTriangle<'_> {
    /// Takes triangle `t` as the best when it comes before it: exactly
    /// nearer, or exactly as near with a smaller index.
    fn consider(&mut self, t: u32) {
        let corners = self.mesh.corners(t);
        // The triangle's own box first: most triangles of a leaf that is
        // in reach lie beyond the best (a tie lies within its box's bound,
        // at most the best's exact distance, at most `reach`).
        let (lo, hi) = (
            corners[0].min(corners[1]).min(corners[2]),
            corners[0].max(corners[1]).max(corners[2]),
        );
        if box_distance_below(lo, hi, self.q, self.s) > self.reach {
            return;
        }
        let scaled = corners.map(|v| scaled_point(v, self.s));
        let found = triangle_bounds::<false>(&self.scaled, &scaled);
        if found.d2.lo > self.reach {
            return;
        }
        if let Some((max, m2)) = self.max
            && found.d2.hi > m2.lo
            && !exact::within(self.q, &corners, max)
        {
            return;
        }
        if let Some((j, best)) = &self.best {
            let before = if found.d2.hi < best.d2.lo {
                true
            } else if found.d2.lo > best.d2.hi {
                false
            } else if same_feature((&corners, found.sole), (&self.mesh.corners(*j), best.sole)) {
                t < *j
            } else {
                match exact::compare(self.q, &corners, &self.mesh.corners(*j)) {
                    Sign::Negative => true,
                    Sign::Zero => t < *j,
                    Sign::Positive => false,
                }
            };
            if !before {
                return;
            }
        }
        self.best = Some((t, found));
        self.reach = self
            .max
            .map_or(found.d2.hi, |(_, m2)| found.d2.hi.min(m2.hi));
    }
}

/// The ends of candidate `c` of a triangle with corners `v` (see
/// `TriangleBounds::sole`): a vertex twice, an edge's two vertices, `None`
/// for the plane.
fn feature_ends(v: &[DVec3; 3], c: u8) -> Option<(DVec3, DVec3)> {
    match c {
        0..=2 => Some((v[c as usize], v[c as usize])),
        3 => Some((v[0], v[1])),
        4 => Some((v[1], v[2])),
        5 => Some((v[2], v[0])),
        _ => None,
    }
}

/// Whether two triangles' sole possible least candidates are the same
/// vertex, or the same edge (the same two points, in either order): their
/// exact squared distances are then both that feature's, exactly equal.
/// A cheap exact tie for the common case of a query nearest to an edge
/// or a vertex that neighbouring triangles share.
fn same_feature(s: (&[DVec3; 3], Option<u8>), t: (&[DVec3; 3], Option<u8>)) -> bool {
    let ends = |(v, c): (&[DVec3; 3], Option<u8>)| c.and_then(|c| feature_ends(v, c));
    match (ends(s), ends(t)) {
        (Some((a, b)), Some((c, d))) => (a == c && b == d) || (a == d && b == c),
        _ => false,
    }
}

impl PointVisitor for NearestTriangle<'_> {
    #[inline(always)]
    fn reach(&self) -> f64 {
        self.reach
    }

    fn leaf(&mut self, items: &[u32]) {
        for &t in items {
            self.consider(t);
        }
    }
}

/// The answer for triangle `triangle` with enclosure `found` at scale `s`.
fn answer(triangle: u32, found: &TriangleBounds, corners: &[DVec3; 3], s: i32) -> ClosestPoint {
    let (low, high) = (
        corners[0].min(corners[1]).min(corners[2]),
        corners[0].max(corners[1]).max(corners[2]),
    );
    let mut point = DVec3::ZERO;
    let mut error = DVec3::ZERO;
    for k in 0..3 {
        // The exact point lies in the triangle's box.
        let b = found.point[k];
        let lo = below(scale_pow2(b.lo, -s)).max(low[k]);
        let hi = above(scale_pow2(b.hi, -s)).min(high[k]);
        let (lo, hi) = if lo <= hi {
            (lo, hi)
        } else {
            (low[k], high[k])
        };
        (point[k], error[k]) = centre(lo, hi);
    }
    // `-2s` may leave `scale_pow2`'s range: two steps of `-s`.
    let lo = below(scale_pow2(below(scale_pow2(found.d2.lo, -s)), -s)).max(0.0);
    let hi = above(scale_pow2(above(scale_pow2(found.d2.hi, -s)), -s));
    let (squared_distance, squared_distance_error) = centre(lo, hi);
    ClosestPoint {
        triangle,
        point,
        error,
        squared_distance,
        squared_distance_error,
    }
}

/// A value below the exact one that `scale_pow2` or one rounding to
/// nearest gave as `x` (within one float step, [`scale_pow2`]).
#[inline(always)]
fn below(x: f64) -> f64 {
    x.next_down().next_down()
}

/// A value above the exact one that `scale_pow2` gave as `x`.
#[inline(always)]
fn above(x: f64) -> f64 {
    x.next_up().next_up()
}

/// The midpoint of `[lo, hi]` and an upper bound of its distance to both
/// ends; `(inf, inf)` when `hi` is infinite.
fn centre(lo: f64, hi: f64) -> (f64, f64) {
    if hi == f64::INFINITY {
        return (f64::INFINITY, f64::INFINITY);
    }
    if lo == hi {
        return (lo, 0.0);
    }
    let mid = (lo * 0.5 + hi * 0.5).clamp(lo, hi);
    (mid, (hi - mid).max(mid - lo).next_up())
}
