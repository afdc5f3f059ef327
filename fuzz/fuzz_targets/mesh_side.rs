//! `TriangleMesh::side` and `TriangleMesh::all_hits` on fuzzer-shaped
//! closed meshes against the exact oracle by brute force
//! (`exactray_oracle::mesh_oracle`): the side of a point equals the exact
//! winding number's (zero outside, `None` on the surface); the hits of a
//! ray are crossings of their triangles (`t` within `EXACT_T_ULPS` plus
//! the subnormal term), in the exact order, every crossing inside a
//! triangle once (but beyond `f64`'s range, the crate's policy), and, from
//! an origin off the surface, as many as the winding number around the
//! origin, modulo 2 (the ownership rule).
//!
//! A mesh is the octahedron's or the cube's triangles (closed and
//! consistently oriented whatever the vertices) over vertices on a small
//! integer lattice scaled by `2^k` for a `k` from -1000 to 1000 (or raw
//! bit patterns), so it may fold over or cross itself, and two vertices
//! may be merged. The point (the ray's origin) is a lattice point, a
//! vertex, an edge's midpoint or a face point, moved by up to two units
//! of rounding; the ray is aimed at a lattice point, a vertex or an
//! edge's midpoint.
#![no_main]

use arbitrary::{Arbitrary, Unstructured};
use exactray::interval::Interval;
use exactray::query::ray::{EXACT_T_ULPS, Ray};
use exactray::scene::{MeshSide, TriangleMesh};
use exactray::testing::{closed_cube, closed_octahedron, lattice_point};
use exactray_oracle::mesh_oracle::{self, Frac};
use exactray_oracle::oracle;
use glam::DVec3;
use libfuzzer_sys::fuzz_target;

/// Whether `t` is within 4 units of rounding of `exact`, or, subnormal,
/// within three subnormal steps of it rounded (the `2^-1073` term).
fn within_bound(t: f64, exact: &Frac) -> bool {
    oracle::within_units(t, &exact.num, &exact.den, 4)
        || (t.abs() < f64::MIN_POSITIVE
            && (t - oracle::ratio_to_f64(&exact.num, &exact.den)).abs() <= 3.0 * 5e-324)
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(mode) = u8::arbitrary(&mut u) else {
        return;
    };
    let raw = mode % 16 == 15;
    let k = i32::from(i16::arbitrary(&mut u).unwrap_or(0)) % 1001;
    let scale = 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
    let shape = if mode & 16 == 0 {
        closed_octahedron(DVec3::ZERO, 1.0)
    } else {
        closed_cube(0.0, 1.0)
    };
    let triangles = shape.triangles;
    let mut vertices = Vec::with_capacity(shape.vertices.len());
    for _ in 0..shape.vertices.len() {
        let Ok(v) = lattice_point(&mut u, raw, 4.0 * scale) else {
            return;
        };
        vertices.push(v);
    }
    let nv = vertices.len();
    let (Ok(edit), Ok(pick)) = (u8::arbitrary(&mut u), u8::arbitrary(&mut u)) else {
        return;
    };
    if edit & 64 != 0 {
        vertices[usize::from(pick) % nv] = vertices[usize::from(pick / 8) % nv];
    }
    let tri = triangles[usize::from(pick) % triangles.len()].map(|i| vertices[i as usize]);
    let Ok(mut p) = lattice_point(&mut u, raw, 4.0 * scale) else {
        return;
    };
    match edit % 4 {
        0 => p = tri[0],
        // Exact on the lattice: coordinates are multiples of 4 scale.
        1 => p = (tri[0] + tri[1]) * 0.5,
        2 => p = (tri[0] + tri[1] + tri[2] * 2.0) * 0.25,
        _ => {}
    }
    let steps = i8::arbitrary(&mut u).unwrap_or(0) % 3;
    let axis = usize::from(pick) % 3;
    for _ in 0..steps.unsigned_abs() {
        p[axis] = if steps > 0 {
            p[axis].next_up()
        } else {
            p[axis].next_down()
        };
    }
    let Ok(mesh) = TriangleMesh::new(&vertices, &triangles) else {
        return;
    };
    assert!(mesh.is_closed());
    let verts: Vec<[f64; 3]> = vertices.iter().map(|v| v.to_array()).collect();
    let tris: Vec<[usize; 3]> = triangles.iter().map(|t| t.map(|i| i as usize)).collect();
    if !p.is_finite() {
        assert!(mesh.side(p).is_err());
        return;
    }
    let winding = mesh_oracle::winding_number(p.to_array(), &verts, &tris);
    let want = match winding {
        None => MeshSide::OnBoundary,
        Some(0) => MeshSide::Outside,
        Some(_) => MeshSide::Inside,
    };
    assert_eq!(mesh.side(p), Ok(want), "{p:?} in {verts:?}");

    let Ok(target) = lattice_point(&mut u, raw, 4.0 * scale) else {
        return;
    };
    let d = match edit / 4 % 4 {
        0 => tri[1] - p,
        1 => (tri[1] + tri[2]) * 0.5 - p,
        _ => target - p,
    };
    let Ok(ray) = Ray::new(p, d) else {
        return;
    };
    let (o, d) = (ray.origin().to_array(), ray.direction().to_array());
    let (crossings, _) = mesh_oracle::ray_crossings(o, d, &verts, &tris);
    let hits: Vec<_> = mesh.all_hits(&ray, Interval::FORWARD).collect();
    let mut previous: Option<(Frac, usize)> = None;
    for h in &hits {
        let i = h.triangle as usize;
        let Some((t, _, _)) = crossings.iter().find(|c| c.1 == i) else {
            panic!("{ray:?}: triangle {i} is not crossed, in {verts:?}");
        };
        assert!(within_bound(h.hit.t, t), "{ray:?}: t {:e} of {i}", h.hit.t);
        if let Some((f, j)) = &previous {
            assert!(*f < *t || (*f == *t && *j < i), "{ray:?}: order");
        }
        previous = Some((t.clone(), i));
    }
    // A crossing beyond f64's range is no hit (the crate's policy; within
    // a few units of rounding of f64::MAX either is right).
    let required = |t: &Frac| {
        oracle::hit_policy(&t.num, &t.den, 0.0, f64::INFINITY, EXACT_T_ULPS as u32) == Some(true)
    };
    for (t, i, inside) in &crossings {
        let n = hits.iter().filter(|h| h.triangle as usize == *i).count();
        assert!(
            n <= 1 && (n == 1 || !inside || !required(t)),
            "{ray:?}: the crossing of {i} {n} times in {verts:?} {tris:?}"
        );
    }
    if let Some(w) = winding.filter(|_| crossings.iter().all(|c| required(&c.0))) {
        let count = hits.len();
        assert_eq!(
            count % 2,
            w.rem_euclid(2) as usize,
            "{ray:?} in {verts:?}: {count} hits, winding {w}"
        );
    }
});
