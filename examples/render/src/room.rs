//! The scene: a Cornell-box-like room built in code (nothing is
//! downloaded), its materials by primitive id, its lights and camera.
//!
//! The room spans `x` in `[-1, 1]`, `y` (up) in `[0, 2]` and `z` in `[-1,
//! 1]`, open towards `+z` where the camera stands. Its walls are triangle
//! meshes (white floor, ceiling and back wall, red left wall, green right
//! wall); inside stand a mirror sphere (analytic), a matte capped cylinder
//! (analytic) and a coarse tessellated sphere with smooth vertex normals
//! and a mirror finish: the Q3 object. A small square light under
//! the ceiling is the path tracer's emitter; the ray tracer lights the room
//! with a point light just below it.

use crate::camera::Camera;
use exactray::scene::{PrimitiveId, Scene, SceneBuilder, TriangleMesh};
use exactray::shape::{CappedCylinder, Sphere};
use exactray::testing::{SceneMesh, uv_sphere};
use glam::DVec3;
use std::f64::consts::PI;

/// How a surface scatters light (with its [`Material::emission`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Surface {
    /// Lambertian, of this albedo per channel.
    Matte(DVec3),
    /// A perfect mirror, reflecting this share per channel.
    Mirror(DVec3),
}

/// A primitive's material: how it scatters, and what it emits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// The scattering.
    pub surface: Surface,
    /// Emitted radiance, the same in every direction of the front side.
    pub emission: DVec3,
}

impl Material {
    /// A matte material that emits nothing.
    pub const fn matte(albedo: DVec3) -> Material {
        Material {
            surface: Surface::Matte(albedo),
            emission: DVec3::ZERO,
        }
    }

    /// A mirror that emits nothing.
    pub const fn mirror(tint: DVec3) -> Material {
        Material {
            surface: Surface::Mirror(tint),
            emission: DVec3::ZERO,
        }
    }
}

/// A parallelogram light `corner + a s + b t` (`s`, `t` in `[0, 1]`),
/// emitting `radiance` on the side of `a x b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLight {
    /// The primitive that is the light's surface.
    pub primitive: PrimitiveId,
    /// One corner.
    pub corner: DVec3,
    /// The first edge from the corner.
    pub a: DVec3,
    /// The second edge from the corner.
    pub b: DVec3,
    /// The emitted radiance.
    pub radiance: DVec3,
}

impl AreaLight {
    /// The area.
    pub fn area(&self) -> f64 {
        self.a.cross(self.b).length()
    }

    /// The unit normal of the emitting side.
    pub fn normal(&self) -> DVec3 {
        self.a.cross(self.b).normalize_or_zero()
    }

    /// The point at `(s, t)` of the unit square.
    pub fn point(&self, s: f64, t: f64) -> DVec3 {
        self.corner + self.a * s + self.b * t
    }
}

/// A point light: `intensity` per steradian, from `position`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// Where it is.
    pub position: DVec3,
    /// Radiant intensity per channel.
    pub intensity: DVec3,
}

/// Triangles to rasterize for one primitive: a mesh's own, or a
/// tessellation of an analytic shape (for the Z-buffer's picture only; the
/// ray-traced scene keeps the shape analytic).
#[derive(Clone, Debug)]
pub struct RasterMesh {
    /// The primitive these triangles show.
    pub primitive: PrimitiveId,
    /// Vertices.
    pub vertices: Vec<DVec3>,
    /// Triangles, as indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
    /// Unit vertex normals, where the surface is smooth.
    pub normals: Option<Vec<DVec3>>,
}

impl RasterMesh {
    fn of(primitive: PrimitiveId, mesh: &TriangleMesh) -> RasterMesh {
        RasterMesh {
            primitive,
            vertices: mesh.vertices().to_vec(),
            triangles: mesh.triangles().to_vec(),
            normals: mesh.normals().map(<[DVec3]>::to_vec),
        }
    }
}

/// The room: the scene to trace, the materials by primitive, the lights.
#[derive(Clone, Debug)]
pub struct Room {
    /// Everything, the light's surface included.
    pub scene: Scene,
    /// Everything but the area light's surface: the scene shadow rays
    /// towards a point sampled on the light are tested against (a convex
    /// planar light cannot shadow itself, and a point sampled on it lies
    /// within rounding of it, where a test against it could not tell).
    pub occluders: Scene,
    /// `materials[id.index()]` is primitive `id`'s.
    pub materials: Vec<Material>,
    /// The path tracer's light.
    pub area_light: Option<AreaLight>,
    /// The ray tracer's light.
    pub point_light: PointLight,
    /// The coarse smooth-shaded mirror sphere (Q3).
    pub smooth_sphere: PrimitiveId,
    /// What the Z-buffer draws, one entry per primitive it can draw.
    pub raster: Vec<RasterMesh>,
    /// The camera the pictures are taken with (at its default size).
    pub camera: Camera,
    /// The radiance of every direction that leaves the room (through its
    /// open side).
    pub environment: DVec3,
}

impl Room {
    /// The material of primitive `id` (black matte for an unknown id).
    pub fn material(&self, id: PrimitiveId) -> Material {
        self.materials
            .get(id.index())
            .copied()
            .unwrap_or(Material::matte(DVec3::ZERO))
    }
}

/// A quad `a b c d` (counter-clockwise seen from the side its normal
/// faces) as a two-triangle mesh.
fn quad(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> TriangleMesh {
    TriangleMesh::new(&[a, b, c, d], &[[0, 1, 2], [0, 2, 3]]).expect("finite quad")
}

/// A capped cylinder's tessellation, for the Z-buffer's picture.
fn cylinder_mesh(
    base: DVec3,
    height: f64,
    radius: f64,
    segments: u32,
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut vertices = vec![base, base + DVec3::Y * height];
    for j in 0..segments {
        let phi = 2.0 * PI * j as f64 / segments as f64;
        let r = DVec3::new(phi.cos(), 0.0, -phi.sin()) * radius;
        vertices.push(base + r);
        vertices.push(base + r + DVec3::Y * height);
    }
    let mut triangles = Vec::new();
    for j in 0..segments {
        let (b0, t0) = (2 + 2 * j, 3 + 2 * j);
        let (b1, t1) = (2 + 2 * ((j + 1) % segments), 3 + 2 * ((j + 1) % segments));
        triangles.extend([[b0, b1, t1], [b0, t1, t0], [0, b1, b0], [1, t0, t1]]);
    }
    (vertices, triangles)
}

const WHITE: DVec3 = DVec3::new(0.73, 0.73, 0.73);
const RED: DVec3 = DVec3::new(0.65, 0.05, 0.05);
const GREEN: DVec3 = DVec3::new(0.12, 0.45, 0.15);

/// The room with its default camera of `width` x `height` pixels.
pub fn cornell_room(width: u32, height: u32) -> Room {
    let v = DVec3::new;
    let mut builder = SceneBuilder::new();
    let mut occluders = SceneBuilder::new();
    let mut materials = Vec::new();
    let mut raster = Vec::new();
    let mut add_mesh = |builder: &mut SceneBuilder, mesh: TriangleMesh, material: Material| {
        let id = builder
            .add(mesh.clone())
            .expect("fewer than 2^31 primitives");
        raster.push(RasterMesh::of(id, &mesh));
        materials.push(material);
        id
    };
    let walls = [
        (
            quad(
                v(-1., 0., 1.),
                v(1., 0., 1.),
                v(1., 0., -1.),
                v(-1., 0., -1.),
            ),
            WHITE,
        ),
        (
            quad(
                v(-1., 2., -1.),
                v(1., 2., -1.),
                v(1., 2., 1.),
                v(-1., 2., 1.),
            ),
            WHITE,
        ),
        (
            quad(
                v(-1., 0., -1.),
                v(1., 0., -1.),
                v(1., 2., -1.),
                v(-1., 2., -1.),
            ),
            WHITE,
        ),
        (
            quad(
                v(-1., 0., 1.),
                v(-1., 0., -1.),
                v(-1., 2., -1.),
                v(-1., 2., 1.),
            ),
            RED,
        ),
        (
            quad(v(1., 0., -1.), v(1., 0., 1.), v(1., 2., 1.), v(1., 2., -1.)),
            GREEN,
        ),
    ];
    for (mesh, colour) in walls {
        occluders.add(mesh.clone()).expect("few primitives");
        add_mesh(&mut builder, mesh, Material::matte(colour));
    }
    let (ui, uj) = ((1.0 - 0.06) * 2.0, 0.25);
    let light_quad = quad(
        v(-uj, ui, -uj),
        v(-uj, ui, uj),
        v(uj, ui, uj),
        v(uj, ui, -uj),
    );
    let light_material = Material {
        surface: Surface::Matte(DVec3::splat(0.78)),
        emission: DVec3::splat(17.0),
    };
    let light_id = add_mesh(&mut builder, light_quad, light_material);
    let SceneMesh {
        vertices,
        triangles,
        normals,
    } = uv_sphere(v(0.42, 0.36, 0.38), 0.34, 4, 7);
    let smooth = TriangleMesh::new(&vertices, &triangles)
        .and_then(|m| m.with_normals(&normals))
        .expect("finite sphere");
    occluders.add(smooth.clone()).expect("few primitives");
    let smooth_sphere = add_mesh(&mut builder, smooth, Material::mirror(DVec3::splat(0.9)));

    let (centre, radius) = (v(-0.42, 0.42, -0.35), 0.42);
    let sphere = Sphere::new(centre, radius).expect("valid sphere");
    let sphere_id = builder.add(sphere).expect("few primitives");
    occluders.add(sphere).expect("few primitives");
    materials.push(Material::mirror(DVec3::splat(0.95)));
    let SceneMesh {
        vertices,
        triangles,
        normals,
    } = uv_sphere(centre, radius, 24, 48);
    raster.push(RasterMesh {
        primitive: sphere_id,
        vertices,
        triangles,
        normals: Some(normals),
    });

    let (base, tall, r) = (v(0.45, 0.0, -0.45), 0.95, 0.26);
    let cylinder = CappedCylinder::new(base, DVec3::Y * tall, r).expect("valid cylinder");
    let cylinder_id = builder.add(cylinder).expect("few primitives");
    occluders.add(cylinder).expect("few primitives");
    materials.push(Material::matte(DVec3::new(0.55, 0.6, 0.75)));
    let (vertices, triangles) = cylinder_mesh(base, tall, r, 48);
    raster.push(RasterMesh {
        primitive: cylinder_id,
        vertices,
        triangles,
        normals: None,
    });

    let camera = Camera::new(
        v(0.0, 1.0, 3.9),
        v(0.0, 1.0, 0.0),
        DVec3::Y,
        38.0,
        width,
        height,
    )
    .expect("valid camera");
    Room {
        scene: builder.build(),
        occluders: occluders.build(),
        materials,
        area_light: Some(AreaLight {
            primitive: light_id,
            corner: v(-uj, ui, -uj),
            // x cross z is -y: the light shines down.
            a: v(2.0 * uj, 0.0, 0.0),
            b: v(0.0, 0.0, 2.0 * uj),
            radiance: light_material.emission,
        }),
        point_light: PointLight {
            // The light's centre: the point light the ray tracer sees
            // where the path tracer sees the square.
            position: v(0.0, ui, 0.0),
            intensity: DVec3::splat(3.0),
        },
        smooth_sphere,
        raster,
        camera,
        environment: DVec3::new(0.05, 0.06, 0.08),
    }
}

/// A closed box of matte walls of albedo `albedo`, every wall emitting
/// radiance 1, the camera inside: the furnace whose radiance is `1 / (1 -
/// albedo)` everywhere (the rendering equation's solution for uniform
/// emission `E` and albedo `a`: `L = E + a L`).
pub fn furnace(albedo: f64, width: u32, height: u32) -> Room {
    let v = DVec3::new;
    let material = Material {
        surface: Surface::Matte(DVec3::splat(albedo)),
        emission: DVec3::ONE,
    };
    let faces = [
        quad(
            v(-1., -1., 1.),
            v(1., -1., 1.),
            v(1., -1., -1.),
            v(-1., -1., -1.),
        ),
        quad(
            v(-1., 1., -1.),
            v(1., 1., -1.),
            v(1., 1., 1.),
            v(-1., 1., 1.),
        ),
        quad(
            v(-1., -1., -1.),
            v(1., -1., -1.),
            v(1., 1., -1.),
            v(-1., 1., -1.),
        ),
        quad(
            v(1., -1., 1.),
            v(-1., -1., 1.),
            v(-1., 1., 1.),
            v(1., 1., 1.),
        ),
        quad(
            v(-1., -1., 1.),
            v(-1., -1., -1.),
            v(-1., 1., -1.),
            v(-1., 1., 1.),
        ),
        quad(
            v(1., -1., -1.),
            v(1., -1., 1.),
            v(1., 1., 1.),
            v(1., 1., -1.),
        ),
    ];
    let mut builder = SceneBuilder::new();
    let mut raster = Vec::new();
    for mesh in faces {
        let id = builder.add(mesh.clone()).expect("few primitives");
        raster.push(RasterMesh::of(id, &mesh));
    }
    let scene = builder.build();
    let camera = Camera::new(
        v(0.1, 0.2, 0.5),
        v(0.0, 0.0, -1.0),
        DVec3::Y,
        60.0,
        width,
        height,
    )
    .expect("valid camera");
    Room {
        occluders: scene.clone(),
        scene,
        materials: vec![material; 6],
        area_light: None,
        point_light: PointLight {
            position: DVec3::ZERO,
            intensity: DVec3::ZERO,
        },
        smooth_sphere: PrimitiveId(u32::MAX),
        raster,
        camera,
        environment: DVec3::ZERO,
    }
}
