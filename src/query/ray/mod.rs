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

use crate::arith::exponent::{pow2, unit_pow2};
use crate::arith::std_or_libm::fma;
use crate::error::InputError;
use crate::interval::Interval;
use crate::point::IntoDVec3;
use crate::roots::{BoundedRoot, Roots};
use glam::DVec3;

mod triangle;

pub use triangle::{
    BOUNDED_T_ULPS, BoundedTriangleHit, EXACT_T_ULPS, Exact, ExactRay, MollerTrumbore, TriangleHit,
    TriangleTest, Watertight, WatertightRay,
};

/// The half-line (or line) `origin + t * direction`. The direction need not
/// be unit length: queries report `t` in units of it, and their exactness
/// never depends on normalizing it.
///
/// ```
/// use exactray::query::ray::Ray;
/// use exactray::InputError;
/// let ray = Ray::new([0.0, 1.0, 0.0], [2.0, 0.0, 0.0]).unwrap();
/// assert_eq!(ray.at(0.5).to_array(), [1.0, 1.0, 0.0]);
/// assert_eq!(Ray::new([0.0; 3], [0.0; 3]).unwrap_err(), InputError::ZeroDirection);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    origin: DVec3,
    direction: DVec3,
}

impl Ray {
    /// A ray from `origin` along `direction` (any [`IntoDVec3`]; `f32`
    /// widens exactly).
    ///
    /// Errors: [`InputError::NonFinite`] naming `"origin"` or `"direction"`
    /// for a NaN or infinite coordinate; [`InputError::ZeroDirection`] for a
    /// zero direction. A direction with a tiny non-zero coordinate (even a
    /// subnormal one) is accepted: every query on it stays defined.
    pub fn new(origin: impl IntoDVec3, direction: impl IntoDVec3) -> Result<Ray, InputError> {
        let (origin, direction) = (origin.into_dvec3(), direction.into_dvec3());
        if !origin.is_finite() {
            return Err(InputError::NonFinite { argument: "origin" });
        }
        if !direction.is_finite() {
            return Err(InputError::NonFinite {
                argument: "direction",
            });
        }
        if direction == DVec3::ZERO {
            return Err(InputError::ZeroDirection);
        }
        Ok(Ray { origin, direction })
    }

    /// The origin.
    #[inline]
    pub fn origin(&self) -> DVec3 {
        self.origin
    }

    /// The direction, as given.
    #[inline]
    pub fn direction(&self) -> DVec3 {
        self.direction
    }

    /// The point at parameter `t`, `origin + t * direction`, rounded
    /// (each coordinate within one rounding of a product and one of a sum).
    /// Where the product overflows but the point does not (a point far
    /// along a ray whose direction is near `f64::MAX`), that coordinate is
    /// the fused `fma(t, d_k, o_k)`, one rounding of the exact value.
    #[inline]
    pub fn at(&self, t: f64) -> DVec3 {
        let p = self.origin + self.direction * t;
        if p.is_finite() {
            return p;
        }
        let fused = |k: usize| {
            if p[k].is_finite() {
                p[k]
            } else {
                fma(t, self.direction[k], self.origin[k])
            }
        };
        DVec3::new(fused(0), fused(1), fused(2))
    }
}

/// Where a ray meets a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Hit {
    /// The ray parameter: the hit point is `origin + t * direction`.
    pub t: f64,
    /// The hit point, `ray.at(t)`.
    pub point: DVec3,
    /// The unit geometric normal of the surface at the hit point, on the
    /// outside of a closed shape (for a plane, a disk or a triangle: the
    /// side its definition names; see each shape).
    pub normal: DVec3,
    /// A per-axis bound on `point`'s distance from the exact point
    /// `ray.at(t_exact)` of the surface crossing returned:
    /// `|point_k - (o_k + d_k t_exact)| <= error_k` for each axis `k`. What
    /// a secondary ray needs to leave the surface (pbrt-v4's `pError`).
    /// Derived beside each shape's cast from the bound on its `t` (see
    /// `point_error.rs`); infinite where a cast's `t` carries no certified
    /// bound (a `t` beyond `f64`'s range).
    pub error: DVec3,
    /// A certified bound on `|t - t_exact|`, the parameter's own error
    /// ([`BoundedRoot::error`]); infinite where no bound is certified.
    pub t_error: f64,
}

impl Hit {
    /// The hit at `t`, `|t - t_exact| <= et`, with the point's error.
    #[inline(always)]
    pub(crate) fn at(ray: &Ray, t: f64, et: f64, normal: DVec3) -> Hit {
        let point = ray.at(t);
        Hit {
            t,
            point,
            normal,
            error: point_error::point_error(ray, t, point, et),
            t_error: et,
        }
    }

    /// The hit at a plane parameter within [`EXACT_T_ULPS`] of the exact
    /// one (a triangle's certified `t`), with the point's error.
    #[inline(always)]
    pub(crate) fn at_plane_t(ray: &Ray, t: f64, normal: DVec3) -> Hit {
        Hit::at(ray, t, point_error::exact_t_error(t), normal)
    }
}

/// A shape a ray can be cast against.
pub trait RayCast {
    /// The hit with the smallest `t` inside `range`, or `None`; never a
    /// hit at an infinite `t` (see the module's policy).
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit>;

    /// The `t` of [`RayCast::cast`]'s hit with its certified bound
    /// ([`Hit::t_error`]), without the point and normal: the exact
    /// parameter of the crossing lies within `error` of `t`.
    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        self.cast(ray, range).map(|hit| BoundedRoot {
            t: hit.t,
            error: hit.t_error,
        })
    }

    /// The `t` of [`RayCast::cast`]'s hit, without its point and normal:
    /// what a closest-hit loop compares before it shades the winner.
    #[inline]
    fn cast_t(&self, ray: &Ray, range: Interval) -> Option<f64> {
        self.cast_bounded(ray, range).map(|hit| hit.t)
    }

    /// Whether the ray meets the shape for some `t` inside `range` (a shadow
    /// ray's question); may be cheaper than [`RayCast::cast`].
    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        self.cast_t(ray, range).is_some()
    }
}

/// The real roots of the whole line `origin + t * direction` (every `t`,
/// not only a cast's interval) against a quadric surface: what a user
/// needs to clip, count or classify crossings in generic code. Each shape's
/// inherent `line_roots` says its accuracy; this trait calls it.
///
/// ```
/// use exactray::prelude::*;
/// fn crossings(shape: &impl LineRoots, ray: &Ray) -> Option<usize> {
///     shape.line_roots(ray).count()
/// }
/// let ray = Ray::new([0.0, 0.0, -3.0], [0.0, 0.0, 1.0]).unwrap();
/// assert_eq!(crossings(&Sphere::new([0.0; 3], 1.0).unwrap(), &ray), Some(2));
/// ```
pub trait LineRoots {
    /// Every real root of the shape's equation along the ray's line,
    /// sorted ([`Roots`]).
    fn line_roots(&self, ray: &Ray) -> Roots;
}

macro_rules! line_roots_by_inherent {
    ($($shape:ty),*) => {$(
        impl LineRoots for $shape {
            #[inline]
            fn line_roots(&self, ray: &Ray) -> Roots {
                <$shape>::line_roots(self, ray)
            }
        }
    )*};
}
line_roots_by_inherent!(
    crate::shape::Sphere,
    crate::shape::Cylinder,
    crate::shape::Quadric,
    crate::shape::Cone
);

mod cone;
mod cylinder;
mod plane;
mod point_error;
mod quadric;
mod rim;
mod sphere;

/// The hit at a bounded root (a cast's first root inside its range), its
/// normal from the hit point: what the quadrics' casts share.
#[inline(always)]
pub(crate) fn hit_at(
    root: Option<BoundedRoot>,
    ray: &Ray,
    normal: impl FnOnce(DVec3) -> DVec3,
) -> Option<Hit> {
    let BoundedRoot { t, error } = root?;
    let hit = Hit::at(ray, t, error, DVec3::ZERO);
    Some(Hit {
        normal: normal(hit.point),
        ..hit
    })
}

/// The precise tier of a quadric's cast: `Precise(shape).cast(..)` returns
/// the same hit or miss as `shape.cast(..)` on every input (both decide it
/// exactly, up to a root within a few ulps of an end of the range, where
/// both decide on the precise root), with every returned root within 4
/// ulps of the correctly rounded exact root (the roots of
/// [`LineRoots::line_roots`], certified a posteriori or from the exact
/// stage), where the default tier returns the stable formula's root and
/// its a-priori bound ([`Hit::t_error`]). Implemented for [`Sphere`],
/// [`Cylinder`], [`CappedCylinder`], [`Cone`] and [`Quadric`].
///
/// ```
/// use exactray::prelude::*;
/// use exactray::query::ray::Precise;
/// let s = Sphere::new([0.0, 0.0, 0.0], 1.0).unwrap();
/// let ray = Ray::new([-1e8, 0.5, 0.0], [1.0, 0.0, 0.0]).unwrap();
/// let fast = s.cast_bounded(&ray, Interval::FORWARD).unwrap();
/// let precise = Precise(s).cast_bounded(&ray, Interval::FORWARD).unwrap();
/// // Both certified; the exact root lies within each bound.
/// assert!((fast.t - precise.t).abs() <= fast.error + precise.error);
/// ```
///
/// [`Sphere`]: crate::shape::Sphere
/// [`Cylinder`]: crate::shape::Cylinder
/// [`CappedCylinder`]: crate::shape::CappedCylinder
/// [`Cone`]: crate::shape::Cone
/// [`Quadric`]: crate::shape::Quadric
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Precise<S>(pub S);

/// `v` normalized, or `fallback` normalized when `v` is zero (a point
/// sphere, a cone's apex, the all-zero quadric). A vector whose largest
/// coordinate lies outside `[2^-500, 2^500]` is first scaled by a power of
/// two, exactly: its squared length would otherwise overflow, underflow or
/// land among the subnormals, whose few bits make the "unit" vector
/// inaccurate. So any nonzero finite `v` or `fallback` gives a unit
/// vector within a few units of rounding.
#[inline]
pub(crate) fn unit_or(v: DVec3, fallback: DVec3) -> DVec3 {
    let unit = |w: DVec3| {
        let m = w.abs().max_element();
        if (pow2(-500)..=pow2(500)).contains(&m) {
            w.normalize_or_zero()
        } else if m > 0.0 && m.is_finite() {
            (w * unit_pow2(m)).normalize_or_zero()
        } else {
            DVec3::ZERO
        }
    };
    let n = unit(v);
    if n != DVec3::ZERO { n } else { unit(fallback) }
}

serde_by_constructor!(
    Ray as "Ray" { origin: DVec3, direction: DVec3 },
    parts: |r| (r.origin, r.direction),
    build: |d| Ray::new(d.origin, d.direction),
);

#[cfg(test)]
mod ray_tests {
    use super::*;

    #[test]
    fn validation() {
        let nan = f64::NAN;
        assert_eq!(
            Ray::new([nan, 0.0, 0.0], [1.0, 0.0, 0.0]),
            Err(InputError::NonFinite { argument: "origin" })
        );
        assert_eq!(
            Ray::new([0.0; 3], [0.0, f64::INFINITY, 0.0]),
            Err(InputError::NonFinite {
                argument: "direction"
            })
        );
        assert_eq!(
            Ray::new([0.0; 3], [-0.0, 0.0, -0.0]),
            Err(InputError::ZeroDirection)
        );
        let tiny = Ray::new([0.0; 3], [f64::from_bits(1), 0.0, 0.0]).unwrap();
        assert_eq!(tiny.direction().x, f64::from_bits(1));
    }
}
