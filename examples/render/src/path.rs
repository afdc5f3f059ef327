//! The path tracer (Q4): diffuse interreflection, with next-event
//! estimation at every matte bounce (one shadow ray to a point sampled
//! uniformly on the area light) and cosine-weighted bounces, Russian
//! roulette after a few bounces, mirrors followed exactly. Each pixel's
//! samples come from a generator seeded by the render's seed and the
//! pixel's index, so a render is the same whatever the thread count.
//!
//! Estimator: at a matte point `x` of albedo `ρ` (BRDF `ρ / π`), the light
//! sample `y` of density `1 / A` contributes `ρ / π · Le · cos θx cos θy /
//! |x - y|² · A` where unoccluded; the bounce direction of density `cos θ /
//! π` multiplies the path's throughput by `ρ`. The sampled light's emission
//! is then not counted again where a bounce hits it (it was counted by the
//! light sample), except right after the camera or a mirror, where no
//! light sample was taken. Every other emitter is counted where a path
//! hits it.

use crate::image::Image;
use crate::room::{Room, Surface};
use crate::shade::{Reflection, facing_normal, mirror_direction};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::scene::{SceneHit, spawn_ray, spawn_ray_to};
use exactray::testing::{SplitMix64, cosine_direction};
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::sync::atomic::{AtomicU64, Ordering};

/// The path tracer's settings.
#[derive(Clone, Copy, Debug)]
pub struct PathTracer {
    /// Paths per pixel.
    pub samples: u32,
    /// The render's seed.
    pub seed: u64,
    /// Bounces before Russian roulette starts.
    pub roulette_after: u32,
    /// Whether matte bounces sample the area light (next-event
    /// estimation); without it, light is found only by hitting it.
    pub next_event: bool,
}

impl Default for PathTracer {
    fn default() -> PathTracer {
        PathTracer {
            samples: 64,
            seed: 1,
            roulette_after: 3,
            next_event: true,
        }
    }
}

/// A path tracer's render: the image and the rays it traced.
#[derive(Clone, Debug)]
pub struct PathRender {
    /// The mean radiance of each pixel's paths.
    pub image: Image,
    /// Per pixel, the sample variance of the mean (for standard errors).
    pub variance_of_mean: Vec<f64>,
    /// Rays traced: closest hits and shadow rays.
    pub rays: u64,
}

/// The generator of pixel `index`: its state hashed from the seed and the
/// index. (Seeding with `seed ^ index * step` would not do: SplitMix64
/// steps its state by a fixed constant, so neighbouring pixels would draw
/// shifted copies of one stream, and their samples would be correlated.)
fn pixel_stream(seed: u64, index: u64) -> SplitMix64 {
    let key = SplitMix64::new(seed).next_u64();
    SplitMix64::new(SplitMix64::new(key ^ index).next_u64())
}

impl PathTracer {
    /// The light sample's contribution at the matte hit `hit` (albedo not
    /// applied), `None` when the room has no area light.
    fn light_sample(
        &self,
        room: &Room,
        ray: &Ray,
        hit: &SceneHit,
        rng: &mut SplitMix64,
        rays: &mut u64,
    ) -> DVec3 {
        let Some(light) = room.area_light.filter(|_| self.next_event) else {
            return DVec3::ZERO;
        };
        let y = light.point(rng.next_f64(), rng.next_f64());
        let x = hit.hit.point;
        let to = y - x;
        let n = facing_normal(ray, hit);
        let (cos_x, cos_y) = (n.dot(to), -light.normal().dot(to));
        if cos_x <= 0.0 || cos_y <= 0.0 {
            return DVec3::ZERO;
        }
        *rays += 1;
        match spawn_ray_to(&hit.hit, y) {
            Ok((shadow, range)) if !room.occluders.occluded(&shadow, range) => {
                let d2 = to.length_squared();
                light.radiance * (cos_x * cos_y / (d2 * d2) * light.area() / PI)
            }
            _ => DVec3::ZERO,
        }
    }

    /// One path's radiance along `ray`.
    pub fn radiance(&self, room: &Room, ray: &Ray, rng: &mut SplitMix64, rays: &mut u64) -> DVec3 {
        let (mut ray, mut throughput, mut sum) = (*ray, DVec3::ONE, DVec3::ZERO);
        let mut counted_by_light_sample = false;
        for bounce in 0.. {
            *rays += 1;
            let Some(hit) = room.scene.closest_hit(&ray, Interval::FORWARD) else {
                sum += throughput * room.environment;
                break;
            };
            let material = room.material(hit.primitive);
            let light = room.area_light.filter(|l| l.primitive == hit.primitive);
            let front = light.is_none_or(|l| ray.direction().dot(l.normal()) < 0.0);
            let sampled = light.is_some() && counted_by_light_sample;
            if front && !sampled {
                sum += throughput * material.emission;
            }
            let next = match material.surface {
                Surface::Mirror(share) => {
                    throughput *= share;
                    counted_by_light_sample = false;
                    mirror_direction(&ray, &hit, Reflection::AboveSurface)
                }
                Surface::Matte(albedo) => {
                    sum += throughput * albedo * self.light_sample(room, &ray, &hit, rng, rays);
                    throughput *= albedo;
                    counted_by_light_sample = self.next_event && room.area_light.is_some();
                    cosine_direction(facing_normal(&ray, &hit), rng)
                }
            };
            if bounce >= self.roulette_after {
                let survive = throughput.max_element().min(0.95);
                if rng.next_f64() >= survive {
                    break;
                }
                throughput /= survive;
            }
            match spawn_ray(&hit.hit, next) {
                Ok(r) => ray = r,
                Err(_) => break,
            }
        }
        sum
    }

    /// The picture of `room` at `width` x `height`, [`samples`](Self::samples)
    /// paths per pixel jittered over the pixel, rows in parallel.
    pub fn render(&self, room: &Room, width: u32, height: u32) -> PathRender {
        let camera = room.camera.with_size(width, height);
        let rays = AtomicU64::new(0);
        let pixels: Vec<(DVec3, f64)> = (0..height)
            .into_par_iter()
            .flat_map_iter(|j| {
                let mut count = 0;
                let row: Vec<(DVec3, f64)> = (0..width)
                    .map(|i| {
                        let index = j as u64 * width as u64 + i as u64;
                        let mut rng = pixel_stream(self.seed, index);
                        self.pixel(room, &camera, i, j, &mut rng, &mut count)
                    })
                    .collect();
                rays.fetch_add(count, Ordering::Relaxed);
                row
            })
            .collect();
        let (image, variance_of_mean) = pixels.into_iter().unzip();
        PathRender {
            image: Image::from_pixels(width, height, image),
            variance_of_mean,
            rays: rays.into_inner(),
        }
    }

    /// The mean of a pixel's paths and the variance of that mean (of the
    /// paths' mean over the three channels).
    fn pixel(
        &self,
        room: &Room,
        camera: &crate::camera::Camera,
        i: u32,
        j: u32,
        rng: &mut SplitMix64,
        rays: &mut u64,
    ) -> (DVec3, f64) {
        let n = self.samples.max(1);
        let (mut sum, mut squares) = (DVec3::ZERO, 0.0);
        for _ in 0..n {
            let ray = camera.ray(i as f64 + rng.next_f64(), j as f64 + rng.next_f64());
            let l = self.radiance(room, &ray, rng, rays);
            sum += l;
            squares += (l.element_sum() / 3.0).powi(2);
        }
        let mean = sum / n as f64;
        let m = mean.element_sum() / 3.0;
        let variance = if n > 1 {
            (squares / n as f64 - m * m).max(0.0) * n as f64 / (n - 1) as f64
        } else {
            0.0
        };
        (mean, variance / n as f64)
    }
}
