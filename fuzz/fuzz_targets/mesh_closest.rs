//! `TriangleMesh::closest_point` on small fuzzer-chosen meshes against
//! brute force with the exact oracle (`exactray_oracle::closest_oracle`):
//! the triangle returned is at the exactly least distance, the smallest
//! index among exact ties; the certified squared distance holds the exact
//! one; `closest_point_within` answers exactly when the exact distance is
//! at most its bound.
//!
//! A mesh is 3 to 8 vertices on a small integer lattice scaled by `2^k` for
//! a `k` from -1000 to 1000 (or raw bit patterns), and 1 to 8 triangles
//! over them, so edges and vertices are shared and exact ties are common;
//! the query is a lattice point (halves included), a vertex, an edge's
//! midpoint, or a raw point anywhere up to `±f64::MAX`.
#![no_main]

use arbitrary::{Arbitrary, Unstructured};
use exactray::scene::TriangleMesh;
use exactray::testing::lattice_point;
use exactray_fuzz::LatticeMesh;
use exactray_oracle::closest_oracle::{closest_triangles, difference, dyadic, product};
use exactray_oracle::mesh_oracle::Frac;
use libfuzzer_sys::fuzz_target;

/// `|exact - value| <= error`, exactly (an infinite value needs an
/// infinite error).
fn holds(exact: &Frac, value: f64, error: f64) -> bool {
    if !value.is_finite() {
        return error == f64::INFINITY;
    }
    let d = difference(exact, &dyadic(value));
    Frac::new(d.num.magnitude().clone().into(), d.den) <= dyadic(error)
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Some(LatticeMesh {
        raw,
        scale,
        vertices,
        triangles,
        ..
    }) = LatticeMesh::decode(&mut u)
    else {
        return;
    };
    let nt = triangles.len();
    let (Ok(edit), Ok(pick)) = (u8::arbitrary(&mut u), u8::arbitrary(&mut u)) else {
        return;
    };
    let Ok(mut p) = lattice_point(&mut u, edit % 5 == 4 || raw, 2.0 * scale) else {
        return;
    };
    let tri = triangles[usize::from(pick) % nt].map(|i| vertices[i as usize]);
    match edit % 5 {
        0 => p *= 0.5,
        1 => p = tri[0],
        // Halved first: raw vertices near `f64::MAX` do not overflow.
        2 => p = tri[0] * 0.5 + tri[1] * 0.5,
        _ => {}
    }
    let Ok(mesh) = TriangleMesh::new(&vertices, &triangles) else {
        return;
    };
    // Every triangle counts, degenerate ones as their segments or points.
    let vs: Vec<[f64; 3]> = vertices.iter().map(|v| v.to_array()).collect();
    let want = closest_triangles(p.to_array(), &vs, &triangles, |_| true);
    let got = mesh.closest_point(p).expect("finite point");
    match (got, &want.least) {
        (None, None) => {}
        (Some(c), Some(least)) => {
            assert_eq!(c.triangle as usize, want.ties[0], "{c:?} {want:?}");
            assert!(holds(least, c.squared_distance, c.squared_distance_error));
        }
        _ => panic!("got {got:?}, oracle {want:?}"),
    }
    // A bound at a lattice distance: exact inclusion.
    let max = f64::from(pick % 16) * scale;
    let within = mesh.closest_point_within(p, max).expect("valid bound");
    let m = dyadic(max);
    let inside = want.least.as_ref().is_some_and(|l| *l <= product(&m, &m));
    assert_eq!(within.is_some(), inside);
    if inside {
        assert_eq!(within, got);
    }
});
