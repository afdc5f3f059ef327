//! Parameter intervals `[min, max]` of a ray, validated once at
//! construction: the ground floor of every ray query and of the roots.

use crate::error::InputError;

/// A closed parameter interval `[min, max]`; either bound may be infinite.
///
/// ```
/// use exactray::interval::Interval;
/// use exactray::InputError;
/// let forward = Interval::new(0.0, f64::INFINITY).unwrap();
/// assert!(forward.contains(1e300) && !forward.contains(-1e-300));
/// assert_eq!(Interval::new(2.0, 1.0).unwrap_err(), InputError::ReversedInterval);
/// assert_eq!(Interval::new(f64::NAN, 1.0).unwrap_err(), InputError::NotANumber { argument: "min" });
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    min: f64,
    max: f64,
}

impl Interval {
    /// Every `t >= 0`: the usual range of a ray.
    pub const FORWARD: Interval = Interval {
        min: 0.0,
        max: f64::INFINITY,
    };

    /// `[min, max]`. Errors: [`InputError::NotANumber`] naming `"min"` or
    /// `"max"`; [`InputError::ReversedInterval`] when `min > max`. `min ==
    /// max` is allowed (a single parameter).
    pub fn new(min: f64, max: f64) -> Result<Interval, InputError> {
        if min.is_nan() {
            return Err(InputError::NotANumber { argument: "min" });
        }
        if max.is_nan() {
            return Err(InputError::NotANumber { argument: "max" });
        }
        if min > max {
            return Err(InputError::ReversedInterval);
        }
        Ok(Interval { min, max })
    }

    /// The lower bound.
    #[inline]
    pub fn min(&self) -> f64 {
        self.min
    }

    /// The upper bound.
    #[inline]
    pub fn max(&self) -> f64 {
        self.max
    }

    /// Whether `min <= t <= max` (`false` for NaN).
    #[inline]
    pub fn contains(&self, t: f64) -> bool {
        self.min <= t && t <= self.max
    }

    /// Whether a cast may report a hit at the computed parameter `t`: `t`
    /// is finite and inside the interval. Every cast of the crate reports
    /// only such hits, so a crossing whose parameter lies beyond `f64`'s
    /// range (it rounds to an infinity) is no hit, and the cast looks on to
    /// a later crossing; one within the cast's stated error of `f64::MAX`
    /// may go either way. A NaN `t` is not admitted.
    ///
    /// ```
    /// use exactray::interval::Interval;
    /// assert!(Interval::FORWARD.admits(1e308));
    /// assert!(!Interval::FORWARD.admits(f64::INFINITY));
    /// assert!(Interval::FORWARD.contains(f64::INFINITY));
    /// ```
    #[inline]
    pub fn admits(&self, t: f64) -> bool {
        // `t` finite and in `[min, max]` is `t` in `[min, max]` clamped to
        // the finite doubles (NaN fails either way): two comparisons with
        // bounds that do not depend on `t`, so a loop over many casts with
        // one interval computes them once.
        let lo = self.min.max(-f64::MAX);
        let hi = self.max.min(f64::MAX);
        lo <= t && t <= hi
    }
}

serde_by_constructor!(
    Interval as "Interval" { min: f64, max: f64 },
    parts: |i| (i.min, i.max),
    build: |d| Interval::new(d.min, d.max),
);

#[cfg(test)]
mod tests {
    use super::*;

    /// `admits` is its definition, finite and contained, on every pair of
    /// bounds and parameter drawn from the values where it could differ:
    /// infinities, the largest finite doubles, zeros, NaN.
    #[test]
    fn admits_is_finite_and_contained() {
        let edges = [
            f64::NEG_INFINITY,
            -f64::MAX,
            -1.0,
            -0.0,
            0.0,
            f64::from_bits(1),
            1.0,
            f64::MAX,
            f64::INFINITY,
        ];
        for &min in &edges {
            for &max in edges.iter().filter(|&&m| m >= min) {
                let range = Interval::new(min, max).unwrap();
                for t in edges.iter().copied().chain([f64::NAN]) {
                    let want = range.contains(t) && t.is_finite();
                    assert_eq!(range.admits(t), want, "[{min}, {max}] at {t}");
                }
            }
        }
    }

    #[test]
    fn validation() {
        let nan = f64::NAN;
        assert_eq!(
            Interval::new(0.0, nan),
            Err(InputError::NotANumber { argument: "max" })
        );
        let point = Interval::new(3.0, 3.0).unwrap();
        assert!(point.contains(3.0) && !point.contains(nan));
        assert!(
            Interval::new(f64::NEG_INFINITY, f64::INFINITY)
                .unwrap()
                .contains(-1e308)
        );
    }
}
