//! ray_cone: the first hit `t >= 0` of a ray on a capped cone (lateral
//! surface and base disk). Peers: the textbook formula on the cone's
//! quadratic (`naive`) and parry3d's `Cone` (apex up the y axis).
//!
//! The oracle takes the lateral surface's roots exactly (count exact,
//! roots correctly rounded) and decides which nappe and which side of the
//! base plane each lies on, and the base disk's hit, in f64: only hits
//! within a few ulps of the rim or the apex are uncertain there.

use crate::ray_family::{
    RayFamily, bounded, inputs, naive_first, parry_cast, quadratic_within, stable_first, unbounded,
};
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::{Precise, RayCast};
use exactray::shape::Cone;
use exactray::testing::{ConeRay, ConeRayClass, cone_ray_case};
use exactray_oracle::line_oracle::{Dyadic, Quadratic, dot3, sub3, v3};
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

fn exact(c: &Case) -> Quadratic {
    Quadratic::cone(c.o.into(), c.d.into(), c.apex.into(), c.axis.into(), c.r)
}

/// The exact first hit, rounded, and whether it lies on the base disk.
fn first_hit(c: &Case) -> Option<(f64, bool)> {
    let (ap, a) = (c.apex, c.axis);
    let s = a.dot(a);
    let ans = exact(c).answer();
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
        (Some(l), Some(b)) if b < l => Some((b, true)),
        (Some(l), _) => Some((l, false)),
        (None, b) => b.map(|b| (b, true)),
    }
}

fn oracle(c: &Case) -> Option<f64> {
    first_hit(c).map(|(t, _)| t)
}

/// Whether the exact first hit lies within `error` of `t`: a lateral
/// root by the line oracle, the base plane's parameter `(|a|^2 - (o -
/// apex) . a) / (d . a)` by exact dyadic signs.
fn within(c: &Case, first: f64, t: f64, error: f64) -> bool {
    let Some((_, on_base)) = first_hit(c) else {
        return false;
    };
    if !on_base {
        return quadratic_within(&exact(c), first, t, error);
    }
    if !(t.is_finite() && error.is_finite()) {
        return error == f64::INFINITY;
    }
    let (o, d, ap, a) = (
        v3(c.o.into()),
        v3(c.d.into()),
        v3(c.apex.into()),
        v3(c.axis.into()),
    );
    let num = dot3(&a, &a).sub(&dot3(&sub3(&o, &ap), &a));
    let den = dot3(&d, &a);
    // The sign of t_exact - x, for t_exact = num / den.
    let side = |x: &Dyadic| num.sub(&x.mul(&den)).sign() * den.sign();
    let (t, e) = (Dyadic::from_f64(t), Dyadic::from_f64(error));
    side(&t.sub(&e)) >= 0 && side(&t.add(&e)) <= 0
}

/// The textbook double cone's coefficients and the capped cone's hit
/// from its lateral root (found by `solve`) and base disk, in `f64`.
#[inline(always)]
fn textbook(c: &Case, solve: fn(f64, f64, f64) -> Option<f64>) -> Option<f64> {
    let (ap, a) = (c.apex, c.axis);
    let (w, d) = (c.o - ap, c.d);
    let s = a.dot(a);
    let k = c.r * c.r / s;
    // |w|^2 - (1 + k) (w . a)^2 / |a|^2 = 0 on the double cone.
    let (p, q) = (w.dot(a), d.dot(a));
    let qa = d.dot(d) - (1.0 + k) * q * q / s;
    let qb = 2.0 * (w.dot(d) - (1.0 + k) * p * q / s);
    let qc = w.dot(w) - (1.0 + k) * p * p / s;
    let lateral = solve(qa, qb, qc).filter(|&t| {
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
fn naive(c: &Case) -> Option<f64> {
    textbook(c, naive_first)
}

#[inline(always)]
fn stable(c: &Case) -> Option<f64> {
    textbook(c, stable_first)
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
        within,
        methods: vec![
            bounded("exactray", |c: &Case| {
                c.cone.cast_bounded(&c.ray, Interval::FORWARD)
            }),
            bounded("exactray-precise", |c: &Case| {
                Precise(c.cone).cast_bounded(&c.ray, Interval::FORWARD)
            }),
            unbounded("naive", naive),
            unbounded("naive-stable", stable),
            unbounded("parry3d", parry),
        ],
        skip: |_, _| false,
    }
}
