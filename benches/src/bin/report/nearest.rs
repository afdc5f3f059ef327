//! nearest: the point of a fixed set nearest to each query, for exactray's
//! sphere BVH (one query at a time, and `nearest_many` on rayon's pool)
//! beside `kiddo`'s k-d tree, `rstar`'s R*-tree and an exact brute force.
//!
//! Inputs: `uniform:N` (points and queries uniform in the unit cube),
//! `clustered:N` (points and queries from the same mixture of 100 Gaussian
//! clusters), `near-ties:N` (a grid nudged by up to an ulp, queried at
//! nudged cell centres; smallest N only) and `off-distribution:N` (the clustered points, queries uniform
//! in the cube). A method's answer is wrong when its point is not at the
//! minimal exact distance from the query (exact `num-bigint` arithmetic,
//! independent of the crate); ties may go to any of the tied points.
//!
//! Shared with `nearest_build` (the same point sets) and
//! `benches/nearest.rs`.

use crate::framework::{Config, Measure, Row, method, note, time_methods};
use exactray::bvh::SphereBvh;
use exactray::bvh::{Nearest, QueryStats};
use exactray::testing::{nearest_points, nearest_queries};
use exactray_oracle::oracle;
use glam::DVec3;
use rstar::RTree;
use std::cell::RefCell;
use std::cmp::Ordering;
use std::sync::Arc;
use std::time::{Duration, Instant};

pub use exactray_peers::nearest::{KiddoTree, Point, kiddo_build, kiddo_nearest, rstar_build};

/// How points and queries are drawn (`exactray::testing`).
pub use exactray::testing::PointDistribution as Dist;

/// The report's `inputs` field: the class and the number of points.
pub fn inputs(dist: Dist, n: usize) -> String {
    format!("{}:{n}", dist.name())
}

/// How much work the nearest families do.
pub struct Sizes {
    /// Numbers of points.
    pub ns: Vec<usize>,
    /// Timed queries per input.
    pub queries: usize,
    /// Queries checked against the exact answer, per input and method.
    pub checked: usize,
    /// Timed repetitions over the query set; the report keeps the median.
    pub reps: usize,
    /// Point distances per timed pass of the brute force: it runs on the
    /// first `budget / N` queries only (at least 20).
    pub brute_budget: usize,
}

impl Sizes {
    pub fn new(cfg: &Config) -> Self {
        if cfg.quick {
            Sizes {
                ns: vec![10_000, 1_000_000],
                queries: 10_000,
                checked: 200,
                reps: 5,
                brute_budget: 20_000_000,
            }
        } else {
            Sizes {
                ns: vec![10_000, 100_000, 1_000_000],
                queries: 100_000,
                checked: 1000,
                reps: 7,
                brute_budget: 100_000_000,
            }
        }
    }

    /// Queries the brute force is timed on, at `n` points.
    pub fn brute_queries(&self, n: usize) -> usize {
        (self.brute_budget / n).clamp(20, self.queries)
    }
}

/// The `n` indexed points of `dist`: `off-distribution` shares the
/// clustered ones. Always the same for the same `n`.
pub fn points(dist: Dist, n: usize) -> Vec<Point> {
    nearest_points(dist, n).collect()
}

/// `count` queries of `dist` for the `n`-point set.
pub fn queries(dist: Dist, n: usize, count: usize) -> Vec<DVec3> {
    nearest_queries(dist, n, count).collect()
}

/// Relative error bound on `fl(|p - q|^2)` (five roundings per term, `5u`
/// plus second-order terms) with a wide margin: `2^-48 = 32u`.
const REL: f64 = 1.0 / (1u64 << 48) as f64;
/// Absolute error of squares that underflow (`2^-1075` each), with margin.
const ABS: f64 = 16.0 * f64::MIN_POSITIVE * f64::EPSILON;

fn dist2(p: &Point, q: &Point) -> f64 {
    let (x, y, z) = (p[0] - q[0], p[1] - q[1], p[2] - q[2]);
    x * x + y * y + z * z
}

/// Exhaustive search: the index of a point at the minimal exact distance
/// from `q` (the first such). `f64` squared distances decide whenever their
/// error bound separates them; near-ties go to `cmp`, an exact comparison of
/// `|p - q|` and `|r - q|` as `cmp(q, p, r)`.
#[inline]
pub fn brute_force(
    points: &[Point],
    q: Point,
    cmp: impl Fn(Point, Point, Point) -> Ordering,
) -> Option<usize> {
    let first = points.first()?;
    let mut best = 0;
    let mut best_d = dist2(first, &q);
    // A point whose computed distance exceeds `far` is strictly farther.
    let mut far = best_d * (1.0 + REL) + ABS;
    for (i, p) in points.iter().enumerate().skip(1) {
        let d = dist2(p, &q);
        if d > far {
            continue;
        }
        if d * (1.0 + REL) + ABS < best_d || cmp(q, *p, points[best]) == Ordering::Less {
            best = i;
            best_d = d;
            far = best_d * (1.0 + REL) + ABS;
        }
    }
    Some(best)
}

/// The brute force with the crate's exact comparison on near-ties.
pub fn brute_force_exactray(points: &[Point], q: Point) -> Option<usize> {
    brute_force(points, q, |q, p, r| {
        exactray::predicates::compare_distance(q, p, r)
    })
}

/// The brute force with the independent `num-bigint` oracle on near-ties:
/// the exact answer the methods are checked against.
pub fn brute_force_oracle(points: &[Point], q: Point) -> Option<usize> {
    brute_force(points, q, oracle::compare_distance)
}

pub fn exactray_build(points: &[Point]) -> SphereBvh {
    SphereBvh::from_points(points).expect("finite points")
}

/// The indexes of one point set, shared by the methods' closures.
pub struct Indexes {
    pub points: Arc<Vec<Point>>,
    pub exactray: Arc<SphereBvh>,
    pub kiddo: Arc<KiddoTree>,
    pub rstar: Arc<RTree<Point>>,
}

impl Indexes {
    pub fn build(points: Vec<Point>) -> Self {
        Indexes {
            exactray: Arc::new(exactray_build(&points)),
            kiddo: Arc::new(kiddo_build(&points)),
            rstar: Arc::new(rstar_build(&points)),
            points: Arc::new(points),
        }
    }
}

/// A method's answer: the point it found.
pub type Answer = Option<Point>;

/// `nearest_many` (or `nearest_many_serial`) over the whole query set: one
/// call per pass, its time divided by the number of queries.
pub struct Batch {
    name: &'static str,
    tree: Arc<SphereBvh>,
    parallel: bool,
    out: RefCell<Vec<Option<Nearest>>>,
}

impl Batch {
    fn run(&self, queries: &[DVec3], out: &mut [Option<Nearest>]) {
        let done = if self.parallel {
            self.tree.nearest_many(queries, out)
        } else {
            self.tree.nearest_many_serial(queries, out)
        };
        done.expect("as many answers as queries");
    }
}

impl Measure<DVec3, Answer> for Batch {
    fn name(&self) -> &'static str {
        self.name
    }

    fn answer(&self, case: &DVec3) -> Answer {
        let mut out = [None];
        self.run(std::slice::from_ref(case), &mut out);
        out[0].map(|n| n.point.to_array())
    }

    fn run_loop(&self, cases: &[DVec3], iters: u64) -> Duration {
        let mut out = self.out.borrow_mut();
        out.resize(cases.len(), None);
        let start = Instant::now();
        for _ in 0..iters {
            self.run(std::hint::black_box(cases), &mut out);
            std::hint::black_box(&mut *out);
        }
        start.elapsed()
    }
}

/// The methods, in report order; `exactray-batch-serial` last (it goes into
/// the notes, not a row).
pub fn methods(ix: &Indexes) -> Vec<Box<dyn Measure<DVec3, Answer>>> {
    let t = ix.exactray.clone();
    let k = ix.kiddo.clone();
    let (kp, r) = (ix.points.clone(), ix.rstar.clone());
    let batch = |name, parallel| -> Box<dyn Measure<DVec3, Answer>> {
        Box::new(Batch {
            name,
            tree: ix.exactray.clone(),
            parallel,
            out: RefCell::new(Vec::new()),
        })
    };
    vec![
        method("exactray", move |q: &DVec3| {
            t.nearest(*q).map(|n| n.point.to_array())
        }),
        batch("exactray-batch", true),
        method("kiddo", move |q: &DVec3| {
            Some(kp[kiddo_nearest(&k, &q.to_array())])
        }),
        method("rstar", move |q: &DVec3| {
            r.nearest_neighbor(q.to_array()).copied()
        }),
        batch("exactray-batch-serial", false),
    ]
}

pub fn brute_force_method(ix: &Indexes) -> Box<dyn Measure<DVec3, Answer>> {
    let p = ix.points.clone();
    method("brute-force", move |q: &DVec3| {
        brute_force_exactray(&p, q.to_array()).map(|i| p[i])
    })
}

/// Wrong answers among `answers` to `queries`, against the exact nearest
/// points `truth`.
fn count_wrong(queries: &[DVec3], answers: &[Answer], truth: &[Point]) -> u64 {
    queries
        .iter()
        .zip(answers)
        .zip(truth)
        .filter(|((q, a), t)| {
            a.is_none_or(|a| oracle::compare_distance(q.to_array(), a, **t) != Ordering::Equal)
        })
        .count() as u64
}

/// Average work per query of the exactray tree on `queries`.
fn exactray_stats(tree: &SphereBvh, queries: &[DVec3]) -> [f64; 3] {
    let mut s = QueryStats::default();
    for q in queries {
        tree.nearest_with_stats(*q, &mut s);
    }
    let n = queries.len().max(1) as f64;
    [
        s.nodes_visited as f64 / n,
        s.distances_computed as f64 / n,
        s.exact_comparisons as f64 / n,
    ]
}

/// Figures of one input for the notes.
struct Detail {
    inputs: String,
    ns: Vec<(String, f64)>,
    brute_queries: usize,
    stats: [f64; 3],
    index_mismatch: u64,
}

/// Rows of one input (one point set, one query distribution).
fn measure(
    cfg: &Config,
    sizes: &Sizes,
    ix: &Indexes,
    dist: Dist,
    details: &mut Vec<Detail>,
) -> Vec<Row> {
    let n = ix.points.len();
    let inputs = inputs(dist, n);
    let qs = queries(dist, n, sizes.queries);
    let timing = Config {
        reps: sizes.reps,
        ..Config::new(cfg.quick)
    };
    let methods = methods(ix);
    let mut times = time_methods(&timing, &qs, &methods);
    let brute = [brute_force_method(ix)];
    let nb = sizes.brute_queries(n);
    times.extend(time_methods(&timing, &qs[..nb], &brute));

    let sample = &qs[..sizes.checked.min(qs.len())];
    let truth: Vec<Point> = sample
        .iter()
        .map(|q| ix.points[brute_force_oracle(&ix.points, q.to_array()).expect("points")])
        .collect();
    // exactray's index must name the point it returns.
    let index_mismatch = sample
        .iter()
        .filter(|q| {
            ix.exactray
                .nearest(**q)
                .is_none_or(|a| ix.points[a.index] != a.point.to_array())
        })
        .count() as u64;

    let mut rows = Vec::new();
    let mut ns = Vec::new();
    for (m, &t) in methods.iter().chain(&brute).zip(&times) {
        ns.push((m.name().to_string(), t));
        if m.name() == "exactray-batch-serial" {
            continue;
        }
        let answers: Vec<Answer> = sample.iter().map(|q| m.answer(q)).collect();
        let mut errors = count_wrong(sample, &answers, &truth);
        if m.name() == "exactray" {
            errors += index_mismatch;
        }
        rows.push(Row {
            family: "nearest",
            method: m.name().to_string(),
            inputs: inputs.clone(),
            ns_per_op: t,
            cases: sample.len() as u64,
            errors,
            max_ulps: None,
            max_bound_ulps: None,
        });
    }
    details.push(Detail {
        inputs,
        ns,
        brute_queries: nb,
        stats: exactray_stats(&ix.exactray, sample),
        index_mismatch,
    });
    rows
}

fn notes(sizes: &Sizes, details: &[Detail]) -> String {
    let get = |d: &Detail, m: &str| d.ns.iter().find(|(n, _)| n == m).map_or(f64::NAN, |x| x.1);
    let body: Vec<Vec<String>> = details
        .iter()
        .map(|d| {
            let e = get(d, "exactray");
            vec![
                d.inputs.clone(),
                crate::output::ns(e),
                format!("{:.2}x", e / get(d, "kiddo")),
                format!("{:.2}x", e / get(d, "rstar")),
                format!(
                    "{:.2}x",
                    get(d, "exactray-batch-serial") / get(d, "exactray-batch")
                ),
                d.brute_queries.to_string(),
                format!("{:.1}", d.stats[0]),
                format!("{:.1}", d.stats[1]),
                format!("{:.3}", d.stats[2]),
            ]
        })
        .collect();
    let mismatches: u64 = details.iter().map(|d| d.index_mismatch).sum();
    format!(
        "**nearest**: ns/op is per query, the median of {} passes over {} queries (the brute force: over the first \
         `brute queries` of them, at most {} point distances per pass). `cases` is the {} queries per input whose \
         answers were checked against an exact brute force (`num-bigint` on near-ties); an answer is wrong when its \
         point is not at the minimal exact distance. `exactray-batch` is `nearest_many` on rayon's pool ({} threads); \
         `batch speed-up` divides `nearest_many_serial`'s time by it. `nodes`, `distances` and `exact cmp` are \
         exactray's average work per checked query (`nearest_with_stats`). exactray's `index` named a different point \
         than it returned {} times (counted as wrong).\n\n{}",
        sizes.reps,
        sizes.queries,
        sizes.brute_budget,
        sizes.checked,
        rayon_threads(),
        mismatches,
        crate::output::markdown(
            &[
                "inputs",
                "exactray ns",
                "vs kiddo",
                "vs rstar",
                "batch speed-up",
                "brute queries",
                "nodes",
                "distances",
                "exact cmp",
            ],
            &body,
        )
    )
}

/// The threads of rayon's global pool, as `nearest_many` and kiddo use it.
fn rayon_threads() -> usize {
    std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.parse().ok())
        .filter(|&n| n > 0)
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}

/// The `nearest` family: one row per (inputs, method).
pub fn run(cfg: &Config) -> Vec<Row> {
    let sizes = Sizes::new(cfg);
    let mut rows = Vec::new();
    let mut details = Vec::new();
    for &n in &sizes.ns {
        let ix = Indexes::build(points(Dist::Uniform, n));
        rows.extend(measure(cfg, &sizes, &ix, Dist::Uniform, &mut details));
        drop(ix);
        let ix = Indexes::build(points(Dist::Clustered, n));
        rows.extend(measure(cfg, &sizes, &ix, Dist::Clustered, &mut details));
        rows.extend(measure(
            cfg,
            &sizes,
            &ix,
            Dist::OffDistribution,
            &mut details,
        ));
    }
    // Near-ties at the smallest size only: the exact brute force settles
    // eight near-tied candidates per query there.
    if let Some(&n) = sizes.ns.first() {
        let ix = Indexes::build(points(Dist::NearTies, n));
        rows.extend(measure(cfg, &sizes, &ix, Dist::NearTies, &mut details));
    }
    note("nearest", notes(&sizes, &details));
    rows
}
