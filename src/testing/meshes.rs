//! Large triangle meshes generated in the crate (no download), for scene
//! benchmarks and tests: a displaced sphere ([`displaced_sphere`]), a
//! terrain ([`terrain`]) and a closed room with objects in it ([`room`]),
//! each with smooth per-vertex normals, sized by a triangle budget; and
//! camera rays looking at them ([`camera_rays`]).
//!
//! ```
//! use exactray::testing::{SplitMix64, camera_rays, displaced_sphere};
//! let mut rng = SplitMix64::new(1);
//! let sphere = displaced_sphere(&mut rng, 2_000);
//! assert!(sphere.triangles.len() <= 2_000);
//! let rays = camera_rays(&sphere, 16, &mut rng);
//! assert_eq!(rays.len(), 16);
//! ```

use super::generators::SplitMix64;
use crate::arith::std_or_libm::{cos, sin, sqrt};
use alloc::vec;
use alloc::vec::Vec;
use core::f64::consts::PI;
use glam::DVec3;

/// An indexed triangle mesh with per-vertex normals (the area-weighted
/// mean of the faces around each vertex, normalized), as plain data.
#[derive(Clone, Debug)]
pub struct SceneMesh {
    /// The vertices.
    pub vertices: Vec<DVec3>,
    /// The triangles, counterclockwise seen from outside (from inside the
    /// room), as indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
    /// One unit normal per vertex.
    pub normals: Vec<DVec3>,
}

impl SceneMesh {
    fn new(vertices: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> SceneMesh {
        let normals = vertex_normals(&vertices, &triangles);
        SceneMesh {
            vertices,
            triangles,
            normals,
        }
    }

    /// The smallest box holding every vertex: `(min, max)`.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        self.vertices
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &p| {
                (lo.min(p), hi.max(p))
            })
    }

    /// The mesh moved by `offset` (each coordinate rounded once: a far
    /// copy of the same shape, for far-from-origin scenes).
    pub fn translated(&self, offset: DVec3) -> SceneMesh {
        SceneMesh {
            vertices: self.vertices.iter().map(|&p| p + offset).collect(),
            triangles: self.triangles.clone(),
            normals: self.normals.clone(),
        }
    }

    /// Appends `other`'s vertices and triangles.
    fn append(&mut self, other: SceneMesh) {
        let base = self.vertices.len() as u32;
        self.vertices.extend(other.vertices);
        self.normals.extend(other.normals);
        self.triangles
            .extend(other.triangles.iter().map(|t| t.map(|i| i + base)));
    }
}

/// Area-weighted vertex normals, normalized (`+z` where the faces around a
/// vertex cancel).
fn vertex_normals(vertices: &[DVec3], triangles: &[[u32; 3]]) -> Vec<DVec3> {
    let mut sum = vec![DVec3::ZERO; vertices.len()];
    for t in triangles {
        let [a, b, c] = t.map(|i| vertices[i as usize]);
        let n = (b - a).cross(c - a);
        for &i in t {
            sum[i as usize] += n;
        }
    }
    sum.into_iter()
        .map(|n| n.try_normalize().unwrap_or(DVec3::Z))
        .collect()
}

/// A smooth random field: a sum of a few plane waves with random
/// directions, frequencies and phases, each term's amplitude falling with
/// its frequency; roughly within `[-1, 1]`.
struct Waves {
    terms: Vec<(DVec3, f64)>,
}

impl Waves {
    fn new(rng: &mut SplitMix64, count: usize, base: f64) -> Waves {
        let terms = (0..count)
            .map(|k| {
                let f = base * (1.0 + k as f64);
                let dir = unit_vector(rng);
                (dir * f, 2.0 * PI * rng.next_f64())
            })
            .collect();
        Waves { terms }
    }

    fn at(&self, p: DVec3) -> f64 {
        let norm: f64 = (1..=self.terms.len()).map(|k| 1.0 / k as f64).sum();
        self.terms
            .iter()
            .enumerate()
            .map(|(k, &(w, phase))| sin(w.dot(p) + phase) / (1.0 + k as f64))
            .sum::<f64>()
            / norm
    }
}

/// A uniform random unit vector.
fn unit_vector(rng: &mut SplitMix64) -> DVec3 {
    let z = 2.0 * rng.next_f64() - 1.0;
    let phi = 2.0 * PI * rng.next_f64();
    let r = sqrt((1.0 - z * z).max(0.0));
    DVec3::new(r * cos(phi), r * sin(phi), z)
}

/// A unit sphere at the origin, latitude-longitude tessellated (`rings`
/// bands, `2 rings` segments: `4 rings (rings - 1)` triangles), each vertex
/// moved along its radius by up to 6% by a smooth random field: smooth,
/// but with no two triangles in one plane.
pub fn displaced_sphere(rng: &mut SplitMix64, max_triangles: usize) -> SceneMesh {
    let rings = rings_for(max_triangles);
    let waves = Waves::new(rng, 6, 3.0);
    let radial = |p: DVec3| p * (1.0 + 0.06 * waves.at(p));
    let mut mesh = sphere_grid(rings, radial);
    mesh.normals = vertex_normals(&mesh.vertices, &mesh.triangles);
    mesh
}

/// The most rings whose sphere has at most `max` triangles (at least 2).
fn rings_for(max: usize) -> usize {
    let mut r = 2;
    while 4 * (r + 1) * r <= max {
        r += 1;
    }
    r
}

/// The latitude-longitude sphere of `rings` bands, each unit point mapped
/// by `place`.
fn sphere_grid(rings: usize, place: impl Fn(DVec3) -> DVec3) -> SceneMesh {
    let segments = 2 * rings;
    let mut vertices = vec![place(DVec3::Z)];
    for i in 1..rings {
        let theta = PI * i as f64 / rings as f64;
        for j in 0..segments {
            let phi = 2.0 * PI * j as f64 / segments as f64;
            let p = DVec3::new(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
            vertices.push(place(p));
        }
    }
    let south = vertices.len() as u32;
    vertices.push(place(-DVec3::Z));
    let at = |i: usize, j: usize| (1 + (i - 1) * segments + j % segments) as u32;
    let mut triangles = Vec::with_capacity(4 * rings * (rings - 1));
    for j in 0..segments {
        triangles.push([0, at(1, j), at(1, j + 1)]);
        triangles.push([south, at(rings - 1, j + 1), at(rings - 1, j)]);
    }
    for i in 1..rings - 1 {
        for j in 0..segments {
            let (a, b, c, d) = (at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    SceneMesh::new(vertices, triangles)
}

/// A height field over `[0, 100]^2`: `2 n^2` triangles on an `n` by `n`
/// grid (the largest within `max_triangles`), heights up to about 8 from
/// a smooth random field plus a little per-vertex roughness.
pub fn terrain(rng: &mut SplitMix64, max_triangles: usize) -> SceneMesh {
    let mut n = 1;
    while 2 * (n + 1) * (n + 1) <= max_triangles {
        n += 1;
    }
    let waves = Waves::new(rng, 8, 0.05);
    let step = 100.0 / n as f64;
    let mut vertices = Vec::with_capacity((n + 1) * (n + 1));
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (i as f64 * step, j as f64 * step);
            let rough = 0.02 * step * (2.0 * rng.next_f64() - 1.0);
            let h = 8.0 * waves.at(DVec3::new(x, y, 0.0)) + rough;
            vertices.push(DVec3::new(x, y, h));
        }
    }
    let at = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    let mut triangles = Vec::with_capacity(2 * n * n);
    for j in 0..n {
        for i in 0..n {
            triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    SceneMesh::new(vertices, triangles)
}

/// A closed box room `[-10, 10] x [-10, 10] x [0, 10]`, its six walls
/// tessellated and facing in, with objects in it: displaced spheres of
/// radius 1 to 2.5 on the floor and hanging in the air. About a quarter of
/// the `max_triangles` go to the walls, the rest to the objects.
pub fn room(rng: &mut SplitMix64, max_triangles: usize) -> SceneMesh {
    let mut m = 1;
    while 12 * (m + 1) * (m + 1) <= max_triangles / 4 {
        m += 1;
    }
    let mut mesh = SceneMesh::new(Vec::new(), Vec::new());
    let (lo, hi) = (DVec3::new(-10.0, -10.0, 0.0), DVec3::new(10.0, 10.0, 10.0));
    for axis in 0..3 {
        for high in [false, true] {
            mesh.append(wall(lo, hi, axis, high, m));
        }
    }
    let objects = 8;
    let budget = (max_triangles - mesh.triangles.len()) / objects;
    for k in 0..objects {
        let radius = 1.0 + 1.5 * rng.next_f64();
        let x = -7.0 + 14.0 * rng.next_f64();
        let y = -7.0 + 14.0 * rng.next_f64();
        let z = if k % 2 == 0 {
            radius * 0.9
        } else {
            3.0 + 4.0 * rng.next_f64()
        };
        let centre = DVec3::new(x, y, z);
        let ball = displaced_sphere(rng, budget);
        let vertices = ball.vertices.iter().map(|&p| centre + p * radius).collect();
        mesh.append(SceneMesh::new(vertices, ball.triangles));
    }
    mesh
}

/// One wall of the box `[lo, hi]`: the face at `hi[axis]` (`high`) or
/// `lo[axis]`, an `m` by `m` grid, counterclockwise seen from inside.
fn wall(lo: DVec3, hi: DVec3, axis: usize, high: bool, m: usize) -> SceneMesh {
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut vertices = Vec::with_capacity((m + 1) * (m + 1));
    for j in 0..=m {
        for i in 0..=m {
            let mut p = DVec3::ZERO;
            p[axis] = if high { hi[axis] } else { lo[axis] };
            p[u] = lo[u] + (hi[u] - lo[u]) * i as f64 / m as f64;
            p[v] = lo[v] + (hi[v] - lo[v]) * j as f64 / m as f64;
            vertices.push(p);
        }
    }
    let at = |i: usize, j: usize| (j * (m + 1) + i) as u32;
    let mut triangles = Vec::with_capacity(2 * m * m);
    for j in 0..m {
        for i in 0..m {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
            // (u, v, axis) is right-handed: counterclockwise in (u, v)
            // faces +axis, which is inward on the low wall.
            if high {
                triangles.extend([[a, c, d], [a, d, b]]);
            } else {
                triangles.extend([[a, b, d], [a, d, c]]);
            }
        }
    }
    SceneMesh::new(vertices, triangles)
}

/// `count` camera rays `(origin, direction)` of a pinhole camera outside
/// the mesh's box, above and to the side of it, looking at its centre over
/// the narrowest square field of view that holds every vertex. Pixel positions are jittered, so
/// that rays fall between vertices and edges as they do in a renderer.
pub fn camera_rays(mesh: &SceneMesh, count: usize, rng: &mut SplitMix64) -> Vec<(DVec3, DVec3)> {
    let (lo, hi) = mesh.bounds();
    let centre = lo * 0.5 + hi * 0.5;
    let size = (hi - lo).max_element();
    let eye = centre + DVec3::new(0.1, -0.9, 1.4) * size;
    // The narrowest square view that holds every vertex.
    let (forward, right, up) = frame(centre - eye);
    let half_width = mesh.vertices.iter().fold(0.0f64, |w, &v| {
        let c = v - eye;
        w.max(c.dot(right).abs().max(c.dot(up).abs()) / c.dot(forward))
    });
    pinhole(eye, centre - eye, half_width, count, rng)
}

/// A camera's unit axes looking along `look`: forward, right, up (`+z`
/// up).
fn frame(look: DVec3) -> (DVec3, DVec3, DVec3) {
    let forward = look.normalize();
    let right = forward.cross(DVec3::Z).normalize();
    (forward, right, right.cross(forward))
}

/// `count` camera rays from inside [`room`], at `(0, -9, 5)`, looking along
/// `+y` over a 90 degree field of view.
pub fn room_camera_rays(count: usize, rng: &mut SplitMix64) -> Vec<(DVec3, DVec3)> {
    pinhole(DVec3::new(0.0, -9.0, 5.0), DVec3::Y, 1.0, count, rng)
}

/// A pinhole camera's jittered rays: `count` pixels of a square image
/// whose half width is `half_width` at unit distance along `look`.
fn pinhole(
    eye: DVec3,
    look: DVec3,
    half_width: f64,
    count: usize,
    rng: &mut SplitMix64,
) -> Vec<(DVec3, DVec3)> {
    let (forward, right, up) = frame(look);
    // The smallest square image holding `count` pixels.
    let mut side = 1;
    while side * side < count {
        side += 1;
    }
    let side_f = side as f64;
    (0..count)
        .map(|k| {
            let (i, j) = ((k % side) as f64, (k / side) as f64);
            let x = ((i + rng.next_f64()) / side_f * 2.0 - 1.0) * half_width;
            let y = ((j + rng.next_f64()) / side_f * 2.0 - 1.0) * half_width;
            (eye, forward + right * x + up * y)
        })
        .collect()
}

/// A direction about the unit `normal` with the cosine-weighted density of
/// a diffuse bounce (Malley's method: a uniform disk point lifted onto the
/// hemisphere).
pub fn cosine_direction(normal: DVec3, rng: &mut SplitMix64) -> DVec3 {
    let (a, b) = normal.any_orthonormal_pair();
    let r = sqrt(rng.next_f64());
    let phi = 2.0 * PI * rng.next_f64();
    let (x, y) = (r * cos(phi), r * sin(phi));
    let z = sqrt((1.0 - x * x - y * y).max(0.0));
    a * x + b * y + normal * z
}

/// A UV sphere of `rings` by `segments` quads (triangles at the poles, on
/// the `z` axis), every triangle counterclockwise seen from outside, with
/// the unit vertex normals of the exact sphere: coarse ones show how far
/// interpolated normals lean from the facets' (question Q3). `rings` is
/// taken as at least 2 and `segments` as at least 3.
pub fn uv_sphere(center: DVec3, radius: f64, rings: u32, segments: u32) -> SceneMesh {
    let (rings, segments) = (rings.max(2), segments.max(3));
    let mut normals = vec![DVec3::Z];
    for i in 1..rings {
        let theta = PI * i as f64 / rings as f64;
        for j in 0..segments {
            let phi = 2.0 * PI * j as f64 / segments as f64;
            normals.push(DVec3::new(
                sin(theta) * cos(phi),
                sin(theta) * sin(phi),
                cos(theta),
            ));
        }
    }
    normals.push(-DVec3::Z);
    let last = normals.len() as u32 - 1;
    let at = |i: u32, j: u32| 1 + (i - 1) * segments + j % segments;
    let mut triangles = Vec::new();
    for j in 0..segments {
        triangles.push([0, at(1, j), at(1, j + 1)]);
        triangles.push([last, at(rings - 1, j + 1), at(rings - 1, j)]);
        for i in 1..rings - 1 {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            triangles.extend([[a, b, c], [a, c, d]]);
        }
    }
    let vertices: Vec<DVec3> = normals.iter().map(|n| center + *n * radius).collect();
    // Counterclockwise from outside: flip any triangle facing inwards.
    for t in &mut triangles {
        let [a, b, c] = t.map(|i| vertices[i as usize]);
        if (b - a).cross(c - a).dot(a + b + c - center * 3.0) < 0.0 {
            t.swap(1, 2);
        }
    }
    SceneMesh {
        vertices,
        triangles,
        normals,
    }
}

/// The six unit vectors along the axes, `+x, -x, +y, -y, +z, -z`: the
/// directions of [`closed_octahedron`]'s vertices from its centre (its
/// exact vertex normals).
pub const AXIS_DIRECTIONS: [DVec3; 6] = [
    DVec3::X,
    DVec3::NEG_X,
    DVec3::Y,
    DVec3::NEG_Y,
    DVec3::Z,
    DVec3::NEG_Z,
];

/// The closed octahedron `|x - c_x| + |y - c_y| + |z - c_z| <= r`: its
/// vertices `c ± r` along each axis (`+x, -x, +y, -y, +z, -z`), its eight
/// triangles counterclockwise seen from outside. Every edge is shared by
/// two triangles running along it in opposite directions.
pub fn closed_octahedron(c: DVec3, r: f64) -> SceneMesh {
    let mut triangles = Vec::with_capacity(8);
    for x in [0u32, 1] {
        for y in [2u32, 3] {
            for z in [4u32, 5] {
                // Counterclockwise from outside when the octant's signs
                // multiply to +1.
                let positive = (x + y + z).is_multiple_of(2);
                triangles.push(if positive { [x, y, z] } else { [x, z, y] });
            }
        }
    }
    SceneMesh::new(AXIS_DIRECTIONS.map(|d| c + d * r).to_vec(), triangles)
}

/// The closed cube `[lo, hi]^3`: vertex `x + 2y + 4z` at the corner whose
/// coordinates are `hi` where the bit is set, two triangles per face,
/// counterclockwise seen from outside.
pub fn closed_cube(lo: f64, hi: f64) -> SceneMesh {
    let vertices = (0..8)
        .map(|i| DVec3::from_array([i & 1, i & 2, i & 4].map(|b| if b == 0 { lo } else { hi })))
        .collect();
    let triangles = vec![
        [0, 2, 3],
        [0, 3, 1],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 6, 7],
        [2, 7, 3],
        [0, 4, 6],
        [0, 6, 2],
        [1, 3, 7],
        [1, 7, 5],
    ];
    SceneMesh::new(vertices, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every scene stays within its budget, indexes only its vertices, and
    /// has one unit normal per vertex; the sizes grow with the budget.
    #[test]
    fn scenes_fit_their_budgets() {
        let mut rng = SplitMix64::new(3);
        for budget in [500, 5_000, 50_000] {
            let scenes = [
                displaced_sphere(&mut rng, budget),
                terrain(&mut rng, budget),
                room(&mut rng, budget),
            ];
            for s in &scenes {
                let n = s.triangles.len();
                assert!(n <= budget && n * 2 > budget, "{n} of {budget}");
                assert!(
                    s.triangles
                        .iter()
                        .flatten()
                        .all(|&i| (i as usize) < s.vertices.len())
                );
                assert_eq!(s.normals.len(), s.vertices.len());
                // `normalize` multiplies by the rounded reciprocal of the
                // rounded length: each coordinate within about 4u of the
                // exact unit vector's, so the squared length within about
                // 11u of 1 (Higham, Lemma 3.1); 16u = 8 EPSILON allows it.
                let near_one = |v: &DVec3| (v.length_squared() - 1.0).abs() <= 8.0 * f64::EPSILON;
                assert!(s.normals.iter().all(near_one));
            }
        }
    }
}
