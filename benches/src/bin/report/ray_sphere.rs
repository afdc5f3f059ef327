//! ray_sphere: the first hit `t >= 0` of a ray on a sphere. Peers: the
//! textbook formula (`naive`), the "stable" form of Ray Tracing Gems
//! chapter 7 (`naive-stable`: the discriminant from the closest point to
//! the centre, the second root by Vieta) and parry3d's `Ball` (f64 build).

use crate::ray_family::{
    RayFamily, bounded, first_forward, inputs, naive_first, parry_cast, quadratic_within,
    stable_circle_first, unbounded,
};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::{Precise, RayCast};
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

fn exact(c: &Case) -> Quadratic {
    Quadratic::sphere(c.o.into(), c.d.into(), c.c.into(), c.r)
}

fn oracle(c: &Case) -> Option<f64> {
    first_forward(&exact(c).answer().roots)
}

#[inline(always)]
fn naive(c: &Case) -> Option<f64> {
    let w = c.o - c.c;
    naive_first(c.d.dot(c.d), 2.0 * w.dot(c.d), w.dot(w) - c.r * c.r)
}

/// Ray Tracing Gems ch. 7's form ([`stable_circle_first`]).
#[inline(always)]
fn stable(c: &Case) -> Option<f64> {
    stable_circle_first(c.o - c.c, c.d, c.r)
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
        within: |c, first, t, error| quadratic_within(&exact(c), first, t, error),
        methods: vec![
            bounded("exactray", |c: &Case| {
                c.sphere.cast_bounded(&c.ray, Interval::FORWARD)
            }),
            bounded("exactray-precise", |c: &Case| {
                Precise(c.sphere).cast_bounded(&c.ray, Interval::FORWARD)
            }),
            unbounded("naive", naive),
            unbounded("naive-stable", stable),
            unbounded("parry3d", parry),
        ],
        skip: |_, _| false,
    }
}
