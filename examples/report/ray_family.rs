//! What the ray-cast families share: a case is a shape and a ray, the
//! answer is the first hit's `t >= 0` (or none), checked against the exact
//! answer (`line_oracle.rs`: exact root count, correctly rounded roots).
//! Errors are wrong hits or misses; `max_ulps` is the largest distance of a
//! hit's `t` from the correctly rounded `t`, over the cases both call hits.

use crate::framework::{Config, Measure, Row, median, note, time_methods};
use exactray::testing::SplitMix64;
use exactray_oracle::line_oracle::ulps_between;
use std::fmt::Write;

/// Draws one case of an input class.
pub type Generate<C> = Box<dyn Fn(&mut SplitMix64) -> C>;

/// A family's input classes (`exactray::testing::SphereRayClass::ALL`, ...):
/// each class's name, and its cases drawn from `exactray::testing` by
/// `draw` and built into the family's case type by `build`.
pub fn inputs<K: Copy + 'static, R: 'static, C: 'static>(
    classes: &[K],
    name: fn(K) -> &'static str,
    draw: fn(K, &mut SplitMix64) -> R,
    build: fn(R) -> C,
) -> Vec<(&'static str, Generate<C>)> {
    classes
        .iter()
        .map(|&class| -> (&'static str, Generate<C>) {
            (name(class), Box::new(move |rng| build(draw(class, rng))))
        })
        .collect()
}

/// A ray-cast family: its input classes, exact answer and methods.
pub struct RayFamily<C> {
    pub name: &'static str,
    /// Input classes: a name and a case generator.
    pub inputs: Vec<(&'static str, Generate<C>)>,
    /// The exact first hit `t >= 0`, rounded correctly, or `None`.
    pub oracle: fn(&C) -> Option<f64>,
    pub methods: Vec<Box<dyn Measure<C, Option<f64>>>>,
    /// Methods that do not run on an input class (a peer without the shape).
    pub skip: fn(&str, &str) -> bool,
}

impl<C> RayFamily<C> {
    pub fn run(&self, cfg: &Config) -> Vec<Row> {
        // The exact answers cost microseconds each (big-integer bisection),
        // so fewer cases are checked than for the sign families.
        let n = if cfg.quick { 4_000 } else { 20_000 };
        let mut rows = Vec::new();
        let mut table = format!(
            "{}: wrong hits or misses, and the error of `t` in ulps against the correctly rounded exact \
             parameter (median / max over cases both call hits), {n} cases per input class.\n\n\
             | inputs | method | wrong | median ulps | max ulps |\n|---|---|---|---|---|\n",
            self.name
        );
        for (inputs, generate) in &self.inputs {
            let mut rng = cfg.rng(self.name, inputs);
            let cases: Vec<C> = (0..n).map(|_| generate(&mut rng)).collect();
            let truth: Vec<Option<f64>> = cases.iter().map(self.oracle).collect();
            let methods: Vec<&Box<dyn Measure<C, Option<f64>>>> = self
                .methods
                .iter()
                .filter(|m| !(self.skip)(m.name(), inputs))
                .collect();
            let working = &cases[..cfg.working_set.min(cases.len())];
            let times = time_methods(cfg, working, &methods);
            for (m, ns) in methods.iter().zip(times) {
                let mut wrong = 0u64;
                let mut ulps = Vec::new();
                for (c, want) in cases.iter().zip(&truth) {
                    match (m.answer(c), want) {
                        (Some(got), Some(want)) => ulps.push(ulps_between(got, *want) as f64),
                        (None, None) => {}
                        _ => wrong += 1,
                    }
                }
                let max = ulps.iter().copied().fold(0.0, f64::max);
                let med = if ulps.is_empty() {
                    0.0
                } else {
                    median(ulps.clone())
                };
                let _ = writeln!(
                    table,
                    "| {inputs} | {} | {wrong} | {med} | {} |",
                    m.name(),
                    if max >= 1e6 {
                        format!("{max:.2e}")
                    } else {
                        format!("{max}")
                    }
                );
                rows.push(Row {
                    family: self.name,
                    method: m.name().to_string(),
                    inputs: inputs.to_string(),
                    ns_per_op: ns,
                    cases: n as u64,
                    errors: wrong,
                    max_ulps: (!ulps.is_empty()).then_some(max),
                });
            }
        }
        note(self.name, table);
        rows
    }
}

/// The first root `>= 0` of sorted roots.
pub fn first_forward(roots: &[f64]) -> Option<f64> {
    roots.iter().copied().find(|&t| t >= 0.0)
}

/// The textbook roots of `a t^2 + b t + c` (`b^2 - 4ac`, `(-b +- sqrt) / 2a`),
/// first one `>= 0`: the `naive` method of every quadric family.
#[inline(always)]
pub fn naive_first(a: f64, b: f64, c: f64) -> Option<f64> {
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let s = disc.sqrt();
    let (t0, t1) = ((-b - s) / (2.0 * a), (-b + s) / (2.0 * a));
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    if t0 >= 0.0 {
        Some(t0)
    } else if t1 >= 0.0 {
        Some(t1)
    } else {
        None
    }
}

/// parry3d's cast of a ray `o + t d` on `shape` placed at `at` (its usual
/// call: the shape posed in the world, non-solid, no distance limit).
#[inline(always)]
pub fn parry_cast(
    shape: &impl parry3d_f64::query::RayCast,
    at: glam::DVec3,
    o: glam::DVec3,
    d: glam::DVec3,
) -> Option<f64> {
    use parry3d_f64::math::{Pose, Vector};
    let v = |p: glam::DVec3| Vector::new(p.x, p.y, p.z);
    let pose = Pose::from_translation(v(at));
    shape.cast_ray(
        &pose,
        &parry3d_f64::query::Ray::new(v(o), v(d)),
        f64::MAX,
        false,
    )
}
