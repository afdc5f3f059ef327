//! The exact audit of a triangulation of a point set: is it a
//! triangulation of the points at all, and is it Delaunay.
//!
//! Why these checks suffice. Let every triangle be strictly
//! counterclockwise, let no directed edge belong to two triangles, and let
//! the directed edges without a reverse be exactly the edges of the convex
//! hull, counterclockwise, with every input point on the hull's boundary
//! as a vertex of it. Then the triangles, as an oriented 2-chain, have the
//! hull polygon as their boundary, so a point off the edges is covered by
//! as many triangles as the polygon winds round it: one inside the hull,
//! none outside; every triangle counting `+1`, they tile the hull without
//! overlap. A vertex inside another triangle or on another edge would make
//! some point be covered twice, or leave an edge without a reverse inside
//! the hull, so with every distinct point a vertex exactly once this is a
//! triangulation of the points, and then Euler's formula gives
//! `2n - h - 2` triangles for `n` points, `h` of them on the hull. In a
//! triangulation, every interior edge being locally Delaunay (neither
//! opposite vertex strictly inside the other triangle's circumcircle)
//! makes the whole of it Delaunay (Delaunay's lemma; see de Berg et al.,
//! *Computational Geometry*, 3rd ed., Theorem 9.8).

use crate::predicates::{Oracle, Predicates};
use crate::triangulate::{Triangulation, TriangulationError};
use exactray::Sign;
use glam::DVec2;
use rayon::prelude::*;

/// What the audit found. [`Audit::errors`] adds up every failure.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Audit {
    /// Triangles audited.
    pub triangles: u64,
    /// Triangles that are clockwise or flat.
    pub inverted: u64,
    /// Triangles that are not inverted but have a neighbour (itself not
    /// inverted) whose opposite vertex lies strictly inside their
    /// circumcircle: they violate the empty circle.
    pub not_delaunay: u64,
    /// Distinct input points that are no triangle's vertex (none when all
    /// are collinear: then no triangle should be there).
    pub missing_points: u64,
    /// Vertex indices beyond the first at one distinct point (a duplicate
    /// kept as a second vertex).
    pub repeated_points: u64,
    /// Triangles with a vertex index past the input.
    pub bad_indices: u64,
    /// Directed edges in more than one triangle (overlapping or
    /// inconsistently oriented triangles).
    pub repeated_edges: u64,
    /// Edges in the symmetric difference of the triangulation's boundary
    /// and the convex hull's (every input point on the hull's boundary a
    /// corner of it).
    pub hull_mismatch: u64,
    /// How far the number of triangles is from Euler's `2n - h - 2`.
    pub euler_gap: u64,
    /// Listed duplicates that are not equal to the point they name.
    pub false_duplicates: u64,
    /// Interior edges whose four points are exactly cocircular: where there
    /// are none, a triangulation without errors is *the* Delaunay
    /// triangulation (not counted as an error).
    pub cocircular_edges: u64,
}

impl Audit {
    /// Every failure found: triangles that are inverted or violate the
    /// empty circle, plus every way the triangles fail to be a
    /// triangulation of the points.
    pub fn errors(&self) -> u64 {
        self.inverted
            + self.not_delaunay
            + self.missing_points
            + self.repeated_points
            + self.bad_indices
            + self.repeated_edges
            + self.hull_mismatch
            + self.euler_gap
            + self.false_duplicates
    }
}

/// [`audit_with`] the exact big-integer oracle: the ground truth.
///
/// # Errors
/// [`TriangulationError::NonFinite`] for a point with a NaN or infinite
/// coordinate.
pub fn audit(points: &[DVec2], t: &Triangulation) -> Result<Audit, TriangulationError> {
    audit_with::<Oracle>(points, t)
}

/// Audits `t` as a Delaunay triangulation of `points` on the predicates
/// `P` (exact ones, or the audit means nothing); the predicate calls run
/// in parallel. Any `t` is taken, however wrong: its failures are counted.
///
/// # Errors
/// [`TriangulationError::NonFinite`] for a point with a NaN or infinite
/// coordinate.
pub fn audit_with<P: Predicates>(
    points: &[DVec2],
    t: &Triangulation,
) -> Result<Audit, TriangulationError> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(TriangulationError::NonFinite { index });
    }
    let mut audit = Audit {
        triangles: t.triangles.len() as u64,
        ..Audit::default()
    };
    let distinct = Distinct::new(points);
    let n = points.len();
    let (tris, bad): (Vec<[u32; 3]>, Vec<[u32; 3]>) = t
        .triangles
        .iter()
        .partition(|tri| tri.iter().all(|&v| (v as usize) < n));
    audit.bad_indices = bad.len() as u64;
    audit.false_duplicates = t
        .duplicates
        .iter()
        .filter(|&&(a, b)| {
            let (a, b) = (a as usize, b as usize);
            a >= n || b >= n || points[a] != points[b]
        })
        .count() as u64;
    count_vertices(&distinct, &tris, &mut audit);

    let at = |v: u32| points[v as usize];
    let inverted: Vec<bool> = tris
        .par_iter()
        .map(|&[a, b, c]| P::orient2d(at(a), at(b), at(c)) != Sign::Positive)
        .collect();
    audit.inverted = inverted.iter().filter(|&&i| i).count() as u64;

    let edges = Edges::new(&distinct, &tris);
    audit.repeated_edges = edges.repeated();
    let (violating, cocircular) = edges.local_delaunay::<P>(&inverted, &distinct.points);
    audit.not_delaunay = violating;
    audit.cocircular_edges = cocircular;

    let hull = hull_edges::<P>(&distinct);
    let boundary = edges.boundary();
    audit.hull_mismatch = symmetric_difference(&boundary, &hull);
    let expected = if hull.is_empty() {
        0
    } else {
        2 * distinct.points.len() as u64 - hull.len() as u64 - 2
    };
    audit.euler_gap = audit.triangles.abs_diff(expected);
    if hull.is_empty() {
        // Fewer than three points, or all collinear: no triangle can hold
        // them, and none should.
        audit.missing_points = 0;
    }
    Ok(audit)
}

/// Triangles whose circumcircle strictly holds some input point, by
/// brute force over every triangle and point on the oracle's signs: the
/// empty-circle property checked directly, for small inputs. Inverted
/// triangles count too.
pub fn brute_force_violations(points: &[DVec2], triangles: &[[u32; 3]]) -> u64 {
    let at = |v: u32| points[v as usize];
    triangles
        .par_iter()
        .filter(|&&[a, b, c]| {
            let (a, b, c) = (at(a), at(b), at(c));
            Oracle::orient2d(a, b, c) != Sign::Positive
                || points
                    .iter()
                    .any(|&p| Oracle::incircle(a, b, c, p) == Sign::Positive)
        })
        .count() as u64
}

/// The input's distinct points in lexicographic order, and each input
/// index's place among them.
struct Distinct {
    points: Vec<DVec2>,
    of: Vec<u32>,
}

impl Distinct {
    fn new(points: &[DVec2]) -> Self {
        // `+ 0.0` turns `-0.0` into `0.0`: one point, as `==` has it.
        let key = |p: DVec2| (p.x + 0.0, p.y + 0.0);
        let mut by: Vec<u32> = (0..points.len() as u32).collect();
        by.sort_unstable_by(|&i, &j| {
            let (a, b) = (key(points[i as usize]), key(points[j as usize]));
            a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1))
        });
        let mut distinct = Distinct {
            points: Vec::new(),
            of: vec![0; points.len()],
        };
        for i in by {
            let p = points[i as usize];
            if distinct.points.last() != Some(&p) {
                distinct.points.push(p);
            }
            distinct.of[i as usize] = distinct.points.len() as u32 - 1;
        }
        distinct
    }
}

/// Missing and repeated points: each distinct point should be the vertex
/// of exactly one input index.
fn count_vertices(distinct: &Distinct, tris: &[[u32; 3]], audit: &mut Audit) {
    let mut used = vec![false; distinct.of.len()];
    for &v in tris.iter().flatten() {
        used[v as usize] = true;
    }
    let mut indices = vec![0u32; distinct.points.len()];
    for (i, _) in used.iter().enumerate().filter(|(_, u)| **u) {
        indices[distinct.of[i] as usize] += 1;
    }
    audit.missing_points = indices.iter().filter(|&&c| c == 0).count() as u64;
    audit.repeated_points = indices.iter().map(|&c| c.saturating_sub(1) as u64).sum();
}

/// Every directed edge `a -> b` of the triangles (in distinct-point ids),
/// sorted, with its triangle and the vertex opposite it.
struct Edges {
    /// `(a, b, triangle, opposite)`.
    list: Vec<(u32, u32, u32, u32)>,
}

impl Edges {
    fn new(distinct: &Distinct, tris: &[[u32; 3]]) -> Self {
        let mut list = Vec::with_capacity(3 * tris.len());
        for (t, tri) in tris.iter().enumerate() {
            let [a, b, c] = tri.map(|v| distinct.of[v as usize]);
            list.extend([
                (a, b, t as u32, c),
                (b, c, t as u32, a),
                (c, a, t as u32, b),
            ]);
        }
        list.par_sort_unstable();
        Edges { list }
    }

    fn repeated(&self) -> u64 {
        self.list
            .windows(2)
            .filter(|w| (w[0].0, w[0].1) == (w[1].0, w[1].1))
            .count() as u64
    }

    /// The entry of the directed edge `a -> b`, if any.
    fn find(&self, a: u32, b: u32) -> Option<&(u32, u32, u32, u32)> {
        let at = self.list.partition_point(|e| (e.0, e.1) < (a, b));
        self.list.get(at).filter(|e| (e.0, e.1) == (a, b))
    }

    /// Directed edges without a reverse, sorted and distinct.
    fn boundary(&self) -> Vec<(u32, u32)> {
        let mut out: Vec<(u32, u32)> = self
            .list
            .iter()
            .filter(|e| self.find(e.1, e.0).is_none())
            .map(|e| (e.0, e.1))
            .collect();
        out.dedup();
        out
    }

    /// Triangles violating the empty circle across an interior edge (both
    /// sides counted, edges with an inverted side left out), and the
    /// number of exactly cocircular interior edges. `pts` are the distinct
    /// points.
    fn local_delaunay<P: Predicates>(&self, inverted: &[bool], pts: &[DVec2]) -> (u64, u64) {
        let signs: Vec<(u32, u32, Sign)> = self
            .list
            .par_iter()
            .filter(|e| e.0 < e.1)
            .filter_map(|&(a, b, t, c)| {
                let &(_, _, u, d) = self.find(b, a)?;
                if inverted[t as usize] || inverted[u as usize] {
                    return None;
                }
                let at = |v: u32| pts[v as usize];
                Some((t, u, P::incircle(at(a), at(b), at(c), at(d))))
            })
            .collect();
        let mut bad = vec![false; inverted.len()];
        let mut cocircular = 0;
        for (t, u, s) in signs {
            match s {
                Sign::Positive => {
                    bad[t as usize] = true;
                    bad[u as usize] = true;
                }
                Sign::Zero => cocircular += 1,
                Sign::Negative => {}
            }
        }
        (bad.iter().filter(|&&b| b).count() as u64, cocircular)
    }
}

/// The directed edges of the convex hull, counterclockwise, in distinct
/// ids, with every point on the hull's boundary a corner (Andrew's
/// monotone chain, popping only at strict right turns); empty when the
/// points are fewer than three or all collinear.
fn hull_edges<P: Predicates>(distinct: &Distinct) -> Vec<(u32, u32)> {
    let pts = &distinct.points;
    let (Some(&first), Some(&last)) = (pts.first(), pts.last()) else {
        return Vec::new();
    };
    if pts
        .iter()
        .all(|&p| P::orient2d(first, last, p) == Sign::Zero)
    {
        return Vec::new();
    }
    let chain = |ids: &mut dyn Iterator<Item = u32>| {
        let mut h: Vec<u32> = Vec::new();
        for i in ids {
            while let [.., a, b] = h[..] {
                if P::orient2d(pts[a as usize], pts[b as usize], pts[i as usize]) == Sign::Negative
                {
                    h.pop();
                } else {
                    break;
                }
            }
            h.push(i);
        }
        h.pop();
        h
    };
    let n = pts.len() as u32;
    let mut cycle = chain(&mut (0..n));
    cycle.extend(chain(&mut (0..n).rev()));
    let mut edges: Vec<(u32, u32)> = cycle
        .iter()
        .zip(cycle.iter().cycle().skip(1))
        .map(|(&a, &b)| (a, b))
        .collect();
    edges.sort_unstable();
    edges
}

/// How many entries are in one sorted, distinct list and not the other.
fn symmetric_difference(a: &[(u32, u32)], b: &[(u32, u32)]) -> u64 {
    let (mut i, mut j, mut out) = (0, 0, 0);
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => (i, out) = (i + 1, out + 1),
            std::cmp::Ordering::Greater => (j, out) = (j + 1, out + 1),
            std::cmp::Ordering::Equal => (i, j) = (i + 1, j + 1),
        }
    }
    out + (a.len() - i + b.len() - j) as u64
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The hull's directed edges by their definition: `a -> b` with every
    /// point left of or on the line, and none strictly between them.
    fn brute_force_hull(pts: &[DVec2]) -> Vec<(u32, u32)> {
        let n = pts.len() as u32;
        let mut out = Vec::new();
        for a in 0..n {
            for b in (0..n).filter(|&b| b != a) {
                let (pa, pb) = (pts[a as usize], pts[b as usize]);
                let side = |p: DVec2| Oracle::orient2d(pa, pb, p);
                let outside = pts.iter().any(|&p| side(p) == Sign::Negative);
                // The dot product is exact on these small integers.
                let between = pts.iter().any(|&p| {
                    side(p) == Sign::Zero && p != pa && p != pb && (p - pa).dot(p - pb) < 0.0
                });
                if !outside && !between {
                    out.push((a, b));
                }
            }
        }
        // All collinear: every neighbouring pair both ways; no hull.
        if pts
            .iter()
            .all(|&p| Oracle::orient2d(pts[0], pts[pts.len() - 1], p) == Sign::Zero)
        {
            out.clear();
        }
        out.sort_unstable();
        out
    }

    proptest! {
        #[test]
        fn the_hull_keeps_every_boundary_point(
            ij in prop::collection::vec((-3i8..=3, -3i8..=3), 1..30)
        ) {
            let points: Vec<DVec2> =
                ij.iter().map(|&(i, j)| DVec2::new(f64::from(i), f64::from(j))).collect();
            let distinct = Distinct::new(&points);
            prop_assert_eq!(hull_edges::<Oracle>(&distinct), brute_force_hull(&distinct.points));
        }
    }
}
