//! Deterministic point sets and queries for nearest-point searches, shared
//! by the tests, the benchmarks and the speed-against-error report: uniform
//! in the unit cube, a mixture of Gaussian clusters, clustered points
//! queried off their distribution, and a grid nudged into near-ties
//! ([`PointDistribution`]). Each set and each query stream has its own
//! [`SplitMix64`] stream, named by its distribution and size, so the same
//! `n` always gives the same points whatever else was drawn; both come as
//! iterators, so nothing here allocates.
//!
//! ```
//! use exactray::testing::{PointDistribution, nearest_points, nearest_queries};
//! let points: Vec<[f64; 3]> = nearest_points(PointDistribution::Clustered, 1000).collect();
//! let queries: Vec<_> = nearest_queries(PointDistribution::Clustered, 1000, 10).collect();
//! assert_eq!((points.len(), queries.len()), (1000, 10));
//! ```

use super::generators::{SplitMix64, step_ulps};
use crate::arith::std_or_libm::{cbrt, ceil, cos, ln, powf, sqrt};
use glam::DVec3;

/// How the points of a nearest-point search and its queries are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointDistribution {
    /// Points and queries uniform in the unit cube.
    Uniform,
    /// Points and queries from the same mixture of 100 Gaussian clusters,
    /// centres uniform in the unit cube, standard deviations log-uniform in
    /// `[0.004, 0.032]`.
    Clustered,
    /// The clustered points, queried uniformly in the unit cube.
    OffDistribution,
    /// A cubic grid whose coordinates are nudged by up to one ulp, queried
    /// at cell centres nudged by up to one ulp: 8-way near-ties everywhere.
    NearTies,
}

impl PointDistribution {
    /// The distribution's name in reports: lower case with hyphens.
    pub fn name(self) -> &'static str {
        match self {
            PointDistribution::Uniform => "uniform",
            PointDistribution::Clustered => "clustered",
            PointDistribution::OffDistribution => "off-distribution",
            PointDistribution::NearTies => "near-ties",
        }
    }
}

/// The mixture's 100 clusters: centre and standard deviation. The same for
/// every `n`.
fn clusters() -> [([f64; 3], f64); 100] {
    let mut rng = SplitMix64::for_inputs("nearest", "clusters");
    core::array::from_fn(|_| {
        let centre = [rng.next_f64(), rng.next_f64(), rng.next_f64()];
        (centre, 0.004 * powf(8.0, rng.next_f64()))
    })
}

/// A standard normal variate (Box-Muller).
fn gaussian(rng: &mut SplitMix64) -> f64 {
    let u = 1.0 - rng.next_f64(); // in (0, 1]
    let v = rng.next_f64();
    sqrt(-2.0 * ln(u)) * cos(core::f64::consts::TAU * v)
}

fn uniform_point(rng: &mut SplitMix64) -> [f64; 3] {
    [rng.next_f64(), rng.next_f64(), rng.next_f64()]
}

fn clustered_point(rng: &mut SplitMix64, clusters: &[([f64; 3], f64)]) -> [f64; 3] {
    let k = ((rng.next_u64() as u128 * clusters.len() as u128) >> 64) as usize;
    let (c, s) = clusters[k];
    [
        c[0] + s * gaussian(rng),
        c[1] + s * gaussian(rng),
        c[2] + s * gaussian(rng),
    ]
}

/// The side of the cubic grid holding `n` points.
fn grid_side(n: usize) -> usize {
    (ceil(cbrt(n as f64)) as usize).max(2)
}

/// `v` moved by -1, 0 or 1 ulp.
fn nudge(rng: &mut SplitMix64, v: f64) -> f64 {
    step_ulps(v, (rng.next_u64() % 3) as i64 - 1)
}

/// A stream's name: the distribution's `name:n`.
pub(super) struct Key<'a>(pub(super) &'a str, pub(super) usize);

/// The stream `<family>/<what>/<key>:<n>` (FNV-1a of the name, as
/// [`SplitMix64::for_inputs`] hashes it), without formatting a string.
pub(super) fn stream(family: &[u8], what: &str, Key(key, n): Key) -> SplitMix64 {
    let mut digits = [0u8; 20];
    let mut at = digits.len();
    let mut rest = n;
    loop {
        at -= 1;
        digits[at] = b'0' + (rest % 10) as u8;
        rest /= 10;
        if rest == 0 {
            break;
        }
    }
    SplitMix64::for_parts(
        family,
        [what.as_bytes(), b"/", key.as_bytes(), b":", &digits[at..]],
    )
}

/// The `n` points of `dist`, always the same for the same `n`:
/// `OffDistribution` shares the clustered ones.
pub fn nearest_points(dist: PointDistribution, n: usize) -> impl Iterator<Item = [f64; 3]> {
    let key = match dist {
        PointDistribution::Uniform => "uniform",
        PointDistribution::Clustered | PointDistribution::OffDistribution => "clustered",
        PointDistribution::NearTies => "near-ties",
    };
    let mut rng = stream(b"nearest", "points", Key(key, n));
    let c = clusters();
    let m = grid_side(n);
    (0..n).map(move |i| match dist {
        PointDistribution::Uniform => uniform_point(&mut rng),
        PointDistribution::NearTies => {
            let cell = [i % m, i / m % m, i / (m * m)];
            cell.map(|c| nudge(&mut rng, c as f64 / m as f64))
        }
        _ => clustered_point(&mut rng, &c),
    })
}

/// `count` queries of `dist` for its `n`-point set (the stream depends on
/// both), always the same.
pub fn nearest_queries(
    dist: PointDistribution,
    n: usize,
    count: usize,
) -> impl Iterator<Item = DVec3> {
    let mut rng = stream(b"nearest", "queries", Key(dist.name(), n));
    let c = clusters();
    (0..count).map(move |_| {
        DVec3::from_array(match dist {
            PointDistribution::Clustered => clustered_point(&mut rng, &c),
            PointDistribution::NearTies => {
                // A cell centre inside the filled part of the grid.
                let m = grid_side(n);
                let cells = (n / (m * m)).max(1);
                let cell = [m - 1, m - 1, cells - 1].map(|k| rng.next_u64() as usize % k.max(1));
                cell.map(|c| nudge(&mut rng, (c as f64 + 0.5) / m as f64))
            }
            _ => uniform_point(&mut rng),
        })
    })
}
