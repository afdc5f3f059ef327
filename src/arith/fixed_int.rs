//! Fixed-width two's-complement integers on the stack, for the exact stages.
//!
//! `FixedInt<N>` holds `N` little-endian 64-bit limbs. Addition and subtraction
//! wrap modulo `2^(64N)`; multiplication skips the zero high limbs of its
//! operands, so a wide type costs only what the actual values need. Callers
//! pick `N` from a proven bound on the magnitudes (stated where each
//! predicate uses it), so wrapping never happens.

use super::exponent::split;
use crate::arith::scaled_float::ScaledFloat;
use crate::sign::Sign;

/// Magnitude bits of an input coordinate, or of a difference of two, as an
/// integer at the finest grain of its axis: finite `f64` values lie below
/// `2^1024` and are multiples of `2^-1074`, so a coordinate is below
/// `2^2098` in those units and a difference below `2^2099`; `2100` keeps
/// one bit to spare (a doubled input, as the quadric's, fits too).
pub(crate) const COORD_BITS: u32 = 2100;

/// Bits for the number of terms summed in a value: every determinant and
/// polynomial of the crate sums fewer than `2^10` products.
const TERM_BITS: u32 = 10;

/// Limbs of a [`FixedInt`] holding every signed value below `2^bits` in
/// magnitude: the bits and a sign bit in whole limbs, and one limb to
/// spare.
pub(crate) const fn limbs_for(bits: u32) -> usize {
    ((bits + 1).div_ceil(64) + 1) as usize
}

/// Limbs for a sum of products of `degree` coordinates or differences.
pub(crate) const fn limbs_of_degree(degree: u32) -> usize {
    limbs_for(degree * COORD_BITS + TERM_BITS)
}

/// [`limbs_of_degree`] for the degrees the exact stages use.
pub(crate) const DEG1: usize = limbs_of_degree(1);
/// Degree 2: products of two differences, squared lengths, 2x2 minors.
pub(crate) const DEG2: usize = limbs_of_degree(2);
/// Degree 3: orient3d's determinant.
pub(crate) const DEG3: usize = limbs_of_degree(3);
/// Degree 4: in-circle's lifted determinant, squared degree-2 values.
pub(crate) const DEG4: usize = limbs_of_degree(4);
/// Degree 5: in-sphere's lifted determinant.
pub(crate) const DEG5: usize = limbs_of_degree(5);

// The widths the exact stages were written and fuzzed with.
const _: () = assert!(DEG1 == 34 && DEG2 == 67 && DEG3 == 100 && DEG4 == 133 && DEG5 == 166);

/// A signed integer of `N` 64-bit limbs (two's complement, little-endian).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FixedInt<const N: usize> {
    limbs: [u64; N],
}

impl<const N: usize> FixedInt<N> {
    /// Zero.
    pub(crate) const ZERO: Self = FixedInt { limbs: [0; N] };

    /// `m * 2^shift`, for `|m| < 2^63` and `shift + 64 <= 64 * N - 1`.
    #[inline]
    pub(crate) fn from_i64_shifted(m: i64, shift: u32) -> Self {
        let mut r = Self::ZERO;
        let mag = m.unsigned_abs() as u128;
        let (word, bit) = ((shift / 64) as usize, shift % 64);
        let wide = mag << bit;
        if word < N {
            r.limbs[word] = wide as u64;
        }
        if word + 1 < N {
            r.limbs[word + 1] = (wide >> 64) as u64;
        }
        if m < 0 { r.neg() } else { r }
    }

    /// The exact value of finite `v`, which must be a multiple of `2^lo`,
    /// divided by `2^lo`; `N` must hold it (at most `2098 + 1` bits).
    #[inline]
    pub(crate) fn from_f64(v: f64, lo: i32) -> Self {
        let (m, e) = split(v);
        if m == 0 {
            return Self::ZERO;
        }
        let tz = m.trailing_zeros();
        Self::from_i64_shifted(m >> tz, (e + tz as i32 - lo) as u32)
    }

    /// The integer whose two's-complement limbs (least significant first)
    /// are `limbs`.
    #[inline]
    pub(crate) fn from_limbs(limbs: [u64; N]) -> Self {
        FixedInt { limbs }
    }

    /// The value of an `i64`.
    #[inline]
    pub(crate) fn from_i64(m: i64) -> Self {
        let mut r = Self {
            limbs: [if m < 0 { u64::MAX } else { 0 }; N],
        };
        r.limbs[0] = m as u64;
        r
    }

    /// The same value in `M` limbs, sign-extended; for `M < N` the value
    /// must fit (the high limbs dropped are copies of the sign).
    #[inline]
    pub(crate) fn widen<const M: usize>(&self) -> FixedInt<M> {
        let fill = if self.is_negative() { u64::MAX } else { 0 };
        let mut r = FixedInt { limbs: [fill; M] };
        let n = N.min(M);
        r.limbs[..n].copy_from_slice(&self.limbs[..n]);
        r
    }

    /// `true` when negative.
    #[inline(always)]
    pub(crate) fn is_negative(&self) -> bool {
        (self.limbs[N - 1] as i64) < 0
    }

    /// The sign of the value.
    #[inline]
    pub(crate) fn sign(&self) -> Sign {
        if self.is_negative() {
            Sign::Negative
        } else if self.limbs.iter().any(|&l| l != 0) {
            Sign::Positive
        } else {
            Sign::Zero
        }
    }

    /// The value rounded to 53 significant bits (to nearest, ties to even),
    /// as `(m, e)` with `value ~ m * 2^e`: `m` is an `f64` integer below
    /// `2^64` in magnitude (`0.0` for zero), so that values far beyond the
    /// range of `f64` keep their exponent.
    #[inline]
    pub(crate) fn rounded_parts(&self) -> (f64, i32) {
        let (limbs, len, neg) = self.magnitude();
        if len == 0 {
            return (0.0, 0);
        }
        // The top 64 bits, with the bits below them folded into a sticky
        // last bit: that bit lies 11 places below where the conversion
        // rounds, so it decides only ties and their side, as the full value
        // would.
        let top = len - 1;
        let shift = limbs[top].leading_zeros();
        let (word, sticky_from, e) = if top == 0 {
            (limbs[0], 0, 0)
        } else {
            let below = limbs[top - 1];
            let word = if shift == 0 {
                limbs[top]
            } else {
                limbs[top] << shift | below >> (64 - shift)
            };
            let lost = if shift == 0 {
                below != 0
            } else {
                below << shift != 0
            };
            let rest = limbs[..top - 1].iter().any(|&l| l != 0);
            (word, (lost || rest) as u64, 64 * top as i32 - shift as i32)
        };
        let m = (word | sticky_from) as f64;
        (if neg { -m } else { m }, e)
    }

    /// The value times `2^lo`, correctly rounded to 53 significant bits,
    /// with an unbounded exponent.
    #[inline]
    pub(crate) fn as_extended(&self, lo: i32) -> ScaledFloat {
        let (m, e) = self.rounded_parts();
        ScaledFloat::new(m, e.saturating_add(lo))
    }

    /// `-self` (wrapping).
    #[inline]
    pub(crate) fn neg(&self) -> Self {
        let mut r = Self::ZERO;
        let mut carry = 1u64;
        for i in 0..N {
            let (v, c) = (!self.limbs[i]).overflowing_add(carry);
            r.limbs[i] = v;
            carry = c as u64;
        }
        r
    }

    /// `self + other` (wrapping).
    #[inline]
    pub(crate) fn add(&self, other: &Self) -> Self {
        let mut r = Self::ZERO;
        let mut carry = false;
        for i in 0..N {
            let (v1, c1) = self.limbs[i].overflowing_add(other.limbs[i]);
            let (v2, c2) = v1.overflowing_add(carry as u64);
            r.limbs[i] = v2;
            carry = c1 | c2;
        }
        r
    }

    /// `self - other` (wrapping).
    #[inline]
    pub(crate) fn sub(&self, other: &Self) -> Self {
        let mut r = Self::ZERO;
        let mut borrow = false;
        for i in 0..N {
            let (v1, b1) = self.limbs[i].overflowing_sub(other.limbs[i]);
            let (v2, b2) = v1.overflowing_sub(borrow as u64);
            r.limbs[i] = v2;
            borrow = b1 | b2;
        }
        r
    }

    /// The magnitude's limbs, how many of them are non-zero, and the sign.
    #[inline]
    fn magnitude(&self) -> ([u64; N], usize, bool) {
        let neg = self.is_negative();
        let limbs = if neg { self.neg().limbs } else { self.limbs };
        let mut len = N;
        while len > 0 && limbs[len - 1] == 0 {
            len -= 1;
        }
        (limbs, len, neg)
    }

    /// `a * b` into `N` limbs, for `|a * b| < 2^(64N - 1)`. Schoolbook
    /// multiplication over the non-zero limbs only.
    #[inline]
    pub(crate) fn mul<const A: usize, const B: usize>(a: &FixedInt<A>, b: &FixedInt<B>) -> Self {
        let (ma, la, na) = a.magnitude();
        let (mb, lb, nb) = b.magnitude();
        let mut r = Self::ZERO;
        if A > 4 && B > 4 {
            r.mul_sparse_add(&ma[..la], &mb[..lb]);
        } else {
            r.mul_schoolbook_add(&ma[..la], &mb[..lb]);
        }
        if na != nb { r.neg() } else { r }
    }

    /// `self += x * y` for magnitudes `x`, `y` (little-endian limbs), by
    /// the schoolbook loop; `self` must start at zero.
    #[inline]
    fn mul_schoolbook_add(&mut self, x: &[u64], y: &[u64]) {
        for (i, &x) in x.iter().enumerate().take(N) {
            let mut carry = 0u128;
            let top = y.len().min(N - i);
            for (j, &y) in y.iter().enumerate().take(top) {
                let t = x as u128 * y as u128 + self.limbs[i + j] as u128 + carry;
                self.limbs[i + j] = t as u64;
                carry = t >> 64;
            }
            if i + top < N {
                self.limbs[i + top] = carry as u64;
            }
        }
    }

    /// `self += x * y` like `mul_schoolbook_add`, multiplying only the
    /// non-zero limb pairs. FixedInt operands (the big-integer stages) are
    /// mostly sparse: a coordinate difference is one or two 53-bit pieces
    /// at bit positions far apart. Each 128-bit limb product is added in
    /// place and carried as far as the carry goes: the same sum of limb
    /// products as the schoolbook loop.
    #[inline]
    fn mul_sparse_add(&mut self, x: &[u64], y: &[u64]) {
        let mut nz = [(0usize, 0u64); N];
        let mut count = 0;
        for (j, &v) in y.iter().enumerate().take(N) {
            if v != 0 {
                nz[count] = (j, v);
                count += 1;
            }
        }
        for (i, &x) in x.iter().enumerate().take(N) {
            if x == 0 {
                continue;
            }
            for &(j, y) in &nz[..count] {
                let k = i + j;
                if k >= N {
                    break;
                }
                let t = x as u128 * y as u128;
                let (v, c0) = self.limbs[k].overflowing_add(t as u64);
                self.limbs[k] = v;
                let mut carry = (t >> 64) + c0 as u128;
                let mut k = k + 1;
                while carry != 0 && k < N {
                    let s = self.limbs[k] as u128 + carry;
                    self.limbs[k] = s as u64;
                    carry = s >> 64;
                    k += 1;
                }
            }
        }
    }
}

/// `x x y`, exactly, for `N2` limbs that hold a sum of two products of
/// `N1`-limb values.
pub(crate) fn cross3<const N1: usize, const N2: usize>(
    x: &[FixedInt<N1>; 3],
    y: &[FixedInt<N1>; 3],
) -> [FixedInt<N2>; 3] {
    core::array::from_fn(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        FixedInt::<N2>::mul(&x[i], &y[j]).sub(&FixedInt::mul(&x[j], &y[i]))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn to_i128(w: &FixedInt<2>) -> i128 {
        (w.limbs[0] as u128 | (w.limbs[1] as u128) << 64) as i128
    }

    #[test]
    fn arithmetic_matches_i128() {
        let vals = [
            0i64,
            1,
            -1,
            7,
            -123456789,
            i64::MAX / 3,
            -(1 << 62),
            (1 << 62) - 1,
        ];
        for &x in &vals {
            for &y in &vals {
                let (a, b) = (FixedInt::<2>::from_i64(x), FixedInt::<2>::from_i64(y));
                assert_eq!(to_i128(&a.add(&b)), x as i128 + y as i128);
                assert_eq!(to_i128(&a.sub(&b)), x as i128 - y as i128);
                assert_eq!(to_i128(&FixedInt::<2>::mul(&a, &b)), x as i128 * y as i128);
                assert_eq!(
                    FixedInt::<2>::mul(&a, &b).sign(),
                    Sign::from_i8((x as i128 * y as i128).signum() as i8)
                );
            }
        }
    }

    #[test]
    fn sparse_products_match_schoolbook() {
        // Random magnitudes, dense and sparse (most limbs zero), of every
        // length: both loops give the same limbs.
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for round in 0..2000 {
            let mut x = [0u64; 20];
            let mut y = [0u64; 20];
            let (lx, ly) = ((next() % 21) as usize, (next() % 21) as usize);
            for v in x[..lx].iter_mut().chain(y[..ly].iter_mut()) {
                let r = next();
                *v = match round % 3 {
                    0 => r,
                    1 if r % 4 == 0 => u64::MAX,
                    _ if r % 5 == 0 => r >> (r % 64),
                    _ => 0,
                };
            }
            let mut dense = FixedInt::<30>::ZERO;
            let mut sparse = FixedInt::<30>::ZERO;
            dense.mul_schoolbook_add(&x[..lx], &y[..ly]);
            sparse.mul_sparse_add(&x[..lx], &y[..ly]);
            assert_eq!(dense.limbs, sparse.limbs, "{x:?} {y:?}");
        }
    }

    #[test]
    fn conversion_rounds_correctly() {
        let w = FixedInt::<4>::from_i64_shifted(3, 200);
        assert_eq!(w.as_extended(-200).to_f64(), 3.0);
        // 2^53 + 1 rounds to even (2^53); 2^53 + 1 + 2^-100 rounds up.
        let tie = FixedInt::<4>::from_i64_shifted((1 << 53) + 1, 100);
        assert_eq!(tie.as_extended(-100).to_f64(), 2f64.powi(53));
        let above = tie.add(&FixedInt::<4>::from_i64(1));
        assert_eq!(above.as_extended(-100).to_f64(), 2f64.powi(53) + 2.0);
        assert_eq!(
            above.neg().as_extended(-100).to_f64(),
            -(2f64.powi(53) + 2.0)
        );
        assert!(FixedInt::<4>::ZERO.as_extended(5).is_zero());
    }

    #[test]
    fn shifted_and_wide_products() {
        let a = FixedInt::<4>::from_i64_shifted(-3, 130);
        let b = FixedInt::<4>::from_i64_shifted(5, 60);
        let p = FixedInt::<4>::mul(&a, &b);
        let expect = FixedInt::<4>::from_i64_shifted(-15, 190);
        assert_eq!(p.sub(&expect).sign(), Sign::Zero);
        assert_eq!(p.sign(), Sign::Negative);
    }
}
