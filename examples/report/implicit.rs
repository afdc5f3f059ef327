//! implicit: predicates on constructed points (line–plane, three-plane and
//! line–line intersections), `../shared/REPORT.md`'s `implicit` family.
//!
//! Inputs `<predicate>:<class>`: `orient3d_lpi` (a triangle and a
//! line–plane point), `orient3d_tpi` (a triangle and a three-plane point),
//! `orient2d_ssi` (two points and a line–line point), `less_on_axis_lpi`
//! (two line–plane points along an axis), each on the classes of
//! `exactray::testing` (`orient3d_lpi_case`, ...).
//!
//! Methods: `exactray` (the constructed point kept as its inputs:
//! `orient3d_implicit`, `orient2d_implicit`, `cmp_on_axis`) and
//! `round-then-exact` (what code does without them: the point constructed
//! in `f64` by the textbook formula, then the exact predicate on explicit
//! points, or for the axis comparison the rounded coordinates compared).
//! Both build their point before the timed loop, as a caller that asks
//! many questions of one point would. On the `uniform` inputs a third row,
//! `explicit-orient3d` (`explicit-orient2d` for `orient2d_ssi`), times
//! exactray's predicate on as many explicit uniform cases in the same run,
//! so that the cost of a constructed point shows as a ratio.
//!
//! Errors: answers that differ from the exact one
//! (`exactray_oracle::implicit_oracle`: rational points). A quarter of the
//! run's cases per class (the oracle's rational points are slow).
//!
//! A self-contained module: its cases, methods and oracle calls are all
//! here.

use crate::framework::{Config, Measure, Row, method, note, time_methods};
use exactray::predicates::{
    Axis, Lpi, Ssi, Tpi, cmp_on_axis, orient2d, orient2d_implicit, orient3d, orient3d_implicit,
};
use exactray::testing::{
    InputClass, less_on_axis_lpi_case, orient2d_case, orient2d_ssi_case, orient3d_case,
    orient3d_lpi_case, orient3d_tpi_case,
};
use exactray_oracle::implicit_oracle::{self as oracle, Pt2, Pt3};
use glam::{DVec2, DVec3};

const FAMILY: &str = "implicit";

/// The line–plane point in `f64`: `p + t (q - p)`, `t = n . (r - p) / n .
/// (q - p)`.
fn round_lpi([p, q, r, s, t]: [DVec3; 5]) -> DVec3 {
    let n = (s - r).cross(t - r);
    let e = q - p;
    p + e * (n.dot(r - p) / n.dot(e))
}

/// The three-plane point in `f64`: `(d_u (n_v x n_w) + d_v (n_w x n_u) +
/// d_w (n_u x n_v)) / det[n_u, n_v, n_w]`, `d_i = n_i . i0`.
fn round_tpi(planes: [[DVec3; 3]; 3]) -> DVec3 {
    let n = planes.map(|[a, b, c]| (b - a).cross(c - a));
    let d: [f64; 3] = core::array::from_fn(|i| n[i].dot(planes[i][0]));
    let c = [n[1].cross(n[2]), n[2].cross(n[0]), n[0].cross(n[1])];
    (c[0] * d[0] + c[1] * d[1] + c[2] * d[2]) / n[0].dot(c[0])
}

/// The line–line point in `f64`: `p + t (q - p)`, `t = (r - p) x (s - r) /
/// (q - p) x (s - r)`.
fn round_ssi([p, q, r, s]: [DVec2; 4]) -> DVec2 {
    let (e, f) = (q - p, s - r);
    p + e * ((r - p).perp_dot(f) / e.perp_dot(f))
}

fn a3(v: DVec3) -> [f64; 3] {
    v.to_array()
}

/// One case of each predicate: the inputs, the constructed points and the
/// rounded ones.
struct Lpi3 {
    abc: [DVec3; 3],
    x: Lpi,
    rounded: DVec3,
    truth: i8,
}

struct Tpi3 {
    abc: [DVec3; 3],
    x: Tpi,
    rounded: DVec3,
    truth: i8,
}

struct Ssi2 {
    ab: [DVec2; 2],
    x: Ssi,
    rounded: DVec2,
    truth: i8,
}

struct Axis2Lpi {
    x: Lpi,
    y: Lpi,
    rounded: [DVec3; 2],
    axis: usize,
    truth: i8,
}

const AXES: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

fn lpi_cases(cfg: &Config, class: InputClass, n: usize) -> Vec<Lpi3> {
    let mut rng = cfg.rng("implicit/orient3d_lpi", class.name());
    (0..n)
        .map(|_| {
            let c = orient3d_lpi_case(class, &mut rng);
            let l = [c[3], c[4], c[5], c[6], c[7]];
            let truth = oracle::orient3d([
                Pt3::E(a3(c[0])),
                Pt3::E(a3(c[1])),
                Pt3::E(a3(c[2])),
                Pt3::Lpi(l.map(a3)),
            ]);
            Lpi3 {
                abc: [c[0], c[1], c[2]],
                x: Lpi::new(l[0], l[1], l[2], l[3], l[4]).expect("valid construction"),
                rounded: round_lpi(l),
                truth: truth.expect("valid construction"),
            }
        })
        .collect()
}

fn tpi_cases(cfg: &Config, class: InputClass, n: usize) -> Vec<Tpi3> {
    let mut rng = cfg.rng("implicit/orient3d_tpi", class.name());
    (0..n)
        .map(|_| {
            let c = orient3d_tpi_case(class, &mut rng);
            let planes = [[c[3], c[4], c[5]], [c[6], c[7], c[8]], [c[9], c[10], c[11]]];
            let truth = oracle::orient3d([
                Pt3::E(a3(c[0])),
                Pt3::E(a3(c[1])),
                Pt3::E(a3(c[2])),
                Pt3::Tpi(planes.map(|p| p.map(a3))),
            ]);
            Tpi3 {
                abc: [c[0], c[1], c[2]],
                x: Tpi::new(planes[0], planes[1], planes[2]).expect("valid construction"),
                rounded: round_tpi(planes),
                truth: truth.expect("valid construction"),
            }
        })
        .collect()
}

fn ssi_cases(cfg: &Config, class: InputClass, n: usize) -> Vec<Ssi2> {
    let mut rng = cfg.rng("implicit/orient2d_ssi", class.name());
    (0..n)
        .map(|_| {
            let c = orient2d_ssi_case(class, &mut rng);
            let l = [c[2], c[3], c[4], c[5]];
            let truth = oracle::orient2d([
                Pt2::E(c[0].to_array()),
                Pt2::E(c[1].to_array()),
                Pt2::Ssi(l.map(|v| v.to_array())),
            ]);
            Ssi2 {
                ab: [c[0], c[1]],
                x: Ssi::new(l[0], l[1], l[2], l[3]).expect("valid construction"),
                rounded: round_ssi(l),
                truth: truth.expect("valid construction"),
            }
        })
        .collect()
}

fn axis_cases(cfg: &Config, class: InputClass, n: usize) -> Vec<Axis2Lpi> {
    let mut rng = cfg.rng("implicit/less_on_axis_lpi", class.name());
    (0..n)
        .map(|_| {
            let (c, axis) = less_on_axis_lpi_case(class, &mut rng);
            let (l, m) = (
                [c[0], c[1], c[2], c[3], c[4]],
                [c[5], c[6], c[7], c[8], c[9]],
            );
            let truth = oracle::cmp_on_axis3(Pt3::Lpi(l.map(a3)), Pt3::Lpi(m.map(a3)), axis);
            let lpi = |v: [DVec3; 5]| Lpi::new(v[0], v[1], v[2], v[3], v[4]).expect("valid");
            Axis2Lpi {
                x: lpi(l),
                y: lpi(m),
                rounded: [round_lpi(l), round_lpi(m)],
                axis,
                truth: truth.expect("valid construction") as i8,
            }
        })
        .collect()
}

/// The rounded coordinates compared (`NaN`, where a construction
/// overflowed, compares as equal: the answer such code would get).
fn cmp_rounded(x: f64, y: f64) -> i8 {
    x.partial_cmp(&y).map_or(0, |o| o as i8)
}

/// One row per method on `cases`.
fn rows_of<C>(
    cfg: &Config,
    inputs: String,
    cases: &[C],
    truth: impl Fn(&C) -> i8,
    methods: &[Box<dyn Measure<C, i8>>],
) -> Vec<Row> {
    let timed = &cases[..cfg.working_set.min(cases.len())];
    let times = time_methods(cfg, timed, methods);
    methods
        .iter()
        .zip(times)
        .map(|(m, ns_per_op)| Row {
            family: FAMILY,
            method: m.name().to_string(),
            inputs: inputs.clone(),
            ns_per_op,
            cases: cases.len() as u64,
            errors: cases.iter().filter(|c| m.answer(c) != truth(c)).count() as u64,
            max_ulps: None,
            max_bound_ulps: None,
        })
        .collect()
}

/// The explicit predicate's time on as many uniform cases, in the same
/// run: `(orient3d, orient2d)`, each as a row under `inputs`.
fn explicit_rows(cfg: &Config, n: usize) -> (Row, Row) {
    let mut rng = cfg.rng("implicit/explicit", "uniform");
    let c3: Vec<[DVec3; 4]> = (0..n)
        .map(|_| orient3d_case(InputClass::Uniform, &mut rng))
        .collect();
    let c2: Vec<[DVec2; 3]> = (0..n)
        .map(|_| orient2d_case(InputClass::Uniform, &mut rng))
        .collect();
    let m3 = [method("explicit-orient3d", |c: &[DVec3; 4]| {
        orient3d(c[0], c[1], c[2], c[3]).as_i8()
    })];
    let m2 = [method("explicit-orient2d", |c: &[DVec2; 3]| {
        orient2d(c[0], c[1], c[2]).as_i8()
    })];
    let e3 =
        |c: &[DVec3; 4]| exactray_oracle::oracle::orient3d(a3(c[0]), a3(c[1]), a3(c[2]), a3(c[3]));
    let e2 = |c: &[DVec2; 3]| {
        exactray_oracle::oracle::orient2d(c[0].to_array(), c[1].to_array(), c[2].to_array())
    };
    let r3 = rows_of(cfg, String::new(), &c3, e3, &m3).remove(0);
    let r2 = rows_of(cfg, String::new(), &c2, e2, &m2).remove(0);
    (r3, r2)
}

pub fn run(cfg: &Config) -> Vec<Row> {
    let n = cfg.cases / 4;
    let mut rows = Vec::new();
    let (explicit3, explicit2) = explicit_rows(cfg, n);
    let with_explicit = |mut r: Vec<Row>, class: InputClass, e: &Row| {
        if class == InputClass::Uniform {
            r.push(Row {
                inputs: r[0].inputs.clone(),
                ..e.clone()
            });
        }
        r
    };
    for class in InputClass::ALL {
        let name = |pred: &str| format!("{pred}:{}", class.name());
        let cases = lpi_cases(cfg, class, n);
        let methods = [
            method("exactray", |c: &Lpi3| {
                orient3d_implicit(c.abc[0], c.abc[1], c.abc[2], &c.x).as_i8()
            }),
            method("round-then-exact", |c: &Lpi3| {
                orient3d(c.abc[0], c.abc[1], c.abc[2], c.rounded).as_i8()
            }),
        ];
        let r = rows_of(cfg, name("orient3d_lpi"), &cases, |c| c.truth, &methods);
        rows.extend(with_explicit(r, class, &explicit3));

        let cases = tpi_cases(cfg, class, n);
        let methods = [
            method("exactray", |c: &Tpi3| {
                orient3d_implicit(c.abc[0], c.abc[1], c.abc[2], &c.x).as_i8()
            }),
            method("round-then-exact", |c: &Tpi3| {
                orient3d(c.abc[0], c.abc[1], c.abc[2], c.rounded).as_i8()
            }),
        ];
        let r = rows_of(cfg, name("orient3d_tpi"), &cases, |c| c.truth, &methods);
        rows.extend(with_explicit(r, class, &explicit3));

        let cases = ssi_cases(cfg, class, n);
        let methods = [
            method("exactray", |c: &Ssi2| {
                orient2d_implicit(c.ab[0], c.ab[1], &c.x).as_i8()
            }),
            method("round-then-exact", |c: &Ssi2| {
                orient2d(c.ab[0], c.ab[1], c.rounded).as_i8()
            }),
        ];
        let r = rows_of(cfg, name("orient2d_ssi"), &cases, |c| c.truth, &methods);
        rows.extend(with_explicit(r, class, &explicit2));

        let cases = axis_cases(cfg, class, n);
        let methods = [
            method("exactray", |c: &Axis2Lpi| {
                cmp_on_axis(&c.x, &c.y, AXES[c.axis]) as i8
            }),
            method("round-then-exact", |c: &Axis2Lpi| {
                cmp_rounded(c.rounded[0][c.axis], c.rounded[1][c.axis])
            }),
        ];
        let r = rows_of(cfg, name("less_on_axis_lpi"), &cases, |c| c.truth, &methods);
        rows.extend(with_explicit(r, class, &explicit3));
    }
    note(
        FAMILY,
        format!(
            "implicit: {n} cases per class (a quarter of the run's); each method builds its point \
             before the timed loop. `explicit-orient3d` / `explicit-orient2d` on the uniform rows: \
             exactray's predicate on {n} explicit uniform cases in the same run ({:.2} / {:.2} ns).",
            explicit3.ns_per_op, explicit2.ns_per_op
        ),
    );
    rows
}
