//! The rasterizing family's two other ways to find a triangle's pixels
//! (`exactray::testing::RasterTriangle`): the textbook rasterizer and one
//! ray per pixel centre through exactray's watertight cast.

use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::shape::Triangle;
use exactray::testing::RasterTriangle;
use glam::{DVec2, DVec3};

/// The pixel range `[first, last)` whose centres the box `[lo, hi]` holds,
/// on a grid of `n` pixels.
#[inline]
pub fn centres(lo: f64, hi: f64, n: u32) -> (u32, u32) {
    let first = (lo - 0.5).ceil().clamp(0.0, n as f64) as u32;
    let last = ((hi - 0.5).floor() + 1.0).clamp(0.0, n as f64) as u32;
    (first, last)
}

/// Calls `f(x, y, covered)` for every pixel of the bounding box, covered
/// when the ray from `(x + 0.5, y + 0.5, 1)` along `-z` hits the triangle
/// placed in the plane `z = 0` (`cast_watertight`).
#[inline]
pub fn by_rays(c: &RasterTriangle, mut f: impl FnMut(u32, u32, bool)) {
    let v = c.vertices;
    let tri = Triangle::new(v[0].extend(0.0), v[1].extend(0.0), v[2].extend(0.0)).expect("finite");
    let lo = v[0].min(v[1]).min(v[2]);
    let hi = v[0].max(v[1]).max(v[2]);
    let (x0, x1) = centres(lo.x, hi.x, c.width);
    let (y0, y1) = centres(lo.y, hi.y, c.height);
    for y in y0..y1 {
        for x in x0..x1 {
            let o = DVec3::new(x as f64 + 0.5, y as f64 + 0.5, 1.0);
            let ray = Ray::new(o, DVec3::NEG_Z).expect("finite");
            f(x, y, tri.cast_watertight(&ray, Interval::FORWARD).is_some());
        }
    }
}

/// The textbook rasterizer: edge functions stepped over every pixel of the
/// bounding box, the top-left rule on plain `f64` signs, calling `f` per
/// covered pixel.
#[inline]
pub fn naive(c: &RasterTriangle, mut f: impl FnMut(u32, u32)) {
    let [a, mut b, mut d] = c.vertices;
    let cross = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let area = cross(a, b, d);
    if area == 0.0 {
        return;
    }
    if area < 0.0 {
        std::mem::swap(&mut b, &mut d);
    }
    let edges = [(b, d), (d, a), (a, b)];
    let owns = edges.map(|(p, q)| q.y < p.y || (q.y == p.y && q.x > p.x));
    let lo = a.min(b).min(d);
    let hi = a.max(b).max(d);
    let (x0, x1) = centres(lo.x, hi.x, c.width);
    let (y0, y1) = centres(lo.y, hi.y, c.height);
    let start = DVec2::new(x0 as f64 + 0.5, y0 as f64 + 0.5);
    let mut row = edges.map(|(p, q)| cross(p, q, start));
    for y in y0..y1 {
        let mut e = row;
        for x in x0..x1 {
            if (0..3).all(|i| e[i] > 0.0 || (e[i] == 0.0 && owns[i])) {
                f(x, y);
            }
            for i in 0..3 {
                e[i] += edges[i].0.y - edges[i].1.y;
            }
        }
        for i in 0..3 {
            row[i] += edges[i].1.x - edges[i].0.x;
        }
    }
}
