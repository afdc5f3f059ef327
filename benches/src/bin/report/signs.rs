//! Families whose answer is a sign: every method is checked case by case
//! against the exact oracle.

use crate::export::{Coords, write_class};
use crate::framework::{Config, Measure, Row, time_methods};
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
    pub fn run(&self, cfg: &Config) -> Vec<Row> {
        let mut rows = Vec::new();
        for class in InputClass::ALL {
            let cases = self.cases(cfg, class);
            let truth: Vec<i8> = cases.iter().map(self.oracle).collect();
            let timed = &cases[..cfg.working_set.min(cases.len())];
            let times = time_methods(cfg, timed, &self.methods);
            for (m, ns_per_op) in self.methods.iter().zip(times) {
                let answers: Vec<i8> = cases.iter().map(|c| m.answer(c)).collect();
                if let Some(dir) = &cfg.export
                    && m.name() == "exactray"
                {
                    write_class(dir, self.name, class.name(), &cases, &answers)
                        .unwrap_or_else(|e| panic!("--export-inputs {}: {e}", dir.display()));
                }
                let errors = answers.iter().zip(&truth).filter(|(a, t)| a != t).count();
                rows.push(Row {
                    family: self.name,
                    method: m.name().to_string(),
                    inputs: class.name().to_string(),
                    ns_per_op,
                    cases: cases.len() as u64,
                    errors: errors as u64,
                    max_ulps: None,
                    max_bound_ulps: None,
                });
            }
        }
        rows
    }
}
