//! Criterion benchmarks for exam question Q2: the pixels of one triangle
//! by rasterizing it and by casting one ray per pixel of its bounding box,
//! at areas from 8 to about 10^5 pixels.
//!
//! The triangles and methods are the report's own
//! (`examples/report/raster_triangle.rs`); times are per triangle.

#[allow(dead_code)]
#[path = "../examples/report/framework.rs"]
mod framework;
#[allow(dead_code)]
#[path = "../examples/report/raster_triangle.rs"]
mod raster_triangle;

use criterion::{Criterion, criterion_group, criterion_main};
use framework::Config;
use std::hint::black_box;
use std::time::Duration;

fn triangles(c: &mut Criterion) {
    let cfg = Config::new(true);
    let methods = raster_triangle::methods();
    for area in exactray::testing::RASTER_AREAS {
        let mut rng = cfg.rng("raster_triangle", &format!("pixels:{area}"));
        let cases: Vec<_> = (0..16)
            .map(|_| exactray::testing::raster_triangle_case(&mut rng, area))
            .collect();
        let mut group = c.benchmark_group(format!("raster_triangle/pixels:{area}"));
        for m in &methods {
            group.bench_function(m.name(), |b| {
                let mut i = 0;
                b.iter(|| {
                    i = (i + 1) % cases.len();
                    m.answer(black_box(&cases[i]))
                })
            });
        }
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    targets = triangles
}
criterion_main!(benches);
