//! Nearest and k-nearest queries: exact answers from `f64` distances, with
//! exact comparisons only for near-ties.

use super::sphere::UNDERFLOW_DISTANCE;
use super::traverse::{Visitor, reach_of, scale_of, walk};
use super::{Child, Counter, LEAF, Nearest, QueryStats, SphereBvh, sqrt};
use crate::arith::exponent::TINY;
use crate::arith::roundoff::U;
use crate::error::InputError;
use crate::point::IntoDVec3;
use crate::predicates::ball::{cmp_ball_distances, cmp_length_to_sum};
use crate::predicates::cmp_lengths;
use crate::predicates::distance;
use crate::sign::Sign;
use core::marker::PhantomData;
use glam::DVec3;

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
pub(crate) struct Band {
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
            lo: overflow_floor(d2, d2 * (1.0 - BAND) - BAND_SLACK),
        }
    }
}

/// `lo`, or 0 when `d2` overflowed: an infinite computed distance (two
/// coordinates near `f64::MAX` of opposite signs) says nothing of the exact
/// one except that it is large, so it must not look certainly farther.
#[inline(always)]
fn overflow_floor(d2: f64, lo: f64) -> f64 {
    if d2 < f64::INFINITY { lo } else { 0.0 }
}

// A leaf's lanes fit the bits of a `u32` (see `Best::leaf`).
const _: () = assert!(LEAF <= 32);

/// `true` when no coordinate difference between `q` and a point of `tree`
/// can overflow: every magnitude is below `2^1022`, so differences stay
/// below `2^1023`, and once scaled (see [`scale_of`]) below 2, as do their
/// squares' sums below 12.
#[inline]
fn no_overflow(tree: &SphereBvh, q: DVec3) -> bool {
    tree.max_abs.max(q.abs().max_element()) < crate::arith::exponent::pow2(1022)
}

/// How a query measures items: points by computed squared scaled distance,
/// balls by computed scaled distance to the ball. A candidate's key and the
/// band of keys its exact value may have; an exact comparison for the rest.
pub(crate) trait Metric {
    /// The key of tree position `i` at computed squared scaled distance
    /// `d2`, and the band it certainly lies in as a candidate.
    fn candidate(tree: &SphereBvh, i: usize, d2: f64, s: f64) -> (f64, Band);
    /// The band of an answer with key `key` and candidate band `band`:
    /// another candidate whose band lies wholly above it is certainly
    /// farther, wholly below it certainly nearer.
    fn answer_band(key: f64, band: Band) -> Band;
    /// For a leaf whose smallest computed squared scaled distance is
    /// `least`, while the answer's band tops out at `hi`: a cut above which
    /// a leaf item's computed squared scaled distance makes it certainly not
    /// the answer (farther than the best so far, or than the leaf's nearest
    /// item), given that no computed squared distance of this query
    /// overflows (`finite`). `inf` when unsure.
    #[inline(always)]
    fn leaf_cut(_least: f64, _hi: f64, _finite: bool) -> f64 {
        f64::INFINITY
    }
    /// An upper bound (for the prune) of the exact scaled distance of an
    /// answer whose band tops out at `hi`.
    fn reach(hi: f64) -> f64;
    /// The exact sign of (distance of `i`) - (distance of `j`), tree positions.
    fn exact(tree: &SphereBvh, q: DVec3, i: usize, j: usize) -> Sign;
    /// Whether item `i` (computed squared scaled distance `d2`) lies at
    /// exact distance at most `r` from `q`; `rs2` is the computed `(r s)^2`.
    fn within(tree: &SphereBvh, q: DVec3, item: (usize, f64), s: f64, radius: (f64, f64)) -> bool;
}

/// Points: the key is the squared distance, and the answer's band (16u
/// each way, see [`BAND`]) covers the errors of both sides.
pub(crate) struct Points;

impl Metric for Points {
    #[inline(always)]
    fn candidate(_: &SphereBvh, _: usize, d2: f64, _: f64) -> (f64, Band) {
        (
            d2,
            Band {
                hi: d2,
                lo: overflow_floor(d2, d2),
            },
        )
    }
    #[inline(always)]
    fn answer_band(key: f64, _: Band) -> Band {
        Band::around(key)
    }
    /// A point's candidate band starts at its `d2` unless `d2` overflowed,
    /// so above `hi` it is rejected; above the band around `least` it is
    /// certainly farther than the leaf's nearest point (see [`before`]).
    #[inline(always)]
    fn leaf_cut(least: f64, hi: f64, finite: bool) -> f64 {
        if finite {
            hi.min(Band::around(least).hi)
        } else {
            f64::INFINITY
        }
    }
    #[inline(always)]
    fn reach(hi: f64) -> f64 {
        reach_of(hi)
    }
    #[inline]
    fn exact(tree: &SphereBvh, q: DVec3, i: usize, j: usize) -> Sign {
        cmp_lengths(tree.point(i), q, tree.point(j), q)
    }
    #[inline]
    fn within(
        tree: &SphereBvh,
        q: DVec3,
        (i, d2): (usize, f64),
        _: f64,
        (r, rs2): (f64, f64),
    ) -> bool {
        match distance::filtered(d2, rs2) {
            Some(sign) => sign == Sign::Negative,
            None => {
                cmp_lengths(tree.point(i), q, DVec3::new(r, 0.0, 0.0), DVec3::ZERO)
                    != Sign::Positive
            }
        }
    }
}

/// Balls: the key is `max(0, sqrt(d2) - r s)`. Its error: `sqrt(d2)` is
/// within `3.5u` of the exact `|c - q| s` (the squared norm's `gamma_5`
/// halved, plus the `sqrt` rounding) and `2^-535` (underflow, see
/// `traverse.rs`), `r s` within `2^-1075`, the subtraction adds `u` of the
/// result, and clamping at zero does not increase an error. `8u (sqrt(d2) +
/// r s) + 2^-530` bounds it all.
pub(crate) struct Balls;

impl Metric for Balls {
    #[inline(always)]
    fn candidate(tree: &SphereBvh, i: usize, d2: f64, s: f64) -> (f64, Band) {
        let (root, r) = (sqrt(d2), tree.radii[i] * s);
        let key = (root - r).max(0.0);
        let err = 8.0 * U * (root + r) + UNDERFLOW_DISTANCE;
        (
            key,
            Band {
                hi: key + err,
                lo: overflow_floor(d2, key - err),
            },
        )
    }
    #[inline(always)]
    fn answer_band(_: f64, band: Band) -> Band {
        band
    }
    #[inline(always)]
    fn reach(hi: f64) -> f64 {
        // The prune wants 7u and 2^-529 over the exact distance; `hi` bounds
        // it already, this adds the margins (see `traverse::reach_of`).
        hi * (1.0 + 8.0 * U) + 2.0 * UNDERFLOW_DISTANCE
    }
    #[inline]
    fn exact(tree: &SphereBvh, q: DVec3, i: usize, j: usize) -> Sign {
        let ball = |k: usize| (tree.point(k), tree.radii[k]);
        cmp_ball_distances(q, ball(i), ball(j))
    }
    #[inline]
    fn within(
        tree: &SphereBvh,
        q: DVec3,
        (i, d2): (usize, f64),
        s: f64,
        (r, _): (f64, f64),
    ) -> bool {
        let (_, band) = Self::candidate(tree, i, d2, s);
        // `r s` is exact or, below `2^-1022`, off by `2^-1075`; its margin
        // here is `u` relative and `2^-1073`.
        let rs = r * s;
        let margin = rs * U + 2.0 * TINY;
        if band.hi < rs - margin {
            true
        } else if band.lo > rs + margin {
            false
        } else {
            cmp_length_to_sum(q, tree.point(i), r, tree.radii[i]) != Sign::Positive
        }
    }
}

/// Whether candidate `i` (band `cand`) comes strictly before the answer at
/// tree position `j` (band `band`): nearer, or exactly as near with a
/// smaller original index.
#[inline]
fn before<M: Metric, C: Counter>(
    tree: &SphereBvh,
    q: DVec3,
    (i, cand): (usize, Band),
    (j, band): (usize, Band),
    counter: &mut C,
) -> bool {
    if cand.hi < band.lo {
        return true;
    }
    if cand.lo > band.hi {
        return false;
    }
    counter.exact();
    match M::exact(tree, q, i, j) {
        Sign::Negative => true,
        Sign::Positive => false,
        Sign::Zero => tree.index[i] < tree.index[j],
    }
}

/// The nearest-point visitor. [`KBest`] with `k = 1` gives the same
/// answers, but its ordered insertion measured 7% more instructions per
/// query (callgrind, 10^4 uniform points), so the single best keeps this
/// lighter update.
struct Best<'c, M, C> {
    q: DVec3,
    s: f64,
    /// Tree position of the best so far (`usize::MAX`: none yet).
    at: usize,
    band: Band,
    reach: f64,
    /// No computed squared distance of this query can overflow.
    finite: bool,
    counter: &'c mut C,
    metric: PhantomData<M>,
}

impl<M: Metric, C: Counter> Visitor for Best<'_, M, C> {
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
    fn leaf(&mut self, tree: &SphereBvh, start: usize, d2: &[f64; LEAF], len: usize, least: f64) {
        // Most leaves reached after the first hold no nearer point, and in
        // the others one point is usually alone near the leaf's nearest.
        let cut = M::leaf_cut(least, self.band.hi, self.finite);
        if least > cut {
            return;
        }
        // The lanes at or below the cut as bits (vector compares), then
        // only those points, in order.
        let mut wanted = 0u32;
        for (k, &d) in d2.iter().enumerate() {
            wanted |= ((d <= cut) as u32) << k;
        }
        // `len <= LEAF`; a leaf is never empty, but an empty one keeps no lane.
        wanted &= u32::MAX.checked_shr((LEAF - len) as u32).unwrap_or(0);
        while wanted != 0 {
            let k = wanted.trailing_zeros() as usize;
            wanted &= wanted - 1;
            self.point(tree, start + k, d2[k]);
        }
    }

    #[inline(always)]
    fn point(&mut self, tree: &SphereBvh, i: usize, d2: f64) {
        let (key, cand) = M::candidate(tree, i, d2, self.s);
        if cand.lo > self.band.hi {
            return;
        }
        let better = self.at == usize::MAX
            || before::<M, C>(tree, self.q, (i, cand), (self.at, self.band), self.counter);
        if better {
            self.at = i;
            self.band = M::answer_band(key, cand);
            self.reach = M::reach(self.band.hi);
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
    /// use exactray::bvh::SphereBvh;
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
    /// use exactray::{bvh::SphereBvh, bvh::QueryStats};
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
        if self.radii.is_empty() {
            self.nearest_by::<Points, C>(root, q, counter)
        } else {
            self.nearest_by::<Balls, C>(root, q, counter)
        }
    }

    #[inline]
    fn nearest_by<M: Metric, C: Counter>(
        &self,
        root: &Child,
        q: DVec3,
        counter: &mut C,
    ) -> Option<Nearest> {
        let s = scale_of(self, q);
        let mut best = Best::<M, C> {
            q,
            s,
            at: usize::MAX,
            band: Band::OPEN,
            reach: f64::INFINITY,
            finite: no_overflow(self, q),
            counter,
            metric: PhantomData,
        };
        walk(self, root, q, s, &mut best);
        if best.at == usize::MAX {
            return None;
        }
        Some(self.answer(best.at, q))
    }
}

/// The k-nearest visitor: `out[..n]` sorted. While the walk runs, an
/// entry's `index` is its tree position and its `point` holds its band
/// `(lo, hi, 0)`; both are replaced when the walk ends.
struct KBest<'o, 'c, M, C> {
    q: DVec3,
    s: f64,
    out: &'o mut [Nearest],
    n: usize,
    reach: f64,
    /// Above this, certainly not among the k nearest (once `n == k`).
    hi: f64,
    counter: &'c mut C,
    metric: PhantomData<M>,
}

impl<M: Metric, C: Counter> Visitor for KBest<'_, '_, M, C> {
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
        let (key, cand) = M::candidate(tree, i, d2, self.s);
        if cand.lo > self.hi {
            return;
        }
        let k = self.out.len();
        let band_of = |e: &Nearest| Band {
            lo: e.point.x,
            hi: e.point.y,
        };
        // Where the candidate goes: after every entry it does not come before.
        let mut at = self.n;
        while at > 0 {
            let e = &self.out[at - 1];
            let entry = (e.index, band_of(e));
            if !before::<M, C>(tree, self.q, (i, cand), entry, self.counter) {
                break;
            }
            at -= 1;
        }
        if at == k {
            return;
        }
        let last = self.n.min(k - 1);
        self.out.copy_within(at..last, at + 1);
        let band = M::answer_band(key, cand);
        self.out[at] = Nearest {
            index: i,
            point: DVec3::new(band.lo, band.hi, 0.0),
            distance: key,
        };
        self.n = (self.n + 1).min(k);
        if self.n == k {
            self.hi = band_of(&self.out[k - 1]).hi;
            self.reach = M::reach(self.hi);
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
    /// use exactray::{bvh::SphereBvh, bvh::Nearest};
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
        let n = if self.radii.is_empty() {
            self.nearest_k_by::<Points, C>(root, q, out, counter)
        } else {
            self.nearest_k_by::<Balls, C>(root, q, out, counter)
        };
        for e in &mut out[..n] {
            *e = self.answer(e.index, q);
        }
        n
    }

    fn nearest_k_by<M: Metric, C: Counter>(
        &self,
        root: &Child,
        q: DVec3,
        out: &mut [Nearest],
        counter: &mut C,
    ) -> usize {
        let s = scale_of(self, q);
        let mut kbest = KBest::<M, C> {
            q,
            s,
            out,
            n: 0,
            reach: f64::INFINITY,
            hi: f64::INFINITY,
            counter,
            metric: PhantomData,
        };
        walk(self, root, q, s, &mut kbest);
        kbest.n
    }
}
