//! With predicates that are wrong, the triangulator still ends, without a
//! panic: with a triangulation (which the audit finds wrong) or with a
//! reported contradiction. `robust`'s at extreme magnitudes, and three
//! made-up ones: random signs, the in-circle test turned inside out, and
//! every sign zero.

use exactray::Sign;
use exactray::testing::{PlaneDistribution, SplitMix64, plane_points};
use exactray_delaunay::{
    Predicates, Robust, Triangulation, TriangulationError, audit, triangulate,
};
use glam::DVec2;
use std::cell::RefCell;

/// A sign drawn from a random stream, whatever the points.
struct Coin;

thread_local! {
    static COIN: RefCell<SplitMix64> = RefCell::new(SplitMix64::new(17));
}

fn toss() -> Sign {
    COIN.with(|c| match c.borrow_mut().next_u64() % 3 {
        0 => Sign::Negative,
        1 => Sign::Zero,
        _ => Sign::Positive,
    })
}

impl Predicates for Coin {
    fn orient2d(_: DVec2, _: DVec2, _: DVec2) -> Sign {
        toss()
    }

    fn incircle(_: DVec2, _: DVec2, _: DVec2, _: DVec2) -> Sign {
        toss()
    }
}

/// Exact orientation, in-circle negated: every cavity grows outwards.
struct InsideOut;

impl Predicates for InsideOut {
    fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Sign {
        exactray::predicates::orient2d(a, b, c)
    }

    fn incircle(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        -exactray::predicates::incircle(a, b, c, d)
    }
}

/// Every sign zero: everything collinear and cocircular.
struct Flat;

impl Predicates for Flat {
    fn orient2d(_: DVec2, _: DVec2, _: DVec2) -> Sign {
        Sign::Zero
    }

    fn incircle(_: DVec2, _: DVec2, _: DVec2, _: DVec2) -> Sign {
        Sign::Zero
    }
}

/// The run ended with a triangulation (audited, however wrong: the audit
/// must not fail either) or with a contradiction; whether it is wrong.
fn ends<P: Predicates>(points: &[DVec2]) -> bool {
    match triangulate::<P>(points) {
        Ok(t) => audit(points, &t).expect("finite points").errors() > 0,
        Err(TriangulationError::WalkCycle { .. } | TriangulationError::BrokenCavity { .. }) => true,
        Err(e) => panic!("finite points, but {e}"),
    }
}

#[test]
fn random_signs_end() {
    let mut wrong = 0;
    for dist in PlaneDistribution::ALL {
        for n in [3, 10, 100, 2000] {
            for _ in 0..5 {
                wrong += usize::from(ends::<Coin>(&plane_points(dist, n).collect::<Vec<_>>()));
            }
        }
    }
    assert!(wrong > 0);
}

#[test]
fn inside_out_circles_end() {
    for dist in PlaneDistribution::ALL {
        for n in [10, 100, 2000] {
            assert!(ends::<InsideOut>(
                &plane_points(dist, n).collect::<Vec<_>>()
            ));
        }
    }
}

#[test]
fn all_zero_signs_give_nothing() {
    let pts: Vec<DVec2> = plane_points(PlaneDistribution::Uniform, 100).collect();
    assert_eq!(triangulate::<Flat>(&pts), Ok(Triangulation::default()));
}

#[test]
fn robust_fails_at_extreme_magnitudes_and_says_so_or_the_audit_does() {
    for dist in [
        PlaneDistribution::Tiny,
        PlaneDistribution::Huge,
        PlaneDistribution::Mixed,
    ] {
        let pts: Vec<DVec2> = plane_points(dist, 5000).collect();
        assert!(ends::<Robust>(&pts), "{dist:?}");
    }
    // Where robust's arithmetic neither underflows nor overflows, it is
    // exact, and so is the triangulation on it.
    for dist in [PlaneDistribution::Uniform, PlaneDistribution::Grid] {
        let pts: Vec<DVec2> = plane_points(dist, 5000).collect();
        assert!(!ends::<Robust>(&pts), "{dist:?}");
    }
}
