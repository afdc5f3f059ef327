//! Where the bits of a set of `f64` values lie: the binary exponents that
//! decide which exact stage can take them, and exact power-of-two scaling.
//!
//! A finite non-zero `f64` is `m * 2^e` with an odd integer `m`; its lowest
//! set bit has weight `2^lo` and its highest `2^hi`. For a set of values,
//! `lo_min` is the finest bit any of them has and `hi_max` the coarsest.

/// The smallest positive `f64`, `2^-1074`: the unit of the absolute error
/// terms that account for underflow.
pub(crate) const TINY: f64 = f64::from_bits(1);

/// `v = m * 2^e` exactly, with `|m| < 2^53` (not reduced to odd).
#[inline(always)]
pub(crate) fn split(v: f64) -> (i64, i32) {
    let bits = v.to_bits();
    let exp_field = ((bits >> 52) & 0x7ff) as i32;
    let hidden = ((exp_field != 0) as u64) << 52;
    let m = ((bits & ((1u64 << 52) - 1)) | hidden) as i64;
    let e = exp_field.max(1) - 1075;
    (if (bits as i64) < 0 { -m } else { m }, e)
}

/// The finest and coarsest bit positions of a set of finite values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Grain {
    /// Smallest `lo` over the non-zero values (`i32::MAX` if all are zero).
    pub lo_min: i32,
    /// Largest `hi` over the non-zero values (`i32::MIN` if all are zero).
    pub hi_max: i32,
}

impl Grain {
    /// The grain of `values`; all must be finite.
    #[inline]
    pub(crate) fn of(values: &[f64]) -> Grain {
        let mut g = Grain {
            lo_min: i32::MAX,
            hi_max: i32::MIN,
        };
        for &v in values {
            let (m, e) = split(v);
            if m != 0 {
                let mag = m.unsigned_abs();
                g.lo_min = g.lo_min.min(e + mag.trailing_zeros() as i32);
                g.hi_max = g.hi_max.max(e + 63 - mag.leading_zeros() as i32);
            }
        }
        g
    }

    /// `true` when every value is zero.
    #[inline]
    pub(crate) fn all_zero(self) -> bool {
        self.lo_min == i32::MAX
    }

    /// Bits needed for the largest value as an integer multiple of
    /// `2^lo_min`: every value is `X * 2^lo_min` with `|X| < 2^span`; 0
    /// when every value is zero.
    #[inline]
    pub(crate) fn span(self) -> i32 {
        if self.all_zero() {
            0
        } else {
            self.hi_max - self.lo_min + 1
        }
    }
}

/// The exponent `s` such that scaling by `2^s` puts the largest magnitude of
/// `values` in `[1/2, 1)`; `0` when all are zero. Reads only the largest.
#[inline]
pub(crate) fn unit_scale(values: &[f64]) -> i32 {
    let max = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if max == 0.0 {
        return 0;
    }
    let (m, e) = split(max);
    -(e + 64 - m.leading_zeros() as i32)
}

/// `2^s` with `s = unit_scale(&[m])` clamped to `[-1000, 1000]`: the power
/// of two that brings `m` into `[1/2, 1)`, or as near as the clamp allows;
/// it and its reciprocal are normal, so scaling by either is exact unless
/// the result leaves the normal range.
#[inline]
pub(crate) fn unit_pow2(m: f64) -> f64 {
    pow2(unit_scale(&[m]).clamp(-1000, 1000))
}

/// Whether a filter that failed saw magnitudes (its permanent) where its
/// bound had no underflow or overflow to absorb: then the input is
/// genuinely near-degenerate and rescaling it cannot help. `false` for NaN.
#[inline]
pub(crate) fn in_range(permanent: f64) -> bool {
    (pow2(-900)..pow2(900)).contains(&permanent)
}

/// `v * 2^-lo` as an integer, for `v` a multiple of `2^lo` with
/// `|v| < 2^(lo + 63)`. Exact: the shift drops only zero bits.
#[inline(always)]
pub(crate) fn to_integer_i64(v: f64, lo: i32) -> i64 {
    let (m, e) = split(v);
    let s = e - lo;
    if m == 0 {
        0
    } else if s >= 0 {
        m << s
    } else {
        m >> -s
    }
}

/// `v * 2^k` for `|k| <= 2046`: exact unless the result falls below
/// `2^-1022`; there the two rounded steps leave an absolute error of at most
/// `2^-1074` (one half-ulp of the smallest subnormal per step).
#[inline(always)]
pub(crate) fn scale_pow2(v: f64, k: i32) -> f64 {
    let half = k / 2;
    v * pow2(half) * pow2(k - half)
}

/// `2^k` for `-1022 <= k <= 1023`, built from its bits.
#[inline(always)]
pub(crate) const fn pow2(k: i32) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}
