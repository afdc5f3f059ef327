//! nearest_build: building the nearest-point indexes of the `nearest`
//! family (the same point sets), timed per point, with the heap each index
//! holds.

use crate::framework::{Config, Row, median, note};
use crate::heap::held_by;
use crate::nearest::{Dist, Point, exactray_build, inputs, kiddo_build, points, rstar_build};
use std::hint::black_box;
use std::time::Instant;

/// Builds an index of the points, drops it; the time of the build alone.
type Build = fn(&[Point]) -> f64;

fn timed<T>(build: impl FnOnce() -> T) -> f64 {
    let start = Instant::now();
    let index = black_box(build());
    let t = start.elapsed().as_secs_f64();
    drop(index);
    t
}

/// Heap bytes held by a freshly built index, measured; and the index's own
/// account of them where it gives one.
type Held = fn(&[Point]) -> (usize, Option<usize>);

const METHODS: [(&str, Build, Held); 3] = [
    (
        "exactray",
        |p| timed(|| exactray_build(p)),
        |p| {
            let (t, bytes) = held_by(|| exactray_build(p));
            (bytes, Some(t.memory_bytes()))
        },
    ),
    (
        "kiddo",
        |p| timed(|| kiddo_build(p)),
        |p| (held_by(|| kiddo_build(p)).1, None),
    ),
    (
        "rstar",
        |p| timed(|| rstar_build(p)),
        |p| (held_by(|| rstar_build(p)).1, None),
    ),
];

/// Timed builds per method at `n` points.
fn reps(cfg: &Config, n: usize) -> usize {
    match (cfg.quick, n) {
        (true, n) if n >= 1_000_000 => 3,
        (true, _) => 5,
        (false, n) if n >= 1_000_000 => 5,
        (false, n) if n >= 100_000 => 7,
        (false, _) => 11,
    }
}

/// The `nearest_build` family: one row per (inputs, method), ns per point.
pub fn run(cfg: &Config) -> Vec<Row> {
    let sizes = crate::nearest::Sizes::new(cfg);
    let mut rows = Vec::new();
    let mut body = Vec::new();
    for dist in [Dist::Uniform, Dist::Clustered] {
        for &n in &sizes.ns {
            let pts = points(dist, n);
            let reps = reps(cfg, n);
            // Repetitions interleave the methods, as in the other families.
            let mut samples = vec![Vec::with_capacity(reps); METHODS.len()];
            for _ in 0..reps {
                for ((_, build, _), s) in METHODS.iter().zip(&mut samples) {
                    s.push(build(&pts) * 1e9 / n as f64);
                }
            }
            // After the timed builds, so that rayon's pool and other one-off
            // allocations are already in place.
            let measured: Vec<(usize, Option<usize>)> =
                METHODS.iter().map(|(_, _, held)| held(&pts)).collect();
            let held: Vec<f64> = measured.iter().map(|m| m.0 as f64 / n as f64).collect();
            let own = measured[0].1.unwrap_or(0) as f64 / n as f64;
            let mut line = vec![inputs(dist, n)];
            for (((name, _, _), s), bytes) in METHODS.iter().zip(samples).zip(&held) {
                let ns = median(s);
                line.push(format!("{ns:.1} ns, {bytes:.1} B"));
                rows.push(Row {
                    family: "nearest_build",
                    method: name.to_string(),
                    inputs: inputs(dist, n),
                    ns_per_op: ns,
                    cases: 0,
                    errors: 0,
                    max_ulps: None,
                    max_bound_ulps: None,
                });
            }
            line.push(format!("{own:.1} B"));
            line.push(reps.to_string());
            body.push(line);
        }
    }
    note(
        "nearest_build",
        format!(
            "**nearest_build**: ns/op is the build time **per point** (median over the `builds` listed, methods \
             interleaved; the time to free an index is not counted), from a `&[[f64; 3]]` of the `nearest` family's \
             points (`off-distribution` shares the clustered ones): `SphereBvh::from_points` (subtrees built on \
             rayon's pool under the default `rayon` feature), kiddo's `ImmutableKdTree::new_from_slice` (its default: \
             built on rayon's pool from 262,144 points on) and rstar's `RTree::bulk_load` (sequential; its time \
             includes copying the slice into the `Vec` it consumes). No \
             answer is checked here (`cases` 0); the `nearest` family checks the same indexes. Memory is **heap bytes \
             per point** held by the built index, measured by the report's counting global allocator (live bytes \
             after the build, index alive, less those before; scratch freed during the build is not counted, \
             allocator overhead is not included); `exactray own` is `SphereBvh::memory_bytes()` per point, for \
             comparison. The points themselves take 24 B per point.\n\n{}",
            crate::output::markdown(
                &[
                    "inputs",
                    "exactray",
                    "kiddo",
                    "rstar",
                    "exactray own",
                    "builds"
                ],
                &body
            )
        ),
    );
    rows
}
