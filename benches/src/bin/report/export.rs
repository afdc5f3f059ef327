//! `--export-inputs DIR`: the sign families' cases and exactray's answers
//! written to files, so that another program (`tools/cgal-timing`) can time
//! its own predicates on the very cases the report timed and check its
//! answers against exactray's case by case.
//!
//! The run goes on as usual after writing the inputs of a class; at the end
//! `DIR/times.txt` holds the report's times for the exported families, so
//! one command gives both the inputs and exactray's times from one run.
//!
//! Files in `DIR` (all little-endian, no padding):
//! - `<family>-<inputs>.f64`: the cases of one class back to back, each
//!   case its points in argument order, each point its coordinates (`x y`
//!   or `x y z`), as IEEE binary64: `coords` values per case.
//! - `<family>-<inputs>.sign`: one signed byte per case, exactray's answer
//!   (`-1`, `0`, `1`; `plane_side` in its `1` same side, `-1` opposite, `0`
//!   on the plane), in CGAL's sign conventions (`docs/fixture-format.md`).
//! - `manifest.txt`: `#` comments, then `timing working_set reps min_loop_ns`
//!   (how the report timed: the median of `reps` loops over the first
//!   `working_set` cases, each loop repeated to last at least `min_loop_ns`),
//!   then one line `family inputs cases coords` per class.
//! - `times.txt`: `family inputs method ns_per_op errors`, one line per row
//!   of the exported families, written when the run ends.

use crate::framework::{Config, Row};
use glam::{DVec2, DVec3};
use std::io::Write;
use std::path::Path;
use std::sync::Mutex;

/// A case as the flat list of its coordinates, point by point.
pub trait Coords {
    /// Coordinates per case.
    const LEN: usize;
    /// Appends the case's coordinates to `out`.
    fn push_coords(&self, out: &mut Vec<f64>);
}

impl<const N: usize> Coords for [DVec2; N] {
    const LEN: usize = 2 * N;
    fn push_coords(&self, out: &mut Vec<f64>) {
        out.extend(self.iter().flat_map(|p| p.to_array()));
    }
}

impl<const N: usize> Coords for [DVec3; N] {
    const LEN: usize = 3 * N;
    fn push_coords(&self, out: &mut Vec<f64>) {
        out.extend(self.iter().flat_map(|p| p.to_array()));
    }
}

/// The manifest's class lines written so far, in order.
static CLASSES: Mutex<Vec<String>> = Mutex::new(Vec::new());

/// Writes one class's cases and exactray's answers into `dir`.
pub fn write_class<C: Coords>(
    dir: &Path,
    family: &str,
    inputs: &str,
    cases: &[C],
    answers: &[i8],
) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let mut coords = Vec::with_capacity(cases.len() * C::LEN);
    cases.iter().for_each(|c| c.push_coords(&mut coords));
    let bytes: Vec<u8> = coords.iter().flat_map(|v| v.to_le_bytes()).collect();
    std::fs::write(dir.join(format!("{family}-{inputs}.f64")), bytes)?;
    let signs: Vec<u8> = answers.iter().map(|&s| s as u8).collect();
    std::fs::write(dir.join(format!("{family}-{inputs}.sign")), signs)?;
    CLASSES.lock().expect("export lock").push(format!(
        "{family} {inputs} {} {}",
        cases.len(),
        C::LEN
    ));
    Ok(())
}

/// Writes `manifest.txt` and `times.txt` for the classes exported in this
/// run, once every family has run.
pub fn finish(dir: &Path, cfg: &Config, rows: &[Row]) -> std::io::Result<()> {
    let classes = CLASSES.lock().expect("export lock");
    if classes.is_empty() {
        return Ok(());
    }
    let mut manifest = std::fs::File::create(dir.join("manifest.txt"))?;
    writeln!(
        manifest,
        "# exactray report inputs (examples/report/export.rs)\n\
         # timing working_set reps min_loop_ns\n\
         timing {} {} {}\n\
         # family inputs cases coords_per_case",
        cfg.working_set,
        cfg.reps,
        cfg.min_loop.as_nanos()
    )?;
    for line in classes.iter() {
        writeln!(manifest, "{line}")?;
    }
    let mut times = std::fs::File::create(dir.join("times.txt"))?;
    writeln!(times, "# family inputs method ns_per_op errors")?;
    for r in rows {
        let exported = |l: &String| l.split(' ').next() == Some(r.family);
        if classes.iter().any(exported) {
            writeln!(
                times,
                "{} {} {} {} {}",
                r.family, r.inputs, r.method, r.ns_per_op, r.errors
            )?;
        }
    }
    Ok(())
}
