//! ray_quadric: the first hit `t >= 0` of a ray on a general quadric
//! (ten coefficients). Peer: the textbook formula on coefficients
//! evaluated in f64 (`naive`); parry3d has no general quadric.

use crate::framework::method;
use crate::ray_family::{RayFamily, first_forward, inputs, naive_first};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::RayCast;
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

fn oracle(c: &Case) -> Option<f64> {
    let a = Quadratic::quadric(c.o.into(), c.d.into(), c.k).answer();
    if a.count.is_none() {
        return Some(0.0);
    }
    first_forward(&a.roots)
}

#[inline(always)]
fn naive(c: &Case) -> Option<f64> {
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
    if qa == 0.0 {
        let t = -qc / qb;
        return (t >= 0.0).then_some(t);
    }
    naive_first(qa, qb, qc)
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
        methods: vec![
            method("exactray", |c: &Case| {
                c.quadric.cast_t(&c.ray, Interval::FORWARD)
            }),
            method("naive", naive),
        ],
        skip: |_, _| false,
    }
}
