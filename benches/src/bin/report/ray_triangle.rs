//! ray_triangle: where a ray first meets a triangle (`t >= 0`), for the
//! crate's three variants (`exactray-mt`, `exactray-watertight`,
//! `exactray-exact`; `exactray` is the default, the watertight one, which
//! `RayCast` uses) beside a textbook Möller–Trumbore (`naive`) and
//! parry3d's triangle cast. The exact variant also on a ray prepared once
//! (`ExactRay`, as a scene prepares it for all the triangles it meets):
//! `exactray-exact-prepared` (`t` within 4 ulps) and
//! `exactray-exact-bounded` (`t` with a certified bound) time the test of
//! one triangle with the ray prepared beforehand, `exactray-exact-prepare`
//! the preparation alone (ns per ray; its answers are the prepared ray's).
//!
//! Inputs (`exactray::testing::RayTriangleClass` and `TiledMesh`): `uniform` (ordinary rays, about
//! a third hit), `far` (origins 10^6 to 10^12 away), `near-edge` (aimed at an
//! edge, then moved by up to 2 ulps), `grazing` (origins within 10^-12 to
//! 10^-4 of the plane), and `shared-edges`: rays aimed at the interior edges
//! and vertices of a tiled height field, timed against the triangles around
//! its target.
//!
//! Errors: on the single-triangle inputs, a hit or miss that differs from
//! the exact answer (num-bigint; a ray whose line lies in the triangle's
//! plane counts as a miss, the crate's convention); `max_ulps` is the
//! largest distance in ulps from a method's `t` to the correctly rounded
//! exact `t`, over the hits it gets right; an answer that comes with a
//! certified bound (`exactray-exact-bounded`) whose interval misses the
//! exact `t` is an error too (`docs/report.md`, "Values that come with
//! a bound"), and a note gives the bounds' sizes. On `shared-edges`, an error is a
//! ray that no triangle of the mesh reports (a false miss: the exact line
//! meets a triangle around the target), and `cases` counts rays; ns/op is
//! per ray–triangle test there too.

use crate::framework::{Config, Measure, Row, median, method, note, time_methods};
use exactray::interval::Interval;
use exactray::query::ray::{ExactRay, Ray};
use exactray::shape::Triangle;
use exactray::testing::{RayTriangleClass, TiledMesh, ray_triangle_case};
use exactray_oracle::oracle;
use glam::DVec3;
use num_bigint::BigInt;
use parry3d_f64::math::Vector as PVector;
use parry3d_f64::query::{Ray as PRay, RayCast as PRayCast};
use parry3d_f64::shape::Triangle as PTriangle;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// One ray against one triangle, in every method's own types.
pub struct Case {
    ray: Ray,
    tri: Triangle,
    /// The ray prepared for the exact test, as a scene prepares it once.
    exact_ray: ExactRay,
    pray: PRay,
    ptri: PTriangle,
}

/// The method whose answers come with a certified bound on `t`: its timed
/// answer is the hit's `t`, as the others', and [`bounded_check`] checks
/// the bound beside it. (Returning the bound from the timed closure, a
/// wider value through `black_box`, cost every method about 2 ns per case.)
const BOUNDED: &str = "exactray-exact-bounded";

impl Case {
    fn new(o: DVec3, d: DVec3, v: [DVec3; 3]) -> Option<Case> {
        let p = |x: DVec3| PVector::new(x.x, x.y, x.z);
        let ray = Ray::new(o, d).ok()?;
        Some(Case {
            exact_ray: ExactRay::new(&ray),
            ray,
            tri: Triangle::new(v[0], v[1], v[2]).ok()?,
            pray: PRay::new(p(o), p(d)),
            ptri: PTriangle::new(p(v[0]), p(v[1]), p(v[2])),
        })
    }
}

/// The textbook Möller–Trumbore, as usually copied: a fixed epsilon for
/// parallel rays and for `t`.
pub fn naive(o: DVec3, d: DVec3, [v0, v1, v2]: [DVec3; 3]) -> Option<f64> {
    const EPSILON: f64 = 1e-8;
    let (e1, e2) = (v1 - v0, v2 - v0);
    let h = d.cross(e2);
    let a = e1.dot(h);
    if a > -EPSILON && a < EPSILON {
        return None;
    }
    let f = 1.0 / a;
    let s = o - v0;
    let u = f * s.dot(h);
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = f * d.dot(q);
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = f * e2.dot(q);
    (t > EPSILON).then_some(t)
}

type Methods = Vec<Box<dyn Measure<Case, Option<f64>>>>;

/// The exact test's per-ray preparation: the timed loop prepares each
/// case's ray and nothing more; its answers are the prepared ray's
/// (`ExactRay::cast`), checked as the others are.
struct Prepare;

impl Measure<Case, Option<f64>> for Prepare {
    fn name(&self) -> &'static str {
        "exactray-exact-prepare"
    }

    fn answer(&self, c: &Case) -> Option<f64> {
        let ray = ExactRay::new(&c.ray);
        ray.cast(&c.tri, Interval::FORWARD).map(|h| h.t)
    }

    fn run_loop(&self, cases: &[Case], iters: u64) -> Duration {
        let start = Instant::now();
        for _ in 0..iters {
            for c in cases {
                black_box(ExactRay::new(&black_box(c).ray));
            }
        }
        start.elapsed()
    }
}

pub fn methods() -> Methods {
    let f = Interval::FORWARD;
    vec![
        method("exactray", move |c: &Case| {
            c.tri.cast_watertight(&c.ray, f).map(|h| h.t)
        }),
        method("exactray-mt", move |c: &Case| {
            c.tri.cast_mt(&c.ray, f).map(|h| h.t)
        }),
        method("exactray-watertight", move |c: &Case| {
            c.tri.cast_watertight(&c.ray, f).map(|h| h.t)
        }),
        method("exactray-exact", move |c: &Case| {
            c.tri.cast_exact(&c.ray, f).map(|h| h.t)
        }),
        method("exactray-exact-prepared", move |c: &Case| {
            c.exact_ray.cast(&c.tri, f).map(|h| h.t)
        }),
        method(BOUNDED, move |c: &Case| {
            c.exact_ray.cast_bounded(&c.tri, f).map(|h| h.hit.t)
        }),
        Box::new(Prepare),
        method("naive", |c: &Case| {
            naive(c.ray.origin(), c.ray.direction(), c.tri.vertices())
        }),
        method("parry3d", |c: &Case| {
            c.ptri.cast_local_ray(&c.pray, f64::MAX, true)
        }),
    ]
}

/// The exact meeting of the case's line with its triangle.
fn line(c: &Case) -> oracle::LineTriangle {
    let (o, d) = (c.ray.origin(), c.ray.direction());
    oracle::line_triangle(
        o.to_array(),
        d.to_array(),
        c.tri.vertices().map(|p| p.to_array()),
    )
}

/// The exact answer: the hit's exact `t` as a fraction, if any.
fn exact(c: &Case) -> Option<(BigInt, BigInt)> {
    line(c)
        .t
        .filter(|(num, den)| oracle::ratio_in(num, den, 0.0, f64::INFINITY))
}

/// The bounded tier's bound on a case it hits, checked: whether the exact
/// `t` lies outside it (an error), and the bound's size in ulps of its `t`
/// (of the smallest subnormal for a zero `t`).
fn bounded_check(c: &Case, (num, den): &(BigInt, BigInt)) -> Option<(bool, f64)> {
    let h = c.exact_ray.cast_bounded(&c.tri, Interval::FORWARD)?;
    let (t, b) = (h.hit.t, h.t_error);
    let outside = !oracle::ratio_in(num, den, (t - b).next_down(), (t + b).next_up());
    let ulp = (t.abs().next_up() - t.abs()).max(f64::from_bits(1));
    Some((outside, b / ulp))
}

pub fn run(cfg: &Config) -> Vec<Row> {
    let methods = methods();
    let checked = cfg.cases / 4;
    let mut rows = Vec::new();
    let mut medians = Vec::new();
    let mut sizes = Vec::new();
    for class in RayTriangleClass::ALL {
        let inputs = class.name();
        let mut rng = cfg.rng("ray_triangle", inputs);
        let cases: Vec<Case> = std::iter::repeat_with(|| {
            let (o, d, v) = ray_triangle_case(class, &mut rng);
            Case::new(o, d, v)
        })
        .flatten()
        .take(checked)
        .collect();
        let want: Vec<Option<(BigInt, BigInt)>> = cases.iter().map(exact).collect();
        let times = time_methods(cfg, &cases[..cfg.working_set.min(cases.len())], &methods);
        for (m, ns) in methods.iter().zip(times) {
            let mut errors = 0;
            let mut ulps = Vec::new();
            let mut bounds = Vec::new();
            for (c, w) in cases.iter().zip(&want) {
                match (m.answer(c), w) {
                    (Some(t), Some(w)) => {
                        let rounded = oracle::ratio_to_f64(&w.0, &w.1);
                        if t.is_finite() && rounded.is_finite() {
                            ulps.push(oracle::ulps_between(t, rounded) as f64);
                        }
                        if m.name() == BOUNDED {
                            let (outside, size) = bounded_check(c, w).unwrap_or((true, 0.0));
                            errors += outside as u64;
                            bounds.push(size);
                        }
                    }
                    (None, None) => {}
                    _ => errors += 1,
                }
            }
            let max = ulps.iter().copied().fold(0.0, f64::max);
            if !bounds.is_empty() {
                let largest = bounds.iter().copied().fold(0.0, f64::max);
                sizes.push((inputs, m.name(), median(bounds), largest));
            }
            medians.push((inputs, m.name(), median(ulps.clone())));
            rows.push(Row {
                family: "ray_triangle",
                method: m.name().to_string(),
                inputs: inputs.to_string(),
                ns_per_op: ns,
                cases: cases.len() as u64,
                errors,
                max_ulps: Some(max),
                max_bound_ulps: None,
            });
        }
    }
    rows.extend(shared_edges(cfg, &methods));
    let mut text = String::from(
        "ray_triangle: median ulps of `t` from the correctly rounded exact `t`, over the hits a method gets right:\n\n\
         | inputs | method | median ulps |\n|---|---|---|\n",
    );
    for (inputs, name, m) in medians {
        text += &format!("| {inputs} | {name} | {m} |\n");
    }
    text += "\nThe certified bounds on `t` of the methods that return one, in ulps of their `t` \
             (every exact `t` lies inside its bound, or the answer counts as an error):\n\n\
             | inputs | method | median bound (ulps) | largest bound (ulps) |\n|---|---|---|---|\n";
    for (inputs, name, med, largest) in sizes {
        text += &format!("| {inputs} | {name} | {med:.0} | {largest:.0} |\n");
    }
    text += "\n`exactray-exact-prepare` is ns per ray of `ExactRay::new` alone; `exactray-exact-prepared` and \
             `exactray-exact-bounded` are ns per triangle with the ray prepared beforehand (its two tiers: `t` within 4 \
             ulps, or with its certified bound). A mesh pays the first once per ray and the second per triangle it \
             tests; `exactray-exact` pays both on every call.\n";
    text += "\nOn `shared-edges` the errors are false misses: rays aimed at a shared edge or vertex of a tiled \
             height field that no triangle of the mesh reports; `cases` counts rays, ns/op is per \
             ray–triangle test. Coplanar rays count as misses everywhere (the crate's convention).";
    note("ray_triangle", text);
    rows
}

/// Rays at the shared edges and vertices of a 16 x 16 tiled height field:
/// timed per ray–triangle test against the triangles around the target;
/// a false miss is a ray that none of the mesh's triangles reports.
///
/// Only rays that pass through the surface at the target count: their
/// exact line meets a triangle around it, and every triangle around it
/// that it meets, it meets from the front. A line through a point within
/// rounding of a silhouette edge (a ridge, with one triangle seen from the
/// front and one from behind) only touches the surface there; it may pass
/// over the ridge and leave the mesh without a hit, and no variant, however
/// watertight, owes it one.
fn shared_edges(cfg: &Config, methods: &Methods) -> Vec<Row> {
    let mut rng = cfg.rng("ray_triangle", "shared-edges");
    let mesh = TiledMesh::new(&mut rng, 16);
    let (edges, inner) = (mesh.interior_edges(), mesh.interior_vertices());
    let rays = cfg.cases / 10;
    let mut timed = Vec::new();
    let mut counted = Vec::new();
    for _ in 0..rays {
        let (o, d, around) = mesh.shared_edge_ray(&mut rng, &edges, &inner);
        let near: Vec<Case> = around
            .iter()
            .filter_map(|&k| Case::new(o, d, mesh.triangle(k)))
            .collect();
        let lines: Vec<_> = near.iter().map(line).collect();
        let meets = lines.iter().any(|l| l.t.is_some());
        if meets && lines.iter().all(|l| l.t.is_none() || l.front) {
            counted.push((o, d));
        }
        timed.extend(near);
    }
    if counted.len() < rays {
        note(
            "ray_triangle",
            format!(
                "shared-edges: {} of {rays} rays left out of the false-miss count: their exact line meets none of \
                 the triangles around the target, or meets one from behind (it only touches a ridge there).",
                rays - counted.len()
            ),
        );
    }
    let times = time_methods(cfg, &timed[..cfg.working_set.min(timed.len())], methods);
    methods
        .iter()
        .zip(times)
        .map(|(m, ns)| {
            let misses = counted
                .iter()
                .filter(|(o, d)| {
                    (0..mesh.triangles.len())
                        .filter_map(|k| Case::new(*o, *d, mesh.triangle(k)))
                        .all(|c| m.answer(&c).is_none())
                })
                .count();
            Row {
                family: "ray_triangle",
                method: m.name().to_string(),
                inputs: "shared-edges".to_string(),
                ns_per_op: ns,
                cases: counted.len() as u64,
                errors: misses as u64,
                max_ulps: None,
                max_bound_ulps: None,
            }
        })
        .collect()
}
