//! Nearest and k-nearest queries: exact answers from `f64` distances, with
//! exact comparisons only for near-ties.

use super::traverse::{Visitor, reach_of, scale_of, walk};
use super::{Counter, Nearest, QueryStats, SphereBvh};
use crate::error::InputError;
use crate::point::IntoDVec3;
use crate::predicates::cmp_lengths;
use crate::predicates::grain::TINY;
use crate::sign::Sign;
use glam::DVec3;

/// `u = 2^-53`.
const U: f64 = f64::EPSILON / 2.0;

/// Half-width of the band of computed squared distances that may hide a
/// tie. Each computed squared distance is within `gamma_5 < 5.01u` (relative)
/// and `2^-1071` (absolute, underflow) of the exact one (see
/// `predicates::distance`). A candidate at computed `d` is certainly farther
/// than the best at computed `b` when `d (1 - gamma_5) - 2^-1071 >
/// b (1 + gamma_5) + 2^-1071`, which `d > b (1 + 16u) + 2^-1069` implies
/// with room for the rounding of the band itself; symmetrically for
/// certainly nearer. Between the two, an exact comparison decides.
const BAND: f64 = 16.0 * U;
const BAND_SLACK: f64 = 32.0 * TINY;

/// A best-so-far distance and the band around it.
#[derive(Clone, Copy, Debug)]
struct Band {
    /// Above this, certainly farther than the best.
    hi: f64,
    /// Below this, certainly nearer than the best.
    lo: f64,
}

impl Band {
    const OPEN: Band = Band {
        hi: f64::INFINITY,
        lo: f64::INFINITY,
    };

    #[inline]
    fn around(d2: f64) -> Band {
        Band {
            hi: d2 * (1.0 + BAND) + BAND_SLACK,
            lo: d2 * (1.0 - BAND) - BAND_SLACK,
        }
    }
}

/// Whether the point at tree position `i` (computed squared distance `d2`)
/// comes strictly before the answer `(j, point_j)` at band `band`: nearer,
/// or exactly as near with a smaller original index.
#[inline]
fn before<C: Counter>(
    tree: &SphereBvh,
    q: DVec3,
    i: usize,
    d2: f64,
    other: (usize, DVec3),
    band: &Band,
    counter: &mut C,
) -> bool {
    if d2 < band.lo {
        return true;
    }
    if d2 > band.hi {
        return false;
    }
    counter.exact();
    match cmp_lengths(tree.point(i), q, other.1, q) {
        Sign::Negative => true,
        Sign::Positive => false,
        Sign::Zero => (tree.index[i] as usize) < other.0,
    }
}

/// The nearest-point visitor.
struct Best<'c, C> {
    q: DVec3,
    /// Tree position of the best so far (`usize::MAX`: none yet).
    at: usize,
    band: Band,
    reach: f64,
    counter: &'c mut C,
}

impl<C: Counter> Visitor for Best<'_, C> {
    type Counter = C;
    #[inline(always)]
    fn counter(&mut self) -> &mut C {
        self.counter
    }

    #[inline(always)]
    fn reach(&self) -> f64 {
        self.reach
    }

    #[inline(always)]
    fn point(&mut self, tree: &SphereBvh, i: usize, d2: f64) {
        if d2 > self.band.hi {
            return;
        }
        let better = self.at == usize::MAX
            || before(
                tree,
                self.q,
                i,
                d2,
                (tree.index[self.at] as usize, tree.point(self.at)),
                &self.band,
                self.counter,
            );
        if better {
            self.at = i;
            self.band = Band::around(d2);
            self.reach = reach_of(self.band.hi);
        }
    }
}

impl SphereBvh {
    /// The point nearest to `q`: a true nearest point for every finite input
    /// (exact on ties and near-ties; among exact ties, the one with the
    /// smallest index). `None` when the index is empty or `q` has a NaN or
    /// infinite coordinate (see [`try_nearest`](Self::try_nearest)).
    ///
    /// ```
    /// use exactray::SphereBvh;
    /// let bvh = SphereBvh::from_points(&[[1.0, 0.0, 0.0], [0.0, 1.0 + f64::EPSILON, 0.0]]).unwrap();
    /// // The two squared distances round to the same f64; point 0 is nearer.
    /// let hit = bvh.nearest([0.0, 0.0, 0.0]).unwrap();
    /// assert_eq!((hit.index, hit.distance), (0, 1.0));
    /// ```
    #[inline]
    pub fn nearest<P: IntoDVec3>(&self, q: P) -> Option<Nearest> {
        self.nearest_counted(q.into_dvec3(), &mut ())
    }

    /// [`nearest`](Self::nearest) that rejects a NaN or infinite query with
    /// [`InputError::NonFinite`] (argument `"q"`); `Ok(None)` when empty.
    pub fn try_nearest<P: IntoDVec3>(&self, q: P) -> Result<Option<Nearest>, InputError> {
        let q = q.into_dvec3();
        if !q.is_finite() {
            return Err(InputError::NonFinite { argument: "q" });
        }
        Ok(self.nearest_counted(q, &mut ()))
    }

    /// [`nearest`](Self::nearest), adding the work it did to `stats`.
    ///
    /// ```
    /// use exactray::{SphereBvh, bvh::QueryStats};
    /// let points: Vec<[f64; 3]> = (0..1000).map(|i| [i as f64, 0.0, 0.0]).collect();
    /// let bvh = SphereBvh::from_points(&points).unwrap();
    /// let mut stats = QueryStats::default();
    /// assert_eq!(bvh.nearest_with_stats([500.2, 1.0, 0.0], &mut stats).unwrap().index, 500);
    /// assert!(stats.distances_computed < 100);
    /// ```
    pub fn nearest_with_stats<P: IntoDVec3>(
        &self,
        q: P,
        stats: &mut QueryStats,
    ) -> Option<Nearest> {
        self.nearest_counted(q.into_dvec3(), stats)
    }

    #[inline]
    fn nearest_counted<C: Counter>(&self, q: DVec3, counter: &mut C) -> Option<Nearest> {
        let root = self.root.as_ref()?;
        if !q.is_finite() {
            return None;
        }
        let s = scale_of(self, q);
        let mut best = Best {
            q,
            at: usize::MAX,
            band: Band::OPEN,
            reach: f64::INFINITY,
            counter,
        };
        walk(self, root, q, s, &mut best);
        if best.at == usize::MAX {
            return None;
        }
        Some(self.answer(best.at, q))
    }
}

/// The k-nearest visitor: `out[..n]` sorted, each entry's `distance` holding
/// its computed squared scaled distance until the walk ends.
struct KBest<'o, 'c, C> {
    q: DVec3,
    out: &'o mut [Nearest],
    n: usize,
    reach: f64,
    /// Above this, certainly not among the k nearest (once `n == k`).
    hi: f64,
    counter: &'c mut C,
}

impl<C: Counter> Visitor for KBest<'_, '_, C> {
    type Counter = C;
    #[inline(always)]
    fn counter(&mut self) -> &mut C {
        self.counter
    }

    #[inline(always)]
    fn reach(&self) -> f64 {
        self.reach
    }

    #[inline]
    fn point(&mut self, tree: &SphereBvh, i: usize, d2: f64) {
        if d2 > self.hi {
            return;
        }
        let k = self.out.len();
        // Where the candidate goes: after every entry it does not come before.
        let mut at = self.n;
        while at > 0 {
            let e = self.out[at - 1];
            let band = Band::around(e.distance);
            if !before(tree, self.q, i, d2, (e.index, e.point), &band, self.counter) {
                break;
            }
            at -= 1;
        }
        if at == k {
            return;
        }
        let last = self.n.min(k - 1);
        self.out.copy_within(at..last, at + 1);
        self.out[at] = Nearest {
            index: tree.index[i] as usize,
            point: tree.point(i),
            distance: d2,
        };
        self.n = (self.n + 1).min(k);
        if self.n == k {
            self.hi = Band::around(self.out[k - 1].distance).hi;
            self.reach = reach_of(self.hi);
        }
    }
}

impl SphereBvh {
    /// The `k = out.len()` points nearest to `q`, nearest first, into
    /// `out[..n]`; returns `n = min(k, len)`. Exact like
    /// [`nearest`](Self::nearest): every returned point is nearer than or
    /// exactly as near as every point left out, ties ordered by index.
    /// Returns 0 (and leaves `out` alone) when `q` is not finite.
    ///
    /// ```
    /// use exactray::{SphereBvh, bvh::Nearest};
    /// use glam::DVec3;
    /// let points: Vec<[f64; 3]> = (0..10).map(|i| [i as f64, 0.0, 0.0]).collect();
    /// let bvh = SphereBvh::from_points(&points).unwrap();
    /// let mut out = [Nearest { index: 0, point: DVec3::ZERO, distance: 0.0 }; 3];
    /// assert_eq!(bvh.nearest_k([4.4, 0.0, 0.0], &mut out), 3);
    /// assert_eq!(out.map(|h| h.index), [4, 5, 3]);
    /// ```
    pub fn nearest_k<P: IntoDVec3>(&self, q: P, out: &mut [Nearest]) -> usize {
        self.nearest_k_counted(q.into_dvec3(), out, &mut ())
    }

    /// [`nearest_k`](Self::nearest_k), adding the work it did to `stats`.
    pub fn nearest_k_with_stats<P: IntoDVec3>(
        &self,
        q: P,
        out: &mut [Nearest],
        stats: &mut QueryStats,
    ) -> usize {
        self.nearest_k_counted(q.into_dvec3(), out, stats)
    }

    fn nearest_k_counted<C: Counter>(
        &self,
        q: DVec3,
        out: &mut [Nearest],
        counter: &mut C,
    ) -> usize {
        let Some(root) = self.root.as_ref() else {
            return 0;
        };
        if out.is_empty() || !q.is_finite() {
            return 0;
        }
        let s = scale_of(self, q);
        let mut kbest = KBest {
            q,
            out,
            n: 0,
            reach: f64::INFINITY,
            hi: f64::INFINITY,
            counter,
        };
        walk(self, root, q, s, &mut kbest);
        let n = kbest.n;
        for e in &mut kbest.out[..n] {
            e.distance = super::distance(e.point, q);
        }
        n
    }
}
