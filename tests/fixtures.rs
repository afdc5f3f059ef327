//! Checks the crate against fixtures whose expected answers come from CGAL's
//! exact kernels: every file in `tests/fixtures/` (written by
//! `tools/cgal-fixtures/regenerate.sh`) and, when the environment variable
//! `EXACTRAY_EXTRA_FIXTURES` names a folder, every file there too.
//!
//! A file's kind is its name up to the first `-` or the `.txt`
//! (`orient3d.txt`, `orient3d-near-degenerate.txt`). Each kind has one row in
//! [`KINDS`]: adding a kind means writing its checker and filling in the row.
//! Kinds listed without a checker are counted and reported as skipped, so a
//! fixture nobody checks is visible rather than silently passing.

mod common;

use common::oracle;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::panic::catch_unwind;
use std::path::{Path, PathBuf};

/// How many mismatches and problems a failing test lists in full.
const SHOWN: usize = 20;

/// The result of running one fixture line.
enum Verdict {
    Pass,
    Mismatch { expected: String, got: String },
}

/// Runs one line's fields (the line split at spaces); `Err` when the line
/// cannot be parsed.
type Checker = fn(&[&str]) -> Result<Verdict, String>;

struct Kind {
    name: &'static str,
    /// Fewest fields a line of this kind can have. Lines of kinds without a
    /// checker are held to this, so that a malformed file fails even before
    /// its kind is checked.
    min_fields: usize,
    /// Runs the crate's implementation; `None` until an issue implements it.
    predicate: Option<Checker>,
    /// Runs the exact oracle of `tests/common/oracle.rs`; agreement with
    /// CGAL validates the fixtures and the oracle against each other.
    oracle: Option<Checker>,
}

const KINDS: &[Kind] = &[
    Kind {
        name: "orient2d",
        min_fields: 7,
        predicate: Some(crate_orient2d),
        oracle: Some(oracle_orient2d),
    },
    Kind {
        name: "orient3d",
        min_fields: 13,
        predicate: Some(crate_orient3d),
        oracle: Some(oracle_orient3d),
    },
    Kind {
        name: "plane_side",
        min_fields: 16,
        predicate: Some(crate_plane_side),
        oracle: Some(oracle_plane_side),
    },
    Kind {
        name: "ray_sphere",
        min_fields: 11,
        predicate: None,
        oracle: None,
    },
    Kind {
        name: "ray_cylinder",
        min_fields: 14,
        predicate: None,
        oracle: None,
    },
    Kind {
        name: "ray_quadric",
        min_fields: 17,
        predicate: None,
        oracle: None,
    },
    Kind {
        name: "ray_triangle",
        min_fields: 16,
        predicate: None,
        oracle: None,
    },
    Kind {
        name: "nearest",
        min_fields: 4,
        predicate: None,
        oracle: None,
    },
];

// ---------------------------------------------------------------------------
// Parsing

fn parse_f64(field: &str) -> Result<f64, String> {
    let v: f64 = field
        .parse()
        .map_err(|e| format!("bad number {field:?}: {e}"))?;
    // f64::from_str accepts "inf" and "NaN"; the format allows finite values
    // only, and a non-finite one would mean a broken generator.
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("non-finite number {field:?}"))
    }
}

fn parse_sign(field: &str) -> Result<i8, String> {
    match field {
        "-1" => Ok(-1),
        "0" => Ok(0),
        "1" => Ok(1),
        _ => Err(format!("bad sign {field:?} (want -1, 0 or 1)")),
    }
}

/// `N` coordinates followed by a sign, and nothing else.
fn parse_sign_case<const N: usize>(fields: &[&str]) -> Result<([f64; N], i8), String> {
    if fields.len() != N + 1 {
        return Err(format!("expected {} fields, found {}", N + 1, fields.len()));
    }
    let mut v = [0.0; N];
    for (x, field) in v.iter_mut().zip(fields) {
        *x = parse_f64(field)?;
    }
    Ok((v, parse_sign(fields[N])?))
}

fn p2(v: &[f64], i: usize) -> [f64; 2] {
    [v[2 * i], v[2 * i + 1]]
}

fn p3(v: &[f64], i: usize) -> [f64; 3] {
    [v[3 * i], v[3 * i + 1], v[3 * i + 2]]
}

fn compare_signs(expected: i8, got: i8) -> Verdict {
    if expected == got {
        Verdict::Pass
    } else {
        Verdict::Mismatch {
            expected: expected.to_string(),
            got: got.to_string(),
        }
    }
}

// ---------------------------------------------------------------------------
// Checkers

fn crate_orient2d(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_sign_case::<6>(f)?;
    Ok(compare_signs(
        want,
        exactray::orient2d(p2(&v, 0), p2(&v, 1), p2(&v, 2)).as_i8(),
    ))
}

fn oracle_orient2d(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_sign_case::<6>(f)?;
    Ok(compare_signs(
        want,
        oracle::orient2d(p2(&v, 0), p2(&v, 1), p2(&v, 2)),
    ))
}

fn crate_orient3d(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_sign_case::<12>(f)?;
    let got = exactray::orient3d(p3(&v, 0), p3(&v, 1), p3(&v, 2), p3(&v, 3));
    Ok(compare_signs(want, got.as_i8()))
}

fn oracle_orient3d(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_sign_case::<12>(f)?;
    Ok(compare_signs(
        want,
        oracle::orient3d(p3(&v, 0), p3(&v, 1), p3(&v, 2), p3(&v, 3)),
    ))
}

fn crate_plane_side(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_sign_case::<15>(f)?;
    let got = exactray::same_side(p3(&v, 0), p3(&v, 1), p3(&v, 2), p3(&v, 3), p3(&v, 4));
    Ok(compare_signs(want, got.as_i8()))
}

fn oracle_plane_side(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_sign_case::<15>(f)?;
    let got = oracle::plane_side(p3(&v, 0), p3(&v, 1), p3(&v, 2), p3(&v, 3), p3(&v, 4));
    Ok(compare_signs(want, got))
}

// ---------------------------------------------------------------------------
// Files

/// The fixture files, sorted so that reports are stable: the built-in ones,
/// then the extra folder's. Dotfiles are ignored (editor and VCS litter);
/// everything else must be a fixture.
fn fixture_files() -> Vec<PathBuf> {
    let builtin = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    let mut files = files_in(&builtin);
    assert!(
        !files.is_empty(),
        "no fixture files in {}",
        builtin.display()
    );
    if let Some(extra) = std::env::var_os("EXACTRAY_EXTRA_FIXTURES") {
        // Named explicitly, so a missing or empty folder is a mistake to report.
        let extra = files_in(Path::new(&extra));
        assert!(
            !extra.is_empty(),
            "EXACTRAY_EXTRA_FIXTURES names a folder with no files"
        );
        files.extend(extra);
    }
    files
}

fn files_in(dir: &Path) -> Vec<PathBuf> {
    let entries =
        std::fs::read_dir(dir).unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()));
    let mut files: Vec<PathBuf> = entries
        .map(|e| {
            e.unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
                .path()
        })
        .filter(|p| {
            p.is_file()
                && !p
                    .file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with('.'))
        })
        .collect();
    files.sort();
    files
}

fn kind_of(path: &Path) -> Result<&'static Kind, String> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let stem = name
        .strip_suffix(".txt")
        .ok_or_else(|| format!("file name {name:?} is not <kind>.txt or <kind>-<anything>.txt"))?;
    let kind = stem.split('-').next().unwrap_or(stem);
    KINDS
        .iter()
        .find(|k| k.name == kind)
        .ok_or_else(|| format!("unknown fixture kind {kind:?}"))
}

/// The path as reported: relative to the crate for the built-in fixtures.
fn shown(path: &Path) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    path.strip_prefix(root)
        .unwrap_or(path)
        .display()
        .to_string()
}

// ---------------------------------------------------------------------------
// Running

#[derive(Default)]
struct Report {
    checked: BTreeMap<&'static str, usize>,
    skipped: BTreeMap<&'static str, usize>,
    /// Mismatch counts by (kind, section), to show where an implementation
    /// goes wrong at a glance.
    mismatches_by_section: BTreeMap<(&'static str, String), usize>,
    mismatches: usize,
    mismatch_list: Vec<String>,
    /// Lines that cannot be parsed, unknown kinds, unreadable files, panics.
    problems: Vec<String>,
}

impl Report {
    fn mismatch(&mut self, kind: &'static str, section: &str, message: String) {
        self.mismatches += 1;
        *self
            .mismatches_by_section
            .entry((kind, section.to_string()))
            .or_default() += 1;
        if self.mismatch_list.len() < SHOWN {
            self.mismatch_list.push(message);
        }
    }

    /// Prints the counts and panics if anything failed.
    fn finish(self, what: &str) {
        println!("{what}:");
        for (kind, n) in &self.checked {
            println!("  {kind}: {n} cases checked");
        }
        for (kind, n) in &self.skipped {
            println!("  {kind}: {n} lines SKIPPED (no checker for this kind yet)");
        }
        if self.mismatches == 0 && self.problems.is_empty() {
            return;
        }
        let mut msg = String::new();
        if self.mismatches > 0 {
            let _ = writeln!(msg, "{} mismatches; by section:", self.mismatches);
            for ((kind, section), n) in &self.mismatches_by_section {
                let _ = writeln!(msg, "  {kind} [{section}]: {n}");
            }
            let _ = writeln!(msg, "first {}:", self.mismatch_list.len());
            for m in &self.mismatch_list {
                let _ = writeln!(msg, "  {m}");
            }
        }
        if !self.problems.is_empty() {
            let _ = writeln!(msg, "{} problems; first {}:", self.problems.len(), SHOWN);
            for p in self.problems.iter().take(SHOWN) {
                let _ = writeln!(msg, "  {p}");
            }
        }
        panic!("{what} failed:\n{msg}");
    }
}

/// Runs the checker that `select` picks from each line's kind over every
/// fixture line; kinds without one are counted as skipped.
fn run(select: fn(&Kind) -> Option<Checker>) -> Report {
    let mut report = Report::default();
    for path in fixture_files() {
        let file = shown(&path);
        let kind = match kind_of(&path) {
            Ok(kind) => kind,
            Err(e) => {
                report.problems.push(format!("{file}: {e}"));
                continue;
            }
        };
        let text = match std::fs::read_to_string(&path) {
            Ok(text) => text,
            Err(e) => {
                report.problems.push(format!("{file}: cannot read: {e}"));
                continue;
            }
        };
        let checker = select(kind);
        let mut section = String::from("no section");
        for (index, line) in text.lines().enumerate() {
            let at = format!("{file}:{}", index + 1);
            if let Some(comment) = line.strip_prefix('#') {
                // The generator opens each section with "# section NAME: ...".
                if let Some(rest) = comment.trim_start().strip_prefix("section ") {
                    section = rest.split(':').next().unwrap_or(rest).trim().to_string();
                }
                continue;
            }
            if line.trim().is_empty() {
                continue;
            }
            // Single spaces separate fields; anything else is a malformed line.
            let fields: Vec<&str> = line.split(' ').collect();
            if fields.iter().any(|f| f.is_empty()) {
                report
                    .problems
                    .push(format!("{at}: fields must be separated by single spaces"));
                continue;
            }
            let Some(check) = checker else {
                if fields.len() < kind.min_fields {
                    report.problems.push(format!(
                        "{at}: {} fields, a {} line has at least {}",
                        fields.len(),
                        kind.name,
                        kind.min_fields
                    ));
                }
                *report.skipped.entry(kind.name).or_default() += 1;
                continue;
            };
            // A panic is reported against its line rather than aborting the run.
            match catch_unwind(|| check(&fields)) {
                Ok(Ok(verdict)) => {
                    *report.checked.entry(kind.name).or_default() += 1;
                    if let Verdict::Mismatch { expected, got } = verdict {
                        let message =
                            format!("{at} [{section}]: expected {expected}, got {got}: {line}");
                        report.mismatch(kind.name, &section, message);
                    }
                }
                Ok(Err(e)) => report.problems.push(format!("{at}: {e}")),
                Err(_) => report.problems.push(format!("{at}: panicked: {line}")),
            }
        }
    }
    report
}

#[test]
fn crate_matches_cgal_fixtures() {
    run(|k| k.predicate).finish("exactray against the CGAL fixtures");
}

#[test]
fn oracle_matches_cgal_fixtures() {
    run(|k| k.oracle).finish("the test oracle against the CGAL fixtures");
}

#[test]
fn kind_names_follow_the_file_name_rule() {
    let kind = |name: &str| kind_of(Path::new(name)).map(|k| k.name);
    assert_eq!(kind("orient3d.txt"), Ok("orient3d"));
    assert_eq!(kind("orient3d-near-degenerate.txt"), Ok("orient3d"));
    assert_eq!(kind("plane_side-x.txt"), Ok("plane_side"));
    assert!(kind("orient4d.txt").is_err());
    assert!(kind("orient3d.csv").is_err());
    assert!(kind("orient3d").is_err());
}

#[test]
fn malformed_lines_are_rejected() {
    let fields = |line: &'static str| line.split(' ').collect::<Vec<_>>();
    assert!(crate_orient2d(&fields("0 0 1 0 0 1 1")).is_ok());
    assert!(
        crate_orient2d(&fields("0 0 1 0 0 1")).is_err(),
        "too few fields"
    );
    assert!(
        crate_orient2d(&fields("0 0 1 0 0 1 1 1")).is_err(),
        "too many fields"
    );
    assert!(
        crate_orient2d(&fields("0 0 1 0 0 x 1")).is_err(),
        "bad number"
    );
    assert!(
        crate_orient2d(&fields("0 0 1 0 0 inf 1")).is_err(),
        "non-finite number"
    );
    assert!(
        crate_orient2d(&fields("0 0 1 0 0 1 2")).is_err(),
        "bad sign"
    );
    assert!(
        crate_orient2d(&fields("0 0 1 0 0 1 +1")).is_err(),
        "bad sign"
    );
}
