//! ray_cylinder: the first hit `t >= 0` of a ray on an infinite cylinder.
//! Peers: the textbook formula on the projected quadratic (`naive`) and
//! parry3d's `Cylinder` (capped, along y: made 2e4 tall, so that rays
//! aimed at its middle meet its side; it runs only on y-axis inputs).

use crate::framework::method;
use crate::ray_family::{RayFamily, cube, first_forward, naive_first, parry_cast, uniform, unit};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::RayCast;
use exactray::shape::Cylinder;
use exactray::testing::SplitMix64;
use exactray_oracle::line_oracle::Quadratic;
use glam::DVec3;

#[derive(Clone)]
pub struct Case {
    o: DVec3,
    d: DVec3,
    p: DVec3,
    a: DVec3,
    r: f64,
    cylinder: Cylinder,
    ray: Ray,
}

fn case(o: [f64; 3], d: [f64; 3], p: [f64; 3], a: [f64; 3], r: f64) -> Case {
    Case {
        o: o.into(),
        d: d.into(),
        p: p.into(),
        a: a.into(),
        r,
        cylinder: Cylinder::new(p, a, r).expect("valid cylinder"),
        ray: Ray::new(o, d).expect("valid ray"),
    }
}

/// The y axis through `p`, radius 0.5 to 2; origins around it aimed within
/// 1.3 radii of the axis, directions of length 1/4 to 4.
fn ordinary(rng: &mut SplitMix64) -> Case {
    let p = cube(rng, 1.0);
    let r = uniform(rng, 0.5, 2.0);
    let o = cube(rng, 6.0);
    let aim = cube(rng, 1.3 * r);
    let target: [f64; 3] = core::array::from_fn(|k| p[k] + aim[k]);
    let s = uniform(rng, 0.25, 4.0);
    case(
        o,
        core::array::from_fn(|k| (target[k] - o[k]) * s),
        p,
        [0.0, 1.0, 0.0],
        r,
    )
}

/// As `uniform`, around a random axis of random length.
fn any_axis(rng: &mut SplitMix64) -> Case {
    let mut c = ordinary(rng);
    let a = unit(rng).map(|x| x * uniform(rng, 0.1, 10.0));
    c = case(c.o.into(), c.d.into(), c.p.into(), a, c.r);
    c
}

/// Rays passing the y axis at distance r (1 +- 1e-12), perpendicular-ish to it.
fn grazing(rng: &mut SplitMix64) -> Case {
    let p = cube(rng, 1.0);
    let r = uniform(rng, 0.5, 2.0);
    let phi = uniform(rng, 0.0, std::f64::consts::TAU);
    let (n, t) = (
        [phi.cos(), 0.0, phi.sin()],
        [-phi.sin(), uniform(rng, -0.5, 0.5), phi.cos()],
    );
    let h = r * (1.0 + uniform(rng, -1e-12, 1e-12));
    let hit: [f64; 3] = core::array::from_fn(|k| p[k] + h * n[k]);
    let back = uniform(rng, 2.0, 5.0) * r;
    let o = core::array::from_fn(|k| hit[k] - back * t[k]);
    case(o, t, p, [0.0, 1.0, 0.0], r)
}

/// The exam's cylinder x^2 + z^2 = 1 seen from 1e6 to 1e8 away.
fn far(rng: &mut SplitMix64) -> Case {
    let dist = 10f64.powf(uniform(rng, 6.0, 8.0));
    let phi = uniform(rng, 0.0, std::f64::consts::TAU);
    let o = [dist * phi.cos(), uniform(rng, -5.0, 5.0), dist * phi.sin()];
    let aim = cube(rng, 1.2);
    case(
        o,
        core::array::from_fn(|k| (aim[k] - o[k]) / dist),
        [0.0; 3],
        [0.0, 1.0, 0.0],
        1.0,
    )
}

/// Rays along the axis direction exactly (scaled by 2^k): inside, outside,
/// or on the surface (every t; the first hit is t = 0).
fn parallel(rng: &mut SplitMix64) -> Case {
    let mut a = cube(rng, 2.0).map(|x| (x * 8.0).round() / 8.0);
    if a == [0.0; 3] {
        a[2] = 0.125;
    }
    let k = 2f64.powi((rng.next_u64() % 9) as i32 - 4);
    let p = cube(rng, 2.0).map(f64::round);
    // The surface point p + e (e perpendicular to a, |e| = r) is exact for
    // e = (a_y, -a_x, 0) and r = |e| when that is a dyadic length; use a
    // random offset otherwise (inside or outside).
    let e = [a[1], -a[0], 0.0];
    let r = (e[0] * e[0] + e[1] * e[1]).sqrt();
    let o = match rng.next_u64() % 3 {
        0 => core::array::from_fn(|i| p[i] + e[i]),
        1 => core::array::from_fn(|i| p[i] + 0.5 * e[i]),
        _ => core::array::from_fn(|i| p[i] + 2.0 * e[i]),
    };
    case(o, a.map(|x| x * k), p, a, r)
}

fn oracle(c: &Case) -> Option<f64> {
    let q = Quadratic::cylinder(c.o.into(), c.d.into(), c.p.into(), c.a.into(), c.r);
    let a = q.answer();
    if a.count.is_none() {
        return Some(0.0);
    }
    first_forward(&a.roots)
}

#[inline(always)]
fn naive(c: &Case) -> Option<f64> {
    let (w, a) = (c.o - c.p, c.a);
    let aa = a.dot(a);
    // Remove the axial components, then solve |w' + t d'|^2 = r^2.
    let dp = c.d - a * (c.d.dot(a) / aa);
    let wp = w - a * (w.dot(a) / aa);
    naive_first(dp.dot(dp), 2.0 * wp.dot(dp), wp.dot(wp) - c.r * c.r)
}

#[inline(always)]
fn parry(c: &Case) -> Option<f64> {
    parry_cast(&parry3d_f64::shape::Cylinder::new(1e4, c.r), c.p, c.o, c.d)
}

pub fn family() -> RayFamily<Case> {
    RayFamily {
        name: "ray_cylinder",
        inputs: vec![
            ("uniform", ordinary),
            ("any-axis", any_axis),
            ("grazing", grazing),
            ("far", far),
            ("parallel", parallel),
        ],
        oracle,
        methods: vec![
            method("exactray", |c: &Case| {
                c.cylinder.cast_t(&c.ray, Interval::FORWARD)
            }),
            method("naive", naive),
            method("parry3d", parry),
        ],
        skip: |m, inputs| m == "parry3d" && matches!(inputs, "any-axis" | "parallel"),
    }
}
