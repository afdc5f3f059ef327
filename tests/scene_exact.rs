//! The scene's exact rule (`docs/fixture-format.md`'s `ray_mesh`) against the
//! brute-force exact oracle (`exactray_oracle::mesh_oracle`): rays lying in
//! a triangle's plane hit where they enter it, the winner of a near tie is
//! decided by the exact parameters (the lower index on exact ties), and
//! shadow segments are decided on their exact ends. Each test also counts
//! the cases where the rounded rule (the least certified `t`; the ray
//! `p + t fl(q - p)`) gives another answer, so that it is known to be able
//! to fail.

use exactray::interval::Interval;
use exactray::query::ray::{Exact, Ray};
use exactray::scene::TriangleMesh;
use exactray::shape::Triangle;
use exactray::testing::SplitMix64;
use exactray_oracle::mesh_oracle::{self, Frac};
use exactray_oracle::oracle::within_units;
use glam::DVec3;

/// An integer in `[-2^bits, 2^bits]`.
fn int(rng: &mut SplitMix64, bits: u32) -> i64 {
    let span = 2u64 << bits;
    (rng.next_u64() % (span + 1)) as i64 - (1i64 << bits)
}

fn ivec(rng: &mut SplitMix64, bits: u32) -> [i64; 3] {
    [int(rng, bits), int(rng, bits), int(rng, bits)]
}

fn cross(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Integer coordinates times `2^e` (exact: every value below `2^53`).
fn at(p: [i64; 3], e: i32) -> [f64; 3] {
    p.map(|x| x as f64 * 2f64.powi(e))
}

/// Whether the crate's answer is one the oracle allows: the same hit or
/// miss, a listed triangle, `t` within 4 units of rounding of the exact
/// first parameter.
fn agrees(got: Option<(u32, f64)>, want: &Option<(Frac, Vec<usize>)>) -> bool {
    match (got, want) {
        (None, None) => true,
        (Some((i, t)), Some((exact, on))) => {
            on.contains(&(i as usize)) && within_units(t, &exact.num, &exact.den, 4)
        }
        _ => false,
    }
}

fn closest_exact(mesh: &TriangleMesh, ray: &Ray) -> Option<(u32, f64)> {
    mesh.closest_hit_with::<Exact>(ray, Interval::FORWARD)
        .map(|h| (h.triangle, h.hit.t))
}

/// Rays exactly in the plane of a lattice triangle: from anywhere in the
/// plane (entering through an edge, or passing by), from inside or on the
/// boundary (t = 0), along an edge's line and through a vertex; against
/// the oracle, single triangles (`cast_exact_closed`) and fans of coplanar
/// triangles sharing edges (the mesh's closest hit).
#[test]
fn coplanar_rays_enter_the_closed_triangle() {
    let mut rng = SplitMix64::new(0xc0_91a);
    let (mut hits, mut misses, mut at_start, mut shared) = (0, 0, 0, 0);
    for case in 0..3000 {
        let e = (rng.next_u64() % 60) as i32 - 30;
        let base = ivec(&mut rng, 20);
        let (u, v) = (ivec(&mut rng, 6), ivec(&mut rng, 6));
        if cross(u, v) == [0; 3] {
            continue;
        }
        // A fan of four triangles around `base` in the plane of u, v (the
        // square base +- 8u +- 8v, split at its centre): shared edges.
        let p = |a: i64, b: i64| -> [i64; 3] {
            core::array::from_fn(|k| base[k] + 8 * (a * u[k] + b * v[k]))
        };
        let vertices = [p(0, 0), p(1, -1), p(1, 1), p(-1, 1), p(-1, -1)].map(|x| at(x, e));
        let triangles = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]];
        let n = if case % 3 == 0 { 1 } else { 4 };
        let tris = &triangles[..n];
        // The origin: a lattice point of the plane (units of u / 8, v / 8),
        // sometimes a vertex; the direction in the plane.
        let (a, b) = (int(&mut rng, 4), int(&mut rng, 4));
        let o: [i64; 3] = if case % 7 == 0 {
            p(1, 1)
        } else {
            core::array::from_fn(|k| base[k] + a * u[k] + b * v[k])
        };
        let (da, db) = (int(&mut rng, 3), int(&mut rng, 3));
        let d: [i64; 3] = core::array::from_fn(|k| da * u[k] + db * v[k]);
        if d == [0; 3] {
            continue;
        }
        let (o, d) = (at(o, e), at(d, e + (rng.next_u64() % 9) as i32 - 4));
        let Ok(ray) = Ray::new(o, d) else { continue };
        let want = mesh_oracle::ray_mesh(
            o,
            d,
            &vertices,
            &tris
                .iter()
                .map(|t| t.map(|i| i as usize))
                .collect::<Vec<_>>(),
        );
        let mesh = TriangleMesh::new(&vertices, tris).unwrap();
        let got = closest_exact(&mesh, &ray);
        assert!(
            agrees(got, &want),
            "case {case}: {o:?} {d:?}: {got:?} vs {want:?}"
        );
        assert_eq!(
            mesh.occluded_with::<Exact>(&ray, Interval::FORWARD),
            want.is_some()
        );
        if n == 1 {
            let tri = Triangle::new(vertices[0], vertices[1], vertices[2]).unwrap();
            let hit = tri.cast_exact_closed(&ray, Interval::FORWARD);
            assert_eq!(hit.map(|h| (0, h.t)), got, "case {case}");
            if let Some(h) = hit {
                assert!(h.u >= 0.0 && h.v >= 0.0 && h.u + h.v <= 1.0 + 4.0 * f64::EPSILON);
            }
            // The single-triangle test of old calls every such ray a miss.
            assert!(tri.cast_exact(&ray, Interval::FORWARD).is_none());
        }
        match &want {
            None => misses += 1,
            Some((t, on)) => {
                hits += 1;
                at_start += (t.num == 0.into()) as u32;
                shared += (on.len() >= 2) as u32;
            }
        }
    }
    assert!(
        hits > 500 && misses > 300 && at_start > 100 && shared > 100,
        "{hits} {misses} {at_start} {shared}"
    );
}

/// Two triangles whose exact parameters differ by a few units of
/// rounding or not at all: a triangle and its copy with every vertex moved
/// by 1-2 ulps, a triangle and its exact duplicate, and two triangles
/// sharing an edge the ray passes through; in both index orders. The
/// winner must contain the exact first point; on exact ties it is the
/// lower index.
#[test]
fn near_ties_are_decided_exactly() {
    let mut rng = SplitMix64::new(0x7_1e5);
    let (mut decided, mut rounded_wrong, mut ties) = (0, 0, 0);
    let unit = |rng: &mut SplitMix64| rng.next_f64() * 2.0 - 1.0;
    let step = |x: f64, k: i64| {
        let mut y = x;
        for _ in 0..k.abs() {
            y = if k > 0 { y.next_up() } else { y.next_down() };
        }
        y
    };
    for case in 0..6000 {
        let scale = [1.0, 1e-20, 1e20, 1e6][case % 4];
        let offset = if case % 8 == 7 { 1e7 } else { 0.0 };
        let v = |rng: &mut SplitMix64| {
            DVec3::new(unit(rng), unit(rng), unit(rng)) * scale + DVec3::splat(offset)
        };
        let a = [v(&mut rng), v(&mut rng), v(&mut rng)];
        let kind = case % 3;
        let b = match kind {
            // Every coordinate moved by -2..2 ulps.
            0 => a.map(|p| {
                DVec3::new(
                    step(p.x, int(&mut rng, 1)),
                    step(p.y, int(&mut rng, 1)),
                    step(p.z, int(&mut rng, 1)),
                )
            }),
            // An exact duplicate (vertices rotated).
            1 => [a[1], a[2], a[0]],
            // Sharing the edge a0 a1, the third vertex elsewhere.
            _ => [a[1], a[0], v(&mut rng)],
        };
        // Aimed at a point of a (for kind 2, of the shared edge: its
        // midpoint is rounded, so the ray passes near it).
        let (w1, w2) = if kind == 2 {
            (0.5, 0.0)
        } else {
            let w1 = rng.next_f64();
            (w1, rng.next_f64() * (1.0 - w1))
        };
        let target = a[0] + (a[1] - a[0]) * w1 + (a[2] - a[0]) * w2;
        let origin = target + v(&mut rng) * 3.0 - DVec3::splat(offset) * 3.0;
        let Ok(ray) = Ray::new(origin, target - origin) else {
            continue;
        };
        let swap = case % 2 == 1;
        let vertices = if swap {
            [b[0], b[1], b[2], a[0], a[1], a[2]]
        } else {
            [a[0], a[1], a[2], b[0], b[1], b[2]]
        };
        let Ok(mesh) = TriangleMesh::new(&vertices, &[[0, 1, 2], [3, 4, 5]]) else {
            continue;
        };
        let verts = vertices.map(|p| p.to_array());
        let want = mesh_oracle::ray_mesh(
            ray.origin().to_array(),
            ray.direction().to_array(),
            &verts,
            &[[0, 1, 2], [3, 4, 5]],
        );
        let got = closest_exact(&mesh, &ray);
        assert!(
            agrees(got, &want),
            "case {case}: {ray:?}: {got:?} vs {want:?}"
        );
        let Some((_, on)) = &want else { continue };
        decided += 1;
        if on.len() == 2 {
            ties += 1;
            assert_eq!(got.map(|g| g.0), Some(0), "case {case}: an exact tie");
        }
        // The rounded rule: the least certified t, the lower index on
        // equal ones.
        let tri = |i: usize| mesh.triangle(i).unwrap();
        let ts = [0, 1].map(|i| {
            tri(i)
                .cast_exact_closed(&ray, Interval::FORWARD)
                .map(|h| h.t)
        });
        let rounded = match ts {
            [Some(x), Some(y)] => Some(if y < x { 1 } else { 0 }),
            [Some(_), None] => Some(0),
            [None, Some(_)] => Some(1),
            [None, None] => None,
        };
        if rounded.is_some_and(|r| !on.contains(&r)) {
            rounded_wrong += 1;
        }
    }
    assert!(decided > 3000 && ties > 1000, "{decided} {ties}");
    // The exact order mattered: the least certified t names a triangle
    // that does not contain the exact first point.
    assert!(rounded_wrong > 20, "{rounded_wrong}");
}

/// Segments from far above a tiled square to just above, on or just
/// below it (1-3 ulps), and segments in its plane ending just short of,
/// on or just past an edge: the exact query decides on the exact end `q`
/// (against the oracle), where the ray `p + t fl(q - p)` may overshoot.
#[test]
fn shadow_segments_end_exactly_at_q() {
    let mut rng = SplitMix64::new(0x5e9);
    let (mut blocked, mut free, mut rounded_wrong) = (0, 0, 0);
    for case in 0..4000 {
        let z0 = [0.1, 1e-3, 3.0, 1e5][case % 4];
        let vertices = [
            [0.0, 0.0, z0],
            [1.0, 0.0, z0],
            [1.0, 1.0, z0],
            [0.0, 1.0, z0],
        ];
        let triangles = [[0, 1, 2], [0, 2, 3]];
        let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
        let (x, y) = (rng.next_f64(), rng.next_f64());
        let k = (rng.next_u64() % 7) as i64 - 3;
        let (p, q) = if case % 3 == 0 {
            // In the plane, ending near the edge x = 1.
            let mut qx = 1.0;
            for _ in 0..k.abs() {
                qx = if k > 0 {
                    f64::next_up(qx)
                } else {
                    f64::next_down(qx)
                };
            }
            ([3.0 + 7.0 * x, y, z0], [qx, y, z0])
        } else {
            let mut qz = z0;
            for _ in 0..k.abs() {
                qz = if k > 0 { qz.next_up() } else { qz.next_down() };
            }
            let p = [
                x * 3.0 - 1.0,
                y * 3.0 - 1.0,
                z0 + 1e3 * (1.0 + rng.next_f64()),
            ];
            (p, [x, y, qz])
        };
        let tris = triangles.map(|t| t.map(|i| i as usize));
        let want = mesh_oracle::segment_mesh(p, q, &vertices, &tris);
        let got = mesh.occluded_between_with::<Exact>(p, q).unwrap();
        assert_eq!(got, want, "case {case}: {p:?} {q:?}");
        let tri = |i: usize| mesh.triangle(i).unwrap();
        assert_eq!(
            want,
            tri(0).meets_segment_exact(p, q) || tri(1).meets_segment_exact(p, q)
        );
        // The ray p + t fl(q - p) for t in [0, 1], decided exactly.
        let ray = Ray::new(p, DVec3::from(q) - DVec3::from(p)).unwrap();
        let unit = Interval::new(0.0, 1.0).unwrap();
        let rounded = (0..2).any(|i| {
            let t = tri(i).cast_exact_closed(&ray, unit);
            t.is_some()
        });
        rounded_wrong += (rounded != want) as u32;
        if want {
            blocked += 1;
        } else {
            free += 1;
        }
    }
    assert!(blocked > 1000 && free > 1000, "{blocked} {free}");
    assert!(rounded_wrong > 20, "{rounded_wrong}");
}

/// Fuzzer findings (`fuzz/fuzz_targets/ray_mesh.rs`), kept as exact bit
/// patterns and checked against the oracle.
#[test]
fn fuzz_findings() {
    // A subnormal direction on a mesh spanning 1e307: the hierarchy's frame
    // scaled its parameters by 2^-2046, where `scale_pow2`'s factors are
    // not both normal, and the range's end became NaN: the box was culled
    // and the ray starting on the triangle's vertex missed.
    let vertices = [
        [0x6968fffffdfffaff, 0x0000000000000050, 0x0000000000000000],
        [0x313131007edd0000, 0x3131313131313131, 0xddff313131313131],
        [0xffbf006c09533dff, 0xfaff5069976971c6, 0x07077b0000000080],
    ]
    .map(|p: [u64; 3]| p.map(f64::from_bits));
    let triangles = [[2, 1, 0], [1, 2, 0], [1, 2, 0]];
    let origin = vertices[1];
    let direction =
        [0x000097a7429f0100, 0x0000000000000000, 0x0000000000000000].map(f64::from_bits);
    let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
    let ray = Ray::new(origin, direction).unwrap();
    let tris: Vec<[usize; 3]> = triangles.iter().map(|t| t.map(|i| i as usize)).collect();
    let want = mesh_oracle::ray_mesh(origin, direction, &vertices, &tris);
    assert!(want.is_some());
    assert!(agrees(closest_exact(&mesh, &ray), &want), "{want:?}");
    assert!(mesh.occluded_with::<Exact>(&ray, Interval::FORWARD));
}
