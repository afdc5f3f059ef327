//! A `Scene` of meshes and analytic shapes against a loop over every
//! primitive with the same primitive tests: random scenes of every kind of
//! primitive, unit-sized, tiny, huge and far from the origin, rays from
//! outside, from inside solids and from their surfaces, both triangle
//! tests and several ranges; occlusion against the closest hit; the batch
//! forms (sequential and rayon) against one ray at a time; the tie rule;
//! the typed errors; and the testing module's proptest strategies.

use exactray::InputError;
use exactray::interval::Interval;
use exactray::query::ray::{Exact, Ray, RayCast, TriangleTest, Watertight};
use exactray::scene::{
    AnalyticShape, BatchQueries, Primitive, PrimitiveId, Scene, SceneBuilder, SceneHit,
    TriangleMesh,
};
use exactray::shape::{Disk, Plane, Sphere};
use exactray::testing::{
    SCENE_PLACES, SplitMix64, TiledMesh, random_scene, scene_ray, spawned_ray,
};
use glam::DVec3;

/// The closest hit by a loop over every primitive in id order: each
/// mesh's `closest_hit_with::<T>` and each shape's `cast` for the whole
/// range, the least `t`, the lower id on ties (a later primitive must be
/// strictly nearer).
fn brute<T: TriangleTest>(scene: &Scene, ray: &Ray, range: Interval) -> Option<SceneHit> {
    let mut best: Option<SceneHit> = None;
    for (i, p) in scene.primitives().iter().enumerate() {
        let primitive = PrimitiveId(i as u32);
        let hit = match p {
            Primitive::Mesh(mesh) => mesh
                .closest_hit_with::<T>(ray, range)
                .map(|h| SceneHit::from((primitive, h))),
            Primitive::Shape(shape) => shape.cast(ray, range).map(|hit| SceneHit {
                primitive,
                hit,
                triangle: None,
            }),
        };
        if let Some(h) = hit
            && best.is_none_or(|b| h.hit.t < b.hit.t)
        {
            best = Some(h);
        }
    }
    best
}

/// Both triangle tests, the query and its brute force on one ray, and the
/// count of hits.
fn check_ray(scene: &Scene, ray: &Ray, name: &str) -> usize {
    let mut hits = 0;
    for range in [
        Interval::FORWARD,
        Interval::new(0.5, 1.0).unwrap(),
        Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap(),
        Interval::new(-2.0, 0.25).unwrap(),
    ] {
        let want = brute::<Watertight>(scene, ray, range);
        let got = scene.closest_hit(ray, range);
        assert_eq!(
            got,
            want,
            "{name}: {ray:?} {range:?} watertight {:?}",
            scene.primitives()
        );
        assert_eq!(
            scene.occluded(ray, range),
            want.is_some(),
            "{name}: {ray:?}"
        );
        assert_eq!(scene.cast(ray, range), want.map(|h| h.hit), "{name}");
        assert_eq!(scene.cast_t(ray, range), want.map(|h| h.hit.t), "{name}");
        assert_eq!(scene.hits(ray, range), want.is_some(), "{name}");
        // The shadow segment to the ray's point at the range's end.
        let end = ray.at(range.max());
        if let (Ok(blocked), Ok(segment)) = (
            scene.occluded_between(ray.origin(), end),
            Ray::new(ray.origin(), end - ray.origin()),
        ) {
            let unit = Interval::new(0.0, 1.0).unwrap();
            let want = brute::<Watertight>(scene, &segment, unit).is_some();
            assert_eq!(blocked, want, "{name}: segment {ray:?} to {end}");
        }
        let want = brute::<Exact>(scene, ray, range);
        let got = scene.closest_hit_with::<Exact>(ray, range);
        assert_eq!(got, want, "{name}: {ray:?} {range:?} exact");
        assert_eq!(scene.occluded_with::<Exact>(ray, range), want.is_some());
        if let Some(h) = got {
            hits += 1;
            assert_eq!(h.hit.point, ray.at(h.hit.t), "{name}");
            assert!(range.admits(h.hit.t), "{name}");
        }
    }
    hits
}

/// The closest hit equals the loop over every primitive, on random scenes
/// at every place, for rays from outside, from inside and from surfaces.
#[test]
fn closest_hit_equals_brute_force() {
    let mut rng = SplitMix64::new(0x5ce7e_5a9e5);
    for (scale, offset) in SCENE_PLACES {
        let offset = DVec3::new(1.0, -0.7, 0.4) * offset;
        let (mut queries, mut hits) = (0, 0);
        for count in [1usize, 2, 5, 12, 30] {
            for _ in 0..4 {
                let scene = random_scene(&mut rng, count, scale, offset);
                let name = format!("scale {scale:e} offset {offset} count {count}");
                for _ in 0..40 {
                    let Some(ray) = scene_ray(&mut rng, &scene) else {
                        continue;
                    };
                    queries += 4;
                    hits += check_ray(&scene, &ray, &name);
                }
            }
        }
        // Most rays aim at a primitive: the comparison is not vacuous.
        assert!(
            hits * 3 > queries,
            "scale {scale:e} offset {offset}: {hits} of {queries}"
        );
    }
}

/// Secondary rays start within rounding of a surface (where the culling
/// margins matter most): the scene still equals the loop, and occlusion
/// the closest hit.
#[test]
fn spawned_rays_equal_brute_force() {
    let mut rng = SplitMix64::new(0x59a3);
    let mut spawned = 0;
    for (scale, offset) in SCENE_PLACES {
        let offset = DVec3::new(1.0, -0.7, 0.4) * offset;
        for count in [1usize, 4, 16] {
            for _ in 0..10 {
                let scene = random_scene(&mut rng, count, scale, offset);
                for _ in 0..20 {
                    if let Some(s) = spawned_ray(&mut rng, &scene) {
                        spawned += 1;
                        check_ray(&scene, &s.ray, &format!("spawned {scale:e} {offset}"));
                    }
                }
            }
        }
    }
    assert!(spawned > 2000, "{spawned}");
}

/// A scene of one tiled height field (shared edges and vertices) beside
/// spheres: rays at the shared edges hit what a loop over the primitives
/// hits.
#[test]
fn shared_edges_beside_shapes() {
    let mut rng = SplitMix64::new(11);
    let tiled = TiledMesh::new(&mut rng, 10);
    let triangles = tiled.indices();
    let mut builder = SceneBuilder::new();
    builder
        .add(Sphere::new([2.0, 2.0, 3.0], 0.5).unwrap())
        .unwrap();
    builder
        .add(TriangleMesh::new(&tiled.vertices, &triangles).unwrap())
        .unwrap();
    builder
        .add(Sphere::new([7.0, 5.0, 2.0], 1.0).unwrap())
        .unwrap();
    let scene = builder.build();
    let (edges, inner) = (tiled.interior_edges(), tiled.interior_vertices());
    let mut hits = 0;
    for _ in 0..2000 {
        let (o, d, _) = tiled.shared_edge_ray(&mut rng, &edges, &inner);
        let ray = Ray::new(o, d).unwrap();
        hits += check_ray(&scene, &ray, "tiled");
    }
    assert!(hits > 4000, "{hits}");
}

/// Unbounded primitives sit outside the tree and are tested on every
/// query; equal `t` goes to the lower id whichever holds it (a disk in
/// the tree and the plane it lies in, both computing the same quotient).
#[test]
fn unbounded_shapes_and_ties() {
    let plane = Plane::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
    let disk = Disk::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0).unwrap();
    let down = |x: f64| Ray::new([x, 0.3, 2.0], [0.0, 0.0, -1.0]).unwrap();
    for disk_first in [true, false] {
        let mut builder = SceneBuilder::new();
        let (d, p) = if disk_first {
            let d = builder.add(disk).unwrap();
            (d, builder.add(plane).unwrap())
        } else {
            let p = builder.add(plane).unwrap();
            (builder.add(disk).unwrap(), p)
        };
        let scene = builder.build();
        let hit = scene.closest_hit(&down(0.5), Interval::FORWARD).unwrap();
        // Both at t = 2 exactly: the lower id wins.
        assert_eq!(hit.hit.t, 2.0);
        assert_eq!(hit.primitive, d.min(p));
        // Beside the disk only the plane.
        let hit = scene.closest_hit(&down(5.0), Interval::FORWARD).unwrap();
        assert_eq!((hit.primitive, hit.hit.t), (p, 2.0));
        assert!(matches!(
            scene.primitive(p),
            Some(Primitive::Shape(AnalyticShape::Plane(_)))
        ));
    }
    // Two equal spheres: the first added wins, from either side.
    let sphere = Sphere::new([0.0; 3], 1.0).unwrap();
    let mut builder = SceneBuilder::new();
    let a = builder.add(sphere).unwrap();
    builder.add(sphere).unwrap();
    let scene = builder.build();
    for z in [3.0, -3.0] {
        let ray = Ray::new([0.1, 0.2, z], [0.0, 0.01, -z]).unwrap();
        let hit = scene.closest_hit(&ray, Interval::FORWARD).unwrap();
        let want = sphere.cast(&ray, Interval::FORWARD).unwrap();
        assert_eq!((hit.primitive, hit.hit), (a, want));
        assert_eq!(hit.shading_normal(), hit.hit.normal);
        assert_eq!(hit.triangle, None);
    }
}

/// A mesh with vertex normals reports its triangle, barycentrics and
/// shading normal through the scene; a mesh with no hittable triangle
/// keeps its id and is never hit; the empty scene hits nothing.
#[test]
fn mesh_details_and_empty_parts() {
    let vertices = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let normals = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];
    let mesh = TriangleMesh::new(&vertices, &[[0, 1, 2]])
        .unwrap()
        .with_normals(&normals)
        .unwrap();
    let flat = TriangleMesh::new(&vertices, &[[0, 1, 1]]).unwrap();
    let mut builder = SceneBuilder::new();
    let none = builder.add(flat).unwrap();
    let id = builder.add(mesh.clone()).unwrap();
    assert_eq!((none, id), (PrimitiveId(0), PrimitiveId(1)));
    let scene = builder.build();
    assert_eq!(scene.len(), 2);
    let ray = Ray::new([0.25, 0.5, 1.0], [0.0, 0.0, -1.0]).unwrap();
    let want = mesh.closest_hit(&ray, Interval::FORWARD).unwrap();
    let got = scene.closest_hit(&ray, Interval::FORWARD).unwrap();
    assert_eq!(got.primitive, id);
    assert_eq!(got.hit, want.hit);
    let p = got.triangle.unwrap();
    assert_eq!((p.triangle, p.u, p.v), (0, want.u, want.v));
    assert_eq!(got.shading_normal(), want.shading_normal.unwrap());
    assert!(scene.primitive(none).is_some());
    assert!(scene.primitive(PrimitiveId(2)).is_none());
    let empty = SceneBuilder::new().build();
    assert!(empty.is_empty() && empty.closest_hit(&ray, Interval::FORWARD).is_none());
    assert!(!empty.occluded(&ray, Interval::FORWARD));
}

/// Every batch form of `g` on `rays` writes the one-ray answers, in
/// parallel too; the count of hits.
fn check_batches<G>(g: &G, rays: &[Ray]) -> usize
where
    G: BatchQueries + Sync,
    G::Hit: PartialEq + std::fmt::Debug + Send,
{
    let range = Interval::FORWARD;
    let mut hits = vec![None; rays.len()];
    g.closest_hits(rays, range, &mut hits).unwrap();
    let mut blocked = vec![false; rays.len()];
    g.occluded_batch(rays, range, &mut blocked).unwrap();
    for (i, ray) in rays.iter().enumerate() {
        assert_eq!(hits[i], g.closest_hit(ray, range));
        assert_eq!(blocked[i], hits[i].is_some());
    }
    let mut par_hits = vec![None; rays.len()];
    g.par_closest_hits(rays, range, &mut par_hits).unwrap();
    assert_eq!(par_hits, hits);
    let mut par_blocked = vec![false; rays.len()];
    g.par_occluded_batch(rays, range, &mut par_blocked).unwrap();
    assert_eq!(par_blocked, blocked);
    hits.iter().filter(|h| h.is_some()).count()
}

/// The batch forms write the one-ray answers, in parallel too, for a
/// scene and for a mesh.
#[test]
fn batches_equal_one_ray_at_a_time() {
    let mut rng = SplitMix64::new(77);
    let scene = random_scene(&mut rng, 40, 1.0, DVec3::ZERO);
    let rays: Vec<Ray> = (0..3000)
        .filter_map(|_| scene_ray(&mut rng, &scene))
        .collect();
    assert!(check_batches(&scene, &rays) > rays.len() / 3);

    let tiled = TiledMesh::new(&mut rng, 16);
    let mesh = TriangleMesh::new(&tiled.vertices, &tiled.indices()).unwrap();
    let rays: Vec<Ray> = (0..2000)
        .filter_map(|_| {
            let o = DVec3::new(16.0 * rng.next_f64(), 16.0 * rng.next_f64(), 3.0);
            let d = DVec3::new(rng.next_f64() - 0.5, rng.next_f64() - 0.5, -1.0);
            Ray::new(o, d).ok()
        })
        .collect();
    assert!(check_batches(&mesh, &rays) > rays.len() / 2);
}

/// Each typed error of the batch forms and the segment query; nothing is
/// written on a length mismatch.
#[test]
fn bad_input() {
    let mut builder = SceneBuilder::new();
    builder.add(Sphere::new([0.0; 3], 1.0).unwrap()).unwrap();
    let scene = builder.build();
    let rays = [Ray::new([0.0, 0.0, 3.0], [0.0, 0.0, -1.0]).unwrap(); 3];
    let range = Interval::FORWARD;
    let mismatch = Err(InputError::LengthMismatch {
        expected: 3,
        got: 2,
    });
    let mut hits = [None; 2];
    assert_eq!(scene.closest_hits(&rays, range, &mut hits), mismatch);
    assert_eq!(scene.par_closest_hits(&rays, range, &mut hits), mismatch);
    assert_eq!(hits, [None; 2]);
    let mut blocked = [false; 2];
    assert_eq!(scene.occluded_batch(&rays, range, &mut blocked), mismatch);
    assert_eq!(
        scene.par_occluded_batch(&rays, range, &mut blocked),
        mismatch
    );
    assert_eq!(blocked, [false; 2]);
    let mesh = TriangleMesh::new(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], &[[0, 1, 2]]);
    let mesh = mesh.unwrap();
    assert_eq!(mesh.occluded_batch(&rays, range, &mut blocked), mismatch);
    // The segment is the mesh's (one type, its errors tested in
    // tests/scene.rs): its errors reach the scene's caller, and ends
    // farther apart than f64::MAX are answered (tests/whole_range.rs).
    let far = scene.occluded_between([-f64::MAX, 0.0, 0.0], [f64::MAX, 0.0, 0.0]);
    let nan = scene.occluded_between([0.0; 3], [0.0, f64::NAN, 0.0]);
    assert_eq!(far, Ok(true));
    assert_eq!(nan.unwrap_err(), InputError::NonFinite { argument: "q" });
    assert_eq!(scene.occluded_between([0.0; 3], [0.0; 3]), Ok(false));
    assert_eq!(
        scene.occluded_between([0.0, 0.0, 3.0], [0.0, 0.0, -3.0]),
        Ok(true)
    );
    assert_eq!(
        scene.occluded_between([0.0, 0.0, 3.0], [0.0, 0.0, 1.5]),
        Ok(false)
    );
}

/// The proptests of `testing`'s scene strategies (the crate's `proptest`
/// feature: `cargo test --features proptest --test scene_shapes`, which
/// `.ci/run` runs).
#[cfg(feature = "proptest")]
mod strategies {
    use super::*;
    use exactray::shape::CappedCylinder;
    use exactray::testing::{SpawnedRay, scenes_with_spawned_rays, small_scenes, spawned_rays};
    use proptest::prelude::*;
    use std::sync::{Arc, LazyLock};

    /// Whether the spawned ray's next hit `next` is a false self-intersection:
    /// the surface it left, met again where the exact geometry says it cannot
    /// be: a plane, a disk or a mesh triangle is never
    /// met again (the origin is strictly off its plane and the ray moves away
    /// or along it); a convex solid (sphere, cylinder, cone) left outwards
    /// after a hit from outside is never met again (the solid lies behind
    /// the tangent plane the ray leaves).
    fn met_again(s: &SpawnedRay, scene: &Scene, next: Option<SceneHit>) -> bool {
        let Some(next) = next.filter(|n| n.primitive == s.hit.primitive) else {
            return false;
        };
        // A mesh may be met again elsewhere, never on the same triangle.
        let same_surface = match (next.triangle, s.hit.triangle) {
            (Some(a), Some(b)) => a.triangle == b.triangle,
            _ => true,
        };
        same_surface
            && match scene.primitive(s.hit.primitive) {
                Some(Primitive::Mesh(_)) => true,
                Some(Primitive::Shape(shape)) => match shape {
                    AnalyticShape::Disk(_) | AnalyticShape::Plane(_) => true,
                    AnalyticShape::Sphere(_)
                    | AnalyticShape::Cylinder(_)
                    | AnalyticShape::CappedCylinder(_)
                    | AnalyticShape::Cone(_) => {
                        s.reflected() && s.primary.direction().dot(s.hit.hit.normal) < 0.0
                    }
                    AnalyticShape::Quadric(_) => false,
                },
                None => false,
            }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// The strategies: on a small scene, a spawned ray's closest hit is
        /// the loop's, and it never meets again the surface it leaves where
        /// the exact geometry says it cannot.
        #[test]
        fn spawned_rays_never_return((scene, s) in scenes_with_spawned_rays())
        {
            let range = Interval::FORWARD;
            let next = scene.closest_hit(&s.ray, range);
            prop_assert_eq!(next, brute::<Watertight>(&scene, &s.ray, range));
            prop_assert_eq!(scene.occluded(&s.ray, range), next.is_some());
            prop_assert!(!met_again(&s, &scene, next), "{:?} -> {:?}", s, next);
        }
    }

    /// A floor, a ball, a can, a disk and a tiled height field above them.
    fn room() -> Scene {
        let mut rng = SplitMix64::new(21);
        let tiled = TiledMesh::new(&mut rng, 6);
        let vertices: Vec<DVec3> = tiled
            .vertices
            .iter()
            .map(|v| *v + DVec3::new(-3.0, -3.0, 4.0))
            .collect();
        let triangles = tiled.indices();
        let mut builder = SceneBuilder::new();
        builder
            .add(Plane::new([0.0; 3], [0.1, 0.0, 1.0]).unwrap())
            .unwrap();
        builder
            .add(Sphere::new([0.0, 0.0, 1.5], 1.0).unwrap())
            .unwrap();
        builder
            .add(CappedCylinder::new([2.0, 1.0, 0.0], [0.0, 0.3, 2.0], 0.7).unwrap())
            .unwrap();
        builder
            .add(Disk::new([-2.0, 1.0, 1.0], [1.0, 1.0, 1.0], 0.8).unwrap())
            .unwrap();
        builder
            .add(TriangleMesh::new(&vertices, &triangles).unwrap())
            .unwrap();
        builder.build()
    }

    static ROOM: LazyLock<Arc<Scene>> = LazyLock::new(|| Arc::new(room()));

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// `small_scenes` with rays of `scene_ray`: closest hit equals the
        /// loop, occlusion equals a hit.
        #[test]
        fn small_scenes_equal_brute_force(scene in small_scenes(), seed in any::<u64>()) {
            let mut rng = SplitMix64::new(seed);
            for _ in 0..8 {
                if let Some(ray) = scene_ray(&mut rng, &scene) {
                    let next = scene.closest_hit(&ray, Interval::FORWARD);
                    let want = brute::<Watertight>(&scene, &ray, Interval::FORWARD);
                    // The one documented exception random scenes reach
                    // (`Scene`'s docs, "Culling"): the loop's winner is a
                    // cone's lateral hit whose bracket failed (error
                    // infinite), which the scene's box test need not keep
                    // or order as the loop does.
                    let uncertified = want.is_some_and(|w| !w.hit.error.is_finite())
                        && want.is_some_and(|w| matches!(
                            scene.primitive(w.primitive),
                            Some(Primitive::Shape(AnalyticShape::Cone(_)))
                        ));
                    if !uncertified {
                        prop_assert_eq!(next, want);
                        prop_assert_eq!(scene.occluded(&ray, Interval::FORWARD), next.is_some());
                    }
                }
            }
        }

        /// `spawned_rays` on a user's scene: a secondary ray never meets again
        /// the surface it leaves where the exact geometry says it cannot.
        #[test]
        fn spawned_rays_in_a_room(s in spawned_rays(ROOM.clone())) {
            let next = ROOM.closest_hit(&s.ray, Interval::FORWARD);
            prop_assert_eq!(next, brute::<Watertight>(&ROOM, &s.ray, Interval::FORWARD));
            prop_assert!(!met_again(&s, &ROOM, next), "{:?} -> {:?}", s, next);
        }
    }
}
