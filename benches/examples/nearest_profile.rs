//! A driver for instruction counts of nearest-point queries under
//! `valgrind --tool=callgrind`, which are deterministic where wall-clock
//! times on a shared machine are not:
//!
//! ```text
//! cargo build --release -p exactray-bench --example nearest_profile
//! valgrind --tool=callgrind --toggle-collect='*nearest_profile*queries_*' \
//!     target/release/examples/nearest_profile uniform 1000000 10000
//! ```
//! Builds the report's point set (`exactray::testing::nearest_points`:
//! `uniform`, `clustered` or `off-distribution`, N points) and runs Q of the
//! report's queries through exactray and kiddo, each in a function of its
//! own (`queries_exactray`, `queries_kiddo`), so that callgrind's
//! per-function inclusive counts divided by Q give instructions per query.
//! A fourth argument `time` prints same-run time ratios instead. Stands
//! alone: the inputs from `exactray::testing`, kiddo's and rstar's calls
//! from `exactray-peers`, as the report has them.

use exactray::bvh::SphereBvh;
use exactray::testing::{PointDistribution as Dist, nearest_points, nearest_queries};
use exactray_peers::nearest::{KiddoTree, Point, kiddo_build, kiddo_nearest, rstar_build};
use glam::DVec3;
use std::hint::black_box;
use std::time::{Duration, Instant};

#[inline(never)]
fn queries_exactray(tree: &SphereBvh, qs: &[DVec3]) -> usize {
    qs.iter()
        .map(|q| black_box(tree).nearest(*q).map_or(0, |n| n.index))
        .sum()
}

#[inline(never)]
fn queries_kiddo(tree: &KiddoTree, qs: &[DVec3]) -> usize {
    qs.iter()
        .map(|q| kiddo_nearest(black_box(tree), &q.to_array()))
        .sum()
}

/// One pass of `f` over the queries, as the report times a method: each
/// query and answer through `black_box`.
fn time(qs: &[DVec3], f: impl Fn(&DVec3) -> Option<Point>) -> Duration {
    let start = Instant::now();
    for q in qs {
        black_box(f(black_box(q)));
    }
    start.elapsed()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dist = match args.first().map(String::as_str) {
        Some("clustered") => Dist::Clustered,
        Some("off-distribution") => Dist::OffDistribution,
        _ => Dist::Uniform,
    };
    let n = args
        .get(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let q = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(10_000);
    let which = args.get(3).map_or("both", String::as_str);
    let points: Vec<Point> = nearest_points(dist, n).collect();
    let qs: Vec<DVec3> = nearest_queries(dist, n, q).collect();
    if which == "time" {
        // Same-run ratios with the report's own methods (kiddo's answer
        // includes fetching its point, as exactray's does): the methods
        // alternate, 15 rounds, and the median per-round ratios are printed.
        let tree = SphereBvh::from_points(&points).expect("finite points");
        let (kiddo, rstar) = (kiddo_build(&points), rstar_build(&points));
        let e = || time(&qs, |q| tree.nearest(*q).map(|n| n.point.to_array()));
        let k = || time(&qs, |q| Some(points[kiddo_nearest(&kiddo, &q.to_array())]));
        let r = || time(&qs, |q| rstar.nearest_neighbor(q.to_array()).copied());
        let mut rounds: Vec<[f64; 3]> = (0..15)
            .map(|_| [e(), k(), r()].map(|t| t.as_secs_f64() * 1e9 / q as f64))
            .collect();
        let median = |f: &dyn Fn(&[f64; 3]) -> f64, rounds: &mut Vec<[f64; 3]>| {
            rounds.sort_by(|a, b| f(a).total_cmp(&f(b)));
            f(&rounds[rounds.len() / 2])
        };
        println!(
            "{} {n}: exactray {:.0} ns, / kiddo {:.3}, / rstar {:.3}",
            dist.name(),
            median(&|t| t[0], &mut rounds),
            median(&|t| t[0] / t[1], &mut rounds),
            median(&|t| t[0] / t[2], &mut rounds),
        );
        return;
    }
    let mut check = (0, 0);
    if which != "kiddo" {
        let tree = SphereBvh::from_points(&points).expect("finite points");
        check.0 = queries_exactray(&tree, &qs);
        let mut stats = exactray::bvh::QueryStats::default();
        for q in &qs {
            tree.nearest_with_stats(*q, &mut stats);
        }
        println!(
            "exactray: {:.1} nodes, {:.1} distances per query",
            stats.nodes_visited as f64 / q as f64,
            stats.distances_computed as f64 / q as f64
        );
    }
    if which != "exactray" {
        let tree = kiddo_build(&points);
        check.1 = queries_kiddo(&tree, &qs);
    }
    println!("{} {n} points, {q} queries: {check:?}", dist.name());
}
