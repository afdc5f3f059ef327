//! The speed-against-error report (see REPORT.md in the project notes):
//! every routine family of the crate beside its peers, on ordinary and hard
//! inputs, timed and checked against the exact answer.
//!
//! ```text
//! cargo run --release --example report [-- --quick] [-- --only orient3d,incircle]
//!     [-- --stream] [-- --export-inputs DIR]
//! ```
//! Prints a table (progress on stderr) and writes `target/report/report.md`,
//! `report.json` and one `<family>.svg` per family.
//!
//! `--stream` times loops over every case of a class instead of a working
//! set that stays in cache (`Config::streaming`). `--export-inputs DIR`
//! also writes the sign families' cases, exactray's answers and this run's
//! times into `DIR` (`export.rs`) for `tools/cgal-timing`, then runs as
//! usual.
//!
//! To add a family: a module under `examples/report/` and a line in
//! [`FAMILIES`]. The inputs come from `exactray::testing`, the exact answers
//! from the `exactray-oracle` crate (`tests/oracle`).

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

/// Every family, in report order.
const FAMILIES: &[(&str, Family)] = &[
    ("orient2d", |cfg| orient2d::family().run(cfg)),
    ("orient3d", |cfg| orient3d::family().run(cfg)),
    ("incircle", |cfg| incircle::family().run(cfg)),
    ("insphere", |cfg| insphere::family().run(cfg)),
    ("plane_side", |cfg| plane_side::family().run(cfg)),
    ("implicit", implicit::run),
    ("nearest", nearest::run),
    ("nearest_build", nearest_build::run),
    ("ray_sphere", |cfg| ray_sphere::family().run(cfg)),
    ("ray_cylinder", |cfg| ray_cylinder::family().run(cfg)),
    ("ray_cone", |cfg| ray_cone::family().run(cfg)),
    ("ray_quadric", |cfg| ray_quadric::family().run(cfg)),
    ("ray_triangle", ray_triangle::run),
    ("raster_triangle", raster_triangle::run),
    ("closest_hit", scene::run_closest),
    ("any_hit", scene::run_any_hit),
    ("spawn", scene::run_spawn),
    ("render", render::run),
    ("delaunay", delaunay::run),
];

fn main() -> std::io::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let quick = args.iter().any(|a| a == "--quick");
    let value = |option: &str| {
        args.iter()
            .position(|a| a == option)
            .and_then(|i| args.get(i + 1))
    };
    let only: Option<Vec<String>> =
        value("--only").map(|list| list.split(',').map(str::to_string).collect());
    const OPTIONS: [&str; 4] = ["--quick", "--only", "--stream", "--export-inputs"];
    if let Some(unknown) = args
        .iter()
        .find(|a| a.starts_with("--") && !OPTIONS.contains(&a.as_str()))
    {
        eprintln!(
            "unknown option {unknown}; options: --quick, --only family[,family...], --stream, \
             --export-inputs DIR"
        );
        std::process::exit(2);
    }
    let mut cfg = Config::new(quick);
    if args.iter().any(|a| a == "--stream") {
        cfg = cfg.streaming();
    }
    cfg.export = value("--export-inputs").map(std::path::PathBuf::from);
    let families: Vec<_> = FAMILIES
        .iter()
        .filter(|(name, _)| only.as_ref().is_none_or(|o| o.iter().any(|n| n == name)))
        .collect();

    let start = Instant::now();
    let mut rows = Vec::new();
    for (k, (name, run)) in families.iter().enumerate() {
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
        .flat_map(|(name, _)| framework::notes(name))
        .map(|n| n + "\n\n")
        .collect();
    println!("{table}");
    println!("Targets met: {met} of {total}\n\n{targets}");
    if !notes.is_empty() {
        println!("{notes}");
    }

    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/report");
    std::fs::create_dir_all(&dir)?;
    let mut md = format!(
        "# exactray: speed against error\n\n{} run: {} cases checked against the exact answer per family and inputs; \
         ns/op is the median of {} timed loops over {} cases (the sign families; families sized otherwise say how \
         under Notes). `vs naive` and `vs robust` divide a row's time by \
         that method's on the same family and inputs, measured in the same run.\n\n{table}\n\
         ## Targets\n\n{met} of {total} met.\n\n{targets}\n{}## Plots\n\n",
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
    for (name, _) in &families {
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
