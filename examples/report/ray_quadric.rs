//! ray_quadric: the first hit `t >= 0` of a ray on a general quadric
//! (ten coefficients). Peer: the textbook formula on coefficients
//! evaluated in f64 (`naive`); parry3d has no general quadric.

use crate::framework::method;
use crate::ray_family::{RayFamily, cube, first_forward, naive_first, uniform};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::RayCast;
use exactray::shape::Quadric;
use exactray::testing::SplitMix64;
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

fn case(o: [f64; 3], d: [f64; 3], k: [f64; 10]) -> Case {
    Case {
        o: o.into(),
        d: d.into(),
        k,
        quadric: Quadric::new(k).expect("valid quadric"),
        ray: Ray::new(o, d).expect("valid ray"),
    }
}

/// Ellipsoids, hyperboloids, paraboloids and cones centred near the origin
/// (diagonal terms of random signs, small cross terms), rays from the cube
/// [-4, 4]^3 aimed near the origin.
fn ordinary(rng: &mut SplitMix64) -> Case {
    let mut k = [0.0; 10];
    for v in &mut k[..3] {
        *v = uniform(rng, 0.3, 2.0)
            * if rng.next_u64().is_multiple_of(4) {
                -1.0
            } else {
                1.0
            };
    }
    for v in &mut k[3..9] {
        *v = uniform(rng, -0.3, 0.3);
    }
    k[9] = uniform(rng, -2.0, 0.5);
    let o = cube(rng, 4.0);
    let aim = cube(rng, 1.0);
    case(o, core::array::from_fn(|i| aim[i] - o[i]), k)
}

/// A sphere of radius ~1 written as a quadric, seen from 1e4 to 1e6 away.
fn far(rng: &mut SplitMix64) -> Case {
    let c = cube(rng, 1.0);
    let r2 = uniform(rng, 0.5, 2.0);
    let k = [
        1.0,
        1.0,
        1.0,
        0.0,
        0.0,
        0.0,
        -2.0 * c[0],
        -2.0 * c[1],
        -2.0 * c[2],
        c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - r2,
    ];
    let dist = 10f64.powf(uniform(rng, 4.0, 6.0));
    let o = cube(rng, 1.0).map(|x| x * dist);
    let aim = cube(rng, 1.2);
    case(
        o,
        core::array::from_fn(|i| (c[i] + aim[i] - o[i]) / dist),
        k,
    )
}

/// Rays parallel to a paraboloid's axis (degree one) and along a cone's
/// rulings (degree one or zero), and exactly tangent to the unit sphere.
fn degenerate(rng: &mut SplitMix64) -> Case {
    let o = cube(rng, 3.0).map(|x| (x * 4.0).round() / 4.0);
    match rng.next_u64() % 3 {
        0 => case(
            o,
            [0.0, 0.0, -1.0],
            [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0],
        ),
        1 => {
            let (m, n) = ((rng.next_u64() % 5 + 1) as f64, (rng.next_u64() % 5) as f64);
            let ruling = [m * m - n * n, 2.0 * m * n, m * m + n * n];
            case(
                ruling.map(|x| x * 2.0),
                ruling,
                [1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            )
        }
        _ => case(
            [-5.0, 1.0, o[2] * 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
        ),
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
        inputs: vec![
            ("uniform", ordinary),
            ("far", far),
            ("degenerate", degenerate),
        ],
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
