//! The three ray–triangle tests as types behind one trait, so that a mesh
//! chooses its variant once and prepares each ray once for all the
//! triangles it meets: [`TriangleTest`].

use super::{Shear, TriangleHit};
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::shape::Triangle;

/// A ray–triangle test: its per-ray setup, then the test of one triangle
/// with it. Each answer is exactly the one of the matching `Triangle`
/// method (`cast_mt`, `cast_watertight`, `cast_exact`), whose docs state
/// its guarantees.
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
    /// `t`, the others' recomputed (what `Triangle`'s `RayCast` reports).
    /// NaN where the line is parallel to the plane.
    #[inline]
    fn certified_t(ray: &Ray, tri: &Triangle, hit: &TriangleHit) -> f64 {
        let _ = hit;
        super::plane_parameter(ray, &tri.v)
    }
}

/// Möller–Trumbore ([`Triangle::cast_mt`]): nothing to prepare.
#[derive(Clone, Copy, Debug, Default)]
pub struct MollerTrumbore;

/// Woop, Benthin and Wald's watertight test ([`Triangle::cast_watertight`]):
/// the ray's shear and axis permutation prepared once.
#[derive(Clone, Copy, Debug, Default)]
pub struct Watertight;

/// The exact test ([`Triangle::cast_exact`]): hit or miss by exact signs,
/// `t` within 4 units of rounding.
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
    type Prepared = Ray;

    #[inline]
    fn prepare(ray: &Ray) -> Ray {
        *ray
    }

    #[inline]
    fn hit(ray: &Ray, tri: &Triangle, range: Interval) -> Option<TriangleHit> {
        tri.cast_exact(ray, range)
    }

    /// The hit's own `t`: it is the plane parameter already.
    #[inline]
    fn certified_t(_ray: &Ray, _tri: &Triangle, hit: &TriangleHit) -> f64 {
        hit.t
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
                    assert_eq!(Exact::hit(&ex, &tri, range), tri.cast_exact(&ray, range));
                    hits += Exact::hit(&ex, &tri, range).is_some() as u32;
                }
            }
        }
        assert!(hits > 500, "{hits}");
    }
}
