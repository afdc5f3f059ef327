//! What the ray-cast families share: a case is a shape and a ray, the
//! answer is the first hit's `t >= 0` (or none), checked against the exact
//! answer (`line_oracle.rs`: exact root count, correctly rounded roots).
//! Errors are wrong hits or misses; `max_ulps` is the largest distance of a
//! hit's `t` from the correctly rounded `t`, over the cases both call hits.

use crate::framework::{Config, Measure, Row, median, method, note, time_methods};
use exactray::roots::BoundedRoot;
use exactray::testing::SplitMix64;
use exactray_oracle::line_oracle::Quadratic;
use exactray_oracle::line_oracle::ulps_between;
use glam::DVec3;
use std::fmt::Write;
use std::hint::black_box;
use std::time::{Duration, Instant};

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

/// A method's answer: the first hit's `t` and, for a method that
/// certifies one, the bound on its error.
#[derive(Clone, Copy, Debug)]
pub struct Answer {
    pub t: f64,
    pub bound: Option<f64>,
}

/// A peer's or a textbook method: its `t`, with no bound.
pub fn unbounded<C: 'static, F: Fn(&C) -> Option<f64> + 'static>(
    name: &'static str,
    f: F,
) -> Box<dyn Measure<C, Option<Answer>>> {
    method(name, move |c: &C| f(c).map(|t| Answer { t, bound: None }))
}

/// An exactray method that returns its `t` with a certified bound: the
/// answers carry the bound, which the family checks; the timed loop keeps
/// `t` alone, as every other method returns (a wider value through
/// `black_box` cost every method about 2 ns a case, the ray–triangle
/// family measured). The bound is computed all the same: a cast decides
/// its hit on it.
pub fn bounded<C: 'static, F: Fn(&C) -> Option<BoundedRoot> + 'static>(
    name: &'static str,
    f: F,
) -> Box<dyn Measure<C, Option<Answer>>> {
    Box::new(Bounded { name, f })
}

/// See [`bounded`].
struct Bounded<F> {
    name: &'static str,
    f: F,
}

impl<C, F: Fn(&C) -> Option<BoundedRoot>> Measure<C, Option<Answer>> for Bounded<F> {
    fn name(&self) -> &'static str {
        self.name
    }

    fn answer(&self, case: &C) -> Option<Answer> {
        (self.f)(case).map(|b| Answer {
            t: b.t,
            bound: Some(b.error),
        })
    }

    fn run_loop(&self, cases: &[C], iters: u64) -> Duration {
        let start = Instant::now();
        for _ in 0..iters {
            for case in cases {
                black_box((self.f)(black_box(case)).map(|b| b.t));
            }
        }
        start.elapsed()
    }
}

/// The spacing of the doubles at `|t|` (the ulp of `t`).
fn ulp(t: f64) -> f64 {
    let a = t.abs();
    f64::from_bits(a.to_bits() + 1) - a
}

/// A ray-cast family: its input classes, exact answer and methods.
pub struct RayFamily<C> {
    pub name: &'static str,
    /// Input classes: a name and a case generator.
    pub inputs: Vec<(&'static str, Generate<C>)>,
    /// The exact first hit `t >= 0`, rounded correctly, or `None`.
    pub oracle: fn(&C) -> Option<f64>,
    /// Whether the exact first hit (`first`, the oracle's rounding of it)
    /// lies in `[t - error, t + error]`, decided exactly: the check of a
    /// value that comes with a bound (`docs/report.md`).
    pub within: fn(case: &C, first: f64, t: f64, error: f64) -> bool,
    pub methods: Vec<Box<dyn Measure<C, Option<Answer>>>>,
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
            "{}: wrong hits or misses, exact roots outside a returned bound, the error of `t` in ulps \
             against the correctly rounded exact parameter and the size of the returned bound in ulps of \
             `t` (median / max over cases both call hits), {n} cases per input class.\n\n\
             | inputs | method | wrong | outside bound | median ulps | max ulps | median bound ulps | max bound ulps |\n\
             |---|---|---|---|---|---|---|---|\n",
            self.name
        );
        for (inputs, generate) in &self.inputs {
            let mut rng = cfg.rng(self.name, inputs);
            let cases: Vec<C> = (0..n).map(|_| generate(&mut rng)).collect();
            let truth: Vec<Option<f64>> = cases.iter().map(self.oracle).collect();
            let methods: Vec<&Box<dyn Measure<C, Option<Answer>>>> = self
                .methods
                .iter()
                .filter(|m| !(self.skip)(m.name(), inputs))
                .collect();
            let working = &cases[..cfg.working_set.min(cases.len())];
            let times = time_methods(cfg, working, &methods);
            for (m, ns) in methods.iter().zip(times) {
                let (mut wrong, mut outside) = (0u64, 0u64);
                let (mut ulps, mut bounds) = (Vec::new(), Vec::new());
                for (c, want) in cases.iter().zip(&truth) {
                    match (m.answer(c), want) {
                        (Some(got), Some(want)) => {
                            ulps.push(ulps_between(got.t, *want) as f64);
                            if let Some(error) = got.bound {
                                bounds.push(error / ulp(got.t));
                                if !(self.within)(c, *want, got.t, error) {
                                    outside += 1;
                                }
                            }
                        }
                        (None, None) => {}
                        _ => wrong += 1,
                    }
                }
                let stats = |v: &Vec<f64>| {
                    let max = v.iter().copied().fold(0.0, f64::max);
                    let med = if v.is_empty() { 0.0 } else { median(v.clone()) };
                    (med, max)
                };
                let (med, max) = stats(&ulps);
                let (bmed, bmax) = stats(&bounds);
                let _ = writeln!(
                    table,
                    "| {inputs} | {} | {wrong} | {} | {med} | {} | {} | {} |",
                    m.name(),
                    if bounds.is_empty() {
                        "-".to_string()
                    } else {
                        outside.to_string()
                    },
                    compact(max),
                    if bounds.is_empty() {
                        "-".to_string()
                    } else {
                        compact(bmed)
                    },
                    if bounds.is_empty() {
                        "-".to_string()
                    } else {
                        compact(bmax)
                    },
                );
                rows.push(Row {
                    family: self.name,
                    method: m.name().to_string(),
                    inputs: inputs.to_string(),
                    ns_per_op: ns,
                    cases: n as u64,
                    // A root outside its certified bound is as wrong as a
                    // wrong hit (`docs/report.md`, "Values that come with a bound").
                    errors: wrong + outside,
                    max_ulps: (!ulps.is_empty()).then_some(max),
                    max_bound_ulps: (!bounds.is_empty()).then_some(bmax),
                });
            }
        }
        note(self.name, table);
        rows
    }
}

/// A count of ulps for the notes: whole below a million, else in
/// scientific notation.
fn compact(v: f64) -> String {
    if v >= 1e6 {
        format!("{v:.2e}")
    } else {
        format!("{}", v.round())
    }
}

/// Whether the exact root of `q` that rounds to `first` lies in `[t -
/// error, t + error]` (decided exactly by the oracle); for a polynomial
/// that vanishes everywhere, whether the exact `0` the casts return there
/// does.
pub fn quadratic_within(q: &Quadratic, first: f64, t: f64, error: f64) -> bool {
    if q.count().is_none() {
        return first == 0.0 && t.abs() <= error;
    }
    let roots = q.answer().roots;
    roots
        .iter()
        .position(|&r| r == first)
        .is_some_and(|i| q.root_within(i, t, error))
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

/// The stable textbook roots of `a t^2 + b t + c` (the discriminant
/// `b^2 - 4ac` in `f64`, then `q = -(b + sign(b) sqrt) / 2` and the roots
/// `q / a` and `c / q`, Vieta's form: no cancellation in `q`), first one
/// `>= 0`: the `naive-stable` method of the cone and the general quadric.
#[inline(always)]
pub fn stable_first(a: f64, b: f64, c: f64) -> Option<f64> {
    if a == 0.0 {
        let t = -c / b;
        return (t >= 0.0).then_some(t);
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    let (t0, t1) = (q / a, c / q);
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    [t0, t1].into_iter().find(|&t| t >= 0.0)
}

/// Ray Tracing Gems ch. 7 (Haines, Günther, Akenine-Möller, "Precision
/// Improvements for Ray/Sphere Intersection"), for unnormalized `d`: the
/// first root `>= 0` of `|f + t d|^2 = r^2`, the discriminant from the
/// closest point to the centre, the second root by Vieta. The sphere's
/// `naive-stable` method, and the cylinder's on the projected problem.
#[inline(always)]
pub fn stable_circle_first(f: DVec3, d: DVec3, r: f64) -> Option<f64> {
    let a = d.dot(d);
    let b = -f.dot(d);
    let l = f + d * (b / a);
    let disc = a * (r * r - l.dot(l));
    if disc < 0.0 {
        return None;
    }
    let q = b + disc.sqrt().copysign(b);
    let (t0, t1) = ((f.dot(f) - r * r) / q, q / a);
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    [t0, t1].into_iter().find(|&t| t >= 0.0)
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
