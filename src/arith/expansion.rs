//! Shewchuk's floating-point expansions: a value held exactly as a sum of
//! `f64` components of increasing magnitude that do not overlap (Shewchuk
//! 1997, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
//! Geometric Predicates", *Discrete & Computational Geometry* 18,
//! sections 2.3 to 2.8), with the sums and scalings the adaptive stages of
//! the predicates need (`predicates::adaptive`).
//!
//! Every operation is exact as long as no product underflows or overflows
//! and no sum overflows: the callers run them on inputs scaled so that
//! every value they form is either zero or far inside the normal range.
//! Zero components are dropped (Shewchuk's "zero elimination"), so the
//! largest component, when there is one, carries the sign of the value.

use super::error_free::two_sum;
use crate::sign::Sign;

/// A value as a nonoverlapping expansion of at most `N` components, the
/// smallest first, none of them zero (an empty expansion is zero).
#[derive(Clone, Copy)]
pub(crate) struct Expansion<const N: usize> {
    c: [f64; N],
    len: usize,
}

impl<const N: usize> Expansion<N> {
    /// Zero.
    const ZERO: Self = Expansion {
        c: [0.0; N],
        len: 0,
    };

    #[inline(always)]
    fn push(&mut self, v: f64) {
        if v != 0.0 {
            self.c[self.len] = v;
            self.len += 1;
        }
    }

    /// The components, smallest first.
    #[inline(always)]
    fn components(&self) -> &[f64] {
        &self.c[..self.len]
    }

    /// The exact sign: the sign of the largest component (the others sum
    /// to less than it in magnitude).
    #[inline]
    pub(crate) fn sign(&self) -> Sign {
        match self.components().last() {
            Some(&top) => Sign::of_f64(top),
            None => Sign::Zero,
        }
    }

    /// The components summed in `f64`, smallest first: an estimate of the
    /// value, with the error the caller's bound allows for (Shewchuk's
    /// `estimate`).
    #[inline]
    pub(crate) fn estimate(&self) -> f64 {
        self.components().iter().sum()
    }

    /// `self + other` exactly, for `R >= N + M` (Shewchuk's
    /// FAST-EXPANSION-SUM with zero elimination, Theorem 13: the
    /// components of both are merged by magnitude and accumulated with
    /// TwoSum, each rounding error kept as a component; round to nearest
    /// even, as Rust's `f64` arithmetic is, keeps the result
    /// nonoverlapping).
    #[inline]
    pub(crate) fn sum<const M: usize, const R: usize>(&self, other: &Expansion<M>) -> Expansion<R> {
        const { assert!(R >= N + M) };
        let (e, f) = (self.components(), other.components());
        let mut h = Expansion::<R>::ZERO;
        let (mut i, mut j) = (0, 0);
        // The next component of the merge, the smaller in magnitude first.
        let mut next = || {
            let take_e = j == f.len() || (i < e.len() && e[i].abs() < f[j].abs());
            if take_e {
                i += 1;
                e[i - 1]
            } else {
                j += 1;
                f[j - 1]
            }
        };
        let total = e.len() + f.len();
        if total == 0 {
            return h;
        }
        let mut q = next();
        for _ in 1..total {
            let (s, err) = two_sum(q, next());
            h.push(err);
            q = s;
        }
        h.push(q);
        h
    }

    /// `-self`, exactly.
    #[inline]
    pub(crate) fn negated(&self) -> Self {
        let mut r = *self;
        r.c[..r.len].iter_mut().for_each(|v| *v = -*v);
        r
    }

    /// `self * b` exactly, for `R >= 2 N` (Shewchuk's SCALE-EXPANSION with
    /// zero elimination, Theorem 19: each component's exact product with
    /// `b` is added into the running sum, the roundings kept as
    /// components).
    #[inline]
    pub(crate) fn scaled<const R: usize>(&self, b: f64) -> Expansion<R> {
        const { assert!(R >= 2 * N) };
        let e = self.components();
        let mut h = Expansion::<R>::ZERO;
        let Some((&first, rest)) = e.split_first() else {
            return h;
        };
        let (mut q, err) = exact_product(first, b);
        h.push(err);
        for &x in rest {
            let (p, p_err) = exact_product(x, b);
            let (s, err) = two_sum(q, p_err);
            h.push(err);
            // |p| >= |s| here (Shewchuk's proof of Theorem 19), so Fast
            // TwoSum would do; TwoSum is exact in either order.
            let (s2, err2) = two_sum(p, s);
            h.push(err2);
            q = s2;
        }
        h.push(q);
        h
    }
}

impl Expansion<4> {
    /// `a b - c d` exactly: the two exact products as two-component
    /// expansions, summed.
    #[inline]
    pub(crate) fn product_difference(a: f64, b: f64, c: f64, d: f64) -> Self {
        let (p, p_err) = exact_product(a, b);
        let (q, q_err) = exact_product(c, d);
        let mut left = Expansion::<2>::ZERO;
        left.push(p_err);
        left.push(p);
        let mut right = Expansion::<2>::ZERO;
        right.push(-q_err);
        right.push(-q);
        left.sum(&right)
    }
}

/// `a b` as `(p, e)` with `p = fl(a b)` and `p + e = a b` exactly, when the
/// product neither overflows nor underflows. With the FMA compiled in, one
/// instruction (`error_free::two_prod`); without it, Dekker's product over
/// Veltkamp's splitting (Shewchuk 1997, Theorem 18 with SPLIT, Theorem 17),
/// which needs no library call.
#[inline(always)]
pub(crate) fn exact_product(a: f64, b: f64) -> (f64, f64) {
    #[cfg(target_feature = "fma")]
    {
        super::error_free::two_prod(a, b)
    }
    #[cfg(not(target_feature = "fma"))]
    {
        let p = a * b;
        let (ah, al) = veltkamp_split(a);
        let (bh, bl) = veltkamp_split(b);
        let err = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
        (p, err)
    }
}

/// `a` as `hi + lo`, each of at most 26 significant bits (Veltkamp's
/// splitting with `2^27 + 1`, Shewchuk 1997, Theorem 17), for `|a|` below
/// `2^996` (so that `a (2^27 + 1)` does not overflow).
#[cfg(not(target_feature = "fma"))]
#[inline(always)]
fn veltkamp_split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::SplitMix64;

    /// Sums and products of expansions against `i128` arithmetic on
    /// integer inputs small enough that every result fits.
    #[test]
    fn exact_on_integers() {
        let mut rng = SplitMix64::new(3);
        let mut int = || (rng.next_u64() >> 34) as i64 - (1 << 29);
        for _ in 0..20_000 {
            let [a, b, c, d, s] = [(); 5].map(|_| int());
            let m = Expansion::product_difference(a as f64, b as f64, c as f64, d as f64);
            let exact = a as i128 * b as i128 - c as i128 * d as i128;
            assert_eq!(m.sign(), Sign::from_i8(exact.signum() as i8));
            let scaled: Expansion<8> = m.scaled(s as f64);
            let exact_scaled = exact * s as i128;
            assert_eq!(scaled.sign(), Sign::from_i8(exact_scaled.signum() as i8));
            let back: Expansion<12> = scaled.sum(&m.negated());
            let exact_back = exact_scaled - exact;
            assert_eq!(back.sign(), Sign::from_i8(exact_back.signum() as i8));
            // The estimate is within a few ulps of the value (the test's
            // `2^-50` relative is eight of them).
            let err = (back.estimate() - exact_back as f64).abs();
            assert!(err <= (exact_back as f64).abs() * 2f64.powi(-50));
        }
    }
}
