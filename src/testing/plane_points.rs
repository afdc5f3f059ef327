//! Deterministic planar point sets for triangulations, shared by the
//! triangulator's tests and the speed-against-error report's `delaunay`
//! family: uniform points, a full integer grid (every unit square
//! cocircular), and the uniform points at extreme magnitudes
//! ([`PlaneDistribution`]). Each set has its own [`SplitMix64`] stream,
//! named by its distribution and size, and comes as an iterator, so
//! nothing here allocates.
//!
//! ```
//! use exactray::testing::{PlaneDistribution, plane_points};
//! let tiny: Vec<_> = plane_points(PlaneDistribution::Tiny, 1000).collect();
//! let uniform: Vec<_> = plane_points(PlaneDistribution::Uniform, 1000).collect();
//! // The same points, scaled by a power of two: exactly.
//! assert!(tiny.iter().zip(&uniform).all(|(t, u)| *t == *u * 2f64.powi(-532)));
//! ```

use super::generators::{SplitMix64, scale};
use super::points::{Key, stream};
use glam::DVec2;

/// How the points of a planar point set are drawn. The extreme classes
/// carry [`InputClass`](super::InputClass)'s `Tiny`, `Huge` and `Mixed`
/// over to whole point sets: coordinates at which the products of a
/// predicate's terms underflow or overflow `f64`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlaneDistribution {
    /// Both coordinates uniform in `[-1, 1)`.
    Uniform,
    /// The first `n` points of the integer grid `0..m` by `0..m`,
    /// `m = ceil(sqrt(n))`, row by row: every unit square is cocircular,
    /// so the Delaunay triangulation is not unique, and rows and columns
    /// are collinear.
    Grid,
    /// The [`Uniform`](Self::Uniform) points times `2^-532` (about
    /// `7e-161`), exactly: the squared distances' products in `incircle`
    /// (about `1e-640`) underflow to zero, and `orient2d`'s products
    /// (about `1e-320`) are subnormal.
    Tiny,
    /// The [`Uniform`](Self::Uniform) points times `2^532` (about
    /// `1.4e160`), exactly: `orient2d`'s products (about `1e320`) and
    /// `incircle`'s overflow to infinity.
    Huge,
    /// Uniform `[-1, 1)` values times `2^e`, `e` uniform in
    /// `-1000..=1000` (magnitudes from about `1e-301` to `1e301` in one
    /// set): half of the points share one `e` for both coordinates (every
    /// scale, the smallest beside the largest), the other half draw `e`
    /// per coordinate (points such as `(1e-300, 1e300)`).
    Mixed,
}

impl PlaneDistribution {
    /// Every distribution, in the order the report lists them.
    pub const ALL: [PlaneDistribution; 5] = [
        PlaneDistribution::Uniform,
        PlaneDistribution::Grid,
        PlaneDistribution::Tiny,
        PlaneDistribution::Huge,
        PlaneDistribution::Mixed,
    ];

    /// The distribution's name in reports: lower case.
    pub fn name(self) -> &'static str {
        match self {
            PlaneDistribution::Uniform => "uniform",
            PlaneDistribution::Grid => "grid",
            PlaneDistribution::Tiny => "tiny",
            PlaneDistribution::Huge => "huge",
            PlaneDistribution::Mixed => "mixed",
        }
    }
}

/// The power of two [`PlaneDistribution::Tiny`] and
/// [`PlaneDistribution::Huge`] scale the uniform points by (negated for
/// `Tiny`): `2^-532` squared twice is `2^-2128`, far below the smallest
/// subnormal `2^-1074`.
const EXTREME_EXPONENT: i64 = 532;

/// The largest exponent [`PlaneDistribution::Mixed`] draws: `2^1000` keeps
/// coordinate differences finite.
const MIXED_EXPONENT: i64 = 1000;

/// The `n` points of `dist`, always the same for the same `n`; `Tiny` and
/// `Huge` are the `Uniform` set of the same `n`, scaled.
pub fn plane_points(dist: PlaneDistribution, n: usize) -> impl Iterator<Item = DVec2> {
    let key = match dist {
        PlaneDistribution::Tiny | PlaneDistribution::Huge => PlaneDistribution::Uniform.name(),
        _ => dist.name(),
    };
    let mut rng = stream(b"delaunay", "points", Key(key, n));
    // The grid's side, ceil(sqrt(n)).
    let side = n.isqrt() + usize::from(n.isqrt() * n.isqrt() < n);
    (0..n).map(move |i| match dist {
        PlaneDistribution::Uniform => uniform_point(&mut rng),
        PlaneDistribution::Grid => DVec2::new((i % side) as f64, (i / side) as f64),
        PlaneDistribution::Tiny => scaled(uniform_point(&mut rng), -EXTREME_EXPONENT),
        PlaneDistribution::Huge => scaled(uniform_point(&mut rng), EXTREME_EXPONENT),
        PlaneDistribution::Mixed => mixed_point(&mut rng),
    })
}

fn uniform_point(rng: &mut SplitMix64) -> DVec2 {
    DVec2::new(rng.signed(), rng.signed())
}

fn scaled(p: DVec2, k: i64) -> DVec2 {
    DVec2::new(scale(p.x, k), scale(p.y, k))
}

fn mixed_point(rng: &mut SplitMix64) -> DVec2 {
    let (x, y) = (rng.signed(), rng.signed());
    let ex = rng.int(-MIXED_EXPONENT, MIXED_EXPONENT);
    let ey = if rng.int(0, 1) == 0 {
        ex
    } else {
        rng.int(-MIXED_EXPONENT, MIXED_EXPONENT)
    };
    DVec2::new(scale(x, ex), scale(y, ey))
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec::Vec;

    #[test]
    fn grid_is_integer_and_distinct() {
        let pts: Vec<DVec2> = plane_points(PlaneDistribution::Grid, 10).collect();
        // side 4: rows of four.
        assert_eq!(pts[4], DVec2::new(0.0, 1.0));
        assert_eq!(pts[9], DVec2::new(1.0, 2.0));
        for (i, p) in pts.iter().enumerate() {
            assert!(pts[..i].iter().all(|q| q != p));
        }
    }

    #[test]
    fn extreme_sets_are_finite_and_at_their_scale() {
        for dist in PlaneDistribution::ALL {
            for p in plane_points(dist, 2000) {
                assert!(p.is_finite(), "{dist:?}: {p}");
            }
        }
        let huge = plane_points(PlaneDistribution::Huge, 100);
        assert!(
            huge.flat_map(|p| [p.x, p.y])
                .all(|v| v.abs() < 2f64.powi(533))
        );
        let mixed: Vec<f64> = plane_points(PlaneDistribution::Mixed, 2000)
            .flat_map(|p| [p.x.abs(), p.y.abs()])
            .collect();
        assert!(mixed.iter().any(|&v| v > 1e290) && mixed.iter().any(|&v| v < 1e-290));
    }
}
