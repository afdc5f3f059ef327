//! A driver for instruction counts of nearest-point queries under
//! `valgrind --tool=callgrind`, which are deterministic where wall-clock
//! times on a shared machine are not:
//!
//! ```text
//! cargo build --release --example nearest_profile
//! valgrind --tool=callgrind --toggle-collect='*nearest_profile*queries_*' \
//!     target/release/examples/nearest_profile uniform 1000000 10000
//! ```
//! Builds the report's point set (`uniform`, `clustered` or
//! `off-distribution`, N points) and runs Q of the report's queries through
//! exactray and kiddo, each in a function of its own (`queries_exactray`,
//! `queries_kiddo`), so that callgrind's per-function inclusive counts
//! divided by Q give instructions per query.

#[allow(dead_code)]
#[path = "report/framework.rs"]
mod framework;
#[allow(dead_code)]
#[path = "report/nearest.rs"]
mod nearest;
#[allow(dead_code)]
#[path = "report/output.rs"]
mod output;

use exactray::bvh::SphereBvh;
use glam::DVec3;
use nearest::{Dist, KiddoTree};
use std::hint::black_box;

#[inline(never)]
fn queries_exactray(tree: &SphereBvh, qs: &[DVec3]) -> usize {
    qs.iter()
        .map(|q| black_box(tree).nearest(*q).map_or(0, |n| n.index))
        .sum()
}

#[inline(never)]
fn queries_kiddo(tree: &KiddoTree, qs: &[DVec3]) -> usize {
    qs.iter()
        .map(|q| nearest::kiddo_nearest(black_box(tree), &q.to_array()))
        .sum()
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
    let points = nearest::points(dist, n);
    let qs = nearest::queries(dist, n, q);
    if which == "time" {
        // Same-run ratios with the report's own methods (kiddo's answer
        // includes fetching its point, as exactray's does): the methods
        // alternate, 15 rounds, and the median per-round ratios are printed.
        let ix = nearest::Indexes::build(points);
        let methods = nearest::methods(&ix);
        let pick = |name: &str| methods.iter().find(|m| m.name() == name).expect("method");
        let (e, k, r) = (pick("exactray"), pick("kiddo"), pick("rstar"));
        let mut rounds: Vec<[f64; 3]> = (0..15)
            .map(|_| [e, k, r].map(|m| m.run_loop(&qs, 1).as_secs_f64() * 1e9 / q as f64))
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
        let tree = nearest::exactray_build(&points);
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
        let tree = nearest::kiddo_build(&points);
        check.1 = queries_kiddo(&tree, &qs);
    }
    println!("{} {n} points, {q} queries: {check:?}", dist.name());
}
