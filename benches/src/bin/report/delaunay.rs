//! delaunay: a Delaunay triangulation as a real client of the predicates.
//! One triangulator (`exactray-delaunay`: BRIO and Hilbert order, a
//! visibility walk, Bowyer–Watson cavities, ghost triangles) run on
//! exactray's `orient2d` and `incircle` (`exactray`) and on the `robust`
//! crate's (`robust`), beside spade's `bulk_load` (`spade`, its own
//! triangulator on its own copy of Shewchuk's predicates).
//!
//! Inputs `uniform:N`, `grid:N` (an integer grid: every unit square
//! cocircular), `tiny:N` and `huge:N` (the uniform points times `2^-532`
//! and `2^532`), `mixed:N` (magnitudes from `1e-301` to `1e301` in one
//! set): `exactray::testing::plane_points`. `ns_per_op` is ns per point,
//! the median of 5 whole triangulations (3 at 10^6 points; ordering
//! included), the methods' runs interleaved.
//! `errors`: the exact audit's count (`exactray_delaunay::audit`, on the
//! big-integer oracle): triangles inverted or violating the empty circle,
//! plus every way the output fails to be a triangulation of the points
//! (missing or repeated points, overlapping edges, a boundary that is not
//! the convex hull, a count off Euler's formula); a run that returns an
//! error or panics counts all `N`, and so does any worse count (an empty
//! output is as wrong as none). `cases`: points.

use crate::framework::{Config, Row, median, note};
use exactray::testing::{PlaneDistribution, plane_points};
use exactray_delaunay::{Audit, Exactray, Robust, Triangulation, audit, triangle_set, triangulate};
use exactray_peers::delaunay::spade_triangles;
use glam::DVec2;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

/// A triangulator: its triangulation, or why there is none.
type Method = fn(&[DVec2]) -> Result<Triangulation, String>;

const METHODS: [(&str, Method); 3] = [
    ("exactray", |p| {
        triangulate::<Exactray>(p).map_err(|e| e.to_string())
    }),
    ("robust", |p| {
        triangulate::<Robust>(p).map_err(|e| e.to_string())
    }),
    ("spade", |p| {
        spade_triangles(p)
            .map(|triangles| Triangulation {
                triangles,
                ..Triangulation::default()
            })
            .map_err(|e| format!("spade refuses the input: {e:?}"))
    }),
];

/// Every method's timed runs on one point set, repetitions interleaved so
/// that a slow spell of a shared machine hits them alike: each method's
/// last output and median time in seconds.
fn timed(points: &[DVec2], reps: usize) -> Vec<(Result<Triangulation, String>, f64)> {
    let mut times = vec![Vec::with_capacity(reps); METHODS.len()];
    let mut outputs: Vec<Result<Triangulation, String>> =
        METHODS.iter().map(|_| Err("not run".to_string())).collect();
    for _ in 0..reps {
        for ((_, method), (output, times)) in METHODS.iter().zip(outputs.iter_mut().zip(&mut times))
        {
            let start = Instant::now();
            *output = catch_unwind(AssertUnwindSafe(|| method(points)))
                .unwrap_or_else(|_| Err("panicked".to_string()));
            times.push(start.elapsed().as_secs_f64());
        }
    }
    outputs
        .into_iter()
        .zip(times.into_iter().map(median))
        .collect()
}

/// The triangles as a set, with the duplicates, sorted: equal keys, equal
/// audits.
fn canonical(t: &Triangulation) -> (Vec<[u32; 3]>, Vec<(u32, u32)>) {
    let mut dups = t.duplicates.clone();
    dups.sort_unstable();
    (triangle_set(&t.triangles), dups)
}

/// What the audit found, in words, for the note.
fn findings(a: &Audit) -> String {
    let parts: Vec<String> = [
        (a.inverted, "inverted"),
        (a.not_delaunay, "not Delaunay"),
        (a.missing_points, "points missing"),
        (a.repeated_points, "points repeated"),
        (a.bad_indices, "bad indices"),
        (a.repeated_edges, "edges repeated"),
        (a.hull_mismatch, "hull edges wrong"),
        (a.euler_gap, "off Euler's count"),
        (a.false_duplicates, "false duplicates"),
    ]
    .iter()
    .filter(|(v, _)| *v > 0)
    .map(|(v, what)| format!("{v} {what}"))
    .collect();
    if parts.is_empty() {
        "valid Delaunay".to_string()
    } else {
        parts.join(", ")
    }
}

/// Outputs already audited, by their [`canonical`] form.
type Audited = Vec<((Vec<[u32; 3]>, Vec<(u32, u32)>), Audit)>;

/// A method's errors on `points` (at most their number) and what the
/// audit found; an output identical to one in `audited` is not audited
/// again.
fn assess(
    points: &[DVec2],
    output: Result<Triangulation, String>,
    spade: bool,
    audited: &mut Audited,
) -> (u64, String) {
    let n = points.len() as u64;
    let t = match output {
        Ok(t) => t,
        Err(why) => return (n, format!("no triangulation: {why}")),
    };
    let key = canonical(&t);
    let found = audited.iter().find(|(k, _)| *k == key).map(|e| e.1);
    let a = match found.map_or_else(|| audit(points, &t), Ok) {
        Ok(a) => a,
        Err(e) => return (n, format!("not audited: {e}")),
    };
    audited.push((key, a));
    let per_point = |v: u64| v as f64 / n as f64;
    let steps = if spade {
        String::new()
    } else {
        format!(
            "; {:.1} walk steps, {:.1} cavity triangles per point",
            per_point(t.walk_steps),
            per_point(t.cavity_triangles)
        )
    };
    let duplicates = if t.duplicates.is_empty() {
        String::new()
    } else {
        format!(", {} duplicates skipped", t.duplicates.len())
    };
    (
        a.errors().min(n),
        format!(
            "{} triangles, {}{duplicates}{steps}",
            a.triangles,
            findings(&a)
        ),
    )
}

pub fn run(cfg: &Config) -> Vec<Row> {
    let sizes: &[usize] = if cfg.quick {
        &[100_000]
    } else {
        &[100_000, 1_000_000]
    };
    let mut rows = Vec::new();
    let mut lines = Vec::new();
    for &n in sizes {
        for dist in PlaneDistribution::ALL {
            let points: Vec<DVec2> = plane_points(dist, n).collect();
            let inputs = format!("{}:{n}", dist.name());
            // Outputs already audited: an identical one is not audited again.
            let mut audited = Vec::new();
            let reps = if n <= 100_000 { 5 } else { 3 };
            for ((name, _), (output, seconds)) in METHODS.iter().zip(timed(&points, reps)) {
                let (errors, detail) = assess(&points, output, *name == "spade", &mut audited);
                lines.push(format!(
                    "| {inputs} | {name} | {:.1} | {errors} | {detail} |",
                    seconds * 1e3
                ));
                rows.push(Row {
                    family: "delaunay",
                    method: name.to_string(),
                    inputs: inputs.clone(),
                    ns_per_op: seconds * 1e9 / n as f64,
                    cases: n as u64,
                    errors,
                    max_ulps: None,
                    max_bound_ulps: None,
                });
            }
        }
    }
    note(
        "delaunay",
        format!(
            "**delaunay**: one triangulator (`exactray-delaunay`) on exactray's predicates and on robust's, and \
             spade's `bulk_load`, on one core; the median of 5 whole runs (3 at 10^6 points), the methods' \
             runs interleaved, checked by the exact audit \
             (big-integer oracle; an output identical to one already audited, triangles and duplicates, \
             shares its audit). A row whose run fails counts all its points wrong, and its time is the \
             time to fail:\n\n\
             | inputs | method | ms | errors | audit |\n|---|---|---|---|---|\n{}",
            lines.join("\n")
        ),
    );
    rows
}
