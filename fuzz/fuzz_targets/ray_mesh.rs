//! The scene's exact queries on small fuzzer-chosen meshes against brute
//! force with the exact oracle (`exactray_oracle::mesh_oracle`, `docs/fixture-format.md`'s
//! `ray_mesh` rule): the exact closest hit (hit or miss, a triangle
//! containing the exact first point, `t` within `EXACT_T_ULPS`), exact
//! occlusion, and the exact shadow segment (its far end drawn up to
//! `f64::MAX` of either sign at times); the watertight queries must not
//! panic, must report only admitted `t` and answer every finite segment.
//!
//! A mesh is 3 to 8 vertices on a small integer lattice scaled by `2^k` for
//! a `k` from -1000 to 1000 (or raw bit patterns), and 1 to 8 triangles
//! over them, so edges and vertices are shared; then edited towards
//! degeneracy: two vertices merged, the ray aimed exactly at a vertex or
//! an edge's midpoint, or laid in a triangle's plane. On the lattice, the
//! watertight default must answer the same hit or miss as on the same
//! configuration at scale 1.
#![no_main]

use arbitrary::{Arbitrary, Unstructured};
use exactray::interval::Interval;
use exactray::query::ray::{EXACT_T_ULPS, Exact, Ray};
use exactray::scene::TriangleMesh;
use exactray::testing::{finite_f64_from_bits, lattice_point};
use exactray_fuzz::LatticeMesh;
use exactray_oracle::mesh_oracle;
use exactray_oracle::oracle;
use glam::DVec3;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Some(LatticeMesh {
        raw,
        k,
        scale,
        mut vertices,
        triangles,
    }) = LatticeMesh::decode(&mut u)
    else {
        return;
    };
    let (nv, nt) = (vertices.len(), triangles.len());
    let (Ok(edit), Ok(pick)) = (u8::arbitrary(&mut u), u8::arbitrary(&mut u)) else {
        return;
    };
    let (Ok(mut o), Ok(mut d)) = (
        lattice_point(&mut u, raw, 2.0 * scale),
        lattice_point(&mut u, raw, 2.0 * scale),
    ) else {
        return;
    };
    let tri = triangles[usize::from(pick) % nt].map(|i| vertices[i as usize]);
    match edit % 6 {
        // Two vertices merged.
        0 => vertices[usize::from(pick) % nv] = vertices[usize::from(pick / 8) % nv],
        // Aimed exactly at a vertex.
        1 => d = tri[0] - o,
        // Aimed at an edge's midpoint (exact on the lattice: coordinates
        // are even multiples of the scale).
        2 => d = (tri[0] + tri[1]) * 0.5 - o,
        // In the triangle's plane: from a lattice point of it, along it.
        3 => {
            let (a, b) = (
                i8::arbitrary(&mut u).unwrap_or(1),
                i8::arbitrary(&mut u).unwrap_or(1),
            );
            let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
            o = tri[0] + e1 * f64::from(a) / 8.0 + e2 * f64::from(b) / 8.0;
            d = e1 * f64::from(b % 5) + e2 * f64::from(a % 7);
        }
        // Starting exactly at a vertex.
        4 => o = tri[usize::from(pick) % 3],
        _ => {}
    }
    let Ok(mesh) = TriangleMesh::new(&vertices, &triangles) else {
        return;
    };
    let Ok(ray) = Ray::new(o, d) else {
        return;
    };
    let verts: Vec<[f64; 3]> = vertices.iter().map(|v| v.to_array()).collect();
    // The mesh leaves out triangles so thin that their rounded normal
    // vanishes (never hit; raw bit patterns make them): so does the oracle.
    let tris: Vec<[usize; 3]> = (0..nt)
        .filter(|&i| mesh.triangle(i).is_some_and(|t| t.normal() != DVec3::ZERO))
        .map(|i| triangles[i].map(|k| k as usize))
        .collect();
    let index: Vec<usize> = (0..nt)
        .filter(|&i| mesh.triangle(i).is_some_and(|t| t.normal() != DVec3::ZERO))
        .collect();
    let (ro, rd) = (ray.origin().to_array(), ray.direction().to_array());
    let want = mesh_oracle::ray_mesh(ro, rd, &verts, &tris);
    let got = mesh.closest_hit_with::<Exact>(&ray, Interval::FORWARD);
    match (&want, got) {
        (None, None) => {}
        (Some((t, on)), Some(h)) => {
            let on: Vec<usize> = on.iter().map(|&k| index[k]).collect();
            assert!(
                on.contains(&(h.triangle as usize)),
                "{ray:?}: {h:?}, want {on:?}"
            );
            assert!(
                h.hit.t.abs() < f64::MIN_POSITIVE
                    || oracle::within_units(h.hit.t, &t.num, &t.den, EXACT_T_ULPS as u32),
                "{ray:?}: t = {:e}",
                h.hit.t
            );
        }
        // A first parameter beyond f64's range is no hit (the crate's
        // policy); within a few ulps of f64::MAX either is right.
        (Some((t, _)), None) => {
            assert!(
                oracle::hit_policy(&t.num, &t.den, 0.0, f64::INFINITY, EXACT_T_ULPS as u32)
                    != Some(true),
                "{ray:?}: a miss, want {want:?}"
            );
        }
        (None, Some(h)) => panic!("{ray:?}: {h:?}, want a miss"),
    }
    let occluded = mesh.occluded_with::<Exact>(&ray, Interval::FORWARD);
    assert_eq!(occluded, got.is_some(), "{ray:?}");
    for hit in [mesh.closest_hit(&ray, Interval::FORWARD)]
        .into_iter()
        .flatten()
    {
        assert!(Interval::FORWARD.admits(hit.hit.t), "{hit:?}");
    }
    let _ = mesh.occluded(&ray, Interval::FORWARD);
    // On the lattice the configuration is an exact multiple of the scale:
    // the watertight default answers the same hit or miss as on the
    // configuration at scale 1, whose values stay where its ordinary
    // evaluation answers (its rescaled one must not change an answer).
    if !raw {
        let unit = |p: DVec3| p / scale;
        if let (Ok(m1), Ok(r1)) = (
            TriangleMesh::new(
                &vertices.iter().map(|&p| unit(p)).collect::<Vec<_>>(),
                &triangles,
            ),
            Ray::new(unit(o), unit(d)),
        ) {
            let at_scale = mesh.closest_hit(&ray, Interval::FORWARD).is_some();
            let at_one = m1.closest_hit(&r1, Interval::FORWARD).is_some();
            assert_eq!(at_scale, at_one, "{ray:?} at 2^{k}");
        }
    }
    // The segment from o to o + d (rounded: the segment is from o to
    // whatever q is), or to a far end drawn over the whole range, up to
    // f64::MAX of either sign (ends farther apart than f64::MAX among them).
    let q = match u8::arbitrary(&mut u).unwrap_or(0) % 4 {
        0 => {
            let c = <[i8; 3]>::arbitrary(&mut u).unwrap_or([0; 3]);
            DVec3::from_array(c.map(|x| f64::MAX * (f64::from(x) / 127.0)))
        }
        1 => DVec3::from_array(
            <[u64; 3]>::arbitrary(&mut u)
                .unwrap_or([0; 3])
                .map(finite_f64_from_bits),
        ),
        _ => o + d,
    };
    if q.is_finite() && q != o {
        let blocked = mesh_oracle::segment_mesh(o.to_array(), q.to_array(), &verts, &tris);
        assert_eq!(
            mesh.occluded_between_with::<Exact>(o, q),
            Ok(blocked),
            "{o:?} {q:?}"
        );
        assert!(mesh.occluded_between(o, q).is_ok(), "{o:?} {q:?}");
    }
});
