//! Exact signs of sums of products of coordinate differences that span
//! thousands of bits but have few significant ones: sparse exact terms
//! with explicit exponents, summed cluster by cluster (see
//! [`sign_of_sum`]). The determinants built on it are in
//! `predicates::sparse`.

use super::exponent::split;
use crate::sign::Sign;

/// Most terms a sum may have: orient3d's six products of three differences
/// of up to two terms each, `6 * 2^3`. (orient2d has at most `2 * 2^2`.)
pub(crate) const MAX_TERMS: usize = 48;

/// Limbs of each of the two cluster accumulators (positive and negative
/// parts): clusters up to `64 * ACC_LIMBS - GUARD_BITS` bits wide.
const ACC_LIMBS: usize = 16;

/// `2^GUARD_BITS >= MAX_TERMS`: a sum of at most `MAX_TERMS` terms, each
/// below `2^t`, is below `2^(t + GUARD_BITS)`.
const GUARD_BITS: i32 = 6;

/// A coordinate difference `p - q`: `n` exact terms `m * 2^e`, `|m| < 2^63`.
#[derive(Clone, Copy)]
pub(crate) struct Diff {
    t: [(i64, i32); 2],
    n: usize,
}

/// `p - q` exactly, for finite `p` and `q`: one term when both exponents are
/// within 9 of each other (shifted onto the smaller one, `|m| < 2^62 +
/// 2^53 < 2^63`), otherwise the two terms `p` and `-q` (zeros dropped).
#[inline]
pub(crate) fn diff(p: f64, q: f64) -> Diff {
    let (mp, ep) = split(p);
    let (mq, eq) = split(q);
    let mut d = Diff {
        t: [(0, 0); 2],
        n: 0,
    };
    if mp != 0 && mq != 0 && (ep - eq).abs() <= 9 {
        let e = ep.min(eq);
        let m = (mp << (ep - e)) - (mq << (eq - e));
        if m != 0 {
            d.t[0] = (m, e);
            d.n = 1;
        }
        return d;
    }
    for (m, e) in [(mp, ep), (-mq, eq)] {
        if m != 0 {
            d.t[d.n] = (m, e);
            d.n += 1;
        }
    }
    d
}

/// An exact term `(-1)^neg * mag * 2^e`, `mag` little-endian, non-zero,
/// below `2^(top - e)`.
#[derive(Clone, Copy)]
pub(crate) struct Term {
    mag: [u64; 3],
    neg: bool,
    e: i32,
    top: i32,
}

/// The terms of a signed sum of products of differences: room for `N <=
/// MAX_TERMS` of them.
pub(crate) struct Terms<const N: usize> {
    t: [Term; N],
    n: usize,
}

impl<const N: usize> Terms<N> {
    #[inline(always)]
    pub(crate) fn new() -> Self {
        Terms {
            t: [Term {
                mag: [0; 3],
                neg: false,
                e: 0,
                top: 0,
            }; N],
            n: 0,
        }
    }

    /// Adds `sign * f[0] * ... * f[K-1]`, expanded into its terms.
    /// The caller keeps the total within `N`.
    #[inline]
    pub(crate) fn push_product<const K: usize>(&mut self, negate: bool, f: [Diff; K]) {
        if f.iter().any(|d| d.n == 0) {
            return;
        }
        // Every choice of one term per factor: bit `i` of `pick` picks
        // factor `i`'s term (only 0 when it has one term).
        for pick in 0..1usize << K {
            if (0..K).any(|i| (pick >> i) & 1 >= f[i].n) {
                continue;
            }
            let mut mag = [1u64, 0, 0];
            let mut neg = negate;
            let mut e = 0;
            for (i, d) in f.iter().enumerate() {
                let (m, x) = d.t[(pick >> i) & 1];
                mag = mul_small(mag, m.unsigned_abs());
                neg ^= m < 0;
                e += x;
            }
            let bits = if mag[2] != 0 {
                192 - mag[2].leading_zeros()
            } else if mag[1] != 0 {
                128 - mag[1].leading_zeros()
            } else {
                64 - mag[0].leading_zeros()
            };
            self.t[self.n] = Term {
                mag,
                neg,
                e,
                top: e + bits as i32,
            };
            self.n += 1;
        }
    }
}

/// `a * x` for `a < 2^128` (two factors below `2^63` so far) and
/// `x < 2^63`: below `2^191`, three limbs.
#[inline(always)]
fn mul_small(a: [u64; 3], x: u64) -> [u64; 3] {
    let lo = a[0] as u128 * x as u128;
    let mid = a[1] as u128 * x as u128 + (lo >> 64);
    let hi = a[2] as u128 * x as u128 + (mid >> 64);
    [lo as u64, mid as u64, hi as u64]
}

/// Adds `mag * 2^shift` to `acc`, for a value that fits in `acc`.
#[inline(always)]
fn add_shifted(acc: &mut [u64; ACC_LIMBS], mag: [u64; 3], shift: u32) {
    let (word, bit) = ((shift / 64) as usize, shift % 64);
    let spread = if bit == 0 {
        [mag[0], mag[1], mag[2], 0]
    } else {
        [
            mag[0] << bit,
            mag[1] << bit | mag[0] >> (64 - bit),
            mag[2] << bit | mag[1] >> (64 - bit),
            mag[2] >> (64 - bit),
        ]
    };
    let mut carry = false;
    let mut i = word;
    for s in spread {
        if i >= ACC_LIMBS {
            return;
        }
        let (v1, c1) = acc[i].overflowing_add(s);
        let (v2, c2) = v1.overflowing_add(carry as u64);
        acc[i] = v2;
        carry = c1 | c2;
        i += 1;
    }
    while carry && i < ACC_LIMBS {
        let (v, c) = acc[i].overflowing_add(1);
        acc[i] = v;
        carry = c;
        i += 1;
    }
}

/// The exact sign of the sum of `terms`, or `None` when a cluster is wider
/// than the accumulators.
///
/// Terms sorted by `top` (descending) are gathered into a cluster from the
/// first while the next term's `top + GUARD_BITS` exceeds the cluster's
/// lowest exponent `lo`. When a term `j` stops the cluster, every later term
/// has `top <= top_j`, so those at most `MAX_TERMS` terms sum to less than
/// `2^(top_j + GUARD_BITS) <= 2^lo` in magnitude; the cluster's sum is a
/// multiple of `2^lo`, so when it is not zero it is at least `2^lo` and its
/// sign is the sign of the whole sum. When it is zero, the rest of the sum
/// is the whole sum, and the next cluster is examined the same way.
pub(crate) fn sign_of_sum<const N: usize>(terms: &mut Terms<N>) -> Option<Sign> {
    // Sort keys: `top` (biased to be non-negative; it lies in (-3300,
    // 3300)) above the term's index, so sorting the keys sorts the terms.
    let n = terms.n;
    let mut keys = [0u32; N];
    for (i, (k, x)) in keys.iter_mut().zip(&terms.t[..n]).enumerate() {
        *k = ((x.top + 4096) as u32) << 8 | i as u32;
    }
    keys[..n].sort_unstable_by(|a, b| b.cmp(a));
    let t = |i: usize| &terms.t[(keys[i] & 255) as usize];
    let mut i = 0;
    while i < n {
        let (hi, mut lo) = (t(i).top, t(i).e);
        let mut j = i + 1;
        while j < n && t(j).top + GUARD_BITS > lo {
            lo = lo.min(t(j).e);
            j += 1;
        }
        // The cluster's parts are below 2^(hi - lo + GUARD_BITS) in units of
        // 2^lo; the accumulators hold 64 * ACC_LIMBS bits.
        if hi - lo + GUARD_BITS > 64 * ACC_LIMBS as i32 {
            return None;
        }
        let mut pos = [0u64; ACC_LIMBS];
        let mut neg = [0u64; ACC_LIMBS];
        for x in (i..j).map(t) {
            let acc = if x.neg { &mut neg } else { &mut pos };
            add_shifted(acc, x.mag, (x.e - lo) as u32);
        }
        // Compare the magnitudes from the top limb down.
        for k in (0..ACC_LIMBS).rev() {
            if pos[k] != neg[k] {
                return Some(if pos[k] > neg[k] {
                    Sign::Positive
                } else {
                    Sign::Negative
                });
            }
        }
        i = j;
    }
    Some(Sign::Zero)
}
