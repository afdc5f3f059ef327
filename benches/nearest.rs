//! Criterion benchmarks of nearest-point queries at 10^5 and 10^6 points,
//! uniform and clustered, for exactray's `SphereBvh` (one query at a time and
//! `nearest_many`), `kiddo` and `rstar`; and of building each index.
//!
//! The point sets, queries, methods and timed loop are the report's own
//! (`examples/report/nearest.rs`), so both measure the same code the same
//! way; query times are per query, build times per index.

#[allow(dead_code)]
#[path = "../examples/report/framework.rs"]
mod framework;
#[allow(dead_code)]
#[path = "../examples/report/nearest.rs"]
mod nearest;
#[allow(dead_code)]
#[path = "../examples/report/output.rs"]
mod output;

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use nearest::{Dist, Indexes};
use std::time::Duration;

const NS: [usize; 2] = [100_000, 1_000_000];
const DISTS: [Dist; 2] = [Dist::Uniform, Dist::Clustered];
const METHODS: [&str; 4] = ["exactray", "exactray-batch", "kiddo", "rstar"];
/// Queries per pass: enough that the batch has work for every thread.
const QUERIES: usize = 4096;

fn queries(c: &mut Criterion) {
    for n in NS {
        for dist in DISTS {
            let ix = Indexes::build(nearest::points(dist, n));
            let qs = nearest::queries(dist, n, QUERIES);
            let mut group = c.benchmark_group(format!("nearest/{}", nearest::inputs(dist, n)));
            for m in nearest::methods(&ix)
                .iter()
                .filter(|m| METHODS.contains(&m.name()))
            {
                group.bench_function(m.name(), |b| {
                    // One criterion iteration is one query: run whole passes
                    // over the queries and scale the time back.
                    b.iter_custom(|iters| {
                        let passes = iters.div_ceil(qs.len() as u64);
                        let t = m.run_loop(&qs, passes);
                        t.mul_f64(iters as f64 / (passes * qs.len() as u64) as f64)
                    })
                });
            }
            group.finish();
        }
    }
}

fn builds(c: &mut Criterion) {
    for n in NS {
        let points = nearest::points(Dist::Uniform, n);
        let mut group = c.benchmark_group(format!(
            "nearest_build/{}",
            nearest::inputs(Dist::Uniform, n)
        ));
        let input = || points.as_slice();
        group.bench_function("exactray", |b| {
            b.iter_batched(input, nearest::exactray_build, BatchSize::PerIteration)
        });
        group.bench_function("kiddo", |b| {
            b.iter_batched(input, nearest::kiddo_build, BatchSize::PerIteration)
        });
        group.bench_function("rstar", |b| {
            b.iter_batched(input, nearest::rstar_build, BatchSize::PerIteration)
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
