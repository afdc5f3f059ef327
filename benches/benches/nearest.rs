//! Criterion benchmarks of nearest-point queries at 10^5 and 10^6 points,
//! uniform and clustered, for exactray's `SphereBvh` (one query at a time and
//! `nearest_many`), `kiddo` and `rstar`; and of building each index.
//!
//! The point sets and queries are the report's (`exactray::testing`), the
//! peers' calls the report's (`exactray-peers`); query times are per query,
//! build times per index.

use criterion::measurement::WallTime;
use criterion::{BatchSize, BenchmarkGroup, Criterion, criterion_group, criterion_main};
use exactray::bvh::SphereBvh;
use exactray::testing::{PointDistribution, nearest_points, nearest_queries};
use exactray_peers::nearest::{Point, kiddo_build, kiddo_nearest, rstar_build};
use glam::DVec3;
use std::hint::black_box;
use std::time::{Duration, Instant};

const NS: [usize; 2] = [100_000, 1_000_000];
const DISTS: [PointDistribution; 2] = [PointDistribution::Uniform, PointDistribution::Clustered];
/// Queries per pass: enough that the batch has work for every thread.
const QUERIES: usize = 4096;

fn exactray_build(points: &[Point]) -> SphereBvh {
    SphereBvh::from_points(points).expect("finite points")
}

/// One criterion iteration is one query: whole passes over the queries
/// (`pass` answers them all once), the time scaled back.
fn per_query(
    group: &mut BenchmarkGroup<WallTime>,
    name: &str,
    queries: usize,
    mut pass: impl FnMut(),
) {
    group.bench_function(name, |b| {
        b.iter_custom(|iters| {
            let passes = iters.div_ceil(queries as u64);
            let start = Instant::now();
            for _ in 0..passes {
                pass();
            }
            let t = start.elapsed();
            t.mul_f64(iters as f64 / (passes * queries as u64) as f64)
        })
    });
}

fn queries(c: &mut Criterion) {
    for n in NS {
        for dist in DISTS {
            let points: Vec<Point> = nearest_points(dist, n).collect();
            let qs: Vec<DVec3> = nearest_queries(dist, n, QUERIES).collect();
            let tree = exactray_build(&points);
            let kiddo = kiddo_build(&points);
            let rstar = rstar_build(&points);
            let mut group = c.benchmark_group(format!("nearest/{}:{n}", dist.name()));
            per_query(&mut group, "exactray", qs.len(), || {
                for q in black_box(&qs) {
                    black_box(tree.nearest(*q).map(|n| n.point.to_array()));
                }
            });
            let mut out = vec![None; qs.len()];
            per_query(&mut group, "exactray-batch", qs.len(), || {
                tree.nearest_many(black_box(&qs), &mut out)
                    .expect("as many answers as queries");
                black_box(&mut out);
            });
            per_query(&mut group, "kiddo", qs.len(), || {
                for q in black_box(&qs) {
                    black_box(points[kiddo_nearest(&kiddo, &q.to_array())]);
                }
            });
            per_query(&mut group, "rstar", qs.len(), || {
                for q in black_box(&qs) {
                    black_box(rstar.nearest_neighbor(q.to_array()).copied());
                }
            });
            group.finish();
        }
    }
}

fn builds(c: &mut Criterion) {
    let dist = PointDistribution::Uniform;
    for n in NS {
        let points: Vec<Point> = nearest_points(dist, n).collect();
        let mut group = c.benchmark_group(format!("nearest_build/{}:{n}", dist.name()));
        let input = || points.as_slice();
        group.bench_function("exactray", |b| {
            b.iter_batched(input, exactray_build, BatchSize::PerIteration)
        });
        group.bench_function("kiddo", |b| {
            b.iter_batched(input, kiddo_build, BatchSize::PerIteration)
        });
        group.bench_function("rstar", |b| {
            b.iter_batched(input, rstar_build, BatchSize::PerIteration)
        });
        group.finish();
    }
}

criterion_group! {
    name = benches;
    // Short by default: the indexes are built once per input, and a 10^6-point
    // build takes a good part of a second.
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    targets = queries, builds
}
criterion_main!(benches);
