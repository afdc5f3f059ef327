//! Ray–triangle cases for the tests, the fuzz target's seeds and the report:
//! ordinary rays, rays aimed at shared edges and vertices of a tiled mesh,
//! far origins, rays within an ulp of an edge, grazing rays.
//!
//! Shared by `tests/` and the report via `#[path]`.
#![allow(dead_code)]

use exactray::testing::{SplitMix64, step_ulps};
use glam::DVec3;

/// One ray against one triangle: origin, direction, vertices.
pub type Case = (DVec3, DVec3, [DVec3; 3]);

fn uniform_in(rng: &mut SplitMix64, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * rng.next_f64()
}

fn point(rng: &mut SplitMix64, r: f64) -> DVec3 {
    DVec3::new(
        uniform_in(rng, -r, r),
        uniform_in(rng, -r, r),
        uniform_in(rng, -r, r),
    )
}

/// A point of the triangle's plane with barycentric coordinates in `[lo, hi]`.
fn aim(rng: &mut SplitMix64, v: &[DVec3; 3], lo: f64, hi: f64) -> DVec3 {
    let (u, w) = (uniform_in(rng, lo, hi), uniform_in(rng, lo, hi));
    v[0] + (v[1] - v[0]) * u + (v[2] - v[0]) * w
}

/// Vertices in `[-1, 1]^3`, the origin in `[-4, 4]^3`, aimed at a point
/// with barycentrics in `[-0.25, 1.25]` (about a third hit).
pub fn uniform(rng: &mut SplitMix64) -> Case {
    let v = [0; 3].map(|_| point(rng, 1.0));
    let o = point(rng, 4.0);
    (o, aim(rng, &v, -0.25, 1.25) - o, v)
}

/// As [`uniform`], with the origin `10^6` to `10^12` away.
pub fn far(rng: &mut SplitMix64) -> Case {
    let v = [0; 3].map(|_| point(rng, 1.0));
    let dist = 10f64.powf(uniform_in(rng, 6.0, 12.0));
    let o = point(rng, 1.0).normalize_or(DVec3::X) * dist;
    (o, aim(rng, &v, -0.25, 1.25) - o, v)
}

/// Aimed at a rounded point of an edge, then the direction moved by 0 to
/// 2 ulps in each coordinate: rays within a few ulps of the edge, on
/// either side.
pub fn near_edge(rng: &mut SplitMix64) -> Case {
    let v = [0; 3].map(|_| point(rng, 1.0));
    let o = point(rng, 4.0);
    let k = (rng.next_u64() % 3) as usize;
    let s = rng.next_f64();
    let p = v[k] + (v[(k + 1) % 3] - v[k]) * s;
    let d = (p - o)
        .to_array()
        .map(|x| step_ulps(x, (rng.next_u64() % 5) as i64 - 2));
    (o, DVec3::from_array(d), v)
}

/// Nearly in the triangle's plane: the origin on the plane (rounded) and
/// moved off it by a relative `10^-12` to `10^-4`, aimed at the triangle.
pub fn grazing(rng: &mut SplitMix64) -> Case {
    let v = [0; 3].map(|_| point(rng, 1.0));
    let n = (v[1] - v[0]).cross(v[2] - v[0]).normalize_or(DVec3::Z);
    let base = aim(rng, &v, -3.0, 4.0);
    let lift =
        10f64.powf(uniform_in(rng, -12.0, -4.0)) * if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
    let o = base + n * lift;
    (o, aim(rng, &v, -0.25, 1.25) - o, v)
}

/// A height field over `[0, n]^2`: grid vertices jittered in x and y,
/// random heights (jitter below 0.15 keeps every triangle counterclockwise), each cell split into two triangles along a diagonal.
/// Every triangle is counterclockwise seen from above.
pub struct TiledMesh {
    pub n: usize,
    pub vertices: Vec<DVec3>,
    pub triangles: Vec<[usize; 3]>,
}

impl TiledMesh {
    pub fn new(rng: &mut SplitMix64, n: usize) -> Self {
        let mut vertices = Vec::with_capacity((n + 1) * (n + 1));
        for j in 0..=n {
            for i in 0..=n {
                // The border stays straight so that the mesh covers the square.
                let jitter = |rng: &mut SplitMix64, k: usize| {
                    if k == 0 || k == n {
                        0.0
                    } else {
                        uniform_in(rng, -0.15, 0.15)
                    }
                };
                let x = i as f64 + jitter(rng, i);
                let y = j as f64 + jitter(rng, j);
                vertices.push(DVec3::new(x, y, uniform_in(rng, -0.5, 0.5)));
            }
        }
        let at = |i: usize, j: usize| j * (n + 1) + i;
        let mut triangles = Vec::with_capacity(2 * n * n);
        for j in 0..n {
            for i in 0..n {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                if (i + j) % 2 == 0 {
                    triangles.extend([[a, b, c], [a, c, d]]);
                } else {
                    triangles.extend([[a, b, d], [b, c, d]]);
                }
            }
        }
        TiledMesh {
            n,
            vertices,
            triangles,
        }
    }

    pub fn triangle(&self, k: usize) -> [DVec3; 3] {
        self.triangles[k].map(|i| self.vertices[i])
    }

    /// The interior edges (shared by two triangles), as vertex pairs.
    pub fn interior_edges(&self) -> Vec<(usize, usize)> {
        let mut edges: Vec<(usize, usize)> = self
            .triangles
            .iter()
            .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
            .map(|(a, b)| (a.min(b), a.max(b)))
            .collect();
        edges.sort_unstable();
        let mut shared = Vec::new();
        let mut i = 0;
        while i < edges.len() {
            let mut j = i;
            while j < edges.len() && edges[j] == edges[i] {
                j += 1;
            }
            if j - i == 2 {
                shared.push(edges[i]);
            }
            i = j;
        }
        shared
    }

    /// The interior vertices (not on the border).
    pub fn interior_vertices(&self) -> Vec<usize> {
        let n = self.n;
        (0..self.vertices.len())
            .filter(|&k| {
                let (i, j) = (k % (n + 1), k / (n + 1));
                i > 0 && i < n && j > 0 && j < n
            })
            .collect()
    }

    /// The triangles that have vertex `a` or `b`: every triangle a ray
    /// passing within rounding of the edge `a b` (or of the vertex `a`)
    /// can meet.
    pub fn around(&self, a: usize, b: usize) -> Vec<usize> {
        (0..self.triangles.len())
            .filter(|&k| self.triangles[k].contains(&a) || self.triangles[k].contains(&b))
            .collect()
    }

    /// A ray from above (an origin 1 to 10 units over the mesh) aimed at a
    /// rounded point of an interior edge, or (one time in four) at an
    /// interior vertex, which the direction `target - origin` then passes
    /// within rounding; and the triangles around that edge or vertex. Its
    /// line crosses the mesh's interior there, so it meets at least one of
    /// them exactly.
    pub fn shared_edge_ray(
        &self,
        rng: &mut SplitMix64,
        edges: &[(usize, usize)],
        inner: &[usize],
    ) -> (DVec3, DVec3, Vec<usize>) {
        let (target, around) = if rng.next_u64().is_multiple_of(4) {
            let a = inner[(rng.next_u64() % inner.len() as u64) as usize];
            (self.vertices[a], self.around(a, a))
        } else {
            let (a, b) = edges[(rng.next_u64() % edges.len() as u64) as usize];
            let s = rng.next_f64();
            let p = self.vertices[a] + (self.vertices[b] - self.vertices[a]) * s;
            (p, self.around(a, b))
        };
        let o = DVec3::new(
            target.x + uniform_in(rng, -3.0, 3.0),
            target.y + uniform_in(rng, -3.0, 3.0),
            uniform_in(rng, 1.0, 10.0),
        );
        (o, target - o, around)
    }
}
