//! Within-radius queries: every point (or ball) at exact distance at most `r`.

use super::nearest::{Balls, Metric, Points};
use super::traverse::{Visitor, reach_of, scale_of, walk};
use super::{Child, Nearest, SphereBvh};
use crate::error::InputError;
use crate::point::IntoDVec3;
use core::marker::PhantomData;
use glam::DVec3;

struct Within<M, F> {
    q: DVec3,
    s: f64,
    r: f64,
    /// Computed `(r s)^2`.
    r2: f64,
    reach: f64,
    found: usize,
    f: F,
    no_counter: (),
    metric: PhantomData<M>,
}

impl<M: Metric, F: FnMut(Nearest)> Visitor for Within<M, F> {
    type Counter = ();
    #[inline(always)]
    fn counter(&mut self) -> &mut () {
        &mut self.no_counter
    }

    #[inline(always)]
    fn reach(&self) -> f64 {
        self.reach
    }

    #[inline]
    fn point(&mut self, tree: &SphereBvh, i: usize, d2: f64) {
        if M::within(tree, self.q, (i, d2), self.s, (self.r, self.r2)) {
            self.found += 1;
            (self.f)(tree.answer(i, self.q));
        }
    }
}

impl SphereBvh {
    /// Calls `f` for every point at exact distance at most `r` from `q`
    /// (boundary included, decided exactly), in no particular order; returns
    /// how many.
    ///
    /// Errors: [`InputError::NonFinite`] for a NaN or infinite coordinate of
    /// `q` (argument `"q"`) or an infinite `r` (argument `"r"`);
    /// [`InputError::InvalidRadius`] for a negative or NaN `r`.
    ///
    /// ```
    /// use exactray::bvh::SphereBvh;
    /// let points: Vec<[f64; 3]> = (0..10).map(|i| [i as f64, 0.0, 0.0]).collect();
    /// let bvh = SphereBvh::from_points(&points).unwrap();
    /// let mut hits = Vec::new();
    /// // Points 2 and 6 lie exactly on the sphere: included.
    /// assert_eq!(bvh.within_radius([4.0, 0.0, 0.0], 2.0, |h| hits.push(h.index)), Ok(5));
    /// hits.sort();
    /// assert_eq!(hits, [2, 3, 4, 5, 6]);
    /// ```
    pub fn within_radius<P: IntoDVec3>(
        &self,
        q: P,
        r: f64,
        f: impl FnMut(Nearest),
    ) -> Result<usize, InputError> {
        let q = q.into_dvec3();
        if !q.is_finite() {
            return Err(InputError::NonFinite { argument: "q" });
        }
        if r.is_nan() || r < 0.0 {
            return Err(InputError::InvalidRadius { argument: "r" });
        }
        if r.is_infinite() {
            return Err(InputError::NonFinite { argument: "r" });
        }
        let Some(root) = self.root.as_ref() else {
            return Ok(0);
        };
        let s = scale_of(self, q);
        let rs = r * s;
        // An upper bound of the exact `(r s)^2`, for the prune; the filter
        // takes the computed square, whose error it bounds itself.
        let r2 = rs * rs;
        let reach = reach_of(r2 * (1.0 + 4.0 * f64::EPSILON));
        Ok(if self.radii.is_empty() {
            self.within_by::<Points, _>(root, (q, s), (r, r2, reach), f)
        } else {
            self.within_by::<Balls, _>(root, (q, s), (r, r2, reach), f)
        })
    }

    fn within_by<M: Metric, F: FnMut(Nearest)>(
        &self,
        root: &Child,
        (q, s): (DVec3, f64),
        (r, r2, reach): (f64, f64, f64),
        f: F,
    ) -> usize {
        let mut within = Within::<M, F> {
            q,
            s,
            r,
            r2,
            reach,
            found: 0,
            f,
            no_counter: (),
            metric: PhantomData,
        };
        walk(self, root, q, s, &mut within);
        within.found
    }
}
