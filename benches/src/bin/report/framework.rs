//! What every family shares: the run configuration, the report row, methods
//! under test and the timing loop.

use exactray::testing::SplitMix64;
use std::hint::black_box;
use std::path::PathBuf;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// How much work a run does.
pub struct Config {
    /// A `--quick` run: families that size their own work scale it down.
    pub quick: bool,
    /// Cases checked against the exact answer per (family, inputs).
    pub cases: usize,
    /// Cases in each timed loop: few enough to stay in cache.
    pub working_set: usize,
    /// Timed repetitions per method; the report keeps their median.
    pub reps: usize,
    /// Shortest timed loop, so that timer resolution does not matter.
    pub min_loop: Duration,
    /// `--export-inputs DIR`: where the sign families write their cases
    /// and exactray's answers (`export.rs`).
    pub export: Option<PathBuf>,
    /// How long checking one method on one class of a sign family may
    /// take; the cases left are not checked (the row's `cases` says so).
    pub check_budget: Duration,
    /// How long one method's timed loops on one class may take in all; a
    /// slower method is timed on a prefix of the working set.
    pub time_budget: Duration,
}

impl Config {
    pub fn new(quick: bool) -> Self {
        if quick {
            Config {
                quick,
                cases: 50_000,
                working_set: 2048,
                reps: 7,
                min_loop: Duration::from_millis(2),
                export: None,
                check_budget: Duration::from_secs(3),
                time_budget: Duration::from_secs(2),
            }
        } else {
            Config {
                quick,
                cases: 200_000,
                working_set: 2048,
                reps: 21,
                min_loop: Duration::from_millis(5),
                export: None,
                check_budget: Duration::from_secs(20),
                time_budget: Duration::from_secs(10),
            }
        }
    }

    /// `--stream`: every timed loop runs over all the cases of a class
    /// rather than a working set that stays in cache, as a caller streaming
    /// through a large input would; fewer repetitions (5, or 3 with
    /// `--quick`) keep the slow classes' loops affordable.
    pub fn streaming(self) -> Self {
        Config {
            working_set: usize::MAX,
            reps: if self.quick { 3 } else { 5 },
            ..self
        }
    }

    /// The case stream of one (family, inputs): fixed, and independent of
    /// which other families run.
    pub fn rng(&self, family: &str, inputs: &str) -> SplitMix64 {
        SplitMix64::for_inputs(family, inputs)
    }
}

/// One line of the report, with exactly the fields of a `report.json` row.
#[derive(Clone, Debug)]
pub struct Row {
    pub family: &'static str,
    pub method: String,
    pub inputs: String,
    pub ns_per_op: f64,
    pub cases: u64,
    pub errors: u64,
    pub max_ulps: Option<f64>,
    /// For a method that returns a certified bound with its value: the
    /// largest bound, in ulps of the value, over the cases it answered.
    pub max_bound_ulps: Option<f64>,
}

/// A routine under test, answering a case of type `C` with an `O`.
pub trait Measure<C, O> {
    fn name(&self) -> &'static str;
    fn answer(&self, case: &C) -> O;
    /// Answers every case `iters` times; the elapsed time.
    fn run_loop(&self, cases: &[C], iters: u64) -> Duration;
}

/// A named closure as a [`Measure`]. The timed loop is generic over the
/// closure so that it inlines: calling through a pointer per case would
/// add the same few nanoseconds to every method and hide their ratios.
pub struct Method<F> {
    name: &'static str,
    f: F,
}

impl<C, O, F: Fn(&C) -> O> Measure<C, O> for Method<F> {
    fn name(&self) -> &'static str {
        self.name
    }

    fn answer(&self, case: &C) -> O {
        (self.f)(case)
    }

    fn run_loop(&self, cases: &[C], iters: u64) -> Duration {
        let start = Instant::now();
        for _ in 0..iters {
            for case in cases {
                black_box((self.f)(black_box(case)));
            }
        }
        start.elapsed()
    }
}

/// A boxed [`Method`], for a family's list of methods.
pub fn method<C, O, F: Fn(&C) -> O + 'static>(name: &'static str, f: F) -> Box<dyn Measure<C, O>> {
    Box::new(Method { name, f })
}

/// Nanoseconds per case of each method: the median over `cfg.reps` timed
/// loops. Repetitions interleave the methods so that a slow spell of a
/// shared machine hits all of them alike and their ratios stay fair.
pub fn time_methods<C, O, M: AsRef<dyn Measure<C, O>>>(
    cfg: &Config,
    cases: &[C],
    methods: &[M],
) -> Vec<f64> {
    let iters: Vec<u64> = methods
        .iter()
        .map(|m| {
            let m = m.as_ref();
            // Warm up, then size the loop to last at least `min_loop`.
            let mut n = 1;
            loop {
                let t = m.run_loop(cases, n);
                if t >= cfg.min_loop / 4 {
                    let per = t.as_secs_f64() / n as f64;
                    break ((cfg.min_loop.as_secs_f64() / per).ceil() as u64).max(1);
                }
                n *= 4;
            }
        })
        .collect();
    let mut samples = vec![Vec::with_capacity(cfg.reps); methods.len()];
    for _ in 0..cfg.reps {
        for ((m, &n), s) in methods.iter().zip(&iters).zip(&mut samples) {
            let t = m.as_ref().run_loop(cases, n);
            s.push(t.as_secs_f64() * 1e9 / (n as f64 * cases.len() as f64));
        }
    }
    samples.into_iter().map(median).collect()
}

pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// Notes that families add beside their rows (how a figure was measured, a
/// side table of figures the rows have no field for), in the order added.
static NOTES: Mutex<Vec<(&'static str, String)>> = Mutex::new(Vec::new());

/// Adds a markdown note for `family`; the report prints it after the targets.
pub fn note(family: &'static str, text: String) {
    NOTES.lock().expect("notes lock").push((family, text));
}

/// The notes added for `family`, in order.
pub fn notes(family: &str) -> Vec<String> {
    NOTES
        .lock()
        .expect("notes lock")
        .iter()
        .filter(|(f, _)| *f == family)
        .map(|(_, t)| t.clone())
        .collect()
}
