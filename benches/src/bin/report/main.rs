//! The speed-against-error report (`docs/report.md`): every routine family
//! of the crate beside the crates a user would otherwise pick, on ordinary
//! and hard inputs, timed and checked against the exact answer.
//!
//! ```text
//! cargo run --release -p exactray-bench --bin report [-- OPTIONS]
//! ```
//! Prints a table (progress on stderr) and writes `target/report/report.md`,
//! `report.json` and one `<family>.svg` per family at the workspace root.
//! `--help` lists the options, `--list` the families.
//!
//! `--stream` times loops over every case of a class instead of a working
//! set that stays in cache (`Config::streaming`). `--export-inputs DIR`
//! also writes the sign families' cases, exactray's answers and this run's
//! times into `DIR` (`export.rs`) for `tools/cgal-timing`, then runs as
//! usual.
//!
//! To add a family: a module beside this file and a line in [`FAMILIES`].
//! The inputs come from `exactray::testing`, the exact answers from the
//! `exactray-oracle` crate (`tests/oracle`).

mod export;
mod framework;
mod heap;
mod output;
mod plot;
mod ray_family;
mod signs;
mod targets;

mod delaunay;
mod implicit;
mod incircle;
mod insphere;
mod nearest;
mod nearest_build;
mod orient2d;
mod orient3d;
mod plane_side;
mod raster_triangle;
mod ray_cone;
mod ray_cylinder;
mod ray_quadric;
mod ray_sphere;
mod ray_triangle;
mod render;
mod scene;

use framework::{Config, Row};
use std::time::Instant;

/// Measures one family: its rows.
type Family = fn(&Config) -> Vec<Row>;

/// Every family, in report order, with what it measures (`--list`).
const FAMILIES: &[(&str, &str, Family)] = &[
    ("orient2d", "sign of (b - a) x (c - a)", |cfg| {
        orient2d::family().run(cfg)
    }),
    ("orient3d", "sign of det[b - a, c - a, d - a]", |cfg| {
        orient3d::family().run(cfg)
    }),
    ("incircle", "d inside the circle through a, b, c", |cfg| {
        incircle::family().run(cfg)
    }),
    (
        "insphere",
        "e inside the sphere through a, b, c, d",
        |cfg| insphere::family().run(cfg),
    ),
    ("plane_side", "p and q against a triangle's plane", |cfg| {
        plane_side::family().run(cfg)
    }),
    (
        "implicit",
        "predicates on constructed points (line-plane, three planes, two lines)",
        implicit::run,
    ),
    ("nearest", "nearest-point queries", nearest::run),
    (
        "nearest_build",
        "building the nearest-point index",
        nearest_build::run,
    ),
    ("ray_sphere", "first hit of a ray on a sphere", |cfg| {
        ray_sphere::family().run(cfg)
    }),
    ("ray_cylinder", "first hit on a cylinder", |cfg| {
        ray_cylinder::family().run(cfg)
    }),
    ("ray_cone", "first hit on a cone", |cfg| {
        ray_cone::family().run(cfg)
    }),
    ("ray_quadric", "first hit on a general quadric", |cfg| {
        ray_quadric::family().run(cfg)
    }),
    (
        "ray_triangle",
        "ray against one triangle",
        ray_triangle::run,
    ),
    (
        "raster_triangle",
        "the pixels of one triangle, against one ray per pixel",
        raster_triangle::run,
    ),
    (
        "closest_hit",
        "closest hit in a mesh scene",
        scene::run_closest,
    ),
    ("any_hit", "shadow rays in a mesh scene", scene::run_any_hit),
    (
        "spawn",
        "secondary rays leaving a surface",
        scene::run_spawn,
    ),
    (
        "render",
        "one frame: Z-buffer against one ray per pixel",
        render::run,
    ),
    (
        "delaunay",
        "a Delaunay triangulator on the predicates",
        delaunay::run,
    ),
];

/// What `--help` prints.
const USAGE: &str = "\
The speed-against-error report: every routine family of exactray beside the
crates a user would otherwise pick, timed and checked against the exact answer.

usage: cargo run --release -p exactray-bench --bin report -- [OPTIONS]

options:
  --quick               fewer cases and repetitions (a few minutes)
  --only F[,F...]       only these families (see --list)
  --stream              time loops over every case of a class, not a working
                        set that stays in cache
  --export-inputs DIR   also write the sign families' cases, exactray's
                        answers and the times to DIR (for tools/cgal-timing)
  --list                list the families and exit
  --help                print this and exit

Writes target/report/report.md, report.json and one <family>.svg per family
(format: docs/report.md). Embree's scene rows need `--features embree`.
";

/// The command line, parsed: `Err` with the exit code for `--help`,
/// `--list` and bad options.
struct Args {
    quick: bool,
    stream: bool,
    only: Option<Vec<String>>,
    export: Option<std::path::PathBuf>,
}

fn parse_args(args: &[String]) -> Result<Args, i32> {
    let mut parsed = Args {
        quick: false,
        stream: false,
        only: None,
        export: None,
    };
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let mut value = || {
            it.next().cloned().ok_or_else(|| {
                eprintln!("{arg} needs a value; see --help");
                2
            })
        };
        match arg.as_str() {
            "--help" | "-h" => {
                print!("{USAGE}");
                return Err(0);
            }
            "--list" => {
                for (name, what, _) in FAMILIES {
                    println!("{name:<16} {what}");
                }
                return Err(0);
            }
            "--quick" => parsed.quick = true,
            "--stream" => parsed.stream = true,
            "--only" => {
                let list: Vec<String> = value()?.split(',').map(str::to_string).collect();
                if let Some(bad) = list.iter().find(|n| !FAMILIES.iter().any(|f| f.0 == *n)) {
                    eprintln!("--only: no family {bad}; --list names them");
                    return Err(2);
                }
                parsed.only = Some(list);
            }
            "--export-inputs" => parsed.export = Some(value()?.into()),
            _ => {
                eprintln!("unknown argument {arg}; see --help");
                return Err(2);
            }
        }
    }
    Ok(parsed)
}

/// Where a run's figures come from, for the pages that quote them: the
/// command line, the Embree feature, the wall time and the commit (with
/// `+changes` when the work tree differed from it).
fn provenance(seconds: f64) -> String {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let git = |args: &[&str]| {
        std::process::Command::new("git")
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .ok()
            .filter(|o| o.status.success())
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
    };
    let commit = match (
        git(&["rev-parse", "--short", "HEAD"]),
        git(&["status", "--porcelain"]),
    ) {
        (Some(c), Some(s)) if s.is_empty() => c,
        (Some(c), Some(_)) => format!("{c}+changes"),
        _ => "unknown".to_string(),
    };
    format!(
        "Run: `report{}`{}, {:.0} s wall time, commit {commit}.",
        args.iter().map(|a| format!(" {a}")).collect::<String>(),
        if cfg!(feature = "embree") {
            ", with the embree feature"
        } else {
            ""
        },
        seconds
    )
}

fn main() -> std::io::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args = match parse_args(&args) {
        Ok(args) => args,
        Err(code) => std::process::exit(code),
    };
    let quick = args.quick;
    let mut cfg = Config::new(quick);
    if args.stream {
        cfg = cfg.streaming();
    }
    cfg.export = args.export;
    let families: Vec<_> = FAMILIES
        .iter()
        .filter(|(name, _, _)| {
            args.only
                .as_ref()
                .is_none_or(|o| o.iter().any(|n| n == name))
        })
        .collect();

    let start = Instant::now();
    let mut rows = Vec::new();
    for (k, (name, _, run)) in families.iter().enumerate() {
        let t = Instant::now();
        let new = run(&cfg);
        let wrong = new
            .iter()
            .filter(|r| r.method == "exactray")
            .map(|r| r.errors)
            .sum::<u64>();
        eprintln!(
            "[{}/{}] {name}: {} rows in {:.1} s (exactray wrong answers: {wrong})",
            k + 1,
            families.len(),
            new.len(),
            t.elapsed().as_secs_f64()
        );
        rows.extend(new);
    }

    let table = output::table(&rows);
    let (targets, met, total) = targets::check(&rows);
    let notes: String = families
        .iter()
        .flat_map(|(name, _, _)| framework::notes(name))
        .map(|n| n + "\n\n")
        .collect();
    println!("{table}");
    println!("Targets met: {met} of {total}\n\n{targets}");
    if !notes.is_empty() {
        println!("{notes}");
    }

    // The workspace root's target/, whichever directory the report runs from.
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("benches/ lies in the workspace")
        .join("target/report");
    std::fs::create_dir_all(&dir)?;
    let mut md = format!(
        "# exactray: speed against error\n\n{}\n\n{} run: {} cases checked against the exact answer per family and inputs; \
         ns/op is the median of {} timed loops over {} cases (the sign families; families sized otherwise say how \
         under Notes). `vs naive` and `vs robust` divide a row's time by \
         that method's on the same family and inputs, measured in the same run.\n\n{table}\n\
         ## Targets\n\n{met} of {total} met.\n\n{targets}\n{}## Plots\n\n",
        provenance(start.elapsed().as_secs_f64()),
        if quick { "Quick" } else { "Full" },
        cfg.cases,
        cfg.reps,
        cfg.working_set.min(cfg.cases),
        if notes.is_empty() {
            String::new()
        } else {
            format!("## Notes\n\n{notes}")
        },
    );
    for (name, _, _) in &families {
        let family_rows: Vec<&Row> = rows.iter().filter(|r| r.family == *name).collect();
        std::fs::write(
            dir.join(format!("{name}.svg")),
            plot::svg(name, &family_rows),
        )?;
        md += &format!("![{name}]({name}.svg)\n\n");
    }
    std::fs::write(dir.join("report.md"), md)?;
    std::fs::write(dir.join("report.json"), output::json(&rows))?;
    if let Some(export) = &cfg.export {
        export::finish(export, &cfg, &rows)?;
        eprintln!(
            "wrote the exported inputs and times to {}",
            export.display()
        );
    }
    eprintln!(
        "wrote {} in {:.1} s",
        dir.display(),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
