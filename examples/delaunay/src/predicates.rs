//! The two signs the triangulator asks, as a trait, and the three sets of
//! them it runs on: exactray's, the `robust` crate's, and the exact
//! big-integer oracle's (the ground truth of the audit).

use exactray::Sign;
use glam::DVec2;

/// The orientation and in-circle signs a triangulation is built on.
///
/// Both follow Shewchuk's and exactray's conventions. The triangulator is
/// correct exactly when they are the exact signs; with inexact ones it
/// still ends (with an error or with a triangulation the audit finds
/// wrong), and never panics.
pub trait Predicates {
    /// `Positive` when `a, b, c` turn counterclockwise, `Zero` when they
    /// are collinear.
    fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Sign;
    /// `Positive` when `d` lies strictly inside the circle through the
    /// counterclockwise `a, b, c`, `Zero` when on it.
    fn incircle(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign;
}

/// exactray's predicates: exact for every finite input.
pub struct Exactray;

impl Predicates for Exactray {
    #[inline]
    fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Sign {
        exactray::predicates::orient2d(a, b, c)
    }

    #[inline]
    fn incircle(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        exactray::predicates::incircle(a, b, c, d)
    }
}

/// The `robust` crate's predicates (Shewchuk's adaptive ones): exact
/// unless a product underflows or overflows, as at the coordinates of
/// [`PlaneDistribution::Tiny`](exactray::testing::PlaneDistribution),
/// `Huge` and `Mixed`. A NaN answer (from an overflow) counts as `Zero`.
pub struct Robust;

impl Robust {
    fn coord(p: DVec2) -> robust::Coord<f64> {
        robust::Coord { x: p.x, y: p.y }
    }
}

impl Predicates for Robust {
    #[inline]
    fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Sign {
        Sign::of_f64(robust::orient2d(
            Self::coord(a),
            Self::coord(b),
            Self::coord(c),
        ))
    }

    #[inline]
    fn incircle(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        Sign::of_f64(robust::incircle(
            Self::coord(a),
            Self::coord(b),
            Self::coord(c),
            Self::coord(d),
        ))
    }
}

/// The exact big-integer signs of `exactray-oracle`, which shares no
/// arithmetic with exactray: slow (microseconds a call), for the audit and
/// for small tests.
pub struct Oracle;

impl Predicates for Oracle {
    fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Sign {
        Sign::from_i8(exactray_oracle::oracle::orient2d(
            a.to_array(),
            b.to_array(),
            c.to_array(),
        ))
    }

    fn incircle(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        Sign::from_i8(exactray_oracle::oracle::incircle(
            a.to_array(),
            b.to_array(),
            c.to_array(),
            d.to_array(),
        ))
    }
}
