//! ray_sphere: the first hit `t >= 0` of a ray on a sphere. Peers: the
//! textbook formula (`naive`), the "stable" form of Ray Tracing Gems
//! chapter 7 (`naive-stable`: the discriminant from the closest point to
//! the centre, the second root by Vieta) and parry3d's `Ball` (f64 build).

use crate::framework::method;
use crate::ray_family::{RayFamily, first_forward, inputs, naive_first, parry_cast};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::RayCast;
use exactray::shape::Sphere;
use exactray::testing::{SphereRay, SphereRayClass, sphere_ray_case};
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

fn case(
    SphereRay {
        origin: o,
        direction: d,
        center: c,
        radius: r,
    }: SphereRay,
) -> Case {
    Case {
        o: o.into(),
        d: d.into(),
        c: c.into(),
        r,
        sphere: Sphere::new(c, r).expect("valid sphere"),
        ray: Ray::new(o, d).expect("valid ray"),
    }
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
        inputs: inputs(
            &SphereRayClass::ALL,
            SphereRayClass::name,
            sphere_ray_case,
            case,
        ),
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
