//! Exact signs of sums of products of coordinate differences that span
//! thousands of bits but have few significant ones: sparse exact terms
//! with explicit exponents, summed from the largest down until the rest
//! cannot change the sign (see [`sign_of_sum`]). The determinants built on
//! it are in `predicates::sparse`.

#![allow(
    unsafe_code,
    reason = "reads back the terms written so far from uninitialized storage"
)]

use super::exponent::split;
use super::fixed_int::FixedInt;
use super::scaled_float::ScaledFloat;
use crate::sign::Sign;
use core::mem::MaybeUninit;

/// Most terms orient3d's sum has: six products of three differences of up
/// to two terms each, `6 * 2^3`. (orient2d has at most `2 * 2^2`.)
pub(crate) const MAX_TERMS: usize = 48;

/// Most terms any sum may have: sort keys keep a term's index in their low
/// [`INDEX_BITS`] bits.
const TERMS_LIMIT: usize = 1 << INDEX_BITS;
const INDEX_BITS: u32 = 10;

/// Most limbs a term's magnitude may have: products of up to five factors
/// below `2^63`.
const MAX_LIMBS: usize = 5;

/// Limbs of the running sum of [`sign_of_sum`], two's complement: `L + 1`
/// of them are used, `L + 2` by [`value_of_sum`].
const WINDOW: usize = MAX_LIMBS + 2;

/// Bits [`value_of_sum`] keeps its running sum above what the terms left
/// can add: it stops when they sum to less than `2^-VALUE_BITS` of it.
const VALUE_BITS: i32 = 60;

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

impl Diff {
    /// How many terms the difference has: 0 (it is zero), 1 or 2.
    #[inline(always)]
    pub(crate) fn len(&self) -> usize {
        self.n
    }
}

/// An exact term `(-1)^neg * (factors[0] * ... * factors[L-1]) * 2^e`,
/// its magnitude kept as its factors (each below `2^63`; `1` past the
/// product's own) until [`sign_of_sum`] needs it: most terms of a sum
/// never are multiplied out. `|term| < 2^top`, with `top - e <= 63 L`.
#[derive(Clone, Copy)]
pub(crate) struct Term<const L: usize> {
    factors: [u64; L],
    neg: bool,
    e: i32,
    top: i32,
}

/// The terms of a signed sum of products of at most `L` differences: room
/// for `N <= 1024` of them. The room is left uninitialized (the sums that
/// need hundreds of terms would spend more time clearing it than adding
/// them up); the first `n` entries have been written.
pub(crate) struct Terms<const N: usize, const L: usize> {
    t: [MaybeUninit<Term<L>>; N],
    n: usize,
    /// A product did not fit: the sum is incomplete.
    overflowed: bool,
}

impl<const N: usize, const L: usize> Terms<N, L> {
    #[inline(always)]
    pub(crate) fn new() -> Self {
        const { assert!(N <= TERMS_LIMIT && L <= MAX_LIMBS) };
        Terms {
            t: [const { MaybeUninit::uninit() }; N],
            n: 0,
            overflowed: false,
        }
    }

    /// Term `i`, for `i < self.n`.
    #[inline(always)]
    fn get(&self, i: usize) -> &Term<L> {
        assert!(i < self.n);
        // SAFETY: `push_product` writes entries in order and counts them in
        // `n`, so every entry below `n` is initialized.
        unsafe { self.t[i].assume_init_ref() }
    }

    /// Adds `sign * f[0] * ... * f[K-1]`, expanded into its terms, for `K
    /// <= L` (the product of `K` magnitudes below `2^63` fits `L` limbs).
    /// When they would exceed `N` terms, nothing is added and the sum is
    /// marked incomplete: [`sign_of_sum`] then declines.
    #[inline]
    pub(crate) fn push_product<const K: usize>(&mut self, negate: bool, f: &[Diff; K]) {
        const { assert!(K <= L) };
        // Which factors have two terms, and how many terms the product
        // has (none when a factor is zero).
        let (mut two, mut count) = (0usize, 1usize);
        for (i, d) in f.iter().enumerate() {
            two |= ((d.n == 2) as usize) << i;
            count *= d.n;
        }
        if count == 0 {
            return;
        }
        if self.n + count > N {
            self.overflowed = true;
            return;
        }
        // Every choice of one term per factor: bit `i` of `pick` picks
        // factor `i`'s second term, so `pick` runs over the subsets of the
        // factors that have two.
        let mut pick = 0usize;
        loop {
            let mut factors = [1u64; L];
            let mut neg = negate;
            let (mut e, mut bits) = (0, 0);
            for (i, d) in f.iter().enumerate() {
                let (m, x) = d.t[(pick >> i) & 1];
                factors[i] = m.unsigned_abs();
                neg ^= m < 0;
                e += x;
                bits += 64 - factors[i].leading_zeros() as i32;
            }
            self.t[self.n].write(Term {
                factors,
                neg,
                e,
                top: e + bits,
            });
            self.n += 1;
            if pick == two {
                break;
            }
            pick = pick.wrapping_sub(two) & two;
        }
    }
}

impl<const L: usize> Term<L> {
    /// The magnitude, multiplied out: below `2^(63 L)`.
    #[inline(always)]
    fn magnitude(&self) -> [u64; L] {
        let mut mag = [0u64; L];
        mag[0] = self.factors[0];
        for (k, &x) in self.factors.iter().enumerate().skip(1) {
            mul_small(&mut mag, k + 1, x);
        }
        mag
    }
}

/// `a *= x` for `x < 2^63`, where `a` is a product of `k - 1` factors below
/// `2^63` and so below `2^(63 (k - 1))`: the result is below `2^(63 k)`,
/// and its limbs above `ceil(63 k / 64)` stay zero. The caller keeps
/// `63 k <= 64 L`.
#[inline(always)]
fn mul_small<const L: usize>(a: &mut [u64; L], k: usize, x: u64) {
    let limbs = (63 * k).div_ceil(64).min(L);
    let mut carry = 0u128;
    for limb in a.iter_mut().take(limbs) {
        let t = *limb as u128 * x as u128 + carry;
        *limb = t as u64;
        carry = t >> 64;
    }
}

/// The exact sign of the sum of `terms`, or `None` when a product did not
/// fit `terms`.
///
/// Terms are taken from the largest bound `top` down (a max-heap of sort
/// keys), multiplied out, and added into a running sum `S` held exactly as
/// `WINDOW` limbs times `2^base`. After term `j`, the terms left are below
/// `2^top_{j+1}` each, and fewer than `N <= 2^guard` of them sum to less
/// than `2^(top_{j+1} + guard)`: when `|S| >= 2^(top_{j+1} + guard)` the
/// sign of `S` is the sign of the whole sum. Otherwise `S` stays below that
/// bound (up to the one bit `magnitude_bits` may underestimate);
/// re-anchoring it at the next term's `base = top - 64 L` (a left shift:
/// exact) and adding that term (whose exponent `e >= top - 63 L` lies
/// above `base`) keeps it below `2^(64 L + guard + 2)` in units of
/// `2^base`: inside `L + 1` limbs, two's complement (`guard <= 10`).
pub(crate) fn sign_of_sum<const N: usize, const L: usize>(terms: &mut Terms<N, L>) -> Option<Sign> {
    let (window, _) = leading_sum(terms, 0)?;
    let (bits, negative) = magnitude_bits(&window[..L + 1]);
    Some(match (bits, negative) {
        (0, _) => Sign::Zero,
        (_, true) => Sign::Negative,
        _ => Sign::Positive,
    })
}

/// The sum of `terms` within a relative `2^-52` (the terms left out sum
/// to less than `2^-60` of the rest, which is then rounded once to 53
/// bits), with its exact sign and an unbounded exponent; `None` when a
/// product did not fit `terms`.
///
/// As [`sign_of_sum`], but the running sum must exceed the bound on the
/// terms left by `VALUE_BITS` more bits before it stops; an undecided sum
/// is then below `2^(64 L + guard + VALUE_BITS + 2)` in units of `2^base`:
/// inside `L + 2` limbs.
pub(crate) fn value_of_sum<const N: usize, const L: usize>(
    terms: &mut Terms<N, L>,
) -> Option<ScaledFloat> {
    let (window, base) = leading_sum(terms, VALUE_BITS)?;
    Some(FixedInt::from_limbs(window).as_extended(base))
}

/// The running sum of [`sign_of_sum`] when it stops, with `extra` more
/// bits of margin over the terms left (`0` or `VALUE_BITS`): its limbs
/// (two's complement, sign-extended over the whole window) and the
/// exponent of its unit.
fn leading_sum<const N: usize, const L: usize>(
    terms: &mut Terms<N, L>,
    extra: i32,
) -> Option<([u64; WINDOW], i32)> {
    const { assert!(L <= MAX_LIMBS) };
    if terms.overflowed {
        return None;
    }
    let guard = (usize::BITS - (N - 1).leading_zeros()) as i32;
    // Heap keys: `top` (biased to be non-negative; it lies in (-5500,
    // 5500): at most five factors, each below `2^1087`, above `2^-1074`)
    // above the term's index, so the largest key is the largest term.
    let mut keys = [0u32; N];
    let mut len = terms.n;
    for (i, k) in keys.iter_mut().take(len).enumerate() {
        *k = ((terms.get(i).top + 8192) as u32) << INDEX_BITS | i as u32;
    }
    for i in (0..len / 2).rev() {
        sift_down(&mut keys[..len], i);
    }
    let term = |key: u32| terms.get((key & (TERMS_LIMIT as u32 - 1)) as usize);
    let mut window = [0u64; WINDOW];
    // `L + 1` limbs of it, `L + 2` with a margin: enough (see above).
    let used = L + 1 + usize::from(extra > 0);
    let sum = &mut window[..used];
    let mut base = 0;
    while len > 0 {
        let t = term(keys[0]);
        len -= 1;
        keys.swap(0, len);
        sift_down(&mut keys[..len], 0);
        let new_base = t.top - 64 * L as i32;
        shift_left(sum, (base - new_base) as u32);
        base = new_base;
        add_term(sum, &t.magnitude(), t.neg, (t.e - base) as u32);
        let (bits, negative) = magnitude_bits(sum);
        let decided = match len {
            0 => true,
            _ => bits > 0 && bits - 1 + base >= term(keys[0]).top + guard + extra,
        };
        if decided {
            let fill = if negative { u64::MAX } else { 0 };
            window[used..].iter_mut().for_each(|l| *l = fill);
            return Some((window, base));
        }
    }
    Some(([0; WINDOW], 0))
}

/// Restores the max-heap order of `keys` below position `i`.
#[inline]
fn sift_down(keys: &mut [u32], mut i: usize) {
    loop {
        let (l, r) = (2 * i + 1, 2 * i + 2);
        let mut big = i;
        if l < keys.len() && keys[l] > keys[big] {
            big = l;
        }
        if r < keys.len() && keys[r] > keys[big] {
            big = r;
        }
        if big == i {
            return;
        }
        keys.swap(i, big);
        i = big;
    }
}

/// `sum * 2^shift`, for a value that stays inside `sum` (the bits shifted
/// out are copies of the sign). A shift past its end leaves zero, which
/// the caller only asks of a zero sum.
#[inline(always)]
fn shift_left(sum: &mut [u64], shift: u32) {
    let (words, bit) = ((shift / 64) as usize, shift % 64);
    for i in (0..sum.len()).rev() {
        let lo = i.checked_sub(words).map_or(0, |k| sum[k]);
        let below = i.checked_sub(words + 1).map_or(0, |k| sum[k]);
        sum[i] = if bit == 0 {
            lo
        } else {
            lo << bit | below >> (64 - bit)
        };
    }
}

/// `sum += (-1)^neg * mag * 2^shift`, two's complement, for `mag *
/// 2^shift < 2^(64 L)` (`sum` has `L + 1` limbs).
#[inline(always)]
fn add_term<const L: usize>(sum: &mut [u64], mag: &[u64; L], neg: bool, shift: u32) {
    let mut wide = [0u64; WINDOW];
    let (words, bit) = ((shift / 64) as usize, shift % 64);
    for (j, &m) in mag.iter().enumerate() {
        let w = (m as u128) << bit;
        if let Some(slot) = wide.get_mut(j + words) {
            *slot |= w as u64;
        }
        if let Some(slot) = wide.get_mut(j + words + 1) {
            *slot |= (w >> 64) as u64;
        }
    }
    // Subtracting is adding the complement plus one.
    let (flip, mut carry) = if neg { (u64::MAX, true) } else { (0, false) };
    for (s, w) in sum.iter_mut().zip(wide) {
        let (v1, c1) = s.overflowing_add(w ^ flip);
        let (v2, c2) = v1.overflowing_add(carry as u64);
        *s = v2;
        carry = c1 | c2;
    }
}

/// A lower bound `b` on the bit length of `|sum|` (`|sum| >= 2^(b - 1)`;
/// `0` exactly when `sum` is zero), and whether `sum` is negative. For a
/// negative `sum`, `|sum| = !sum + 1` is at least `2^(len(!sum) - 1)` and
/// at least 1.
#[inline(always)]
fn magnitude_bits(sum: &[u64]) -> (i32, bool) {
    let negative = (sum[sum.len() - 1] as i64) < 0;
    let flip = if negative { u64::MAX } else { 0 };
    let bits = match sum.iter().rposition(|&m| m ^ flip != 0) {
        Some(k) => 64 * (k as i32 + 1) - (sum[k] ^ flip).leading_zeros() as i32,
        None => 0,
    };
    (if negative { bits.max(1) } else { bits }, negative)
}
