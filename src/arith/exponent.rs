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
    #[inline(always)]
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

/// Every value as an integer at one scale, when they allow it: `(ints,
/// s)` with `values[i] = ints[i] * 2^-s` exactly and `|ints[i]| < 2^bits`,
/// for the power of two `2^s` that puts `m`, their largest magnitude, in
/// `[2^(bits - 1), 2^bits)` (or below, for a subnormal `m`). `None` when a
/// value is not an integer at that scale (the values span more than `bits`
/// bits) or is not finite. `1 <= bits <= 62`.
///
/// Exact: with `E` the exponent field of `m`, `s = bits - 1 + 1023 - E`
/// lies in `[bits - 1024, bits + 1022]`, and `m * 2^s < 2^bits` (`m <
/// 2^(E - 1022)` for `E >= 1`, `m < 2^-1022` for `E = 0`). Each value is
/// scaled by `2^(s/2)`, then by `2^(s - s/2)`, both normal powers of two of
/// the sign of `s`. Scaling up never rounds (nor overflows, below
/// `2^bits`). Scaling down rounds only a result below `2^-1022`, and a
/// value whose first step rounds ends below 1: it passes the tests below
/// only as a zero, and a non-zero value that became zero fails the last
/// one. A scaled value below `2^62` converts to `i64` exactly when it is
/// an integer, and the round trip compares equal exactly then; a NaN, an
/// infinity or a value of `2^bits` or more fails the magnitude test. Those
/// tests are what the result rests on: were `m` not the largest magnitude,
/// the answer would still be exact, or `None`.
#[inline(always)]
pub(crate) fn unit_integers<const N: usize>(
    values: &[f64; N],
    m: f64,
    bits: i32,
) -> Option<([i64; N], i32)> {
    let limit = pow2(bits);
    let field = ((m.to_bits() >> 52) & 0x7ff) as i32;
    let s = bits - 1 + 1023 - field;
    let (up, then) = (pow2(s / 2), pow2(s - s / 2));
    let mut ints = [0i64; N];
    let mut exact = true;
    for (n, &v) in ints.iter_mut().zip(values) {
        let y = v * up * then;
        *n = y as i64;
        exact &= (y.abs() < limit) & (*n as f64 == y) & ((y == 0.0) == (v == 0.0));
    }
    exact.then_some((ints, s))
}

/// The exponent of the finest bit set in any of `values`: each is an
/// integer multiple of `2^lowest_bit(values)`. `i32::MAX` when all are
/// zero; for a non-finite value, some exponent (the caller has checked).
#[inline(always)]
pub(crate) fn lowest_bit(values: &[f64]) -> i32 {
    values.iter().fold(i32::MAX, |lo, &v| {
        let bits = v.to_bits();
        let field = ((bits >> 52) & 0x7ff) as i32;
        // The significand with its hidden bit at 52: its trailing zeros
        // are those of the fraction for a normal value, at most 52.
        let tz = (bits | 1 << 52).trailing_zeros() as i32;
        let bit = field.max(1) - 1075 + tz;
        if v == 0.0 { lo } else { lo.min(bit) }
    })
}

/// What the small-integer stage makes of the coordinates of a determinant
/// that is a degree-`degree` integer polynomial in their differences, once
/// a filter declined it with the error bound `bound`.
pub(crate) enum SmallInteger<const N: usize> {
    /// The determinant is zero: every coordinate is, or the filter's bound
    /// lies below the spacing of the lattice that holds it (the lattice
    /// stage, see [`small_integer`]).
    Zero,
    /// The coordinates as integers at one scale, below `2^bits`.
    Integers([i64; N]),
    /// The coordinates span more than `bits` bits.
    Wide,
}

/// The small-integer stage's entry for `coords` (their largest magnitude
/// `max`), with the lattice stage: [`unit_integers`] gives the integers,
/// their lowest set bit the grain `2^lo` of every coordinate, so the
/// determinant, a degree-`degree` integer polynomial in differences of
/// multiples of `2^lo`, is a multiple of `2^(degree lo)`. The filter
/// declined, so `|det_computed| <= bound`, and where its bound held (the
/// caller passes NaN where it did not, and it is infinite where something
/// overflowed) `|det - det_computed| <= bound`, up to the rounding of the
/// bound itself: a bound below the lattice step proves the zero
/// ([`below_lattice`]).
#[inline(always)]
pub(crate) fn small_integer<const N: usize>(
    coords: &[f64; N],
    max: f64,
    bits: i32,
    degree: i32,
    bound: f64,
) -> SmallInteger<N> {
    let Some((ints, s)) = unit_integers(coords, max, bits) else {
        return SmallInteger::Wide;
    };
    let any = ints.iter().fold(0u64, |acc, &n| acc | n as u64);
    let lo = any.trailing_zeros() as i32 - s;
    if any == 0 || below_lattice(bound, degree * lo) {
        SmallInteger::Zero
    } else {
        SmallInteger::Integers(ints)
    }
}

/// Whether `bound` proves a value zero on its lattice: true when `x` is an
/// integer multiple of `2^lattice`, `x_c` an approximation of it with
/// `|x_c| <= bound` and `|x - x_c| <= 2 * bound`, and `bound <
/// 2^(lattice - 3)`. Then `|x| <= 3 * bound < 2^lattice`, so `x = 0`.
/// (A filter that declined has `|x_c| <= bound`; twice its bound covers
/// the rounding of the bound's own evaluation many times over.) `false`
/// for a NaN bound.
#[inline(always)]
pub(crate) fn below_lattice(bound: f64, lattice: i32) -> bool {
    let e = lattice.saturating_sub(3).min(1023);
    e >= -1022 && bound < pow2(e)
}

/// `v * 2^k` for `-2044 <= k <= 2046` (both factors `2^(k/2)` and
/// `2^(k - k/2)` normal): exact unless the result falls below
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{SplitMix64, step_ulps};

    /// A value from every part of the range: zeros, subnormals, short and
    /// full significands at any exponent, powers of two near `2^bits`, and
    /// now and then a non-finite one.
    fn value(rng: &mut SplitMix64, bits: i32) -> f64 {
        let e = (rng.next_u64() % 2000) as i32 - 1000;
        let v = match rng.next_u64() % 9 {
            0 => 0.0,
            1 => f64::from_bits(rng.next_u64() >> 12),
            2 => (rng.next_u64() % 1024) as f64 * pow2(e.clamp(-1000, 1000)),
            3 => step_ulps(pow2(bits), -((rng.next_u64() % 3) as i64)),
            4 => [f64::NAN, f64::INFINITY][(rng.next_u64() % 2) as usize],
            5 => (rng.next_u64() % 1024) as f64,
            _ => rng.next_f64() * pow2(e.clamp(-1000, 1000)),
        };
        if rng.next_u64() & 1 == 0 { v } else { -v }
    }

    /// `unit_integers` against the bit counts of `Grain`: it answers
    /// exactly when the values fit `bits` bits at the scale of the
    /// largest, and then exactly.
    #[test]
    fn unit_integers_is_exact_or_declines() {
        let mut rng = SplitMix64::new(3);
        let mut answered = 0;
        for i in 0..200_000 {
            let bits = [60, 61, 62][i % 3];
            let n = (rng.next_u64() % 4) as usize;
            let mut v = [0.0; 4];
            for x in v.iter_mut().take(n + 1) {
                *x = value(&mut rng, bits);
            }
            // Sometimes values close together, so that they fit.
            if i % 2 == 0 {
                let base = v[0];
                for x in v.iter_mut().skip(1) {
                    *x = step_ulps(base, (rng.next_u64() % 64) as i64 - 32);
                }
            }
            let m = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let got = unit_integers(&v, m, bits);
            let finite = v.iter().all(|x| x.is_finite());
            let g = Grain::of(&v.map(|x| if x.is_finite() { x } else { 0.0 }));
            let expect = finite && g.span() <= bits;
            assert_eq!(got.is_some(), expect, "{v:?} {bits}");
            if let Some((ints, s)) = got {
                answered += 1;
                for (&x, &n) in v.iter().zip(&ints) {
                    assert!(n.unsigned_abs() < 1 << bits, "{v:?}");
                    assert_eq!(n, to_integer_i64(x, -s), "{v:?}");
                }
            }
        }
        assert!(answered > 50_000, "{answered}");
    }

    #[test]
    fn below_lattice_bounds() {
        assert!(below_lattice(0.0, -1022 + 3));
        assert!(!below_lattice(0.0, -1022 + 2));
        assert!(below_lattice(0.1, 1));
        assert!(!below_lattice(0.25, 1));
        assert!(!below_lattice(f64::NAN, 10));
        assert!(!below_lattice(f64::INFINITY, 5000));
        // Far above the range of `f64` it compares with `2^1023`: safe.
        assert!(below_lattice(pow2(1022), 5000));
        assert!(!below_lattice(f64::MAX, 5000));
    }
}
