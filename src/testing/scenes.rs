//! Deterministic small scenes and rays for them (with `alloc`): a mix of
//! every analytic shape and small closed meshes with vertex normals, at a
//! chosen scale and offset ([`random_scene`]); rays aimed at the
//! primitives from outside or starting inside them ([`scene_ray`]); and
//! secondary rays spawned from a hit ([`spawned_ray`]). The proptest
//! strategies over them are `small_scenes` and `spawned_rays`.
//!
//! ```
//! use exactray::prelude::*;
//! use exactray::testing::{SplitMix64, random_scene, scene_ray};
//! use glam::DVec3;
//! let mut rng = SplitMix64::new(5);
//! let scene = random_scene(&mut rng, 6, 1e-3, DVec3::new(1e8, 0.0, 0.0));
//! let ray = scene_ray(&mut rng, &scene).unwrap();
//! let _ = scene.closest_hit(&ray, Interval::FORWARD);
//! ```

use super::generators::SplitMix64;
use super::rays::{point, point_in_triangle, uniform, unit_vector};
use crate::arith::std_or_libm::{powf, sqrt};
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::scene::{
    AnalyticShape, Primitive, Scene, SceneBuilder, SceneHit, TriangleMesh, spawn_ray,
};
use crate::shape::{Aabb, Bounded, CappedCylinder, Cone, Cylinder, Disk, Plane, Quadric, Sphere};
use alloc::vec::Vec;
use glam::DVec3;

/// `2^k` for `-1022 <= k <= 1023`.
const fn pow2(k: i32) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// Scales and offsets `(scale, offset)` for [`random_scene`] (the offset
/// along `(1, -0.7, 0.4)`): unit, tiny and huge scenes at the origin, from
/// `2^-1000` to `2^1000`, and scenes `10^6` to `10^8` (or `2^20`) times
/// their size from it, at unit, `1e-3`, `2^±600` and `2^±980` sizes.
pub const SCENE_PLACES: [(f64, f64); 21] = [
    (1.0, 0.0),
    (1e-30, 0.0),
    (1e-40, 0.0),
    (1e30, 0.0),
    (1e40, 0.0),
    (1e-100, 0.0),
    (1e100, 0.0),
    (1e-200, 0.0),
    (1e200, 0.0),
    (pow2(-600), 0.0),
    (pow2(600), 0.0),
    (pow2(-1000), 0.0),
    (pow2(1000), 0.0),
    (1.0, 1e6),
    (1.0, 1e7),
    (1.0, 1e8),
    (1e-3, 1e8),
    (1e-3, 1e6),
    (pow2(-600), pow2(-580)),
    (pow2(600), pow2(620)),
    (pow2(980), pow2(1000)),
];

/// A closed octahedron around `c` of radius `r`, its triangles
/// counterclockwise seen from outside, with the exact unit vertex normals.
fn octahedron(c: DVec3, r: f64) -> Option<TriangleMesh> {
    let mesh = super::meshes::closed_octahedron(c, r);
    TriangleMesh::new(&mesh.vertices, &mesh.triangles)
        .and_then(|m| m.with_normals(&super::meshes::AXIS_DIRECTIONS))
        .ok()
}

/// One primitive around `c` of size about `s`: spheres, capped cylinders
/// and cones, disks and meshes most often; planes, infinite cylinders and
/// cones and paraboloids (the unbounded kinds) one time in four.
fn primitive(rng: &mut SplitMix64, c: DVec3, s: f64) -> Option<Primitive> {
    let axis = unit_vector(rng) * s * uniform(rng, 0.5, 2.0);
    let r = s * uniform(rng, 0.2, 1.0);
    Some(match rng.next_u64() % 16 {
        0..=2 => Sphere::new(c, r).ok()?.into(),
        3 | 4 => CappedCylinder::new(c - axis * 0.5, axis, r).ok()?.into(),
        5 | 6 => Cone::new(c - axis * 0.5, axis, r).ok()?.into(),
        7 | 8 => Disk::new(c, axis, r).ok()?.into(),
        9 | 10 => octahedron(c, r)?.into(),
        11 | 12 => {
            // A soup of three triangles around `c`.
            let v: Vec<DVec3> = (0..9).map(|_| c + unit_vector(rng) * r).collect();
            TriangleMesh::new(&v, &[[0, 1, 2], [3, 4, 5], [6, 7, 8]])
                .ok()?
                .into()
        }
        13 => Plane::new(c, axis).ok()?.into(),
        14 => {
            if rng.next_u64().is_multiple_of(2) {
                Cylinder::new(c, axis, r).ok()?.into()
            } else {
                Cone::infinite(c - axis, axis, r).ok()?.into()
            }
        }
        _ => {
            // The paraboloid (x - cx)^2 + (y - cy)^2 = s (z - cz), through c.
            let k = [
                1.0,
                1.0,
                0.0,
                0.0,
                0.0,
                0.0,
                -2.0 * c.x,
                -2.0 * c.y,
                -s,
                c.x * c.x + c.y * c.y + s * c.z,
            ];
            Quadric::new(k).ok()?.into()
        }
    })
}

/// A scene of `count` primitives (fewer where a constructor refuses one),
/// centred in `offset + scale [-2, 2]^3`, each of size `scale` times 0.2
/// to 2: every kind of [`AnalyticShape`], octahedra with vertex normals
/// and triangle soups. Finite `scale > 0` and `offset` give finite
/// primitives (a non-finite one is refused and left out).
pub fn random_scene(rng: &mut SplitMix64, count: usize, scale: f64, offset: DVec3) -> Scene {
    let mut builder = SceneBuilder::new();
    for _ in 0..count {
        let c = offset + point(rng, 2.0) * scale;
        if let Some(p) = primitive(rng, c, scale)
            && builder.add(p).is_err()
        {
            break;
        }
    }
    builder.build()
}

/// A point of primitive `p` or inside it, from `rng`: a shape's centre
/// (its apex side for a cone), a random point of a random triangle of a
/// mesh; `None` for a mesh without triangles. A ray aimed at it from
/// outside a bounded shape meets the shape.
pub fn target(rng: &mut SplitMix64, p: &Primitive) -> Option<DVec3> {
    Some(match p {
        Primitive::Mesh(mesh) => {
            let n = mesh.triangles().len() as u64;
            let tri = mesh.triangle((rng.next_u64() % n.max(1)) as usize)?;
            point_in_triangle(rng, tri.vertices())
        }
        Primitive::Shape(shape) => match shape {
            AnalyticShape::Sphere(s) => s.center,
            AnalyticShape::Cylinder(s) => s.point,
            AnalyticShape::CappedCylinder(s) => s.side.point + s.side.axis * 0.5,
            AnalyticShape::Cone(s) => s.apex + s.axis * 0.75,
            AnalyticShape::Quadric(q) => quadric_point(q),
            AnalyticShape::Disk(s) => s.plane.point,
            AnalyticShape::Plane(s) => s.point,
        },
    })
}

/// The paraboloid vertex of a [`random_scene`] quadric (`G = -2 c_x`, `H =
/// -2 c_y`, `I = -s`, `J = c_x^2 + c_y^2 + s c_z`); for any other quadric,
/// a point near which it may pass.
fn quadric_point(q: &Quadric) -> DVec3 {
    let [.., g, h, i, j] = q.coefficients();
    let (x, y) = (-g / 2.0, -h / 2.0);
    let z = if i != 0.0 {
        (j - x * x - y * y) / -i
    } else {
        0.0
    };
    DVec3::new(x, y, z)
}

/// The largest extent of `p`'s box (a mesh's vertices'), 0 for an
/// unbounded shape or an empty mesh.
fn size(p: &Primitive) -> f64 {
    let aabb = match p {
        Primitive::Mesh(mesh) => Aabb::of_points(mesh.vertices()),
        Primitive::Shape(shape) => shape.aabb(),
    };
    aabb.map_or(0.0, |b| (b.max() - b.min()).max_element())
}

/// A ray for `scene`: aimed at a random primitive's [`target`] from a
/// random point around it (one to ten times the distance to another
/// target, or the primitive's size), or, one time in four, starting at
/// the target (inside a solid, or on a surface) in a random direction.
/// `None` for an empty scene (or when the direction comes out zero).
pub fn scene_ray(rng: &mut SplitMix64, scene: &Scene) -> Option<Ray> {
    let n = scene.len() as u64;
    if n == 0 {
        return None;
    }
    let pick = |rng: &mut SplitMix64| &scene.primitives()[(rng.next_u64() % n) as usize];
    let p = pick(rng);
    let t = target(rng, p)?;
    if rng.next_u64().is_multiple_of(4) {
        return Ray::new(t, unit_vector(rng)).ok();
    }
    let q = pick(rng);
    let other = target(rng, q)?;
    // The first positive finite one of: the distance to the other target,
    // the primitive's size, the target's magnitude, 1.
    let reach = [(other - t).length(), size(p), t.abs().max_element()]
        .into_iter()
        .find(|r| *r > 0.0 && r.is_finite())
        .unwrap_or(1.0);
    let origin = t + unit_vector(rng) * reach * uniform(rng, 1.0, 10.0);
    Ray::new(origin, t - origin).ok()
}

/// A secondary ray: a hit of a primary ray on a scene, and a ray spawned
/// from it ([`spawn_ray`]).
#[derive(Clone, Copy, Debug)]
pub struct SpawnedRay {
    /// The primary ray.
    pub primary: Ray,
    /// Its closest hit ([`Interval::FORWARD`], watertight meshes).
    pub hit: SceneHit,
    /// The unit direction chosen: at a random elevation (sine from 1
    /// down to `10^-5`, often grazing) on the side of the surface the
    /// primary came from, or one time in four on the other side.
    pub direction: DVec3,
    /// The ray spawned from the hit along `direction`.
    pub ray: Ray,
}

impl SpawnedRay {
    /// Whether `direction` leaves on the side the primary came from.
    #[inline]
    pub fn reflected(&self) -> bool {
        (self.direction.dot(self.hit.hit.normal) > 0.0)
            != (self.primary.direction().dot(self.hit.hit.normal) > 0.0)
    }
}

/// A [`SpawnedRay`] for `scene` from up to eight [`scene_ray`] primaries,
/// or `None` when none hits (or the hit's point error is infinite, where
/// no ray can be spawned).
pub fn spawned_ray(rng: &mut SplitMix64, scene: &Scene) -> Option<SpawnedRay> {
    for _ in 0..8 {
        let Some(primary) = scene_ray(rng, scene) else {
            continue;
        };
        let Some(hit) = scene.closest_hit(&primary, Interval::FORWARD) else {
            continue;
        };
        let n = hit.hit.normal;
        let front = if primary.direction().dot(n) > 0.0 {
            -n
        } else {
            n
        };
        let side = if rng.next_u64().is_multiple_of(4) {
            -front
        } else {
            front
        };
        let s = powf(10.0, -5.0 * rng.next_f64());
        let tangent = unit_vector(rng)
            .reject_from_normalized(side)
            .normalize_or(side.any_orthonormal_vector());
        let direction = tangent * sqrt((1.0 - s * s).max(0.0)) + side * s;
        if let Ok(ray) = spawn_ray(&hit.hit, direction) {
            return Some(SpawnedRay {
                primary,
                hit,
                direction,
                ray,
            });
        }
    }
    None
}
