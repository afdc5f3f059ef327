//! ray_cylinder: the first hit `t >= 0` of a ray on an infinite cylinder.
//! Peers: the textbook formula on the projected quadratic (`naive`) and
//! parry3d's `Cylinder` (capped, along y: made 2e4 tall, so that rays
//! aimed at its middle meet its side; it runs only on y-axis inputs).

use crate::ray_family::{
    RayFamily, bounded, first_forward, inputs, naive_first, parry_cast, quadratic_within,
    stable_circle_first, unbounded,
};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::{Precise, RayCast};
use exactray::shape::Cylinder;
use exactray::testing::{CylinderRay, CylinderRayClass, cylinder_ray_case};
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

fn case(
    CylinderRay {
        origin: o,
        direction: d,
        point: p,
        axis: a,
        radius: r,
    }: CylinderRay,
) -> Case {
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

fn exact(c: &Case) -> Quadratic {
    Quadratic::cylinder(c.o.into(), c.d.into(), c.p.into(), c.a.into(), c.r)
}

fn oracle(c: &Case) -> Option<f64> {
    let a = exact(c).answer();
    if a.count.is_none() {
        return Some(0.0);
    }
    first_forward(&a.roots)
}

/// `w = o - p` and `d` with their axial components removed: the circle
/// problem `|w' + t d'|^2 = r^2` the textbook methods solve.
#[inline(always)]
fn projected(c: &Case) -> (DVec3, DVec3) {
    let (w, a) = (c.o - c.p, c.a);
    let aa = a.dot(a);
    (w - a * (w.dot(a) / aa), c.d - a * (c.d.dot(a) / aa))
}

#[inline(always)]
fn naive(c: &Case) -> Option<f64> {
    let (wp, dp) = projected(c);
    naive_first(dp.dot(dp), 2.0 * wp.dot(dp), wp.dot(wp) - c.r * c.r)
}

/// Ray Tracing Gems ch. 7's form on the projected problem.
#[inline(always)]
fn stable(c: &Case) -> Option<f64> {
    let (wp, dp) = projected(c);
    stable_circle_first(wp, dp, c.r)
}

#[inline(always)]
fn parry(c: &Case) -> Option<f64> {
    parry_cast(&parry3d_f64::shape::Cylinder::new(1e4, c.r), c.p, c.o, c.d)
}

pub fn family() -> RayFamily<Case> {
    RayFamily {
        name: "ray_cylinder",
        inputs: inputs(
            &CylinderRayClass::ALL,
            CylinderRayClass::name,
            cylinder_ray_case,
            case,
        ),
        oracle,
        within: |c, first, t, error| quadratic_within(&exact(c), first, t, error),
        methods: vec![
            bounded("exactray", |c: &Case| {
                c.cylinder.cast_bounded(&c.ray, Interval::FORWARD)
            }),
            bounded("exactray-precise", |c: &Case| {
                Precise(c.cylinder).cast_bounded(&c.ray, Interval::FORWARD)
            }),
            unbounded("naive", naive),
            unbounded("naive-stable", stable),
            unbounded("parry3d", parry),
        ],
        skip: |m, inputs| m == "parry3d" && matches!(inputs, "any-axis" | "parallel"),
    }
}
