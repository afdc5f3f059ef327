//! Within-radius queries: every point at exact distance at most `r`.

use super::traverse::{Visitor, reach_of, scale_of, walk};
use super::{Nearest, SphereBvh};
use crate::error::InputError;
use crate::point::IntoDVec3;
use crate::predicates::{cmp_lengths, distance};
use crate::sign::Sign;
use glam::DVec3;

struct Within<F> {
    q: DVec3,
    /// `(r, 0, 0)`: the exact comparison measures `|p - q|` against it.
    r: DVec3,
    /// Computed `(r s)^2`.
    r2: f64,
    reach: f64,
    found: usize,
    f: F,
    no_counter: (),
}

impl<F: FnMut(Nearest)> Visitor for Within<F> {
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
        let inside = match distance::filtered(d2, self.r2) {
            Some(sign) => sign == Sign::Negative,
            None => cmp_lengths(tree.point(i), self.q, self.r, DVec3::ZERO) != Sign::Positive,
        };
        if inside {
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
    /// use exactray::SphereBvh;
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
        let mut within = Within {
            q,
            r: DVec3::new(r, 0.0, 0.0),
            r2,
            reach: reach_of(r2 * (1.0 + 4.0 * f64::EPSILON)),
            found: 0,
            f,
            no_counter: (),
        };
        walk(self, root, q, s, &mut within);
        Ok(within.found)
    }
}
