//! The scene peers on exactray's meshes and rays: obvhs's own traversals
//! (its eight-wide compressed `CwBvh` and its `Bvh2`, both with obvhs's
//! `f32` Möller–Trumbore test, as its README and examples use them) and
//! parry3d-f64's `TriMesh` ray cast. Each answers a closest hit as `(triangle,
//! t)` with `t` along the ray's own direction, and a shadow ray as
//! blocked or not, for `t` in `[tmin, tmax]` (obvhs, in `f32`) or `[0,
//! tmax]` (parry3d, in `f64`).

use glam::DVec3;
use obvhs::BvhBuildParams;
use obvhs::bvh2::Bvh2;
use obvhs::bvh2::builder::build_bvh2_from_tris;
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::builder::build_cwbvh_from_tris;
use obvhs::ray::{Ray as ORay, RayHit};
use obvhs::triangle::Triangle as OTriangle;
use parry3d_f64::math::Vector as PVector;
use parry3d_f64::query::{Ray as PRay, RayCast as _};
use parry3d_f64::shape::TriMesh;
use std::mem::size_of;
use std::time::Duration;

/// obvhs's structures over one mesh, in `f32` (each coordinate rounded
/// once), built with its `medium_build` preset.
pub struct ObvhsScene {
    triangles: Vec<OTriangle>,
    cw: CwBvh,
    bvh2: Bvh2,
}

fn f32x3(p: DVec3) -> glam::Vec3A {
    glam::Vec3A::new(p.x as f32, p.y as f32, p.z as f32)
}

impl ObvhsScene {
    /// Both hierarchies over the mesh.
    pub fn new(vertices: &[DVec3], triangles: &[[u32; 3]]) -> ObvhsScene {
        let triangles: Vec<OTriangle> = triangles
            .iter()
            .map(|t| {
                let [v0, v1, v2] = t.map(|i| f32x3(vertices[i as usize]));
                OTriangle { v0, v1, v2 }
            })
            .collect();
        let params = BvhBuildParams::medium_build();
        let cw = build_cwbvh_from_tris(&triangles, params, &mut Duration::default());
        let bvh2 = build_bvh2_from_tris(&triangles, params, &mut Duration::default());
        ObvhsScene {
            triangles,
            cw,
            bvh2,
        }
    }

    fn ray(o: DVec3, d: DVec3, tmin: f64, tmax: f64) -> ORay {
        ORay::new(f32x3(o), f32x3(d), tmin as f32, tmax as f32)
    }

    /// The closest hit by the `CwBvh` traversal.
    #[inline]
    pub fn closest_cw(&self, o: DVec3, d: DVec3, tmin: f64, tmax: f64) -> Option<(u32, f64)> {
        let mut hit = RayHit::none();
        let found = self
            .cw
            .ray_traverse(Self::ray(o, d, tmin, tmax), &mut hit, |ray, id| {
                self.triangles[self.cw.primitive_indices[id] as usize].intersect(ray)
            });
        found.then(|| {
            (
                self.cw.primitive_indices[hit.primitive_id as usize],
                hit.t as f64,
            )
        })
    }

    /// The closest hit by the `Bvh2` traversal.
    #[inline]
    pub fn closest_bvh2(&self, o: DVec3, d: DVec3, tmin: f64, tmax: f64) -> Option<(u32, f64)> {
        let mut hit = RayHit::none();
        let found = self
            .bvh2
            .ray_traverse(Self::ray(o, d, tmin, tmax), &mut hit, |ray, id| {
                self.triangles[self.bvh2.primitive_indices[id] as usize].intersect(ray)
            });
        found.then(|| {
            (
                self.bvh2.primitive_indices[hit.primitive_id as usize],
                hit.t as f64,
            )
        })
    }

    /// Whether the `CwBvh` traversal finds any hit (stopping at the first).
    #[inline]
    pub fn occluded_cw(&self, o: DVec3, d: DVec3, tmin: f64, tmax: f64) -> bool {
        !self
            .cw
            .ray_traverse_miss(Self::ray(o, d, tmin, tmax), |ray, id| {
                self.triangles[self.cw.primitive_indices[id] as usize].intersect(ray)
            })
    }

    /// Whether the `Bvh2` traversal finds any hit (stopping at the first).
    #[inline]
    pub fn occluded_bvh2(&self, o: DVec3, d: DVec3, tmin: f64, tmax: f64) -> bool {
        !self
            .bvh2
            .ray_traverse_miss(Self::ray(o, d, tmin, tmax), |ray, id| {
                self.triangles[self.bvh2.primitive_indices[id] as usize].intersect(ray)
            })
    }

    /// Bytes per triangle beside the mesh's own data: `(CwBvh, Bvh2)`,
    /// each with its nodes, its primitive indices and the `f32` triangles
    /// its test reads (obvhs keeps no index buffer).
    pub fn bytes_per_triangle(&self) -> (f64, f64) {
        let n = self.triangles.len().max(1) as f64;
        let tris = self.triangles.len() * size_of::<OTriangle>();
        let cw = self.cw.nodes.len() * size_of::<obvhs::cwbvh::node::CwBvhNode>()
            + self.cw.primitive_indices.len() * 4
            + tris;
        let b2 = self.bvh2.nodes.len() * size_of::<obvhs::bvh2::node::Bvh2Node>()
            + self.bvh2.primitive_indices.len() * 4
            + tris;
        (cw as f64 / n, b2 as f64 / n)
    }
}

/// parry3d-f64's `TriMesh` over one mesh.
pub struct ParryScene {
    mesh: TriMesh,
}

fn pvec(p: DVec3) -> PVector {
    PVector::new(p.x, p.y, p.z)
}

impl ParryScene {
    /// The `TriMesh`, or `None` where parry refuses the mesh.
    pub fn new(vertices: &[DVec3], triangles: &[[u32; 3]]) -> Option<ParryScene> {
        let vertices = vertices.iter().map(|&p| pvec(p)).collect();
        TriMesh::new(vertices, triangles.to_vec())
            .ok()
            .map(|mesh| ParryScene { mesh })
    }

    /// The closest hit (not solid: a ray starting inside a closed mesh hits
    /// its wall, as the others do).
    #[inline]
    pub fn closest(&self, o: DVec3, d: DVec3, tmax: f64) -> Option<(u32, f64)> {
        let ray = PRay::new(pvec(o), pvec(d));
        self.mesh
            .cast_local_ray_and_get_normal(&ray, tmax, false)
            .map(|hit| (hit.subshape, hit.time_of_impact))
    }

    /// Whether the ray meets the mesh.
    #[inline]
    pub fn occluded(&self, o: DVec3, d: DVec3, tmax: f64) -> bool {
        let ray = PRay::new(pvec(o), pvec(d));
        self.mesh.intersects_local_ray(&ray, tmax)
    }

    /// Bytes per triangle: vertices, indices and the hierarchy's nodes
    /// (two per wide node, one wide node per leaf pair).
    pub fn bytes_per_triangle(&self) -> f64 {
        let n = self.mesh.indices().len().max(1);
        let nodes =
            self.mesh.bvh().leaf_count() as usize * size_of::<parry3d_f64::partitioning::BvhNode>();
        let bytes = std::mem::size_of_val(self.mesh.vertices()) + n * 12 + nodes;
        bytes as f64 / n as f64
    }
}
