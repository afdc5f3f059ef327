//! A driver for instruction counts of mesh ray queries under
//! `valgrind --tool=callgrind`, which are deterministic where wall-clock
//! times on a shared machine are not:
//!
//! ```text
//! cargo build --release -p exactray-bench --example scene_profile
//! valgrind --tool=callgrind --toggle-collect='*scene_profile*queries_*' \
//!     target/release/examples/scene_profile sphere 100000 diffuse 4000
//! ```
//! Builds one of the report's meshes (`exactray::testing`: `sphere`, the
//! displaced sphere, `terrain` or `room`; N triangles) and Q of its rays
//! (`primary`: camera rays; `diffuse`: bounces spawned from the primary
//! hits; `shadow`: spawned from the primary hits towards the report's
//! light; `blocked-shadow`: in the room, towards a light above the
//! ceiling), then runs them through the closest-hit query
//! (`queries_closest`) and the any-hit query (`queries_any`), each a
//! function of its own, so that callgrind's inclusive counts divided by Q
//! give instructions per ray. A fifth argument `time` prints same-run
//! medians of ns per ray instead (15 alternating rounds); `stats` prints
//! the walk's work per ray; `batch` the speed-up of the rayon batch.

use exactray::interval::Interval;
use exactray::query::ray::{Exact, Ray};
use exactray::scene::{BatchQueries, MeshHit, TraceStats, TriangleMesh, spawn_ray, spawn_ray_to};
use exactray::testing::{
    SceneMesh, SplitMix64, camera_rays, cosine_direction, displaced_sphere, room, room_camera_rays,
    terrain,
};
use glam::DVec3;
use std::hint::black_box;
use std::time::Instant;

#[inline(never)]
fn queries_closest(mesh: &TriangleMesh, rays: &[(Ray, Interval)]) -> usize {
    rays.iter()
        .filter(|(r, i)| black_box(mesh).closest_hit(r, *i).is_some())
        .count()
}

#[inline(never)]
fn queries_any(mesh: &TriangleMesh, rays: &[(Ray, Interval)]) -> usize {
    rays.iter()
        .filter(|(r, i)| black_box(mesh).occluded(r, *i))
        .count()
}

/// The rays of `kind` on `data` (see the module docs).
fn rays(
    room_scene: bool,
    data: &SceneMesh,
    mesh: &TriangleMesh,
    kind: &str,
    q: usize,
) -> Vec<(Ray, Interval)> {
    let mut rng = SplitMix64::new(7);
    let camera = if room_scene {
        room_camera_rays(q, &mut rng)
    } else {
        camera_rays(data, q, &mut rng)
    };
    let primaries: Vec<Ray> = camera
        .into_iter()
        .filter_map(|(o, d)| Ray::new(o, d).ok())
        .collect();
    if kind == "primary" {
        return primaries
            .into_iter()
            .map(|r| (r, Interval::FORWARD))
            .collect();
    }
    let hits: Vec<(Ray, MeshHit)> = primaries
        .iter()
        .filter_map(|r| Some((*r, mesh.closest_hit_with::<Exact>(r, Interval::FORWARD)?)))
        .collect();
    let (lo, hi) = data.bounds();
    let light = match (kind, room_scene) {
        ("blocked-shadow", _) => DVec3::new(0.0, 0.0, 10.5),
        (_, true) => DVec3::new(2.0, 1.0, 9.5),
        _ => (lo + hi) * 0.5 + DVec3::new(-0.7, 0.4, 1.0) * (hi - lo).max_element(),
    };
    hits.iter()
        .filter_map(|(r, h)| {
            let n = h.hit.normal;
            let n = if n.dot(r.direction()) > 0.0 { -n } else { n };
            if kind == "diffuse" {
                let ray = spawn_ray(&h.hit, cosine_direction(n, &mut rng)).ok()?;
                Some((ray, Interval::FORWARD))
            } else {
                spawn_ray_to(&h.hit, light).ok()
            }
        })
        .collect()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let room_scene = args.first().is_some_and(|a| a == "room");
    let n = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(100_000);
    let kind = args.get(2).map_or("primary", String::as_str);
    let q = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(4_000);
    let mut rng = SplitMix64::new(1);
    let data = match args.first().map(String::as_str) {
        Some("room") => room(&mut rng, n),
        Some("terrain") => terrain(&mut rng, n),
        _ => displaced_sphere(&mut rng, n),
    };
    let mesh = TriangleMesh::new(&data.vertices, &data.triangles).expect("valid mesh");
    let rays = rays(room_scene, &data, &mesh, kind, q);
    match args.get(4).map(String::as_str) {
        Some("time") => {
            let per_ray = |f: &dyn Fn() -> usize| {
                let t = Instant::now();
                black_box(f());
                t.elapsed().as_secs_f64() * 1e9 / rays.len() as f64
            };
            let mut rounds: Vec<[f64; 2]> = (0..15)
                .map(|_| {
                    [
                        per_ray(&|| queries_closest(&mesh, &rays)),
                        per_ray(&|| queries_any(&mesh, &rays)),
                    ]
                })
                .collect();
            let mut median = |k: usize| {
                rounds.sort_by(|a, b| a[k].total_cmp(&b[k]));
                rounds[rounds.len() / 2][k]
            };
            println!(
                "{kind} {n}: closest {:.0} ns, any {:.0} ns per ray",
                median(0),
                median(1)
            );
        }
        Some("batch") => {
            // `closest_hits` on this thread against `par_closest_hits` on
            // rayon's pool, in calls of `chunk` rays (the report's 2048,
            // and all the rays at once), alternating, 15 rounds.
            let plain: Vec<Ray> = rays.iter().map(|r| r.0).collect();
            for chunk in [2048, plain.len()] {
                let mut out = vec![None; plain.len()];
                let pass = |parallel: bool, out: &mut [Option<MeshHit>]| {
                    let t = Instant::now();
                    for (r, o) in plain.chunks(chunk).zip(out.chunks_mut(chunk)) {
                        let done = if parallel {
                            mesh.par_closest_hits(r, Interval::FORWARD, o)
                        } else {
                            mesh.closest_hits(r, Interval::FORWARD, o)
                        };
                        done.expect("one answer per ray");
                    }
                    t.elapsed().as_secs_f64()
                };
                let mut ratios: Vec<f64> = (0..15)
                    .map(|_| pass(false, &mut out) / pass(true, &mut out))
                    .collect();
                ratios.sort_by(f64::total_cmp);
                println!(
                    "{kind} {n}, calls of {chunk} rays: 2 threads {:.2}x faster than 1 (median of 15)",
                    ratios[7]
                );
            }
        }
        Some("stats") => {
            let mut stats = TraceStats::default();
            for (r, i) in &rays {
                mesh.closest_hit_with_stats::<exactray::query::ray::Watertight>(r, *i, &mut stats);
            }
            let per = |x: u64| x as f64 / rays.len() as f64;
            println!(
                "{kind} {n}: {:.1} nodes, {:.1} boxes, {:.1} triangles per closest-hit ray",
                per(stats.nodes_visited),
                per(stats.boxes_tested),
                per(stats.triangles_tested)
            );
        }
        _ => {
            let closest = queries_closest(&mesh, &rays);
            let any = queries_any(&mesh, &rays);
            println!(
                "{kind} {n}: {} rays, {closest} hit, {any} blocked, {} bytes of hierarchy per triangle",
                rays.len(),
                mesh.bvh_bytes() as f64 / data.triangles.len() as f64
            );
        }
    }
}
