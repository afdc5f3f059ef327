//! implicit: predicates on constructed points (line–plane, three-plane and
//! line–line intersections), `docs/report.md`'s `implicit` family.
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
//! `explicit-orient3d` (and for `orient2d_ssi` also `explicit-orient2d`),
//! times exactray's explicit predicate on uniform cases kept beside the
//! constructed ones, in the same timed loops, so that the cost of a
//! constructed point shows as a ratio (its errors count against those
//! cases' own exact answers).
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
    InputClass, SplitMix64, less_on_axis_lpi_case, orient2d_case, orient2d_ssi_case, orient3d_case,
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
/// rounded ones, and beside it an explicit `orient3d` (`orient2d`) case of
/// the uniform class with its answer, which the `explicit-` rows answer in
/// the same timed loops.
struct Lpi3 {
    abc: [DVec3; 3],
    x: Lpi,
    rounded: DVec3,
    truth: i8,
    explicit: Explicit3,
}

struct Tpi3 {
    abc: [DVec3; 3],
    x: Tpi,
    rounded: DVec3,
    truth: i8,
    explicit: Explicit3,
}

struct Ssi2 {
    ab: [DVec2; 2],
    x: Ssi,
    rounded: DVec2,
    truth: i8,
    explicit: Explicit3,
    explicit2: Explicit2,
}

struct Axis2Lpi {
    x: Lpi,
    y: Lpi,
    rounded: [DVec3; 2],
    axis: usize,
    truth: i8,
    explicit: Explicit3,
}

/// A uniform explicit `orient3d` case and its exact answer.
#[derive(Clone, Copy)]
struct Explicit3([DVec3; 4], i8);

/// A uniform explicit `orient2d` case and its exact answer.
#[derive(Clone, Copy)]
struct Explicit2([DVec2; 3], i8);

fn explicit3(rng: &mut SplitMix64) -> Explicit3 {
    let c = orient3d_case(InputClass::Uniform, rng);
    Explicit3(
        c,
        exactray_oracle::oracle::orient3d(a3(c[0]), a3(c[1]), a3(c[2]), a3(c[3])),
    )
}

fn explicit2(rng: &mut SplitMix64) -> Explicit2 {
    let c = orient2d_case(InputClass::Uniform, rng);
    let a = |i: usize| c[i].to_array();
    Explicit2(c, exactray_oracle::oracle::orient2d(a(0), a(1), a(2)))
}

/// A case's answer key: the method under test reads the constructed case,
/// an `explicit-` one the explicit case beside it.
trait Truth {
    fn truth(&self, method: &str) -> i8;
}

macro_rules! truth {
    ($($t:ident),*) => {$(
        impl Truth for $t {
            fn truth(&self, method: &str) -> i8 {
                if method.starts_with("explicit-") { self.explicit.1 } else { self.truth }
            }
        }
    )*};
}
truth!(Lpi3, Tpi3, Axis2Lpi);

impl Truth for Ssi2 {
    fn truth(&self, method: &str) -> i8 {
        match method {
            "explicit-orient3d" => self.explicit.1,
            "explicit-orient2d" => self.explicit2.1,
            _ => self.truth,
        }
    }
}

const AXES: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

fn lpi_cases(cfg: &Config, class: InputClass, n: usize) -> Vec<Lpi3> {
    let mut rng = cfg.rng("implicit/orient3d_lpi", class.name());
    let mut side = cfg.rng("implicit/explicit3", class.name());
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
                explicit: explicit3(&mut side),
            }
        })
        .collect()
}

fn tpi_cases(cfg: &Config, class: InputClass, n: usize) -> Vec<Tpi3> {
    let mut rng = cfg.rng("implicit/orient3d_tpi", class.name());
    let mut side = cfg.rng("implicit/explicit3", class.name());
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
                explicit: explicit3(&mut side),
            }
        })
        .collect()
}

fn ssi_cases(cfg: &Config, class: InputClass, n: usize) -> Vec<Ssi2> {
    let mut rng = cfg.rng("implicit/orient2d_ssi", class.name());
    let mut side = cfg.rng("implicit/explicit2", class.name());
    let mut side3 = cfg.rng("implicit/explicit3", class.name());
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
                explicit: explicit3(&mut side3),
                explicit2: explicit2(&mut side),
            }
        })
        .collect()
}

fn axis_cases(cfg: &Config, class: InputClass, n: usize) -> Vec<Axis2Lpi> {
    let mut rng = cfg.rng("implicit/less_on_axis_lpi", class.name());
    let mut side = cfg.rng("implicit/explicit3", class.name());
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
                explicit: explicit3(&mut side),
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
fn rows_of<C: Truth>(
    cfg: &Config,
    inputs: String,
    cases: &[C],
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
            errors: cases
                .iter()
                .filter(|c| m.answer(c) != c.truth(m.name()))
                .count() as u64,
            max_ulps: None,
            max_bound_ulps: None,
        })
        .collect()
}

/// The explicit predicate beside the constructed one, on `uniform` only.
fn explicit_orient3d<C: 'static>(
    class: InputClass,
    get: fn(&C) -> &Explicit3,
) -> Option<Box<dyn Measure<C, i8>>> {
    (class == InputClass::Uniform).then(|| {
        method("explicit-orient3d", move |c: &C| {
            let Explicit3(p, _) = get(c);
            orient3d(p[0], p[1], p[2], p[3]).as_i8()
        })
    })
}

pub fn run(cfg: &Config) -> Vec<Row> {
    let n = cfg.cases / 4;
    let mut rows = Vec::new();
    for class in InputClass::ALL {
        let name = |pred: &str| format!("{pred}:{}", class.name());
        let cases = lpi_cases(cfg, class, n);
        let methods: Vec<_> = [
            Some(method("exactray", |c: &Lpi3| {
                orient3d_implicit(c.abc[0], c.abc[1], c.abc[2], &c.x).as_i8()
            })),
            Some(method("round-then-exact", |c: &Lpi3| {
                orient3d(c.abc[0], c.abc[1], c.abc[2], c.rounded).as_i8()
            })),
            explicit_orient3d(class, |c: &Lpi3| &c.explicit),
        ]
        .into_iter()
        .flatten()
        .collect();
        rows.extend(rows_of(cfg, name("orient3d_lpi"), &cases, &methods));

        let cases = tpi_cases(cfg, class, n);
        let methods: Vec<_> = [
            Some(method("exactray", |c: &Tpi3| {
                orient3d_implicit(c.abc[0], c.abc[1], c.abc[2], &c.x).as_i8()
            })),
            Some(method("round-then-exact", |c: &Tpi3| {
                orient3d(c.abc[0], c.abc[1], c.abc[2], c.rounded).as_i8()
            })),
            explicit_orient3d(class, |c: &Tpi3| &c.explicit),
        ]
        .into_iter()
        .flatten()
        .collect();
        rows.extend(rows_of(cfg, name("orient3d_tpi"), &cases, &methods));

        let cases = ssi_cases(cfg, class, n);
        let explicit2 = (class == InputClass::Uniform).then(|| {
            method("explicit-orient2d", |c: &Ssi2| {
                let Explicit2(p, _) = c.explicit2;
                orient2d(p[0], p[1], p[2]).as_i8()
            })
        });
        let methods: Vec<_> = [
            Some(method("exactray", |c: &Ssi2| {
                orient2d_implicit(c.ab[0], c.ab[1], &c.x).as_i8()
            })),
            Some(method("round-then-exact", |c: &Ssi2| {
                orient2d(c.ab[0], c.ab[1], c.rounded).as_i8()
            })),
            explicit_orient3d(class, |c: &Ssi2| &c.explicit),
            explicit2,
        ]
        .into_iter()
        .flatten()
        .collect();
        rows.extend(rows_of(cfg, name("orient2d_ssi"), &cases, &methods));

        let cases = axis_cases(cfg, class, n);
        let methods: Vec<_> = [
            Some(method("exactray", |c: &Axis2Lpi| {
                cmp_on_axis(&c.x, &c.y, AXES[c.axis]) as i8
            })),
            Some(method("round-then-exact", |c: &Axis2Lpi| {
                cmp_rounded(c.rounded[0][c.axis], c.rounded[1][c.axis])
            })),
            explicit_orient3d(class, |c: &Axis2Lpi| &c.explicit),
        ]
        .into_iter()
        .flatten()
        .collect();
        rows.extend(rows_of(cfg, name("less_on_axis_lpi"), &cases, &methods));
    }
    note(
        FAMILY,
        format!(
            "implicit: {n} cases per class (a quarter of the run's); each method builds its point \
             before the timed loop. On the uniform rows, `explicit-orient3d` (and for orient2d_ssi \
             `explicit-orient2d`) is exactray's explicit predicate on uniform cases, timed in the \
             same loops as the other methods of the row."
        ),
    );
    rows
}
