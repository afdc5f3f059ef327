//! Embree 3 (`libembree3`, through the `embree` crate) on exactray's meshes:
//! its default BVH and its own `f32` ray–triangle test, one ray at a time
//! (`rtcIntersect1` / `rtcOccluded1`), as a renderer calls it. Behind the
//! `embree` feature, which needs Debian's `libembree-dev`.
//!
//! The device and scene are leaked once per mesh, so the committed scene
//! can be `'static` (the crate's `CommittedScene` borrows both) and sit in
//! the report's shared setups: a few megabytes per mesh, report-only.

use embree::{Device, Geometry, IntersectContext, Ray, RayHit, Scene, TriangleMesh};
use glam::DVec3;

/// An Embree scene of one triangle mesh, coordinates rounded to `f32`.
pub struct EmbreeScene {
    scene: embree::CommittedScene<'static>,
}

fn v3(p: DVec3) -> cgmath::Vector3<f32> {
    cgmath::Vector3::new(p.x as f32, p.y as f32, p.z as f32)
}

impl EmbreeScene {
    /// The scene over the mesh (indices must be in range, as exactray's
    /// meshes guarantee).
    pub fn new(vertices: &[DVec3], triangles: &[[u32; 3]]) -> EmbreeScene {
        let device: &'static Device = Box::leak(Box::new(Device::new()));
        let mut mesh = TriangleMesh::unanimated(device, triangles.len(), vertices.len());
        {
            let mut v = mesh.vertex_buffer.map();
            for (k, p) in vertices.iter().enumerate() {
                v[k] = cgmath::Vector4::new(p.x as f32, p.y as f32, p.z as f32, 0.0);
            }
            let mut i = mesh.index_buffer.map();
            for (k, t) in triangles.iter().enumerate() {
                i[k] = cgmath::Vector3::new(t[0], t[1], t[2]);
            }
        }
        let mut geometry = Geometry::Triangle(mesh);
        geometry.commit();
        let mut scene = Scene::new(device);
        scene.attach_geometry(geometry);
        let scene: &'static Scene<'static> = Box::leak(Box::new(scene));
        EmbreeScene {
            scene: scene.commit(),
        }
    }

    /// The closest hit for `t` in `[tmin, tmax]`: the triangle and `t`.
    #[inline]
    pub fn closest(&self, o: DVec3, d: DVec3, tmin: f64, tmax: f64) -> Option<(u32, f64)> {
        let mut ctx = IntersectContext::coherent();
        let mut hit = RayHit::new(Ray::segment(v3(o), v3(d), tmin as f32, tmax as f32));
        self.scene.intersect(&mut ctx, &mut hit);
        hit.hit
            .hit()
            .then_some((hit.hit.primID, hit.ray.tfar as f64))
    }

    /// Whether the ray meets the mesh for `t` in `[tmin, tmax]`.
    #[inline]
    pub fn occluded(&self, o: DVec3, d: DVec3, tmin: f64, tmax: f64) -> bool {
        let mut ctx = IntersectContext::coherent();
        let mut ray = Ray::segment(v3(o), v3(d), tmin as f32, tmax as f32);
        self.scene.occluded(&mut ctx, &mut ray);
        // Embree marks an occluded ray by setting its `tfar` to -inf.
        ray.tfar == f32::NEG_INFINITY
    }
}
