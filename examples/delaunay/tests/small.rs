//! Small inputs whose triangulations are known exactly: the square, an
//! integer grid and twelve integer points on one circle (cocircular
//! everywhere), collinear points, duplicates, points on the hull, bad
//! input.

use exactray_delaunay::{
    Exactray, Oracle, Triangulation, TriangulationError, audit, triangle_set, triangulate,
};
use glam::DVec2;

fn pts(coords: &[[f64; 2]]) -> Vec<DVec2> {
    coords.iter().map(|&c| DVec2::from_array(c)).collect()
}

fn exact(points: &[DVec2]) -> Triangulation {
    let t = triangulate::<Exactray>(points).expect("finite points");
    let a = audit(points, &t).expect("finite points");
    assert_eq!(a.errors(), 0, "{a:?}");
    // The same code on the oracle's signs makes the same choices.
    assert_eq!(triangulate::<Oracle>(points), Ok(t.clone()));
    t
}

#[test]
fn a_square_is_two_triangles_on_either_diagonal() {
    let points = pts(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    let t = exact(&points);
    let tris = triangle_set(&t.triangles);
    assert!(
        tris == vec![[0, 1, 2], [0, 2, 3]] || tris == vec![[0, 1, 3], [1, 2, 3]],
        "{tris:?}"
    );
    assert_eq!(audit(&points, &t).map(|a| a.cocircular_edges), Ok(1));
}

#[test]
fn a_cocircular_grid() {
    // 6 x 6 lattice points: every unit square cocircular, so its diagonal
    // may go either way, and no other edge is cocircular.
    let points: Vec<DVec2> = (0..36)
        .map(|i| DVec2::new((i % 6) as f64, (i / 6) as f64))
        .collect();
    let t = exact(&points);
    assert_eq!(t.triangles.len(), 2 * 25);
    assert_eq!(audit(&points, &t).map(|a| a.cocircular_edges), Ok(25));
}

#[test]
fn twelve_points_on_one_circle() {
    // The integer points of x^2 + y^2 = 25.
    let mut coords = vec![[5.0, 0.0], [-5.0, 0.0], [0.0, 5.0], [0.0, -5.0]];
    for (x, y) in [(3.0, 4.0), (4.0, 3.0)] {
        for (sx, sy) in [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)] {
            coords.push([sx * x, sy * y]);
        }
    }
    let points = pts(&coords);
    let t = exact(&points);
    // A convex 12-gon: 10 triangles, 9 interior edges, all cocircular.
    assert_eq!(t.triangles.len(), 10);
    assert_eq!(audit(&points, &t).map(|a| a.cocircular_edges), Ok(9));
}

#[test]
fn collinear_points_have_no_triangle() {
    let points = pts(&[[0.0, 0.0], [3.0, 3.0], [1.0, 1.0], [2.0, 2.0], [-1.0, -1.0]]);
    assert_eq!(
        triangulate::<Exactray>(&points),
        Ok(Triangulation::default())
    );
    assert_eq!(
        audit(&points, &Triangulation::default()).map(|a| a.errors()),
        Ok(0)
    );
}

#[test]
fn collinear_points_and_an_apex_make_a_fan() {
    // Four points on a line (given out of order) and one above: the only
    // triangulation joins the apex to each of the three segments.
    let points = pts(&[[3.0, 0.0], [0.0, 0.0], [1.5, 1.0], [2.0, 0.0], [1.0, 0.0]]);
    let t = exact(&points);
    assert_eq!(
        triangle_set(&t.triangles),
        vec![[0, 2, 3], [1, 4, 2], [2, 4, 3]]
    );
}

#[test]
fn a_point_inside_a_triangle() {
    let points = pts(&[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [1.0, 1.0]]);
    let t = exact(&points);
    assert_eq!(
        triangle_set(&t.triangles),
        vec![[0, 1, 3], [0, 3, 2], [1, 2, 3]]
    );
}

#[test]
fn duplicates_are_skipped_and_listed() {
    // -0.0 equals 0.0: the same point.
    let points = pts(&[
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 1.0],
        [0.0, 1.0],
        [1.0, 0.0],
        [-0.0, 0.0],
        [1.0, 0.0],
    ]);
    let t = exact(&points);
    assert_eq!(t.triangles.len(), 2);
    assert_eq!(t.duplicates.len(), 3);
    for &(skipped, kept) in &t.duplicates {
        assert_eq!(points[skipped as usize], points[kept as usize]);
        assert!(t.triangles.iter().flatten().any(|&v| v == kept));
        assert!(t.triangles.iter().flatten().all(|&v| v != skipped));
    }
    // All one point: no triangle.
    let same = pts(&[[2.0, 3.0]; 5]);
    assert_eq!(triangulate::<Exactray>(&same), Ok(Triangulation::default()));
}

#[test]
fn points_on_the_hull_and_its_edges() {
    // A triangle with points on each edge and inside: all vertices, the
    // ones on edges on the boundary.
    let points = pts(&[
        [0.0, 0.0],
        [4.0, 0.0],
        [0.0, 4.0],
        [2.0, 0.0],
        [2.0, 2.0],
        [0.0, 2.0],
        [1.0, 1.0],
        [3.0, 0.0],
        [1.0, 3.0],
    ]);
    let t = exact(&points);
    // n = 9 points, h = 8 on the hull: 2n - h - 2 = 8 triangles.
    assert_eq!(t.triangles.len(), 8);
}

#[test]
fn fewer_than_three_points() {
    for n in 0..3 {
        let points = pts(&[[0.0, 0.0], [1.0, 0.0]][..n.min(2)]);
        assert_eq!(
            triangulate::<Exactray>(&points),
            Ok(Triangulation::default())
        );
    }
}

#[test]
fn non_finite_input_is_an_error() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let points = pts(&[[0.0, 0.0], [1.0, 0.0], [0.0, bad], [0.0, 1.0]]);
        assert_eq!(
            triangulate::<Exactray>(&points),
            Err(TriangulationError::NonFinite { index: 2 })
        );
        assert_eq!(
            audit(&points, &Triangulation::default()),
            Err(TriangulationError::NonFinite { index: 2 })
        );
    }
}

#[test]
fn the_audit_finds_what_is_wrong() {
    let points = pts(&[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [1.0, 1.0], [4.0, 4.0]]);
    let good = exact(&points);
    let with = |triangles: Vec<[u32; 3]>| Triangulation {
        triangles,
        ..Triangulation::default()
    };
    let found = |t: &Triangulation| audit(&points, t).expect("finite points");
    // A clockwise triangle.
    let mut flipped = good.triangles.clone();
    flipped[0].swap(0, 1);
    assert!(found(&with(flipped)).inverted >= 1);
    // A missing point: (1, 1) left out, the rest triangulated.
    let a = found(&with(vec![[0, 1, 2], [1, 4, 2]]));
    assert_eq!((a.missing_points, a.inverted, a.not_delaunay), (1, 0, 0));
    // Not Delaunay: in the quadrilateral (0,0), (2,-1), (4,0), (2,3),
    // (2, 3) lies inside the circle through the first three (centre
    // (2, 1.5), radius 2.5), so the diagonal from (0,0) to (4,0) makes
    // both triangles bad and the other diagonal is the Delaunay one.
    let kite = pts(&[[0.0, 0.0], [2.0, -1.0], [4.0, 0.0], [2.0, 3.0]]);
    assert_eq!(
        triangle_set(&exact(&kite).triangles),
        vec![[0, 1, 3], [1, 2, 3]]
    );
    let a = audit(&kite, &with(vec![[0, 1, 2], [0, 2, 3]])).expect("finite points");
    assert_eq!((a.inverted, a.not_delaunay, a.errors()), (0, 2, 2));
    // An extra triangle over others: an edge repeated, Euler off.
    let mut extra = good.triangles.clone();
    extra.push(good.triangles[0]);
    let a = found(&with(extra));
    assert!(a.repeated_edges >= 3 && a.euler_gap == 1);
    // A vertex index past the input, a false duplicate.
    let a = found(&Triangulation {
        triangles: vec![[0, 1, 9]],
        duplicates: vec![(3, 4)],
        ..Triangulation::default()
    });
    assert_eq!((a.bad_indices, a.false_duplicates), (1, 1));
}
