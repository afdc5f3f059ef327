//! Bounding spheres that provably enclose what they bound, despite rounding.
//!
//! Every radius here is an upper bound of the exact distance it stands for.
//! Distances are computed on differences scaled by a power of two `s` (the
//! index's scale, chosen from its largest coordinate) so that squares
//! neither overflow nor lose the small differences to underflow.

use super::sqrt;
use crate::arith::exponent::{TINY, pow2};
use glam::DVec3;

use crate::arith::roundoff::{U, gamma};

/// Relative margin of a computed squared norm of computed differences: the
/// difference, the square and two additions round once each, `gamma(5)`
/// (Higham 2002, Lemma 3.1), and the multiplication by this factor once
/// more: `(1 + gamma(5)) (1 + u)^2 <= 1 + gamma(7) < 1 + gamma(8)`, the last
/// leaving room for the rounding of the constant.
const NORM2_UP: f64 = 1.0 + gamma(8);

/// Relative margin for one `sqrt`, product or sum rounded to nearest, and
/// the multiplication by this factor itself: `(1 - u)^2 (1 + 4u) > 1`.
const ROUND_UP: f64 = 1.0 + 4.0 * U;

/// Absolute margin, in scaled units, for underflow: a scaled difference
/// below `2^-1022` is off by up to `2^-1075`, a square below it by
/// `2^-1075`; a squared norm by at most `8 * 2^-1074 = 2^-1071`, whose square
/// root is below `2^-535`. `2^-530` leaves a factor 32.
pub(crate) const UNDERFLOW_DISTANCE: f64 = pow2(-530);

/// An upper bound of the exact `|a - b|`, given the scale `s`.
#[inline]
pub(crate) fn distance_up(a: DVec3, b: DVec3, s: f64) -> f64 {
    let d = (a - b) * s;
    unscale_up(norm2_root_up(d.x * d.x + d.y * d.y + d.z * d.z), s)
}

/// An upper bound of `x / s` for `x >= 0`: the division by a power of two is
/// exact unless the quotient is subnormal, where it is off by at most
/// `2^-1075`; adding `2^-1073` (exact there, and absorbed by rounding above
/// `2^-1022`) makes it an upper bound again.
#[inline]
pub(crate) fn unscale_up(x: f64, s: f64) -> f64 {
    x / s + 2.0 * TINY
}

/// An upper bound, in scaled units, of the exact norm whose computed square
/// (from computed scaled differences) is `n2`.
#[inline]
pub(crate) fn norm2_root_up(n2: f64) -> f64 {
    sqrt(n2 * NORM2_UP) * ROUND_UP + UNDERFLOW_DISTANCE
}

/// An upper bound of `x + y` for `x, y >= 0`.
#[inline]
pub(crate) fn sum_up(x: f64, y: f64) -> f64 {
    (x + y) * ROUND_UP
}

/// A sphere `(center, radius)` enclosing the spheres `(c1, r1)` and
/// `(c2, r2)`: the smallest one, up to rounding (which only enlarges it).
pub(crate) fn merge(c1: DVec3, r1: f64, c2: DVec3, r2: f64, s: f64) -> (DVec3, f64) {
    let d = {
        let v = (c2 - c1) * s;
        sqrt(v.x * v.x + v.y * v.y + v.z * v.z) / s
    };
    let center = if r1 >= d + r2 {
        c1
    } else if r2 >= d + r1 {
        c2
    } else {
        // The smallest enclosing sphere of two spheres lies on the segment
        // of their centres, with radius (d + r1 + r2) / 2.
        let t = (((d + r1 + r2) * 0.5 - r1) / d).clamp(0.0, 1.0);
        c1 * (1.0 - t) + c2 * t
    };
    // Whatever the rounding of `center`, this radius encloses both.
    let radius = sum_up(distance_up(center, c1, s), r1).max(sum_up(distance_up(center, c2, s), r2));
    (center, radius)
}
