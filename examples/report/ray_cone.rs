//! ray_cone: the first hit `t >= 0` of a ray on a capped cone (lateral
//! surface and base disk). Peers: the textbook formula on the cone's
//! quadratic (`naive`) and parry3d's `Cone` (apex up the y axis).
//!
//! The oracle takes the lateral surface's roots exactly (count exact,
//! roots correctly rounded) and decides which nappe and which side of the
//! base plane each lies on, and the base disk's hit, in f64: only hits
//! within a few ulps of the rim or the apex are uncertain there.

use crate::framework::method;
use crate::ray_family::{RayFamily, inputs, naive_first, parry_cast};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::RayCast;
use exactray::shape::Cone;
use exactray::testing::{ConeRay, ConeRayClass, cone_ray_case};
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
    /// The apex `c + (0, hh, 0)` and the axis `(0, -2 hh, 0)` to the base.
    apex: DVec3,
    axis: DVec3,
    cone: Cone,
    ray: Ray,
}

fn case(r: ConeRay) -> Case {
    Case {
        o: r.origin.into(),
        d: r.direction.into(),
        c: r.center.into(),
        hh: r.half_height,
        r: r.radius,
        apex: r.apex(),
        axis: r.axis(),
        cone: Cone::new(r.apex(), r.axis(), r.radius).expect("valid cone"),
        ray: Ray::new(r.origin, r.direction).expect("valid ray"),
    }
}

fn oracle(c: &Case) -> Option<f64> {
    let (ap, a) = (c.apex, c.axis);
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
    let (ap, a) = (c.apex, c.axis);
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
        inputs: inputs(&ConeRayClass::ALL, ConeRayClass::name, cone_ray_case, case),
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
