//! Property tests: on exactray's predicates the output is always a
//! Delaunay triangulation of the points, by the exact audit and by brute
//! force over every triangle and point on the big-integer oracle, and it
//! is the very output the same code builds on the oracle's signs.

use exactray::testing::{PlaneDistribution, finite_dvec2, plane_points};
use exactray_delaunay::audit::brute_force_violations;
use exactray_delaunay::{Exactray, Oracle, audit, triangulate};
use glam::DVec2;
use proptest::prelude::*;

/// Points of a small integer lattice (collinear, cocircular and repeated
/// points everywhere), all scaled by one power of two from the subnormals
/// to near overflow: exactly, so the degeneracies stay.
fn lattice() -> impl Strategy<Value = Vec<DVec2>> {
    (
        prop::collection::vec((-4i8..=4, -4i8..=4), 0..40),
        -1070i32..=1000,
    )
        .prop_map(|(ij, k)| {
            let s = 2f64.powi(k);
            ij.into_iter()
                .map(|(i, j)| DVec2::new(f64::from(i) * s, f64::from(j) * s))
                .collect()
        })
}

/// Any finite coordinates, every bit pattern alike: magnitudes from the
/// subnormals to `1e308` in one set.
fn anywhere() -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec(finite_dvec2(), 0..16)
}

/// A prefix of the report's point sets.
fn report_sets() -> impl Strategy<Value = Vec<DVec2>> {
    (
        prop::sample::select(&PlaneDistribution::ALL[..]),
        0usize..60,
    )
        .prop_map(|(dist, n)| plane_points(dist, n).collect())
}

fn assert_delaunay(points: &[DVec2]) -> Result<(), TestCaseError> {
    let t = triangulate::<Exactray>(points);
    prop_assert!(t.is_ok(), "{t:?}");
    let t = t.unwrap_or_default();
    let a = audit(points, &t);
    prop_assert_eq!(a.map(|a| a.errors()), Ok(0), "{:?}", a);
    prop_assert_eq!(brute_force_violations(points, &t.triangles), 0);
    prop_assert_eq!(triangulate::<Oracle>(points), Ok(t));
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn lattice_points_are_triangulated_exactly(points in lattice()) {
        assert_delaunay(&points)?;
    }

    #[test]
    fn points_anywhere_are_triangulated_exactly(points in anywhere()) {
        assert_delaunay(&points)?;
    }

    #[test]
    fn report_sets_are_triangulated_exactly(points in report_sets()) {
        assert_delaunay(&points)?;
    }

    #[test]
    fn mixtures_are_triangulated_exactly(a in lattice(), b in anywhere(), c in report_sets()) {
        assert_delaunay(&[a, b, c].concat())?;
    }
}
