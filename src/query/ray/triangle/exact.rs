//! The exact ray–triangle test on a prepared ray ([`ExactRay`]): what
//! depends only on the ray (the axis of its direction's largest
//! coordinate, the direction permuted and scaled by a power of two) is
//! computed once, so that each triangle costs a filter over three 2D edge
//! functions of its sheared vertices, as in Woop, Benthin and Wald's
//! watertight test, but with a certified error bound.
//!
//! # The sheared edge functions
//! With the axes permuted so that the direction's largest coordinate `d_z`
//! comes last, and `a = v - o` a vertex relative to the origin, the shear
//! `x = d_z a_x - d_x a_z`, `y = d_z a_y - d_y a_z` (Woop et al.'s, times
//! `d_z`: no division) sends the direction to `(0, 0)`. For two vertices
//! `a_j, a_k`, eliminating `a_z d` from the rows of `det[d, a_j, a_k]`
//! multiplies it by `d_z^2` and leaves it `d_z (x_j y_k - y_j x_k)`, so
//! the 2D edge function `E_i = x_j y_k - y_j x_k` (`j = i + 1`, `k = i + 2`
//! modulo 3) equals `d_z det[d, a_j, a_k]` exactly: the same signs as the
//! edge determinants `orient_dir` decides (`predicates::orient_dir`), all
//! flipped where `d_z < 0`. A cyclic permutation of the axes leaves
//! determinants unchanged, and scaling the direction by a power of two
//! scales every `E_i` alike.
//!
//! # The filter's bound
//! [`edge_bound`] derives it; the signs it cannot certify (a ray within a
//! few units of rounding of an edge's line, relative to the distance from
//! the origin to the triangle over the triangle's size) go to the exact
//! stages of `orient_dir` one edge at a time, as do every sign of a ray
//! whose direction cannot be scaled exactly and of a triangle beyond the
//! filter's range.

use super::super::point_error::exact_t_error;
use super::plane_parameter::plane_parameter;
use super::{TriangleHit, closed, largest_axis, permute};
use crate::arith::exponent::pow2;
use crate::arith::magnitude::{larger, smaller};
use crate::arith::roundoff::{U, gamma};
use crate::interval::Interval;
use crate::predicates::orient_dir::orient_dir;
use crate::query::ray::Ray;
use crate::shape::Triangle;
use crate::sign::Sign;
use glam::DVec3;

/// Beyond this magnitude of `M` ([`edge_bound`]) the filter declines:
/// below it no sheared coordinate, no `z` difference and no product of two
/// of them overflows (they stay below `2^662`), and the absolute error of
/// underflowed products stays below [`ABS_SLACK`].
const FILTER_MAX: f64 = pow2(330);

/// The absolute error bound added to the filter for underflow. A product
/// that underflows is off by at most `2^-1075` beyond its relative
/// rounding: two such in each sheared coordinate add `2^-1074` to its
/// error, which the edge function multiplies by at most `2 (S + η) <
/// 2^332` twice, and its own two products add `2^-1074`; the bound's own
/// computation loses at most `2^-1075` per underflowed product, times at
/// most `M <= 2^330` ([`edge_bound`]). Together below `2^-738`.
const ABS_SLACK: f64 = pow2(-700);

/// A relative margin on the bound's constants for the bound's own
/// rounding: five operations (`4 Z + S`, `S C_MS`, `M C_MM`, their sum, the
/// product with `M`, the slack's addition), each within a relative `u`,
/// and the constants' own rounding, together below `2^-40`.
const MARGIN: f64 = 1.0 + 1.0 / (1u64 << 40) as f64;

/// `g = gamma(3) / (1 - gamma(3)) / (1 - u)`: a sheared coordinate's
/// error per unit of `M` ([`edge_bound`]).
const G: f64 = gamma(3) / (1.0 - gamma(3)) / (1.0 - U);

/// The bound's coefficient of `M S`: `4 g + 2 gamma(2)` (about `14 u`),
/// derived in [`edge_bound`].
const C_MS: f64 = (4.0 * G + 2.0 * gamma(2)) * MARGIN;

/// The bound's coefficient of `M^2`: `2 g^2` (about `18 u^2`), derived in
/// [`edge_bound`].
const C_MM: f64 = 2.0 * G * G * MARGIN;

/// A ray prepared for the exact ray–triangle test: the ray, the axis of
/// its direction's largest coordinate, and its direction permuted so that
/// that coordinate comes last and scaled by a power of two into `[1, 2)`.
/// Built once per ray ([`ExactRay::new`], a few nanoseconds), it answers
/// any number of triangles ([`ExactRay::cast`], [`ExactRay::cast_closed`])
/// exactly as [`Triangle::cast_exact`] and [`Triangle::cast_exact_closed`]
/// do (they prepare the ray and call these).
///
/// ```
/// use exactray::interval::Interval;
/// use exactray::query::ray::{ExactRay, Ray};
/// use exactray::shape::Triangle;
/// let ray = ExactRay::new(&Ray::new([0.25, 0.25, 5.0], [0.0, 0.0, -1.0]).unwrap());
/// let near = Triangle::new([0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]).unwrap();
/// let far = Triangle::new([0.0, 0.0, -1.0], [1.0, 0.0, -1.0], [0.0, 1.0, -1.0]).unwrap();
/// let ts = [near, far].map(|tri| ray.cast(&tri, Interval::FORWARD).unwrap().t);
/// assert_eq!(ts, [4.0, 6.0]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct ExactRay {
    ray: Ray,
    /// The axes `kx, ky, kz`: `kz` that of the direction's largest
    /// coordinate, the others following cyclically (`kx = kz + 1`, `ky =
    /// kz + 2`, modulo 3). Vertices are read through them, with no branch
    /// on the axis.
    axes: [usize; 3],
    /// The origin's coordinates `o_kx, o_ky, o_kz`.
    origin: [f64; 3],
    /// `d_kx, d_ky, d_kz` of the direction scaled by a power of two, `|d_kz|`
    /// in `[1, 2)` where the scaling is exact.
    d: [f64; 3],
    /// `1 / d_kz` of the scaled direction, rounded (in `(1/2, 1]`).
    inv_dz: f64,
    /// The scaling's power of two, `2^-e` for the direction multiplied by
    /// `2^-e`: a parameter is a `z` difference times `inv_dz` times
    /// `t_unit`. NaN where it is not a normal number (a subnormal `d_kz`).
    t_unit: f64,
    /// The largest vertex-to-origin magnitude the filter takes:
    /// [`FILTER_MAX`], or `-inf` where the direction cannot be scaled into
    /// `[1, 2)` exactly (then every sign is decided by the exact stages).
    filter_max: f64,
}

impl ExactRay {
    /// The ray prepared for the exact test. Every [`Ray`] is accepted (its
    /// coordinates are finite and its direction non-zero).
    #[inline]
    pub fn new(ray: &Ray) -> ExactRay {
        let (o, d) = (ray.origin(), ray.direction());
        let kz = largest_axis(d);
        let (origin, d) = match kz {
            0 => (permute::<0>(o), permute::<0>(d)),
            1 => (permute::<1>(o), permute::<1>(d)),
            _ => (permute::<2>(o), permute::<2>(d)),
        };
        let (d, exact, t_unit) = unit_scaled(d);
        ExactRay {
            ray: *ray,
            axes: [(kz + 1) % 3, (kz + 2) % 3, kz],
            origin,
            d,
            inv_dz: 1.0 / d[2],
            t_unit,
            filter_max: if exact { FILTER_MAX } else { f64::NEG_INFINITY },
        }
    }

    /// `ray` without its preparation: a filter that declines every
    /// triangle, so that each sign goes to the exact stages, for a caller
    /// that holds an `ExactRay` it will not cast with
    /// (`Exact::prepare_segment`). A cast with it still decides hit or miss
    /// and `t` exactly, but slowly, and its barycentrics may be the crude
    /// equal weights of the exact non-zero signs.
    #[inline]
    pub(super) fn unfiltered(ray: &Ray) -> ExactRay {
        ExactRay {
            ray: *ray,
            axes: [0, 1, 2],
            origin: ray.origin().to_array(),
            d: ray.direction().to_array(),
            inv_dz: f64::NAN,
            t_unit: f64::NAN,
            filter_max: f64::NEG_INFINITY,
        }
    }

    /// The ray as given.
    #[inline]
    pub fn ray(&self) -> &Ray {
        &self.ray
    }

    /// [`Triangle::cast_exact`] of `tri` for this ray: hit or miss decided
    /// exactly, `t` within [`EXACT_T_ULPS`](super::EXACT_T_ULPS) (4) units
    /// of rounding. Never allocates; a degenerate triangle and a ray lying
    /// in the triangle's plane are misses.
    #[inline]
    pub fn cast(&self, tri: &Triangle, range: Interval) -> Option<TriangleHit> {
        self.cast_rule::<false, true>(tri, range).map(|h| h.hit)
    }

    /// [`Triangle::cast_exact_closed`] of `tri` for this ray: as
    /// [`ExactRay::cast`], and a ray lying in the triangle's plane hits
    /// where it enters the closed triangle. Never allocates.
    #[inline]
    pub fn cast_closed(&self, tri: &Triangle, range: Interval) -> Option<TriangleHit> {
        self.cast_rule::<true, true>(tri, range).map(|h| h.hit)
    }

    /// The exact test's cheaper tier: hit or miss decided exactly, as
    /// [`ExactRay::cast`] decides it, and `t` with a certified bound on
    /// its error instead of within 4 units of rounding. Never allocates; a
    /// degenerate triangle and a ray lying in the triangle's plane are
    /// misses.
    ///
    /// `t` is the barycentric mean of the vertices' `z` differences,
    /// `Σ E_i z_i / (d_z Σ E_i)`, from the filter's own edge functions,
    /// with the bound derived in `bounded_parameter` (a few tens of
    /// nanoseconds cheaper per hit than [`ExactRay::cast`]'s
    /// double-double): about a hundred units of rounding of `t` on ordinary
    /// rays (the true error is usually one or two). Where that bound
    /// exceeds [`BOUNDED_T_ULPS`] (1024) units of rounding (a ray nearly
    /// parallel to the plane, an origin nearly on it, a subnormal `t`), or
    /// where a sign needed the exact stages, `t` is [`ExactRay::cast`]'s,
    /// with its 4-unit bound. So `|t - t_exact| <= t_error <= 1024 * 2^-53
    /// |t| + 2^-1073`, and `t`'s sign is exact: [`Interval::FORWARD`]'s `t
    /// >= 0` is decided exactly; an exact `t` within `t_error` of another
    /// finite end of `range` may be placed on either side of it.
    ///
    /// ```
    /// use exactray::interval::Interval;
    /// use exactray::query::ray::{ExactRay, Ray};
    /// use exactray::shape::Triangle;
    /// let tri = Triangle::new([0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 3.0]).unwrap();
    /// let ray = ExactRay::new(&Ray::new([0.1, 0.2, -1.0], [0.05, 0.05, 1.0]).unwrap());
    /// let bounded = ray.cast_bounded(&tri, Interval::FORWARD).unwrap();
    /// let precise = ray.cast(&tri, Interval::FORWARD).unwrap();
    /// assert!((bounded.hit.t - precise.t).abs() <= bounded.t_error);
    /// ```
    #[inline]
    pub fn cast_bounded(&self, tri: &Triangle, range: Interval) -> Option<BoundedTriangleHit> {
        self.cast_rule::<false, false>(tri, range)
    }

    /// The common cases straight through: three certified signs that
    /// differ (a miss) or agree (a hit); the others in [`uncertain_cast`].
    /// `PRECISE`: `t` within 4 units of rounding, else with the bound of
    /// `ExactRay::bounded_parameter` where it separates `t` from zero.
    #[inline(always)]
    fn cast_rule<const CLOSED: bool, const PRECISE: bool>(
        &self,
        tri: &Triangle,
        range: Interval,
    ) -> Option<BoundedTriangleHit> {
        if tri.degenerate {
            // Its three exact signs are mixed or all zero: always a miss.
            return None;
        }
        let edges = self.edges(tri);
        let (e, bound) = (edges.e, edges.bound);
        let (low, high) = (
            smaller(smaller(e[0], e[1]), e[2]),
            larger(larger(e[0], e[1]), e[2]),
        );
        if low < -bound && high > bound {
            // Two certified opposite signs.
            return None;
        }
        if !(low > bound || high < -bound) {
            // The signs of `det[d, a_j, a_k]` are those of `E_i` times
            // `d_z`'s; the barycentrics are ratios, unchanged.
            let w = if self.d[2] < 0.0 { e.map(|x| -x) } else { e };
            return uncertain_cast::<CLOSED>(tri, &self.ray, range, w, bound).map(precise);
        }
        // Three certified signs alike: a hit of the line, inside the
        // triangle; `E_i / Σ E` are the barycentrics.
        // One division: `1 / Σ E` is a normal number (`3 B <= |Σ E| <
        // 2^664`).
        let inv_total = 1.0 / (e[0] + e[1] + e[2]);
        let (t, t_error) = if PRECISE {
            precise_parameter(&self.ray, tri)
        } else {
            self.bounded_parameter(&edges, inv_total)
                .unwrap_or_else(|| precise_parameter(&self.ray, tri))
        };
        if !range.admits(t) {
            return None;
        }
        Some(BoundedTriangleHit {
            hit: TriangleHit {
                t,
                u: e[1] * inv_total,
                v: e[2] * inv_total,
            },
            t_error,
        })
    }

    /// `fl(v - o)` in the order `kx, ky, kz`.
    #[inline(always)]
    fn relative(&self, v: &DVec3) -> [f64; 3] {
        let ([kx, ky, kz], o) = (self.axes, self.origin);
        let v = v.as_ref();
        [v[kx] - o[0], v[ky] - o[1], v[kz] - o[2]]
    }

    /// The rounded edge functions of `tri`'s sheared vertices and the
    /// bound on their errors.
    #[inline(always)]
    fn edges(&self, tri: &Triangle) -> Edges {
        let [v0, v1, v2] = &tri.v;
        let a = [self.relative(v0), self.relative(v1), self.relative(v2)];
        let [dx, dy, dz] = self.d;
        let x = a.map(|a| dz * a[0] - dx * a[2]);
        let y = a.map(|a| dz * a[1] - dy * a[2]);
        let e = [
            x[1] * y[2] - y[1] * x[2],
            x[2] * y[0] - y[2] * x[0],
            x[0] * y[1] - y[0] * x[1],
        ];
        let z = [a[0][2], a[1][2], a[2][2]];
        let z_max = larger(larger(z[0].abs(), z[1].abs()), z[2].abs());
        // Pairwise, so that the maxima can be taken two lanes at a time.
        let m = [
            larger(larger(x[0].abs(), x[1].abs()), x[2].abs()),
            larger(larger(y[0].abs(), y[1].abs()), y[2].abs()),
        ];
        let s = larger(m[0], m[1]);
        Edges {
            e,
            bound: edge_bound(s, z_max, self.filter_max),
            z,
            z_max,
        }
    }
}

/// A hit of [`ExactRay::cast_bounded`]: the hit, and a certified bound on
/// the error of its `t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundedTriangleHit {
    /// The hit, as [`ExactRay::cast`] would report it but for `t`.
    pub hit: TriangleHit,
    /// `|hit.t - t_exact| <= t_error`, for `t_exact` the exact parameter
    /// where the ray's line crosses the triangle's plane.
    pub t_error: f64,
}

/// A triangle's rounded edge functions `E_i` for a prepared ray, the bound
/// on their errors ([`edge_bound`]; infinite where the filter declines),
/// and the rounded `z` differences `fl(v_kz - o_kz)` with their largest
/// magnitude.
struct Edges {
    e: [f64; 3],
    bound: f64,
    z: [f64; 3],
    z_max: f64,
}

/// The precise tier's parameter, `t` within 4 units of rounding
/// (`plane_parameter`), and its bound as an error.
#[inline(always)]
fn precise_parameter(ray: &Ray, tri: &Triangle) -> (f64, f64) {
    let t = plane_parameter(ray, &tri.v);
    (t, exact_t_error(t))
}

/// A hit of the precise tier as a [`BoundedTriangleHit`].
#[inline(always)]
fn precise(hit: TriangleHit) -> BoundedTriangleHit {
    BoundedTriangleHit {
        hit,
        t_error: exact_t_error(hit.t),
    }
}

/// The bounded tier's promise ([`ExactRay::cast_bounded`]): `|t -
/// t_exact| <= t_error <= BOUNDED_T_ULPS * 2^-53 * |t| + 2^-1073`.
pub const BOUNDED_T_ULPS: f64 = 1024.0;

/// `2^-1072`: `ExactRay::bounded_parameter`'s absolute term for underflow in its
/// numerator.
const TINY_4: f64 = f64::from_bits(4);

/// `2^-1074`: `ExactRay::bounded_parameter`'s absolute term for an underflowed
/// quotient (at most `2^-1075`).
const TINY_1: f64 = f64::from_bits(1);

/// `gamma(10)`, the bounded parameter's rounding coefficient per unit of
/// `Z` (`ExactRay::bounded_parameter`).
const C_ROUND: f64 = gamma(10);

/// `gamma(3)`, the bounded parameter's rounding coefficient per unit of
/// `|t|` (`ExactRay::bounded_parameter`).
const C_UNIT: f64 = gamma(3);

impl ExactRay {
    /// The bounded tier's `t` and its error bound, from edge functions
    /// whose three signs the filter certified alike (`inv_total =
    /// fl(1 / fl(Σ E~_i))`): `t = fl(fl(fl(Σ E~_i z~_i) inv_total) inv_dz)
    /// t_unit`. `None` where the bound exceeds [`BOUNDED_T_ULPS`] units of
    /// rounding of `t` (then it is not finite, nor does it reach `t`'s
    /// sign, or `t` is subnormal, or the ray is nearly parallel to the
    /// plane, or its origin nearly on it), or where `t` overflowed.
    ///
    /// The exact `t* = τ* / d_z` with `τ* = Σ E_i z_i / Σ E_i` (exact
    /// values: the crossing's barycentrics weigh the vertices' `z`
    /// differences), a mean of the `z_i` with weights of one sign. With
    /// `τ1 = Σ E~_i z_i / Σ E~_i` (exact `z`, computed `E~`), the
    /// difference `τ1 - τ*` is `Σ (E~_i - E_i) (z_i - τ*) / Σ E~_i` (the
    /// `E_i (z_i - τ*)` sum to zero), so `|τ1 - τ*| <= 2 B Z_s / |Σ E~|`:
    /// each `|E~_i - E_i| <= B` ([`edge_bound`]), and the three distances
    /// from a mean of them sum to at most twice their spread `Z_s`, itself
    /// below the rounded one plus `2u Z` (`Z` the largest `|z~_i|`, `|z_i|
    /// <= Z / (1 - u)`). The numerator rounds each term at most four times
    /// (the difference `z~`, the product, two sums): `gamma(4) Σ |E~_i|
    /// |z_i| <= gamma(4) |Σ E~| Z / (1 - u)`; the sum of three terms of one
    /// sign is within `gamma(2)`, its reciprocal and the product with it
    /// within `u` each: together within `(gamma(4) (1 + u) + gamma(2) +
    /// 2u) Z / ((1 - gamma(2)) (1 - u)^2) <= gamma(10) Z` ([`C_ROUND`]) of
    /// `τ1`, since `|τ1| <= Z / (1 - u)`. Then `inv_dz` and the product
    /// with it round once each, and `t_unit`, a power of two, is exact but
    /// for underflow (overflow makes `t` infinite, which is refused):
    /// within `gamma(3) |t|` of `τ / d_z`. Underflow adds at most
    /// `2^-1073` to the numerator (three products; sums of subnormals are
    /// exact) and `2^-1075` to each product after it. So
    ///
    /// `|t - t*| <= ((2 B (Z_s + 2u Z) + 2^-1072) |inv_total| +
    /// gamma(10) Z + 2^-1074) / |d_z| + gamma(3) |t| + 2^-1074`,
    ///
    /// with `1 / |d_z| <= |inv_dz| t_unit / (1 - u)`, and the factors `1 +
    /// gamma(2)` and `1 / (1 - u)^2` for `|inv_total|` against `1 / |Σ
    /// E~|` and the bound's own roundings (about ten) inside [`MARGIN`]
    /// twice.
    #[inline(always)]
    fn bounded_parameter(&self, edges: &Edges, inv_total: f64) -> Option<(f64, f64)> {
        let (e, z) = (edges.e, edges.z);
        let t = (e[0] * z[0] + e[1] * z[1] + e[2] * z[2]) * inv_total * self.inv_dz * self.t_unit;
        let spread = larger(larger(z[0], z[1]), z[2]) - smaller(smaller(z[0], z[1]), z[2]);
        let tau_error = (2.0 * edges.bound * (spread + 2.0 * U * edges.z_max) + TINY_4)
            * inv_total.abs()
            + C_ROUND * edges.z_max
            + TINY_1;
        let t_error = (tau_error * self.inv_dz.abs() * self.t_unit + C_UNIT * t.abs() + TINY_1)
            * (MARGIN * MARGIN);
        (t_error <= BOUNDED_T_ULPS * U * t.abs() && t.abs() <= f64::MAX).then_some((t, t_error))
    }
}

/// `p` scaled by the power of two `2^-e` that puts `|p[2]|` (non-zero, the
/// largest) in `[1, 2)`, whether that scaling is exact, and `2^-e` (NaN
/// where it is not a normal number). Scaling down may lose the low bits of
/// a much smaller coordinate, which scaling back up (exact) detects; the
/// scaling is not exact either for `|p[2]| >= 2^1023`, whose factor
/// `2^-1023` is not a normal number (`p` is returned unscaled then).
#[inline(always)]
fn unit_scaled(p: [f64; 3]) -> ([f64; 3], bool, f64) {
    let biased = |x: f64| ((x.to_bits() >> 52) & 0x7ff) as i32;
    // A subnormal `p[2]` first becomes normal: scaling up is exact; the
    // whole factor `2^(64 - e)` is then beyond the normal numbers.
    let subnormal = biased(p[2]) == 0;
    let pre = if subnormal { pow2(64) } else { 1.0 };
    let p = [p[0] * pre, p[1] * pre, p[2] * pre];
    let e = biased(p[2]) - 1023;
    if e > 1022 {
        return (p, false, f64::NAN);
    }
    let (down, up) = (pow2(-e), pow2(e));
    let d = [p[0] * down, p[1] * down, p[2] * down];
    let exact = d[0] * up == p[0] && d[1] * up == p[1] && d[2] * up == p[2];
    (d, exact, if subnormal { f64::NAN } else { down })
}

/// The error bound of the rounded edge functions, from `S`, the largest
/// magnitude of a rounded sheared coordinate, and `Z`, the largest
/// magnitude of a rounded `fl(v_z - o_z)`; infinite (the filter declines)
/// when `M = fl(S + 4 Z)` exceeds `filter_max` ([`FILTER_MAX`], or `-inf`
/// for a direction that could not be scaled).
///
/// With `D = |d_z|` in `[1, 2)` and `|d_x|, |d_y| <= D`, each sheared
/// coordinate is two products and a difference of the rounded differences
/// `a~ = fl(v - o)`: three roundings on each term (Higham, Lemma 3.1), so
/// against the exact `x = d_z a_x - d_x a_z`, `|x~ - x| <= gamma(3) (|d_z
/// a_x| + |d_x a_z|)`. Since `|d_z a_x| <= |x| + |d_x a_z|`, `|d_x| <= D <
/// 2`, `|a_z| <= Z / (1 - u)` and `|x| <= S + |x~ - x|`, this is at most
/// `gamma(3) (S + |x~ - x| + 4 Z / (1 - u))`, so `|x~ - x| <= g M = η` with
/// `g = gamma(3) / (1 - gamma(3)) / (1 - u)` ([`G`]; `M` rounded down by at
/// most a relative `u`, inside [`MARGIN`]). Then, for `E = x_j y_k - y_j
/// x_k`, `|x~_j y~_k - x_j y_k| <= |x~_j - x_j| |y~_k| + |x_j| |y~_k - y_k|
/// <= η S + (S + η) η`, the same for the other product, and the two
/// products and their difference round within `gamma(2) (|x~_j y~_k| +
/// |y~_j x~_k|) <= 2 gamma(2) S^2`:
///
/// `|E~ - E| <= 4 η S + 2 η^2 + 2 gamma(2) S^2 <= (4 g + 2 gamma(2)) M S +
/// 2 g^2 M^2`
///
/// (`S <= M`), the coefficients [`C_MS`] and [`C_MM`]; underflow adds at
/// most [`ABS_SLACK`]. The check `M <= FILTER_MAX` also rules out overflow:
/// a non-finite `fl(v - o)` or product makes some sheared coordinate
/// infinite (`S`, and `M`, infinite) or, through `d_x a_z`, makes `Z`
/// huge. The bound is relative to the distance `M` times the triangle's
/// spread `S` about the ray's line: a ray escapes the filter only within a
/// relative `14 u M / S` of an edge's line.
#[inline(always)]
fn edge_bound(s: f64, z: f64, filter_max: f64) -> f64 {
    let m = 4.0 * z + s;
    if m <= filter_max {
        m * (s * C_MS + m * C_MM) + ABS_SLACK
    } else {
        f64::INFINITY
    }
}

/// The exact cast where the filter left some of the three signs of `w`
/// (the rounded edge determinants, or positive multiples of them) beyond
/// `bound` uncertain: the others exact (`orient_dir`), then the hit as for
/// certified signs, with the barycentrics of the zero signs zero. All three
/// signs zero (a ray in the plane, or a degenerate triangle) is a miss, or
/// with `CLOSED` the coplanar entry (`closed::coplanar_hit`).
#[cold]
#[inline(never)]
fn uncertain_cast<const CLOSED: bool>(
    tri: &Triangle,
    ray: &Ray,
    range: Interval,
    w: [f64; 3],
    bound: f64,
) -> Option<TriangleHit> {
    let (o, d) = (ray.origin(), ray.direction());
    let s = [0, 1, 2].map(|i| {
        if w[i] > bound {
            Sign::Positive
        } else if w[i] < -bound {
            Sign::Negative
        } else {
            orient_dir(d, o, tri.v[(i + 1) % 3], tri.v[(i + 2) % 3])
        }
    });
    let has = |x: Sign| s.contains(&x);
    let side = match (has(Sign::Positive), has(Sign::Negative)) {
        (true, true) => return None,
        (false, false) if CLOSED => return closed::coplanar_hit(tri, ray, range),
        (false, false) => return None,
        (true, false) => 1.0,
        (false, true) => -1.0,
    };
    let t = plane_parameter(ray, &tri.v);
    if !range.admits(t) {
        return None;
    }
    let (u, v) = barycentrics(w, s, side);
    Some(TriangleHit { t, u, v })
}

/// Barycentrics `(u, v)` from the rounded determinants `w`, on the exact
/// side: zero where the exact sign `s` is, never negative.
#[inline(always)]
fn barycentrics(w: [f64; 3], s: [Sign; 3], side: f64) -> (f64, f64) {
    let wz = [0, 1, 2].map(|i| {
        if s[i] == Sign::Zero {
            0.0
        } else {
            (w[i] * side).max(0.0)
        }
    });
    let total = wz[0] + wz[1] + wz[2];
    if total > 0.0 && total.is_finite() {
        (wz[1] / total, wz[2] / total)
    } else {
        // Every rounded determinant vanished or overflowed while the
        // exact signs did not: weigh the non-zero ones equally.
        let nz = s.map(|x| (x != Sign::Zero) as u8 as f64);
        let k = nz[0] + nz[1] + nz[2];
        (nz[1] / k, nz[2] / k)
    }
}

/// The filter's certified signs on directions whose largest coordinate
/// is subnormal, and on the rays of a fuzzer finding; an unfiltered ray
/// against a prepared one.
#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{RayTriangleClass, SplitMix64, ray_triangle_case};

    /// A ray that skipped its preparation (`ExactRay::unfiltered`, every
    /// sign from the exact stages) hits and misses as the prepared one and
    /// reports the same `t`, on every input class.
    #[test]
    fn unfiltered_rays_answer_as_prepared_ones() {
        let mut hits = 0;
        for class in RayTriangleClass::ALL {
            let mut rng = SplitMix64::new(0x5e9);
            for _ in 0..300 {
                let (o, d, v) = ray_triangle_case(class, &mut rng);
                let (Ok(ray), Ok(tri)) = (Ray::new(o, d), Triangle::new(v[0], v[1], v[2])) else {
                    continue;
                };
                let t = |r: ExactRay| r.cast_closed(&tri, Interval::FORWARD).map(|h| h.t);
                let prepared = t(ExactRay::new(&ray));
                assert_eq!(t(ExactRay::unfiltered(&ray)), prepared, "{o:?} {d:?} {v:?}");
                hits += prepared.is_some() as u32;
            }
        }
        assert!(hits > 300, "{hits}");
    }

    /// Every sign the filter certifies is the exact one, on directions
    /// whose largest coordinate is subnormal (and their multiples by
    /// `2^k`): a fuzzer finding, a huge and nearly flat triangle
    /// where an earlier filter's bound underflowed to zero and a wrong sign
    /// was certified; and a huge well-shaped triangle, whose signs the
    /// filter must still certify.
    #[test]
    fn certified_signs_are_exact_for_subnormal_directions() {
        let b = f64::from_bits;
        let finding = crate::testing::ray_triangle_finding(0).expect("the recorded fuzzer finding");
        let big = pow2(200);
        let well_shaped = (
            DVec3::ZERO,
            DVec3::new(b(3), b(5), b(1 << 40)),
            [
                DVec3::new(-1.0, -1.0, 1.0),
                DVec3::new(1.0, -1.0, 1.0),
                DVec3::new(0.0, 1.0, 1.0),
            ]
            .map(|p| p * big),
        );
        for (case, (o, d, v)) in [finding, well_shaped].into_iter().enumerate() {
            let mut certified = 0;
            for k in 0..60 {
                let d = d * pow2(k);
                let ray = ExactRay::new(&Ray::new(o, d).expect("a finite ray"));
                let tri = Triangle::new(v[0], v[1], v[2]).expect("finite vertices");
                let Edges { e, bound, .. } = ray.edges(&tri);
                for i in 0..3 {
                    if e[i].abs() > bound {
                        certified += 1;
                        let exact = orient_dir(d, o, v[(i + 1) % 3], v[(i + 2) % 3]);
                        let dz = Sign::of_f64(ray.d[2]);
                        assert_eq!(
                            Sign::of_f64(e[i]),
                            if dz == Sign::Negative { -exact } else { exact },
                            "case {case}, 2^{k} d, edge {i}: {:e}",
                            e[i]
                        );
                    }
                }
            }
            // The finding is too ill-conditioned for the filter at any
            // scale; the well-shaped triangle is certified at every one.
            assert_eq!(certified, [0, 180][case], "case {case}");
        }
    }
}
