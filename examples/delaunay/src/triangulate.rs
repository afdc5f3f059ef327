//! The incremental triangulator: Bowyer–Watson insertion into a
//! triangulation closed by ghost triangles, after a visibility walk from
//! the last insertion.
//!
//! Ghost triangles (Shewchuk's "ghost triangles", as in his Triangle and
//! in CGAL's infinite vertex): every hull edge `a -> b` (interior on its
//! left) carries a triangle `[b, a, GHOST]`, so the triangulation is a
//! closed surface and a point outside the hull lands in a triangle like
//! any other. Nothing depends on coordinates that are not the input's:
//! there is no super-triangle whose huge corners would have to be
//! compared with inputs near `1e300`.
//!
//! A ghost `[a, b, GHOST]` conflicts with `p` when `p` lies strictly left
//! of `a -> b` (outside the hull) or on the open segment `ab`: the limit of
//! a circumcircle through `a`, `b` and a point moving away to infinity. A
//! real triangle conflicts when `p` lies strictly inside its circumcircle.
//! With exact predicates the conflicting triangles form a disk whose
//! boundary edges all see `p` strictly, and replacing them by the fan from
//! `p` leaves a Delaunay triangulation (Bowyer 1981, Watson 1981; the
//! cocircular case is why the test is strict).

use crate::predicates::Predicates;
use exactray::Sign;
use exactray::testing::SplitMix64;
use glam::DVec2;
use std::marker::PhantomData;

/// The vertex at infinity of ghost triangles; also "no triangle".
const GHOST: u32 = u32::MAX;

/// The most points [`triangulate`] takes: triangle indices (about twice the
/// points) stay below `u32::MAX`.
pub const MAX_POINTS: usize = 1 << 30;

/// `NEXT[i]` and `PREV[i]`: the edge opposite vertex `i` of a
/// counterclockwise triangle runs from `v[NEXT[i]]` to `v[PREV[i]]`.
const NEXT: [usize; 3] = [1, 2, 0];
const PREV: [usize; 3] = [2, 0, 1];

/// A triangle: counterclockwise vertices, the ghost vertex (if any) last;
/// `n[i]` is the neighbour across the edge opposite `v[i]`.
#[derive(Clone, Copy, Debug)]
struct Triangle {
    v: [u32; 3],
    n: [u32; 3],
}

impl Triangle {
    fn is_ghost(&self) -> bool {
        self.v[2] == GHOST
    }
}

/// A Delaunay triangulation of a point set, as the triangulator returns it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Triangulation {
    /// The triangles, counterclockwise, as indices into the input points.
    /// Empty when the input has fewer than three distinct points or all of
    /// them are collinear.
    pub triangles: Vec<[u32; 3]>,
    /// Input points skipped because an equal point (`-0.0` equals `0.0`)
    /// is already a vertex: `(skipped, vertex)`.
    pub duplicates: Vec<(u32, u32)>,
    /// Triangles the point-location walks crossed, over all insertions.
    pub walk_steps: u64,
    /// Triangles the insertions' cavities removed, over all insertions.
    pub cavity_triangles: u64,
}

/// The triangles as a set, to compare triangulations: each rotated to
/// start at its least index (which keeps its orientation), sorted.
pub fn triangle_set(triangles: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let mut out: Vec<[u32; 3]> = triangles
        .iter()
        .map(|&[a, b, c]| {
            if a <= b && a <= c {
                [a, b, c]
            } else if b <= c {
                [b, c, a]
            } else {
                [c, a, b]
            }
        })
        .collect();
    out.sort_unstable();
    out
}

/// Why a triangulation could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriangulationError {
    /// The input point at `index` has a NaN or infinite coordinate.
    NonFinite {
        /// Its index in the input.
        index: usize,
    },
    /// More than [`MAX_POINTS`] points.
    TooManyPoints {
        /// How many were given.
        count: usize,
    },
    /// Locating the input point at `index` crossed more triangles than the
    /// triangulation has: the walk went round a cycle, which a visibility
    /// walk in a Delaunay triangulation cannot (Edelsbrunner's acyclicity
    /// theorem), so the predicates contradicted themselves.
    WalkCycle {
        /// Its index in the input.
        index: u32,
    },
    /// The triangles in conflict with the input point at `index` did not
    /// form a disk with every vertex on its boundary (which exact signs
    /// guarantee): the predicates contradicted themselves.
    BrokenCavity {
        /// Its index in the input.
        index: u32,
    },
}

impl std::fmt::Display for TriangulationError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NonFinite { index } => write!(f, "point {index} is not finite"),
            Self::TooManyPoints { count } => {
                write!(f, "{count} points; at most {MAX_POINTS} are taken")
            }
            Self::WalkCycle { index } => write!(
                f,
                "locating point {index} went round a cycle: inconsistent predicates"
            ),
            Self::BrokenCavity { index } => write!(
                f,
                "the cavity of point {index} is not a disk: inconsistent predicates"
            ),
        }
    }
}

impl std::error::Error for TriangulationError {}

/// The Delaunay triangulation of `points` on the predicates `P`.
///
/// Points are inserted in a biased randomized order along a Hilbert curve
/// ([`insertion_order`](crate::order::insertion_order)), each located by a
/// visibility walk from a triangle of the previous insertion. Duplicate
/// points are skipped and listed in [`Triangulation::duplicates`];
/// collinear points are fine (all of them collinear: no triangle); points
/// on the hull are vertices of it. Where four or more points are
/// cocircular, one of the Delaunay triangulations is returned.
///
/// With exact predicates ([`Exactray`](crate::Exactray),
/// [`Oracle`](crate::Oracle)) the result is a Delaunay triangulation of the
/// distinct points. With inexact ones ([`Robust`](crate::Robust) at
/// extreme magnitudes) it may be wrong, or the triangulator notices that
/// the signs contradict each other and returns
/// [`TriangulationError::WalkCycle`] or
/// [`TriangulationError::BrokenCavity`]; it never loops and never panics.
///
/// # Errors
/// [`TriangulationError::NonFinite`] for a NaN or infinite coordinate,
/// [`TriangulationError::TooManyPoints`] past [`MAX_POINTS`], and the two
/// contradictions above.
pub fn triangulate<P: Predicates>(points: &[DVec2]) -> Result<Triangulation, TriangulationError> {
    if points.len() > MAX_POINTS {
        return Err(TriangulationError::TooManyPoints {
            count: points.len(),
        });
    }
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(TriangulationError::NonFinite { index });
    }
    let order = crate::order::insertion_order(points);
    let pts: Vec<DVec2> = order.iter().map(|&i| points[i as usize]).collect();
    let Some(mut mesh) = Mesh::<P>::start(pts, order) else {
        return Ok(Triangulation::default());
    };
    mesh.insert_all()?;
    Ok(mesh.finish())
}

/// Where a walk ended.
enum Located {
    /// In the closed triangle (or, outside the hull, the ghost triangle
    /// beyond the edge the walk left by): it conflicts with the point.
    Triangle(u32),
    /// On this vertex: the point is a duplicate.
    Vertex(u32),
}

/// An edge of the cavity's boundary, counterclockwise around the cavity,
/// and the triangle outside it.
#[derive(Clone, Copy)]
struct Boundary {
    u: u32,
    w: u32,
    outside: u32,
}

/// The triangulation under construction. Vertices are positions in the
/// insertion order; `input` maps them back.
struct Mesh<P> {
    pts: Vec<DVec2>,
    input: Vec<u32>,
    tris: Vec<Triangle>,
    /// The insertion whose cavity last took each triangle (1 + its vertex).
    stamp: Vec<u32>,
    /// The next insertions: every vertex but the first triangle's.
    rest: Vec<u32>,
    /// Which edge a walk tries first: random, so that no walk can be
    /// trapped in a cycle by a fixed order (Devillers, Pion and Teillaud,
    /// "Walking in a triangulation", 2002).
    rng: SplitMix64,
    duplicates: Vec<(u32, u32)>,
    walk_steps: u64,
    cavity_triangles: u64,
    cavity: Vec<u32>,
    stack: Vec<u32>,
    boundary: Vec<Boundary>,
    starts: Vec<(u32, u32)>,
    predicates: PhantomData<P>,
}

impl<P: Predicates> Mesh<P> {
    /// The first triangle, from the first point, the first one different
    /// from it, and the first one not collinear with both, closed by three
    /// ghosts; `None` when there is no such triangle.
    fn start(pts: Vec<DVec2>, input: Vec<u32>) -> Option<Self> {
        let first = *pts.first()?;
        let i1 = pts.iter().position(|&p| p != first)?;
        let (i2, turn) = pts
            .iter()
            .enumerate()
            .skip(i1 + 1)
            .map(|(k, &p)| (k, P::orient2d(first, pts[i1], p)))
            .find(|&(_, s)| s != Sign::Zero)?;
        let (v1, v2) = if turn == Sign::Positive {
            (i1 as u32, i2 as u32)
        } else {
            (i2 as u32, i1 as u32)
        };
        let t = |v, n| Triangle { v, n };
        let tris = vec![
            t([0, v1, v2], [1, 2, 3]),
            t([v2, v1, GHOST], [3, 2, 0]),
            t([0, v2, GHOST], [1, 3, 0]),
            t([v1, 0, GHOST], [2, 1, 0]),
        ];
        let rest = (1..pts.len() as u32)
            .filter(|&k| k != v1 && k != v2)
            .collect();
        Some(Mesh {
            stamp: vec![0; tris.len()],
            tris,
            pts,
            input,
            rest,
            rng: SplitMix64::for_inputs("exactray-delaunay", "walk"),
            duplicates: Vec::new(),
            walk_steps: 0,
            cavity_triangles: 0,
            cavity: Vec::new(),
            stack: Vec::new(),
            boundary: Vec::new(),
            starts: Vec::new(),
            predicates: PhantomData,
        })
    }

    fn insert_all(&mut self) -> Result<(), TriangulationError> {
        let mut last = 0;
        for j in 0..self.rest.len() {
            let k = self.rest[j];
            match self.locate(k, last)? {
                Located::Vertex(v) => self
                    .duplicates
                    .push((self.input[k as usize], self.input[v as usize])),
                Located::Triangle(t) => last = self.insert(k, t)?,
            }
        }
        Ok(())
    }

    fn finish(self) -> Triangulation {
        let input = &self.input;
        Triangulation {
            triangles: self
                .tris
                .iter()
                .filter(|t| !t.is_ghost())
                .map(|t| t.v.map(|v| input[v as usize]))
                .collect(),
            duplicates: self.duplicates,
            walk_steps: self.walk_steps,
            cavity_triangles: self.cavity_triangles,
        }
    }

    fn error_at(&self, k: u32, error: fn(u32) -> TriangulationError) -> TriangulationError {
        error(self.input[k as usize])
    }

    /// Walks from `start` towards vertex `k`'s point, crossing an edge
    /// whenever the point lies strictly beyond it.
    fn locate(&mut self, k: u32, start: u32) -> Result<Located, TriangulationError> {
        let p = self.pts[k as usize];
        let mut t = start;
        if self.tris[t as usize].is_ghost() {
            t = self.tris[t as usize].n[2];
        }
        // Every triangle at most once, or the walk is going round.
        let most = self.tris.len() as u64;
        let mut prev = GHOST;
        let mut steps = 0;
        'walk: loop {
            let tri = self.tris[t as usize];
            if tri.is_ghost() {
                return Err(self.error_at(k, |index| TriangulationError::WalkCycle { index }));
            }
            let first = (self.rng.next_u64() % 3) as usize;
            for i in [first, NEXT[first], PREV[first]] {
                let next = tri.n[i];
                // The point lies strictly on this side of the edge just crossed.
                if next == prev {
                    continue;
                }
                let (u, w) = (tri.v[NEXT[i]], tri.v[PREV[i]]);
                if P::orient2d(self.pts[u as usize], self.pts[w as usize], p) == Sign::Negative {
                    steps += 1;
                    if steps > most {
                        return Err(
                            self.error_at(k, |index| TriangulationError::WalkCycle { index })
                        );
                    }
                    if self.tris[next as usize].is_ghost() {
                        self.walk_steps += steps;
                        return Ok(Located::Triangle(next));
                    }
                    prev = t;
                    t = next;
                    continue 'walk;
                }
            }
            self.walk_steps += steps;
            return Ok(match tri.v.iter().find(|&&v| self.pts[v as usize] == p) {
                Some(&v) => Located::Vertex(v),
                None => Located::Triangle(t),
            });
        }
    }

    /// Whether triangle `t`'s circumcircle (a ghost's half-plane) holds `p`.
    fn conflicts(&self, t: u32, p: DVec2) -> bool {
        let [a, b, c] = self.tris[t as usize].v;
        let (a, b) = (self.pts[a as usize], self.pts[b as usize]);
        if c == GHOST {
            match P::orient2d(a, b, p) {
                Sign::Positive => true,
                Sign::Zero => strictly_between(a, b, p),
                Sign::Negative => false,
            }
        } else {
            P::incircle(a, b, self.pts[c as usize], p) == Sign::Positive
        }
    }

    /// Inserts vertex `k` into the cavity grown from `t0`; a new triangle.
    fn insert(&mut self, k: u32, t0: u32) -> Result<u32, TriangulationError> {
        self.grow_cavity(k, t0);
        let broken = |m: &Self| m.error_at(k, |index| TriangulationError::BrokenCavity { index });
        // A disk of c triangles with every vertex on its boundary has
        // c + 2 boundary edges; one with a hole or an inner vertex fewer.
        if self.boundary.len() != self.cavity.len() + 2 {
            return Err(broken(self));
        }
        self.cavity_triangles += self.cavity.len() as u64;
        for _ in 0..2 {
            self.cavity.push(self.tris.len() as u32);
            self.tris.push(Triangle {
                v: [GHOST; 3],
                n: [GHOST; 3],
            });
            self.stamp.push(0);
        }
        self.starts.clear();
        for (&e, &s) in self.boundary.iter().zip(&self.cavity) {
            self.tris[s as usize] = Triangle {
                v: [e.u, e.w, k],
                n: [GHOST, GHOST, e.outside],
            };
            let outside = &mut self.tris[e.outside as usize];
            let Some(i) = (0..3).find(|&i| outside.v[i] != e.u && outside.v[i] != e.w) else {
                return Err(broken(self));
            };
            outside.n[i] = s;
            self.starts.push((e.u, s));
        }
        self.link_fan().ok_or_else(|| broken(self))?;
        Ok(self.cavity[0])
    }

    /// The cavity of vertex `k`: the triangles in conflict with it,
    /// connected to `t0`, in `self.cavity`, and their boundary.
    fn grow_cavity(&mut self, k: u32, t0: u32) {
        let p = self.pts[k as usize];
        let stamp = k + 1;
        self.cavity.clear();
        self.boundary.clear();
        self.stack.clear();
        self.stamp[t0 as usize] = stamp;
        self.cavity.push(t0);
        self.stack.push(t0);
        while let Some(t) = self.stack.pop() {
            let tri = self.tris[t as usize];
            for i in 0..3 {
                let next = tri.n[i];
                if self.stamp[next as usize] == stamp {
                    continue;
                }
                if self.conflicts(next, p) {
                    self.stamp[next as usize] = stamp;
                    self.cavity.push(next);
                    self.stack.push(next);
                } else {
                    self.boundary.push(Boundary {
                        u: tri.v[NEXT[i]],
                        w: tri.v[PREV[i]],
                        outside: next,
                    });
                }
            }
        }
    }

    /// Links the new triangles `[u, w, k]` (slots in `self.cavity`, edge
    /// starts in `self.starts`) to each other round the new vertex, then
    /// puts each ghost vertex last. `None` when the boundary is not one
    /// loop through distinct vertices.
    fn link_fan(&mut self) -> Option<()> {
        self.starts.sort_unstable();
        if self.starts.windows(2).any(|w| w[0].0 == w[1].0) {
            return None;
        }
        for &s in &self.cavity {
            let w = self.tris[s as usize].v[1];
            let at = self.starts.binary_search_by_key(&w, |e| e.0).ok()?;
            let b = self.starts[at].1;
            self.tris[s as usize].n[0] = b;
            self.tris[b as usize].n[1] = s;
        }
        // Two edges ending at one vertex leave a triangle without a
        // predecessor, its link unset.
        if self
            .cavity
            .iter()
            .any(|&s| self.tris[s as usize].n[1] == GHOST)
        {
            return None;
        }
        for &s in &self.cavity {
            let t = &mut self.tris[s as usize];
            let (v, n) = (t.v, t.n);
            if v[0] == GHOST {
                *t = Triangle {
                    v: [v[1], v[2], v[0]],
                    n: [n[1], n[2], n[0]],
                };
            } else if v[1] == GHOST {
                *t = Triangle {
                    v: [v[2], v[0], v[1]],
                    n: [n[2], n[0], n[1]],
                };
            }
        }
        Some(())
    }
}

/// Whether `p`, collinear with `a` and `b`, lies strictly between them.
fn strictly_between(a: DVec2, b: DVec2, p: DVec2) -> bool {
    let inside = |a: f64, b: f64, p: f64| (a < p && p < b) || (b < p && p < a);
    if a.x != b.x {
        inside(a.x, b.x, p.x)
    } else {
        inside(a.y, b.y, p.y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Exactray;

    /// Every neighbour link is mutual and across a shared, reversed edge.
    fn assert_linked<P: Predicates>(mesh: &Mesh<P>) {
        for (t, tri) in mesh.tris.iter().enumerate() {
            for i in 0..3 {
                let other = &mesh.tris[tri.n[i] as usize];
                let (u, w) = (tri.v[NEXT[i]], tri.v[PREV[i]]);
                let j = (0..3)
                    .find(|&j| other.v[NEXT[j]] == w && other.v[PREV[j]] == u)
                    .unwrap_or_else(|| panic!("triangle {t} edge {i}: no reversed edge"));
                assert_eq!(other.n[j] as usize, t, "triangle {t} edge {i}");
            }
        }
    }

    #[test]
    fn a_boundary_that_is_not_one_loop_is_refused() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]].map(DVec2::from_array);
        let mut mesh = Mesh::<Exactray>::start(pts.to_vec(), (0..4).collect()).expect("a triangle");
        let fan = |mesh: &mut Mesh<Exactray>, edges: &[(u32, u32)]| {
            mesh.cavity.clear();
            mesh.starts.clear();
            for &(u, w) in edges {
                mesh.cavity.push(mesh.tris.len() as u32);
                mesh.starts.push((u, mesh.tris.len() as u32));
                mesh.tris.push(Triangle {
                    v: [u, w, 3],
                    n: [GHOST; 3],
                });
            }
            mesh.link_fan()
        };
        // One loop: 0 -> 1 -> 2 -> 0.
        assert!(fan(&mut mesh, &[(0, 1), (1, 2), (2, 0)]).is_some());
        // Two edges start at 1.
        assert!(fan(&mut mesh, &[(0, 1), (1, 2), (1, 0)]).is_none());
        // Two edges end at 1, none at 0.
        assert!(fan(&mut mesh, &[(0, 1), (1, 2), (2, 1)]).is_none());
        // An edge ends where none starts.
        assert!(fan(&mut mesh, &[(0, 1), (1, GHOST - 1)]).is_none());
    }

    #[test]
    fn links_stay_mutual() {
        let pts: Vec<DVec2> =
            exactray::testing::plane_points(exactray::testing::PlaneDistribution::Grid, 200)
                .collect();
        let mut mesh = Mesh::<Exactray>::start(pts, (0..200).collect()).expect("a triangle");
        assert_linked(&mesh);
        let rest = mesh.rest.clone();
        let mut last = 0;
        for k in rest {
            if let Located::Triangle(t) = mesh.locate(k, last).expect("walks") {
                last = mesh.insert(k, t).expect("inserts");
                assert_linked(&mesh);
            }
        }
        assert!(
            mesh.tris
                .iter()
                .all(|t| t.v[..2].iter().all(|&v| v != GHOST))
        );
    }
}
