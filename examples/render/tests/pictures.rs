//! The tests that pin the pictures down: shadows,
//! the furnace, reproducibility. The visibility comparison of the two
//! renderers is in `visibility.rs`.

use exactray::Sign;
use exactray::interval::Interval;
use exactray::predicates::orient3d;
use exactray::query::ray::{Exact, Ray, Watertight};
use exactray::scene::{SceneBuilder, TriangleMesh, spawn_ray_to};
use exactray_render::path::PathTracer;
use exactray_render::room::{Material, Surface, cornell_room, furnace};
use exactray_render::whitted::RayTracer;
use glam::DVec3;

/// The floor `y = 0` (a big quad) and a square blocker at `y = 1`, `x`, `z`
/// in `[-0.5, 0.5]`, with a point light at `(0, 2, 0)`: the floor point
/// `(1, 0, 0)` lies exactly on the shadow's edge (its segment to the light
/// passes through the blocker's edge point `(0.5, 1, 0)`).
fn blocker() -> TriangleMesh {
    let v = [
        [-0.5, 1.0, -0.5],
        [0.5, 1.0, -0.5],
        [0.5, 1.0, 0.5],
        [-0.5, 1.0, 0.5],
    ];
    TriangleMesh::new(&v, &[[0, 1, 2], [0, 2, 3]]).unwrap()
}

const LIGHT: [f64; 3] = [0.0, 2.0, 0.0];

/// A point exactly in the shadow is dark, through the renderer's own path
/// (primary hit on the floor, shadow ray spawned from it); one well
/// outside is lit.
#[test]
fn a_point_in_the_shadow_is_dark() {
    let floor = TriangleMesh::new(
        &[
            [-9.0, 0.0, -9.0],
            [9.0, 0.0, -9.0],
            [9.0, 0.0, 9.0],
            [-9.0, 0.0, 9.0],
        ],
        &[[0, 2, 1], [0, 3, 2]],
    )
    .unwrap();
    let mut b = SceneBuilder::new();
    b.add(floor).unwrap();
    b.add(blocker()).unwrap();
    let scene = b.build();
    // Seen from the side, below the blocker's height.
    let eye = DVec3::new(3.0, 0.5, 0.0);
    for (target, dark) in [
        (DVec3::ZERO, true),
        (DVec3::new(0.3, 0.0, 0.2), true),
        (DVec3::new(2.0, 0.0, 0.0), false),
    ] {
        let ray = Ray::new(eye, target - eye).unwrap();
        let hit = scene.closest_hit(&ray, Interval::FORWARD).unwrap();
        assert_eq!(hit.primitive.0, 0, "the floor is hit first");
        let (shadow, range) = spawn_ray_to(&hit.hit, LIGHT).unwrap();
        assert_eq!(scene.occluded(&shadow, range), dark, "{target}");
    }
}

/// The stated rule at a shadow's edge. The segment from the exact floor
/// point to the light through the blocker's edge is blocked: the exact
/// segment test counts the closed triangle, edge included, and the
/// watertight test agrees; one ulp outwards it is not. Through the
/// renderer, a floor point on the edge is lit: its shadow ray leaves from
/// the spawned origin above the floor, and the segment from a point above
/// `(1, 0, 0)` to the light passes outside the blocker's edge.
#[test]
fn a_point_on_the_shadows_edge_follows_the_rule() {
    let b = blocker();
    let edge_point = [1.0, 0.0, 0.0];
    assert!(b.occluded_between_with::<Exact>(edge_point, LIGHT).unwrap());
    assert!(
        b.occluded_between_with::<Watertight>(edge_point, LIGHT)
            .unwrap()
    );
    let outside = [1f64.next_up(), 0.0, 0.0];
    assert!(!b.occluded_between_with::<Exact>(outside, LIGHT).unwrap());
    let floor = TriangleMesh::new(
        &[[-9.0, 0.0, -9.0], [9.0, 0.0, 9.0], [9.0, 0.0, -9.0]],
        &[[0, 1, 2]],
    )
    .unwrap();
    let ray = Ray::new([1.0, 3.0, 0.0], [0.0, -1.0, 0.0]).unwrap();
    let hit = floor.closest_hit(&ray, Interval::FORWARD).unwrap().hit;
    assert_eq!(hit.point, DVec3::new(1.0, 0.0, 0.0));
    let (shadow, range) = spawn_ray_to(&hit, LIGHT).unwrap();
    assert!(shadow.origin().y > 0.0);
    assert!(!b.occluded(&shadow, range));
}

/// No surface shadows itself: at every pixel of a ray-traced frame whose
/// primary ray hits a wall (planar) with the light exactly on the wall's
/// visible side (exact `orient3d` of the wall, the eye and the light), the
/// shadow ray towards the light never hits that wall.
#[test]
fn no_wall_shadows_itself() {
    let room = cornell_room(160, 120);
    let camera = room.camera;
    let light = room.point_light.position;
    let (mut checked, mut self_hits) = (0, 0);
    for j in 0..camera.height() {
        for i in 0..camera.width() {
            let ray = camera.pixel_ray(i, j);
            let Some(hit) = room.scene.closest_hit(&ray, Interval::FORWARD) else {
                continue;
            };
            let Some(p) = hit.triangle else { continue };
            let exactray::scene::Primitive::Mesh(mesh) =
                &room.scene.primitives()[hit.primitive.index()]
            else {
                continue;
            };
            let wall = mesh.triangle(p.triangle as usize).unwrap();
            let [a, b, c] = wall.vertices();
            let facing = orient3d(a, b, c, camera.eye());
            if facing == Sign::Zero
                || orient3d(a, b, c, light) != facing
                || mesh.triangles().len() != 2
            {
                continue;
            }
            let (shadow, range) = spawn_ray_to(&hit.hit, light).unwrap();
            checked += 1;
            if mesh.closest_hit(&shadow, range).is_some() {
                self_hits += 1;
            }
        }
    }
    assert!(checked > 10_000, "{checked}");
    assert_eq!(self_hits, 0, "of {checked}");
}

/// The furnace: a closed box of albedo `a` emitting radiance 1 everywhere
/// has radiance `1 / (1 - a)` everywhere; the path tracer's mean over a
/// frame is within four standard errors of it (the standard error from
/// the pixels' own sample variances; the seed is fixed, so the test is
/// deterministic).
#[test]
fn furnace_converges_to_one_over_one_minus_albedo() {
    for albedo in [0.5, 0.8] {
        let room = furnace(albedo, 24, 16);
        let tracer = PathTracer {
            samples: 64,
            ..PathTracer::default()
        };
        let r = tracer.render(&room, 24, 16);
        let n = r.variance_of_mean.len() as f64;
        let mean = r.image.mean().element_sum() / 3.0;
        let standard_error = r.variance_of_mean.iter().sum::<f64>().sqrt() / n;
        let expected = 1.0 / (1.0 - albedo);
        assert!(standard_error > 0.0);
        assert!(
            (mean - expected).abs() < 4.0 * standard_error,
            "albedo {albedo}: {mean} vs {expected} (se {standard_error})"
        );
        assert!(room.materials.iter().all(|m| matches!(
            m,
            Material {
                surface: Surface::Matte(_),
                ..
            }
        )));
    }
}

/// The same seed gives the same PNG bytes, whatever the number of threads;
/// another seed gives other bytes.
#[test]
fn renders_are_reproducible() {
    let room = cornell_room(48, 36);
    let tracer = PathTracer {
        samples: 4,
        ..PathTracer::default()
    };
    let png = |threads: usize, seed: u64| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            PathTracer { seed, ..tracer }
                .render(&room, 48, 36)
                .image
                .png_bytes()
                .unwrap()
        })
    };
    let one = png(1, 7);
    assert_eq!(one, png(2, 7));
    assert_eq!(one, png(3, 7));
    assert_ne!(one, png(2, 8));
    let traced = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            RayTracer::default()
                .render(&room, 48, 36)
                .0
                .png_bytes()
                .unwrap()
        })
    };
    assert_eq!(traced(1), traced(2));
}
