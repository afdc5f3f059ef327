//! The frame the wide nodes' `f32` boxes are stored in: coordinates
//! moved by a centre `c` and scaled by a power of two `2^e`, `x' = (x -
//! c) 2^e`, chosen per hierarchy so that its root box spans about
//! `[-1, 1]` on its longest axis. A mesh far from the origin, or at any
//! scale from `2^-1074` to `2^1023`, keeps `f32`'s relative precision for
//! its own size, and no frame coordinate of a box overflows `f32`.
//!
//! # Rounding outward
//! A box bound `b` is stored as an `f32` below (`min`) or above (`max`)
//! its exact frame value `v = (b - c) 2^e` ([`Frame::down`],
//! [`Frame::up`]). The `f64` value `x = fl(fl(b - c) 2^e)` is within `u
//! |x| + 2^-1074` of `v` (`u = 2^-53`: the subtraction's rounding, the
//! scaling exact but where it falls below `2^-1022`, `scale_pow2`'s
//! bound). `f` is then `x` rounded to the nearest `f32` and moved two
//! `f32` steps down (two units off its bits, away from zero for a
//! negative `f`). Rounding to nearest leaves `x` at least half of the
//! first step above the result of that step, and the second step adds a
//! whole step (the smaller of the two where they cross a power of two), so
//! `x` lies at least one step at the result above it: at least `2^-149`
//! and at least `2^-24 |result|`, which exceeds `u |x| + 2^-1074` (the `f32`
//! steps are `2^29` times the `f64` ones): so `f < v`. A result of
//! magnitude below `2^-100` (a positive `x` below a few steps above zero
//! included) is replaced by `-2^-100`, which is below it too: no bound,
//! origin or range end is then subnormal or near it, in the frame where
//! boxes span about `[-1, 1]` (subnormal operands or results slow `f32`
//! vector arithmetic a hundredfold on common processors: the room's
//! camera, at its frame's centre on one axis, took 2.6 times as long per
//! ray before). A rounding to `±inf` or to `-f32::MAX` is kept apart: `x
//! = +inf` or above `f32::MAX` gives `f32::MAX` less two steps, `x <=
//! -f32::MAX` gives `-inf`. [`Frame::up`] mirrors it. In the frame every
//! bound of the hierarchy has `|x| <= 2`.
//!
//! The same two functions round a ray's origin into the frame, below and
//! above its exact frame coordinates (`traverse.rs`), and the range's
//! parameters into the walk's `f32` parameter.

use crate::arith::exponent::{scale_pow2, unit_scale};
use glam::DVec3;

/// The frame of a hierarchy (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Frame {
    /// The centre `c` subtracted from every coordinate.
    pub(crate) centre: DVec3,
    /// The power of two `e` the difference is scaled by, `|e| <= 1075`.
    pub(crate) exp: i32,
}

impl Frame {
    /// The frame of an empty hierarchy (never read).
    pub(crate) const EMPTY: Frame = Frame {
        centre: DVec3::ZERO,
        exp: 0,
    };

    /// The frame of the exact box `[lo, hi]` (finite): its centre, and the
    /// power of two bringing its largest half extent into `[1/2, 1)`; the
    /// origin as centre where the extent overflows, so that every `b - c`
    /// of a bound is finite.
    pub(crate) fn of(lo: DVec3, hi: DVec3) -> Frame {
        let centre = if (hi - lo).is_finite() {
            lo * 0.5 + hi * 0.5
        } else {
            DVec3::ZERO
        };
        let reach = (hi - centre).max(centre - lo).max_element();
        Frame {
            centre,
            exp: unit_scale(&[reach]),
        }
    }

    /// `fl(fl(x - c_k) 2^e)`, within `u |.| + 2^-1074` of the exact frame
    /// coordinate of `x` on axis `k` (infinite where `x - c_k` overflows).
    #[inline(always)]
    pub(crate) fn coordinate(&self, x: f64, k: usize) -> f64 {
        scale_pow2(x - self.centre[k], self.exp)
    }

    /// An `f32` below the exact frame coordinate of `b` on axis `k`.
    #[inline]
    pub(crate) fn down(&self, b: f64, k: usize) -> f32 {
        down(self.coordinate(b, k))
    }

    /// An `f32` above the exact frame coordinate of `b` on axis `k`.
    #[inline]
    pub(crate) fn up(&self, b: f64, k: usize) -> f32 {
        up(self.coordinate(b, k))
    }

    /// An `f64` at most the world coordinate `c_k + f 2^-e` of the frame
    /// value `f` on axis `k`: the product is exact but below `2^-1022`
    /// (an error of at most `2^-1074`), the sum rounds to nearest (half a
    /// step at the result), and two steps down cover both.
    /// An infinite `f` (an empty lane's bound) stays infinite.
    #[inline(always)]
    pub(crate) fn world_down(&self, f: f32, k: usize) -> f64 {
        -self.world_up_of(-f, -self.centre[k])
    }

    /// An `f64` at least the world coordinate of `f` (as
    /// [`Frame::world_down`]).
    #[inline(always)]
    pub(crate) fn world_up(&self, f: f32, k: usize) -> f64 {
        self.world_up_of(f, self.centre[k])
    }

    /// An `f64` at least `c + f 2^-e`, for a centre coordinate `c`.
    #[inline(always)]
    fn world_up_of(&self, f: f32, c: f64) -> f64 {
        if !f.is_finite() {
            return f64::from(f);
        }
        (c + scale_pow2(f64::from(f), -self.exp))
            .next_up()
            .next_up()
    }
}

/// An `f32` strictly below every value within `u |x| + 2^-1074` of `x`
/// (see the module docs); `-inf` for `x <= -f32::MAX`, `f32::MAX` less
/// two steps for `x = +inf` or `x > f32::MAX`. NaN stays NaN.
#[inline(always)]
pub(crate) fn down(x: f64) -> f32 {
    let f = x as f32;
    let bits = f.to_bits();
    let f = if f > 0.0 {
        // Two steps towards zero; an `f` of one or two steps above zero
        // goes to zero, which the floor below replaces.
        f32::from_bits(bits.saturating_sub(2).min(f32::MAX.to_bits() - 2))
    } else if f > -f32::MAX {
        // Two steps away from zero (`-0.0` and `0.0` too, whose bits
        // plus two are a positive or negative subnormal: floored below).
        f32::from_bits(bits + 2)
    } else {
        // `-f32::MAX`, `-inf` or NaN.
        f - f32::INFINITY
    };
    // Never within 2^-100 of zero: -2^-100 instead, still below.
    if f.abs() < TINY { -TINY } else { f }
}

/// The least magnitude of an outward rounding (see the module docs).
const TINY: f32 = 1.0 / (1u128 << 100) as f32;

/// An `f32` strictly above every value within `u |x| + 2^-1074` of `x`.
#[inline(always)]
pub(crate) fn up(x: f64) -> f32 {
    -down(-x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arith::exponent::pow2;

    /// Outward rounding brackets the exact value of `x` and its
    /// neighbours, at every scale and near `f32`'s limits.
    #[test]
    fn outward_rounding_brackets() {
        let mut values = alloc::vec![0.0, -0.0, 1.0, -1.0, 3.0, f64::MAX, f64::INFINITY];
        // Near f32's limits, its least steps, the floor and a rounding up
        // to a power of two.
        for f in [
            f32::MAX,
            f32::from_bits(1),
            f32::from_bits(2),
            f32::from_bits(3),
            TINY,
        ] {
            let x = f64::from(f);
            values.extend([x, -x, x.next_up(), x.next_down(), -x.next_up()]);
        }
        values.extend([
            1.0 - pow2(-25),
            1.0 - pow2(-26),
            -(1.0 - pow2(-25)),
            -f64::MAX,
        ]);
        for k in (-1074..=1023).step_by(7) {
            let p = scale_pow2(1.0, k);
            values.extend([p, -p, p * 1.25, p.next_up(), p.next_down(), -p.next_down()]);
        }
        for x in values {
            let (lo, hi) = (down(x), up(x));
            for near in [x.next_down(), x, x.next_up()] {
                assert!(f64::from(lo) < near || near == f64::NEG_INFINITY, "{x:e}");
                assert!(f64::from(hi) > near || near == f64::INFINITY, "{x:e}");
            }
        }
        assert_eq!(down(f64::NEG_INFINITY), f32::NEG_INFINITY);
        assert_eq!(up(f64::INFINITY), f32::INFINITY);
        assert!(down(f64::INFINITY).is_finite() && down(2.0).is_finite());
    }

    /// A frame maps its box into `[-1, 1]`, and its bounds' outward
    /// roundings map back outside the exact bounds, at every scale and
    /// offset.
    #[test]
    fn frames_hold_their_boxes() {
        for k in [-1074, -1000, -500, 0, 500, 1000] {
            for offset in [0.0, 1e8, -1e300] {
                let s = scale_pow2(1.0, k);
                let lo = DVec3::new(-3.0 * s, 1.0 * s, 0.5 * s) + offset;
                let hi = DVec3::new(5.0 * s, 1.5 * s, 7.0 * s) + offset;
                if !(lo.is_finite() && hi.is_finite()) {
                    continue;
                }
                let frame = Frame::of(lo, hi);
                for axis in 0..3 {
                    let (a, b) = (frame.down(lo[axis], axis), frame.up(hi[axis], axis));
                    assert!(a.abs() <= 1.01 && b.abs() <= 1.01, "{k} {offset}");
                    assert!(frame.world_down(a, axis) <= lo[axis], "{k} {offset}");
                    assert!(frame.world_up(b, axis) >= hi[axis], "{k} {offset}");
                }
            }
        }
        // A box whose extent overflows is framed about the origin.
        let wide = Frame::of(DVec3::splat(-f64::MAX), DVec3::splat(f64::MAX));
        assert_eq!((wide.centre, wide.exp), (DVec3::ZERO, -1024));
        assert_eq!(pow2(0), 1.0);
    }
}
