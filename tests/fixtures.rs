//! Checks the crate against fixtures whose expected answers come from CGAL's
//! exact kernels: every file in `tests/fixtures/` (written by
//! `tools/cgal-fixtures/regenerate.sh`) and, when the environment variable
//! `EXACTRAY_EXTRA_FIXTURES` names a folder, every file there too. The
//! files' format is `docs/fixture-format.md`.
//!
//! A file's kind is its name up to the first `-` or the `.txt`
//! (`orient3d.txt`, `orient3d-near-degenerate.txt`). Each kind has one row in
//! [`KINDS`]: adding a kind means writing its checker and filling in the row.
//! Kinds listed without a checker are counted and reported as skipped, so a
//! fixture nobody checks is visible rather than silently passing.
//!
//! Every file is also checked scaled by `2^k` for each `k` of [`SCALES`],
//! from `-1000` to `1000`: an exact uniform scaling of a configuration
//! (points, directions and radii by `2^k`; a quadric's coefficients by
//! `2^-2k`, `2^-k` and 1, [`Scaling`]) leaves every answer unchanged, the
//! ray parameters included. A line with a number that would leave the
//! normal range is left out of that copy, and counted; the counts per kind
//! and scale are printed (`--nocapture`).
//!
//! Most kinds have one case per line. A `nearest` file is one point set (its
//! `p` lines) and queries against it (its `q` lines), so its checkers take
//! the whole file: see [`Check`].

use exactray::bvh::Nearest;
use exactray::bvh::SphereBvh;
use exactray::interval::Interval;
use exactray::query::ray::{Exact, Ray};
use exactray::roots::Roots;
use exactray::scene::{MeshSide, TriangleMesh};
use exactray::shape::{Cone, Cylinder, Quadric, Sphere, Triangle};
use exactray_oracle::implicit_oracle::{self, Pt2, Pt3};
use exactray_oracle::line_oracle::{LineAnswer, Quadratic, ulps_between};
use exactray_oracle::oracle;
use exactray_oracle::{closest_oracle, mesh_oracle};
use num_traits::Zero;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};
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

/// What running one case gave: a verdict, a line that cannot be parsed
/// (`Ok(Err)`), or a panic (`Err`).
type Outcome = std::thread::Result<Result<Verdict, String>>;

/// Runs a whole file: gets the fields of every line that is not a comment or
/// blank, in order, and returns an outcome for each case as (position in
/// that list, outcome). Lines that are not cases themselves (a nearest
/// file's points) get an outcome only when they cannot be parsed.
type FileChecker = fn(&[Vec<&str>]) -> Vec<(usize, Outcome)>;

#[derive(Clone, Copy)]
enum Check {
    /// Each line is one case, independent of the others.
    PerLine(Checker),
    /// The lines depend on each other (a point set and queries against it).
    WholeFile(FileChecker),
}
use Check::{PerLine, WholeFile};

struct Kind {
    name: &'static str,
    /// Fewest fields a line of this kind can have. Lines of kinds without a
    /// checker are held to this, so that a malformed file fails even before
    /// its kind is checked.
    min_fields: usize,
    /// Runs the crate's implementation; `None` for a kind no checker covers yet.
    predicate: Option<Check>,
    /// Runs the exact oracle of `exactray-oracle` (`tests/oracle/src/oracle.rs`); agreement with
    /// CGAL validates the fixtures and the oracle against each other.
    oracle: Option<Check>,
    /// Which numbers of a line scale with the configuration: an exact
    /// scaling of every input by `2^k` leaves every answer unchanged.
    scaling: Scaling,
}

/// How a kind's lines scale: the power of `2^k` each field is multiplied
/// by when the whole configuration is (points, directions and radii by
/// `2^k`; answers, counts, indices and ray parameters unchanged).
#[derive(Clone, Copy)]
enum Scaling {
    /// `count` coordinates from field `from`; the other fields unchanged.
    Coordinates { from: usize, count: usize },
    /// `ray_quadric`: the origin and direction by `2^k`, the quadratic
    /// coefficients `A`..`F` by `2^-2k`, the linear ones `G`, `H`, `I` by
    /// `2^-k`, `J` unchanged: the quadric's points are scaled by `2^k`.
    Quadric,
    /// A whole-file kind: a line tagged `tag` holds `count` coordinates
    /// after its tag; `set` lines (points, vertices) are the file's set,
    /// the others its queries.
    Tagged(&'static [Tag]),
}

/// A line tag of a [`Scaling::Tagged`] kind: `count` coordinates after
/// the tag, scaled by `2^k`, then `squared` fields scaled by `2^2k`
/// (squared distances).
struct Tag {
    tag: &'static str,
    count: usize,
    squared: usize,
    set: bool,
}

impl Scaling {
    /// The power of `2^k` field `i` of `fields` is multiplied by.
    fn power(self, fields: &[&str], i: usize) -> i32 {
        match self {
            Scaling::Coordinates { from, count } => i32::from((from..from + count).contains(&i)),
            Scaling::Quadric => match i {
                0..6 => 1,
                6..12 => -2,
                12..15 => -1,
                _ => 0,
            },
            Scaling::Tagged(_) => self.tag(fields).map_or(0, |t| {
                if (1..=t.count).contains(&i) {
                    1
                } else if (t.count + 1..=t.count + t.squared).contains(&i) {
                    2
                } else {
                    0
                }
            }),
        }
    }

    /// Whether a line is part of a whole file's set (a point, a vertex):
    /// a file whose set cannot be scaled is skipped whole.
    fn is_set(self, fields: &[&str]) -> bool {
        self.tag(fields).is_some_and(|t| t.set)
    }

    /// Whether a line is a case: every line of a per-line kind, a query
    /// of a whole-file kind.
    fn is_case(self, fields: &[&str]) -> bool {
        match self {
            Scaling::Tagged(_) => self.tag(fields).is_some_and(|t| !t.set),
            _ => true,
        }
    }

    /// The [`Tag`] of a whole-file kind's line.
    fn tag(self, fields: &[&str]) -> Option<&'static Tag> {
        match self {
            Scaling::Tagged(tags) => tags.iter().find(|t| fields.first() == Some(&t.tag)),
            _ => None,
        }
    }
}

/// `nearest`: `p x y z` (the set) and `q x y z i ...`.
const NEAREST_TAGS: &[Tag] = &[
    Tag {
        tag: "p",
        count: 3,
        squared: 0,
        set: true,
    },
    Tag {
        tag: "q",
        count: 3,
        squared: 0,
        set: false,
    },
];

/// `mesh_side`: `v x y z` (the set), `f i j k`, `p x y z side`.
const MESH_SIDE_TAGS: &[Tag] = &[
    Tag {
        tag: "v",
        count: 3,
        squared: 0,
        set: true,
    },
    Tag {
        tag: "p",
        count: 3,
        squared: 0,
        set: false,
    },
];

/// `mesh_closest`: `v x y z` (the set), `f i j k`, `p x y z d2 tri ...`
/// (`d2` a squared distance).
const MESH_CLOSEST_TAGS: &[Tag] = &[
    Tag {
        tag: "v",
        count: 3,
        squared: 0,
        set: true,
    },
    Tag {
        tag: "p",
        count: 3,
        squared: 1,
        set: false,
    },
];

/// `ray_mesh`: `v x y z` (the set), `f i j k` (unchanged), `r o d ...` and
/// `s p q blocked`.
const RAY_MESH_TAGS: &[Tag] = &[
    Tag {
        tag: "v",
        count: 3,
        squared: 0,
        set: true,
    },
    Tag {
        tag: "r",
        count: 6,
        squared: 0,
        set: false,
    },
    Tag {
        tag: "s",
        count: 6,
        squared: 0,
        set: false,
    },
];

const KINDS: &[Kind] = &[
    Kind {
        name: "orient2d",
        min_fields: 7,
        predicate: Some(PerLine(crate_orient2d)),
        oracle: Some(PerLine(oracle_orient2d)),
        scaling: Scaling::Coordinates { from: 0, count: 6 },
    },
    Kind {
        name: "orient3d",
        min_fields: 13,
        predicate: Some(PerLine(crate_orient3d)),
        oracle: Some(PerLine(oracle_orient3d)),
        scaling: Scaling::Coordinates { from: 0, count: 12 },
    },
    Kind {
        name: "plane_side",
        min_fields: 16,
        predicate: Some(PerLine(crate_plane_side)),
        oracle: Some(PerLine(oracle_plane_side)),
        scaling: Scaling::Coordinates { from: 0, count: 15 },
    },
    Kind {
        name: "incircle",
        min_fields: 9,
        predicate: Some(PerLine(crate_incircle)),
        oracle: Some(PerLine(oracle_incircle)),
        scaling: Scaling::Coordinates { from: 0, count: 8 },
    },
    Kind {
        name: "insphere",
        min_fields: 16,
        predicate: Some(PerLine(crate_insphere)),
        oracle: Some(PerLine(oracle_insphere)),
        scaling: Scaling::Coordinates { from: 0, count: 15 },
    },
    Kind {
        name: "orient3d_lpi",
        min_fields: 25,
        predicate: Some(PerLine(crate_orient3d_lpi)),
        oracle: Some(PerLine(oracle_orient3d_lpi)),
        scaling: Scaling::Coordinates { from: 0, count: 24 },
    },
    Kind {
        name: "orient3d_tpi",
        min_fields: 37,
        predicate: Some(PerLine(crate_orient3d_tpi)),
        oracle: Some(PerLine(oracle_orient3d_tpi)),
        scaling: Scaling::Coordinates { from: 0, count: 36 },
    },
    Kind {
        name: "orient2d_ssi",
        min_fields: 13,
        predicate: Some(PerLine(crate_orient2d_ssi)),
        oracle: Some(PerLine(oracle_orient2d_ssi)),
        scaling: Scaling::Coordinates { from: 0, count: 12 },
    },
    Kind {
        name: "less_on_axis_lpi",
        min_fields: 32,
        predicate: Some(PerLine(crate_less_on_axis_lpi)),
        oracle: Some(PerLine(oracle_less_on_axis_lpi)),
        scaling: Scaling::Coordinates { from: 1, count: 30 },
    },
    Kind {
        name: "ray_sphere",
        min_fields: 11,
        predicate: Some(PerLine(crate_ray_sphere)),
        oracle: Some(PerLine(oracle_ray_sphere)),
        scaling: Scaling::Coordinates { from: 0, count: 10 },
    },
    Kind {
        name: "ray_cylinder",
        min_fields: 14,
        predicate: Some(PerLine(crate_ray_cylinder)),
        oracle: Some(PerLine(oracle_ray_cylinder)),
        scaling: Scaling::Coordinates { from: 0, count: 13 },
    },
    Kind {
        name: "ray_cone",
        min_fields: 14,
        predicate: Some(PerLine(crate_ray_cone)),
        oracle: Some(PerLine(oracle_ray_cone)),
        scaling: Scaling::Coordinates { from: 0, count: 13 },
    },
    Kind {
        name: "ray_quadric",
        min_fields: 17,
        predicate: Some(PerLine(crate_ray_quadric)),
        oracle: Some(PerLine(oracle_ray_quadric)),
        scaling: Scaling::Quadric,
    },
    Kind {
        name: "ray_triangle",
        min_fields: 16,
        predicate: Some(PerLine(crate_ray_triangle)),
        oracle: Some(PerLine(oracle_ray_triangle)),
        scaling: Scaling::Coordinates { from: 0, count: 15 },
    },
    Kind {
        name: "nearest",
        min_fields: 4,
        predicate: Some(WholeFile(crate_nearest)),
        oracle: Some(WholeFile(oracle_nearest)),
        scaling: Scaling::Tagged(NEAREST_TAGS),
    },
    Kind {
        name: "ray_mesh",
        min_fields: 4,
        predicate: Some(WholeFile(crate_ray_mesh)),
        oracle: Some(WholeFile(oracle_ray_mesh)),
        scaling: Scaling::Tagged(RAY_MESH_TAGS),
    },
    Kind {
        name: "mesh_side",
        min_fields: 4,
        predicate: Some(WholeFile(crate_mesh_side)),
        oracle: Some(WholeFile(oracle_mesh_side)),
        scaling: Scaling::Tagged(MESH_SIDE_TAGS),
    },
    Kind {
        name: "mesh_closest",
        min_fields: 4,
        predicate: Some(WholeFile(crate_mesh_closest)),
        oracle: Some(WholeFile(oracle_mesh_closest)),
        scaling: Scaling::Tagged(MESH_CLOSEST_TAGS),
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

/// A sign line of `N` coordinates against `sign(coordinates)`.
fn check_sign<const N: usize>(
    f: &[&str],
    sign: impl Fn(&[f64; N]) -> i8,
) -> Result<Verdict, String> {
    let (v, want) = parse_sign_case::<N>(f)?;
    Ok(compare_signs(want, sign(&v)))
}

fn crate_orient2d(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<6>(f, |v| {
        exactray::predicates::orient2d(p2(v, 0), p2(v, 1), p2(v, 2)).as_i8()
    })
}

fn oracle_orient2d(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<6>(f, |v| oracle::orient2d(p2(v, 0), p2(v, 1), p2(v, 2)))
}

fn crate_orient3d(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<12>(f, |v| {
        exactray::predicates::orient3d(p3(v, 0), p3(v, 1), p3(v, 2), p3(v, 3)).as_i8()
    })
}

fn oracle_orient3d(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<12>(f, |v| {
        oracle::orient3d(p3(v, 0), p3(v, 1), p3(v, 2), p3(v, 3))
    })
}

fn crate_plane_side(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<15>(f, |v| {
        exactray::predicates::same_side(p3(v, 0), p3(v, 1), p3(v, 2), p3(v, 3), p3(v, 4)).as_i8()
    })
}

fn oracle_plane_side(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<15>(f, |v| {
        oracle::plane_side(p3(v, 0), p3(v, 1), p3(v, 2), p3(v, 3), p3(v, 4))
    })
}

/// incircle: the crate and CGAL's `side_of_oriented_circle` share the sign
/// convention (positive inside a counterclockwise circle).
fn crate_incircle(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<8>(f, |v| {
        exactray::predicates::incircle(p2(v, 0), p2(v, 1), p2(v, 2), p2(v, 3)).as_i8()
    })
}

fn oracle_incircle(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<8>(f, |v| {
        oracle::incircle(p2(v, 0), p2(v, 1), p2(v, 2), p2(v, 3))
    })
}

/// insphere: the crate documents CGAL's `side_of_oriented_sphere` sign
/// (the opposite of Shewchuk's), which the fixtures hold; no conversion.
fn crate_insphere(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<15>(f, |v| {
        exactray::predicates::insphere(p3(v, 0), p3(v, 1), p3(v, 2), p3(v, 3), p3(v, 4)).as_i8()
    })
}

fn oracle_insphere(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<15>(f, |v| {
        oracle::insphere(p3(v, 0), p3(v, 1), p3(v, 2), p3(v, 3), p3(v, 4))
    })
}

// ---------------------------------------------------------------------------
// Predicates on constructed points: the points' inputs, then the sign.

/// A constructed point the crate refuses: always a mismatch (every fixture
/// line defines one point).
fn refused(want: i8, e: exactray::InputError) -> Verdict {
    Verdict::Mismatch {
        expected: want.to_string(),
        got: format!("construction refused: {e}"),
    }
}

/// A sign line whose answer needs constructions: `sign(coordinates)`, or a
/// construction error.
fn check_constructed<const N: usize>(
    f: &[&str],
    sign: impl Fn(&[f64; N]) -> Result<i8, exactray::InputError>,
) -> Result<Verdict, String> {
    let (v, want) = parse_sign_case::<N>(f)?;
    Ok(match sign(&v) {
        Ok(got) => compare_signs(want, got),
        Err(e) => refused(want, e),
    })
}

fn lpi_of(v: &[f64], i: usize) -> Result<exactray::predicates::Lpi, exactray::InputError> {
    let p = |k: usize| p3(v, i + k);
    exactray::predicates::Lpi::new(p(0), p(1), p(2), p(3), p(4))
}

fn lpi_pt(v: &[f64], i: usize) -> Pt3 {
    Pt3::Lpi(core::array::from_fn(|k| p3(v, i + k)))
}

/// The axis field of a `less_on_axis_lpi` line.
fn axis_of(x: f64) -> Result<usize, String> {
    match x {
        0.0 => Ok(0),
        1.0 => Ok(1),
        2.0 => Ok(2),
        _ => Err(format!("bad axis {x} (want 0, 1 or 2)")),
    }
}

fn crate_orient3d_lpi(f: &[&str]) -> Result<Verdict, String> {
    check_constructed::<24>(f, |v| {
        let x = lpi_of(v, 3)?;
        Ok(exactray::predicates::orient3d_implicit(p3(v, 0), p3(v, 1), p3(v, 2), &x).as_i8())
    })
}

fn oracle_orient3d_lpi(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<24>(f, |v| {
        let e = |i| Pt3::E(p3(v, i));
        implicit_oracle::orient3d([e(0), e(1), e(2), lpi_pt(v, 3)]).unwrap_or(2)
    })
}

fn crate_orient3d_tpi(f: &[&str]) -> Result<Verdict, String> {
    check_constructed::<36>(f, |v| {
        let plane = |i: usize| [p3(v, i), p3(v, i + 1), p3(v, i + 2)];
        let x = exactray::predicates::Tpi::new(plane(3), plane(6), plane(9))?;
        Ok(exactray::predicates::orient3d_implicit(p3(v, 0), p3(v, 1), p3(v, 2), &x).as_i8())
    })
}

fn oracle_orient3d_tpi(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<36>(f, |v| {
        let e = |i| Pt3::E(p3(v, i));
        let plane = |i: usize| [p3(v, i), p3(v, i + 1), p3(v, i + 2)];
        let x = Pt3::Tpi([plane(3), plane(6), plane(9)]);
        implicit_oracle::orient3d([e(0), e(1), e(2), x]).unwrap_or(2)
    })
}

fn crate_orient2d_ssi(f: &[&str]) -> Result<Verdict, String> {
    check_constructed::<12>(f, |v| {
        let x = exactray::predicates::Ssi::new(p2(v, 2), p2(v, 3), p2(v, 4), p2(v, 5))?;
        Ok(exactray::predicates::orient2d_implicit(p2(v, 0), p2(v, 1), &x).as_i8())
    })
}

fn oracle_orient2d_ssi(f: &[&str]) -> Result<Verdict, String> {
    check_sign::<12>(f, |v| {
        let x = Pt2::Ssi([p2(v, 2), p2(v, 3), p2(v, 4), p2(v, 5)]);
        implicit_oracle::orient2d([Pt2::E(p2(v, 0)), Pt2::E(p2(v, 1)), x]).unwrap_or(2)
    })
}

/// `axis p q r s t p' q' r' s' t' sign`: the points start after the axis.
fn crate_less_on_axis_lpi(f: &[&str]) -> Result<Verdict, String> {
    let axis = axis_of(parse_f64(f.first().ok_or("empty line")?)?)?;
    check_constructed::<31>(f, |v| {
        let (x, y) = (lpi_of(&v[1..], 0)?, lpi_of(&v[1..], 5)?);
        let axes = exactray::predicates::Axis::ALL;
        Ok(exactray::predicates::cmp_on_axis(&x, &y, axes[axis]) as i8)
    })
}

fn oracle_less_on_axis_lpi(f: &[&str]) -> Result<Verdict, String> {
    let axis = axis_of(parse_f64(f.first().ok_or("empty line")?)?)?;
    check_sign::<31>(f, |v| {
        implicit_oracle::cmp_on_axis3(lpi_pt(&v[1..], 0), lpi_pt(&v[1..], 5), axis)
            .map_or(2, |o| o as i8)
    })
}

// ---------------------------------------------------------------------------
// Rays against quadrics: `inputs... n [t0 [t1]]`

/// How far a root may lie from the fixture's correctly rounded root.
const ROOT_ULPS: u64 = 4;

/// The expected answer of a ray line after its `inputs` numbers: the count
/// (`None` for `inf`) and the roots. Spheres and cylinders write a tangent
/// root twice; quadrics once.
fn parse_line_answer(
    f: &[&str],
    inputs: usize,
    tangent_twice: bool,
) -> Result<(Vec<f64>, LineAnswer), String> {
    if f.len() <= inputs {
        return Err(format!("expected at least {} fields", inputs + 1));
    }
    let v = f[..inputs]
        .iter()
        .map(|x| parse_f64(x))
        .collect::<Result<Vec<_>, _>>()?;
    let count = match f[inputs] {
        "inf" => None,
        n => Some(
            n.parse::<usize>()
                .map_err(|_| format!("bad root count {n:?}"))?,
        ),
    };
    let fields = match count {
        None | Some(0) => 0,
        Some(1) if tangent_twice => 2,
        Some(n) => n,
    };
    if f.len() != inputs + 1 + fields {
        return Err(format!(
            "expected {} fields, found {}",
            inputs + 1 + fields,
            f.len()
        ));
    }
    let mut roots = f[inputs + 1..]
        .iter()
        .map(|x| parse_f64(x))
        .collect::<Result<Vec<_>, _>>()?;
    if count == Some(1) && tangent_twice {
        if roots[0] != roots[1] {
            return Err("a tangent's two roots differ".into());
        }
        roots.truncate(1);
    }
    Ok((v, LineAnswer { count, roots }))
}

fn compare_roots(want: &LineAnswer, got: Roots) -> Verdict {
    let roots: Vec<f64> = match got {
        Roots::One(t) => vec![t],
        Roots::Two(t0, t1) => vec![t0, t1],
        _ => vec![],
    };
    let close = roots.len() == want.roots.len()
        && roots
            .iter()
            .zip(&want.roots)
            .all(|(g, w)| ulps_between(*g, *w) <= ROOT_ULPS);
    if got.count() == want.count && close {
        Verdict::Pass
    } else {
        Verdict::Mismatch {
            expected: format!("{want:?}"),
            got: format!("{got:?}"),
        }
    }
}

/// The oracle must reproduce the fixture exactly: the same count and the
/// same correctly rounded roots.
fn compare_answers(want: &LineAnswer, got: LineAnswer) -> Verdict {
    if *want == got {
        Verdict::Pass
    } else {
        Verdict::Mismatch {
            expected: format!("{want:?}"),
            got: format!("{got:?}"),
        }
    }
}

fn ray_of(v: &[f64]) -> Result<Ray, String> {
    Ray::new(p3(v, 0), p3(v, 1)).map_err(|e| e.to_string())
}

fn crate_ray_sphere(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_line_answer(f, 10, true)?;
    let sphere = Sphere::new(p3(&v, 2), v[9]).map_err(|e| e.to_string())?;
    Ok(compare_roots(&want, sphere.line_roots(&ray_of(&v)?)))
}

fn oracle_ray_sphere(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_line_answer(f, 10, true)?;
    Ok(compare_answers(
        &want,
        Quadratic::sphere(p3(&v, 0), p3(&v, 1), p3(&v, 2), v[9]).answer(),
    ))
}

fn crate_ray_cylinder(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_line_answer(f, 13, true)?;
    let cyl = Cylinder::new(p3(&v, 2), p3(&v, 3), v[12]).map_err(|e| e.to_string())?;
    Ok(compare_roots(&want, cyl.line_roots(&ray_of(&v)?)))
}

fn oracle_ray_cylinder(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_line_answer(f, 13, true)?;
    let q = Quadratic::cylinder(p3(&v, 0), p3(&v, 1), p3(&v, 2), p3(&v, 3), v[12]);
    Ok(compare_answers(&want, q.answer()))
}

/// The fixture's double cone as the crate's: the same apex, axis and
/// radius at `apex + axis`, and the same polynomial (`Cone::line_roots`
/// covers both nappes). Only `r^2` enters it, so a negative `r` is the cone
/// of radius `|r|`; `r = 0` (the axis line, doubled) is no `Cone`, which
/// rejects a zero radius, and the line is reported as unusable.
fn cone_of(v: &[f64]) -> Result<Cone, String> {
    if v[12] == 0.0 {
        return Err("r = 0: the cone degenerates to its axis, which Cone cannot express".into());
    }
    Cone::infinite(p3(v, 2), p3(v, 3), v[12].abs()).map_err(|e| e.to_string())
}

/// `line_roots` promises the sphere's accuracy (4 ulps of the correctly
/// rounded root) for roots in the normal range, which is where the
/// fixtures' roots lie.
fn crate_ray_cone(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_line_answer(f, 13, false)?;
    Ok(compare_roots(&want, cone_of(&v)?.line_roots(&ray_of(&v)?)))
}

fn oracle_ray_cone(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_line_answer(f, 13, false)?;
    let q = Quadratic::cone(p3(&v, 0), p3(&v, 1), p3(&v, 2), p3(&v, 3), v[12]);
    Ok(compare_answers(&want, q.answer()))
}

fn quadric_coefficients(v: &[f64]) -> [f64; 10] {
    core::array::from_fn(|i| v[6 + i])
}

fn crate_ray_quadric(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_line_answer(f, 16, false)?;
    let q = Quadric::new(quadric_coefficients(&v)).map_err(|e| e.to_string())?;
    Ok(compare_roots(&want, q.line_roots(&ray_of(&v)?)))
}

fn oracle_ray_quadric(f: &[&str]) -> Result<Verdict, String> {
    let (v, want) = parse_line_answer(f, 16, false)?;
    let q = Quadratic::quadric(p3(&v, 0), p3(&v, 1), quadric_coefficients(&v));
    Ok(compare_answers(&want, q.answer()))
}

// ---------------------------------------------------------------------------
// Rays against triangles: `o d v0 v1 v2 hit [t]`

/// A ray_triangle line: the 15 inputs, `hit` (0, 1 or 2) and `t` for 1.
fn parse_ray_triangle(f: &[&str]) -> Result<(Vec<f64>, u8, Option<f64>), String> {
    let v = f[..15]
        .iter()
        .map(|x| parse_f64(x))
        .collect::<Result<Vec<_>, _>>()?;
    let hit: u8 = f[15].parse().map_err(|_| format!("bad hit {:?}", f[15]))?;
    match (hit, f.len()) {
        (0 | 2, 16) => Ok((v, hit, None)),
        (1, 17) => Ok((v, hit, Some(parse_f64(f[16])?))),
        _ => Err(format!("hit {hit} with {} fields", f.len())),
    }
}

fn verdict(ok: bool, expected: String, got: String) -> Verdict {
    if ok {
        Verdict::Pass
    } else {
        Verdict::Mismatch { expected, got }
    }
}

/// The exact cast must agree with CGAL's do_intersect (coplanar `hit=2`
/// may go either way) and give `t` within 4 ulps of the correctly rounded
/// parameter.
fn crate_ray_triangle(f: &[&str]) -> Result<Verdict, String> {
    let (v, hit, t) = parse_ray_triangle(f)?;
    let tri = Triangle::new(p3(&v, 2), p3(&v, 3), p3(&v, 4)).map_err(|e| e.to_string())?;
    let got = tri.cast_exact(&ray_of(&v)?, Interval::FORWARD).map(|h| h.t);
    let ok = match (hit, got, t) {
        (0, None, _) | (2, _, _) => true,
        (1, Some(g), Some(w)) => ulps_between(g, w) <= ROOT_ULPS,
        _ => false,
    };
    Ok(verdict(
        ok,
        format!("hit {hit} t {t:?}"),
        format!("{got:?}"),
    ))
}

/// The num-bigint oracle against CGAL: a crossing at exactly the fixture's
/// (correctly rounded) parameter for `hit=1`, none with `t >= 0` for
/// `hit=0`, a coplanar line or a degenerate triangle for `hit=2`.
fn oracle_ray_triangle(f: &[&str]) -> Result<Verdict, String> {
    let (v, hit, t) = parse_ray_triangle(f)?;
    let l = oracle::line_triangle(p3(&v, 0), p3(&v, 1), [p3(&v, 2), p3(&v, 3), p3(&v, 4)]);
    let crossing = l.t.as_ref().filter(|(_, den)| !den.is_zero());
    let forward = crossing.filter(|(num, den)| oracle::ratio_in(num, den, 0.0, f64::INFINITY));
    let degenerate = l.t.as_ref().is_some_and(|(_, den)| den.is_zero());
    let ok = match (hit, forward, t) {
        (0, None, _) => true,
        (1, Some((num, den)), Some(t)) => oracle::within_units(t, num, den, 1),
        (2, _, _) => l.coplanar || degenerate || crossing.is_none(),
        _ => false,
    };
    Ok(verdict(
        ok,
        format!("hit {hit} t {t:?}"),
        format!("coplanar {} crossing {}", l.coplanar, forward.is_some()),
    ))
}

// ---------------------------------------------------------------------------
// Nearest: one point set per file

/// A nearest file: `p x y z` lines (the points, indexed from 0 in order) and
/// `q x y z i [i ...]` lines (a query and every index at exactly the
/// smallest distance, strictly ascending).
struct NearestFile {
    points: Vec<[f64; 3]>,
    /// (position among the file's lines, query, expected indices).
    queries: Vec<(usize, [f64; 3], Vec<usize>)>,
}

fn parse_point3(fields: &[&str]) -> Result<[f64; 3], String> {
    Ok([
        parse_f64(fields[0])?,
        parse_f64(fields[1])?,
        parse_f64(fields[2])?,
    ])
}

/// The file, or the first line that cannot be parsed with why.
fn parse_nearest(lines: &[Vec<&str>]) -> Result<NearestFile, (usize, String)> {
    let mut file = NearestFile {
        points: Vec::new(),
        queries: Vec::new(),
    };
    for (i, f) in lines.iter().enumerate() {
        match f[0] {
            "p" if f.len() == 4 => file.points.push(parse_point3(&f[1..]).map_err(|e| (i, e))?),
            "p" => return Err((i, format!("a p line has 4 fields, found {}", f.len()))),
            "q" if f.len() >= 5 => {
                let q = parse_point3(&f[1..4]).map_err(|e| (i, e))?;
                let mut want = Vec::with_capacity(f.len() - 4);
                for field in &f[4..] {
                    let index: usize = field
                        .parse()
                        .map_err(|e| (i, format!("bad index {field:?}: {e}")))?;
                    if want.last().is_some_and(|&last| last >= index) {
                        return Err((i, "indices must be strictly ascending".to_string()));
                    }
                    want.push(index);
                }
                file.queries.push((i, q, want));
            }
            "q" => {
                return Err((
                    i,
                    format!("a q line has at least 5 fields, found {}", f.len()),
                ));
            }
            tag => return Err((i, format!("expected a p or q line, found {tag:?}"))),
        }
    }
    // Indices refer to the whole set, so they are checked once it is read.
    for (i, _, want) in &file.queries {
        if let Some(&bad) = want.iter().find(|&&index| index >= file.points.len()) {
            let n = file.points.len();
            return Err((*i, format!("index {bad} but the file has {n} points")));
        }
    }
    Ok(file)
}

/// Runs `check` on every query, catching panics per query.
fn nearest_queries(
    lines: &[Vec<&str>],
    check: impl Fn(&NearestFile, [f64; 3], &[usize]) -> Verdict,
) -> Vec<(usize, Outcome)> {
    let file = match parse_nearest(lines) {
        Ok(file) => file,
        Err((i, e)) => return vec![(i, Ok(Err(e)))],
    };
    file.queries
        .iter()
        .map(|(i, q, want)| {
            let outcome = catch_unwind(AssertUnwindSafe(|| Ok(check(&file, *q, want))));
            (*i, outcome)
        })
        .collect()
}

fn one_of(want: &[usize]) -> String {
    if want.len() == 1 {
        want[0].to_string()
    } else {
        format!("one of {want:?}")
    }
}

/// `nearest(q)` and `nearest_k(q)` with k = 1 must return one of the listed
/// indices (and that index's point).
fn crate_nearest(lines: &[Vec<&str>]) -> Vec<(usize, Outcome)> {
    // Built once per file, on first use: a file that does not parse has none.
    let bvh = std::cell::OnceCell::new();
    nearest_queries(lines, |file, q, want| {
        let bvh: &SphereBvh = bvh
            .get_or_init(|| SphereBvh::from_points(&file.points).expect("the points are finite"));
        let mismatch = |got: String| Verdict::Mismatch {
            expected: one_of(want),
            got,
        };
        let Some(hit) = bvh.nearest(q) else {
            return mismatch("nearest: None".to_string());
        };
        if !want.contains(&hit.index) {
            return mismatch(format!("nearest: {}", hit.index));
        }
        if hit.point.to_array() != file.points[hit.index] {
            return mismatch(format!("nearest: {} with point {}", hit.index, hit.point));
        }
        let mut out = [Nearest {
            index: usize::MAX,
            point: glam::DVec3::NAN,
            distance: f64::NAN,
        }];
        let n = bvh.nearest_k(q, &mut out);
        if n != 1 || !want.contains(&out[0].index) {
            return mismatch(format!(
                "nearest_k (k = 1): {n} answers, index {}",
                out[0].index
            ));
        }
        Verdict::Pass
    })
}

/// Every point at exactly the smallest distance, by the num-bigint oracle:
/// the listed indices must be exactly those.
fn oracle_nearest(lines: &[Vec<&str>]) -> Vec<(usize, Outcome)> {
    let set = std::cell::OnceCell::new();
    nearest_queries(lines, |file, q, want| {
        let set = set.get_or_init(|| oracle::ExactPointSet::new(&file.points));
        let got = set.nearest(q);
        if got == want {
            Verdict::Pass
        } else {
            Verdict::Mismatch {
                expected: format!("{want:?}"),
                got: format!("{got:?}"),
            }
        }
    })
}

// ---------------------------------------------------------------------------
// Ray meshes: one mesh per file

/// A `ray_mesh` query line: its position among the file's lines and what
/// it asks.
enum MeshQuery {
    /// `r`: the ray, and the hit (`t`, every triangle containing the exact
    /// first point, strictly ascending) or `None` for a miss.
    Ray {
        o: [f64; 3],
        d: [f64; 3],
        want: Option<(f64, Vec<usize>)>,
    },
    /// `s`: the segment's ends and whether it is blocked.
    Segment {
        p: [f64; 3],
        q: [f64; 3],
        blocked: bool,
    },
    /// `p x y z side` (`mesh_side`): `1` inside, `0` on the boundary, `-1`
    /// outside.
    Side { p: [f64; 3], side: i8 },
    /// `p x y z d2 tri ...` (`mesh_closest`): the least squared distance,
    /// rounded, and every triangle at exactly it, strictly ascending.
    Closest {
        p: [f64; 3],
        d2: f64,
        tris: Vec<usize>,
    },
}

/// A `ray_mesh` file: `v x y z` vertices and `f i j k` triangles (each
/// indexed from 0 in order, `v` and `f` lines in any order), `r` and `s`
/// queries against them.
struct MeshFile {
    vertices: Vec<[f64; 3]>,
    triangles: Vec<[u32; 3]>,
    /// The position of each `f` line, to report a bad index there.
    triangle_lines: Vec<usize>,
    queries: Vec<(usize, MeshQuery)>,
}

fn parse_index(field: &str) -> Result<usize, String> {
    // `usize::from_str` accepts a leading `+`; the format does not.
    if field.starts_with('+') {
        return Err(format!("bad index {field:?}"));
    }
    field
        .parse()
        .map_err(|e| format!("bad index {field:?}: {e}"))
}

fn parse_flag(field: &str, what: &str) -> Result<bool, String> {
    match field {
        "0" => Ok(false),
        "1" => Ok(true),
        _ => Err(format!("bad {what} {field:?} (want 0 or 1)")),
    }
}

/// Triangle indices, strictly ascending.
fn ascending_indices(fields: &[&str]) -> Result<Vec<usize>, String> {
    let mut tris: Vec<usize> = Vec::with_capacity(fields.len());
    for field in fields {
        let index = parse_index(field)?;
        if tris.last().is_some_and(|&last| last >= index) {
            return Err("triangles must be strictly ascending".to_string());
        }
        tris.push(index);
    }
    Ok(tris)
}

fn parse_mesh_line(f: &[&str], file: &mut MeshFile, i: usize) -> Result<(), String> {
    let count = |n: usize, tag: &str| {
        if f.len() == n {
            Ok(())
        } else {
            Err(format!("a {tag} line has {n} fields, found {}", f.len()))
        }
    };
    match f[0] {
        "v" => {
            count(4, "v")?;
            file.vertices.push(parse_point3(&f[1..])?);
        }
        "f" => {
            count(4, "f")?;
            let mut t = [0u32; 3];
            for (x, field) in t.iter_mut().zip(&f[1..]) {
                *x = u32::try_from(parse_index(field)?)
                    .map_err(|_| format!("index {field} beyond u32"))?;
            }
            file.triangles.push(t);
            file.triangle_lines.push(i);
        }
        "r" => {
            if f.len() < 8 {
                return Err(format!(
                    "an r line has at least 8 fields, found {}",
                    f.len()
                ));
            }
            let (o, d) = (parse_point3(&f[1..4])?, parse_point3(&f[4..7])?);
            let want = if parse_flag(f[7], "hit")? {
                if f.len() < 10 {
                    return Err("a hit needs t and at least one triangle".to_string());
                }
                let t = parse_f64(f[8])?;
                Some((t, ascending_indices(&f[9..])?))
            } else {
                count(8, "miss (hit 0) r")?;
                None
            };
            file.queries.push((i, MeshQuery::Ray { o, d, want }));
        }
        "s" => {
            count(8, "s")?;
            let (p, q) = (parse_point3(&f[1..4])?, parse_point3(&f[4..7])?);
            let blocked = parse_flag(f[7], "blocked")?;
            file.queries.push((i, MeshQuery::Segment { p, q, blocked }));
        }
        "p" if f.len() == 5 => {
            let side = match f[4] {
                "1" => 1,
                "0" => 0,
                "-1" => -1,
                other => return Err(format!("side must be 1, 0 or -1, found {other:?}")),
            };
            let p = parse_point3(&f[1..4])?;
            file.queries.push((i, MeshQuery::Side { p, side }));
        }
        "p" => {
            if f.len() < 6 {
                return Err(format!(
                    "a p line has 5 or at least 6 fields, found {}",
                    f.len()
                ));
            }
            let (p, d2) = (parse_point3(&f[1..4])?, parse_f64(f[4])?);
            let tris = ascending_indices(&f[5..])?;
            file.queries.push((i, MeshQuery::Closest { p, d2, tris }));
        }
        tag => return Err(format!("expected a v, f, r, s or p line, found {tag:?}")),
    }
    Ok(())
}

/// The file, or the first line that cannot be parsed with why: a
/// malformed line, a triangle's vertex index beyond the vertices, or a
/// query's triangle index beyond the triangles.
fn parse_ray_mesh(lines: &[Vec<&str>]) -> Result<MeshFile, (usize, String)> {
    let mut file = MeshFile {
        vertices: Vec::new(),
        triangles: Vec::new(),
        triangle_lines: Vec::new(),
        queries: Vec::new(),
    };
    for (i, f) in lines.iter().enumerate() {
        parse_mesh_line(f, &mut file, i).map_err(|e| (i, e))?;
    }
    let n = file.vertices.len();
    for (t, &at) in file.triangles.iter().zip(&file.triangle_lines) {
        if let Some(bad) = t.iter().find(|&&k| k as usize >= n) {
            return Err((at, format!("vertex {bad} but the file has {n} vertices")));
        }
    }
    let n = file.triangles.len();
    for (at, q) in &file.queries {
        let listed = match q {
            MeshQuery::Ray {
                want: Some((_, tris)),
                ..
            }
            | MeshQuery::Closest { tris, .. } => Some(tris),
            _ => None,
        };
        if let Some(tris) = listed
            && let Some(bad) = tris.iter().find(|&&k| k >= n)
        {
            return Err((
                *at,
                format!("triangle {bad} but the file has {n} triangles"),
            ));
        }
    }
    Ok(file)
}

/// Runs `check` on every query of a parsed file, catching panics per
/// query; `setup` runs once (building the mesh), and its error is the
/// first triangle line's problem.
fn mesh_queries<S>(
    lines: &[Vec<&str>],
    setup: impl Fn(&MeshFile) -> Result<S, String>,
    check: impl Fn(&MeshFile, &S, &MeshQuery) -> Result<Verdict, String>,
) -> Vec<(usize, Outcome)> {
    let file = match parse_ray_mesh(lines) {
        Ok(file) => file,
        Err((i, e)) => return vec![(i, Ok(Err(e)))],
    };
    let state = match catch_unwind(AssertUnwindSafe(|| setup(&file))) {
        Ok(Ok(state)) => state,
        Ok(Err(e)) => {
            return vec![(
                file.triangle_lines.first().copied().unwrap_or(0),
                Ok(Err(e)),
            )];
        }
        Err(p) => return vec![(0, Err(p))],
    };
    file.queries
        .iter()
        .map(|(i, q)| {
            let outcome = catch_unwind(AssertUnwindSafe(|| check(&file, &state, q)));
            (*i, outcome)
        })
        .collect()
}

/// What the crate's checker builds once per file: the mesh, and for each
/// triangle whether all three of its edges are shared by exactly two
/// triangles of the file (the watertight check's condition).
struct CrateMesh {
    mesh: TriangleMesh,
    closed: Vec<bool>,
}

fn crate_mesh_setup(file: &MeshFile) -> Result<CrateMesh, String> {
    let mesh = TriangleMesh::new(&file.vertices, &file.triangles).map_err(|e| e.to_string())?;
    let mut uses: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    let edges = |t: &[u32; 3]| {
        [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])].map(|(a, b)| (a.min(b), a.max(b)))
    };
    for t in &file.triangles {
        for e in edges(t) {
            *uses.entry(e).or_default() += 1;
        }
    }
    let closed = file
        .triangles
        .iter()
        .map(|t| edges(t).iter().all(|e| uses[e] == 2))
        .collect();
    Ok(CrateMesh { mesh, closed })
}

/// The crate on one `ray_mesh` query.
///
/// `r`: the exact variant (`closest_hit_with::<Exact>`) must agree on hit
/// or miss, give `t` within 4 ulps of the fixture's and one of the listed
/// triangles, and `occluded_with::<Exact>` must agree. The watertight
/// default must not miss where the exact point is shared (two or more
/// triangles listed) in a closed part of the mesh (every edge of every
/// listed triangle shared by exactly two triangles: a closed fan around
/// the point) and the ray crosses the surface there (every listed triangle
/// faces the ray on the same side, exactly, once the fan is taken in one
/// orientation: the fan's projection along the ray covers the point, where
/// its guarantee holds; [`oriented_alike`]). A ray lying in the
/// plane of a listed triangle, and a ray touching a silhouette edge or
/// vertex (the fan folds: its triangles face the ray on different sides,
/// and the shared edge's one rounded sign puts the ray outside all of
/// them or inside), it may call a miss (documented in `scene`).
///
/// `s`: `occluded_between_with::<Exact>` must equal `blocked`, and the
/// watertight `occluded_between` must answer.
fn crate_ray_mesh_query(file: &MeshFile, m: &CrateMesh, q: &MeshQuery) -> Result<Verdict, String> {
    match q {
        MeshQuery::Ray { o, d, want } => {
            let ray = Ray::new(*o, *d).map_err(|e| e.to_string())?;
            let exact = m.mesh.closest_hit_with::<Exact>(&ray, Interval::FORWARD);
            let occluded = m.mesh.occluded_with::<Exact>(&ray, Interval::FORWARD);
            let got = exact.map(|h| (h.hit.t, h.triangle as usize));
            let ok = occluded == want.is_some()
                && match (want, got) {
                    (None, None) => true,
                    (Some((t, tris)), Some((gt, gi))) => {
                        ulps_between(gt, *t) <= ROOT_ULPS && tris.contains(&gi)
                    }
                    _ => false,
                };
            if !ok {
                return Ok(Verdict::Mismatch {
                    expected: format!("exact {want:?}"),
                    got: format!("exact {got:?}, occluded {occluded}"),
                });
            }
            if let Some((_, tris)) = want
                && tris.len() >= 2
                && tris.iter().all(|&i| m.closed[i])
            {
                let lines: Vec<_> = tris
                    .iter()
                    .map(|&i| {
                        let v = file.triangles[i].map(|k| file.vertices[k as usize]);
                        oracle::line_triangle(*o, *d, v)
                    })
                    .collect();
                let in_plane = lines.iter().any(|l| l.coplanar);
                let fronts: Vec<bool> = lines.iter().map(|l| l.front).collect();
                let crosses = oriented_alike(&file.triangles, tris, &fronts)
                    .is_some_and(|f| f.iter().all(|&x| x == f[0]));
                if !in_plane && crosses && m.mesh.closest_hit(&ray, Interval::FORWARD).is_none() {
                    return Ok(Verdict::Mismatch {
                        expected: format!("a watertight hit at the shared point of {tris:?}"),
                        got: "a watertight miss".to_string(),
                    });
                }
            }
            Ok(Verdict::Pass)
        }
        MeshQuery::Segment { p, q, blocked } => {
            let got = m
                .mesh
                .occluded_between_with::<Exact>(*p, *q)
                .map_err(|e| e.to_string())?;
            // The watertight segment answers every finite pair too.
            m.mesh.occluded_between(*p, *q).map_err(|e| e.to_string())?;
            Ok(verdict(
                got == *blocked,
                format!("blocked {blocked}"),
                format!("blocked {got}"),
            ))
        }
        other => Err(not_this_kind(other)),
    }
}

/// The side each listed triangle faces the ray on (`fronts`, by each
/// triangle's own vertex order), taken in one orientation of the fan:
/// a triangle that runs an edge it shares with another in the same
/// direction is oriented against it, so its side is flipped. Then the
/// ray crosses the fan (its triangles lie around the point in the ray's
/// projection) exactly when every side agrees; a silhouette (the fan
/// folded) has both. `None` where the listed triangles are not joined by
/// shared edges.
fn oriented_alike(triangles: &[[u32; 3]], tris: &[usize], fronts: &[bool]) -> Option<Vec<bool>> {
    let edges = |i: usize| {
        let t = triangles[tris[i]];
        [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]
    };
    let mut flip: Vec<Option<bool>> = vec![None; tris.len()];
    let Some(first) = flip.first_mut() else {
        return Some(Vec::new());
    };
    *first = Some(false);
    for _ in 0..tris.len() {
        for i in 0..tris.len() {
            let Some(fi) = flip[i] else { continue };
            let ei = edges(i);
            for (j, slot) in flip.iter_mut().enumerate() {
                if slot.is_some() {
                    continue;
                }
                let ej = edges(j);
                for &(a, b) in &ei {
                    if ej.contains(&(a, b)) {
                        *slot = Some(!fi);
                    } else if ej.contains(&(b, a)) {
                        *slot = Some(fi);
                    }
                }
            }
        }
    }
    flip.iter()
        .zip(fronts)
        .map(|(f, &front)| f.map(|f| front != f))
        .collect()
}

/// The crate on one `mesh_side` query: `TriangleMesh::side` must give the
/// file's side exactly.
fn crate_mesh_side(lines: &[Vec<&str>]) -> Vec<(usize, Outcome)> {
    let setup = |file: &MeshFile| {
        TriangleMesh::new(&file.vertices, &file.triangles).map_err(|e| e.to_string())
    };
    mesh_queries(lines, setup, |_, mesh, q| match q {
        MeshQuery::Side { p, side } => {
            let got = match mesh.side(*p).map_err(|e| e.to_string())? {
                MeshSide::Inside => 1,
                MeshSide::OnBoundary => 0,
                MeshSide::Outside => -1,
            };
            Ok(verdict(
                got == *side,
                format!("side {side}"),
                format!("side {got}"),
            ))
        }
        other => Err(not_this_kind(other)),
    })
}

/// The oracle's exact winding number (`mesh_oracle::winding_number`) must
/// give the same side: on a triangle, around the point (inside) or not.
fn oracle_mesh_side(lines: &[Vec<&str>]) -> Vec<(usize, Outcome)> {
    let setup = |file: &MeshFile| -> Result<Vec<[usize; 3]>, String> {
        Ok(file
            .triangles
            .iter()
            .map(|t| t.map(|k| k as usize))
            .collect())
    };
    mesh_queries(lines, setup, |file, tris, q| match q {
        MeshQuery::Side { p, side } => {
            let got = match mesh_oracle::winding_number(*p, &file.vertices, tris) {
                None => 0,
                Some(0) => -1,
                Some(_) => 1,
            };
            Ok(verdict(
                got == *side,
                format!("side {side}"),
                format!("side {got}"),
            ))
        }
        other => Err(not_this_kind(other)),
    })
}

/// The crate on one `mesh_closest` query: `TriangleMesh::closest_point`
/// must pick a listed triangle, and its squared distance with its
/// certified error must hold the exact one, which lies within half an ulp
/// of the file's `d2` (so within `[d2.next_down(), d2.next_up()]`).
fn crate_mesh_closest(lines: &[Vec<&str>]) -> Vec<(usize, Outcome)> {
    let setup = |file: &MeshFile| {
        TriangleMesh::new(&file.vertices, &file.triangles).map_err(|e| e.to_string())
    };
    mesh_queries(lines, setup, |_, mesh, q| match q {
        MeshQuery::Closest { p, d2, tris } => {
            let Some(c) = mesh.closest_point(*p).map_err(|e| e.to_string())? else {
                return Ok(verdict(false, format!("{tris:?}"), "none".to_string()));
            };
            let (lo, hi) = (
                c.squared_distance - c.squared_distance_error,
                c.squared_distance + c.squared_distance_error,
            );
            // Each bound rounded once: one more step covers it.
            let holds = lo.next_down() <= d2.next_up() && d2.next_down() <= hi.next_up();
            Ok(verdict(
                tris.contains(&(c.triangle as usize)) && holds,
                format!("one of {tris:?} at {d2:e}"),
                format!(
                    "{} at {:e} +- {:e}",
                    c.triangle, c.squared_distance, c.squared_distance_error
                ),
            ))
        }
        other => Err(not_this_kind(other)),
    })
}

/// The oracle's exact squared distances (`closest_oracle`) must give the
/// same least distance, rounded, and the same triangles.
fn oracle_mesh_closest(lines: &[Vec<&str>]) -> Vec<(usize, Outcome)> {
    let setup = |_: &MeshFile| -> Result<(), String> { Ok(()) };
    mesh_queries(lines, setup, |file, _, q| match q {
        MeshQuery::Closest { p, d2, tris } => {
            let c =
                closest_oracle::closest_triangles(*p, &file.vertices, &file.triangles, |_| true);
            let least = c.least.map(|l| oracle::ratio_to_f64(&l.num, &l.den));
            Ok(verdict(
                least == Some(*d2) && c.ties == *tris,
                format!("{d2:e} at {tris:?}"),
                format!("{least:?} at {:?}", c.ties),
            ))
        }
        other => Err(not_this_kind(other)),
    })
}

fn crate_ray_mesh(lines: &[Vec<&str>]) -> Vec<(usize, Outcome)> {
    mesh_queries(lines, crate_mesh_setup, crate_ray_mesh_query)
}

/// The brute-force oracle (`exactray_oracle::mesh_oracle`) must reproduce
/// every answer exactly: hit or miss, `t` the correctly rounded exact
/// first parameter, the same list of triangles, `blocked`.
fn oracle_ray_mesh(lines: &[Vec<&str>]) -> Vec<(usize, Outcome)> {
    let setup = |file: &MeshFile| -> Result<Vec<[usize; 3]>, String> {
        Ok(file
            .triangles
            .iter()
            .map(|t| t.map(|k| k as usize))
            .collect())
    };
    mesh_queries(lines, setup, |file, tris, q| match q {
        MeshQuery::Ray { o, d, want } => {
            if *d == [0.0; 3] {
                return Err("zero direction".to_string());
            }
            let got = mesh_oracle::ray_mesh(*o, *d, &file.vertices, tris)
                .map(|(t, on)| (oracle::ratio_to_f64(&t.num, &t.den), on));
            Ok(verdict(
                got == *want,
                format!("{want:?}"),
                format!("{got:?}"),
            ))
        }
        MeshQuery::Segment { p, q, blocked } => {
            let got = mesh_oracle::segment_mesh(*p, *q, &file.vertices, tris);
            Ok(verdict(
                got == *blocked,
                format!("blocked {blocked}"),
                format!("blocked {got}"),
            ))
        }
        other => Err(not_this_kind(other)),
    })
}

/// The error for a query line of another mesh kind (a `p` line in a
/// `ray_mesh` file, say).
fn not_this_kind(q: &MeshQuery) -> String {
    let tag = match q {
        MeshQuery::Ray { .. } => "r",
        MeshQuery::Segment { .. } => "s",
        MeshQuery::Side { .. } => "p (mesh_side)",
        MeshQuery::Closest { .. } => "p (mesh_closest)",
    };
    format!("a {tag} line does not belong to this kind")
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

/// The scales the crate is also checked at: every file's configuration
/// multiplied by `2^k`, which leaves every answer unchanged.
const SCALES: [i32; 8] = [-1000, -900, -600, -300, 300, 600, 900, 1000];

#[derive(Default)]
struct Report {
    /// Cases checked by (kind, scale exponent; 0 for the files as written).
    checked: BTreeMap<(&'static str, i32), usize>,
    /// Lines of kinds without a checker.
    skipped: BTreeMap<&'static str, usize>,
    /// Lines left out of a scaled copy, by (kind, scale exponent): a
    /// number would leave the normal range (or the file's set would).
    unscaled: BTreeMap<(&'static str, i32), usize>,
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
        for ((kind, k), n) in &self.checked {
            let left = self.unscaled.get(&(*kind, *k)).copied().unwrap_or(0);
            match k {
                0 => println!("  {kind}: {n} cases checked"),
                _ => println!("  {kind} at 2^{k}: {n} cases checked, {left} left out"),
            }
        }
        for ((kind, k), n) in &self.unscaled {
            if !self.checked.contains_key(&(*kind, *k)) {
                println!("  {kind} at 2^{k}: 0 cases checked, {n} left out");
            }
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

    /// Records the outcome of the case on `line`, at scale `2^k`.
    fn record(&mut self, kind: &'static str, k: i32, line: &Line, outcome: Outcome) {
        let at = &line.at;
        match outcome {
            Ok(Ok(verdict)) => {
                *self.checked.entry((kind, k)).or_default() += 1;
                if let Verdict::Mismatch { expected, got } = verdict {
                    let section = &line.section;
                    let message = format!(
                        "{at} [{section}]: expected {expected}, got {got}: {}",
                        line.text()
                    );
                    self.mismatch(kind, section, message);
                }
            }
            Ok(Err(e)) => self.problems.push(format!("{at}: {e}")),
            Err(_) => self
                .problems
                .push(format!("{at}: panicked: {}", line.text())),
        }
    }
}

/// A line that is not a comment or blank (or a scaled copy of one).
struct Line {
    /// `file:line`, as reported (with the scale for a copy).
    at: String,
    /// The section it is in (the generator's `# section NAME: ...` lines).
    section: String,
    fields: Vec<String>,
}

impl Line {
    fn text(&self) -> String {
        self.fields.join(" ")
    }

    fn fields(&self) -> Vec<&str> {
        self.fields.iter().map(String::as_str).collect()
    }

    /// The line with its configuration scaled by `2^k` ([`Scaling`]), or
    /// `None` where a scaled number is not exact (see [`scale_exactly`]).
    /// A field that does not parse is kept as it is: the unscaled line
    /// reports it.
    fn scaled(&self, scaling: Scaling, k: i32) -> Option<Line> {
        let fields = self.fields();
        let mut out = Vec::with_capacity(fields.len());
        for (i, field) in fields.iter().enumerate() {
            let m = scaling.power(&fields, i);
            match field.parse::<f64>() {
                Ok(x) if m != 0 && x.is_finite() => {
                    out.push(format!("{:e}", scale_exactly(x, m * k)?));
                }
                _ => out.push(field.to_string()),
            }
        }
        Some(Line {
            at: format!("{} at 2^{k}", self.at),
            section: self.section.clone(),
            fields: out,
        })
    }
}

/// `x 2^e` where that is exact and normal (a zero stays zero), or `None`:
/// the product, rounded, must be a normal number and scale back to `x`
/// exactly. A value just below a power of two can round up to `2^-1022`
/// (normal, but not `x 2^e`). The check itself never rounds where it
/// matters: scaling up is exact (below overflow), and scaling a normal
/// `y` down to a normal `x` passes only through normal values between
/// them; a subnormal `x` is only ever scaled up, exactly.
fn scale_exactly(x: f64, e: i32) -> Option<f64> {
    let scale = |v: f64, e: i32| v * 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
    if x == 0.0 {
        return Some(x);
    }
    let y = scale(x, e);
    (y.is_normal() && scale(y, -e) == x).then_some(y)
}

/// Runs `check` on `lines` (one file's cases, or a scaled copy's) at scale
/// `2^k`; a panic is reported against its line rather than aborting.
fn check_lines(report: &mut Report, kind: &'static Kind, check: Check, k: i32, lines: &[Line]) {
    match check {
        PerLine(check) => {
            for line in lines {
                let outcome = catch_unwind(|| check(&line.fields()));
                report.record(kind.name, k, line, outcome);
            }
        }
        WholeFile(check) => {
            let fields: Vec<Vec<&str>> = lines.iter().map(Line::fields).collect();
            match catch_unwind(|| check(&fields)) {
                Ok(outcomes) => {
                    for (i, outcome) in outcomes {
                        report.record(kind.name, k, &lines[i], outcome);
                    }
                }
                Err(_) => {
                    let at = lines.first().map_or("?", |l| l.at.as_str());
                    report.problems.push(format!("{at}: the file panicked"));
                }
            }
        }
    }
}

/// The copy of a file's `lines` scaled by `2^k` and the number of cases
/// left out: a line of a per-line kind, or a query of a whole-file kind,
/// whose numbers would leave the normal range; every case of a whole file
/// whose set would.
fn scaled_copy(kind: &Kind, lines: &[Line], k: i32) -> (Vec<Line>, usize) {
    let mut copy = Vec::with_capacity(lines.len());
    let mut left_out = 0;
    for line in lines {
        match line.scaled(kind.scaling, k) {
            Some(scaled) => copy.push(scaled),
            None if kind.scaling.is_set(&line.fields()) => {
                let cases = lines.iter().filter(|l| kind.scaling.is_case(&l.fields()));
                return (Vec::new(), cases.count());
            }
            None => left_out += 1,
        }
    }
    (copy, left_out)
}

/// The lines of a fixture file that are not comments or blank, each with
/// its section; `None` with the problems where a line is malformed.
fn read_lines(file: &str, text: &str, report: &mut Report) -> Vec<Line> {
    let mut section = String::from("no section");
    let mut lines = Vec::new();
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
        lines.push(Line {
            at,
            section: section.clone(),
            fields: fields.iter().map(|f| f.to_string()).collect(),
        });
    }
    lines
}

/// Runs the checker that `select` picks from each line's kind over every
/// fixture line, and over copies of every file scaled by `2^k` for each
/// `k` of `scales`; kinds without a checker are counted as skipped.
fn run(select: fn(&Kind) -> Option<Check>, scales: &[i32]) -> Report {
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
        let lines = read_lines(&file, &text, &mut report);
        let Some(check) = select(kind) else {
            for line in &lines {
                if line.fields.len() < kind.min_fields {
                    report.problems.push(format!(
                        "{}: {} fields, a {} line has at least {}",
                        line.at,
                        line.fields.len(),
                        kind.name,
                        kind.min_fields
                    ));
                }
            }
            *report.skipped.entry(kind.name).or_default() += lines.len();
            continue;
        };
        check_lines(&mut report, kind, check, 0, &lines);
        for &k in scales {
            let (copy, left_out) = scaled_copy(kind, &lines, k);
            *report.unscaled.entry((kind.name, k)).or_default() += left_out;
            if !copy.is_empty() {
                check_lines(&mut report, kind, check, k, &copy);
            }
        }
    }
    report
}

/// The crate against every fixture, and against copies of every file
/// scaled by `2^k` for each `k` of [`SCALES`] (from `2^-1000` to
/// `2^1000`): an exact scaling leaves every answer unchanged.
#[test]
fn crate_matches_cgal_fixtures() {
    run(|k| k.predicate, &SCALES).finish("exactray against the CGAL fixtures");
}

#[test]
fn oracle_matches_cgal_fixtures() {
    run(|k| k.oracle, &[]).finish("the test oracle against the CGAL fixtures");
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

#[test]
fn ray_cone_lines_are_checked() {
    let fields = |line: &'static str| line.split(' ').collect::<Vec<_>>();
    let passes = |check: Checker, line| matches!(check(&fields(line)), Ok(Verdict::Pass));
    let mismatches =
        |check: Checker, line| matches!(check(&fields(line)), Ok(Verdict::Mismatch { .. }));
    // Apex 0, axis (0, 0, 2), radius 2 at (0, 0, 2): along x at height 0.5,
    // (t - 2)^2 = 0.25; along the ruling (1, 0, 1) every t; through the apex
    // a double root.
    let line = "-2 0 0.5 1 0 0 0 0 0 0 0 2 2";
    for check in [crate_ray_cone as Checker, oracle_ray_cone] {
        assert!(passes(check, "-2 0 0.5 1 0 0 0 0 0 0 0 2 2 2 1.5 2.5"));
        assert!(passes(check, "3 0 3 1 0 1 0 0 0 0 0 2 2 inf"));
        assert!(passes(check, "-1 -2 -3 1 2 3 0 0 0 0 0 2 2 1 1"));
        assert!(mismatches(check, "-2 0 0.5 1 0 0 0 0 0 0 0 2 2 2 1.5 2.75"));
        assert!(mismatches(check, "-2 0 0.5 1 0 0 0 0 0 0 0 2 2 0"));
        assert!(mismatches(check, "3 0 3 1 0 1 0 0 0 0 0 2 2 0"));
        for bad in [
            format!("{line} 2 1.5"),       // too few roots
            format!("{line} 1 1.5 2.5"),   // too many
            format!("{line} inf 1.5"),     // roots after inf
            format!("{line} two 1.5 2.5"), // bad count
            line.to_string(),              // no count
        ] {
            assert!(check(&bad.split(' ').collect::<Vec<_>>()).is_err(), "{bad}");
        }
    }
    // A negative radius is the same polynomial; a zero radius is no Cone.
    assert!(passes(
        crate_ray_cone,
        "-2 0 0.5 1 0 0 0 0 0 0 0 2 -2 2 1.5 2.5"
    ));
    assert!(crate_ray_cone(&fields("-2 0 0.5 1 0 0 0 0 0 0 0 2 0 1 2")).is_err());
}

/// A whole-file checker's outcomes on the lines of `text`: `Some(true)` a
/// pass, `Some(false)` a mismatch, `None` a line that cannot be parsed (or
/// a panic).
fn file_outcomes(check: FileChecker, text: &str) -> Vec<(usize, Option<bool>)> {
    let lines: Vec<Vec<&str>> = text.lines().map(|l| l.split(' ').collect()).collect();
    check(&lines)
        .into_iter()
        .map(|(i, o)| match o {
            Ok(Ok(Verdict::Pass)) => (i, Some(true)),
            Ok(Ok(Verdict::Mismatch { .. })) => (i, Some(false)),
            Ok(Err(_)) | Err(_) => (i, None),
        })
        .collect()
}

#[test]
fn nearest_files_are_parsed_strictly() {
    let outcomes = file_outcomes;
    // Points 0 and 2 are at distance 1 from the first query, point 1 at 1.5.
    let good = "p 0 0 1\np 0 0 -1.5\np 1 0 0\nq 0 0 0 0 2\nq 0 0 -2 1";
    for check in [crate_nearest as FileChecker, oracle_nearest] {
        assert_eq!(outcomes(check, good), [(3, Some(true)), (4, Some(true))]);
        // A wrong list: the crate's answer is not in it, or the oracle's differs.
        assert_eq!(
            outcomes(check, "p 0 0 1\np 0 0 -1.5\nq 0 0 0 1"),
            [(2, Some(false))]
        );
        for (bad, line) in [
            ("p 0 0\nq 0 0 0 0", 0),              // too few fields
            ("p 0 0 1 2\nq 0 0 0 0", 0),          // too many
            ("p 0 0 x\nq 0 0 0 0", 0),            // bad number
            ("p 0 0 inf\nq 0 0 0 0", 0),          // non-finite
            ("p 0 0 1\nq 0 0 0", 1),              // no index
            ("p 0 0 1\nq 0 0 0 1", 1),            // index out of range
            ("p 0 0 1\np 0 0 1\nq 0 0 0 1 0", 2), // not ascending
            ("p 0 0 1\np 0 0 1\nq 0 0 0 0 0", 2), // repeated
            ("p 0 0 1\nq 0 0 0 -1", 1),           // negative index
            ("p 0 0 1\nr 0 0 0 0", 1),            // unknown line
        ] {
            assert_eq!(outcomes(check, bad), [(line, None)], "{bad:?}");
        }
    }
    // The oracle ties exactly, across magnitudes.
    let set =
        oracle::ExactPointSet::new(&[[1e-300, 0.0, 0.0], [0.0, 0.0, -1e-300], [1.0, 0.0, 0.0]]);
    assert_eq!(set.nearest([0.0; 3]), [0, 1]);
    assert_eq!(set.nearest([0.0, 0.0, -5e-324]), [1]);
    assert_eq!(set.nearest([1.0, 5e-324, 0.0]), [2]);
    // Squared distances around 1e600, which overflow f64.
    let set =
        oracle::ExactPointSet::new(&[[1e300, 0.0, 0.0], [0.0, -1e300, 0.0], [3.0, 1e300, 0.0]]);
    assert_eq!(set.nearest([0.0; 3]), [0, 1]);
    assert_eq!(set.nearest([0.0, 0.0, 1e300]), [0, 1]);
    assert_eq!(set.nearest([5e-324, 0.0, 0.0]), [0]);
    assert_eq!(set.nearest([1.5, 1e300, 0.0]), [2]);
}

#[test]
fn ray_mesh_files_are_parsed_strictly() {
    let outcomes = file_outcomes;
    // The unit square in two triangles: a ray through the shared diagonal,
    // a ray in the plane entering through the edge x = 0 at t = 0.5, a
    // miss, a blocked and an unblocked segment.
    let square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 0 1 2\nf 0 2 3";
    let good = format!(
        "{square}\nr 0.5 0.5 2 0 0 -1 1 2 0 1\nr -1 0.25 0 2 0 0 1 0.5 1\nr 0.5 0.5 2 0 0 1 0\n\
         s 0.5 0.5 1 0.5 0.5 -1 1\ns 0.5 0.5 1 0.5 0.5 0.5 0"
    );
    for check in [crate_ray_mesh as FileChecker, oracle_ray_mesh] {
        assert_eq!(
            outcomes(check, &good),
            [6, 7, 8, 9, 10].map(|i| (i, Some(true)))
        );
        // Wrong answers: another t, a triangle not containing the point, a
        // hit called a miss, a blocked segment called free.
        for (wrong, line) in [
            ("r 0.5 0.5 2 0 0 -1 1 2.5 0 1", 6),
            ("r -1 0.25 0 2 0 0 1 0.5 0", 6),
            ("r 0.5 0.5 2 0 0 -1 0", 6),
            ("s 0.5 0.5 1 0.5 0.5 -1 0", 6),
        ] {
            let text = format!("{square}\n{wrong}");
            assert_eq!(outcomes(check, &text), [(line, Some(false))], "{wrong}");
        }
        for (bad, line) in [
            ("v 0 0\nf 0 0 0", 0),                         // too few fields
            ("v 0 0 0 1", 0),                              // too many
            ("v 0 0 x", 0),                                // bad number
            ("v 0 0 inf", 0),                              // non-finite
            ("v 0 0 0\nf 0 0 1", 1),                       // vertex index out of range
            ("v 0 0 0\nf 0 0 -1", 1),                      // negative index
            ("v 0 0 0\nf 0 0 +0", 1),                      // signed index
            ("v 0 0 0\nf 0 0 4294967296", 1),              // beyond u32
            ("v 0 0 0\nf 0 0 0\nr 0 0 1 0 0 -1 1 0 1", 2), // triangle out of range
            ("v 0 0 0\nf 0 0 0\nr 0 0 1 0 0 -1 1 0", 2),   // no triangle
            ("v 0 0 0\nf 0 0 0\nr 0 0 1 0 0 -1 2 1 0", 2), // bad hit
            ("v 0 0 0\nf 0 0 0\nr 0 0 1 0 0 -1 0 1", 2),   // a miss with a t
            ("v 0 0 0\nr 0 0 1 0 0 0 0", 1),               // zero direction
            ("v 0 0 0\ns 0 0 1 0 0 0 2", 1),               // bad blocked
            ("v 0 0 0\ns 0 0 1 0 0 0", 1),                 // too few
            ("v 0 0 0\nq 0 0 1", 1),                       // unknown line
        ] {
            assert_eq!(outcomes(check, bad), [(line, None)], "{bad:?}");
        }
        // Degenerate triangles (a repeated vertex, collinear vertices) are
        // never hit, and no query panics on them.
        let degenerate = "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 0 1 2\nf 0 0 1\n\
                          r 1 1 2 0 0 -1 0\ns -1 -1 -1 3 3 3 0";
        assert_eq!(
            outcomes(check, degenerate),
            [(5, Some(true)), (6, Some(true))]
        );
    }
}

/// Scaled copies scale exactly the configuration's numbers, keep the
/// answers, and leave out a line (or a whole file, for its set) with a
/// number that would leave the normal range.
#[test]
fn scaled_copies_scale_the_configuration_only() {
    let line = |text: &str| Line {
        at: "x:1".to_string(),
        section: String::new(),
        fields: text.split(' ').map(String::from).collect(),
    };
    let kind = |name: &str| KINDS.iter().find(|k| k.name == name).unwrap();
    let scaled =
        |name: &str, text: &str, k: i32| line(text).scaled(kind(name).scaling, k).map(|l| l.text());
    // A sphere's ray: every number but the count and the roots.
    assert_eq!(
        scaled("ray_sphere", "0 0 -3 0 0 1 0 0 0 1 2 2 4", 2).as_deref(),
        Some("0e0 0e0 -1.2e1 0e0 0e0 4e0 0e0 0e0 0e0 4e0 2 2 4")
    );
    // A quadric: o and d by 2^k, A..F by 2^-2k, G..I by 2^-k, J kept.
    assert_eq!(
        scaled("ray_quadric", "1 2 3 4 5 6 1 1 1 1 1 1 1 1 1 1 0", 1).as_deref(),
        Some(
            "2e0 4e0 6e0 8e0 1e1 1.2e1 2.5e-1 2.5e-1 2.5e-1 2.5e-1 2.5e-1 2.5e-1 5e-1 5e-1 5e-1 1 0"
        )
    );
    // Mesh lines: vertices and query coordinates; faces, flags, t and
    // triangle indices kept.
    assert_eq!(
        scaled("ray_mesh", "v 1 0 -1", 3).as_deref(),
        Some("v 8e0 0e0 -8e0")
    );
    assert_eq!(scaled("ray_mesh", "f 0 1 2", 3).as_deref(), Some("f 0 1 2"));
    assert_eq!(
        scaled("ray_mesh", "r 0 0 1 0 0 -1 1 1 0 3", 1).as_deref(),
        Some("r 0e0 0e0 2e0 0e0 0e0 -2e0 1 1 0 3")
    );
    // Out of the normal range: left out.
    assert_eq!(scaled("orient2d", "1e300 0 0 1 1 0 1", 100), None);
    assert_eq!(scaled("orient2d", "1e-300 0 0 1 1 0 1", -100), None);
    // 2^-22 less one ulp times 2^-1000 rounds up to 2^-1022, a normal
    // number that is not the scaled value: left out; 2^-22 itself scales.
    let below = 2f64.powi(-22).next_down();
    assert_eq!(below, 2.3841857910156247e-07);
    assert_eq!(below * 2f64.powi(-500) * 2f64.powi(-500), f64::MIN_POSITIVE);
    assert_eq!(scale_exactly(below, -1000), None);
    assert_eq!(
        scale_exactly(2f64.powi(-22), -1000),
        Some(f64::MIN_POSITIVE)
    );
    assert_eq!(
        scaled("orient2d", "2.3841857910156247e-07 0 0 1 1 0 1", -1000),
        None
    );
    let mesh = [
        "v 1e300 0 0",
        "v 0 1 0",
        "v 0 0 1",
        "f 0 1 2",
        "r 0 0 0 1 1 1 0",
        "s 0 0 0 1 1 1 0",
    ];
    let lines: Vec<Line> = mesh.iter().map(|t| line(t)).collect();
    let (copy, left_out) = scaled_copy(kind("ray_mesh"), &lines, 100);
    assert!(copy.is_empty());
    assert_eq!(left_out, 2);
    let (copy, left_out) = scaled_copy(kind("ray_mesh"), &lines, -100);
    assert_eq!((copy.len(), left_out), (6, 0));
}

/// The fan's orientation: a neighbour running the shared edge the other
/// way keeps its side, one running it the same way has it flipped; a
/// triangle joined by no shared edge leaves the fan without one.
#[test]
fn fans_are_taken_in_one_orientation() {
    let triangles = [[0, 1, 2], [0, 2, 3], [2, 0, 4], [5, 6, 7], [3, 0, 4]];
    assert_eq!(
        oriented_alike(&triangles, &[0, 1], &[true, true]),
        Some(vec![true, true])
    );
    assert_eq!(
        oriented_alike(&triangles, &[0, 2], &[true, false]),
        Some(vec![true, true])
    );
    // Around vertex 0: the third joined to the fan through the second only.
    assert_eq!(
        oriented_alike(&triangles, &[0, 1, 4], &[true, true, false]),
        Some(vec![true, true, true])
    );
    assert_eq!(oriented_alike(&triangles, &[0, 3], &[true, true]), None);
}
