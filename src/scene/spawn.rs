//! Secondary rays that leave a surface: the origin moved off the hit point
//! by its certified error (pbrt-v4's `OffsetRayOrigin`, Pharr, Jakob and
//! Humphreys, *Physically Based Rendering*, 4th ed., §6.8.6), derived here
//! for `f64`. No fixed epsilon: the offset is the hit's own error bound.
//!
//! # Derivation
//! The exact crossing `x` lies in the box `p ± e` around the computed
//! point `p` (`e` is [`Hit::error`], per axis). Every point of that box is
//! within `δ = |n| . e = Σ |n_k| e_k` of the plane through `p` with unit
//! normal `n`, measured along `n`, so `p + δ n` lies on `n`'s side of the
//! plane through `x` (or on it). In `f64`:
//!
//! - `δ` is a dot product of three non-negative terms: three products and
//!   two sums, `fl(δ) >= δ (1 - gamma(3))`; the offset `fl(fl(δ) n_k)`
//!   loses one more rounding, and the computed normal has `|n|^2` within
//!   `gamma(3)` of 1. Taking `δ' = fl(δ) (1 + gamma(8))` the offset moves the
//!   point at least `δ` along `n`, to first order in `u`.
//! - `fl(p_k + offset_k)` may round back towards the surface by half an
//!   ulp; stepping every offset coordinate one ulp further away
//!   (`next_up` for a positive offset, `next_down` for a negative one) puts
//!   it at or beyond the exact `p_k + offset_k`.
//!
//! The offset goes to the side of the surface the new direction `w` points
//! to: along `n` when `w . n >= 0`, along `-n` otherwise.

use crate::arith::roundoff::gamma;
use crate::error::InputError;
use crate::interval::Interval;
use crate::point::IntoDVec3;
use crate::query::ray::{Hit, Ray};
use glam::DVec3;

/// The hit point moved off the surface, to the side `w` points to (see the
/// module docs). Non-finite when the error is (an uncertified hit).
fn offset_origin(hit: &Hit, w: DVec3) -> DVec3 {
    let n = hit.normal;
    let delta = n.abs().dot(hit.error) * (1.0 + gamma(8));
    let offset = if w.dot(n) < 0.0 {
        -n * delta
    } else {
        n * delta
    };
    let p = hit.point + offset;
    let away = |p: f64, o: f64| {
        if o > 0.0 {
            p.next_up()
        } else if o < 0.0 {
            p.next_down()
        } else {
            p
        }
    };
    DVec3::new(
        away(p.x, offset.x),
        away(p.y, offset.y),
        away(p.z, offset.z),
    )
}

/// A ray leaving the surface of `hit` along `direction`: its origin is the
/// hit point moved off the surface by the hit's certified error, to the
/// side `direction` points to, and rounded away from the surface (the
/// module docs derive it), so the ray does not meet the surface it leaves
/// again at the hit point. A direction tangent to the surface leaves on
/// the normal's side.
///
/// # Errors
/// As [`Ray::new`]: [`InputError::NonFinite`] naming `"direction"` for a
/// NaN or infinite direction and `"origin"` for a hit whose error is
/// infinite (no certified point to leave from) or a hit within its error
/// of `±f64::MAX` left outward (no finite origin lies off the surface
/// there); [`InputError::ZeroDirection`] for a zero direction.
pub fn spawn_ray(hit: &Hit, direction: impl IntoDVec3) -> Result<Ray, InputError> {
    let w = direction.into_dvec3();
    Ray::new(offset_origin(hit, w), w)
}

/// A ray from the surface of `hit` towards `point`, and the parameter
/// range that covers the segment up to the point, the point excluded: a
/// shadow ray. The origin is offset as by [`spawn_ray`], to the side the
/// point lies on; the direction is `point - origin`, rounded, and the
/// range `[0, 1)` (the largest double below 1 is the bound), so `origin +
/// direction` is `point` up to that rounding. Where that difference
/// overflows (a point on the far side of the range from the hit) the
/// direction is half of it, rounded as a segment's is
/// ([`TriangleMesh::occluded_between`](super::TriangleMesh::occluded_between)),
/// and the range `[0, 2)`. A point on another surface is within rounding
/// of that surface at the end of the range: offset it too (spawn from
/// both ends) where that matters.
///
/// ```
/// use exactray::prelude::*;
/// let vertices = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
/// let mesh = TriangleMesh::new(&vertices, &[[0, 1, 2]]).unwrap();
/// let ray = Ray::new([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]).unwrap();
/// let hit = mesh.closest_hit(&ray, Interval::FORWARD).unwrap().hit;
/// // A light above is visible; one below, behind the triangle, is not
/// // blocked by the triangle the ray leaves either.
/// let (shadow, range) = spawn_ray_to(&hit, [0.5, 0.5, 2.0]).unwrap();
/// assert!(!mesh.occluded(&shadow, range));
/// let (through, range) = spawn_ray_to(&hit, [0.1, 0.1, -2.0]).unwrap();
/// assert!(!mesh.occluded(&through, range));
/// ```
///
/// # Errors
/// [`InputError::NonFinite`] naming `"point"` for a NaN or infinite
/// point, `"origin"` as for [`spawn_ray`];
/// [`InputError::ZeroDirection`] when the point is the offset origin.
pub fn spawn_ray_to(hit: &Hit, point: impl IntoDVec3) -> Result<(Ray, Interval), InputError> {
    let q = point.into_dvec3();
    if !q.is_finite() {
        return Err(InputError::NonFinite { argument: "point" });
    }
    if !hit.point.is_finite() {
        return Err(InputError::NonFinite { argument: "origin" });
    }
    let origin = offset_origin(hit, difference(hit.point, q).0);
    let (d, halved) = difference(origin, q);
    let ray = Ray::new(origin, d)?;
    let end = if halved { 2.0 } else { 1.0 };
    Ok((ray, Interval::new(0.0, f64::next_down(end))?))
}

/// A segment between two finite points as the ray the walks and the
/// rounded triangle tests read, with the parameters that cover it.
///
/// Where `q - p` is finite the ray is `p + t fl(q - p)` over `[0, 1]`, as
/// it always was. Where it overflows (the ends are finite but on opposite
/// sides of the range, `|q_k - p_k| > f64::MAX` on some axis) the ray is
/// `p + t d'` over `[0, 2]`, with the halved difference `d'_k = fl(q_k -
/// p_k) / 2` on the axes where that difference is finite and `fl(q_k / 2
/// - p_k / 2)` on the others:
///
/// - on an axis that overflows both ends exceed `2^970` in magnitude (a
///   difference above `f64::MAX` needs it), so their halves are exact and
///   `d'_k` is `(q_k - p_k) / 2` times `1 + δ`, `|δ| <= u`;
/// - on another axis `fl(q_k - p_k)` is the difference times `1 + δ`, and
///   halving it is exact unless it is below `2^-1021`, where the
///   difference itself was exact (it is a multiple of `2^-1074` below
///   `2^53` of them) and the halving rounds once, by at most `2^-1075`.
///
/// So `d'_k = (q_k - p_k) / 2 (1 + δ) + η` with `|δ| <= u` and `|η| <=
/// 2^-1075`, never both non-zero: over `t` in `[0, 2]` the ray strays
/// from the exact segment `p + t (q - p) / 2` by the relative rounding of
/// one difference, as an ordinary segment's ray does, and by at most
/// `2^-1074` per axis more. The halved walk
/// (`bvh::boxes::walk_halved_segment`) covers that by one more step
/// outward on every box bound.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Segment {
    /// The ray `p + t d` (`d = fl(q - p)`, or `d'` above).
    pub(crate) ray: Ray,
    /// The exact far end `q`.
    pub(crate) q: DVec3,
    /// Whether the direction is the halved difference: the parameters are
    /// `[0, 2]`, not `[0, 1]`.
    pub(crate) halved: bool,
}

impl Segment {
    /// The segment from `p` to `q`, or `None` for `p == q`: what
    /// `occluded_between` asks of a mesh or a scene.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] naming `"p"` or `"q"` for a NaN or
    /// infinite coordinate.
    pub(crate) fn new(p: impl IntoDVec3, q: impl IntoDVec3) -> Result<Option<Segment>, InputError> {
        let (p, q) = (p.into_dvec3(), q.into_dvec3());
        if !p.is_finite() {
            return Err(InputError::NonFinite { argument: "p" });
        }
        if !q.is_finite() {
            return Err(InputError::NonFinite { argument: "q" });
        }
        let (d, halved) = difference(p, q);
        match Ray::new(p, d) {
            Ok(ray) => Ok(Some(Segment { ray, q, halved })),
            Err(InputError::ZeroDirection) => Ok(None),
            Err(e) => Err(e),
        }
    }

    /// The parameters that cover the segment, both ends included: `[0,
    /// 1]`, or `[0, 2]` for a halved direction.
    #[inline]
    pub(crate) fn range(&self) -> Interval {
        Interval::new(0.0, self.end()).unwrap_or(Interval::FORWARD)
    }

    /// The parameter of the far end: 1, or 2 for a halved direction.
    #[inline]
    pub(crate) fn end(&self) -> f64 {
        if self.halved { 2.0 } else { 1.0 }
    }
}

/// `fl(q - p)` and `false` where it is finite (finite ends), otherwise
/// the halved difference of [`Segment`]'s docs and `true`.
fn difference(p: DVec3, q: DVec3) -> (DVec3, bool) {
    let d = q - p;
    if d.is_finite() {
        return (d, false);
    }
    let half = |k: usize| {
        if d[k].is_finite() {
            d[k] * 0.5
        } else {
            q[k] * 0.5 - p[k] * 0.5
        }
    };
    (DVec3::new(half(0), half(1), half(2)), true)
}
