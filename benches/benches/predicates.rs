//! Criterion benchmarks of the predicates on uniform, near-degenerate and
//! tiny inputs, for exactray, the naive formula and `robust`: the report's
//! cases (`exactray::testing`, the report's streams `family/class`, 1024
//! of them: few enough to stay in cache) and peers (`exactray-peers`);
//! times are per operation.

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, criterion_group, criterion_main};
use exactray::predicates;
use exactray::testing::{
    InputClass, SplitMix64, incircle_case, insphere_case, orient2d_case, orient3d_case,
    plane_side_case,
};
use exactray_peers::signs::{naive, robust};
use std::hint::black_box;
use std::time::{Duration, Instant};

const CLASSES: [InputClass; 3] = [
    InputClass::Uniform,
    InputClass::NearDegenerate,
    InputClass::Tiny,
];

/// Cases per class.
const CASES: usize = 1024;

/// One criterion iteration is one operation: whole passes over the cases,
/// the time scaled back. Generic over the method, so that it inlines into
/// the loop as in the report's.
fn per_op<C>(group: &mut BenchmarkGroup<WallTime>, id: String, cases: &[C], f: impl Fn(&C) -> i8) {
    group.bench_function(id, |b| {
        b.iter_custom(|iters| {
            let passes = iters.div_ceil(cases.len() as u64);
            let start = Instant::now();
            for _ in 0..passes {
                for case in cases {
                    black_box(f(black_box(case)));
                }
            }
            let t = start.elapsed();
            t.mul_f64(iters as f64 / (passes * cases.len() as u64) as f64)
        })
    });
}

/// A family's three methods on each class.
fn family<C>(
    c: &mut Criterion,
    name: &str,
    generate: fn(InputClass, &mut SplitMix64) -> C,
    methods: (impl Fn(&C) -> i8, impl Fn(&C) -> i8, impl Fn(&C) -> i8),
) {
    let mut group = c.benchmark_group(name);
    for class in CLASSES {
        let mut rng = SplitMix64::for_inputs(name, class.name());
        let cases: Vec<C> = (0..CASES).map(|_| generate(class, &mut rng)).collect();
        let id = |method: &str| format!("{}/{method}", class.name());
        per_op(&mut group, id("exactray"), &cases, &methods.0);
        per_op(&mut group, id("naive"), &cases, &methods.1);
        per_op(&mut group, id("robust"), &cases, &methods.2);
    }
    group.finish();
}

fn benches(c: &mut Criterion) {
    family(
        c,
        "orient2d",
        orient2d_case,
        (
            |&[a, b, d]: &_| predicates::orient2d(a, b, d).as_i8(),
            naive::orient2d,
            robust::orient2d,
        ),
    );
    family(
        c,
        "orient3d",
        orient3d_case,
        (
            |&[a, b, d, e]: &_| predicates::orient3d(a, b, d, e).as_i8(),
            |&[a, b, d, e]: &_| naive::orient3d(a, b, d, e),
            |&[a, b, d, e]: &_| robust::orient3d(a, b, d, e),
        ),
    );
    family(
        c,
        "incircle",
        incircle_case,
        (
            |&[a, b, d, e]: &_| predicates::incircle(a, b, d, e).as_i8(),
            naive::incircle,
            robust::incircle,
        ),
    );
    family(
        c,
        "insphere",
        insphere_case,
        (
            |&[a, b, d, e, f]: &_| predicates::insphere(a, b, d, e, f).as_i8(),
            naive::insphere,
            robust::insphere,
        ),
    );
    family(
        c,
        "plane_side",
        plane_side_case,
        (
            |&[x0, x1, x2, p, q]: &_| predicates::same_side(x0, x1, x2, p, q).as_i8(),
            naive::plane_side,
            robust::plane_side,
        ),
    );
}

criterion_group! {
    name = predicate_benches;
    // Short by default: 45 benchmarks in well under a minute.
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_millis(500));
    targets = benches
}
criterion_main!(predicate_benches);
