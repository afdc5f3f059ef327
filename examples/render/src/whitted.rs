//! The ray tracer (Whitted style): matte surfaces lit by the point light
//! through one shadow ray each (Q5), mirrors followed by reflected
//! rays (Q3), every secondary ray spawned from the hit's certified point
//! error (`spawn_ray`, `spawn_ray_to`): no epsilon anywhere.

use crate::image::Image;
use crate::room::{Room, Surface};
use crate::shade::{Reflection, facing_normal, mirror_direction};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::scene::{spawn_ray, spawn_ray_to};
use glam::DVec3;
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// The ray tracer's settings.
#[derive(Clone, Copy, Debug)]
pub struct RayTracer {
    /// How mirrors reflect about smooth normals.
    pub reflection: Reflection,
    /// Mirror bounces followed before a path is cut (black).
    pub max_depth: u32,
    /// Radiance added to every matte surface, so that shadows are not
    /// pure black (a constant, as in Whitted's model).
    pub ambient: f64,
}

impl Default for RayTracer {
    fn default() -> RayTracer {
        RayTracer {
            reflection: Reflection::AboveSurface,
            max_depth: 8,
            ambient: 0.03,
        }
    }
}

/// What a render counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounts {
    /// Rays traced for a closest hit (primary and reflected).
    pub closest: u64,
    /// Shadow rays (any-hit queries).
    pub shadow: u64,
    /// Mirror reflections that pointed below the geometric surface they
    /// leave (computed dot product with the side the ray came from not
    /// positive): the Q3 failure, zero with
    /// [`Reflection::AboveSurface`].
    pub below_surface: u64,
}

impl RayCounts {
    /// Every ray.
    pub fn total(&self) -> u64 {
        self.closest + self.shadow
    }
}

impl RayTracer {
    /// The radiance arriving along `ray` (the room's environment where it
    /// leaves the room, black where the mirror depth runs out).
    pub fn radiance(&self, room: &Room, ray: &Ray, counts: &mut RayCounts) -> DVec3 {
        let mut ray = *ray;
        let mut tint = DVec3::ONE;
        for _ in 0..=self.max_depth {
            counts.closest += 1;
            let Some(hit) = room.scene.closest_hit(&ray, Interval::FORWARD) else {
                return tint * room.environment;
            };
            let material = room.material(hit.primitive);
            match material.surface {
                Surface::Mirror(share) => {
                    tint *= share;
                    let dir = mirror_direction(&ray, &hit, self.reflection);
                    let n = hit.hit.normal;
                    let side = if ray.direction().dot(n) > 0.0 { -n } else { n };
                    if dir.dot(side) <= 0.0 {
                        counts.below_surface += 1;
                    }
                    match spawn_ray(&hit.hit, dir) {
                        Ok(next) => ray = next,
                        Err(_) => return DVec3::ZERO,
                    }
                }
                Surface::Matte(albedo) => {
                    let n = facing_normal(&ray, &hit);
                    let light = room.point_light;
                    let mut lit = DVec3::splat(self.ambient);
                    counts.shadow += 1;
                    if let Ok((shadow, range)) = spawn_ray_to(&hit.hit, light.position) {
                        let to_light = light.position - hit.hit.point;
                        let cos = n.dot(to_light.normalize_or_zero());
                        // The light's own surface is not an occluder: the
                        // point light sits in its plane.
                        if cos > 0.0 && !room.occluders.occluded(&shadow, range) {
                            lit += light.intensity * cos / to_light.length_squared();
                        }
                    }
                    return tint * (albedo * lit + material.emission);
                }
            }
        }
        DVec3::ZERO
    }

    /// The picture of `room` through its camera resized to `width` x
    /// `height`, one primary ray per pixel centre, rows in parallel.
    pub fn render(&self, room: &Room, width: u32, height: u32) -> (Image, RayCounts) {
        let camera = room.camera.with_size(width, height);
        let [closest, shadow, below] = [0; 3].map(AtomicU64::new);
        let pixels: Vec<DVec3> = (0..height)
            .into_par_iter()
            .flat_map_iter(|j| {
                let mut counts = RayCounts::default();
                let row: Vec<DVec3> = (0..width)
                    .map(|i| self.radiance(room, &camera.pixel_ray(i, j), &mut counts))
                    .collect();
                closest.fetch_add(counts.closest, Ordering::Relaxed);
                shadow.fetch_add(counts.shadow, Ordering::Relaxed);
                below.fetch_add(counts.below_surface, Ordering::Relaxed);
                row
            })
            .collect();
        let counts = RayCounts {
            closest: closest.into_inner(),
            shadow: shadow.into_inner(),
            below_surface: below.into_inner(),
        };
        (Image::from_pixels(width, height, pixels), counts)
    }
}
