//! Queries across the whole finite range, where a difference or a product
//! of two finite inputs overflows: segments whose ends are farther apart
//! than `f64::MAX` on some axis (a light at one end of a huge scene, a
//! point at the other) get an answer, equal to the exact oracle's
//! (`exactray_oracle::mesh_oracle`) for the exact variant, on meshes and
//! scenes; shadow rays spawned towards such points; rays whose origin and
//! boxes lie on opposite ends of the range; hit points far along a ray;
//! and the nearest index over points spanning the range.

use exactray::bvh::SphereBvh;
use exactray::interval::Interval;
use exactray::query::ray::{Exact, Ray, Watertight};
use exactray::scene::{Scene, SceneBuilder, TriangleMesh, spawn_ray_to};
use exactray::shape::{Sphere, Triangle};
use exactray::testing::SplitMix64;
use exactray_oracle::mesh_oracle;
use exactray_oracle::oracle::{ExactPointSet, cmp_ratio};
use glam::DVec3;
use proptest::prelude::*;
use std::ops::Not;

const MAX: f64 = f64::MAX;

/// A wall in the plane `x = 0` spanning `[-MAX, MAX]` in `y` and `z`, as
/// two triangles sharing the diagonal.
fn wall() -> ([[f64; 3]; 4], [[u32; 3]; 2]) {
    (
        [
            [0.0, -MAX, -MAX],
            [0.0, MAX, -MAX],
            [0.0, MAX, MAX],
            [0.0, -MAX, MAX],
        ],
        [[0, 1, 2], [0, 2, 3]],
    )
}

/// A closed octahedron of radius `r` around `c`.
fn octahedron(c: [f64; 3], r: f64) -> ([[f64; 3]; 6], [[u32; 3]; 8]) {
    let v = |k: usize, s: f64| {
        let mut p = c;
        p[k] += s * r;
        p
    };
    (
        [
            v(0, 1.0),
            v(0, -1.0),
            v(1, 1.0),
            v(1, -1.0),
            v(2, 1.0),
            v(2, -1.0),
        ],
        [
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 0, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ],
    )
}

/// The oracle's answer over the triangles a mesh holds in its hierarchy:
/// a triangle so thin that its rounded normal vanishes is never hit (the
/// `scene::mesh` module's rule), so it is left out here too.
fn oracle(p: [f64; 3], q: [f64; 3], vertices: &[[f64; 3]], triangles: &[[u32; 3]]) -> bool {
    let tris: Vec<[usize; 3]> = triangles
        .iter()
        .filter(|&&t| hierarchy_holds(vertices, t))
        .map(|t| t.map(|i| i as usize))
        .collect();
    mesh_oracle::segment_mesh(p, q, vertices, &tris)
}

/// Whether a mesh keeps the triangle in its hierarchy: not degenerate,
/// and its rounded normal not zero.
fn hierarchy_holds(vertices: &[[f64; 3]], t: [u32; 3]) -> bool {
    let [a, b, c] = t.map(|i| vertices[i as usize]);
    Triangle::new(a, b, c).is_ok_and(|t| t.normal() != DVec3::ZERO)
}

/// The mesh alone and in a scene of its own: the exact variant's answer
/// on both, and the watertight one's.
fn answers(mesh: &TriangleMesh, scene: &Scene, p: [f64; 3], q: [f64; 3]) -> [bool; 4] {
    [
        mesh.occluded_between_with::<Exact>(p, q).unwrap(),
        scene.occluded_between_with::<Exact>(p, q).unwrap(),
        mesh.occluded_between(p, q).unwrap(),
        scene.occluded_between_with::<Watertight>(p, q).unwrap(),
    ]
}

fn scene_of(mesh: &TriangleMesh) -> Scene {
    let mut b = SceneBuilder::new();
    b.add(mesh.clone()).unwrap();
    b.build()
}

/// A scene's shapes on a far segment: a sphere of radius `MAX / 8`, hit
/// or missed by segments across the range; the wall beside it.
#[test]
fn far_segments_meet_shapes() {
    let (vertices, triangles) = wall();
    let mut b = SceneBuilder::new();
    b.add(TriangleMesh::new(&vertices, &triangles).unwrap())
        .unwrap();
    b.add(Sphere::new([MAX / 2.0, MAX / 2.0, 0.0], MAX / 8.0).unwrap())
        .unwrap();
    let scene = b.build();
    // Along y at x = MAX / 2: through the sphere, beside the wall.
    let (p, q) = ([MAX / 2.0, -MAX, 1.0], [MAX / 2.0, MAX, -1.0]);
    assert!(scene.occluded_between(p, q).unwrap());
    assert!(scene.occluded_between_with::<Exact>(p, q).unwrap());
    // Past it, at z = MAX / 4.
    let (p, q) = ([MAX / 2.0, -MAX, MAX / 4.0], [MAX / 2.0, MAX, MAX / 4.0]);
    assert!(!scene.occluded_between(p, q).unwrap());
    assert!(!scene.occluded_between_with::<Exact>(p, q).unwrap());
}

/// The reported case: a shadow segment from `x = -1.369e308` to `x =
/// 1.777e308` across a mesh spanning the range, which answered an error.
#[test]
fn a_segment_across_the_range_is_answered() {
    let (vertices, triangles) = wall();
    let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
    let scene = scene_of(&mesh);
    let p = [-1.369e308, 0.25, -3.5e200];
    let q = [1.777e308, 1e307, 7.0];
    assert!((DVec3::from(q) - DVec3::from(p)).x.is_infinite());
    assert!(oracle(p, q, &vertices, &triangles));
    assert_eq!(answers(&mesh, &scene, p, q), [true; 4]);
    // Across the range along y, beside the wall.
    let (p, q) = ([1e-300, -MAX, 0.0], [1e-300, MAX, -MAX]);
    assert!(!oracle(p, q, &vertices, &triangles));
    assert_eq!(answers(&mesh, &scene, p, q), [false; 4]);
}

/// A far segment whose other coordinates are subnormal, where halving the
/// difference rounds (`2^-1074 / 2` to 0): its far end `q` lies on a
/// triangle's edge at `y = 5 2^-1074`. The exact variant decides on `q`
/// itself (the rounded ray ends at `y = 4 2^-1074`, one step short, and
/// the watertight test's rounded edge values cannot tell the two apart
/// next to `f64::MAX`).
#[test]
fn far_segments_with_subnormal_coordinates() {
    let s = f64::from_bits(1);
    let vertices = [[MAX, 5.0 * s, -1.0], [MAX, 5.0 * s, 1.0], [MAX, 1.0, 0.0]];
    let triangles = [[0, 1, 2]];
    let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
    let scene = scene_of(&mesh);
    let (p, q) = ([-MAX, 4.0 * s, 0.0], [MAX, 5.0 * s, 0.0]);
    assert!(oracle(p, q, &vertices, &triangles));
    assert_eq!(answers(&mesh, &scene, p, q)[..2], [true; 2]);
    // One step past the edge's side.
    let q = [MAX, 4.0 * s, 0.0];
    assert!(!oracle(p, q, &vertices, &triangles));
    assert_eq!(answers(&mesh, &scene, p, q)[..2], [false; 2]);
}

/// Ends at `±(1 - 2^-53) 2^1024` on every axis: every pair of the cube's
/// corners, against the wall and an octahedron spanning half the range.
#[test]
fn segments_between_the_largest_corners() {
    let corners: Vec<[f64; 3]> = (0..8)
        .map(|i| [0, 1, 2].map(|k| if i >> k & 1 == 1 { MAX } else { -MAX }))
        .collect();
    let (wv, wt) = wall();
    let (ov, ot) = octahedron([MAX / 4.0, 0.0, 0.0], MAX / 2.0);
    let meshes = [(wv.to_vec(), wt.to_vec()), (ov.to_vec(), ot.to_vec())];
    let mut met = 0;
    for (vertices, triangles) in &meshes {
        let mesh = TriangleMesh::new(vertices, triangles).unwrap();
        let scene = scene_of(&mesh);
        for &p in &corners {
            for &q in &corners {
                let want = oracle(p, q, vertices, triangles);
                let got = answers(&mesh, &scene, p, q);
                assert_eq!(got[..2], [want; 2], "{p:?} {q:?}");
                met += usize::from(want);
            }
        }
    }
    assert!(met > 20, "{met}");
}

/// Coordinates drawn from the whole range: huge of either sign, up to
/// `f64::MAX`, ordinary, tiny and subnormal (where halving a difference
/// rounds), zero.
fn coordinate(rng: &mut SplitMix64) -> f64 {
    let sign = if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
    let x = match rng.next_u64() % 6 {
        0 => MAX * (1.0 - rng.next_f64() * 0.5),
        1 => MAX * rng.next_f64(),
        2 => rng.next_f64() * 2f64.powi((rng.next_u64() % 2000) as i32 - 1000),
        3 => f64::from_bits(rng.next_u64() % 64),
        4 => (rng.next_u64() % 5) as f64,
        _ => MAX,
    };
    sign * x
}

fn point(rng: &mut SplitMix64) -> [f64; 3] {
    [coordinate(rng), coordinate(rng), coordinate(rng)]
}

/// Four triangles over six points drawn from the whole range, sharing
/// vertices.
fn random_mesh(rng: &mut SplitMix64) -> (Vec<[f64; 3]>, [[u32; 3]; 4], TriangleMesh) {
    let vertices: Vec<[f64; 3]> = (0..6).map(|_| point(rng)).collect();
    let triangles = [[0, 1, 2], [3, 4, 5], [0, 2, 4], [1, 3, 5]];
    let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
    (vertices, triangles, mesh)
}

/// Random meshes and segments over the whole range, the exact variant
/// against the oracle on meshes and scenes; the watertight one against
/// the exact one wherever no coordinate of the case is tiny (the
/// watertight rules differ only at edges, which random huge cases do not
/// meet).
#[test]
fn random_far_segments_agree_with_the_oracle() {
    let mut rng = SplitMix64::new(0xfa7);
    let (mut met, mut far) = (0, 0);
    for case in 0..600 {
        let (vertices, triangles, mesh) = random_mesh(&mut rng);
        let scene = scene_of(&mesh);
        for _ in 0..8 {
            let (p, q) = (point(&mut rng), point(&mut rng));
            far += usize::from(!(DVec3::from(q) - DVec3::from(p)).is_finite());
            let want = oracle(p, q, &vertices, &triangles);
            let got = answers(&mesh, &scene, p, q);
            assert_eq!(got[..2], [want; 2], "case {case}: {p:?} {q:?}");
            met += usize::from(want);
        }
    }
    assert!(far > 1000 && met > 300, "{far} {met}");
}

/// A path tracer's shadow ray from a hit near one end of the range to a
/// light at the other: the direction is halved, the range `[0, 2)`, the
/// surface it leaves is not hit again, and a wall between blocks it.
#[test]
fn shadow_rays_towards_the_far_end() {
    let (ov, ot) = octahedron([-MAX / 2.0, 0.0, 0.0], MAX / 4.0);
    let (wv, wt) = wall();
    let mut vertices = ov.to_vec();
    vertices.extend(wv.iter().map(|v| [v[0] + MAX / 2.0, v[1], v[2]]));
    let mut triangles = ot.to_vec();
    triangles.extend(wt.iter().map(|t| t.map(|i| i + 6)));
    let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
    let ray = Ray::new([-MAX / 2.0, 0.0, -MAX], [0.0, 0.0, 1.0]).unwrap();
    let hit = mesh.closest_hit(&ray, Interval::FORWARD).unwrap().hit;
    for light in [[MAX, 1.0, -MAX], [MAX, -MAX, MAX], [-MAX, 0.0, -MAX]] {
        let (shadow, range) = spawn_ray_to(&hit, light).unwrap();
        let halved = light[0] == MAX;
        assert_eq!(
            range.max(),
            if halved {
                2.0f64.next_down()
            } else {
                1.0f64.next_down()
            }
        );
        // Halfway, the ray is at the segment's midpoint up to three
        // roundings of values at most MAX (the direction's, the point's
        // sum and the midpoint's own), each within u MAX, u = 2^-53.
        let o = shadow.origin();
        let mid = DVec3::from(light) * 0.5 + o * 0.5;
        let half = shadow.at(if halved { 1.0 } else { 0.5 });
        let bound = 4.0 * (f64::EPSILON / 2.0) * MAX;
        assert!(
            (half - mid).abs().max_element() <= bound,
            "{half:?} {mid:?}"
        );
        let blocked = mesh.occluded(&shadow, range);
        assert_eq!(blocked, halved, "{light:?}");
        assert_eq!(mesh.occluded_with::<Exact>(&shadow, range), halved);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// End points drawn up to `f64::MAX` of either sign on a mesh whose
    /// vertices span the range: the exact variant equals the oracle.
    #[test]
    fn far_segments_are_exact(
        seed in any::<u64>(),
        p in prop::array::uniform3(prop::num::f64::NORMAL | prop::num::f64::SUBNORMAL | prop::num::f64::ZERO),
        q in prop::array::uniform3(prop::num::f64::NORMAL | prop::num::f64::SUBNORMAL | prop::num::f64::ZERO),
    ) {
        let mut rng = SplitMix64::new(seed);
        let vertices: Vec<[f64; 3]> = (0..5).map(|_| point(&mut rng)).collect();
        let triangles = [[0, 1, 2], [2, 3, 4], [0, 3, 1]];
        let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
        let want = oracle(p, q, &vertices, &triangles);
        prop_assert_eq!(mesh.occluded_between_with::<Exact>(p, q).unwrap(), want);
        // The watertight answer exists for every finite pair.
        prop_assert!(mesh.occluded_between(p, q).is_ok());
    }
}

/// Rays from one end of the range to the other: the origin beyond `2^969`
/// and the boxes on the far side, where `b - o` overflows in the world
/// slab test (it halves there). Exact closest hits against the oracle,
/// with a finite hit point and error.
#[test]
fn rays_across_the_range_agree_with_the_oracle() {
    let mut rng = SplitMix64::new(0xacc);
    let (mut hits, mut across) = (0, 0);
    for case in 0..3000 {
        let (vertices, triangles, mesh) = random_mesh(&mut rng);
        let (o, d) = (point(&mut rng), point(&mut rng));
        let Ok(ray) = Ray::new(o, d) else { continue };
        // The triangles in the hierarchy, by their indices in the mesh.
        let kept: Vec<usize> = (0..triangles.len())
            .filter(|&i| hierarchy_holds(&vertices, triangles[i]))
            .collect();
        let tris: Vec<[usize; 3]> = kept
            .iter()
            .map(|&i| triangles[i].map(|x| x as usize))
            .collect();
        // A first hit beyond `f64::MAX` is none: no `f64` parameter holds it.
        let want = mesh_oracle::ray_mesh(o, d, &vertices, &tris)
            .filter(|(t, _)| cmp_ratio(&t.num, &t.den, MAX).is_le())
            .map(|(t, on)| (t, on.iter().map(|&i| kept[i]).collect::<Vec<_>>()));
        let got = mesh.closest_hit_with::<Exact>(&ray, Interval::FORWARD);
        assert_eq!(got.is_some(), want.is_some(), "case {case}: {o:?} {d:?}");
        assert_eq!(
            mesh.occluded_with::<Exact>(&ray, Interval::FORWARD),
            want.is_some()
        );
        if let (Some(h), Some((_, on))) = (got, &want) {
            assert!(
                on.contains(&(h.triangle as usize)),
                "case {case}: {o:?} {d:?} {vertices:?} {h:?} {want:?}"
            );
            hits += 1;
            let far = vertices
                .iter()
                .any(|v| (DVec3::from(*v) - DVec3::from(o)).is_finite().not());
            across += usize::from(far);
            if h.hit.point.is_finite() {
                assert!(h.hit.error.is_finite(), "case {case}: {:?}", h.hit);
            }
        }
    }
    assert!(hits > 300 && across > 100, "{hits} {across}");
}

/// Small meshes near one end of the range and rays from the other end
/// aimed at them: the hierarchy's frame is far too small for the ray, so
/// the world slab test runs, with `b - o` beyond `f64::MAX`.
#[test]
fn rays_from_the_far_end_reach_small_meshes() {
    let mut rng = SplitMix64::new(0xe2d);
    let mut hits = 0;
    for case in 0..2000 {
        let side = |rng: &mut SplitMix64| if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
        let c: [f64; 3] =
            core::array::from_fn(|_| side(&mut rng) * MAX * (0.5 + 0.4 * rng.next_f64()));
        // Sizes from 2^960, where the aim's rounding (about 2^-53 MAX) is
        // a fraction of the size, to 2^1019.
        let r = 2f64.powi((rng.next_u64() % 60) as i32 + 960);
        let (vertices, triangles) = octahedron(c, r);
        let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
        let o: [f64; 3] =
            core::array::from_fn(|k| -c[k].signum() * MAX * (0.5 + 0.5 * rng.next_f64()));
        // Aimed at the centre, up to a few radii off, as a halved difference.
        let aim: [f64; 3] = core::array::from_fn(|k| c[k] + r * 4.0 * (rng.next_f64() - 0.5));
        let d: [f64; 3] = core::array::from_fn(|k| aim[k] * 0.5 - o[k] * 0.5);
        let ray = Ray::new(o, d).unwrap();
        let tris: Vec<[usize; 3]> = triangles.iter().map(|t| t.map(|i| i as usize)).collect();
        let want = mesh_oracle::ray_mesh(o, d, &vertices, &tris);
        let got = mesh.closest_hit_with::<Exact>(&ray, Interval::FORWARD);
        assert_eq!(
            got.is_some(),
            want.is_some(),
            "case {case}: {o:?} {d:?} {c:?} {r}"
        );
        assert_eq!(
            mesh.occluded_with::<Exact>(&ray, Interval::FORWARD),
            want.is_some()
        );
        if let (Some(h), Some((_, on))) = (got, &want) {
            assert!(on.contains(&(h.triangle as usize)), "case {case}");
            assert!(
                h.hit.point.is_finite() && h.hit.error.is_finite(),
                "{:?}",
                h.hit
            );
            hits += 1;
        }
    }
    assert!(hits > 200, "{hits}");
}

/// The nearest index over points spanning the range (squared distances
/// far beyond `f64::MAX`): a point at exactly the least distance, against
/// the exact oracle.
#[test]
fn nearest_points_across_the_range() {
    let mut rng = SplitMix64::new(0x9ea);
    for case in 0..40 {
        let points: Vec<[f64; 3]> = (0..200).map(|_| point(&mut rng)).collect();
        let bvh = SphereBvh::from_points(&points).unwrap();
        let exact = ExactPointSet::new(&points);
        for _ in 0..50 {
            let q = point(&mut rng);
            let got = bvh.nearest(q).unwrap().index;
            assert_eq!(got, exact.nearest(q)[0], "case {case}: {q:?}");
        }
    }
}

/// Shapes whose boxes reach past `f64::MAX` (a sphere of radius `MAX / 2`
/// centred at `0.9 MAX`): the scene's box is infinite on that side and
/// still culls nothing it must keep.
#[test]
fn shapes_whose_boxes_overflow() {
    let mut b = SceneBuilder::new();
    let big = Sphere::new([0.9 * MAX, 0.0, 0.0], MAX / 2.0).unwrap();
    b.add(big).unwrap();
    b.add(Sphere::new([-0.9 * MAX, 0.0, 0.0], 1.0).unwrap())
        .unwrap();
    let scene = b.build();
    let ray = Ray::new([-MAX, 0.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    let hit = scene.closest_hit(&ray, Interval::FORWARD).unwrap();
    assert_eq!(hit.primitive.0, 1);
    let ray = Ray::new([0.0, -MAX, 0.0], [0.0, MAX, 0.0]).unwrap();
    assert!(scene.closest_hit(&ray, Interval::FORWARD).is_none());
    let ray = Ray::new([0.9 * MAX, -MAX, 0.0], [0.0, MAX, 0.0]).unwrap();
    let hit = scene.closest_hit(&ray, Interval::FORWARD).unwrap();
    assert_eq!(hit.primitive.0, 0);
    assert!(
        hit.hit.point.is_finite() && hit.hit.error.is_finite(),
        "{hit:?}"
    );
    assert!(
        scene
            .occluded_between([0.9 * MAX, -MAX, 0.0], [0.9 * MAX, MAX, 0.0])
            .unwrap()
    );
}

/// A surface at `f64::MAX` itself: a ray leaving it outwards has no
/// finite origin off the surface, a typed error; inwards it leaves.
#[test]
fn spawning_at_the_end_of_the_range() {
    let vertices = [[MAX, -1.0, -1.0], [MAX, 1.0, -1.0], [MAX, 0.0, 1.0]];
    let mesh = TriangleMesh::new(&vertices, &[[0, 1, 2]]).unwrap();
    let ray = Ray::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    let hit = mesh.closest_hit(&ray, Interval::FORWARD).unwrap().hit;
    assert!(hit.point.is_finite());
    let back = exactray::scene::spawn_ray(&hit, [-1.0, 0.0, 0.0]).unwrap();
    assert!(!mesh.occluded(&back, Interval::FORWARD));
    assert_eq!(
        exactray::scene::spawn_ray(&hit, [1.0, 0.0, 0.0]),
        Err(exactray::InputError::NonFinite { argument: "origin" })
    );
}
