//! The two hierarchy builders give the same answers: a mesh built by
//! obvhs's PLOC builder (`BvhBuilder::Ploc`, the `ploc` feature) answers every
//! closest-hit and shadow query as the mesh built by the binned builder
//! does (which `tests/scene.rs` holds to a loop over every triangle), on
//! tiled height fields and random soups, at tiny and huge scales and far
//! from the origin, where the `f32` boxes obvhs builds over would collapse
//! without the builder's rescaling; and meshes that PLOC cannot shape
//! within the walk's stack (many identical triangles) still build.
#![cfg(feature = "ploc")]

use exactray::bvh::boxes::{BvhBuilder, PlocQuality};
use exactray::interval::Interval;
use exactray::query::ray::Watertight;
use exactray::query::ray::{Exact, Ray};
use exactray::scene::{TraceStats, TriangleMesh};
use exactray::testing::{SplitMix64, TiledMesh, unit_vector};
use glam::DVec3;

fn meshes(rng: &mut SplitMix64) -> Vec<(String, Vec<DVec3>, Vec<[u32; 3]>)> {
    let tiled = TiledMesh::new(rng, 20);
    let tris: Vec<[u32; 3]> = tiled
        .triangles
        .iter()
        .map(|t| t.map(|i| i as u32))
        .collect();
    let mut soup = Vec::new();
    for _ in 0..400 {
        let c = DVec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 5.0;
        soup.extend([0, 1, 2].map(|_| c + unit_vector(rng) * 0.4));
    }
    let soup_tris: Vec<[u32; 3]> = (0..400).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect();
    let mut out = Vec::new();
    for (kind, v, t) in [
        ("tiled", &tiled.vertices, &tris),
        ("soup", &soup, &soup_tris),
    ] {
        for (scale, offset) in [
            (1.0, 0.0),
            (1e-200, 0.0),
            (1e200, 0.0),
            (1.0, 1e8),
            (1e-6, 1e7),
        ] {
            let shift = DVec3::new(1.0, -0.6, 0.3) * offset;
            out.push((
                format!("{kind} scale {scale:e} offset {offset:e}"),
                v.iter().map(|p| *p * scale + shift).collect(),
                t.clone(),
            ));
        }
    }
    out
}

/// Rays from around the mesh's box at random points of it and at its
/// vertices.
fn rays(rng: &mut SplitMix64, vertices: &[DVec3], n: usize) -> Vec<Ray> {
    let lo = vertices.iter().fold(DVec3::INFINITY, |a, v| a.min(*v));
    let hi = vertices.iter().fold(DVec3::NEG_INFINITY, |a, v| a.max(*v));
    let (centre, size) = (lo * 0.5 + hi * 0.5, (hi - lo).max_element());
    (0..n)
        .filter_map(|k| {
            let target = if k % 2 == 0 {
                lo + (hi - lo) * DVec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64())
            } else {
                vertices[(rng.next_u64() % vertices.len() as u64) as usize]
            };
            let origin = centre + unit_vector(rng) * (size * 2.0);
            Ray::new(origin, target - origin).ok()
        })
        .collect()
}

#[test]
fn ploc_and_binned_meshes_answer_alike() {
    let mut rng = SplitMix64::new(0x9_10c);
    for (name, vertices, triangles) in meshes(&mut rng) {
        let binned =
            TriangleMesh::with_builder(&vertices, &triangles, BvhBuilder::BinnedSah).unwrap();
        for quality in [PlocQuality::Fast, PlocQuality::Medium, PlocQuality::Slow] {
            let ploc = TriangleMesh::with_builder(&vertices, &triangles, BvhBuilder::Ploc(quality))
                .unwrap();
            let mut hits = 0;
            for ray in rays(&mut rng, &vertices, 300) {
                let range = Interval::FORWARD;
                let want = binned.closest_hit_with::<Exact>(&ray, range);
                assert_eq!(
                    ploc.closest_hit_with::<Exact>(&ray, range),
                    want,
                    "{name} {quality:?}"
                );
                assert_eq!(
                    ploc.closest_hit(&ray, range),
                    binned.closest_hit(&ray, range),
                    "{name}"
                );
                assert_eq!(
                    ploc.occluded(&ray, range),
                    binned.occluded(&ray, range),
                    "{name}"
                );
                hits += usize::from(want.is_some());
            }
            assert!(hits > 100, "{name}: {hits} hits of 300");
        }
    }
}

/// Thousands of identical triangles: every box the same, no split
/// separates them. Whatever tree PLOC makes (or the binned fallback when
/// it is too deep), every query still finds the lowest index.
#[test]
fn identical_triangles_still_build() {
    let vertices = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let triangles = vec![[0u32, 1, 2]; 5000];
    let mesh =
        TriangleMesh::with_builder(&vertices, &triangles, BvhBuilder::Ploc(PlocQuality::Medium))
            .unwrap();
    let ray = Ray::new([0.2, 0.2, 1.0], [0.0, 0.0, -1.0]).unwrap();
    let hit = mesh.closest_hit(&ray, Interval::FORWARD).unwrap();
    assert_eq!((hit.triangle, hit.hit.t), (0, 1.0));
    // An empty hierarchy: every triangle degenerate.
    let flat =
        TriangleMesh::with_builder(&vertices, &[[0, 0, 1]], BvhBuilder::Ploc(PlocQuality::Fast))
            .unwrap();
    assert!(!flat.occluded(&ray, Interval::FORWARD));
}

/// The counted query answers as the plain one, and counts what the
/// hierarchy saves: on a 20 by 20 tiled height field (800 triangles), a
/// ray tests a few dozen triangles at most.
#[test]
fn counted_queries_answer_alike_and_prune() {
    let mut rng = SplitMix64::new(0x57a7);
    let tiled = TiledMesh::new(&mut rng, 20);
    let tris: Vec<[u32; 3]> = tiled
        .triangles
        .iter()
        .map(|t| t.map(|i| i as u32))
        .collect();
    let mesh = TriangleMesh::new(&tiled.vertices, &tris).unwrap();
    let mut total = TraceStats::default();
    let rays = rays(&mut rng, &tiled.vertices, 500);
    for ray in &rays {
        let mut stats = TraceStats::default();
        let counted = mesh.closest_hit_with_stats::<Watertight>(ray, Interval::FORWARD, &mut stats);
        assert_eq!(counted, mesh.closest_hit(ray, Interval::FORWARD));
        assert!(stats.nodes_visited >= 1 && stats.triangles_tested <= 800);
        total.nodes_visited += stats.nodes_visited;
        total.triangles_tested += stats.triangles_tested;
    }
    let per_ray = total.triangles_tested as f64 / rays.len() as f64;
    assert!(per_ray < 40.0, "{per_ray} triangles per ray");
}
