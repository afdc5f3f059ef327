//! `TriangleMesh::side` and `TriangleMesh::all_hits` on closed meshes (an
//! octahedron, a cube, and a cube with a cube-shaped hollow), against the
//! exact oracle by brute force over every triangle
//! (`exactray_oracle::mesh_oracle`: the winding number by an independent
//! generic ray, the crossings as fractions): points exactly on vertices,
//! edges and faces, one or two units of rounding off them, on a lattice
//! and far away, all scaled by `2^k` for `k` in `-1000..1000`; rays aimed
//! exactly at shared vertices and edges.

use core::ops::ControlFlow;
use exactray::InputError;
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::scene::{HitCount, MeshHit, MeshSide, TriangleMesh};
use exactray::testing::{SceneMesh, closed_cube, closed_octahedron};
use exactray_oracle::mesh_oracle::{self, Frac};
use exactray_oracle::oracle;
use glam::DVec3;
use proptest::prelude::*;

/// A closed mesh's vertices and triangles (counterclockwise seen from
/// outside the solid).
type Solid = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// `mesh`'s vertices and triangles as plain arrays.
fn plain(mesh: SceneMesh) -> Solid {
    (
        mesh.vertices.iter().map(|p| p.to_array()).collect(),
        mesh.triangles,
    )
}

/// The octahedron `|x| + |y| + |z| <= 4`.
fn octahedron() -> Solid {
    plain(closed_octahedron(DVec3::ZERO, 4.0))
}

/// The cube `[lo, hi]^3`, its triangles reversed when `inward`.
fn cube(lo: f64, hi: f64, inward: bool) -> Solid {
    let (v, mut t) = plain(closed_cube(lo, hi));
    if inward {
        for tri in &mut t {
            tri.swap(1, 2);
        }
    }
    (v, t)
}

/// The cube `[-2, 4]^3` with the hollow `[0, 2]^3` (its triangles facing
/// into the hollow): the winding number is 1 in the shell, 0 in the
/// hollow.
fn shell() -> Solid {
    let (mut v, mut t) = cube(-2.0, 4.0, false);
    let (inner_v, inner_t) = cube(0.0, 2.0, true);
    v.extend(inner_v);
    t.extend(inner_t.iter().map(|tri| tri.map(|i| i + 8)));
    (v, t)
}

/// The cube `[0, 2]^3` with its edge from vertex 0 to vertex 1 split at
/// its midpoint (vertex 8) in one of its two triangles, `0 1 5`, and the
/// degenerate triangle `0 1 8` closing the gap: closed, with a degenerate
/// triangle on the surface.
fn split_cube() -> Solid {
    let (mut v, mut t) = cube(0.0, 2.0, false);
    v.push([1.0, 0.0, 0.0]);
    let at = t
        .iter()
        .position(|tri| *tri == [0, 1, 5])
        .expect("the face");
    t[at] = [0, 8, 5];
    t.extend([[8, 1, 5], [0, 1, 8]]);
    (v, t)
}

/// A sliver tetrahedron whose face `a c b` (the first triangle) is so thin
/// that its rounded normal vanishes, `c` a subnormal step off the line of
/// `a b`: the hierarchy leaves it out, `side` and `all_hits` do not.
fn thin_tetrahedron() -> Solid {
    let v = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [2.0, f64::from_bits(1), 0.0],
        [1.0, 1.0, 1.0],
    ];
    (v, vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]])
}

fn solid(which: usize) -> Solid {
    match which {
        0 => octahedron(),
        1 => cube(0.0, 2.0, false),
        2 => shell(),
        3 => split_cube(),
        _ => thin_tetrahedron(),
    }
}

/// `x * 2^k`, exact for `k` in `-1000..1000` and the small coordinates
/// here (two steps, each a normal power of two).
fn scaled(x: [f64; 3], k: i32) -> [f64; 3] {
    x.map(|c| c * 2f64.powi(k / 2) * 2f64.powi(k - k / 2))
}

/// A point of class `kind` for `solid`: a vertex, an edge's midpoint, a
/// face point `(a + b + 2c) / 4`, a lattice point in `[-6, 6]^3` with
/// half steps, or a lattice point times `2^40`; `pick` chooses among them.
fn point(solid: &Solid, kind: u8, pick: [i8; 3]) -> [f64; 3] {
    let (v, t) = solid;
    let tri = t[pick[0].unsigned_abs() as usize % t.len()];
    let corner = |i: usize| v[tri[i % 3] as usize];
    let j = pick[1].unsigned_abs() as usize;
    match kind % 5 {
        0 => corner(j),
        1 => {
            let (a, b) = (corner(j), corner(j + 1));
            [0, 1, 2].map(|k| (a[k] + b[k]) / 2.0)
        }
        2 => {
            let (a, b, c) = (corner(j), corner(j + 1), corner(j + 2));
            [0, 1, 2].map(|k| (a[k] + b[k] + 2.0 * c[k]) / 4.0)
        }
        3 => pick.map(|x| f64::from(x % 13) / 2.0),
        _ => pick.map(|x| f64::from(x) * 2f64.powi(40)),
    }
}

/// `x` moved by `steps` units of rounding (signed) along `axis`.
fn nudged(mut x: [f64; 3], axis: usize, steps: i8) -> [f64; 3] {
    for _ in 0..steps.unsigned_abs() {
        x[axis] = if steps > 0 {
            x[axis].next_up()
        } else {
            x[axis].next_down()
        };
    }
    x
}

fn mesh_of(solid: &Solid, k: i32) -> (TriangleMesh, Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let v: Vec<[f64; 3]> = solid.0.iter().map(|&p| scaled(p, k)).collect();
    let t: Vec<[usize; 3]> = solid.1.iter().map(|t| t.map(|i| i as usize)).collect();
    let mesh = TriangleMesh::new(&v, &solid.1).expect("finite vertices");
    (mesh, v, t)
}

/// The oracle's answer for `side`.
fn oracle_side(p: [f64; 3], v: &[[f64; 3]], t: &[[usize; 3]]) -> MeshSide {
    match mesh_oracle::winding_number(p, v, t) {
        None => MeshSide::OnBoundary,
        Some(0) => MeshSide::Outside,
        Some(_) => MeshSide::Inside,
    }
}

/// Whether `t` is within `EXACT_T_ULPS` (4) units of rounding of `exact`
/// plus `2^-1073` (the bound's term for subnormal results): the second
/// checked, where `t` is subnormal, against `exact` rounded (within one
/// subnormal step), so within three steps.
fn within_bound(t: f64, exact: &Frac) -> bool {
    let step = f64::from_bits(1);
    oracle::within_units(t, &exact.num, &exact.den, 4)
        || (t.abs() < f64::MIN_POSITIVE
            && (t - oracle::ratio_to_f64(&exact.num, &exact.den)).abs() <= 3.0 * step)
}

/// `all_hits` of the ray against the oracle: every hit is a crossing of
/// its triangle (its `t` within 4 units of rounding of the exact one),
/// the hits in the exact order of their crossings, every crossing inside
/// a triangle reported, and, with the origin off the surface, as many
/// hits as the winding number around the origin, modulo 2. The buffer and
/// visitor forms agree with the iterator.
fn check_all_hits(
    mesh: &TriangleMesh,
    v: &[[f64; 3]],
    t: &[[usize; 3]],
    o: [f64; 3],
    d: [f64; 3],
) -> Result<usize, TestCaseError> {
    let Ok(ray) = Ray::new(o, d) else {
        return Ok(0);
    };
    let hits: Vec<MeshHit> = mesh.all_hits(&ray, Interval::FORWARD).collect();
    let (crossings, _) = mesh_oracle::ray_crossings(o, d, v, t);
    let mut previous: Option<(Frac, usize)> = None;
    for h in &hits {
        let i = h.triangle as usize;
        let c = crossings.iter().find(|c| c.1 == i);
        prop_assert!(c.is_some(), "{o:?} {d:?}: triangle {i} is not crossed");
        let (frac, _, _) = c.unwrap();
        prop_assert!(
            within_bound(h.hit.t, frac),
            "{o:?} {d:?}: t {} of triangle {i}",
            h.hit.t
        );
        if let Some((f, j)) = &previous {
            prop_assert!(*f < *frac || (*f == *frac && *j < i), "{o:?} {d:?}: order");
        }
        previous = Some((frac.clone(), i));
    }
    for (_, i, inside) in &crossings {
        if *inside {
            let n = hits.iter().filter(|h| h.triangle as usize == *i).count();
            prop_assert_eq!(n, 1, "{:?} {:?}: crossing of {}", o, d, i);
        }
    }
    if let Some(w) = mesh_oracle::winding_number(o, v, t) {
        prop_assert_eq!(
            hits.len() % 2,
            w.rem_euclid(2) as usize,
            "{:?} {:?}: {} hits, winding {}",
            o,
            d,
            hits.len(),
            w
        );
    }
    let none = mesh.all_hits_into(&ray, Interval::FORWARD, &mut []);
    let want = HitCount {
        count: 0,
        truncated: !hits.is_empty(),
    };
    prop_assert_eq!(none, want);
    if let Some(&first) = hits.first() {
        let mut buffer = [first; 2];
        let written = mesh.all_hits_into(&ray, Interval::FORWARD, &mut buffer);
        let want = HitCount {
            count: hits.len().min(2),
            truncated: hits.len() > 2,
        };
        prop_assert_eq!(written, want);
        prop_assert_eq!(&buffer[..written.count], &hits[..written.count]);
    }
    let visited = mesh.visit_all_hits(&ray, Interval::FORWARD, |_| ControlFlow::Break(()));
    prop_assert_eq!(visited, hits.len().min(1));
    Ok(hits.len())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(384))]

    /// `side` equals the exact winding number's answer at every scale, on
    /// and near vertices, edges and faces, and away from the mesh.
    #[test]
    fn side_is_exact(
        which in 0usize..5,
        kind in 0u8..5,
        pick in any::<[i8; 3]>(),
        axis in 0usize..3,
        steps in -2i8..=2,
        k in -1000i32..1000,
    ) {
        let solid = solid(which);
        let (mesh, v, t) = mesh_of(&solid, k);
        prop_assert!(mesh.is_closed());
        let p = nudged(scaled(point(&solid, kind, pick), k), axis, steps);
        // Far points at the largest scales overflow.
        prop_assume!(p.iter().all(|x| x.is_finite()));
        prop_assert_eq!(mesh.side(p), Ok(oracle_side(p, &v, &t)), "{:?} at 2^{}", p, k);
    }

    /// `all_hits` against the oracle for rays from lattice, surface and
    /// nudged points aimed exactly at vertices, edge midpoints and face
    /// points (and lattice points), at every scale.
    #[test]
    fn all_hits_are_exact(
        which in 0usize..5,
        kinds in any::<[u8; 2]>(),
        picks in any::<[[i8; 3]; 2]>(),
        axis in 0usize..3,
        steps in -2i8..=2,
        k in -1000i32..1000,
    ) {
        let solid = solid(which);
        let (mesh, v, t) = mesh_of(&solid, k);
        let origin = point(&solid, kinds[0], picks[0]);
        let target = point(&solid, kinds[1] % 4, picks[1]);
        let d = [0, 1, 2].map(|i| target[i] - origin[i]);
        let o = nudged(scaled(origin, k), axis, steps);
        prop_assume!(o.iter().chain(&d).all(|x| x.is_finite()));
        check_all_hits(&mesh, &v, &t, o, scaled(d, k))?;
    }
}

/// Rays along an axis through two opposite vertices of the octahedron
/// (four faces meet at each), along a face diagonal through two edges of
/// the cube, in the plane of the cube's bottom face, and touching the
/// octahedron's vertex from outside: one crossing where the surface is
/// crossed, none or two where it is touched, at every scale.
#[test]
fn rays_through_shared_vertices_and_edges() {
    for k in [-1000, -500, -1, 0, 1, 500, 999] {
        let oct = octahedron();
        let (mesh, v, t) = mesh_of(&oct, k);
        let ray = |o: [f64; 3], d: [f64; 3]| (scaled(o, k), scaled(d, k));
        let cases = [
            (ray([-8.0, 0.0, 0.0], [1.0, 0.0, 0.0]), 2),
            (ray([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), 1),
            (ray([0.0, 0.0, 0.0], [1.0, 1.0, 0.0]), 1),
            (ray([1.0, -6.0, 1.0], [0.0, 1.0, 0.0]), 2),
        ];
        for ((o, d), want) in cases {
            let n = check_all_hits(&mesh, &v, &t, o, d).unwrap();
            assert_eq!(n, want, "octahedron {o:?} {d:?} at 2^{k}");
        }
        // Touching the vertex (4, 0, 0) from outside: even.
        let (o, d) = ray([4.0, -4.0, 0.0], [0.0, 1.0, 0.0]);
        assert_eq!(check_all_hits(&mesh, &v, &t, o, d).unwrap() % 2, 0);

        let c = cube(0.0, 2.0, false);
        let (mesh, v, t) = mesh_of(&c, k);
        let cases = [
            // Through the edges at (0, 1, 0) and (2, 1, 2).
            (ray([-1.0, 1.0, -1.0], [1.0, 0.0, 1.0]), 2),
            // Through the corners (0, 0, 0) and (2, 2, 2).
            (ray([-1.0, -1.0, -1.0], [1.0, 1.0, 1.0]), 2),
            (ray([1.0, 1.0, 1.0], [1.0, 1.0, 1.0]), 1),
            // In the bottom face's plane, through its edges' lines.
            (ray([-1.0, 1.0, 0.0], [1.0, 0.0, 0.0]), 2),
        ];
        for ((o, d), want) in cases {
            let n = check_all_hits(&mesh, &v, &t, o, d).unwrap();
            assert_eq!(n % 2, want % 2, "cube {o:?} {d:?} at 2^{k}");
            if want == 1 {
                assert_eq!(n, 1, "cube {o:?} {d:?} at 2^{k}");
            }
        }
    }
}

/// Points on vertices, edges and faces are on the boundary, the centre
/// inside, a point 1 unit of rounding beyond a face outside; the hollow of
/// the shell is outside.
#[test]
fn side_of_chosen_points() {
    let (mesh, ..) = mesh_of(&octahedron(), 0);
    for p in [[4.0, 0.0, 0.0], [2.0, 2.0, 0.0], [1.0, 1.0, 2.0]] {
        assert_eq!(mesh.side(p), Ok(MeshSide::OnBoundary), "{p:?}");
    }
    assert_eq!(mesh.side([0.0; 3]), Ok(MeshSide::Inside));
    assert_eq!(mesh.side([1.0, 1.0, 2f64.next_up()]), Ok(MeshSide::Outside));
    assert_eq!(
        mesh.side([1.0, 1.0, 2f64.next_down()]),
        Ok(MeshSide::Inside)
    );
    let (mesh, v, t) = mesh_of(&shell(), 0);
    assert_eq!(mesh_oracle::winding_number([1.0; 3], &v, &t), Some(0));
    assert_eq!(mesh_oracle::winding_number([-1.0; 3], &v, &t), Some(1));
    assert_eq!(mesh.side([1.0; 3]), Ok(MeshSide::Outside));
    assert_eq!(mesh.side([-1.0; 3]), Ok(MeshSide::Inside));
    assert_eq!(mesh.side([0.0, 1.0, 1.0]), Ok(MeshSide::OnBoundary));
}

/// A mesh with a hole, or with one triangle turned over, is not closed:
/// `side` says so; a NaN point is refused first.
#[test]
fn open_meshes_are_refused() {
    let (v, mut t) = cube(0.0, 2.0, false);
    assert!(TriangleMesh::new(&v, &t).unwrap().is_closed());
    t[3].swap(1, 2);
    let turned = TriangleMesh::new(&v, &t).unwrap();
    assert!(!turned.is_closed());
    assert_eq!(turned.side([1.0; 3]), Err(InputError::OpenMesh));
    t.pop();
    let holed = TriangleMesh::new(&v, &t).unwrap();
    assert_eq!(holed.side([1.0; 3]), Err(InputError::OpenMesh));
    let (v, t) = cube(0.0, 2.0, false);
    let closed = TriangleMesh::new(&v, &t).unwrap();
    assert_eq!(
        closed.side([f64::NAN, 0.0, 0.0]),
        Err(InputError::NonFinite { argument: "point" })
    );
}

/// The thin face of the sliver is left out of the hierarchy but not out of
/// `side` and `all_hits`; the degenerate triangle of the split cube is on
/// its surface: both against the oracle, on points and rays at and near
/// their vertices.
#[test]
fn thin_and_degenerate_triangles() {
    let (mesh, v, t) = mesh_of(&thin_tetrahedron(), 0);
    let thin = mesh.triangle(0).unwrap();
    assert!(!thin.is_degenerate() && thin.normal() == DVec3::ZERO);
    let c = v[2];
    let points = [
        c,
        [1.5, 0.0, 0.0],
        [1.5, f64::from_bits(1), 0.0],
        [1.0, f64::from_bits(1), f64::from_bits(1)],
        [1.0, 0.5, 0.25],
        [3.0, 0.0, 0.0],
    ];
    let mut on = 0;
    for p in points {
        let want = oracle_side(p, &v, &t);
        on += usize::from(want == MeshSide::OnBoundary);
        assert_eq!(mesh.side(p), Ok(want), "{p:?}");
        for target in [c, [1.5, 0.0, 0.0], [1.0, 1.0, 1.0]] {
            let d = [0, 1, 2].map(|i| target[i] - p[i]);
            check_all_hits(&mesh, &v, &t, p, d).unwrap();
        }
    }
    // The vertex c and the point on the edge b d.
    assert_eq!(on, 2);
    let (mesh, v, t) = mesh_of(&split_cube(), 0);
    assert!(mesh.is_closed());
    for p in [
        [0.5, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, -1.0, -1.0],
        [1.0, 1.0, 1.0],
    ] {
        assert_eq!(mesh.side(p), Ok(oracle_side(p, &v, &t)), "{p:?}");
        // From below the split edge, through it (a zero direction, from
        // the origin itself, is no ray: no hits).
        let d = [p[0] - 1.0, p[1] + 1.0, p[2] + 1.0];
        check_all_hits(&mesh, &v, &t, [1.0, -1.0, -1.0], d).unwrap();
    }
}

/// A fuzzer finding: on an octahedron of raw vertices (two merged) spanning
/// `1e-308` to `1e222`, a ray from a subnormal origin crosses triangles
/// only at parameters beyond `f64::MAX`: no hit (a crossing beyond `f64`'s
/// range is none, as for every mesh query), and `side` agrees with the
/// oracle.
#[test]
fn crossings_beyond_the_range_are_no_hits() {
    let v = [
        [-2.246907600971213e-161, -1.679844441290292e-308, 0.0],
        [
            3.0000000000000187,
            1.026408111779361e-220,
            -2.3047129517839915e-116,
        ],
        [
            3.6827872023677564e-235,
            -1.3067702097974576e122,
            5.983222633864129e-280,
        ],
        [
            -5.946305191561497e222,
            1.2882297539194913e-231,
            2.0616766582375757e69,
        ],
        [
            -2.9953887609770226e-265,
            -1.204869704713901e140,
            8.277275887708697e169,
        ],
        [
            -2.9953887609770226e-265,
            -1.204869704713901e140,
            8.277275887708697e169,
        ],
    ];
    let t = [
        [0, 2, 4],
        [0, 5, 2],
        [0, 4, 3],
        [0, 3, 5],
        [1, 4, 2],
        [1, 2, 5],
        [1, 3, 4],
        [1, 5, 3],
    ];
    let mesh = TriangleMesh::new(&v, &t).unwrap();
    let (o, d) = ([1.14277e-319, 0.0, 0.0], [-1.14277e-319, 0.0, 0.0]);
    let tris: Vec<[usize; 3]> = t.iter().map(|t| t.map(|i| i as usize)).collect();
    let (crossings, _) = mesh_oracle::ray_crossings(o, d, &v, &tris);
    assert!(crossings.iter().any(|c| c.2));
    for (t, ..) in &crossings {
        assert!(oracle::cmp_ratio(&t.num, &t.den, f64::MAX).is_gt());
    }
    let ray = Ray::new(o, d).unwrap();
    assert_eq!(mesh.all_hits(&ray, Interval::FORWARD).count(), 0);
    assert_eq!(mesh.side(o), Ok(oracle_side(o, &v, &tris)));
}
