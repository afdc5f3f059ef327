//! Exact signs of determinants over coordinates that span thousands of bits
//! but have few significant ones: sparse exact terms with explicit exponents.
//!
//! A finite `f64` is `m * 2^e` with `|m| < 2^53`. The difference of two of
//! them is one such term when their exponents are close, and otherwise
//! exactly the two terms themselves (no rounding: the difference is never
//! formed). A product of `K <= 3` differences is a sum of at most `2^K`
//! exact products of terms, each a magnitude below `2^189` (three limbs)
//! times a power of two. A determinant is a signed sum of such products, so
//! its sign is the sign of a sum of at most [`MAX_TERMS`] exact terms whose
//! exponents may lie thousands of bits apart.
//!
//! That sign comes from the top *cluster* of terms: sort the terms by their
//! top bit, and gather terms from the top until the next term's top bit
//! lies so far below the lowest bit of the gathered ones that the rest
//! cannot reach it (see [`sign_of_sum`]). The cluster's exact sum, when not
//! zero, decides the sign; when zero, the next cluster does. A cluster is
//! summed in a fixed accumulator of [`ACC_LIMBS`] limbs; a wider one makes
//! the function decline (`None`) and the caller uses its dense integers.
//!
//! For the hard mixed-magnitude inputs (a configuration near `2^1000`
//! decided by offsets near `2^-1000`) this costs a few dozen small integer
//! products instead of products of dense 2,000-bit integers.

use super::grain::split;
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// Most terms a sum may have: orient3d's six products of three differences
/// of up to two terms each, `6 * 2^3`. (orient2d has at most `2 * 2^2`.)
const MAX_TERMS: usize = 48;

/// Limbs of each of the two cluster accumulators (positive and negative
/// parts): clusters up to `64 * ACC_LIMBS - GUARD_BITS` bits wide.
const ACC_LIMBS: usize = 16;

/// `2^GUARD_BITS >= MAX_TERMS`: a sum of at most `MAX_TERMS` terms, each
/// below `2^t`, is below `2^(t + GUARD_BITS)`.
const GUARD_BITS: i32 = 6;

/// A coordinate difference `p - q`: `n` exact terms `m * 2^e`, `|m| < 2^63`.
#[derive(Clone, Copy)]
struct Diff {
    t: [(i64, i32); 2],
    n: usize,
}

/// `p - q` exactly, for finite `p` and `q`: one term when both exponents are
/// within 9 of each other (shifted onto the smaller one, `|m| < 2^62 +
/// 2^53 < 2^63`), otherwise the two terms `p` and `-q` (zeros dropped).
#[inline]
fn diff(p: f64, q: f64) -> Diff {
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
struct Term {
    mag: [u64; 3],
    neg: bool,
    e: i32,
    top: i32,
}

/// The terms of a signed sum of products of differences: room for `N <=
/// MAX_TERMS` of them.
struct Terms<const N: usize> {
    t: [Term; N],
    n: usize,
}

impl<const N: usize> Terms<N> {
    #[inline(always)]
    fn new() -> Self {
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
    fn push_product<const K: usize>(&mut self, negate: bool, f: [Diff; K]) {
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
fn sign_of_sum<const N: usize>(terms: &mut Terms<N>) -> Option<Sign> {
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

/// The exact sign of `(b - a) x (c - a)` for finite input, or `None` when
/// the terms do not fit the accumulators.
pub(super) fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Option<Sign> {
    let (bx, by) = (diff(b.x, a.x), diff(b.y, a.y));
    let (cx, cy) = (diff(c.x, a.x), diff(c.y, a.y));
    let mut terms = Terms::<8>::new();
    terms.push_product(false, [bx, cy]);
    terms.push_product(true, [by, cx]);
    sign_of_sum(&mut terms)
}

/// The exact sign of `det[b - a, c - a, d - a]` for finite input, or `None`
/// when the terms do not fit the accumulators.
pub(super) fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Option<Sign> {
    let rel = |p: DVec3| [diff(p.x, a.x), diff(p.y, a.y), diff(p.z, a.z)];
    det3(rel(b), rel(c), rel(d))
}

/// The exact sign of `det[d, p - o, q - o]` for finite input (a ray's
/// direction `d` and two points seen from its origin `o`), or `None` when
/// the terms do not fit the accumulators.
pub(super) fn orient_dir(d: DVec3, o: DVec3, p: DVec3, q: DVec3) -> Option<Sign> {
    let rel = |p: DVec3| [diff(p.x, o.x), diff(p.y, o.y), diff(p.z, o.z)];
    // `d - 0` is the one exact term `d` (a zero difference has none).
    let dir = [diff(d.x, 0.0), diff(d.y, 0.0), diff(d.z, 0.0)];
    det3(dir, rel(p), rel(q))
}

/// The exact sign of `det[b, c, d]` for rows of exact differences.
fn det3(b: [Diff; 3], c: [Diff; 3], d: [Diff; 3]) -> Option<Sign> {
    let mut terms = Terms::<MAX_TERMS>::new();
    // Expanded along z: z_u * (x_v y_w - x_w y_v) over (u, v, w) cyclic.
    for (u, v, w) in [(b, c, d), (c, d, b), (d, b, c)] {
        terms.push_product(false, [u[2], v[0], w[1]]);
        terms.push_product(true, [u[2], w[0], v[1]]);
    }
    sign_of_sum(&mut terms)
}

#[cfg(test)]
mod tests {
    use super::super::grain::{Grain, pow2};
    use super::super::{orient2d as o2, orient3d as o3};
    use super::*;
    use crate::hard_inputs::{InputClass, SplitMix64, orient2d_case, orient3d_case};

    /// A coordinate built to cancel: a few shared anchors at scattered
    /// exponents, moved by a few ulps or by a tiny offset, or zero.
    fn coord(rng: &mut SplitMix64, anchors: &[f64; 4]) -> f64 {
        let pick = (rng.next_u64() % 4) as usize;
        let base = anchors[pick];
        match rng.next_u64() % 8 {
            0 => 0.0,
            1 => f64::from_bits(rng.next_u64() >> 12), // subnormal or tiny
            2 => base + base * f64::EPSILON * ((rng.next_u64() % 5) as f64 - 2.0),
            3 => -base,
            4 => base * pow2((rng.next_u64() % 200) as i32 - 100),
            5 => base + pow2(-1074 + (rng.next_u64() % 2000) as i32),
            _ => base,
        }
    }

    fn anchors(rng: &mut SplitMix64) -> [f64; 4] {
        core::array::from_fn(|_| {
            let e = (rng.next_u64() % 2040) as i32 - 1020;
            (rng.next_f64() + 0.5) * pow2(e)
        })
    }

    fn dense2(p: [DVec2; 3]) -> Sign {
        let gx = Grain::of(&[p[0].x, p[1].x, p[2].x]);
        let gy = Grain::of(&[p[0].y, p[1].y, p[2].y]);
        if gx.all_zero() || gy.all_zero() {
            return Sign::Zero;
        }
        o2::big_integer(p[0], p[1], p[2], gx.lo_min, gy.lo_min)
    }

    fn dense3(p: [DVec3; 4]) -> Sign {
        let axis = |k: usize| [p[0][k], p[1][k], p[2][k], p[3][k]];
        let g = [0, 1, 2].map(|k| Grain::of(&axis(k)));
        if g.iter().any(|g| g.all_zero()) {
            return Sign::Zero;
        }
        o3::integer::<34, 67, 100>(&p, g.map(|g| g.lo_min))
    }

    #[test]
    fn matches_dense_integers() {
        let mut rng = SplitMix64::new(2024);
        let (mut declined, mut zero) = (0, 0);
        for i in 0..60_000 {
            let (p2, p3) = if i % 3 == 0 {
                let class = InputClass::ALL[i % 6];
                (
                    orient2d_case(class, &mut rng),
                    orient3d_case(class, &mut rng),
                )
            } else {
                let an = anchors(&mut rng);
                let mut c = || coord(&mut rng, &an);
                (
                    [(); 3].map(|_| DVec2::new(c(), c())),
                    [(); 4].map(|_| DVec3::new(c(), c(), c())),
                )
            };
            match orient2d(p2[0], p2[1], p2[2]) {
                Some(s) => assert_eq!(s, dense2(p2), "{p2:?}"),
                None => declined += 1,
            }
            match orient3d(p3[0], p3[1], p3[2], p3[3]) {
                Some(s) => {
                    assert_eq!(s, dense3(p3), "{p3:?}");
                    zero += (s == Sign::Zero) as u32;
                }
                None => declined += 1,
            }
        }
        // The generator does reach exact cancellation.
        assert!(zero > 100, "{zero}");
        assert!(declined < 1000, "{declined}");
    }
}
