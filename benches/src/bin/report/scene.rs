//! closest_hit, any_hit and spawn: ray queries over triangle meshes of
//! 10^5 to 10^6 triangles generated in the crate (`exactray::testing`: a
//! displaced sphere, a terrain, a closed room with objects), beside
//! obvhs's own traversals (`CwBvh`, `Bvh2`, its `f32` triangle test) and
//! parry3d-f64's `TriMesh`.
//!
//! - `closest_hit` inputs: `primary:N` (camera rays at the displaced
//!   sphere), `terrain-primary:N`, `room-primary:N` (from inside the
//!   room), `diffuse:N` and `room-diffuse:N` (cosine-weighted bounces from
//!   the primary hits: incoherent), `far:N` (the sphere moved to `1e7`),
//!   `vertices:N` (rays aimed at mesh vertices, where triangles meet).
//!   Methods: `exactray` (the default watertight test, default builder),
//!   `exactray-ploc` / `exactray-sah` (the other builder), `exactray-exact`,
//!   `obvhs`, `obvhs-bvh2`, `parry3d`, `embree` (Embree 3's
//!   `rtcIntersect1` / `rtcOccluded1` in `f32`, only with the report's
//!   `embree` feature), `exactray-batch` and
//!   `exactray-rayon` (the default query's `closest_hits` on one core and
//!   `par_closest_hits` on rayon's pool, both cores, each writing whole
//!   hits), `brute-force` (the exact test on
//!   every triangle; a few rays, smallest sphere only). `errors`: a hit or
//!   miss that differs from the exact variant's, or a hit on a triangle
//!   that does not contain the exact first hit point (decided with
//!   `exactray-oracle`'s rationals); `max_ulps`: of `t` against the
//!   correctly rounded exact `t`.
//! - `any_hit` inputs: `shadow:N`, `terrain-shadow:N`, `room-shadow:N`:
//!   from spawned primary hit points towards a point light. `errors`:
//!   blocked or unblocked unlike the exact variant. `exactray-closest` is
//!   the default closest-hit query on the same rays (what stopping at the
//!   first blocker saves).
//! - `spawn` inputs: situations on a displaced sphere (`diffuse`,
//!   `reflect`, `grazing`, `far`, `tiny`, `huge`); methods `exactray`
//!   (`spawn_ray`), `epsilon-1e-4`, `epsilon-1e-8` (the hit point moved by
//!   that much along the normal). `errors`: secondary rays whose closest
//!   hit (exact variant) is the triangle they leave; `cases`: rays traced.
//!   `ns_per_op`: spawning and tracing one secondary ray.

use crate::framework::{Config, Measure, Row, method, note, time_methods};
use exactray::bvh::boxes::{BvhBuilder, PlocQuality};
use exactray::interval::Interval;
use exactray::query::ray::{Exact, Ray, Watertight};
use exactray::scene::BatchQueries;
use exactray::scene::{MeshHit, TraceStats, TriangleMesh, reflect_above, spawn_ray, spawn_ray_to};
use exactray::testing::{
    SceneMesh, SplitMix64, camera_rays, cosine_direction, displaced_sphere, room, room_camera_rays,
    terrain,
};
use exactray_oracle::oracle;
use exactray_peers::scene::{ObvhsScene, ParryScene};
use glam::DVec3;
use num_bigint::BigInt;
use std::sync::{Arc, OnceLock};
use std::time::Duration;
use std::time::Instant;

/// One scene and every structure the methods query.
struct Setup {
    name: &'static str,
    data: SceneMesh,
    ours: TriangleMesh,
    other: TriangleMesh,
    obvhs: Option<ObvhsScene>,
    parry: Option<ParryScene>,
    /// Embree's scene (the report's `embree` feature).
    #[cfg(feature = "embree")]
    embree: exactray_peers::scene_embree::EmbreeScene,
}

/// The builder `exactray` does not use by default, and its method name.
fn other_builder() -> (BvhBuilder, &'static str) {
    match BvhBuilder::default() {
        BvhBuilder::BinnedSah => (BvhBuilder::Ploc(PlocQuality::Medium), "exactray-ploc"),
        _ => (BvhBuilder::BinnedSah, "exactray-sah"),
    }
}

impl Setup {
    fn new(name: &'static str, data: SceneMesh, with_obvhs: bool) -> Setup {
        let t = Instant::now();
        let ours = TriangleMesh::new(&data.vertices, &data.triangles)
            .and_then(|m| m.with_normals(&data.normals))
            .expect("generated meshes are valid");
        let built_ours = t.elapsed();
        let t = Instant::now();
        let other = TriangleMesh::with_builder(&data.vertices, &data.triangles, other_builder().0)
            .expect("generated meshes are valid");
        let built_other = t.elapsed();
        let t = Instant::now();
        let obvhs = if with_obvhs { obvhs_scene(&data) } else { None };
        let built_obvhs = t.elapsed();
        let t = Instant::now();
        let parry = ParryScene::new(&data.vertices, &data.triangles);
        let built_parry = t.elapsed();
        let n = data.triangles.len();
        eprintln!(
            "  {name}: {n} triangles built in {:.1} s",
            (built_ours + built_other + built_obvhs + built_parry).as_secs_f64()
        );
        let (cw, b2) = obvhs
            .as_ref()
            .map_or(("-".to_string(), "-".to_string()), |o| {
                let (cw, b2) = o.bytes_per_triangle();
                (format!("{cw:.0}"), format!("{b2:.0}"))
            });
        let ours_bytes = (ours.bvh_bytes() + n * 12 + data.vertices.len() * 24) as f64 / n as f64;
        note(
            "closest_hit",
            format!(
                "{name} ({n} triangles): build exactray {:.0} ms, {} {:.0} ms, obvhs (CwBvh and Bvh2) {:.0} ms, parry3d {:.0} ms; \
                 bytes per triangle: exactray {ours_bytes:.0} (f64 vertices, indices, hierarchy), obvhs CwBvh {cw}, \
                 Bvh2 {b2} (f32 triangles, nodes, indices), parry3d {}",
                built_ours.as_secs_f64() * 1e3,
                other_builder().1,
                built_other.as_secs_f64() * 1e3,
                built_obvhs.as_secs_f64() * 1e3,
                built_parry.as_secs_f64() * 1e3,
                parry.as_ref().map_or("-".to_string(), |p| format!(
                    "{:.0}",
                    p.bytes_per_triangle()
                )),
            ),
        );
        #[cfg(feature = "embree")]
        let embree = {
            let t = Instant::now();
            let embree =
                exactray_peers::scene_embree::EmbreeScene::new(&data.vertices, &data.triangles);
            note(
                "closest_hit",
                format!(
                    "{name}: Embree's scene built and committed in {:.0} ms (its bytes per triangle are not \
                     reported by its API)",
                    t.elapsed().as_secs_f64() * 1e3
                ),
            );
            embree
        };
        Setup {
            name,
            data,
            ours,
            other,
            obvhs,
            parry,
            #[cfg(feature = "embree")]
            embree,
        }
    }

    fn n(&self) -> usize {
        self.data.triangles.len()
    }
}

/// obvhs's structures, built on a thread with a large stack: its `CwBvh`
/// conversion recurses once per level of its `Bvh2`, and on a mesh whose
/// `f32` coordinates collapse (the far sphere) the tree degenerates to a
/// chain deeper than a thread's usual stack. `None` if the build fails.
fn obvhs_scene(data: &SceneMesh) -> Option<ObvhsScene> {
    std::thread::scope(|scope| {
        std::thread::Builder::new()
            .stack_size(4 << 30)
            .spawn_scoped(scope, || ObvhsScene::new(&data.vertices, &data.triangles))
            .ok()?
            .join()
            .ok()
    })
}

/// A ray, its range, and the least `t` an `f32` peer starts it at.
#[derive(Clone, Copy)]
struct Case {
    ray: Ray,
    range: Interval,
    /// `0` for a camera ray; for a ray leaving a surface, the `tnear` a
    /// user of an `f32` peer sets so that the origin's rounding does not
    /// put it back on the surface it leaves (see [`peer_tnear`]).
    peer_tmin: f64,
}

impl Case {
    fn of(o: DVec3, d: DVec3, range: Interval) -> Option<Case> {
        Ray::new(o, d).ok().map(|ray| Case {
            ray,
            range,
            peer_tmin: 0.0,
        })
    }

    /// A ray spawned from the hit `h`: the `f32` peers start it at
    /// [`peer_tnear`].
    fn leaving(ray: Ray, range: Interval, h: &MeshHit) -> Case {
        Case {
            ray,
            range,
            peer_tmin: peer_tnear(&ray, h.hit.normal),
        }
    }

    /// What a peer takes: origin, direction, `tnear` (for the `f32` peers)
    /// and `tfar`.
    fn parts(&self) -> (DVec3, DVec3, f64, f64) {
        (
            self.ray.origin(),
            self.ray.direction(),
            self.peer_tmin,
            self.range.max(),
        )
    }
}

/// The `tnear` that keeps an `f32` peer's ray off the surface it leaves,
/// as a renderer that knows the surface's normal `n` sets it: rounding the
/// origin and the triangle's vertices to `f32` moves each by at most half
/// an `f32` step per coordinate, so the surface comes back within
/// `sum_k step(o_k) |n_k|` of the origin along `n`, which the ray covers at
/// `t = that / |d . n|`; twice that, so that the peer's own test's
/// rounding is covered too.
fn peer_tnear(ray: &Ray, n: DVec3) -> f64 {
    let step = |x: f64| {
        let f = (x as f32).abs();
        f64::from(f.next_up() - f)
    };
    let o = ray.origin();
    let along = (0..3).map(|k| step(o[k]) * n[k].abs()).sum::<f64>();
    2.0 * along / ray.direction().dot(n).abs()
}

/// How much work the scene families do.
struct Sizes {
    /// Rays checked per input (and the first `timed` of them timed).
    checked: usize,
    timed: usize,
    /// Triangle budgets: the displaced sphere's, and the terrain's and
    /// room's.
    spheres: Vec<usize>,
    others: usize,
    /// Secondary rays per spawn situation.
    spawned: usize,
}

impl Sizes {
    fn new(cfg: &Config) -> Sizes {
        if cfg.quick {
            Sizes {
                checked: 4_000,
                timed: 2048,
                spheres: vec![100_000],
                others: 100_000,
                spawned: 20_000,
            }
        } else {
            Sizes {
                checked: 20_000,
                timed: 2048,
                spheres: vec![100_000, 1_000_000],
                others: 250_000,
                spawned: 1_000_000,
            }
        }
    }
}

/// The exact first hit of `c` on `s`, by the exact variant.
fn exact_hit(s: &Setup, c: &Case) -> Option<MeshHit> {
    s.ours.closest_hit_with::<Exact>(&c.ray, c.range)
}

/// The exact parameter of the crossing of `c`'s line with triangle `tri`,
/// as `(num, den)`, `den > 0`; `None` off the triangle.
fn exact_t(s: &Setup, c: &Case, tri: u32) -> Option<(BigInt, BigInt)> {
    let v = s.data.triangles[tri as usize].map(|i| s.data.vertices[i as usize].to_array());
    oracle::line_triangle(c.ray.origin().to_array(), c.ray.direction().to_array(), v).t
}

/// A closest-hit method: `(triangle, t)` or a miss.
type Closest = Box<dyn Measure<Case, Option<(u32, f64)>>>;

/// A shadow-ray method: blocked or not.
type AnyHit = Box<dyn Measure<Case, bool>>;

fn closest_methods(s: &Arc<Setup>) -> Vec<Closest> {
    let (a, b, c, d, e) = (s.clone(), s.clone(), s.clone(), s.clone(), s.clone());
    let mut m: Vec<Closest> = vec![
        method("exactray", move |q: &Case| {
            a.ours
                .closest_hit(&q.ray, q.range)
                .map(|h| (h.triangle, h.hit.t))
        }),
        method(other_builder().1, move |q: &Case| {
            b.other
                .closest_hit(&q.ray, q.range)
                .map(|h| (h.triangle, h.hit.t))
        }),
        method("exactray-exact", move |q: &Case| {
            exact_hit(&c, q).map(|h| (h.triangle, h.hit.t))
        }),
    ];
    if s.obvhs.is_some() {
        m.push(method("obvhs", move |q: &Case| {
            let (o, dir, min, max) = q.parts();
            d.obvhs
                .as_ref()
                .and_then(|b| b.closest_cw(o, dir, min, max))
        }));
        m.push(method("obvhs-bvh2", move |q: &Case| {
            let (o, dir, min, max) = q.parts();
            e.obvhs
                .as_ref()
                .and_then(|b| b.closest_bvh2(o, dir, min, max))
        }));
    }
    if s.parry.is_some() {
        let p = s.clone();
        m.push(method("parry3d", move |q: &Case| {
            let (o, dir, _, max) = q.parts();
            p.parry.as_ref().and_then(|p| p.closest(o, dir, max))
        }));
    }
    #[cfg(feature = "embree")]
    {
        let p = s.clone();
        m.push(method("embree", move |q: &Case| {
            let (o, dir, min, max) = q.parts();
            p.embree.closest(o, dir, min, max)
        }));
    }
    for parallel in [false, true] {
        m.push(Box::new(Batch {
            setup: s.clone(),
            parallel,
        }));
    }
    m
}

/// `closest_hits` (one core) or `par_closest_hits` (rayon's pool) over the
/// whole timed set (every case of a closest-hit input has the range `[0,
/// inf)`): one call per pass, its time divided by the number of rays. Both
/// write each ray's whole `MeshHit` (point, normal, shading normal), which
/// the per-ray methods, keeping only `(triangle, t)`, may leave uncomputed;
/// so the speed-up on two cores is `exactray-batch` over `exactray-rayon`.
struct Batch {
    setup: Arc<Setup>,
    parallel: bool,
}

impl Batch {
    fn run(&self, rays: &[Ray], out: &mut [Option<MeshHit>]) {
        let mesh = &self.setup.ours;
        let done = if self.parallel {
            mesh.par_closest_hits(rays, Interval::FORWARD, out)
        } else {
            mesh.closest_hits(rays, Interval::FORWARD, out)
        };
        done.expect("one answer per ray");
    }
}

impl Measure<Case, Option<(u32, f64)>> for Batch {
    fn name(&self) -> &'static str {
        if self.parallel {
            "exactray-rayon"
        } else {
            "exactray-batch"
        }
    }

    fn answer(&self, case: &Case) -> Option<(u32, f64)> {
        let mut out = [None];
        self.run(&[case.ray], &mut out);
        out[0].map(|h| (h.triangle, h.hit.t))
    }

    fn run_loop(&self, cases: &[Case], iters: u64) -> Duration {
        let rays: Vec<Ray> = cases.iter().map(|c| c.ray).collect();
        let mut out = vec![None; rays.len()];
        let start = Instant::now();
        for _ in 0..iters {
            self.run(std::hint::black_box(&rays), &mut out);
            std::hint::black_box(&mut out);
        }
        start.elapsed()
    }
}

fn any_hit_methods(s: &Arc<Setup>) -> Vec<AnyHit> {
    let (a, b, c, d, e) = (s.clone(), s.clone(), s.clone(), s.clone(), s.clone());
    let f = s.clone();
    let mut m: Vec<AnyHit> = vec![
        method("exactray", move |q: &Case| a.ours.occluded(&q.ray, q.range)),
        // The closest hit on the same rays: what a shadow ray saves.
        method("exactray-closest", move |q: &Case| {
            f.ours.closest_hit(&q.ray, q.range).is_some()
        }),
        method(other_builder().1, move |q: &Case| {
            b.other.occluded(&q.ray, q.range)
        }),
        method("exactray-exact", move |q: &Case| {
            c.ours.occluded_with::<Exact>(&q.ray, q.range)
        }),
    ];
    if s.obvhs.is_some() {
        m.push(method("obvhs", move |q: &Case| {
            let (o, dir, min, max) = q.parts();
            d.obvhs
                .as_ref()
                .is_some_and(|b| b.occluded_cw(o, dir, min, max))
        }));
        m.push(method("obvhs-bvh2", move |q: &Case| {
            let (o, dir, min, max) = q.parts();
            e.obvhs
                .as_ref()
                .is_some_and(|b| b.occluded_bvh2(o, dir, min, max))
        }));
    }
    if s.parry.is_some() {
        let p = s.clone();
        m.push(method("parry3d", move |q: &Case| {
            let (o, dir, _, max) = q.parts();
            p.parry.as_ref().is_some_and(|p| p.occluded(o, dir, max))
        }));
    }
    #[cfg(feature = "embree")]
    {
        let p = s.clone();
        m.push(method("embree", move |q: &Case| {
            let (o, dir, min, max) = q.parts();
            p.embree.occluded(o, dir, min, max)
        }));
    }
    m
}

/// Whether the method's `(tri, t)` is right for the exact hit `want`: the
/// same hit or miss, on a triangle holding the exact first point; with
/// the ulps of `t` from the correctly rounded exact `t`.
fn judge_closest(
    s: &Setup,
    c: &Case,
    got: Option<(u32, f64)>,
    want: Option<&MeshHit>,
) -> Result<f64, ()> {
    match (got, want) {
        (None, None) => Ok(0.0),
        (Some((tri, t)), Some(w)) => {
            let (num, den) = exact_t(s, c, w.triangle).ok_or(())?;
            let same_point = tri == w.triangle
                || exact_t(s, c, tri).is_some_and(|(n2, d2)| &num * &d2 == &n2 * &den);
            if !same_point {
                return Err(());
            }
            Ok(oracle::ulps_between(t, oracle::ratio_to_f64(&num, &den)) as f64)
        }
        _ => Err(()),
    }
}

/// Times and checks the closest-hit methods on one input.
fn closest_rows(
    s: &Arc<Setup>,
    inputs: String,
    cases: &[Case],
    sizes: &Sizes,
    cfg: &Config,
) -> Vec<Row> {
    let methods = closest_methods(s);
    let timed = &cases[..sizes.timed.min(cases.len())];
    let ns = time_methods(cfg, timed, &methods);
    let exact: Vec<Option<MeshHit>> = cases.iter().map(|c| exact_hit(s, c)).collect();
    let mut misses = Vec::new();
    let mut rows: Vec<Row> = methods
        .iter()
        .zip(ns)
        .map(|(m, ns)| {
            let (mut errors, mut max_ulps, mut false_misses) = (0, 0.0f64, 0);
            for (c, want) in cases.iter().zip(&exact) {
                let got = m.answer(c);
                false_misses += usize::from(got.is_none() && want.is_some());
                match judge_closest(s, c, got, want.as_ref()) {
                    Ok(u) => max_ulps = max_ulps.max(u),
                    Err(()) => errors += 1,
                }
            }
            misses.push(format!("{} {false_misses}", m.name()));
            Row {
                family: "closest_hit",
                method: m.name().to_string(),
                inputs: inputs.clone(),
                ns_per_op: ns,
                cases: cases.len() as u64,
                errors,
                max_ulps: Some(max_ulps),
                max_bound_ulps: None,
            }
        })
        .collect();
    let mut stats = TraceStats::default();
    for c in cases {
        s.ours
            .closest_hit_with_stats::<Watertight>(&c.ray, c.range, &mut stats);
    }
    let per_ray = |n: u64| n as f64 / cases.len().max(1) as f64;
    note(
        "closest_hit",
        format!(
            "{inputs}: exactray visits {:.1} nodes, tests {:.1} boxes and {:.1} triangles per ray; false misses (the exact \
             variant hits, the method misses): {}",
            per_ray(stats.nodes_visited),
            per_ray(stats.boxes_tested),
            per_ray(stats.triangles_tested),
            misses.join(", ")
        ),
    );
    if s.name == "sphere" && s.n() <= 200_000 && inputs.starts_with("primary") {
        rows.push(brute_force_row(
            s,
            inputs,
            &cases[..16.min(cases.len())],
            &exact,
            cfg,
        ));
    }
    rows
}

/// The exact test on every triangle (closed triangles, as the exact
/// variant decides them), the lowest `t` (lower index on ties): the
/// definition the hierarchy's answers are held to, up to the order of
/// hits within 4 units of rounding of each other, which the exact variant
/// decides exactly and this loop by the rounded `t`.
fn brute_force_row(
    s: &Arc<Setup>,
    inputs: String,
    cases: &[Case],
    exact: &[Option<MeshHit>],
    cfg: &Config,
) -> Row {
    let b = s.clone();
    let brute: Closest = method("brute-force", move |q: &Case| brute_force(&b, q));
    let ns = time_methods(cfg, cases, &[brute]);
    let errors = cases
        .iter()
        .zip(exact)
        .filter(|(c, w)| judge_closest(s, c, brute_force(s, c), w.as_ref()).is_err())
        .count();
    Row {
        family: "closest_hit",
        method: "brute-force".to_string(),
        inputs,
        ns_per_op: ns[0],
        cases: cases.len() as u64,
        errors: errors as u64,
        max_ulps: None,
        max_bound_ulps: None,
    }
}

fn brute_force(s: &Setup, c: &Case) -> Option<(u32, f64)> {
    (0..s.n())
        .filter_map(|i| {
            let hit = s.ours.triangle(i)?.cast_exact_closed(&c.ray, c.range)?;
            Some((i as u32, hit.t))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)))
}

/// Times and checks the shadow-ray methods on one input.
fn any_hit_rows(
    s: &Arc<Setup>,
    inputs: String,
    cases: &[Case],
    sizes: &Sizes,
    cfg: &Config,
) -> Vec<Row> {
    let methods = any_hit_methods(s);
    let timed = &cases[..sizes.timed.min(cases.len())];
    let ns = time_methods(cfg, timed, &methods);
    let exact: Vec<bool> = cases
        .iter()
        .map(|c| s.ours.occluded_with::<Exact>(&c.ray, c.range))
        .collect();
    let blocked = exact.iter().filter(|&&b| b).count();
    note(
        "any_hit",
        format!(
            "{inputs}: {blocked} of {} rays blocked (exact variant); the f32 peers start each ray at the \
             tnear of its origin's rounding (scene.rs, peer_tnear)",
            cases.len()
        ),
    );
    methods
        .iter()
        .zip(ns)
        .map(|(m, ns)| Row {
            family: "any_hit",
            method: m.name().to_string(),
            inputs: inputs.clone(),
            ns_per_op: ns,
            cases: cases.len() as u64,
            errors: cases
                .iter()
                .zip(&exact)
                .filter(|(c, w)| m.answer(c) != **w)
                .count() as u64,
            max_ulps: None,
            max_bound_ulps: None,
        })
        .collect()
}

/// The camera rays of a scene.
fn primary_cases(s: &Setup, count: usize, rng: &mut SplitMix64) -> Vec<Case> {
    let rays = if s.name == "room" {
        room_camera_rays(count, rng)
    } else {
        camera_rays(&s.data, count, rng)
    };
    rays.into_iter()
        .filter_map(|(o, d)| Case::of(o, d, Interval::FORWARD))
        .collect()
}

/// The primary hits (exact variant), with the ray that found them.
fn primary_hits(s: &Setup, primaries: &[Case]) -> Vec<(Case, MeshHit)> {
    primaries
        .iter()
        .filter_map(|c| exact_hit(s, c).map(|h| (*c, h)))
        .collect()
}

/// The geometric normal of `h` turned towards the side the ray came from.
fn facing(h: &MeshHit, c: &Case) -> DVec3 {
    let n = h.hit.normal;
    if n.dot(c.ray.direction()) > 0.0 {
        -n
    } else {
        n
    }
}

/// Diffuse bounces from the primary hits.
fn diffuse_cases(hits: &[(Case, MeshHit)], rng: &mut SplitMix64) -> Vec<Case> {
    hits.iter()
        .filter_map(|(c, h)| {
            let ray = spawn_ray(&h.hit, cosine_direction(facing(h, c), rng)).ok()?;
            Some(Case::leaving(ray, Interval::FORWARD, h))
        })
        .collect()
}

/// The point light of `shadow:N`: above the scene (inside the room, under
/// its ceiling).
fn light(s: &Setup) -> DVec3 {
    let (lo, hi) = s.data.bounds();
    if s.name == "room" {
        DVec3::new(2.0, 1.0, 9.5)
    } else {
        let size = (hi - lo).max_element();
        (lo + hi) * 0.5 + DVec3::new(-0.7, 0.4, 1.0) * size
    }
}

/// The light of the room's `blocked-shadow:N`: above its ceiling, so that
/// every segment from a point below the ceiling is blocked (by the
/// ceiling or by an object on the way); those from the ceiling itself
/// leave it upwards, unblocked.
const BLOCKED_LIGHT: DVec3 = DVec3::new(0.0, 0.0, 10.5);

/// Shadow rays from the primary hits to a point light.
fn shadow_cases(light: DVec3, hits: &[(Case, MeshHit)]) -> Vec<Case> {
    hits.iter()
        .filter_map(|(_, h)| {
            let (ray, range) = spawn_ray_to(&h.hit, light).ok()?;
            Some(Case::leaving(ray, range, h))
        })
        .collect()
}

/// Rays from the camera aimed at mesh vertices: where triangles meet, and
/// where a test that is not watertight lets rays through.
fn vertex_cases(s: &Setup, count: usize, rng: &mut SplitMix64) -> Vec<Case> {
    let eye = primary_cases(s, 1, rng)[0].ray.origin();
    (0..count)
        .filter_map(|_| {
            let v = s.data.vertices[(rng.next_u64() % s.data.vertices.len() as u64) as usize];
            Case::of(eye, v - eye, Interval::FORWARD)
        })
        .collect()
}

/// The scenes, built once per run for both families (the far sphere
/// last).
fn setups(cfg: &Config) -> &'static [Arc<Setup>] {
    static SETUPS: OnceLock<Vec<Arc<Setup>>> = OnceLock::new();
    SETUPS.get_or_init(|| {
        let sizes = Sizes::new(cfg);
        let mut rng = cfg.rng("closest_hit", "scenes");
        let mut out: Vec<Arc<Setup>> = sizes
            .spheres
            .iter()
            .map(|&n| Arc::new(Setup::new("sphere", displaced_sphere(&mut rng, n), true)))
            .collect();
        out.push(Arc::new(Setup::new("terrain", terrain(&mut rng, sizes.others), true)));
        out.push(Arc::new(Setup::new("room", room(&mut rng, sizes.others), true)));
        // Every coordinate near 1e7, where f32's spacing is 1: obvhs's
        // f32 copy of the unit sphere collapses to a few points, and its
        // build of that took 173 s in a quick run (and its CwBvh
        // conversion overflowed an 8 MiB stack), so obvhs is left out.
        let far = displaced_sphere(&mut rng, sizes.spheres[0]).translated(DVec3::splat(1e7));
        out.push(Arc::new(Setup::new("far", far, false)));
        note(
            "closest_hit",
            "far: obvhs is not measured (its f32 copy of the sphere at 1e7 collapses to a few points; \
             building it took 173 s in a quick run)."
                .to_string(),
        );
        out
    })
}

/// The scene's name as an inputs prefix: none for the sphere, whose
/// inputs are the plain `primary:N`, `diffuse:N`, ... of `docs/report.md`.
fn prefix(s: &Setup) -> String {
    match s.name {
        "sphere" | "far" => String::new(),
        name => format!("{name}-"),
    }
}

/// Runs `closest_hit`.
pub fn run_closest(cfg: &Config) -> Vec<Row> {
    let sizes = Sizes::new(cfg);
    let mut rows = Vec::new();
    for s in setups(cfg) {
        let (n, p) = (s.n(), prefix(s));
        let mut rng = cfg.rng("closest_hit", &format!("{}:{n}", s.name));
        let primaries = primary_cases(s, sizes.checked, &mut rng);
        if s.name == "far" {
            rows.extend(closest_rows(s, format!("far:{n}"), &primaries, &sizes, cfg));
            continue;
        }
        rows.extend(closest_rows(
            s,
            format!("{p}primary:{n}"),
            &primaries,
            &sizes,
            cfg,
        ));
        if s.name != "terrain" {
            let diffuse = diffuse_cases(&primary_hits(s, &primaries), &mut rng);
            rows.extend(closest_rows(
                s,
                format!("{p}diffuse:{n}"),
                &diffuse,
                &sizes,
                cfg,
            ));
        }
        if s.name == "sphere" {
            let vertices = vertex_cases(s, sizes.checked, &mut rng);
            rows.extend(closest_rows(
                s,
                format!("vertices:{n}"),
                &vertices,
                &sizes,
                cfg,
            ));
        }
    }
    rows
}

/// Runs `any_hit`.
pub fn run_any_hit(cfg: &Config) -> Vec<Row> {
    let sizes = Sizes::new(cfg);
    let mut rows = Vec::new();
    for s in setups(cfg).iter().filter(|s| s.name != "far") {
        let (n, p) = (s.n(), prefix(s));
        let mut rng = cfg.rng("any_hit", &format!("{}:{n}", s.name));
        let primaries = primary_cases(s, sizes.checked, &mut rng);
        let hits = primary_hits(s, &primaries);
        let shadows = shadow_cases(light(s), &hits);
        rows.extend(any_hit_rows(
            s,
            format!("{p}shadow:{n}"),
            &shadows,
            &sizes,
            cfg,
        ));
        if s.name == "room" {
            let blocked = shadow_cases(BLOCKED_LIGHT, &hits);
            rows.extend(any_hit_rows(
                s,
                format!("blocked-shadow:{n}"),
                &blocked,
                &sizes,
                cfg,
            ));
        }
    }
    rows
}

/// A secondary ray to spawn: the hit it leaves, its triangle, a direction.
#[derive(Clone, Copy)]
struct Leave {
    hit: MeshHit,
    direction: DVec3,
}

/// The hit point moved by `eps` along the normal, to the side the
/// direction points to: the fixed offset many renderers use.
fn epsilon_ray(l: &Leave, eps: f64) -> Option<Ray> {
    let n = l.hit.hit.normal;
    let side = if n.dot(l.direction) < 0.0 { -n } else { n };
    Ray::new(l.hit.hit.point + side * eps, l.direction).ok()
}

type Spawner = fn(&Leave) -> Option<Ray>;

const SPAWNERS: [(&str, Spawner); 3] = [
    ("exactray", |l| spawn_ray(&l.hit.hit, l.direction).ok()),
    ("epsilon-1e-4", |l| epsilon_ray(l, 1e-4)),
    ("epsilon-1e-8", |l| epsilon_ray(l, 1e-8)),
];

/// A direction leaving the surface at `elevation` radians above it (a
/// random azimuth), on the side `n` points to.
fn at_elevation(n: DVec3, elevation: f64, rng: &mut SplitMix64) -> DVec3 {
    let (a, b) = n.any_orthonormal_pair();
    let phi = std::f64::consts::TAU * rng.next_f64();
    (a * phi.cos() + b * phi.sin()) * elevation.cos() + n * elevation.sin()
}

/// The situations: a name, the sphere's scale and offset, and how the
/// secondary direction is drawn from a primary hit.
fn leaves(
    name: &str,
    mesh: &TriangleMesh,
    hits: &[(Case, MeshHit)],
    rng: &mut SplitMix64,
) -> Vec<Leave> {
    hits.iter()
        .map(|(c, h)| {
            let n = facing(h, c);
            let direction = match name {
                "reflect" => {
                    let shading = h.shading_normal.unwrap_or(n);
                    let shading = if shading.dot(n) < 0.0 {
                        -shading
                    } else {
                        shading
                    };
                    reflect_above(c.ray.direction(), shading, n)
                }
                // Elevations from 1e-6 to 1e-2 radians, log-uniform.
                "grazing" => at_elevation(n, 10f64.powf(-6.0 + 4.0 * rng.next_f64()), rng),
                _ => cosine_direction(n, rng),
            };
            let _ = mesh;
            Leave { hit: *h, direction }
        })
        .collect()
}

/// Runs `spawn`: for each situation, the secondary rays of every method
/// traced with the exact variant, a self-intersection counted where the
/// closest hit is the triangle left; timed as spawn plus the default
/// closest-hit query.
pub fn run_spawn(cfg: &Config) -> Vec<Row> {
    let sizes = Sizes::new(cfg);
    let mut rng = cfg.rng("spawn", "sphere");
    let base = displaced_sphere(&mut rng, 100_000);
    let situations: [(&str, f64, f64); 6] = [
        ("diffuse", 1.0, 0.0),
        ("reflect", 1.0, 0.0),
        ("grazing", 1.0, 0.0),
        ("far", 1.0, 1e8),
        ("tiny", 1e-30, 0.0),
        ("huge", 1e30, 0.0),
    ];
    let mut rows = Vec::new();
    for (name, scale, offset) in situations {
        let data = SceneMesh {
            vertices: base
                .vertices
                .iter()
                .map(|&p| p * scale + DVec3::splat(offset))
                .collect(),
            triangles: base.triangles.clone(),
            normals: base.normals.clone(),
        };
        let mesh = Arc::new(
            TriangleMesh::new(&data.vertices, &data.triangles)
                .and_then(|m| m.with_normals(&data.normals))
                .expect("generated meshes are valid"),
        );
        let mut rng = cfg.rng("spawn", name);
        // Camera rays until `spawned` of them hit (about half do): one
        // secondary ray per primary hit.
        let mut hits: Vec<(Case, MeshHit)> = Vec::with_capacity(sizes.spawned);
        while hits.len() < sizes.spawned {
            let batch = camera_rays(&data, sizes.spawned, &mut rng);
            hits.extend(batch.into_iter().filter_map(|(o, d)| {
                let c = Case::of(o, d, Interval::FORWARD)?;
                mesh.closest_hit_with::<Exact>(&c.ray, c.range)
                    .map(|h| (c, h))
            }));
        }
        hits.truncate(sizes.spawned);
        let cases = leaves(name, &mesh, &hits, &mut rng);
        let methods: Vec<Box<dyn Measure<Leave, Option<u32>>>> = SPAWNERS
            .iter()
            .map(|&(method_name, spawn)| {
                let m = mesh.clone();
                method(method_name, move |l: &Leave| {
                    let ray = spawn(l)?;
                    m.closest_hit_with::<Watertight>(&ray, Interval::FORWARD)
                        .map(|h| h.triangle)
                })
            })
            .collect();
        let ns = time_methods(cfg, &cases[..sizes.timed.min(cases.len())], &methods);
        for (&(method_name, spawn), ns) in SPAWNERS.iter().zip(ns) {
            let errors = cases
                .iter()
                .filter(|l| {
                    spawn(l).is_some_and(|ray| {
                        mesh.closest_hit_with::<Exact>(&ray, Interval::FORWARD)
                            .is_some_and(|h| h.triangle == l.hit.triangle)
                    })
                })
                .count();
            rows.push(Row {
                family: "spawn",
                method: method_name.to_string(),
                inputs: name.to_string(),
                ns_per_op: ns,
                cases: cases.len() as u64,
                errors: errors as u64,
                max_ulps: None,
                max_bound_ulps: None,
            });
        }
    }
    rows
}
