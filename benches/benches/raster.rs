//! Criterion benchmarks for question Q2: the pixels of one triangle
//! by rasterizing it and by casting one ray per pixel of its bounding box,
//! beside the textbook rasterizer, at areas from 8 to about 10^5 pixels.
//!
//! The triangles are the report's (`exactray::testing`, the report's
//! streams `raster_triangle/pixels:N`), the rays and the textbook
//! rasterizer the report's (`exactray-peers`); times are per triangle.

use criterion::{Criterion, criterion_group, criterion_main};
use exactray::raster::rasterize_triangle;
use exactray::testing::{RASTER_AREAS, RasterTriangle, SplitMix64, raster_triangle_case};
use exactray_peers::raster::{by_rays, naive};
use std::hint::black_box;
use std::time::Duration;

/// A method: the number of pixels it covers.
type Method = fn(&RasterTriangle) -> u64;

/// The methods, by name.
const METHODS: [(&str, Method); 3] = [
    ("exactray", |c| {
        let [a, b, d] = c.vertices;
        rasterize_triangle(a, b, d, c.width, c.height, |_, _, _| {}).unwrap_or(0)
    }),
    ("exactray-rays", |c| {
        let mut n = 0;
        by_rays(c, |_, _, hit| n += hit as u64);
        n
    }),
    ("naive", |c| {
        let mut n = 0;
        naive(c, |_, _| n += 1);
        n
    }),
];

fn triangles(c: &mut Criterion) {
    for area in RASTER_AREAS {
        let inputs = format!("pixels:{area}");
        let mut rng = SplitMix64::for_inputs("raster_triangle", &inputs);
        let cases: Vec<RasterTriangle> = (0..16)
            .map(|_| raster_triangle_case(&mut rng, area))
            .collect();
        let mut group = c.benchmark_group(format!("raster_triangle/{inputs}"));
        for (name, method) in METHODS {
            group.bench_function(name, |b| {
                let mut i = 0;
                b.iter(|| {
                    i = (i + 1) % cases.len();
                    method(black_box(&cases[i]))
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
