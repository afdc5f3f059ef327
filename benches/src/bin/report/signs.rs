//! Families whose answer is a sign: every method is checked case by case
//! against the exact oracle.

use crate::export::{Coords, write_class};
use crate::framework::{Config, Measure, Row, note, time_methods};
use exactray::Sign;
use exactray::testing::{InputClass, SplitMix64};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// A predicate's batch variant (`exactray::predicates::orient2d_many`, ...)
/// as a [`Measure`]: the timed loop answers the whole slice of cases in one
/// call per iteration, as a caller with many cases would.
pub struct Batch<C> {
    name: &'static str,
    f: fn(&[C], &mut [Sign]) -> usize,
}

impl<C: Clone> Measure<C, i8> for Batch<C> {
    fn name(&self) -> &'static str {
        self.name
    }

    fn answer(&self, case: &C) -> i8 {
        let mut out = [Sign::Zero];
        (self.f)(std::slice::from_ref(case), &mut out);
        out[0].as_i8()
    }

    fn run_loop(&self, cases: &[C], iters: u64) -> Duration {
        let mut out = vec![Sign::Zero; cases.len()];
        let start = Instant::now();
        for _ in 0..iters {
            black_box((self.f)(black_box(cases), black_box(&mut out[..])));
        }
        start.elapsed()
    }
}

/// A boxed [`Batch`], for a family's list of methods.
pub fn batch<C: Clone + 'static>(
    name: &'static str,
    f: fn(&[C], &mut [Sign]) -> usize,
) -> Box<dyn Measure<C, i8>> {
    Box::new(Batch { name, f })
}

/// A sign family: how to draw its cases, its exact answer, its methods.
pub struct SignFamily<C> {
    pub name: &'static str,
    pub generate: fn(InputClass, &mut SplitMix64) -> C,
    pub oracle: fn(&C) -> i8,
    pub methods: Vec<Box<dyn Measure<C, i8>>>,
}

impl<C: Coords> SignFamily<C> {
    /// `cfg.cases` cases of one class, always the same ones.
    pub fn cases(&self, cfg: &Config, class: InputClass) -> Vec<C> {
        let mut rng = cfg.rng(self.name, class.name());
        (0..cfg.cases)
            .map(|_| (self.generate)(class, &mut rng))
            .collect()
    }

    /// One row per (inputs, method).
    ///
    /// Every method is checked first, each within `cfg.check_budget` per
    /// class (a peer whose exact stage takes milliseconds a case would
    /// otherwise hold the run for hours): the row's `cases` says how many
    /// it answered. The methods whose timed loops fit `cfg.time_budget` on
    /// the whole working set are timed there together, repetitions
    /// interleaved; a slower one alone on the prefix that fits. Either
    /// shortfall is written under the report's notes.
    pub fn run(&self, cfg: &Config) -> Vec<Row> {
        let mut rows = Vec::new();
        for class in InputClass::ALL {
            let cases = self.cases(cfg, class);
            let truth: Vec<i8> = cases.iter().map(self.oracle).collect();
            let checked: Vec<(Vec<i8>, f64)> = self
                .methods
                .iter()
                .map(|m| check(cfg, m.as_ref(), &cases))
                .collect();
            let working = cfg.working_set.min(cases.len());
            let fits = |seconds_per_case: f64| {
                seconds_per_case * (working * cfg.reps) as f64 <= cfg.time_budget.as_secs_f64()
            };
            let fast: Vec<usize> = (0..self.methods.len())
                .filter(|&i| fits(checked[i].1))
                .collect();
            let mut times = vec![0.0; self.methods.len()];
            let fast_methods: Vec<&Box<dyn Measure<C, i8>>> =
                fast.iter().map(|&i| &self.methods[i]).collect();
            for (&i, t) in fast
                .iter()
                .zip(time_methods(cfg, &cases[..working], &fast_methods))
            {
                times[i] = t;
            }
            for (i, m) in self.methods.iter().enumerate() {
                let (answers, per_case) = &checked[i];
                if !fast.contains(&i) {
                    let fitting = cfg.time_budget.as_secs_f64() / (per_case * cfg.reps as f64);
                    let prefix = (fitting as usize).clamp(16, working);
                    times[i] = time_methods(cfg, &cases[..prefix], &[m])[0];
                    note(
                        self.name,
                        format!(
                            "`{}` on {}/`{}` is timed on the first {prefix} of the {working} cases the \
                             others are timed on (about {:.0} µs a case).",
                            m.name(),
                            self.name,
                            class.name(),
                            per_case * 1e6
                        ),
                    );
                }
                if answers.len() < cases.len() {
                    note(
                        self.name,
                        format!(
                            "`{}` on {}/`{}`: {} of {} cases checked within the {} s budget.",
                            m.name(),
                            self.name,
                            class.name(),
                            answers.len(),
                            cases.len(),
                            cfg.check_budget.as_secs()
                        ),
                    );
                }
                if let Some(dir) = &cfg.export
                    && m.name() == "exactray"
                {
                    write_class(dir, self.name, class.name(), &cases, answers)
                        .unwrap_or_else(|e| panic!("--export-inputs {}: {e}", dir.display()));
                }
                let errors = answers.iter().zip(&truth).filter(|(a, t)| a != t).count();
                rows.push(Row {
                    family: self.name,
                    method: m.name().to_string(),
                    inputs: class.name().to_string(),
                    ns_per_op: times[i],
                    cases: answers.len() as u64,
                    errors: errors as u64,
                    max_ulps: None,
                    max_bound_ulps: None,
                });
            }
        }
        rows
    }
}

/// `m`'s answers to the cases, in order, until `cfg.check_budget` runs out
/// (the clock read every 8 cases), and its mean time per case in seconds.
fn check<C>(cfg: &Config, m: &dyn Measure<C, i8>, cases: &[C]) -> (Vec<i8>, f64) {
    let start = Instant::now();
    let mut answers = Vec::with_capacity(cases.len());
    for block in cases.chunks(8) {
        answers.extend(block.iter().map(|c| m.answer(c)));
        if start.elapsed() > cfg.check_budget {
            break;
        }
    }
    let per_case = start.elapsed().as_secs_f64() / answers.len().max(1) as f64;
    (answers, per_case)
}
