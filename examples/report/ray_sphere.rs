//! ray_sphere: the first hit `t >= 0` of a ray on a sphere. Peers: the
//! textbook formula (`naive`), the "stable" form of Ray Tracing Gems
//! chapter 7 (`naive-stable`: the discriminant from the closest point to
//! the centre, the second root by Vieta) and parry3d's `Ball` (f64 build).

use crate::framework::method;
use crate::ray_family::{RayFamily, cube, first_forward, naive_first, parry_cast, uniform, unit};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::RayCast;
use exactray::shape::Sphere;
use exactray::testing::SplitMix64;
use exactray_oracle::line_oracle::Quadratic;
use glam::DVec3;

#[derive(Clone)]
pub struct Case {
    o: DVec3,
    d: DVec3,
    c: DVec3,
    r: f64,
    sphere: Sphere,
    ray: Ray,
}

fn case(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64) -> Case {
    Case {
        o: o.into(),
        d: d.into(),
        c: c.into(),
        r,
        sphere: Sphere::new(c, r).expect("valid sphere"),
        ray: Ray::new(o, d).expect("valid ray"),
    }
}

/// A ray from `o` through `target`, its direction scaled by `s`.
fn through(o: [f64; 3], target: [f64; 3], s: f64) -> [f64; 3] {
    core::array::from_fn(|k| (target[k] - o[k]) * s)
}

/// Origins around the sphere, aimed within 1.3 radii of its centre
/// (about two thirds hit), directions of length 1/4 to 4.
fn ordinary(rng: &mut SplitMix64) -> Case {
    let c = cube(rng, 1.0);
    let r = uniform(rng, 0.5, 2.0);
    let o = cube(rng, 6.0);
    let aim = cube(rng, 1.3 * r);
    let target = core::array::from_fn(|k| c[k] + aim[k]);
    case(o, through(o, target, uniform(rng, 0.25, 4.0)), c, r)
}

/// Rays passing the sphere within about 1e-12 of its radius from a few
/// radii away: near-tangent hits and misses.
fn grazing(rng: &mut SplitMix64) -> Case {
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

/// Origins 1e6 to 1e8 away from a unit sphere, aimed within 1.2 of it.
fn far(rng: &mut SplitMix64) -> Case {
    let c = cube(rng, 1.0);
    let dist = 10f64.powf(uniform(rng, 6.0, 8.0));
    let u = unit(rng);
    let o = core::array::from_fn(|k| c[k] + dist * u[k]);
    let aim = cube(rng, 1.2);
    let target = core::array::from_fn(|k| c[k] + aim[k]);
    case(o, through(o, target, 1.0 / dist), c, 1.0)
}

/// Exactly tangent rays: integer centres, radius 5, the ray through a
/// point (3, 4) of the circle perpendicular to its radius, in a random
/// coordinate order, scaled by a random power of two.
fn tangent(rng: &mut SplitMix64) -> Case {
    let c: [f64; 3] = cube(rng, 8.0).map(f64::round);
    let k = 2f64.powi((rng.next_u64() % 41) as i32 - 20);
    let perm = (rng.next_u64() % 3) as usize;
    let mut p = [3.0, 4.0, 0.0];
    let mut d = [-4.0, 3.0, 0.0];
    p.rotate_right(perm);
    d.rotate_right(perm);
    let back = (rng.next_u64() % 8 + 1) as f64;
    let o: [f64; 3] = core::array::from_fn(|i| (c[i] + p[i] - back * d[i]) * k);
    case(o, d, c.map(|x| x * k), 5.0 * k)
}

fn oracle(c: &Case) -> Option<f64> {
    let a = Quadratic::sphere(c.o.into(), c.d.into(), c.c.into(), c.r).answer();
    first_forward(&a.roots)
}

#[inline(always)]
fn naive(c: &Case) -> Option<f64> {
    let w = c.o - c.c;
    naive_first(c.d.dot(c.d), 2.0 * w.dot(c.d), w.dot(w) - c.r * c.r)
}

/// Ray Tracing Gems ch. 7 (Haines, Günther, Akenine-Möller, "Precision
/// Improvements for Ray/Sphere Intersection"), for unnormalized `d`.
#[inline(always)]
fn stable(c: &Case) -> Option<f64> {
    let f = c.o - c.c;
    let a = c.d.dot(c.d);
    let b = -f.dot(c.d);
    let l = f + c.d * (b / a);
    let disc = a * (c.r * c.r - l.dot(l));
    if disc < 0.0 {
        return None;
    }
    let q = b + disc.sqrt().copysign(b);
    let (t0, t1) = ((f.dot(f) - c.r * c.r) / q, q / a);
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    [t0, t1].into_iter().find(|&t| t >= 0.0)
}

#[inline(always)]
fn parry(c: &Case) -> Option<f64> {
    parry_cast(&parry3d_f64::shape::Ball::new(c.r), c.c, c.o, c.d)
}

pub fn family() -> RayFamily<Case> {
    RayFamily {
        name: "ray_sphere",
        inputs: vec![
            ("uniform", ordinary),
            ("grazing", grazing),
            ("far", far),
            ("tangent", tangent),
        ],
        oracle,
        methods: vec![
            method("exactray", |c: &Case| {
                c.sphere.cast_t(&c.ray, Interval::FORWARD)
            }),
            method("naive", naive),
            method("naive-stable", stable),
            method("parry3d", parry),
        ],
        skip: |_, _| false,
    }
}
