//! Deterministic generators of hard ray inputs, shared by the tests, the
//! fuzz targets' seeds, the benchmarks and the speed-against-error report:
//! rays against one triangle ([`RayTriangleClass`]), rays at the shared
//! edges and vertices of a tiled mesh ([`TiledMesh`], with `alloc`), and
//! rays against spheres, cylinders, cones and general quadrics
//! ([`SphereRayClass`], [`CylinderRayClass`], [`ConeRayClass`],
//! [`QuadricRayClass`]).
//!
//! Each generator draws one case of a class with a [`SplitMix64`] stream,
//! so a seed names a case set exactly (up to the last bit of `pow`, `sin`
//! and `cos`, see the [module](super) note). Cases are plain data: the caller
//! builds the shapes and rays (a degenerate triangle or a zero direction
//! may come out, and a caller skips what its constructor refuses).
//!
//! ```
//! use exactray::query::ray::{Ray, RayCast};
//! use exactray::shape::Sphere;
//! use exactray::testing::{SphereRayClass, SplitMix64, sphere_ray_case};
//! let mut rng = SplitMix64::new(7);
//! for class in SphereRayClass::ALL {
//!     let c = sphere_ray_case(class, &mut rng);
//!     let sphere = Sphere::new(c.center, c.radius).unwrap();
//!     let ray = Ray::new(c.origin, c.direction).unwrap();
//!     let _ = sphere.line_roots(&ray);
//! }
//! ```

use super::generators::{SplitMix64, pow2, step_ulps};
use crate::arith::std_or_libm::{cos, powf, round, sin, sqrt};
use glam::DVec3;

/// Uniform in `[lo, hi)`.
pub(super) fn uniform(rng: &mut SplitMix64, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * rng.next_f64()
}

/// A point uniform in the cube `[-h, h]^3`.
fn cube(rng: &mut SplitMix64, h: f64) -> [f64; 3] {
    core::array::from_fn(|_| uniform(rng, -h, h))
}

/// A point uniform in the cube `[-h, h]^3`, as a vector.
pub(super) fn point(rng: &mut SplitMix64, h: f64) -> DVec3 {
    DVec3::from_array(cube(rng, h))
}

/// A unit vector, uniform on the sphere.
fn unit(rng: &mut SplitMix64) -> [f64; 3] {
    loop {
        let v = cube(rng, 1.0);
        let n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if n > 0.1 && n <= 1.0 {
            return v.map(|x| x / n);
        }
    }
}

/// A unit vector, uniform on the sphere: directions for tests of rays
/// and scenes.
pub fn unit_vector(rng: &mut SplitMix64) -> DVec3 {
    DVec3::from_array(unit(rng))
}

/// A point of the triangle `[a, b, c]`, uniform over its area: `a + (b -
/// a) u + (c - a) v` for `(u, v)` uniform in the unit square, folded into
/// `u + v <= 1` (rounded).
pub fn point_in_triangle(rng: &mut SplitMix64, [a, b, c]: [DVec3; 3]) -> DVec3 {
    let (u, v) = (rng.next_f64(), rng.next_f64());
    let (u, v) = if u + v > 1.0 {
        (1.0 - u, 1.0 - v)
    } else {
        (u, v)
    };
    a + (b - a) * u + (c - a) * v
}

/// `10^x`.
fn pow10(x: f64) -> f64 {
    powf(10.0, x)
}

/// Input classes of one kind of ray case, with the names reports give them.
macro_rules! ray_classes {
    ($(#[$doc:meta])* $class:ident { $($(#[$vdoc:meta])* $variant:ident = $name:literal,)* }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum $class {
            $($(#[$vdoc])* $variant,)*
        }

        impl $class {
            /// Every class, in the order the report lists them.
            pub const ALL: [$class; [$($class::$variant),*].len()] = [$($class::$variant),*];

            /// The class's name in reports: lower case with hyphens.
            pub fn name(self) -> &'static str {
                match self {
                    $($class::$variant => $name,)*
                }
            }
        }
    };
}

/// One ray against one triangle: origin, direction, vertices.
pub type RayTriangleCase = (DVec3, DVec3, [DVec3; 3]);

ray_classes! {
    /// A kind of ray against one triangle, for [`ray_triangle_case`]:
    /// vertices in `[-1, 1]^3`.
    RayTriangleClass {
        /// Origins in `[-4, 4]^3` aimed at a point with barycentrics in
        /// `[-0.25, 1.25]` (about a third hit).
        Uniform = "uniform",
        /// As `Uniform`, with the origin `10^6` to `10^12` away.
        Far = "far",
        /// Aimed at a rounded point of an edge, then the direction moved by
        /// -2 to 2 ulps in each coordinate: rays within a few ulps of the
        /// edge, on either side.
        NearEdge = "near-edge",
        /// Nearly in the triangle's plane: the origin on the plane (rounded)
        /// and moved off it by a relative `10^-12` to `10^-4`, aimed at the
        /// triangle.
        Grazing = "grazing",
    }
}

/// A point of the triangle's plane with barycentric coordinates in `[lo, hi]`.
fn aim(rng: &mut SplitMix64, v: &[DVec3; 3], lo: f64, hi: f64) -> DVec3 {
    let (u, w) = (uniform(rng, lo, hi), uniform(rng, lo, hi));
    v[0] + (v[1] - v[0]) * u + (v[2] - v[0]) * w
}

/// A ray–triangle case as bit patterns: origin, direction, vertices.
pub type RayTriangleBits = ([u64; 3], [u64; 3], [[u64; 3]; 3]);

/// Fuzzer findings against the exact ray–triangle cast, as bit patterns
/// (origin, direction, vertices): kept so every suite can replay them.
///
/// - A fuzzer finding: subnormal, tiny and huge coordinates in one case, a
///   direction whose largest coordinate is subnormal and an exact `t` near
///   `2^1177`; the filter's bound once underflowed to zero there.
pub const RAY_TRIANGLE_FINDINGS: [RayTriangleBits; 1] = [(
    [0x0000000000001348, 0x482b488eb0a3bf00, 0x0000000025000048],
    [0x0000000012000000, 0x0000000000000000, 0x000000d100000000],
    [
        [0x060000000a000000, 0x25fd166cffd81300, 0x4848486840c729fe],
        [0x0000545454544848, 0x0000000000393b00, 0x00250600002f0000],
        [0x5454545454000000, 0x5454545054545454, 0x4854000ccf0a5454],
    ],
)];

/// [`RAY_TRIANGLE_FINDINGS`]`[i]` as a case, or `None` past the end.
pub fn ray_triangle_finding(i: usize) -> Option<RayTriangleCase> {
    let (o, d, v) = RAY_TRIANGLE_FINDINGS.get(i)?;
    let p = |b: &[u64; 3]| {
        DVec3::new(
            f64::from_bits(b[0]),
            f64::from_bits(b[1]),
            f64::from_bits(b[2]),
        )
    };
    Some((p(o), p(d), v.map(|b| p(&b))))
}

/// One ray–triangle case of `class`.
pub fn ray_triangle_case(class: RayTriangleClass, rng: &mut SplitMix64) -> RayTriangleCase {
    let v = [0; 3].map(|_| point(rng, 1.0));
    match class {
        RayTriangleClass::Uniform => {
            let o = point(rng, 4.0);
            (o, aim(rng, &v, -0.25, 1.25) - o, v)
        }
        RayTriangleClass::Far => {
            let dist = pow10(uniform(rng, 6.0, 12.0));
            let o = point(rng, 1.0).normalize_or(DVec3::X) * dist;
            (o, aim(rng, &v, -0.25, 1.25) - o, v)
        }
        RayTriangleClass::NearEdge => {
            let o = point(rng, 4.0);
            let k = (rng.next_u64() % 3) as usize;
            let s = rng.next_f64();
            let p = v[k] + (v[(k + 1) % 3] - v[k]) * s;
            let d = (p - o)
                .to_array()
                .map(|x| step_ulps(x, (rng.next_u64() % 5) as i64 - 2));
            (o, DVec3::from_array(d), v)
        }
        RayTriangleClass::Grazing => {
            let n = (v[1] - v[0]).cross(v[2] - v[0]).normalize_or(DVec3::Z);
            let base = aim(rng, &v, -3.0, 4.0);
            let lift =
                pow10(uniform(rng, -12.0, -4.0)) * if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
            let o = base + n * lift;
            (o, aim(rng, &v, -0.25, 1.25) - o, v)
        }
    }
}

#[cfg(feature = "alloc")]
pub use mesh::TiledMesh;

#[cfg(feature = "alloc")]
mod mesh {
    use super::{SplitMix64, uniform};
    use alloc::vec::Vec;
    use glam::DVec3;

    /// A height field over `[0, n]^2`: grid vertices jittered in x and y
    /// (below 0.15, which keeps every triangle counterclockwise seen from
    /// above), random heights in `[-0.5, 0.5)`, each cell split into two
    /// triangles along a diagonal.
    pub struct TiledMesh {
        /// Cells per side.
        pub n: usize,
        /// The `(n + 1)^2` vertices, row by row.
        pub vertices: Vec<DVec3>,
        /// The `2 n^2` triangles, as indices into `vertices`.
        pub triangles: Vec<[usize; 3]>,
    }

    impl TiledMesh {
        /// A mesh of `n` by `n` cells drawn from `rng`.
        pub fn new(rng: &mut SplitMix64, n: usize) -> Self {
            let mut vertices = Vec::with_capacity((n + 1) * (n + 1));
            for j in 0..=n {
                for i in 0..=n {
                    // The border stays straight so that the mesh covers the square.
                    let jitter = |rng: &mut SplitMix64, k: usize| {
                        if k == 0 || k == n {
                            0.0
                        } else {
                            uniform(rng, -0.15, 0.15)
                        }
                    };
                    let x = i as f64 + jitter(rng, i);
                    let y = j as f64 + jitter(rng, j);
                    vertices.push(DVec3::new(x, y, uniform(rng, -0.5, 0.5)));
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

        /// The triangles as `u32` indices, as `TriangleMesh::new` takes
        /// them (an index beyond `u32` becomes `u32::MAX`, which the mesh
        /// refuses as out of range).
        pub fn indices(&self) -> Vec<[u32; 3]> {
            self.triangles
                .iter()
                .map(|t| t.map(|i| u32::try_from(i).unwrap_or(u32::MAX)))
                .collect()
        }

        /// The vertices of triangle `k`.
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

        /// A ray from above (an origin 1 to 10 units over the mesh) aimed at
        /// a rounded point of an interior edge, or (one time in four) at an
        /// interior vertex, which the direction `target - origin` then
        /// passes within rounding; and the triangles around that edge or
        /// vertex. Its line crosses the mesh's interior there, so it meets
        /// at least one of them exactly. `edges` and `inner` are
        /// [`interior_edges`](Self::interior_edges) and
        /// [`interior_vertices`](Self::interior_vertices).
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
                target.x + uniform(rng, -3.0, 3.0),
                target.y + uniform(rng, -3.0, 3.0),
                uniform(rng, 1.0, 10.0),
            );
            (o, target - o, around)
        }
    }
}

/// A ray against a sphere, for [`sphere_ray_case`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereRay {
    /// The ray's origin.
    pub origin: [f64; 3],
    /// The ray's direction (not normalized).
    pub direction: [f64; 3],
    /// The sphere's centre.
    pub center: [f64; 3],
    /// The sphere's radius.
    pub radius: f64,
}

ray_classes! {
    /// A kind of ray against a sphere.
    SphereRayClass {
        /// Centres in `[-1, 1]^3`, radii 0.5 to 2, origins in `[-6, 6]^3`
        /// aimed within 1.3 radii of the centre (about two thirds hit),
        /// directions of length 1/4 to 4 of the aim.
        Uniform = "uniform",
        /// Rays passing the sphere within a relative `1e-12` of its radius
        /// from 2 to 5 radii away: near-tangent hits and misses.
        Grazing = "grazing",
        /// Origins `1e6` to `1e8` away from a unit sphere, aimed within 1.2
        /// of its centre.
        Far = "far",
        /// Exactly tangent rays: integer centres, radius 5, the ray through
        /// a point (3, 4) of the circle perpendicular to its radius, in a
        /// random coordinate order, scaled by a power of two in `2^-20` to
        /// `2^20`.
        Tangent = "tangent",
    }
}

/// A ray from `o` through `target`, its direction scaled by `s`.
fn through(o: [f64; 3], target: [f64; 3], s: f64) -> [f64; 3] {
    core::array::from_fn(|k| (target[k] - o[k]) * s)
}

/// One ray–sphere case of `class`.
pub fn sphere_ray_case(class: SphereRayClass, rng: &mut SplitMix64) -> SphereRay {
    let case = |origin, direction, center, radius| SphereRay {
        origin,
        direction,
        center,
        radius,
    };
    match class {
        SphereRayClass::Uniform => {
            let c = cube(rng, 1.0);
            let r = uniform(rng, 0.5, 2.0);
            let o = cube(rng, 6.0);
            let aim = cube(rng, 1.3 * r);
            let target = core::array::from_fn(|k| c[k] + aim[k]);
            case(o, through(o, target, uniform(rng, 0.25, 4.0)), c, r)
        }
        SphereRayClass::Grazing => {
            let c = cube(rng, 1.0);
            let r = uniform(rng, 0.5, 2.0);
            let n = unit(rng);
            let t = unit(rng);
            // Tangent direction: t with its component along n removed.
            let dot = n[0] * t[0] + n[1] * t[1] + n[2] * t[2];
            let tan: [f64; 3] = core::array::from_fn(|k| t[k] - dot * n[k]);
            let h = r * (1.0 + uniform(rng, -1e-12, 1e-12));
            let p: [f64; 3] = core::array::from_fn(|k| c[k] + h * n[k]);
            let back = uniform(rng, 2.0, 5.0) * r;
            let o = core::array::from_fn(|k| p[k] - back * tan[k]);
            case(o, through(o, p, 1.0), c, r)
        }
        SphereRayClass::Far => {
            let c = cube(rng, 1.0);
            let dist = pow10(uniform(rng, 6.0, 8.0));
            let u = unit(rng);
            let o = core::array::from_fn(|k| c[k] + dist * u[k]);
            let aim = cube(rng, 1.2);
            let target = core::array::from_fn(|k| c[k] + aim[k]);
            case(o, through(o, target, 1.0 / dist), c, 1.0)
        }
        SphereRayClass::Tangent => {
            let c: [f64; 3] = cube(rng, 8.0).map(round);
            let k = pow2((rng.next_u64() % 41) as i64 - 20);
            let perm = (rng.next_u64() % 3) as usize;
            let mut p = [3.0, 4.0, 0.0];
            let mut d = [-4.0, 3.0, 0.0];
            p.rotate_right(perm);
            d.rotate_right(perm);
            let back = (rng.next_u64() % 8 + 1) as f64;
            let o: [f64; 3] = core::array::from_fn(|i| (c[i] + p[i] - back * d[i]) * k);
            case(o, d, c.map(|x| x * k), 5.0 * k)
        }
    }
}

/// A ray against an infinite cylinder, for [`cylinder_ray_case`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CylinderRay {
    /// The ray's origin.
    pub origin: [f64; 3],
    /// The ray's direction (not normalized).
    pub direction: [f64; 3],
    /// A point of the cylinder's axis.
    pub point: [f64; 3],
    /// The axis's direction (not normalized).
    pub axis: [f64; 3],
    /// The cylinder's radius.
    pub radius: f64,
}

ray_classes! {
    /// A kind of ray against an infinite cylinder.
    CylinderRayClass {
        /// The y axis through a point of `[-1, 1]^3`, radius 0.5 to 2;
        /// origins in `[-6, 6]^3` aimed within 1.3 radii of the axis's
        /// point, directions of length 1/4 to 4 of the aim.
        Uniform = "uniform",
        /// As `Uniform`, around a random axis of length 0.1 to 10 per
        /// coordinate.
        AnyAxis = "any-axis",
        /// Rays passing the y axis at a distance within a relative `1e-12`
        /// of the radius, perpendicular-ish to it.
        Grazing = "grazing",
        /// The cylinder `x^2 + z^2 = 1` seen from `1e6` to `1e8` away.
        Far = "far",
        /// Rays along the axis direction exactly (dyadic axes, scaled by
        /// `2^-4` to `2^4`): inside, outside, or on the surface (every `t`).
        Parallel = "parallel",
    }
}

/// One ray–cylinder case of `class`.
pub fn cylinder_ray_case(class: CylinderRayClass, rng: &mut SplitMix64) -> CylinderRay {
    let case = |origin, direction, point, axis, radius| CylinderRay {
        origin,
        direction,
        point,
        axis,
        radius,
    };
    const Y: [f64; 3] = [0.0, 1.0, 0.0];
    match class {
        CylinderRayClass::Uniform => {
            let p = cube(rng, 1.0);
            let r = uniform(rng, 0.5, 2.0);
            let o = cube(rng, 6.0);
            let aim = cube(rng, 1.3 * r);
            let target: [f64; 3] = core::array::from_fn(|k| p[k] + aim[k]);
            let s = uniform(rng, 0.25, 4.0);
            case(o, through(o, target, s), p, Y, r)
        }
        CylinderRayClass::AnyAxis => {
            let c = cylinder_ray_case(CylinderRayClass::Uniform, rng);
            // Each coordinate its own length.
            let axis = unit(rng).map(|x| x * uniform(rng, 0.1, 10.0));
            CylinderRay { axis, ..c }
        }
        CylinderRayClass::Grazing => {
            let p = cube(rng, 1.0);
            let r = uniform(rng, 0.5, 2.0);
            let phi = uniform(rng, 0.0, core::f64::consts::TAU);
            let (n, t) = (
                [cos(phi), 0.0, sin(phi)],
                [-sin(phi), uniform(rng, -0.5, 0.5), cos(phi)],
            );
            let h = r * (1.0 + uniform(rng, -1e-12, 1e-12));
            let hit: [f64; 3] = core::array::from_fn(|k| p[k] + h * n[k]);
            let back = uniform(rng, 2.0, 5.0) * r;
            let o = core::array::from_fn(|k| hit[k] - back * t[k]);
            case(o, t, p, Y, r)
        }
        CylinderRayClass::Far => {
            let dist = pow10(uniform(rng, 6.0, 8.0));
            let phi = uniform(rng, 0.0, core::f64::consts::TAU);
            let o = [dist * cos(phi), uniform(rng, -5.0, 5.0), dist * sin(phi)];
            let aim = cube(rng, 1.2);
            let d = core::array::from_fn(|k| (aim[k] - o[k]) / dist);
            case(o, d, [0.0; 3], Y, 1.0)
        }
        CylinderRayClass::Parallel => {
            let mut a = cube(rng, 2.0).map(|x| round(x * 8.0) / 8.0);
            if a == [0.0; 3] {
                a[2] = 0.125;
            }
            let k = pow2((rng.next_u64() % 9) as i64 - 4);
            let p = cube(rng, 2.0).map(round);
            // The surface point p + e (e perpendicular to a, |e| = r) is
            // exact for e = (a_y, -a_x, 0) and r = |e| when that is a dyadic
            // length; a random offset otherwise (inside or outside).
            let e = [a[1], -a[0], 0.0];
            let r = sqrt(e[0] * e[0] + e[1] * e[1]);
            let o = match rng.next_u64() % 3 {
                0 => core::array::from_fn(|i| p[i] + e[i]),
                1 => core::array::from_fn(|i| p[i] + 0.5 * e[i]),
                _ => core::array::from_fn(|i| p[i] + 2.0 * e[i]),
            };
            case(o, a.map(|x| x * k), p, a, r)
        }
    }
}

/// A ray against a capped cone placed as parry3d places its `Cone`: the
/// base's centre at `center - (0, half_height, 0)`, the apex at
/// `center + (0, half_height, 0)`; for [`cone_ray_case`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConeRay {
    /// The ray's origin.
    pub origin: [f64; 3],
    /// The ray's direction (not normalized).
    pub direction: [f64; 3],
    /// The middle of the cone's axis.
    pub center: [f64; 3],
    /// Half the cone's height.
    pub half_height: f64,
    /// The base's radius.
    pub radius: f64,
}

impl ConeRay {
    /// The apex: `center + (0, half_height, 0)`.
    pub fn apex(&self) -> DVec3 {
        DVec3::from(self.center) + DVec3::new(0.0, self.half_height, 0.0)
    }

    /// The axis from the apex to the base's centre: `(0, -2 half_height, 0)`.
    pub fn axis(&self) -> DVec3 {
        DVec3::new(0.0, -2.0 * self.half_height, 0.0)
    }
}

ray_classes! {
    /// A kind of ray against a capped cone.
    ConeRayClass {
        /// Centres in `[-1, 1]^3`, half heights and radii 0.5 to 2, origins
        /// in `[-6, 6]^3` aimed within 1.2 of the centre.
        Uniform = "uniform",
        /// A `Uniform` case with the origin moved `1e6` to `1e8` farther from
        /// the centre, aimed at the same point.
        Far = "far",
    }
}

/// One ray–cone case of `class`.
pub fn cone_ray_case(class: ConeRayClass, rng: &mut SplitMix64) -> ConeRay {
    match class {
        ConeRayClass::Uniform => {
            let c = cube(rng, 1.0);
            let (hh, r) = (uniform(rng, 0.5, 2.0), uniform(rng, 0.5, 2.0));
            let o = cube(rng, 6.0);
            let aim = cube(rng, 1.2);
            let target: [f64; 3] = core::array::from_fn(|k| c[k] + aim[k]);
            ConeRay {
                origin: o,
                direction: core::array::from_fn(|k| target[k] - o[k]),
                center: c,
                half_height: hh,
                radius: r,
            }
        }
        ConeRayClass::Far => {
            let x = cone_ray_case(ConeRayClass::Uniform, rng);
            let (xo, xc) = (DVec3::from(x.origin), DVec3::from(x.center));
            let dist = pow10(uniform(rng, 6.0, 8.0));
            let o = xo + (xo - xc).normalize() * dist;
            ConeRay {
                origin: o.into(),
                direction: ((xo + DVec3::from(x.direction)) - o).to_array(),
                ..x
            }
        }
    }
}

/// A ray against a general quadric `k0 x^2 + k1 y^2 + k2 z^2 + k3 xy +
/// k4 xz + k5 yz + k6 x + k7 y + k8 z + k9 = 0`, for [`quadric_ray_case`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadricRay {
    /// The ray's origin.
    pub origin: [f64; 3],
    /// The ray's direction (not normalized).
    pub direction: [f64; 3],
    /// The quadric's ten coefficients, in `Quadric::new`'s order.
    pub coefficients: [f64; 10],
}

ray_classes! {
    /// A kind of ray against a general quadric.
    QuadricRayClass {
        /// Ellipsoids, hyperboloids, paraboloids and cones centred near the
        /// origin (diagonal terms 0.3 to 2, negative one time in four, cross
        /// terms below 0.3), rays from `[-4, 4]^3` aimed within 1 of the
        /// origin.
        Uniform = "uniform",
        /// A sphere of radius about 1 written as a quadric, seen from `1e4`
        /// to `1e6` away.
        Far = "far",
        /// Rays along a paraboloid's axis (degree one), along a cone's
        /// rulings (degree one or zero), and exactly tangent to the unit
        /// sphere.
        Degenerate = "degenerate",
    }
}

/// One ray–quadric case of `class`.
pub fn quadric_ray_case(class: QuadricRayClass, rng: &mut SplitMix64) -> QuadricRay {
    let case = |origin, direction, coefficients| QuadricRay {
        origin,
        direction,
        coefficients,
    };
    match class {
        QuadricRayClass::Uniform => {
            let mut k = [0.0; 10];
            for v in &mut k[..3] {
                *v = uniform(rng, 0.3, 2.0)
                    * if rng.next_u64().is_multiple_of(4) {
                        -1.0
                    } else {
                        1.0
                    };
            }
            for v in &mut k[3..9] {
                *v = uniform(rng, -0.3, 0.3);
            }
            k[9] = uniform(rng, -2.0, 0.5);
            let o = cube(rng, 4.0);
            let aim = cube(rng, 1.0);
            case(o, core::array::from_fn(|i| aim[i] - o[i]), k)
        }
        QuadricRayClass::Far => {
            let c = cube(rng, 1.0);
            let r2 = uniform(rng, 0.5, 2.0);
            let k = [
                1.0,
                1.0,
                1.0,
                0.0,
                0.0,
                0.0,
                -2.0 * c[0],
                -2.0 * c[1],
                -2.0 * c[2],
                c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - r2,
            ];
            let dist = pow10(uniform(rng, 4.0, 6.0));
            let o = cube(rng, 1.0).map(|x| x * dist);
            let aim = cube(rng, 1.2);
            case(
                o,
                core::array::from_fn(|i| (c[i] + aim[i] - o[i]) / dist),
                k,
            )
        }
        QuadricRayClass::Degenerate => {
            let o = cube(rng, 3.0).map(|x| round(x * 4.0) / 4.0);
            match rng.next_u64() % 3 {
                0 => case(
                    o,
                    [0.0, 0.0, -1.0],
                    [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0],
                ),
                1 => {
                    let (m, n) = ((rng.next_u64() % 5 + 1) as f64, (rng.next_u64() % 5) as f64);
                    let ruling = [m * m - n * n, 2.0 * m * n, m * m + n * n];
                    case(
                        ruling.map(|x| x * 2.0),
                        ruling,
                        [1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                    )
                }
                _ => case(
                    [-5.0, 1.0, o[2] * 0.0],
                    [1.0, 0.0, 0.0],
                    [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
                ),
            }
        }
    }
}
