//! spade as a consumer: Delaunay triangulations of hard point sets, checked
//! with this crate's exact predicates.
//!
//! spade decides its own orientation and in-circle tests (with the `robust`
//! crate, within its allowed coordinate range). An exact `orient2d` and
//! `incircle` must agree with every decision it made: each inner face is
//! counterclockwise, no vertex lies strictly inside the circumcircle of the
//! face across an edge, and the outer boundary is convex. A disagreement is a
//! bug in one of the two, and the exact oracle tests of this crate say which.

use exactray::testing::{InputClass, SplitMix64, incircle_case, orient2d_case};
use exactray::{
    Sign,
    predicates::{incircle, orient2d},
};
use glam::DVec2;
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, InsertionError, Point2, Triangulation};
use std::collections::HashSet;

type Tri = DelaunayTriangulation<Point2<f64>>;

fn dv(p: Point2<f64>) -> DVec2 {
    DVec2::new(p.x, p.y)
}

/// The points spade accepts; it rejects coordinates whose magnitude is below
/// `spade::MIN_ALLOWED_VALUE` (except zero) or above `MAX_ALLOWED_VALUE`.
fn accepted(points: &[DVec2]) -> Vec<Point2<f64>> {
    points
        .iter()
        .filter(|p| {
            spade::validate_coordinate(p.x).is_ok() && spade::validate_coordinate(p.y).is_ok()
        })
        .map(|p| Point2::new(p.x, p.y))
        .collect()
}

fn distinct_count(points: &[Point2<f64>]) -> usize {
    // `+ 0.0` folds -0.0 into 0.0, as spade's position equality does.
    points
        .iter()
        .map(|p| ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits()))
        .collect::<HashSet<_>>()
        .len()
}

/// Checks every decision of the triangulation with the exact predicates.
/// Returns the number of inner faces.
fn check(t: &Tri, label: &str) -> usize {
    let n = t.num_vertices();
    let mut faces = 0;
    for face in t.inner_faces() {
        faces += 1;
        let [a, b, c] = face.positions().map(dv);
        assert_eq!(
            orient2d(a, b, c),
            Sign::Positive,
            "{label}: face {a} {b} {c} is not counterclockwise"
        );
        for edge in face.adjacent_edges() {
            // The face across `edge` is to the left of its reverse.
            if let Some(opposite) = edge.rev().opposite_vertex() {
                let d = dv(opposite.position());
                assert_ne!(
                    incircle(a, b, c, d),
                    Sign::Positive,
                    "{label}: {d} is strictly inside the circumcircle of face {a} {b} {c}"
                );
            }
        }
    }

    // The outer face is to the left of each hull edge: every vertex must be on
    // its right or on its line, which makes the boundary convex.
    let hull: Vec<[DVec2; 2]> = t
        .directed_edges()
        .filter(|e| e.is_outer_edge())
        .map(|e| e.positions().map(dv))
        .collect();
    for [from, to] in &hull {
        for v in t.vertices() {
            let p = dv(v.position());
            assert_ne!(
                orient2d(*from, *to, p),
                Sign::Positive,
                "{label}: vertex {p} is outside hull edge {from} -> {to}"
            );
        }
    }

    if faces > 0 {
        // Euler's formula for a triangulated disc whose boundary has h vertices
        // (collinear boundary vertices included, as spade keeps them).
        let h = hull.len();
        assert_eq!(
            faces,
            2 * n - h - 2,
            "{label}: {n} vertices, {h} on the hull"
        );
        assert_eq!(
            t.num_undirected_edges(),
            3 * n - h - 3,
            "{label}: edge count"
        );
    } else {
        // No face means every vertex is on one line; the exact test agrees.
        let v: Vec<DVec2> = t.vertices().map(|v| dv(v.position())).collect();
        if let Some(&first) = v.first() {
            let second = v.iter().copied().find(|&p| p != first);
            if let Some(second) = second {
                for &p in &v {
                    assert_eq!(
                        orient2d(first, second, p),
                        Sign::Zero,
                        "{label}: not collinear yet no face"
                    );
                }
            }
        }
    }
    faces
}

/// Triangulates `points` both incrementally and by bulk loading, checks both,
/// and checks they have the same vertex count and face count (the Delaunay
/// triangulation is unique up to the choice inside cocircular groups, which
/// does not change the number of triangles).
fn triangulate_and_check(points: &[DVec2], label: &str) -> usize {
    let input = accepted(points);
    let mut incremental = Tri::new();
    for p in &input {
        let _: FixedVertexHandle = incremental.insert(*p).expect("validated coordinates");
    }
    assert_eq!(
        incremental.num_vertices(),
        distinct_count(&input),
        "{label}: vertex count"
    );
    let faces = check(&incremental, &format!("{label} (incremental)"));

    let bulk = Tri::bulk_load(input.clone()).expect("validated coordinates");
    assert_eq!(
        bulk.num_vertices(),
        incremental.num_vertices(),
        "{label}: bulk vertex count"
    );
    let bulk_faces = check(&bulk, &format!("{label} (bulk)"));
    assert_eq!(
        bulk_faces, faces,
        "{label}: bulk and incremental face counts"
    );
    faces
}

fn grid(n: i32, scale: f64, offset: DVec2) -> Vec<DVec2> {
    let mut v = Vec::new();
    for i in 0..n {
        for j in 0..n {
            v.push(offset + DVec2::new(f64::from(i), f64::from(j)) * scale);
        }
    }
    v
}

/// All integer points on the circle x² + y² = r² (exactly cocircular).
fn lattice_circle(r: i64) -> Vec<DVec2> {
    let mut v = Vec::new();
    for x in -r..=r {
        let y2 = r * r - x * x;
        let y = (y2 as f64).sqrt() as i64;
        for y in [y - 1, y, y + 1] {
            if y >= 0 && y * y == y2 {
                v.push(DVec2::new(x as f64, y as f64));
                if y != 0 {
                    v.push(DVec2::new(x as f64, -(y as f64)));
                }
            }
        }
    }
    v
}

#[test]
fn spade_rejects_what_it_says_it_rejects() {
    let mut t = Tri::new();
    assert!(matches!(
        t.insert(Point2::new(1e-300, 0.0)),
        Err(InsertionError::TooSmall)
    ));
    assert!(matches!(
        t.insert(Point2::new(0.0, 1e300)),
        Err(InsertionError::TooLarge)
    ));
    assert!(matches!(
        t.insert(Point2::new(f64::NAN, 0.0)),
        Err(InsertionError::NAN)
    ));
    assert_eq!(t.num_vertices(), 0);
}

#[test]
fn integer_grids_with_many_cocircular_quadruples() {
    let faces = triangulate_and_check(&grid(16, 1.0, DVec2::ZERO), "grid");
    // 16x16 grid: h = 60 boundary vertices, 2n - h - 2 = 450 triangles.
    assert_eq!(faces, 450);
    // Far from the origin, where the fraction bits run out: 2^49 + i/8 is
    // still exact (the spacing there is 2^-3), and every square is cocircular.
    let far = DVec2::new(2f64.powi(49), -(2f64.powi(49)));
    assert_eq!(
        triangulate_and_check(&grid(16, 0.125, far), "far grid"),
        450
    );
    // Non-dyadic spacing: the points are rounded, so squares are only nearly
    // cocircular and the decision rests on the exact in-circle sign.
    triangulate_and_check(&grid(16, 0.1, DVec2::new(1e6, 1e6)), "0.1 grid");
    triangulate_and_check(&grid(16, 1.0 / 3.0, DVec2::new(-7.7, 3.3)), "1/3 grid");
}

#[test]
fn points_on_circles() {
    // 5^4 * 13 has many Pythagorean points: a large exactly cocircular set,
    // plus the centre so there is a vertex strictly inside.
    let mut exact = lattice_circle(8125);
    assert!(exact.len() > 40, "{}", exact.len());
    triangulate_and_check(&exact, "lattice circle");
    exact.push(DVec2::ZERO);
    triangulate_and_check(&exact, "lattice circle and centre");

    // Rounded trigonometric points: nearly cocircular, each side decided by
    // bits below the rounding error of a plain in-circle evaluation.
    for (count, radius, centre) in [
        (64, 1.0, DVec2::ZERO),
        (200, 1e3, DVec2::new(1e7, -3e7)),
        (50, 1e-20, DVec2::ZERO),
    ] {
        let pts: Vec<DVec2> = (0..count)
            .map(|i| {
                let t = core::f64::consts::TAU * f64::from(i) / f64::from(count);
                centre + DVec2::new(t.cos(), t.sin()) * radius
            })
            .collect();
        triangulate_and_check(&pts, &format!("circle r={radius}"));
    }
}

#[test]
fn near_collinear_points() {
    // Points computed on the line y = 0.3 x + 0.7: rounding puts each
    // slightly above, below or exactly on it, so spade builds slivers.
    let line: Vec<DVec2> = (0..200)
        .map(|i| {
            let x = f64::from(i) * 0.1 - 3.0;
            DVec2::new(x, 0.3 * x + 0.7)
        })
        .collect();
    triangulate_and_check(&line, "rounded line");

    let mut with_apex = line.clone();
    with_apex.push(DVec2::new(0.0, 50.0));
    with_apex.push(DVec2::new(0.0, -50.0));
    triangulate_and_check(&with_apex, "rounded line with apexes");

    // Exactly collinear: no face at all.
    let exact: Vec<DVec2> = (0..50)
        .map(|i| DVec2::new(f64::from(i), f64::from(2 * i) + 1.0))
        .collect();
    assert_eq!(triangulate_and_check(&exact, "exact line"), 0);

    // Nudged by one ulp off an exact line.
    let mut nudged = exact.clone();
    for (k, p) in nudged.iter_mut().enumerate() {
        if k % 7 == 3 {
            p.y = f64::from_bits(p.y.to_bits() + 1);
        }
    }
    triangulate_and_check(&nudged, "nudged line");
}

#[test]
fn huge_and_tiny_coordinates_within_spade_range() {
    // spade accepts 2^-142 <= |x| <= 2^201 (and zero). Power-of-two scalings
    // keep the geometry, so the face counts match the unit grid.
    for k in [-130, -100, 60, 150, 190] {
        let s = 2f64.powi(k);
        assert_eq!(
            triangulate_and_check(&grid(12, s, DVec2::ZERO), &format!("grid * 2^{k}")),
            242
        );
    }
    // Non-dyadic scalings round, so only the checks apply.
    for s in [1e-40, 1e-25, 1e30, 1e55] {
        triangulate_and_check(
            &grid(12, s, DVec2::splat(s * 0.3)),
            &format!("grid * {s:e}"),
        );
        let lattice: Vec<DVec2> = lattice_circle(325).into_iter().map(|p| p * s).collect();
        triangulate_and_check(&lattice, &format!("lattice circle * {s:e}"));
    }
    // Points beyond spade's range are skipped, the rest triangulated.
    let mut mixed = grid(8, 1.0, DVec2::ZERO);
    mixed.push(DVec2::new(1e-300, 1.0));
    mixed.push(DVec2::new(1e300, 1.0));
    assert_eq!(accepted(&mixed).len(), 64);
    triangulate_and_check(&mixed, "grid with rejected points");
}

#[test]
fn hard_generator_point_clouds() {
    // Many independent hard triples and quadruples from the crate's
    // generators, pooled into one cloud per class: nearly collinear and nearly
    // cocircular subsets close to one another.
    for class in InputClass::ALL {
        let mut rng = SplitMix64::new(0x5eed ^ class as u64);
        let mut pts = Vec::new();
        for _ in 0..40 {
            pts.extend(orient2d_case(class, &mut rng));
            pts.extend(incircle_case(class, &mut rng));
        }
        triangulate_and_check(&pts, class.name());
    }
}
