//! ray_quadric: the first hit `t >= 0` of a ray on a general quadric
//! (ten coefficients). Peer: the textbook formula on coefficients
//! evaluated in f64 (`naive`); parry3d has no general quadric.

use crate::ray_family::{
    RayFamily, bounded, first_forward, inputs, naive_first, quadratic_within, stable_first,
    unbounded,
};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::{Precise, RayCast};
use exactray::shape::Quadric;
use exactray::testing::{QuadricRay, QuadricRayClass, quadric_ray_case};
use exactray_oracle::line_oracle::Quadratic;
use glam::DVec3;

#[derive(Clone)]
pub struct Case {
    o: DVec3,
    d: DVec3,
    k: [f64; 10],
    quadric: Quadric,
    ray: Ray,
}

fn case(
    QuadricRay {
        origin: o,
        direction: d,
        coefficients: k,
    }: QuadricRay,
) -> Case {
    Case {
        o: o.into(),
        d: d.into(),
        k,
        quadric: Quadric::new(k).expect("valid quadric"),
        ray: Ray::new(o, d).expect("valid ray"),
    }
}

fn exact(c: &Case) -> Quadratic {
    Quadratic::quadric(c.o.into(), c.d.into(), c.k)
}

fn oracle(c: &Case) -> Option<f64> {
    let a = exact(c).answer();
    if a.count.is_none() {
        return Some(0.0);
    }
    first_forward(&a.roots)
}

/// The textbook coefficients of `a t^2 + b t + c` in `f64`.
#[inline(always)]
fn coefficients(c: &Case) -> (f64, f64, f64) {
    let [a, b, cc, d, e, f, g, h, i, j] = c.k;
    let (o, v) = (c.o, c.d);
    let qa = a * v.x * v.x
        + b * v.y * v.y
        + cc * v.z * v.z
        + d * v.x * v.y
        + e * v.x * v.z
        + f * v.y * v.z;
    let qb = 2.0 * (a * o.x * v.x + b * o.y * v.y + cc * o.z * v.z)
        + d * (o.x * v.y + o.y * v.x)
        + e * (o.x * v.z + o.z * v.x)
        + f * (o.y * v.z + o.z * v.y)
        + g * v.x
        + h * v.y
        + i * v.z;
    let qc = a * o.x * o.x
        + b * o.y * o.y
        + cc * o.z * o.z
        + d * o.x * o.y
        + e * o.x * o.z
        + f * o.y * o.z
        + g * o.x
        + h * o.y
        + i * o.z
        + j;
    (qa, qb, qc)
}

#[inline(always)]
fn naive(c: &Case) -> Option<f64> {
    let (qa, qb, qc) = coefficients(c);
    if qa == 0.0 {
        let t = -qc / qb;
        return (t >= 0.0).then_some(t);
    }
    naive_first(qa, qb, qc)
}

#[inline(always)]
fn stable(c: &Case) -> Option<f64> {
    let (qa, qb, qc) = coefficients(c);
    stable_first(qa, qb, qc)
}

pub fn family() -> RayFamily<Case> {
    RayFamily {
        name: "ray_quadric",
        inputs: inputs(
            &QuadricRayClass::ALL,
            QuadricRayClass::name,
            quadric_ray_case,
            case,
        ),
        oracle,
        within: |c, first, t, error| quadratic_within(&exact(c), first, t, error),
        methods: vec![
            bounded("exactray", |c: &Case| {
                c.quadric.cast_bounded(&c.ray, Interval::FORWARD)
            }),
            bounded("exactray-precise", |c: &Case| {
                Precise(c.quadric).cast_bounded(&c.ray, Interval::FORWARD)
            }),
            unbounded("naive", naive),
            unbounded("naive-stable", stable),
        ],
        skip: |_, _| false,
    }
}
