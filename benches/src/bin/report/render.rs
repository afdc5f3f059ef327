//! render (question Q2 at frame scale): one frame's primary
//! visibility, by the Z-buffer rasterizer (`exactray-raster`: every
//! triangle clipped in homogeneous coordinates against the frustum,
//! rasterized with exact coverage and the top-left rule, the nearest
//! fragment kept) and by one ray per pixel centre through the mesh's BVH
//! (`exactray-rays`: `TriangleMesh::closest_hit`, the default watertight
//! test). Both on one core, both from `exactray-render`.
//!
//! Inputs `WxH:N`: a displaced sphere of `N` triangles (`exactray::testing`)
//! filling most of a `W` x `H` frame, seen by a camera outside it.
//! `ns_per_op` is ns per frame (building the BVH is not timed; clipping
//! and projecting every triangle is). `errors`: pixels whose visible
//! triangle differs from the other method's (each triangle counts as its
//! own primitive here; the two renderers differ only where a pixel centre
//! lies within the projection's rounding of an edge: see
//! `examples/render/tests/visibility.rs`). `cases`: pixels.

use crate::framework::{Config, Row, method, note, time_methods};
use exactray::interval::Interval;
use exactray::scene::{PrimitiveId, TriangleMesh};
use exactray::testing::{SceneMesh, SplitMix64, displaced_sphere};
use exactray_render::camera::Camera;
use exactray_render::room::RasterMesh;
use exactray_render::zbuffer::visibility;
use glam::DVec3;
use std::sync::Arc;

/// One frame to draw both ways.
struct Frame {
    mesh: TriangleMesh,
    raster: [RasterMesh; 1],
    camera: Camera,
}

impl Frame {
    fn new(data: &SceneMesh, width: u32, height: u32) -> Frame {
        let (lo, hi) = data.bounds();
        let centre = (lo + hi) * 0.5;
        let size = (hi - lo).max_element();
        let eye = centre + DVec3::new(0.3, 0.5, 2.2) * size;
        let camera = Camera::new(eye, centre, DVec3::Y, 30.0, width, height).expect("valid camera");
        Frame {
            mesh: TriangleMesh::new(&data.vertices, &data.triangles).expect("finite mesh"),
            raster: [RasterMesh {
                primitive: PrimitiveId(0),
                vertices: data.vertices.clone(),
                triangles: data.triangles.clone(),
                normals: None,
            }],
            camera,
        }
    }

    /// The visible triangle per pixel, by the rasterizer.
    fn rasterized(&self) -> Vec<Option<u32>> {
        visibility(&self.raster, &self.camera)
            .pixels
            .iter()
            .map(|v| v.map(|v| v.triangle))
            .collect()
    }

    /// The visible triangle per pixel, by rays.
    fn traced(&self) -> Vec<Option<u32>> {
        let (w, h) = (self.camera.width(), self.camera.height());
        (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .map(|(i, j)| {
                let ray = self.camera.pixel_ray(i, j);
                self.mesh
                    .closest_hit(&ray, Interval::FORWARD)
                    .map(|h| h.triangle)
            })
            .collect()
    }
}

pub fn run(cfg: &Config) -> Vec<Row> {
    let sizes: &[usize] = if cfg.quick {
        &[1_000, 100_000]
    } else {
        &[1_000, 10_000, 100_000, 1_000_000]
    };
    let resolutions: &[(u32, u32)] = if cfg.quick {
        &[(160, 120)]
    } else {
        &[(160, 120), (640, 480), (1280, 960)]
    };
    let mut rows = Vec::new();
    let mut per = Vec::new();
    for &n in sizes {
        let data = displaced_sphere(&mut SplitMix64::for_inputs("render", &n.to_string()), n);
        for &(w, h) in resolutions {
            let frame = Arc::new(Frame::new(&data, w, h));
            let (a, b) = (frame.rasterized(), frame.traced());
            let differ = a.iter().zip(&b).filter(|(x, y)| x != y).count() as u64;
            let methods = [
                method("exactray-raster", |f: &Arc<Frame>| f.rasterized().len()),
                method("exactray-rays", |f: &Arc<Frame>| f.traced().len()),
            ];
            let ns = time_methods(cfg, std::slice::from_ref(&frame), &methods);
            let inputs = format!("{w}x{h}:{}", data.triangles.len());
            let pixels = (w * h) as f64;
            per.push(format!(
                "| {inputs} | {:.2} | {:.2} | {:.1} | {:.1} | {:.2}x |",
                ns[0] / 1e6,
                ns[1] / 1e6,
                ns[0] / data.triangles.len() as f64,
                ns[1] / pixels,
                ns[1] / ns[0]
            ));
            for (m, ns) in methods.iter().zip(ns) {
                rows.push(Row {
                    family: "render",
                    method: m.name().to_string(),
                    inputs: inputs.clone(),
                    ns_per_op: ns,
                    cases: pixels as u64,
                    errors: differ,
                    max_ulps: None,
                    max_bound_ulps: None,
                });
            }
        }
    }
    note(
        "render",
        format!(
            "**render**: one frame of primary visibility, one core each. Per frame, per triangle (raster) and per \
             pixel (rays), and the rays' time over the rasterizer's:\n\n\
             | inputs | raster ms | rays ms | raster ns/triangle | rays ns/pixel | rays / raster |\n|---|---|---|---|---|---|\n{}",
            per.join("\n")
        ),
    );
    rows
}
