//! Criterion benchmarks of the predicates on uniform, near-degenerate and
//! tiny inputs, for exactray, the naive formula and `robust`.
//!
//! The families, their methods and the timed loop are the report's own
//! (`examples/report/`), so both measure the same code the same way; times
//! are per operation.

#[allow(dead_code)]
#[path = "../examples/report/framework.rs"]
mod framework;
#[allow(dead_code)]
#[path = "../examples/report/signs.rs"]
mod signs;

#[allow(dead_code)]
#[path = "../examples/report/incircle.rs"]
mod incircle;
#[allow(dead_code)]
#[path = "../examples/report/insphere.rs"]
mod insphere;
#[allow(dead_code)]
#[path = "../examples/report/orient2d.rs"]
mod orient2d;
#[allow(dead_code)]
#[path = "../examples/report/orient3d.rs"]
mod orient3d;
#[allow(dead_code)]
#[path = "../examples/report/plane_side.rs"]
mod plane_side;

use criterion::{Criterion, criterion_group, criterion_main};
use exactray::testing::InputClass;
use framework::Config;
use signs::SignFamily;
use std::time::Duration;

const CLASSES: [InputClass; 3] = [
    InputClass::Uniform,
    InputClass::NearDegenerate,
    InputClass::Tiny,
];
const METHODS: [&str; 3] = ["exactray", "naive", "robust"];

fn bench_family<C>(c: &mut Criterion, family: SignFamily<C>) {
    // Few enough cases to stay in cache, as in the report.
    let cfg = Config {
        cases: 1024,
        ..Config::new(true)
    };
    let mut group = c.benchmark_group(family.name);
    for class in CLASSES {
        let cases = family.cases(&cfg, class);
        for m in family
            .methods
            .iter()
            .filter(|m| METHODS.contains(&m.name()))
        {
            group.bench_function(format!("{}/{}", class.name(), m.name()), |b| {
                // One criterion iteration is one operation: run whole passes
                // over the cases and scale the time back.
                b.iter_custom(|iters| {
                    let passes = iters.div_ceil(cases.len() as u64);
                    let t = m.run_loop(&cases, passes);
                    t.mul_f64(iters as f64 / (passes * cases.len() as u64) as f64)
                })
            });
        }
    }
    group.finish();
}

fn predicates(c: &mut Criterion) {
    bench_family(c, orient2d::family());
    bench_family(c, orient3d::family());
    bench_family(c, incircle::family());
    bench_family(c, insphere::family());
    bench_family(c, plane_side::family());
}

criterion_group! {
    name = benches;
    // Short by default: 45 benchmarks in well under a minute.
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_millis(500));
    targets = predicates
}
criterion_main!(benches);
