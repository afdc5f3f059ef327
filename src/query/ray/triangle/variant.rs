//! The three ray–triangle tests as types behind one trait, so that a mesh
//! chooses its variant once and prepares each ray once for all the
//! triangles it meets: [`TriangleTest`].

use super::{ExactRay, Shear, TriangleHit, closed};
use crate::arith::roundoff::U;
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::shape::Triangle;
use core::cmp::Ordering;
use glam::DVec3;

/// A ray–triangle test: its per-ray setup, then the test of one triangle
/// with it. Each answer is exactly the one of the matching `Triangle`
/// method (`cast_mt`, `cast_watertight`, `cast_exact_closed`), whose docs
/// state its guarantees; a scene also asks it which of two hits comes
/// first ([`TriangleTest::precedes`]) and whether a segment meets a
/// triangle ([`TriangleTest::segment_hit`]).
///
/// ```
/// use exactray::prelude::*;
/// use exactray::query::ray::{TriangleTest, Watertight};
/// // The nearest hit over many triangles, the ray prepared once.
/// fn nearest<T: TriangleTest>(tris: &[Triangle], ray: &Ray) -> Option<f64> {
///     let prepared = T::prepare(ray);
///     tris.iter()
///         .filter_map(|t| T::hit(&prepared, t, Interval::FORWARD))
///         .map(|h| h.t)
///         .reduce(f64::min)
/// }
/// let tris = [
///     Triangle::new([0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]).unwrap(),
///     Triangle::new([0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 1.0, 2.0]).unwrap(),
/// ];
/// let ray = Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, 1.0]).unwrap();
/// assert_eq!(nearest::<Watertight>(&tris, &ray), Some(1.0));
/// ```
pub trait TriangleTest {
    /// What the test computes once per ray.
    type Prepared: Copy;

    /// The per-ray setup.
    fn prepare(ray: &Ray) -> Self::Prepared;

    /// The hit of `tri` in `range`, from the prepared ray. Never allocates;
    /// a degenerate triangle is a miss.
    fn hit(ray: &Self::Prepared, tri: &Triangle, range: Interval) -> Option<TriangleHit>;

    /// The parameter where `ray`'s line crosses the plane of `tri`, within
    /// [`EXACT_T_ULPS`](super::EXACT_T_ULPS) (4) units of rounding of the
    /// exact one, for a `hit` this test returned: the exact variant's own
    /// `t` (for a ray in the plane, its entry), the others' recomputed
    /// (what `Triangle`'s `RayCast` reports). NaN where the line is
    /// parallel to the plane.
    #[inline]
    fn certified_t(ray: &Ray, tri: &Triangle, hit: &TriangleHit) -> f64 {
        let _ = hit;
        super::plane_parameter(ray, &tri.v)
    }

    /// Whether the hit `a` comes before the hit `b` on `ray` in `range`,
    /// each given as (certified `t`, triangle index), `triangle` giving
    /// the triangle of an index. The default: the lesser certified `t`,
    /// the lower index on equal ones. [`Exact`] decides exactly.
    #[inline(always)]
    fn precedes<F: Fn(u32) -> Triangle>(
        ray: &Ray,
        range: Interval,
        a: (f64, u32),
        b: (f64, u32),
        triangle: F,
    ) -> bool {
        let _ = (ray, range, triangle);
        a.0 < b.0 || (a.0 == b.0 && a.1 < b.1)
    }

    /// The setup [`TriangleTest::segment_hit`] is given for `ray`:
    /// [`TriangleTest::prepare`]'s, unless the test decides segments
    /// without it ([`Exact`], on the exact segment), which then skips that
    /// work.
    #[inline]
    fn prepare_segment(ray: &Ray) -> Self::Prepared {
        Self::prepare(ray)
    }

    /// Whether the segment from `ray.origin()` to `q` meets `tri`, with
    /// `ray` the ray that covers it over `range` (and `prepared` its setup
    /// from [`TriangleTest::prepare_segment`]): `p + t fl(q - p)` over
    /// `[0, 1]`, or, where `q - p` overflows, `p + t d'` over `[0, 2]`
    /// with `d'` the halved difference, rounded. The default: a hit of
    /// the ray in `range` whose certified `t` is in `range`, so the far
    /// end is `q` up to the rounding of the difference. [`Exact`] decides
    /// on the exact segment.
    #[inline(always)]
    fn segment_hit(
        ray: &Ray,
        prepared: &Self::Prepared,
        q: DVec3,
        range: Interval,
        tri: &Triangle,
    ) -> bool {
        let _ = q;
        Self::hit(prepared, tri, range)
            .is_some_and(|h| range.admits(Self::certified_t(ray, tri, &h)))
    }
}

/// Möller–Trumbore ([`Triangle::cast_mt`]): nothing to prepare.
#[derive(Clone, Copy, Debug, Default)]
pub struct MollerTrumbore;

/// Woop, Benthin and Wald's watertight test ([`Triangle::cast_watertight`]):
/// the ray's shear and axis permutation prepared once.
#[derive(Clone, Copy, Debug, Default)]
pub struct Watertight;

/// The exact test under the closed-triangle rule
/// ([`Triangle::cast_exact_closed`]): hit or miss by exact signs, a ray in
/// the triangle's plane hitting where it enters, `t` within 4 units of
/// rounding; the ray prepared once ([`ExactRay`]); hits ordered by their exact parameters
/// ([`TriangleTest::precedes`]) and segments decided on their exact ends
/// ([`Triangle::meets_segment_exact`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct Exact;

/// A ray prepared for [`Watertight`]: its origin, and its direction scaled
/// by a power of two and permuted so that its largest coordinate comes
/// last.
#[derive(Clone, Copy, Debug)]
pub struct WatertightRay(Shear);

impl TriangleTest for MollerTrumbore {
    type Prepared = Ray;

    #[inline]
    fn prepare(ray: &Ray) -> Ray {
        *ray
    }

    #[inline]
    fn hit(ray: &Ray, tri: &Triangle, range: Interval) -> Option<TriangleHit> {
        tri.cast_mt(ray, range)
    }
}

impl TriangleTest for Watertight {
    type Prepared = WatertightRay;

    #[inline]
    fn prepare(ray: &Ray) -> WatertightRay {
        WatertightRay(Shear::of(ray))
    }

    #[inline]
    fn hit(ray: &WatertightRay, tri: &Triangle, range: Interval) -> Option<TriangleHit> {
        if tri.degenerate {
            return None;
        }
        ray.0.cast(tri, range)
    }
}

impl TriangleTest for Exact {
    type Prepared = ExactRay;

    #[inline]
    fn prepare(ray: &Ray) -> ExactRay {
        ExactRay::new(ray)
    }

    #[inline]
    fn hit(ray: &ExactRay, tri: &Triangle, range: Interval) -> Option<TriangleHit> {
        ray.cast_closed(tri, range)
    }

    /// The hit's own `t`: it is the plane parameter already (or the
    /// coplanar entry).
    #[inline]
    fn certified_t(_ray: &Ray, _tri: &Triangle, hit: &TriangleHit) -> f64 {
        hit.t
    }

    /// The exact order of the two hits' exact parameters, the lower index
    /// on equal ones: where the certified `t` cannot separate them, the
    /// exact parameters are compared in integers (`closed::exact_order`).
    ///
    /// Each certified `t` is within `4u |t*| + 2^-1073` of its exact `t*`
    /// (`EXACT_T_ULPS`; the second term for subnormal results), so
    /// `|t*| <= (|t| + 2^-1073) / (1 - 4u)` and `|t - t*| <= e(t) =
    /// 4u (|t| + 2^-1073) / (1 - 4u) + 2^-1073 < 4.01u |t| + 2^-1072`.
    /// `E(t) = fl(5u |t|) + 2^-1072` is at least that (one rounding of the
    /// product,
    /// and the sum's rounding is at most `u` of it). The computed gap
    /// `fl(|a - b|)` is within `u` of the exact one (exact when subnormal),
    /// so `fl(|a - b|) > 2 fl(E(a) + E(b))` gives `|a - b| > e(a) + e(b)`:
    /// the exact parameters are in the certified ones' order.
    #[inline]
    fn precedes<F: Fn(u32) -> Triangle>(
        ray: &Ray,
        range: Interval,
        a: (f64, u32),
        b: (f64, u32),
        triangle: F,
    ) -> bool {
        /// `2^-1072`.
        const TINY4: f64 = f64::from_bits(4);
        let e = |t: f64| 5.0 * U * t.abs() + TINY4;
        if (a.0 - b.0).abs() > 2.0 * (e(a.0) + e(b.0)) {
            return a.0 < b.0;
        }
        match closed::exact_order(ray, range, &triangle(a.1), &triangle(b.1)) {
            Ordering::Less => true,
            Ordering::Greater => false,
            Ordering::Equal => a.1 < b.1,
        }
    }

    /// The ray unprepared: segments are decided on the exact segment
    /// ([`Triangle::meets_segment_exact`]), not with this ray.
    #[inline]
    fn prepare_segment(ray: &Ray) -> ExactRay {
        ExactRay::unfiltered(ray)
    }

    /// [`Triangle::meets_segment_exact`] from the ray's origin to `q`.
    #[inline]
    fn segment_hit(
        ray: &Ray,
        _prepared: &ExactRay,
        q: DVec3,
        _range: Interval,
        tri: &Triangle,
    ) -> bool {
        tri.meets_segment_exact(ray.origin(), q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::SplitMix64;
    use glam::DVec3;

    fn coordinate(rng: &mut SplitMix64) -> f64 {
        let unit = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
        unit * [1.0, 1e-8, 1e8][(rng.next_u64() % 3) as usize]
    }

    /// A prepared ray answers every triangle exactly as the unprepared call
    /// does, for each variant, including degenerate triangles.
    #[test]
    fn prepared_rays_answer_as_the_methods() {
        let mut rng = SplitMix64::new(0x7e57);
        let mut hits = 0;
        for _ in 0..2_000 {
            let v = |rng: &mut SplitMix64| {
                DVec3::new(coordinate(rng), coordinate(rng), coordinate(rng))
            };
            let Ok(ray) = Ray::new(v(&mut rng), v(&mut rng)) else {
                continue;
            };
            let (mt, wt, ex) = (
                MollerTrumbore::prepare(&ray),
                Watertight::prepare(&ray),
                Exact::prepare(&ray),
            );
            for k in 0..16 {
                // Around a point of the ray's line, which is the centroid:
                // most rays hit. Every fourth triangle is degenerate.
                let q = ray.at(coordinate(&mut rng) * 2.0);
                let (e1, e2) = (v(&mut rng), v(&mut rng));
                let (a, b) = (q + e1, q + e2);
                let c = if k % 4 == 0 { a } else { q - e1 - e2 };
                let Ok(tri) = Triangle::new(a, b, c) else {
                    continue;
                };
                for range in [Interval::FORWARD, Interval::new(-1.0, 1.0).unwrap()] {
                    assert_eq!(
                        MollerTrumbore::hit(&mt, &tri, range),
                        tri.cast_mt(&ray, range)
                    );
                    assert_eq!(
                        Watertight::hit(&wt, &tri, range),
                        tri.cast_watertight(&ray, range)
                    );
                    assert_eq!(
                        Exact::hit(&ex, &tri, range),
                        tri.cast_exact_closed(&ray, range)
                    );
                    hits += Exact::hit(&ex, &tri, range).is_some() as u32;
                }
            }
        }
        assert!(hits > 500, "{hits}");
    }
}
