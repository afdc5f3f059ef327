//! `TriangleMesh::closest_point` against the exact oracle: the triangle
//! returned is at the exactly least distance, the smallest index among
//! exact ties, and the certified squared distance holds the exact one.
//! Points near edges and vertices, exact ties built on lattices, far
//! points, and every case scaled by `2^k` for `k` in `-1000..1000` and
//! moved near `±f64::MAX`.

use exactray::InputError;
use exactray::scene::{ClosestPoint, TriangleMesh};
use exactray_oracle::closest_oracle::{Closest, closest_triangles, difference, dyadic, product};
use exactray_oracle::mesh_oracle::Frac;
use glam::DVec3;
use proptest::prelude::*;

/// The oracle's answer over every triangle (degenerate ones count: the
/// segments or points they are).
fn oracle(vertices: &[[f64; 3]], tris: &[[u32; 3]], p: [f64; 3]) -> Closest {
    closest_triangles(p, vertices, tris, |_| true)
}

/// `|exact - value| <= error`, exactly.
fn holds(exact: &Frac, value: f64, error: f64) -> bool {
    if !value.is_finite() {
        return error == f64::INFINITY;
    }
    let d = difference(exact, &dyadic(value));
    let abs = Frac::new(d.num.magnitude().clone().into(), d.den);
    abs <= dyadic(error)
}

/// The query's answer for `p` checked against the oracle.
fn check(vertices: &[[f64; 3]], tris: &[[u32; 3]], p: [f64; 3]) -> Option<ClosestPoint> {
    let mesh = TriangleMesh::new(vertices, tris).unwrap();
    let got = mesh.closest_point(p).unwrap();
    let want = oracle(vertices, tris, p);
    match (got, want.least) {
        (None, None) => {}
        (Some(c), Some(least)) => {
            assert_eq!(
                c.triangle as usize, want.ties[0],
                "p {p:?}: got {c:?}, the exact nearest are {:?}",
                want.ties
            );
            assert!(
                holds(&least, c.squared_distance, c.squared_distance_error),
                "p {p:?}: {c:?} misses the exact squared distance {least:?}"
            );
            assert!(c.error.is_finite() && c.point.is_finite());
        }
        (got, least) => panic!("p {p:?}: got {got:?}, oracle {least:?}"),
    }
    got
}

/// `closest_point_within(p, max)` is the plain answer exactly when its
/// exact distance is at most `max`.
fn check_within(vertices: &[[f64; 3]], tris: &[[u32; 3]], p: [f64; 3], max: f64) {
    let mesh = TriangleMesh::new(vertices, tris).unwrap();
    let got = mesh.closest_point_within(p, max).unwrap();
    let want = oracle(vertices, tris, p);
    let m = dyadic(max);
    let inside = want.least.as_ref().is_some_and(|l| *l <= product(&m, &m));
    assert_eq!(got.is_some(), inside, "p {p:?}, max {max}");
    if inside {
        assert_eq!(got, mesh.closest_point(p).unwrap());
    }
}

/// A lattice soup: `n` triangles with small integer vertices, every
/// coordinate times `2^k` plus `shift`.
fn lattice_mesh() -> impl Strategy<Value = (Vec<[f64; 3]>, Vec<[u32; 3]>)> {
    (1usize..8).prop_flat_map(|n| {
        (
            prop::collection::vec(prop::array::uniform3(-4i32..=4), 3 * n),
            Just(n),
        )
            .prop_map(|(coords, n)| {
                let vertices = coords.iter().map(|c| c.map(f64::from)).collect();
                let tris = (0..n as u32)
                    .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
                    .collect();
                (vertices, tris)
            })
    })
}

fn place(v: [f64; 3], k: i32, shift: f64) -> [f64; 3] {
    v.map(|x| x * 2f64.powi(k) + shift)
}

/// Moves a lattice case to scale `2^k` (exact for these small integers
/// and halves at every `k` in `-1000..1000` but the last few, where the
/// subnormal rounding keeps it a valid, if coarser, input).
fn scaled(
    (vertices, _): &(Vec<[f64; 3]>, Vec<[u32; 3]>),
    p: [f64; 3],
    k: i32,
) -> (Vec<[f64; 3]>, [f64; 3]) {
    let vs = vertices.iter().map(|&v| place(v, k, 0.0)).collect();
    (vs, place(p, k, 0.0))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Lattice points (halves included, so some lie exactly on edges,
    /// at vertices and equidistant from several triangles) at every scale.
    #[test]
    fn lattice_soups_at_every_scale(
        mesh in lattice_mesh(),
        p in prop::array::uniform3(-12i32..=12),
        k in -1000i32..1000,
    ) {
        let p = p.map(|x| f64::from(x) / 2.0);
        let (vs, p) = scaled(&mesh, p, k);
        check(&vs, &mesh.1, p);
    }

    /// Triangles sharing vertices and edges (indices into a few lattice
    /// vertices): queries nearest to a shared edge or vertex are exact
    /// ties between neighbours.
    #[test]
    fn shared_edges_and_vertices(
        vertices in prop::collection::vec(prop::array::uniform3(-3i32..=3), 4..7),
        picks in prop::collection::vec(prop::array::uniform3(0usize..7), 1..9),
        p in prop::array::uniform3(-8i32..=8),
        k in -1000i32..1000,
    ) {
        let n = vertices.len();
        let tris: Vec<[u32; 3]> = picks.iter().map(|t| t.map(|i| (i % n) as u32)).collect();
        let vs: Vec<[f64; 3]> = vertices.iter().map(|v| place(v.map(f64::from), k, 0.0)).collect();
        check(&vs, &tris, place(p.map(|x| f64::from(x) / 2.0), k, 0.0));
    }

    /// Points a few units of rounding off vertices and edge midpoints.
    #[test]
    fn near_vertices_and_edges(
        mesh in lattice_mesh(),
        at in 0usize..21,
        off in prop::array::uniform3(-3i32..=3),
        k in -600i32..600,
    ) {
        let (vs, tris) = &mesh;
        let v = vs[at % vs.len()];
        let w = vs[(at + 1) % vs.len()];
        let base = if at % 2 == 0 { v } else { [0, 1, 2].map(|i| (v[i] + w[i]) / 2.0) };
        let p = [0, 1, 2].map(|i| base[i] + f64::from(off[i]) * f64::EPSILON * 4.0);
        let (vs, p) = scaled(&mesh, p, k);
        check(&vs, tris, p);
    }

    /// Far points, huge and tiny meshes, and coordinates near `±f64::MAX`.
    #[test]
    fn far_and_extreme(
        mesh in lattice_mesh(),
        p in prop::array::uniform3(-12i32..=12),
        far in prop::array::uniform3(-1.0f64..1.0),
        k in prop::sample::select(vec![-1074, -1060, -1000, 0, 900, 1000, 1018]),
    ) {
        let p = p.map(f64::from);
        let (vs, p) = scaled(&mesh, p, k);
        check(&vs, &mesh.1, p);
        let far = far.map(|x| x * f64::MAX);
        check(&vs, &mesh.1, far);
    }

    /// The distance bound decides exactly, at and around the exact distance.
    #[test]
    fn within_bounds(
        mesh in lattice_mesh(),
        p in prop::array::uniform3(-12i32..=12),
        max in 0u32..40,
        k in -900i32..900,
    ) {
        let p = p.map(|x| f64::from(x) / 2.0);
        let (vs, p) = scaled(&mesh, p, k);
        let max = f64::from(max) / 4.0 * 2f64.powi(k);
        for m in [max, max.next_down(), max.next_up()] {
            check_within(&vs, &mesh.1, p, m.max(0.0));
        }
    }
}

/// Two triangles mirrored across `x = 0`: every query on that plane is
/// exactly as near to both; the smaller index wins whichever comes first.
#[test]
fn mirrored_ties_take_the_smaller_index() {
    let a = [[1.0, 0.0, 0.0], [3.0, 1.0, 0.0], [2.0, -1.0, 2.0]];
    let b = a.map(|[x, y, z]| [-x, y, z]);
    let vertices: Vec<[f64; 3]> = a.iter().chain(&b).copied().collect();
    for k in [-1000, -500, 0, 500, 1000] {
        let vs: Vec<[f64; 3]> = vertices.iter().map(|&v| place(v, k, 0.0)).collect();
        for tris in [[[0, 1, 2], [3, 4, 5]], [[3, 4, 5], [0, 1, 2]]] {
            for p in [
                [0.0, 0.0, 0.0],
                [0.0, 0.5, 1.0],
                [0.0, -3.0, 7.0],
                [0.0, 1e3, -1e3],
            ] {
                let c = check(&vs, &tris, place(p, k, 0.0)).unwrap();
                assert_eq!(c.triangle, 0);
            }
        }
    }
}

/// Squared distances that round alike but differ exactly.
#[test]
fn near_ties_decided_exactly() {
    let e = f64::EPSILON;
    let vertices = [
        [0.0, 0.0, 1.0 + e],
        [1.0, 0.0, 1.0 + e],
        [0.0, 1.0, 1.0 + e],
        [0.0, 0.0, -1.0],
        [1.0, 0.0, -1.0],
        [0.0, 1.0, -1.0],
    ];
    let tris = [[0, 1, 2], [3, 4, 5]];
    let c = check(&vertices, &tris, [0.25, 0.25, 0.0]).unwrap();
    assert_eq!(c.triangle, 1);
    let c = check(&vertices, &tris, [0.25, 0.25, e]).unwrap();
    assert_eq!(c.triangle, 0);
}

/// A mesh at `f64::MAX` and a query at `-f64::MAX`: squared distances
/// overflow, the choice is still exact.
#[test]
fn overflowing_distances() {
    let m = f64::MAX;
    let vertices = [
        [m, m, m],
        [m * 0.5, m, m],
        [m, m * 0.5, m],
        [m, m, m * 0.75],
        [m * 0.5, m, m * 0.75],
        [m, m * 0.5, m * 0.75],
    ];
    let tris = [[0, 1, 2], [3, 4, 5]];
    let c = check(&vertices, &tris, [-m, -m, -m]).unwrap();
    assert_eq!(c.triangle, 1);
    assert_eq!(c.squared_distance, f64::INFINITY);
}

/// The closest point on a face, an edge and at a vertex.
#[test]
fn closest_points_on_each_feature() {
    let vertices = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]];
    let mesh = TriangleMesh::new(&vertices, &[[0, 1, 2]]).unwrap();
    for (p, want) in [
        ([1.0, 1.0, 3.0], [1.0, 1.0, 0.0]),
        ([3.0, 3.0, 1.0], [2.0, 2.0, 0.0]),
        ([-1.0, -2.0, 5.0], [0.0, 0.0, 0.0]),
    ] {
        let c = mesh.closest_point(p).unwrap().unwrap();
        let off = (c.point - DVec3::from(want)).abs();
        assert!(off.cmple(c.error).all(), "{p:?}: {c:?}");
    }
}

#[test]
fn errors_and_empty_meshes() {
    let vertices = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [2.0, 0.0, 0.0],
    ];
    let mesh = TriangleMesh::new(&vertices, &[[0, 1, 2]]).unwrap();
    for bad in [f64::NAN, f64::INFINITY] {
        assert_eq!(
            mesh.closest_point([0.0, bad, 0.0]),
            Err(InputError::NonFinite { argument: "point" })
        );
    }
    for bad in [f64::NAN, -1.0] {
        assert_eq!(
            mesh.closest_point_within([0.0; 3], bad),
            Err(InputError::InvalidRadius {
                argument: "max_distance"
            })
        );
    }
    let none = TriangleMesh::new(&vertices, &[]).unwrap();
    assert_eq!(none.closest_point([0.0; 3]), Ok(None));
}

/// Degenerate triangles (left out of the hierarchy) count as the segments
/// and points they are, beside ordinary ones.
#[test]
fn degenerate_triangles_count() {
    let vertices = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [2.0, 0.0, 0.0],
        [5.0, 5.0, 5.0],
    ];
    // A segment from (0,0,0) to (2,0,0), a point, and a real triangle.
    let tris = [[0, 1, 3], [4, 4, 4], [0, 1, 2]];
    for k in [-1000, 0, 1000] {
        let vs: Vec<[f64; 3]> = vertices.iter().map(|&v| place(v, k, 0.0)).collect();
        for p in [
            [1.5, -1.0, 0.0],
            [5.0, 5.0, 6.0],
            [0.25, 0.25, 1.0],
            [0.5, 0.0, 0.0],
        ] {
            check(&vs, &tris, place(p, k, 0.0));
        }
        let c = check(&vs, &tris, place([1.5, -1.0, 0.0], k, 0.0)).unwrap();
        assert_eq!(c.triangle, 0);
        let c = check(&vs, &tris, place([5.0, 5.0, 6.0], k, 0.0)).unwrap();
        assert_eq!(c.triangle, 1);
    }
}

#[test]
fn batches_match_single_queries() {
    let mut vertices = Vec::new();
    let mut tris = Vec::new();
    for i in 0..200u32 {
        let x = f64::from(i % 20);
        let y = f64::from(i / 20);
        vertices.extend([[x, y, 0.0], [x + 1.0, y, 0.5], [x, y + 1.0, 1.0]]);
        tris.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    let mesh = TriangleMesh::new(&vertices, &tris).unwrap();
    let points: Vec<[f64; 3]> = (0..300)
        .map(|i| {
            let i = f64::from(i);
            [
                (i * 0.37) % 22.0 - 1.0,
                (i * 0.61) % 12.0 - 1.0,
                (i * 0.13) % 4.0 - 2.0,
            ]
        })
        .collect();
    let mut out = vec![None; points.len()];
    mesh.closest_points(&points, &mut out).unwrap();
    let mut par = vec![None; points.len()];
    mesh.par_closest_points(&points, &mut par).unwrap();
    for (p, (a, b)) in points.iter().zip(out.iter().zip(&par)) {
        assert_eq!(*a, check(&vertices, &tris, *p));
        assert_eq!(a, b);
    }
    assert_eq!(
        mesh.closest_points(&points, &mut out[1..]),
        Err(InputError::LengthMismatch {
            expected: 300,
            got: 299
        })
    );
    let bad = [[0.0, f64::NAN, 0.0]];
    assert_eq!(
        mesh.closest_points(&bad, &mut [None]),
        Err(InputError::NonFinite { argument: "points" })
    );
}
