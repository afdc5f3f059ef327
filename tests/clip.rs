//! Homogeneous clipping and Z-buffer fragments against exact references:
//! the pixel-centre ray against the clip-space triangle in big integers
//! (barycentrics, visibility and depth), the perspective artifact of
//! dividing before clipping (question Q6), watertightness of a grid
//! mesh crossing the near plane, the clip weights' bound, bad input.

use exactray::InputError;
use exactray::raster::{
    ClipPlanes, ClipVertex, ClippedPolygon, Fragment, clip_triangle, rasterize_clip_space,
    rasterize_clipped, rasterize_triangle, to_screen,
};
use exactray_oracle::oracle::{common_integers, ratio_to_f64};
use glam::{DMat4, DVec2, DVec3, DVec4};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use proptest::prelude::*;
use std::collections::{BTreeMap, BTreeSet};

const U: f64 = f64::EPSILON / 2.0;

/// pbrt's `gamma(n)`, as the crate defines it (`arith::roundoff`).
fn gamma(n: u32) -> f64 {
    let nu = f64::from(n) * U;
    nu / (1.0 - nu)
}

fn planes_used(planes: ClipPlanes) -> u32 {
    match planes {
        ClipPlanes::Near => 1,
        ClipPlanes::Frustum => 6,
    }
}

/// The depth-0-to-1 right-handed perspective (glam's former
/// `DMat4::perspective_rh`).
fn perspective(fov: f64, aspect: f64, near: f64, far: f64) -> DMat4 {
    glam::dcamera::rh::proj::directx::perspective(fov, aspect, near, far)
}

/// The exact ray through a pixel centre against the clip-space triangle:
/// barycentrics `c_i / det` (`det > 0`) of the point it meets the
/// triangle's plane at, solved in big integers.
struct ExactRay {
    c: [BigInt; 3],
    det: BigInt,
    /// `det` times the point's `w` and `z`.
    w: BigInt,
    z: BigInt,
}

impl ExactRay {
    /// `None` when the ray is parallel to the triangle's plane.
    fn new(v: &[DVec4; 3], px: u32, py: u32, width: u32, height: u32) -> Option<ExactRay> {
        let values: Vec<f64> = v.iter().flat_map(|p| p.to_array()).collect();
        let ints = common_integers(&values);
        let at = |i: usize, k: usize| ints[4 * i + k].clone();
        // The centre's device coordinates: x / w = (2 px + 1 - width) / width,
        // y / w = (height - 2 py - 1) / height (screen y down).
        let cx = BigInt::from(2 * i64::from(px) + 1 - i64::from(width));
        let cy = BigInt::from(i64::from(height) - 2 * i64::from(py) - 1);
        let (nx, ny) = (BigInt::from(width), BigInt::from(height));
        let a: Vec<BigInt> = (0..3).map(|i| &nx * at(i, 0) - &cx * at(i, 3)).collect();
        let b: Vec<BigInt> = (0..3).map(|i| &ny * at(i, 1) - &cy * at(i, 3)).collect();
        let mut c = [
            &a[1] * &b[2] - &a[2] * &b[1],
            &a[2] * &b[0] - &a[0] * &b[2],
            &a[0] * &b[1] - &a[1] * &b[0],
        ];
        let mut det = &c[0] + &c[1] + &c[2];
        if det.is_zero() {
            return None;
        }
        if det.is_negative() {
            det = -det;
            c = c.map(|x| -x);
        }
        let w = (0..3).map(|i| &c[i] * at(i, 3)).sum();
        let z = (0..3).map(|i| &c[i] * at(i, 2)).sum();
        Some(ExactRay { c, det, w, z })
    }

    /// Whether the pixel shows the triangle: the point is inside it, in
    /// front of the eye (`w > 0`) and between the planes (`0 <= z`, and
    /// `z <= w` for the frustum).
    fn visible(&self, planes: ClipPlanes) -> bool {
        let inside = self.c.iter().all(|c| !c.is_negative());
        let far = planes == ClipPlanes::Near || self.z <= self.w;
        inside && self.w.is_positive() && !self.z.is_negative() && far
    }

    fn weights(&self) -> DVec3 {
        let [a, b, c] = [0, 1, 2].map(|i| ratio_to_f64(&self.c[i], &self.det));
        DVec3::new(a, b, c)
    }

    /// The exact `z / w`, rounded (for `w > 0`).
    fn depth(&self) -> f64 {
        ratio_to_f64(&self.z, &self.w)
    }
}

/// The bound of `rasterize_clipped`'s docs for the fragment at pixel
/// `(px, py)` of the fan triangle `fan` (clip vertices): (weights, depth).
fn fragment_bounds(
    fan: [ClipVertex; 3],
    px: u32,
    py: u32,
    (width, height): (u32, u32),
    j: u32,
    big_v: f64,
) -> (f64, f64) {
    let c = DVec2::new(f64::from(px) + 0.5, f64::from(py) + 0.5);
    let s = fan.map(|v| to_screen(v.position, width, height));
    let a = s.map(|s| s.truncate() - c);
    let area = (a[1].perp_dot(a[2]) + a[2].perp_dot(a[0]) + a[0].perp_dot(a[1])).abs();
    let m = [(1, 2), (2, 0), (0, 1)]
        .map(|(j, l): (usize, usize)| (a[j].x * a[l].y).abs() + (a[j].y * a[l].x).abs());
    let k = (m[0] + m[1] + m[2]) / area;
    let d: f64 = a.iter().map(|a| a.x.abs() + a.y.abs()).sum();
    let w = fan.map(|v| v.position.w);
    let rho =
        w.iter().cloned().fold(0.0, f64::max) / w.iter().cloned().fold(f64::INFINITY, f64::min);
    let r = 10.0 * f64::from(j) * gamma(4) * big_v;
    let mut delta: f64 = 0.0;
    for v in &fan {
        let p = v.position;
        for (coord, n) in [(p.x, width), (p.y, height)] {
            let e = (1.0 + (coord / p.w).abs()) / 2.0 * f64::from(n) * (gamma(3) + r / p.w);
            delta = delta.max(e);
        }
    }
    let beta = 3.0 * gamma(4) * k + 5.0 * delta * d / area;
    let weights = 3.0 * rho * beta + gamma(10) + r / big_v;
    let depths = fan.map(|v| v.position.z / v.position.w);
    let max_depth = depths.iter().fold(0.0f64, |m, d| m.max(d.abs()));
    let clip_depth = fan
        .iter()
        .zip(depths)
        .map(|(v, d)| r * (1.0 + d.abs()) / v.position.w)
        .fold(0.0, f64::max);
    (weights, (3.0 * beta + gamma(4)) * max_depth + clip_depth)
}

/// The fan triangle of `polygon` covering each pixel (exactly as
/// `rasterize_clipped` splits and rasterizes it).
fn fan_of_pixels(
    polygon: &ClippedPolygon,
    width: u32,
    height: u32,
) -> BTreeMap<(u32, u32), [ClipVertex; 3]> {
    let mut out = BTreeMap::new();
    let v = polygon.vertices();
    for k in 1..v.len().saturating_sub(1) {
        let fan = [v[0], v[k], v[k + 1]];
        if fan.iter().any(|v| v.position.w <= 0.0) {
            continue;
        }
        let s = fan.map(|v| to_screen(v.position, width, height).truncate());
        rasterize_triangle(s[0], s[1], s[2], width, height, |y, x0, x1| {
            for x in x0..x1 {
                assert!(
                    out.insert((x, y), fan).is_none(),
                    "fan triangles overlap at {x} {y}"
                );
            }
        })
        .unwrap();
    }
    out
}

/// What a check of one triangle's fragments found.
#[derive(Debug, Default)]
struct Checked {
    fragments: u64,
    /// The largest error of a weight and of depth, each over its bound.
    worst_weights: f64,
    worst_depth: f64,
}

/// Clips and rasterizes `v`, and checks every fragment against the exact
/// ray through its centre (coverage, weights and depth within the bounds)
/// and every pixel the exact ray says is visible for a fragment.
fn check_triangle(v: [DVec4; 3], planes: ClipPlanes, width: u32, height: u32) -> Checked {
    let polygon = clip_triangle(v[0], v[1], v[2], planes).unwrap();
    let fans = fan_of_pixels(&polygon, width, height);
    let big_v = v.iter().map(|p| p.abs().max_element()).fold(0.0, f64::max);
    let j = planes_used(planes);
    let mut seen = BTreeSet::new();
    let mut checked = Checked::default();
    let n = rasterize_clipped(&polygon, width, height, |f: Fragment| {
        assert!(seen.insert((f.x, f.y)), "pixel {} {} twice", f.x, f.y);
        let fan = fans[&(f.x, f.y)];
        let exact = ExactRay::new(&v, f.x, f.y, width, height)
            .expect("a covered pixel's ray meets the plane");
        let (wb, db) = fragment_bounds(fan, f.x, f.y, (width, height), j, big_v);
        let want = exact.weights();
        // The reference is rounded once: within u of the exact value.
        let err = (f.weights - want).abs().max_element();
        checked.worst_weights = checked.worst_weights.max(err / (wb + U));
        let depth_err = (f.depth - exact.depth()).abs();
        checked.worst_depth = checked
            .worst_depth
            .max(depth_err / (db + U * exact.depth().abs()));
    });
    checked.fragments = n;
    assert_eq!(n as usize, seen.len());
    for y in 0..height {
        for x in 0..width {
            let visible = ExactRay::new(&v, x, y, width, height).is_some_and(|e| e.visible(planes));
            assert_eq!(
                seen.contains(&(x, y)),
                visible,
                "pixel {x} {y}: covered against the exact ray"
            );
        }
    }
    assert!(
        checked.worst_weights <= 1.0,
        "weights beyond their bound: {checked:?}"
    );
    assert!(
        checked.worst_depth <= 1.0,
        "depth beyond its bound: {checked:?}"
    );
    checked
}

/// Question Q6: a floor triangle under the eye with one vertex behind it.
/// Dividing by `w` first wraps that vertex through infinity to the other
/// side of the screen, and the 2D triangle covers pixels, at depths inside
/// [0, 1], that the true triangle never reaches; clipping first leaves
/// exactly the exact ray's pixels.
#[test]
fn dividing_before_clipping_puts_fragments_where_nothing_is() {
    let (width, height) = (64, 48);
    let projection = perspective(1.3, f64::from(width) / f64::from(height), 0.1, 100.0);
    let world = [
        DVec3::new(-1.37, -1.02, -2.11),
        DVec3::new(1.53, -0.97, -2.43),
        DVec3::new(0.21, -1.06, 3.17),
    ];
    let v = world.map(|p| projection * p.extend(1.0));
    assert!(v[2].w < 0.0, "the third vertex is behind the eye");
    // Without clipping: each vertex divided by its own w.
    let s = v.map(|p| to_screen(p, width, height));
    let mut unclipped = BTreeMap::new();
    rasterize_triangle(
        s[0].truncate(),
        s[1].truncate(),
        s[2].truncate(),
        width,
        height,
        |y, x0, x1| {
            for x in x0..x1 {
                let c = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                let a = s.map(|s| s.truncate() - c);
                let e = [
                    a[1].perp_dot(a[2]),
                    a[2].perp_dot(a[0]),
                    a[0].perp_dot(a[1]),
                ];
                let sum = e[0] + e[1] + e[2];
                let depth = (0..3).map(|k| e[k] / sum * s[k].z).sum::<f64>();
                unclipped.insert((x, y), depth);
            }
        },
    )
    .unwrap();
    for planes in [ClipPlanes::Near, ClipPlanes::Frustum] {
        let mut clipped = BTreeSet::new();
        rasterize_clip_space(v[0], v[1], v[2], planes, width, height, |f| {
            clipped.insert((f.x, f.y));
        })
        .unwrap();
        let artifacts = unclipped
            .iter()
            .filter(|&(p, d)| (0.0..=1.0).contains(d) && !clipped.contains(p))
            .count();
        // 404 of the unclipped triangle's pixels have depths in [0, 1]
        // where nothing is (both planes settings; 495 pixels with clipping).
        assert!(artifacts > 0, "{planes:?}: {artifacts} artifact fragments");
        eprintln!(
            "{planes:?}: {artifacts} artifact fragments without clipping, {} with clipping",
            clipped.len()
        );
        // With clipping: exactly the pixels the exact ray sees, none else.
        let checked = check_triangle(v, planes, width, height);
        assert!(checked.fragments > 0);
    }
}

/// A camera 1 to 3 above the floor `y = 0`, pitched down steeply enough
/// that the floor fills the whole view: for these ranges a corner ray
/// `(±a tan(fov / 2), ±tan(fov / 2), -1)` has a downward component of at
/// least `0.35 - 0.87 = -0.52` (pitch -60, fov 70), so every pixel's ray
/// meets the floor at a view depth between `1 / 1.61` (beyond the nearest
/// near plane, 0.5) and `3 / 0.52 < 6` (before the far plane, and within 9
/// of the eye's foot: inside the grid's 20). The floor behind the eye
/// (`w < 0`) begins `height tan(-pitch) <= 3 tan 75 < 11.2` behind its
/// foot, inside the grid too.
#[derive(Clone, Debug)]
struct Camera {
    height: f64,
    yaw: f64,
    pitch: f64,
    fov: f64,
    aspect: f64,
    near: f64,
    far: f64,
}

fn camera() -> impl Strategy<Value = Camera> {
    (
        1.0..3.0f64,
        0.0..std::f64::consts::TAU,
        -75f64..-60.0,
        40f64..70.0,
        1.0..1.5f64,
        0.01..0.5f64,
        50.0..200.0f64,
    )
        .prop_map(|(height, yaw, pitch, fov, aspect, near, far)| Camera {
            height,
            yaw,
            pitch: pitch.to_radians(),
            fov: fov.to_radians(),
            aspect,
            near,
            far,
        })
}

impl Camera {
    fn matrix(&self) -> DMat4 {
        let eye = DVec3::new(0.3, self.height, -0.2);
        let forward = DVec3::new(
            self.yaw.sin() * self.pitch.cos(),
            self.pitch.sin(),
            -self.yaw.cos() * self.pitch.cos(),
        );
        let view = glam::dcamera::rh::view::look_to_mat4(eye, forward, DVec3::Y);
        perspective(self.fov, self.aspect, self.near, self.far) * view
    }
}

/// The grid's vertices in clip space and its triangles (indices), `n` x `n`
/// cells of side `cell` centred at the origin, jittered inside.
fn grid(camera: &Camera, n: usize, cell: f64, seed: u64) -> (Vec<DVec4>, Vec<[usize; 3]>) {
    let mut rng = exactray::testing::SplitMix64::new(seed);
    let m = camera.matrix();
    let half = n as f64 * cell / 2.0;
    let mut v = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let jitter = |rng: &mut exactray::testing::SplitMix64, k: usize| {
                if k == 0 || k == n {
                    0.0
                } else {
                    (rng.next_f64() - 0.5) * 0.6 * cell
                }
            };
            let x = i as f64 * cell - half + jitter(&mut rng, i);
            let z = j as f64 * cell - half + jitter(&mut rng, j);
            v.push(m * DVec4::new(x, 0.0, z, 1.0));
        }
    }
    let at = |i: usize, j: usize| j * (n + 1) + i;
    let mut tris = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if (i + j) % 2 == 0 {
                tris.extend([[a, b, c], [a, c, d]]);
            } else {
                tris.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    (v, tris)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The grid, clipped triangle by triangle and rasterized: every pixel
    /// of the view exactly once (the floor fills it), with some triangles
    /// behind the eye and some crossing the near plane; and on every edge
    /// two triangles share, the same clipped vertices to the bit.
    #[test]
    fn grid_crossing_the_near_plane_covers_each_pixel_once(cam in camera(), seed in 0u64..1000) {
        let (width, height) = (40u32, 30u32);
        let (v, tris) = grid(&cam, 16, 2.5, seed);
        prop_assert!(v.iter().any(|p| p.w < 0.0), "a vertex behind the eye");
        prop_assert!(tris.iter().any(|t| t.iter().any(|&i| v[i].w < 0.0) && t.iter().any(|&i| v[i].w > 0.0)));
        for planes in [ClipPlanes::Near, ClipPlanes::Frustum] {
            let mut counts = vec![0u32; (width * height) as usize];
            // Per undirected edge, the bits of the clipped vertices on it from
            // each triangle that has it.
            let mut on_edge: BTreeMap<(usize, usize), Vec<BTreeSet<[u64; 4]>>> = BTreeMap::new();
            for t in &tris {
                let polygon = clip_triangle(v[t[0]], v[t[1]], v[t[2]], planes).unwrap();
                rasterize_clipped(&polygon, width, height, |f| {
                    counts[(f.y * width + f.x) as usize] += 1;
                    assert!((0.0..=1.0).contains(&f.depth), "depth {}", f.depth);
                });
                for k in 0..3 {
                    // The edge opposite vertex k: its points have weight k exactly 0.
                    let (p, q) = (t[(k + 1) % 3], t[(k + 2) % 3]);
                    let bits: BTreeSet<[u64; 4]> = polygon
                        .vertices()
                        .iter()
                        .filter(|c| c.weights[k] == 0.0)
                        .map(|c| c.position.to_array().map(f64::to_bits))
                        .collect();
                    on_edge.entry((p.min(q), p.max(q))).or_default().push(bits);
                }
            }
            for (i, &c) in counts.iter().enumerate() {
                prop_assert_eq!(c, 1, "{:?}: pixel {} {} covered {} times", planes, i as u32 % width, i as u32 / width, c);
            }
            for (edge, sets) in &on_edge {
                if sets.len() == 2 {
                    prop_assert_eq!(&sets[0], &sets[1], "{:?}: edge {:?}", planes, edge);
                }
            }
        }
    }

    /// Random triangles around the eye, some behind it: coverage is the
    /// exact ray's, and weights and depth are within their bounds.
    #[test]
    fn fragments_match_the_exact_ray(
        cam in camera(),
        p in prop::array::uniform3(prop::array::uniform3(-6.0..6.0f64)),
    ) {
        let m = cam.matrix();
        let v = p.map(|p| m * DVec3::from(p).extend(1.0));
        for planes in [ClipPlanes::Near, ClipPlanes::Frustum] {
            check_triangle(v, planes, 24, 18);
        }
    }

    /// A clipped vertex's weights give back its position from the input
    /// vertices, and sum to 1, within the bounds of `ClipVertex`.
    #[test]
    fn clip_weights_reproduce_positions(
        p in prop::array::uniform3(prop::array::uniform4(-3.0..3.0f64)),
    ) {
        let v = p.map(DVec4::from_array);
        let big_v = v.iter().map(|p| p.abs().max_element()).fold(0.0, f64::max);
        for planes in [ClipPlanes::Near, ClipPlanes::Frustum] {
            let polygon = clip_triangle(v[0], v[1], v[2], planes).unwrap();
            let r = 10.0 * f64::from(planes_used(planes)) * gamma(4);
            for c in polygon.vertices() {
                let w = c.weights;
                prop_assert!(w.min_element() >= 0.0 && w.max_element() <= 1.0);
                let back = w.x * v[0] + w.y * v[1] + w.z * v[2];
                // The sum above: three products and two sums of terms
                // at most |w_i| V each.
                let evaluation = gamma(3) * w.element_sum() * big_v;
                let err = (back - c.position).abs().max_element();
                prop_assert!(err <= r * big_v + evaluation, "{:?}: {} > {}", planes, err, r * big_v + evaluation);
                prop_assert!((w.element_sum() - 1.0).abs() <= r + gamma(2));
            }
        }
    }
}

#[test]
fn bad_input_is_a_typed_error_and_outside_is_empty() {
    let ok = DVec4::new(0.0, 0.0, 0.5, 1.0);
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for k in 0..4 {
            let mut p = ok.to_array();
            p[k] = bad;
            let p = DVec4::from_array(p);
            for planes in [ClipPlanes::Near, ClipPlanes::Frustum] {
                let err = |argument| Err(InputError::NonFinite { argument });
                assert_eq!(clip_triangle(p, ok, ok, planes).map(|p| p.len()), err("v0"));
                assert_eq!(clip_triangle(ok, p, ok, planes).map(|p| p.len()), err("v1"));
                assert_eq!(clip_triangle(ok, ok, p, planes).map(|p| p.len()), err("v2"));
                let none = |_: Fragment| panic!("no fragment");
                assert_eq!(
                    rasterize_clip_space(ok, ok, p, planes, 8, 8, none).map(|n| n as usize),
                    err("v2")
                );
            }
        }
    }
    let tri = |a: [f64; 4], b: [f64; 4], c: [f64; 4]| [a, b, c].map(DVec4::from_array);
    // Behind the eye: empty for both.
    let behind = tri(
        [0.0, 0.0, -1.0, -1.0],
        [1.0, 0.0, -2.0, -2.0],
        [0.0, 1.0, -0.5, -0.5],
    );
    // Left of the view, beyond the far plane: empty for the frustum only.
    let left = tri(
        [-3.0, 0.0, 0.5, 1.0],
        [-2.0, 0.0, 0.5, 1.0],
        [-3.0, 1.0, 0.5, 1.0],
    );
    let far = tri(
        [0.0, 0.0, 2.0, 1.0],
        [0.5, 0.0, 2.0, 1.0],
        [0.0, 0.5, 3.0, 1.5],
    );
    for (v, near_empty) in [(behind, true), (left, false), (far, false)] {
        let frustum = clip_triangle(v[0], v[1], v[2], ClipPlanes::Frustum).unwrap();
        assert!(frustum.is_empty() && frustum.vertices().is_empty());
        let near = clip_triangle(v[0], v[1], v[2], ClipPlanes::Near).unwrap();
        assert_eq!(near.is_empty(), near_empty);
        let count = rasterize_clip_space(v[0], v[1], v[2], ClipPlanes::Frustum, 8, 8, |_| {
            panic!("outside")
        });
        assert_eq!(count, Ok(0));
    }
    // Extreme but finite: no panic, finite fragments.
    let m = f64::MAX;
    let huge = tri([-m, m, m, m], [m, -m, -m, -m], [0.0, m, 0.5 * m, m]);
    for planes in [ClipPlanes::Near, ClipPlanes::Frustum] {
        rasterize_clip_space(huge[0], huge[1], huge[2], planes, 8, 8, |f| {
            assert!(f.depth.is_finite() && f.weights.is_finite());
        })
        .unwrap();
    }
    // A vertex at the origin of clip space (w = 0 on the near plane).
    let origin = tri([0.0; 4], [1.0, 0.0, 0.5, 1.0], [0.0, 1.0, 0.5, 1.0]);
    for planes in [ClipPlanes::Near, ClipPlanes::Frustum] {
        rasterize_clip_space(origin[0], origin[1], origin[2], planes, 8, 8, |f| {
            assert!(f.depth.is_finite() && f.weights.is_finite());
        })
        .unwrap();
    }
}
