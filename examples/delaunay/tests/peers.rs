//! Against spade and against scaling: where the Delaunay triangulation is
//! unique (no four cocircular points, which the exact audit counts) it is
//! spade's; scaling the points by a power of two changes nothing; the
//! report's extreme sets are triangulated exactly.

use exactray::testing::{PlaneDistribution, plane_points};
use exactray_delaunay::{Exactray, Triangulation, audit, triangle_set, triangulate};
use exactray_peers::delaunay::spade_triangles;
use glam::DVec2;

fn points(dist: PlaneDistribution, n: usize) -> Vec<DVec2> {
    plane_points(dist, n).collect()
}

/// exactray's triangulation, audited clean; and whether it is the only
/// Delaunay triangulation (no exactly cocircular interior edge).
fn audited(points: &[DVec2]) -> (Triangulation, bool) {
    let t = triangulate::<Exactray>(points).expect("finite points");
    let a = audit(points, &t).expect("finite points");
    assert_eq!(a.errors(), 0, "{a:?}");
    (t, a.cocircular_edges == 0)
}

#[test]
fn uniform_points_give_spade_s_triangles() {
    for n in [3, 10, 1000, 30_000] {
        let pts = points(PlaneDistribution::Uniform, n);
        let (t, unique) = audited(&pts);
        assert!(unique, "uniform:{n} has four cocircular points");
        let spade = spade_triangles(&pts).expect("in spade's range");
        assert_eq!(
            triangle_set(&t.triangles),
            triangle_set(&spade),
            "uniform:{n}"
        );
    }
}

#[test]
fn a_grid_has_as_many_triangles_as_spade_s() {
    // Cocircular everywhere: many Delaunay triangulations, all of one size.
    let pts = points(PlaneDistribution::Grid, 10_000);
    let (t, unique) = audited(&pts);
    assert!(!unique);
    let spade = spade_triangles(&pts).expect("in spade's range");
    let with_spade = Triangulation {
        triangles: spade,
        ..Triangulation::default()
    };
    assert_eq!(audit(&pts, &with_spade).map(|a| a.errors()), Ok(0));
    assert_eq!(t.triangles.len(), with_spade.triangles.len());
}

#[test]
fn scaling_by_a_power_of_two_changes_nothing() {
    // Tiny and huge are the uniform set times 2^-532 and 2^532.
    let n = 20_000;
    let (uniform, _) = audited(&points(PlaneDistribution::Uniform, n));
    for dist in [PlaneDistribution::Tiny, PlaneDistribution::Huge] {
        let (t, unique) = audited(&points(dist, n));
        assert!(unique);
        assert_eq!(
            triangle_set(&t.triangles),
            triangle_set(&uniform.triangles),
            "{dist:?}"
        );
    }
}

#[test]
fn mixed_magnitudes_are_triangulated_exactly() {
    let (t, _) = audited(&points(PlaneDistribution::Mixed, 5000));
    assert!(t.triangles.len() > 9000);
}

#[test]
fn spade_refuses_the_extreme_sets() {
    for dist in [
        PlaneDistribution::Tiny,
        PlaneDistribution::Huge,
        PlaneDistribution::Mixed,
    ] {
        assert!(spade_triangles(&points(dist, 100)).is_err(), "{dist:?}");
    }
}
