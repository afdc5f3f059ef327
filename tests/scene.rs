//! The scene's queries against a loop over every triangle with the same
//! triangle test, on random triangle soups, tiled height fields (shared
//! edges and vertices), meshes far from the origin and at tiny and huge
//! scales; and each typed error of the mesh's constructors and queries.

use exactray::InputError;
use exactray::interval::Interval;
use exactray::query::ray::{Ray, RayCast};
use exactray::scene::{TriangleMesh, spawn_ray, spawn_ray_to};
use exactray::shape::Triangle;
use exactray::testing::{SplitMix64, TiledMesh, unit_vector};
use exactray_oracle::oracle;
use glam::DVec3;
use num_bigint::BigInt;

/// Which test a brute-force loop uses.
#[derive(Clone, Copy, Debug)]
enum Test {
    Watertight,
    Exact,
}

/// The closest hit by a loop over every triangle: for the watertight test
/// (`Triangle`'s `RayCast`) the least certified `t`, the lower index on
/// ties; for the exact one (`cast_exact_closed`, which admits the same
/// triangles in `range` as the mesh) the least exact parameter, compared
/// as big-integer fractions by the oracle (these rays lie in no
/// triangle's plane), the lower index on exact ties. Triangles the mesh
/// leaves out (degenerate, or a vanishing rounded normal) skipped.
fn brute(tris: &[Triangle], ray: &Ray, range: Interval, test: Test) -> Option<(u32, f64)> {
    let mut best: Option<(u32, f64)> = None;
    let mut best_exact: Option<(BigInt, BigInt)> = None;
    for (i, tri) in tris.iter().enumerate() {
        if tri.is_degenerate() || tri.normal() == DVec3::ZERO {
            continue;
        }
        let t = match test {
            Test::Watertight => tri.cast(ray, range).map(|h| h.t),
            Test::Exact => tri.cast_exact_closed(ray, range).map(|h| h.t),
        };
        let Some(t) = t else { continue };
        match test {
            Test::Watertight => {
                if best.is_none_or(|(_, bt)| t < bt) {
                    best = Some((i as u32, t));
                }
            }
            Test::Exact => {
                let line = oracle::line_triangle(
                    ray.origin().to_array(),
                    ray.direction().to_array(),
                    tri.vertices().map(|p| p.to_array()),
                );
                let exact = line.t.expect("an exact hit off the plane crosses it");
                let earlier = best_exact
                    .as_ref()
                    .is_none_or(|(n, d)| &exact.0 * d < n * &exact.1);
                if earlier {
                    best = Some((i as u32, t));
                    best_exact = Some(exact);
                }
            }
        }
    }
    best
}

/// A mesh moved to `offset` and scaled by `scale` (rounded per vertex).
struct Case {
    name: String,
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
}

fn soup(rng: &mut SplitMix64, n: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for k in 0..n as u32 {
        let c = DVec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 4.0;
        let size = 0.05 + 0.5 * rng.next_f64();
        let a = c + unit_vector(rng) * size;
        let b = c + unit_vector(rng) * size;
        // Every tenth triangle degenerate: a repeated vertex.
        let d = if k % 10 == 0 {
            a
        } else {
            c + unit_vector(rng) * size
        };
        vertices.extend([a, b, d]);
        triangles.push([3 * k, 3 * k + 1, 3 * k + 2]);
    }
    (vertices, triangles)
}

fn cases() -> Vec<Case> {
    let mut rng = SplitMix64::new(0x5ce7e);
    let mut out = Vec::new();
    let tiled = TiledMesh::new(&mut rng, 12);
    let tiled = (
        tiled.vertices.clone(),
        tiled
            .triangles
            .iter()
            .map(|t| t.map(|i| i as u32))
            .collect::<Vec<_>>(),
    );
    let soup = soup(&mut rng, 300);
    for (kind, (v, t)) in [("tiled", &tiled), ("soup", &soup)] {
        for (scale, offset) in [
            (1.0, 0.0),
            (1e-30, 0.0),
            (2f64.powi(-600), 0.0),
            (1e30, 0.0),
            (2f64.powi(600), 0.0),
            (1.0, 1e6),
            (1.0, 1e7),
            (1.0, 1e8),
            (1e-3, 1e8),
        ] {
            let shift = DVec3::new(1.0, -0.7, 0.4) * offset;
            out.push(Case {
                name: format!("{kind} scale {scale:e} offset {offset:e}"),
                vertices: v.iter().map(|p| *p * scale + shift).collect(),
                triangles: t.clone(),
            });
        }
    }
    out
}

/// Rays at random points of the mesh's box, at its vertices exactly and at
/// points of its edges, from random origins around it.
fn rays(rng: &mut SplitMix64, case: &Case, n: usize) -> Vec<Ray> {
    let lo = case.vertices.iter().fold(DVec3::INFINITY, |a, v| a.min(*v));
    let hi = case
        .vertices
        .iter()
        .fold(DVec3::NEG_INFINITY, |a, v| a.max(*v));
    let (center, size) = ((lo + hi) * 0.5, (hi - lo).max_element());
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let tri = case.triangles[(rng.next_u64() % case.triangles.len() as u64) as usize];
        let [a, b, _] = tri.map(|i| case.vertices[i as usize]);
        let target = match out.len() % 3 {
            0 => lo + (hi - lo) * DVec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()),
            1 => a,
            _ => a + (b - a) * 0.5,
        };
        let origin = center + unit_vector(rng) * (size * 2.0);
        if let Ok(ray) = Ray::new(origin, target - origin) {
            out.push(ray);
        }
    }
    out
}

/// Closest hit and occlusion equal the brute-force loop, same triangle and
/// same `t`, for both tests and for a full and a clipped range.
#[test]
fn closest_hit_equals_brute_force() {
    let mut rng = SplitMix64::new(0xb0b);
    for case in cases() {
        let mesh = TriangleMesh::new(&case.vertices, &case.triangles).unwrap();
        let tris: Vec<Triangle> = (0..case.triangles.len())
            .map(|i| mesh.triangle(i).unwrap())
            .collect();
        let mut hits = 0;
        let rays = rays(&mut rng, &case, 400);
        for ray in &rays {
            for range in [Interval::FORWARD, Interval::new(0.9, 1.0).unwrap()] {
                for test in [Test::Watertight, Test::Exact] {
                    let want = brute(&tris, ray, range, test);
                    let got = match test {
                        Test::Watertight => mesh.closest_hit(ray, range),
                        Test::Exact => {
                            mesh.closest_hit_with::<exactray::query::ray::Exact>(ray, range)
                        }
                    };
                    let got_pair = got.map(|h| (h.triangle, h.hit.t));
                    assert_eq!(got_pair, want, "{}: {ray:?} {range:?} {test:?}", case.name);
                    let occluded = match test {
                        Test::Watertight => mesh.occluded(ray, range),
                        Test::Exact => {
                            mesh.occluded_with::<exactray::query::ray::Exact>(ray, range)
                        }
                    };
                    assert_eq!(occluded, want.is_some(), "{}: {ray:?} {test:?}", case.name);
                    if let Some(h) = got {
                        hits += 1;
                        // The hit's point is the ray's point at its t, its
                        // error finite, its barycentrics in the triangle.
                        assert_eq!(h.hit.point, ray.at(h.hit.t));
                        assert!(h.hit.error.is_finite());
                        assert!(h.u >= 0.0 && h.v >= 0.0 && h.u + h.v <= 1.0 + 1e-12);
                        if let Test::Watertight = test {
                            assert_eq!(mesh.cast(ray, range), Some(h.hit));
                        }
                    }
                }
            }
        }
        // Most rays aim at the mesh: the comparison is not vacuous.
        assert!(hits > rays.len() / 2, "{}: {hits}", case.name);
    }
}

/// The segment query is the ray query on `[0, 1]`: the segment between two
/// points on either side of a tiled mesh is blocked, one ending above it
/// is not.
#[test]
fn occluded_between_is_the_segment() {
    let mut rng = SplitMix64::new(3);
    let tiled = TiledMesh::new(&mut rng, 8);
    let triangles: Vec<[u32; 3]> = tiled
        .triangles
        .iter()
        .map(|t| t.map(|i| i as u32))
        .collect();
    let mesh = TriangleMesh::new(&tiled.vertices, &triangles).unwrap();
    for _ in 0..1000 {
        let (x, y) = (1.0 + 6.0 * rng.next_f64(), 1.0 + 6.0 * rng.next_f64());
        let p = DVec3::new(x, y, 3.0);
        assert!(mesh.occluded_between(p, [x + 0.3, y, -3.0]).unwrap());
        assert!(!mesh.occluded_between(p, [x + 0.3, y, 1.0]).unwrap());
    }
    assert_eq!(mesh.occluded_between([1.0; 3], [1.0; 3]), Ok(false));
}

/// Each typed error, and degenerate triangles never hit.
#[test]
fn bad_input() {
    let v = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    assert_eq!(
        TriangleMesh::new(&[[0.0, f64::NAN, 0.0]], &[]).unwrap_err(),
        InputError::NonFinite {
            argument: "vertices"
        }
    );
    assert_eq!(
        TriangleMesh::new(&v, &[[0, 1, 3]]).unwrap_err(),
        InputError::IndexOutOfRange { index: 3, len: 3 }
    );
    let mesh = TriangleMesh::new(&v, &[[0, 1, 2]]).unwrap();
    assert_eq!(
        mesh.clone()
            .with_normals(&[[0.0, 0.0, 1.0]; 2])
            .unwrap_err(),
        InputError::LengthMismatch {
            expected: 3,
            got: 2
        }
    );
    assert_eq!(
        mesh.clone()
            .with_normals(&[[0.0, 0.0, 1.0], [0.0, f64::INFINITY, 1.0], [0.0, 0.0, 1.0]])
            .unwrap_err(),
        InputError::NonFinite {
            argument: "normals"
        }
    );
    assert_eq!(
        mesh.occluded_between([f64::NAN, 0.0, 0.0], [0.0; 3]),
        Err(InputError::NonFinite { argument: "p" })
    );
    assert_eq!(
        mesh.occluded_between([0.0; 3], [0.0, 0.0, f64::INFINITY]),
        Err(InputError::NonFinite { argument: "q" })
    );
    // Ends farther apart than f64::MAX are a segment too (tests/whole_range.rs).
    assert_eq!(
        mesh.occluded_between([0.25, 0.25, -f64::MAX], [0.25, 0.25, f64::MAX]),
        Ok(true)
    );
    assert!(mesh.triangle(1).is_none() && mesh.triangle(usize::MAX).is_none());
    // Spawning: zero and NaN directions, a NaN target, an uncertified hit.
    let ray = Ray::new([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]).unwrap();
    let hit = mesh.closest_hit(&ray, Interval::FORWARD).unwrap().hit;
    assert_eq!(spawn_ray(&hit, [0.0; 3]), Err(InputError::ZeroDirection));
    assert_eq!(
        spawn_ray(&hit, [f64::NAN, 0.0, 1.0]),
        Err(InputError::NonFinite {
            argument: "direction"
        })
    );
    assert_eq!(
        spawn_ray_to(&hit, [f64::NAN, 0.0, 1.0]),
        Err(InputError::NonFinite { argument: "point" })
    );
    let mut uncertified = hit;
    uncertified.error = DVec3::INFINITY;
    assert_eq!(
        spawn_ray(&uncertified, [0.0, 0.0, 1.0]),
        Err(InputError::NonFinite { argument: "origin" })
    );
    // Degenerate triangles (a repeated vertex, collinear vertices) and an
    // empty mesh: never a hit.
    let flat = TriangleMesh::new(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [2.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
        ],
        &[[0, 1, 2], [0, 0, 3]],
    )
    .unwrap();
    let down = Ray::new([1.0, 1.0, 1.0], [0.0, 0.0, -1.0]).unwrap();
    assert!(flat.closest_hit(&down, Interval::FORWARD).is_none());
    assert!(!flat.occluded(&down, Interval::FORWARD));
    let empty = TriangleMesh::new::<[f64; 3]>(&[], &[]).unwrap();
    assert!(empty.closest_hit(&down, Interval::FORWARD).is_none());
    // A ray whose direction has zero coordinates, from a face of a box.
    let on_face = Ray::new([0.0, 0.5, 1.0], [0.0, 0.0, -1.0]).unwrap();
    assert!(mesh.occluded(&on_face, Interval::FORWARD));
}
