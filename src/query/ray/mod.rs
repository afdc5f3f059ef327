//! Ray casts: where a ray `origin + t * direction` first meets a shape for
//! `t` in a parameter [`Interval`], and whether it meets it at all.
//!
//! Every shape implements [`RayCast`]. Quadrics also give all the roots of
//! the whole line against their surface.
//!
//! One policy for parameters beyond `f64`'s range, for every cast: a hit
//! is reported only at a finite `t` ([`Interval::admits`]). A crossing
//! whose exact parameter exceeds `f64::MAX` in magnitude is no hit (the
//! cast looks on to a later crossing in the range); one within the cast's
//! stated error of `f64::MAX` may go either way. `line_roots`, which
//! reports the whole line, returns such roots as infinities of their sign.

use crate::predicates::grain::unit_pow2;
use crate::ray::{Interval, Ray};
use glam::DVec3;

pub mod triangle;

pub use triangle::TriangleHit;

/// Where a ray meets a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The ray parameter: the hit point is `origin + t * direction`.
    pub t: f64,
    /// The hit point, `ray.at(t)`.
    pub point: DVec3,
    /// The unit geometric normal of the surface at the hit point, on the
    /// outside of a closed shape (for a plane, a disk or a triangle: the
    /// side its definition names; see each shape).
    pub normal: DVec3,
}

/// A shape a ray can be cast against.
pub trait RayCast {
    /// The hit with the smallest `t` inside `range`, or `None`; never a
    /// hit at an infinite `t` (see the module's policy).
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit>;

    /// The `t` of [`RayCast::cast`]'s hit, without its point and normal:
    /// what a closest-hit loop compares before it shades the winner.
    #[inline]
    fn cast_t(&self, ray: &Ray, range: Interval) -> Option<f64> {
        self.cast(ray, range).map(|hit| hit.t)
    }

    /// Whether the ray meets the shape for some `t` inside `range` (a shadow
    /// ray's question); may be cheaper than [`RayCast::cast`].
    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        self.cast_t(ray, range).is_some()
    }
}

mod circle;
mod cone;
mod cylinder;
pub(crate) use cylinder::scaled_square;
mod plane;
pub(crate) mod quadratic;
mod quadric;
mod sphere;

use crate::roots::Roots;

/// The smallest root that `range` admits ([`Interval::admits`]: a root
/// beyond `f64`'s range, returned as an infinity, is no hit); for
/// [`Roots::All`] (the line lies on the surface) the point of `range`
/// nearest `t = 0`.
#[inline]
pub(crate) fn first_in(roots: Roots, range: Interval) -> Option<f64> {
    let inside = |t: f64| range.admits(t);
    match roots {
        Roots::None => None,
        Roots::One(t) => inside(t).then_some(t),
        Roots::Two(t1, t2) => {
            if inside(t1) {
                Some(t1)
            } else {
                inside(t2).then_some(t2)
            }
        }
        Roots::All => {
            let t = range.min().max(range.max().min(0.0));
            t.is_finite().then_some(t)
        }
    }
}

/// The hit at `t` (a cast's first root inside its range), its normal from
/// the hit point: what the quadrics' casts share.
#[inline(always)]
pub(crate) fn hit_at(
    t: Option<f64>,
    ray: &Ray,
    normal: impl FnOnce(DVec3) -> DVec3,
) -> Option<Hit> {
    let t = t?;
    let point = ray.at(t);
    Some(Hit {
        t,
        point,
        normal: normal(point),
    })
}

/// `v` normalized, or `fallback` normalized when `v` is zero (a point
/// sphere, a cone's apex, the all-zero quadric). A vector whose squared
/// length underflows or overflows (a subnormal ray direction, a huge
/// gradient) is first scaled by a power of two, exactly, so any nonzero
/// finite `v` or `fallback` gives a unit vector.
#[inline]
pub(crate) fn unit_or(v: DVec3, fallback: DVec3) -> DVec3 {
    let n = v.normalize_or_zero();
    if n != DVec3::ZERO {
        return n;
    }
    // The cold path: rescaled, then the fallback likewise.
    let rescaled = |w: DVec3| {
        let m = w.abs().max_element();
        if m > 0.0 {
            (w * unit_pow2(m)).normalize_or_zero()
        } else {
            DVec3::ZERO
        }
    };
    let n = rescaled(v);
    if n != DVec3::ZERO {
        n
    } else {
        rescaled(fallback)
    }
}
