//! Woop, Benthin and Wald's watertight ray–triangle test, at every finite
//! scale.
//!
//! # The test
//! The vertices are moved to the ray's origin and sheared so that the ray
//! runs along the axis `kz` of its direction's largest coordinate
//! ([`Shear::vertex`]); the ray then meets the triangle where the origin
//! of the sheared plane lies inside the triangle's projection, which the
//! signs of three 2D edge functions decide. The edge function of the edge
//! from `b` to `c` is `x_c y_b - y_c x_b`, computed from those two sheared
//! vertices alone and with no fused operation: a triangle on the other
//! side of a shared edge, which lists it from `c` to `b`, computes exactly
//! its negation.
//!
//! # Exact or neutral
//! Rounding is monotone, overflow to an infinity and underflow to zero
//! included, so `fl(x_c y_b)` and `fl(y_c x_b)` lie in the order of the
//! exact products, and the computed edge function is zero, NaN (where both
//! products overflow) or of the exact sign of `x_c y_b - y_c x_b` for the
//! (rounded) sheared vertices. A zero or NaN edge function is *neutral*:
//! it counts as inside for the triangles on both sides of the edge.
//!
//! # Every scale
//! Near `2^±510` in the sheared coordinates those products leave the
//! normal range (and near `2^±340` the parameter's numerator, a product
//! of three), so the ordinary evaluation ([`sheared_hit`]) answers only
//! where its values stay in range, and hands the rest to the rescaled one
//! ([`rescaled_hit`]), which computes the same test at powers of two
//! chosen from the values themselves:
//!
//! - A vertex keeps its sheared `x` and `y` unless one is not finite
//!   (`|p - o|` near `f64::MAX`); then both are sheared again from `p` and
//!   `o` scaled by `2^-8`, with that exponent beside them. The choice
//!   depends on the vertex and the ray alone.
//! - An edge function keeps the ordinary value where it is finite and not
//!   zero (its sign is then exact, and is the sign the ordinary evaluation
//!   of any triangle computes for this edge). Otherwise it is the
//!   *canonical* value: the four coordinates (each times its vertex's
//!   power of two) scaled by the one power of two that brings the largest
//!   into `[1/2, 1)`, then the same unfused formula. That is a
//!   function of the edge's two vertices alone, and exactly negated by
//!   the reversed edge.
//! - The ordinary evaluation decides a miss only from two finite edge
//!   functions of strict opposite signs (computed from finite vertices),
//!   and a hit only where every value it computed is in range.
//!
//! So two triangles sharing an edge either compute the same value for it,
//! negated, or one of them computes zero (neutral): never both a strict
//! "outside". That is the consistency Woop et al.'s watertightness rests
//! on, now for every finite input: a ray crossing a closed or tiled
//! surface at a shared edge or vertex is never missed by all the triangles
//! around it.
//!
//! A sign can differ from the exact sign of the exact (unrounded) sheared
//! vertices only where the ray passes within a few units of rounding of
//! the edge, relative to its vertices' sheared coordinates: the rounding
//! of the vertices themselves, of the two products (`u` each), and, only
//! in the canonical value, of a coordinate more than `2^1021` times
//! smaller than the edge's largest (`2^-1075` of it).
//!
//! # The parameter
//! `t = (e_0 z_a + e_1 z_b + e_2 z_c) / (d_kz (e_0 + e_1 + e_2))` in units
//! of the scaled direction, then multiplied by the direction's scale. The
//! ordinary evaluation keeps its rounded formula where no step loses bits
//! to underflow or overflow (see [`sheared_hit`]'s gate); the rescaled one
//! evaluates the same formula on values with unbounded exponents
//! ([`ScaledFloat`], one rounding per operation).
//!
//! Reference: S. Woop, C. Benthin and I. Wald, "Watertight Ray/Triangle
//! Intersection", Journal of Computer Graphics Techniques 2(1), 2013.

use super::{TriangleHit, largest_axis, permute};
use crate::arith::exponent::{pow2, scale_pow2, unit_scale};
use crate::arith::scaled_float::ScaledFloat;
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::shape::Triangle;
use glam::DVec3;

/// A ray prepared for the watertight test: its origin, and its direction
/// scaled by a power of two and permuted so that its largest coordinate
/// comes last.
#[derive(Clone, Copy, Debug)]
pub(super) struct Shear {
    origin: DVec3,
    /// The axis of the direction's largest coordinate, `kz`; the others
    /// follow cyclically (`kx = kz + 1`, `ky = kz + 2`, modulo 3).
    kz: usize,
    /// `d_kx, d_ky, d_kz` of the scaled direction, `|d_kz|` in `[1, 2)`
    /// unless the direction is subnormal or huge.
    d: [f64; 3],
    /// The power of two the direction was multiplied by.
    scale: f64,
}

/// What the ordinary evaluation made of a triangle.
enum Ordinary {
    /// Decided: the hit, or `None` for a miss.
    Decided(Option<TriangleHit>),
    /// A value left the range where the ordinary evaluation is exact or
    /// neutral: the rescaled evaluation decides.
    Rescale,
}

/// The exponent a vertex's coordinates are sheared again at when the
/// ordinary shear overflows: `|p 2^-8 - o 2^-8| < 2^1017`, and with
/// `|d_kx|, |d_ky| <= |d_kz| < 4` the sheared coordinates stay below
/// `2^1020`.
const VERTEX_DOWN: i32 = 8;

/// `2^-1000` and `2^1000`: the ordinary evaluation's range (see
/// [`sheared_hit`]).
const LOW: f64 = pow2(-1000);
const HIGH: f64 = pow2(1000);

impl Shear {
    #[inline(always)]
    pub(super) fn of(ray: &Ray) -> Shear {
        let d = ray.direction();
        let kz = largest_axis(d);
        let p = match kz {
            0 => permute::<0>(d),
            1 => permute::<1>(d),
            _ => permute::<2>(d),
        };
        // `2^-e` for `|d_kz|` in `[2^e, 2^(e+1))`, from the exponent bits,
        // clamped so that it is a normal number.
        let biased = ((p[2].to_bits() >> 52) & 0x7ff).clamp(1, 2045);
        let scale = f64::from_bits((2046 - biased) << 52);
        Shear {
            origin: ray.origin(),
            kz,
            d: p.map(|x| x * scale),
            scale,
        }
    }

    #[inline(always)]
    pub(super) fn cast(&self, tri: &Triangle, range: Interval) -> Option<TriangleHit> {
        match self.kz {
            0 => self.cast_permuted::<0>(tri, range),
            1 => self.cast_permuted::<1>(tri, range),
            _ => self.cast_permuted::<2>(tri, range),
        }
    }

    /// The vertex `p` relative to the origin, sheared and multiplied by
    /// `d_kz`: `(d_kz p_kx - d_kx p_kz, d_kz p_ky - d_ky p_kz, p_kz)`.
    #[inline(always)]
    fn vertex<const K: usize>(&self, p: DVec3) -> [f64; 3] {
        self.sheared::<K>(p - self.origin)
    }

    /// `w = p - o` (permuted), sheared and multiplied by `d_kz`.
    #[inline(always)]
    fn sheared<const K: usize>(&self, w: DVec3) -> [f64; 3] {
        let [x, y, z] = permute::<K>(w);
        let [dx, dy, dz] = self.d;
        [dz * x - dx * z, dz * y - dy * z, z]
    }

    #[inline(always)]
    fn cast_permuted<const K: usize>(
        &self,
        tri: &Triangle,
        range: Interval,
    ) -> Option<TriangleHit> {
        let v = tri.v.map(|p| self.vertex::<K>(p));
        match sheared_hit(v, self.d[2], self.scale, range) {
            Ordinary::Decided(hit) => hit,
            Ordinary::Rescale => self.rescaled_hit::<K>(tri, range),
        }
    }

    /// The vertex `p` for the rescaled evaluation: its sheared `x, y` with
    /// their exponent, and its `z` (see the module docs).
    fn rescaled_vertex<const K: usize>(&self, p: DVec3) -> (Planar, ScaledFloat) {
        let [x, y, z] = self.vertex::<K>(p);
        let s = pow2(-VERTEX_DOWN);
        let down = || self.sheared::<K>(p * s - self.origin * s);
        let xy = if x.is_finite() && y.is_finite() {
            Planar { x, y, k: 0 }
        } else {
            let [x, y, _] = down();
            Planar {
                x,
                y,
                k: VERTEX_DOWN,
            }
        };
        let z = if z.is_finite() {
            ScaledFloat::new(z, 0)
        } else {
            ScaledFloat::new(down()[2], VERTEX_DOWN)
        };
        (xy, z)
    }

    /// The test on values of unbounded exponent, for what
    /// [`sheared_hit`] hands over (see the module docs).
    #[cold]
    #[inline(never)]
    fn rescaled_hit<const K: usize>(self, tri: &Triangle, range: Interval) -> Option<TriangleHit> {
        let [(a, za), (b, zb), (c, zc)] = tri.v.map(|p| self.rescaled_vertex::<K>(p));
        let e = [edge(c, b), edge(a, c), edge(b, a)];
        let negative = e.iter().any(|e| e.is_negative());
        let positive = e.iter().any(|e| !e.is_zero() && !e.is_negative());
        if negative && positive {
            return None;
        }
        let det = e[0].add(e[1]).add(e[2]);
        if det.is_zero() {
            return None;
        }
        // The ordinary evaluation's operations in its order, each rounded
        // once as it rounds them where its values stay in range: at scales
        // where both apply (no subnormal value), the same answer.
        let num = e[0].mul(za).add(e[1].mul(zb)).add(e[2].mul(zc));
        let dz = ScaledFloat::new(self.d[2], 0);
        let inv = ScaledFloat::new(1.0, 0).div(det.mul(dz));
        let t = num.mul(inv).mul(ScaledFloat::new(self.scale, 0)).to_f64();
        range.admits(t).then(|| TriangleHit {
            t,
            u: e[1].mul(dz).mul(inv).to_f64(),
            v: e[2].mul(dz).mul(inv).to_f64(),
        })
    }
}

/// A sheared vertex's `x` and `y`, times `2^k`.
#[derive(Clone, Copy)]
struct Planar {
    x: f64,
    y: f64,
    k: i32,
}

/// The edge function `x_c y_b - y_c x_b` for the rescaled evaluation: the
/// ordinary value where it is finite and not zero (its sign is the one
/// every ordinary evaluation computes), else the canonical value (see the
/// module docs). Where both are available and agree in sign, the
/// canonical one's magnitude, which has all its bits where the ordinary
/// one may be subnormal.
fn edge(c: Planar, b: Planar) -> ScaledFloat {
    let canonical = canonical_edge(c, b);
    let ordinary = if c.k == 0 && b.k == 0 {
        c.x * b.y - c.y * b.x
    } else {
        f64::NAN
    };
    if ordinary.is_finite() && ordinary != 0.0 {
        let agrees = !canonical.is_zero() && canonical.is_negative() == (ordinary < 0.0);
        if !agrees {
            return ScaledFloat::new(ordinary, 0);
        }
    }
    canonical
}

/// The canonical edge function: each vertex's coordinates (times its
/// `2^k`) scaled by the one power of two that brings the largest of the
/// four into `[1/2, 1)` (exact, but for a coordinate more than `2^1021`
/// times smaller than that largest, which rounds), then the unfused
/// formula; its products are below 1. A function of the two vertices
/// alone, negated exactly by `(b, c)`.
fn canonical_edge(c: Planar, b: Planar) -> ScaledFloat {
    // The exponent bringing each vertex's largest coordinate times its
    // 2^k into [1/2, 1); a zero vertex asks for none.
    let unit = |p: Planar| (p.x != 0.0 || p.y != 0.0).then(|| unit_scale(&[p.x, p.y]) - p.k);
    let Some(s) = [unit(c), unit(b)].into_iter().flatten().min() else {
        return ScaledFloat::ZERO;
    };
    let at = |p: Planar| [scale_pow2(p.x, p.k + s), scale_pow2(p.y, p.k + s)];
    let ([cx, cy], [bx, by]) = (at(c), at(b));
    ScaledFloat::new(cx * by - cy * bx, -2 * s)
}

/// The watertight test on the sheared vertices `(x, y, z)` (see
/// [`Shear::vertex`]), for a direction scaled by `scale` whose largest
/// coordinate is `dz`, in ordinary `f64` arithmetic: today's rounded
/// formula wherever its values stay where it is exact or neutral.
///
/// A miss is decided here from the least and the greatest edge function
/// (by comparisons: a NaN one may hide the others, and is neutral) when
/// they have strict opposite signs and are both finite (their difference
/// is): an edge function with an infinite or NaN vertex coordinate is
/// itself infinite or NaN, so both come from finite vertices, and each is
/// exact for them, the value the rescaled evaluation keeps too (module
/// docs). A hit is returned only where no step lost bits:
/// - `2^-1000 <= |det| <= 2^1000`. For a hit every edge function has the
///   sign of `det`, so `|det|` is the sum of their magnitudes, and the
///   underflow each may carry (`2^-1074`: its two products within
///   `2^-1075` of their roundings with unbounded exponent, a subnormal
///   difference exact) is below `2^-73` of `|det|`; `d_kz det` stays below
///   `2^1002`, and its reciprocal normal.
///   The weights `e_i / det` of the `z` in `t` (a convex combination)
///   then move by less than `2^-73`, and `t` by less than `2^-73 max |z|`,
///   far below the rounding it carries anyway.
/// - `2^-1000 <= |num| <= f64::MAX` for the numerator `sum e_i z_i`: no
///   overflow (nor an infinite `z`), and the underflow of its three
///   products (`2^-1075` each) is below `2^-73` of it. A numerator that
///   is zero or tiny (an origin on or within `2^-1000` of the plane, in
///   these units) goes to the rescaled evaluation, which computes it with
///   the same roundings where nothing underflows.
/// - the unscaled `t` normal: `t` is then the rounded formula at every
///   scale, and its last product by the direction's power of two rounds
///   once, at most.
///
/// Everything else goes to [`Shear::rescaled_hit`].
#[inline(always)]
fn sheared_hit([a, b, c]: [[f64; 3]; 3], dz: f64, scale: f64, range: Interval) -> Ordinary {
    // Each edge's function from its own two vertices, unfused, so that
    // the reversed edge of a neighbour computes exactly its negation.
    let e0 = c[0] * b[1] - c[1] * b[0];
    let e1 = a[0] * c[1] - a[1] * c[0];
    let e2 = b[0] * a[1] - b[1] * a[0];
    let min = |a: f64, b: f64| if a < b { a } else { b };
    let max = |a: f64, b: f64| if a > b { a } else { b };
    let (lo, hi) = (min(min(e0, e1), e2), max(max(e0, e1), e2));
    if lo < 0.0 && hi > 0.0 {
        return if hi - lo < f64::INFINITY {
            Ordinary::Decided(None)
        } else {
            Ordinary::Rescale
        };
    }
    let det = e0 + e1 + e2;
    let num = e0 * a[2] + e1 * b[2] + e2 * c[2];
    if !((LOW..=HIGH).contains(&det.abs()) && (LOW..=f64::MAX).contains(&num.abs())) {
        return Ordinary::Rescale;
    }
    // The sheared system's t is (sum e_i z_i) / (d_kz det), in units of
    // the scaled direction; the scale converts it back. One division.
    let inv = 1.0 / (det * dz);
    let unscaled = num * inv;
    if !unscaled.is_normal() {
        return Ordinary::Rescale;
    }
    let t = unscaled * scale;
    if !range.admits(t) {
        return Ordinary::Decided(None);
    }
    Ordinary::Decided(Some(TriangleHit {
        t,
        u: e1 * dz * inv,
        v: e2 * dz * inv,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::predicates::orient2d;
    use crate::sign::Sign;
    use crate::testing::SplitMix64;

    /// A coordinate of any sign at `2^e` for `e` in `[lo, lo + span)`, or
    /// zero one time in eight.
    fn coordinate(rng: &mut SplitMix64, lo: i32, span: u64) -> f64 {
        if rng.next_u64().is_multiple_of(8) {
            return 0.0;
        }
        let e = lo + (rng.next_u64() % span) as i32;
        let m = 1.0 + rng.next_f64();
        let s = if rng.next_u64().is_multiple_of(2) {
            -m
        } else {
            m
        };
        scale_pow2(s, e)
    }

    fn planar(rng: &mut SplitMix64, lo: i32, span: u64) -> Planar {
        Planar {
            x: coordinate(rng, lo, span),
            y: coordinate(rng, lo, span),
            k: if rng.next_u64().is_multiple_of(4) {
                VERTEX_DOWN
            } else {
                0
            },
        }
    }

    fn sign(e: ScaledFloat) -> Sign {
        if e.is_zero() {
            Sign::Zero
        } else if e.is_negative() {
            Sign::Negative
        } else {
            Sign::Positive
        }
    }

    /// Every edge function is negated exactly by the reversed edge (the
    /// watertightness argument), is the ordinary value's sign wherever
    /// that is finite and not zero (what the ordinary evaluation of a
    /// neighbour decides), and is the exact sign of `x_c y_b - y_c x_b`
    /// or zero wherever no coordinate is more than `2^1000` times smaller
    /// than its edge's largest: at every exponent from `2^-1074` to
    /// `2^1023`, with both vertex exponents.
    #[test]
    fn edge_functions_are_antisymmetric_and_exact_or_neutral() {
        let mut rng = SplitMix64::new(0xed9e);
        let (mut strict, mut checked) = (0, 0);
        for round in 0..200_000 {
            // Narrow spans (the ordinary and canonical values near each
            // other) and the whole range.
            let (lo, span) = match round % 3 {
                0 => ((rng.next_u64() % 2090) as i32 - 1074, 8),
                1 => ((rng.next_u64() % 2000) as i32 - 1074, 60),
                _ => (-1074, 2098),
            };
            let (c, b) = (planar(&mut rng, lo, span), planar(&mut rng, lo, span));
            let (cb, bc) = (edge(c, b), edge(b, c));
            assert_eq!(cb, bc.neg(), "{:?} {:?}", (c.x, c.y, c.k), (b.x, b.y, b.k));
            let ordinary = c.x * b.y - c.y * b.x;
            if c.k == 0 && b.k == 0 && ordinary.is_finite() && ordinary != 0.0 {
                assert_eq!(cb.is_negative(), ordinary < 0.0);
            }
            // Magnitudes with the vertex exponents applied, as exponents.
            let log = |v: f64, k: i32| (v != 0.0).then(|| unit_scale(&[v]) - k);
            let m = [log(c.x, c.k), log(c.y, c.k), log(b.x, b.k), log(b.y, b.k)];
            let m = m.iter().flatten();
            let (big, small) = (m.clone().min(), m.max());
            if big
                .zip(small)
                .is_none_or(|(big, small)| small - big <= 1000)
            {
                checked += 1;
                // The sign of x_c y_b - y_c x_b, that is of orient2d(0, c,
                // b), which the vertices' positive factors 2^k do not change.
                let exact = orient2d([0.0, 0.0], [c.x, c.y], [b.x, b.y]);
                let got = sign(cb);
                assert!(
                    got == exact || got == Sign::Zero,
                    "{exact:?} {got:?}: {:?} {:?}",
                    (c.x, c.y, c.k),
                    (b.x, b.y, b.k)
                );
                strict += (got != Sign::Zero) as u32;
            }
        }
        assert!(checked > 100_000 && strict > 50_000, "{checked} {strict}");
    }
}
