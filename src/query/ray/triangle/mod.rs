//! Ray–triangle intersection in three variants, each returning the ray
//! parameter `t` and the barycentric coordinates of the hit:
//!
//! | variant | on a shared edge or vertex | `t` | cost |
//! |---|---|---|---|
//! | [`Triangle::cast_mt`] (Möller–Trumbore) | may miss on both sides | rounded formula | the reference |
//! | [`Triangle::cast_watertight`] (Woop, Benthin, Wald) | never missed on both sides | rounded formula | about the same |
//! | [`Triangle::cast_exact`] | decided exactly | within 4 ulps | about 2.7x; more within a few ulps of an edge |
//! | [`ExactRay::cast`] (the ray prepared once) | decided exactly | within 4 ulps | about 2.2x per triangle |
//! | [`ExactRay::cast_bounded`] (the ray prepared once) | decided exactly | with a certified bound, at most 1024 ulps | about 1.7x per triangle |
//!
//! A mesh prepares each ray once for all the triangles it meets
//! ([`TriangleTest`]): for the exact test, an [`ExactRay`] (about as long
//! as one Möller–Trumbore test) holds the axis of the direction's largest
//! coordinate and the direction scaled into `[1, 2)`, and each triangle
//! costs a certified filter over three 2D edge functions of its sheared
//! vertices (`exact.rs`), then the exact stages only for an edge within a
//! few units of rounding of the ray; `t` is the double-double plane
//! parameter (`plane_parameter.rs`), or in the bounded tier the filter's
//! own barycentric mean with a derived bound.
//!
//! Every variant takes a parameter [`Interval`] and reports the hit only
//! when its computed `t` is finite and lies in it ([`Interval::admits`]):
//! a crossing whose parameter lies beyond `f64`'s range is no hit, the
//! policy of every cast in the crate. A degenerate triangle (collinear vertices,
//! decided exactly when it is built) is always a miss. A ray whose line
//! lies in the triangle's plane (a coplanar ray) or runs parallel to it is
//! always a miss for the exact variant, and for the others wherever their
//! rounded determinant comes out zero (see each).
//! [`Triangle::cast_exact_closed`] is the exact variant under the scene's
//! closed-triangle rule: a coplanar ray hits where it enters the triangle
//! (`closed.rs`, with the exact order of two triangles' parameters and the
//! exact segment test [`Triangle::meets_segment_exact`]).
//!
//! The barycentric coordinates `u` (of `v1`) and `v` (of `v2`) place the
//! hit at `(1 - u - v) v0 + u v1 + v v2` ([`TriangleHit::point`]).
//!
//! References: T. Möller and B. Trumbore, "Fast, Minimum Storage
//! Ray/Triangle Intersection", Journal of Graphics Tools 2(1), 1997;
//! S. Woop, C. Benthin and I. Wald, "Watertight Ray/Triangle
//! Intersection", Journal of Computer Graphics Techniques 2(1), 2013.

use super::{Hit, RayCast};
use crate::interval::Interval;
use crate::point::IntoDVec3;
use crate::query::ray::Ray;
use plane_parameter::plane_parameter;

mod closed;
mod exact;
mod plane_parameter;
mod variant;
mod watertight;

use crate::shape::Triangle;
pub use exact::{BOUNDED_T_ULPS, BoundedTriangleHit, ExactRay};
use glam::DVec3;
pub use variant::{Exact, MollerTrumbore, TriangleTest, Watertight, WatertightRay};
use watertight::Shear;

/// Where a ray meets a triangle: the ray parameter and the barycentric
/// coordinates of the hit point.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TriangleHit {
    /// The ray parameter: the hit is at `origin + t * direction`.
    pub t: f64,
    /// The barycentric coordinate of `v1`, in `[0, 1]`.
    pub u: f64,
    /// The barycentric coordinate of `v2`, in `[0, 1]`; `u + v <= 1` up to
    /// rounding.
    pub v: f64,
}

impl TriangleHit {
    /// The hit point from the barycentric coordinates, `(1 - u - v) v0 +
    /// u v1 + v v2` (rounded); it lies in the triangle up to rounding,
    /// where `ray.at(t)` may lie off its plane by the error of `t`.
    ///
    /// ```
    /// use exactray::interval::Interval;
    /// use exactray::query::ray::Ray;
    /// use exactray::shape::Triangle;
    /// let tri = Triangle::new([0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]).unwrap();
    /// let ray = Ray::new([1.0, 2.0, 5.0], [0.0, 0.0, -1.0]).unwrap();
    /// let hit = tri.cast_exact(&ray, Interval::FORWARD).unwrap();
    /// assert_eq!((hit.t, hit.u, hit.v), (5.0, 0.25, 0.5));
    /// assert_eq!(hit.point(&tri).to_array(), [1.0, 2.0, 0.0]);
    /// ```
    #[inline]
    pub fn point(&self, triangle: &Triangle) -> DVec3 {
        let [v0, v1, v2] = triangle.v;
        v0 * (1.0 - self.u - self.v) + v1 * self.u + v2 * self.v
    }
}

/// The exact variant's promise: `|t - t_exact| <= T_ULPS * 2^-53 * |t_exact|`.
pub const EXACT_T_ULPS: f64 = 4.0;

impl Triangle {
    /// Möller–Trumbore: the textbook fast test, `t`, `u` and `v` from
    /// three triple products divided by `det = (v1 - v0) . (d x (v2 - v0))`.
    ///
    /// The hit test is on rounded barycentrics: a ray aimed at an edge
    /// shared by two triangles can miss both (the two triangles compute
    /// that edge's coordinate from different operands). Coplanar rays and
    /// rays parallel to the plane give `det == 0` in exact arithmetic; a
    /// `det` that computes as zero is a miss, one that rounds away from
    /// zero may give a hit. A degenerate triangle is a miss. No division by
    /// zero and no NaN reaches the answer: overflowing products fail the
    /// comparisons and miss.
    ///
    /// ```
    /// use exactray::interval::Interval;
    /// use exactray::query::ray::Ray;
    /// use exactray::shape::Triangle;
    /// let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    /// let ray = Ray::new([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]).unwrap();
    /// assert_eq!(tri.cast_mt(&ray, Interval::FORWARD).unwrap().t, 1.0);
    /// ```
    #[inline]
    pub fn cast_mt(&self, ray: &Ray, range: Interval) -> Option<TriangleHit> {
        if self.degenerate {
            return None;
        }
        let [v0, v1, v2] = self.v;
        let (o, d) = (ray.origin(), ray.direction());
        let (e1, e2) = (v1 - v0, v2 - v0);
        let p = d.cross(e2);
        let det = e1.dot(p);
        // NaN: overflowed products.
        if det == 0.0 || det.is_nan() {
            return None;
        }
        let inv = 1.0 / det;
        let s = o - v0;
        let u = s.dot(p) * inv;
        if !(0.0..=1.0).contains(&u) {
            return None;
        }
        let q = s.cross(e1);
        let v = d.dot(q) * inv;
        if !(v >= 0.0 && u + v <= 1.0) {
            return None;
        }
        let t = e2.dot(q) * inv;
        range.admits(t).then_some(TriangleHit { t, u, v })
    }

    /// Watertight (Woop, Benthin and Wald 2013): the vertices are moved to
    /// the ray's origin and sheared so that the ray runs along an axis,
    /// then tested by 2D edge functions.
    ///
    /// Each vertex is sheared on its own, and an edge's function uses only
    /// its two sheared vertices, computed as `x_q y_p - y_q x_p` with no
    /// fused operations: the triangle on the other side of a shared edge
    /// computes exactly the negated value. So a ray through a shared edge
    /// or vertex of a closed or tiled mesh is never missed by all the
    /// triangles around it; it may hit two of them (an edge function that
    /// rounds to zero counts as inside on both sides).
    ///
    /// The shear is Woop et al.'s (axis `kz` of the direction's largest
    /// coordinate, the others sheared by `d_k / d_kz`) multiplied through
    /// by `d_kz`, after scaling the direction by a power of two so that
    /// `|d_kz|` lies in `[1, 2)`: no division per vertex and the same
    /// magnitudes as theirs. The per-vertex rounding that makes it
    /// watertight also makes it inexact: rays within a few ulps of an edge
    /// may be classified on the wrong side of it (consistently for both
    /// triangles). Coplanar and parallel rays give a zero determinant in
    /// exact arithmetic: a miss where it computes as zero, possibly a hit
    /// where it rounds away from zero. A degenerate triangle is a miss.
    ///
    /// # Every scale
    /// Both guarantees hold for every finite input, from coordinates near
    /// `2^-1074` to near `f64::MAX`: no false miss at a shared edge or
    /// vertex, and a hit only where the ray passes within a few units of
    /// rounding (relative to the vertices' coordinates about the origin)
    /// of the closed triangle. Where the edge functions' products or the
    /// parameter's numerator would overflow or underflow (sheared
    /// coordinates beyond about `2^±340`, or a vertex about `f64::MAX`
    /// from the origin), the same test is evaluated again at powers of two
    /// chosen from the values, consistently for the triangles sharing an
    /// edge; everywhere else the arithmetic is the rounded formula above
    /// (the module `watertight.rs` gives the argument).
    ///
    /// ```
    /// use exactray::interval::Interval;
    /// use exactray::query::ray::Ray;
    /// use exactray::shape::Triangle;
    /// // Two triangles sharing the diagonal of the unit square; a ray
    /// // through a point of the diagonal hits at least one of them.
    /// let a = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]).unwrap();
    /// let b = Triangle::new([0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    /// let ray = Ray::new([-0.4, 0.1, 1.0], [0.7, 0.2, -1.0]).unwrap();
    /// let hits = [a, b].into_iter().filter(|t| t.cast_watertight(&ray, Interval::FORWARD).is_some());
    /// assert!(hits.count() >= 1);
    /// // The same square and ray scaled by 2^600, where the edge functions'
    /// // products overflow: the same answers, t unchanged.
    /// let s = 2f64.powi(600);
    /// let scaled = |t: &Triangle| {
    ///     let [p, q, r] = t.vertices();
    ///     Triangle::new(p * s, q * s, r * s).unwrap()
    /// };
    /// let far = Ray::new([-0.4 * s, 0.1 * s, s], [0.7 * s, 0.2 * s, -s]).unwrap();
    /// for t in [a, b] {
    ///     let near = t.cast_watertight(&ray, Interval::FORWARD);
    ///     assert_eq!(scaled(&t).cast_watertight(&far, Interval::FORWARD), near);
    /// }
    /// ```
    #[inline]
    pub fn cast_watertight(&self, ray: &Ray, range: Interval) -> Option<TriangleHit> {
        if self.degenerate {
            return None;
        }
        Shear::of(ray).cast(self, range)
    }

    /// Exact: hit or miss decided by exact signs on the original
    /// coordinates, and `t` within [`EXACT_T_ULPS`] (4) units of rounding
    /// of the exact parameter: `|t - t_exact| <= 4 * 2^-53 * |t_exact|` for
    /// a normal `t`, `2^-1073` absolutely for a subnormal one.
    ///
    /// With `a_i = v_i - o` the exact differences, the line `o + s d` meets
    /// the closed triangle exactly when the three signs of `det[d, a_1,
    /// a_2]`, `det[d, a_2, a_0]`, `det[d, a_0, a_1]` are all `>= 0` or all
    /// `<= 0`, not all zero (all zero: the line lies in the triangle's plane,
    /// a miss, or the triangle is degenerate). Edges and vertices belong to
    /// the triangle: a ray through a shared edge hits both triangles.
    /// Each sign comes from a floating-point filter, or when the filter
    /// cannot certify it, from the crate's exact orient3d machinery.
    /// This prepares the ray ([`ExactRay::new`]) and tests the triangle
    /// with it ([`ExactRay::cast`]): to test many triangles with one ray,
    /// prepare it once.
    ///
    /// `t` is `det[a_0, e_1, e_2] / det[d, e_1, e_2]`, each determinant
    /// within `1.45 u` of its value, then divided (`u = 2^-53`). A filtered
    /// stage evaluates both in double-double from error-free
    /// transformations and certifies them with a bound computed beside
    /// them; where it cannot (an origin within about `2^-45` of the plane
    /// relative to its distance from the triangle, or a direction within
    /// about `2^-45` radians of the plane) the
    /// determinants are evaluated exactly in integers and rounded once.
    /// (The plain `f64` formula's forward error bound cannot certify 4
    /// units: the bound of the numerator `(v0 - o) . ((v1 - v0) x (v2 -
    /// v0))` alone is 5 units times its condition number, which is at
    /// least 1.)
    /// Its sign is always exact (a `t` that would round to zero from a
    /// non-zero value is the smallest subnormal of that sign), so the
    /// bound `t >= 0` of [`Interval::FORWARD`] is decided exactly; other
    /// finite bounds are compared with the returned `t`, so an exact `t`
    /// within 4 ulps of a bound may be placed on either side of it.
    ///
    /// The barycentric coordinates are the three rounded determinants (up
    /// to a common factor) over their sum: exactly zero on the edges the
    /// ray meets, in `[0, 1]`.
    ///
    /// ```
    /// use exactray::interval::Interval;
    /// use exactray::query::ray::Ray;
    /// use exactray::shape::Triangle;
    /// let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    /// // 0.1 + 0.9 rounds to 1, but the doubles 0.1 and 0.9 sum to just
    /// // above 1: the ray passes outside the hypotenuse x + y = 1.
    /// let ray = Ray::new([0.1, 0.9, 1.0], [0.0, 0.0, -1.0]).unwrap();
    /// assert!(tri.cast_exact(&ray, Interval::FORWARD).is_none());
    /// // 0.25 + 0.75 is exactly 1: on the edge, a hit.
    /// let ray = Ray::new([0.25, 0.75, 1.0], [0.0, 0.0, -1.0]).unwrap();
    /// assert!(tri.cast_exact(&ray, Interval::FORWARD).is_some());
    /// // Edges belong to the triangle; the t of an axis-aligned ray is exact.
    /// let edge = Ray::new([0.5, 0.0, 2.0], [0.0, 0.0, -1.0]).unwrap();
    /// assert_eq!(tri.cast_exact(&edge, Interval::FORWARD).unwrap().t, 2.0);
    /// ```
    #[inline]
    pub fn cast_exact(&self, ray: &Ray, range: Interval) -> Option<TriangleHit> {
        ExactRay::new(ray).cast(self, range)
    }

    /// [`Triangle::cast_exact`] under the closed-triangle rule of the
    /// scene's exact queries (`docs/fixture-format.md`'s `ray_mesh`): the same answer for
    /// every ray not lying in the triangle's plane, and for a ray in its
    /// plane (the three edge signs exactly zero), which touches the closed
    /// triangle along a segment, the hit where it enters it within `range`:
    /// `t` is `range.min()` itself when the ray's point there lies in the
    /// triangle, otherwise the parameter where the ray crosses the first
    /// edge, within [`EXACT_T_ULPS`] (4) units of rounding of the exact
    /// one (kept inside `range`). Every decision, in the plane or not
    /// (which edge, whether the entry lies in `range`), is exact; the
    /// barycentrics are rounded from exact fractions, exactly zero on the
    /// edges the entry point lies on. The coplanar case costs some
    /// microseconds (integers of a few thousand bits); rays not in the
    /// plane cost what `cast_exact` costs.
    ///
    /// ```
    /// use exactray::interval::Interval;
    /// use exactray::query::ray::Ray;
    /// use exactray::shape::Triangle;
    /// let tri = Triangle::new([0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]).unwrap();
    /// // In the plane z = 0, entering through the edge x = 0 at t = 1.
    /// let ray = Ray::new([-1.0, 1.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    /// assert!(tri.cast_exact(&ray, Interval::FORWARD).is_none());
    /// let hit = tri.cast_exact_closed(&ray, Interval::FORWARD).unwrap();
    /// assert_eq!((hit.t, hit.u, hit.v), (1.0, 0.0, 0.25));
    /// // From inside: the hit is at the range's start.
    /// let inside = Ray::new([1.0, 1.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(tri.cast_exact_closed(&inside, Interval::FORWARD).unwrap().t, 0.0);
    /// ```
    #[inline]
    pub fn cast_exact_closed(&self, ray: &Ray, range: Interval) -> Option<TriangleHit> {
        ExactRay::new(ray).cast_closed(self, range)
    }

    /// Whether the closed segment from `p` to `q` meets the closed
    /// triangle, decided exactly on the segment itself (its end is `q`,
    /// not `p + fl(q - p)`): by the signs of `orient3d`, and for a segment
    /// in the triangle's plane by the exact coplanar span (as in
    /// [`Triangle::cast_exact_closed`]). A degenerate triangle, or a
    /// non-finite coordinate, is never met; `p == q` is met when that
    /// point lies on the triangle.
    ///
    /// ```
    /// use exactray::shape::Triangle;
    /// let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    /// assert!(tri.meets_segment_exact([0.25, 0.25, 1.0], [0.25, 0.25, -1.0]));
    /// // In the plane, ending exactly on the hypotenuse; then just short of it.
    /// assert!(tri.meets_segment_exact([2.0, 2.0, 0.0], [0.5, 0.5, 0.0]));
    /// assert!(!tri.meets_segment_exact([2.0, 2.0, 0.0], [0.5, 0.5000000000000001, 0.0]));
    /// ```
    #[inline]
    pub fn meets_segment_exact(&self, p: impl IntoDVec3, q: impl IntoDVec3) -> bool {
        closed::segment_meets(self, p.into_dvec3(), q.into_dvec3())
    }
}

/// The axis of `d`'s largest coordinate in magnitude (the first of equal
/// ones), `kz` of the watertight and exact tests' permutations.
#[inline(always)]
fn largest_axis(d: DVec3) -> usize {
    let a = d.abs();
    if a.x >= a.y {
        if a.x >= a.z { 0 } else { 2 }
    } else if a.y >= a.z {
        1
    } else {
        2
    }
}

/// `p`'s coordinates in the order `kx, ky, kz` for `kz = K`.
#[inline(always)]
fn permute<const K: usize>(p: DVec3) -> [f64; 3] {
    match K {
        0 => [p.y, p.z, p.x],
        1 => [p.z, p.x, p.y],
        _ => [p.x, p.y, p.z],
    }
}

impl RayCast for Triangle {
    /// The watertight hit ([`Triangle::cast_watertight`] decides hit or
    /// miss), with the unit normal `(v1 - v0) x (v2 - v0)` normalized (the
    /// front side, whichever side the ray comes from). A degenerate
    /// triangle is never hit; nor is one so thin that the cross product of
    /// its rounded edges vanishes (it has no unit normal to report).
    ///
    /// # Accuracy
    /// `t` is the parameter where the ray's line crosses the triangle's
    /// plane, within `4u` of the exact one (the exact variant's plane
    /// parameter, [`EXACT_T_ULPS`]), so [`Hit::error`] is certified; a hit
    /// whose line turns out parallel to the plane, or whose certified `t`
    /// leaves the range, is a miss.
    ///
    /// # Performance
    /// The certified `t` costs about as much as the watertight test again
    /// on a hit; [`Triangle::cast_watertight`] alone gives the rounded `t`.
    ///
    /// ```
    /// use exactray::query::ray::RayCast;
    /// use exactray::interval::Interval;
    /// use exactray::query::ray::Ray;
    /// use exactray::shape::Triangle;
    /// let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    /// let ray = Ray::new([0.25, 0.25, -2.0], [0.0, 0.0, 1.0]).unwrap();
    /// let hit = tri.cast(&ray, Interval::FORWARD).unwrap();
    /// assert_eq!((hit.t, hit.point.to_array()), (2.0, [0.25, 0.25, 0.0]));
    /// assert_eq!(hit.normal.to_array(), [0.0, 0.0, 1.0]);
    /// ```
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.cast_watertight(ray, range)?;
        let normal = self.normal();
        if normal == DVec3::ZERO {
            return None;
        }
        // The certified plane parameter, not the watertight formula's `t`
        // (which carries no bound): the hit point's error follows from it.
        let t = plane_parameter(ray, &self.v);
        range.admits(t).then(|| Hit::at_plane_t(ray, t, normal))
    }

    /// Whether [`RayCast::cast`] hits, without normalizing on a hit.
    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        self.cast_watertight(ray, range).is_some() && self.normal() != DVec3::ZERO
    }
}
