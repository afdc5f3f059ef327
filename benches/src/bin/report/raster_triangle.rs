//! raster_triangle (question Q2): the pixels of one triangle found by
//! rasterizing it (`exactray`: `raster::rasterize_triangle`, edge functions
//! stepped over the bounding box, exact at pixel centres, top-left rule)
//! and by casting one ray per pixel of the same bounding box at the
//! triangle placed in the plane z = 0 (`exactray-rays`: the crate's
//! watertight cast, rays from `(x + 0.5, y + 0.5, 1)` along `-z`), beside
//! the textbook rasterizer (`naive`): edge functions stepped over every
//! pixel of the bounding box, the same fill rule on plain `f64` signs.
//! The crate's rasterizer reports a span per row (its cost grows with the
//! rows); the rays and the textbook loop visit every pixel of the box.
//!
//! Inputs `pixels:N`: right isosceles triangles of area `N` pixels (legs
//! `sqrt(2N)`), rotated at random and placed at a random sub-pixel offset.
//! ns/op is per triangle. Errors are pixels whose coverage differs from the
//! exact one (num-bigint orient2d at the pixel centre with the top-left
//! rule); the rays have no fill rule, so a centre exactly on an edge is
//! theirs on both sides of it.

use crate::framework::{Config, Measure, Row, method, note, time_methods};
use exactray::raster::rasterize_triangle;
use exactray::testing::{RASTER_AREAS, RasterTriangle, raster_triangle_case};
use exactray_oracle::oracle;
use exactray_peers::raster::{by_rays, centres, naive};

/// One triangle on a grid that holds it (`exactray::testing`).
type Case = RasterTriangle;

pub fn methods() -> Vec<Box<dyn Measure<Case, u64>>> {
    vec![
        method("exactray", |c: &Case| {
            let [a, b, d] = c.vertices;
            rasterize_triangle(a, b, d, c.width, c.height, |_, _, _| {}).unwrap_or(0)
        }),
        method("exactray-rays", |c: &Case| {
            let mut n = 0;
            by_rays(c, |_, _, hit| n += hit as u64);
            n
        }),
        method("naive", |c: &Case| {
            let mut n = 0;
            naive(c, |_, _| n += 1);
            n
        }),
    ]
}

/// Each method's coverage of `c` as a grid of flags.
fn coverage(c: &Case, name: &str) -> Vec<bool> {
    let mut grid = vec![false; (c.width * c.height) as usize];
    let w = c.width;
    let mut set = |x: u32, y: u32| grid[(y * w + x) as usize] = true;
    match name {
        "exactray" => {
            let [a, b, d] = c.vertices;
            rasterize_triangle(a, b, d, c.width, c.height, |y, x0, x1| {
                (x0..x1).for_each(|x| set(x, y))
            })
            .expect("finite");
        }
        "exactray-rays" => by_rays(c, |x, y, hit| {
            if hit {
                set(x, y)
            }
        }),
        _ => naive(c, set),
    }
    grid
}

/// The exact coverage: orient2d in integers at every centre of the grid.
fn exact(c: &Case) -> Vec<bool> {
    let v = c.vertices.map(|p| p.to_array());
    let (a, b, d) = match oracle::orient2d(v[0], v[1], v[2]) {
        1 => (v[0], v[1], v[2]),
        -1 => (v[0], v[2], v[1]),
        _ => return vec![false; (c.width * c.height) as usize],
    };
    let edges = [(a, b), (b, d), (d, a)];
    let lo = c.vertices[0].min(c.vertices[1]).min(c.vertices[2]);
    let hi = c.vertices[0].max(c.vertices[1]).max(c.vertices[2]);
    let mut grid = vec![false; (c.width * c.height) as usize];
    let (x0, x1) = centres(lo.x, hi.x, c.width);
    let (y0, y1) = centres(lo.y, hi.y, c.height);
    for y in y0..y1 {
        for x in x0..x1 {
            let p = [x as f64 + 0.5, y as f64 + 0.5];
            grid[(y * c.width + x) as usize] =
                edges
                    .iter()
                    .all(|&(p0, q)| match oracle::orient2d(p0, q, p) {
                        1 => true,
                        0 => q[1] < p0[1] || (q[1] == p0[1] && q[0] > p0[0]),
                        _ => false,
                    });
        }
    }
    grid
}

pub fn run(cfg: &Config) -> Vec<Row> {
    let methods = methods();
    let mut rows = Vec::new();
    let mut per_pixel = String::from(
        "raster_triangle (Q2): ns per covered pixel, and the rays' time over the rasterizer's, same run:\n\n\
         | pixels | exactray ns/pixel | exactray-rays ns/pixel | rays / raster |\n|---|---|---|---|\n",
    );
    for area in RASTER_AREAS {
        let inputs = format!("pixels:{area}");
        let mut rng = cfg.rng("raster_triangle", &inputs);
        // Enough triangles that a timed loop lasts, few enough to check
        // every pixel of each against the exact coverage.
        let count = (if cfg.quick { 200_000 } else { 800_000 } / area).clamp(2, 256) as usize;
        let checked = (if cfg.quick { 400_000 } else { 2_000_000 } / area)
            .clamp(1, 64)
            .min(count as u32) as usize;
        let cases: Vec<Case> = (0..count)
            .map(|_| raster_triangle_case(&mut rng, area))
            .collect();
        let truth: Vec<Vec<bool>> = cases[..checked].iter().map(exact).collect();
        let times = time_methods(cfg, &cases, &methods);
        for (m, &ns) in methods.iter().zip(&times) {
            let errors = cases[..checked]
                .iter()
                .zip(&truth)
                .map(|(c, t)| {
                    let got = coverage(c, m.name());
                    got.iter().zip(t).filter(|(a, b)| a != b).count() as u64
                })
                .sum();
            rows.push(Row {
                family: "raster_triangle",
                method: m.name().to_string(),
                inputs: inputs.clone(),
                ns_per_op: ns,
                cases: checked as u64,
                errors,
                max_ulps: None,
                max_bound_ulps: None,
            });
        }
        let pixels = truth.iter().flatten().filter(|&&b| b).count() as f64 / checked as f64;
        per_pixel += &format!(
            "| {area} | {:.2} | {:.2} | {:.1}x |\n",
            times[0] / pixels,
            times[1] / pixels,
            times[1] / times[0]
        );
    }
    per_pixel += "\nErrors count pixels checked against the exact coverage; `cases` counts the triangles checked \
                  (all of those timed at the small sizes, fewer at the large ones).";
    note("raster_triangle", per_pixel);
    rows
}
