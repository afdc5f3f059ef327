//! Many nearest-point queries at once, in parallel under the `rayon` feature.

use super::{Nearest, SphereBvh};
use crate::error::InputError;
use glam::DVec3;

impl SphereBvh {
    /// `out[i] = self.nearest(queries[i])` for every `i`, spread over
    /// rayon's thread pool under the `rayon` feature (default), on the
    /// calling thread otherwise. Non-finite queries give `None`.
    ///
    /// Errors: [`InputError::LengthMismatch`] (`expected` = `queries.len()`)
    /// when `out` has another length; nothing is written then.
    ///
    /// ```
    /// use exactray::bvh::SphereBvh;
    /// use glam::DVec3;
    /// let bvh = SphereBvh::from_points(&[DVec3::ZERO, DVec3::X]).unwrap();
    /// let queries = [DVec3::new(0.9, 0.0, 0.0), DVec3::new(-1.0, 0.0, 0.0)];
    /// let mut out = [None; 2];
    /// bvh.nearest_many(&queries, &mut out).unwrap();
    /// assert_eq!(out.map(|h| h.unwrap().index), [1, 0]);
    /// ```
    pub fn nearest_many(
        &self,
        queries: &[DVec3],
        out: &mut [Option<Nearest>],
    ) -> Result<(), InputError> {
        InputError::check_lengths(queries.len(), out.len())?;
        #[cfg(feature = "rayon")]
        {
            use rayon::prelude::*;
            queries
                .par_iter()
                .zip(out.par_iter_mut())
                .with_min_len(256)
                .for_each(|(q, o)| *o = self.nearest(*q));
        }
        #[cfg(not(feature = "rayon"))]
        self.nearest_many_serial(queries, out)?;
        Ok(())
    }

    /// [`nearest_many`](Self::nearest_many) on the calling thread only.
    pub fn nearest_many_serial(
        &self,
        queries: &[DVec3],
        out: &mut [Option<Nearest>],
    ) -> Result<(), InputError> {
        InputError::check_lengths(queries.len(), out.len())?;
        for (q, o) in queries.iter().zip(out.iter_mut()) {
            *o = self.nearest(*q);
        }
        Ok(())
    }
}
