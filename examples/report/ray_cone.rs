//! ray_cone: the first hit `t >= 0` of a ray on a capped cone (lateral
//! surface and base disk). Peers: the textbook formula on the cone's
//! quadratic (`naive`) and parry3d's `Cone` (apex up the y axis).
//!
//! The oracle takes the lateral surface's roots exactly (count exact,
//! roots correctly rounded) and decides which nappe and which side of the
//! base plane each lies on, and the base disk's hit, in f64: only hits
//! within a few ulps of the rim or the apex are uncertain there.

use crate::framework::method;
use crate::ray_family::{RayFamily, cube, naive_first, parry_cast, uniform};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::RayCast;
use exactray::shape::Cone;
use exactray::testing::SplitMix64;
use exactray_oracle::line_oracle::Quadratic;
use glam::DVec3;

#[derive(Clone)]
pub struct Case {
    o: DVec3,
    d: DVec3,
    /// parry's cone: base centre at `c - (0, hh, 0)`, apex at `c + (0, hh, 0)`.
    c: DVec3,
    hh: f64,
    r: f64,
    cone: Cone,
    ray: Ray,
}

fn apex(c: DVec3, hh: f64) -> DVec3 {
    c + DVec3::new(0.0, hh, 0.0)
}

fn axis(hh: f64) -> DVec3 {
    DVec3::new(0.0, -2.0 * hh, 0.0)
}

fn case(o: [f64; 3], d: [f64; 3], c: [f64; 3], hh: f64, r: f64) -> Case {
    let c = DVec3::from(c);
    Case {
        o: o.into(),
        d: d.into(),
        c,
        hh,
        r,
        cone: Cone::new(apex(c, hh), axis(hh), r).expect("valid cone"),
        ray: Ray::new(o, d).expect("valid ray"),
    }
}

fn ordinary(rng: &mut SplitMix64) -> Case {
    let c = cube(rng, 1.0);
    let (hh, r) = (uniform(rng, 0.5, 2.0), uniform(rng, 0.5, 2.0));
    let o = cube(rng, 6.0);
    let aim = cube(rng, 1.2);
    let target: [f64; 3] = core::array::from_fn(|k| c[k] + aim[k]);
    case(o, core::array::from_fn(|k| target[k] - o[k]), c, hh, r)
}

fn far(rng: &mut SplitMix64) -> Case {
    let mut x = ordinary(rng);
    let dist = 10f64.powf(uniform(rng, 6.0, 8.0));
    let o = x.o + (x.o - x.c).normalize() * dist;
    x = case(
        o.into(),
        ((x.o + x.d) - o).to_array(),
        x.c.into(),
        x.hh,
        x.r,
    );
    x
}

fn oracle(c: &Case) -> Option<f64> {
    let (ap, a) = (apex(c.c, c.hh), axis(c.hh));
    let s = a.dot(a);
    let ans = Quadratic::cone(c.o.into(), c.d.into(), ap.into(), a.into(), c.r).answer();
    let at = |t: f64| c.o + c.d * t;
    let lateral = ans.roots.iter().copied().find(|&t| {
        let h = (at(t) - ap).dot(a);
        t >= 0.0 && (0.0..=s).contains(&h)
    });
    let dh = c.d.dot(a);
    let base = (dh != 0.0)
        .then(|| (s - (c.o - ap).dot(a)) / dh)
        .filter(|&t| {
            let radial = (at(t) - ap).cross(a);
            t >= 0.0 && radial.dot(radial) <= c.r * c.r * s
        });
    match (lateral, base) {
        (Some(l), Some(b)) => Some(l.min(b)),
        (l, b) => l.or(b),
    }
}

#[inline(always)]
fn naive(c: &Case) -> Option<f64> {
    let (ap, a) = (apex(c.c, c.hh), axis(c.hh));
    let (w, d) = (c.o - ap, c.d);
    let s = a.dot(a);
    let k = c.r * c.r / s;
    // |w|^2 - (1 + k) (w . a)^2 / |a|^2 = 0 on the double cone.
    let (p, q) = (w.dot(a), d.dot(a));
    let qa = d.dot(d) - (1.0 + k) * q * q / s;
    let qb = 2.0 * (w.dot(d) - (1.0 + k) * p * q / s);
    let qc = w.dot(w) - (1.0 + k) * p * p / s;
    let lateral = naive_first(qa, qb, qc).filter(|&t| {
        let h = (w + d * t).dot(a);
        (0.0..=s).contains(&h)
    });
    let base = (q != 0.0).then(|| (s - p) / q).filter(|&t| {
        let x = w + d * t - a;
        t >= 0.0 && x.dot(x) <= c.r * c.r
    });
    match (lateral, base) {
        (Some(l), Some(b)) => Some(l.min(b)),
        (l, b) => l.or(b),
    }
}

#[inline(always)]
fn parry(c: &Case) -> Option<f64> {
    parry_cast(&parry3d_f64::shape::Cone::new(c.hh, c.r), c.c, c.o, c.d)
}

pub fn family() -> RayFamily<Case> {
    RayFamily {
        name: "ray_cone",
        inputs: vec![("uniform", ordinary), ("far", far)],
        oracle,
        methods: vec![
            method("exactray", |c: &Case| {
                c.cone.cast_t(&c.ray, Interval::FORWARD)
            }),
            method("naive", naive),
            method("parry3d", parry),
        ],
        skip: |_, _| false,
    }
}
