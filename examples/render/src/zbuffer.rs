//! The Z-buffer rasterizer: every triangle taken to clip space, clipped
//! against the frustum before the perspective divide (Q6), rasterized
//! with exact coverage and the top-left rule, the nearest fragment kept per
//! pixel. Shading is local (Lambert under the point light, mirrors drawn
//! grey): a rasterizer alone has no shadows and no reflections, which is
//! what the ray tracer adds (Q2, Q5).

use crate::camera::Camera;
use crate::image::Image;
use crate::room::{RasterMesh, Room, Surface};
use exactray::raster::{ClipPlanes, Fragment, rasterize_clip_space, rasterize_triangle, to_screen};
use exactray::scene::PrimitiveId;
use glam::{DVec3, DVec4};

/// Whether triangles are clipped before the perspective divide.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Clipping {
    /// Against the six frustum planes, in clip space (the right way).
    Frustum,
    /// Not at all: every vertex divided by its `w`, even a negative one
    /// behind the eye, the 2D triangle rasterized, depth interpolated on
    /// screen and fragments outside depth `[0, 1]` dropped. The Q6
    /// failure: a triangle reaching behind the eye is drawn inverted, at
    /// depths that look visible.
    None,
}

/// The nearest surface found at a pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Visible {
    /// The primitive.
    pub primitive: PrimitiveId,
    /// Which entry of [`Room::raster`] it was drawn from.
    pub mesh: u32,
    /// The triangle within it.
    pub triangle: u32,
    /// Its fragment: depth and perspective-correct barycentric weights.
    pub fragment: Fragment,
}

/// A frame's visibility: the nearest surface per pixel, rows top to bottom.
#[derive(Clone, Debug)]
pub struct Visibility {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `None` where nothing covers the pixel.
    pub pixels: Vec<Option<Visible>>,
    /// Fragments the rasterizer produced (before the depth test).
    pub fragments: u64,
}

/// The nearest fragment per pixel of `meshes` through `camera`. A fragment
/// replaces the stored one only when strictly nearer, so among equal
/// depths the first drawn stays (the tie rule: drawing order, which is
/// `meshes` order, then triangle order).
pub fn visibility(meshes: &[RasterMesh], camera: &Camera) -> Visibility {
    visibility_with(meshes, camera, Clipping::Frustum)
}

/// [`visibility`] with the given [`Clipping`].
pub fn visibility_with(meshes: &[RasterMesh], camera: &Camera, clipping: Clipping) -> Visibility {
    let (w, h) = (camera.width(), camera.height());
    let m = camera.clip_from_world();
    let mut pixels: Vec<Option<Visible>> = vec![None; w as usize * h as usize];
    let mut fragments = 0;
    for (mi, mesh) in meshes.iter().enumerate() {
        let clip: Vec<_> = mesh.vertices.iter().map(|v| m * v.extend(1.0)).collect();
        for (ti, t) in mesh.triangles.iter().enumerate() {
            let at = |i: u32| clip.get(i as usize).copied();
            let (Some(a), Some(b), Some(c)) = (at(t[0]), at(t[1]), at(t[2])) else {
                continue;
            };
            let keep = |f: Fragment| {
                let slot = &mut pixels[(f.y * w + f.x) as usize];
                if slot.is_none_or(|s| f.depth < s.fragment.depth) {
                    *slot = Some(Visible {
                        primitive: mesh.primitive,
                        mesh: mi as u32,
                        triangle: ti as u32,
                        fragment: f,
                    });
                }
            };
            // A non-finite clip-space vertex (from a non-finite matrix) is
            // skipped: the error leaves this triangle out, nothing else.
            fragments += match clipping {
                Clipping::Frustum => {
                    rasterize_clip_space(a, b, c, ClipPlanes::Frustum, w, h, keep).unwrap_or(0)
                }
                Clipping::None => divided_without_clipping([a, b, c], w, h, keep),
            };
        }
    }
    Visibility {
        width: w,
        height: h,
        pixels,
        fragments,
    }
}

/// The Q6 failure: rasterizes the triangle of clip-space vertices `v` by
/// dividing each by its `w` (a vertex behind the eye has `w < 0`, and lands
/// mirrored through the image centre), interpolating depth linearly on
/// screen and weights without perspective correction, and keeping the
/// fragments with depth in `[0, 1]`, as a depth range test would.
fn divided_without_clipping(v: [DVec4; 3], w: u32, h: u32, mut keep: impl FnMut(Fragment)) -> u64 {
    if v.iter().any(|p| p.w == 0.0) {
        return 0;
    }
    let s = v.map(|p| to_screen(p, w, h));
    let mut kept = 0;
    let _ = rasterize_triangle(
        s[0].truncate(),
        s[1].truncate(),
        s[2].truncate(),
        w,
        h,
        |y, x0, x1| {
            for x in x0..x1 {
                let c = glam::DVec2::new(x as f64 + 0.5, y as f64 + 0.5);
                let a = s.map(|p| p.truncate() - c);
                let e = [
                    a[1].perp_dot(a[2]),
                    a[2].perp_dot(a[0]),
                    a[0].perp_dot(a[1]),
                ];
                let sum = e[0] + e[1] + e[2];
                let l = e.map(|e| e / sum);
                let depth = l[0] * s[0].z + l[1] * s[1].z + l[2] * s[2].z;
                if (0.0..=1.0).contains(&depth) {
                    kept += 1;
                    keep(Fragment {
                        x,
                        y,
                        depth,
                        weights: DVec3::from(l),
                    });
                }
            }
        },
    );
    kept
}

/// The world point and unit normal of a visible surface, interpolated
/// with its perspective-correct weights.
fn surface_point(mesh: &RasterMesh, v: &Visible) -> (DVec3, DVec3) {
    let t = mesh.triangles[v.triangle as usize].map(|i| i as usize);
    let w = v.fragment.weights;
    let [a, b, c] = t.map(|i| mesh.vertices[i]);
    let p = a * w.x + b * w.y + c * w.z;
    let n = match &mesh.normals {
        Some(n) => (n[t[0]] * w.x + n[t[1]] * w.y + n[t[2]] * w.z).normalize_or_zero(),
        None => (b - a).cross(c - a).normalize_or_zero(),
    };
    (p, n)
}

/// The rasterized picture of `room` at `width` x `height`: Lambert under
/// the point light with no shadows, the same ambient term as the ray
/// tracer's, mirrors grey.
pub fn render(room: &Room, width: u32, height: u32) -> (Image, Visibility) {
    render_from(
        room,
        &room.camera.with_size(width, height),
        Clipping::Frustum,
    )
}

/// [`render`] through `camera`, with the given [`Clipping`].
pub fn render_from(room: &Room, camera: &Camera, clipping: Clipping) -> (Image, Visibility) {
    let (width, height) = (camera.width(), camera.height());
    let vis = visibility_with(&room.raster, camera, clipping);
    let eye = camera.eye();
    let pixels = vis
        .pixels
        .iter()
        .map(|v| {
            let Some(v) = v else { return DVec3::ZERO };
            let mesh = &room.raster[v.mesh as usize];
            let (p, mut n) = surface_point(mesh, v);
            if n.dot(eye - p) < 0.0 {
                n = -n;
            }
            let material = room.material(v.primitive);
            let albedo = match material.surface {
                Surface::Matte(a) => a,
                Surface::Mirror(_) => DVec3::splat(0.35),
            };
            let light = room.point_light;
            let to = light.position - p;
            let cos = n.dot(to.normalize_or_zero()).max(0.0);
            albedo
                * (DVec3::splat(0.03)
                    + material.emission
                    + light.intensity * cos / to.length_squared())
        })
        .collect();
    (Image::from_pixels(width, height, pixels), vis)
}
