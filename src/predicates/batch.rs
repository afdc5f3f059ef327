//! Batch variants: one predicate over a slice of cases, the crate's way of
//! evaluating many predicates at once.
//!
//! Each function takes a slice of cases (each case the predicate's points,
//! as an array) and a slice of answers, and answers `min(cases.len(),
//! out.len())` cases: the first that many of `out` receive exactly what the
//! scalar predicate returns for the same case (`Sign::Zero` for a case with
//! a NaN or infinite coordinate). It returns how many it answered, so a
//! length mismatch never panics and never reads or writes out of bounds.
//! Nothing allocates.
//!
//! The cases are taken in blocks of [`BLOCK`]: a first, branch-free pass
//! computes stage 1 (the `f64` determinant and its certified error bound,
//! the same arithmetic as the scalar filter) for the whole block, which the
//! compiler can vectorize; a second pass writes the certified signs and
//! sends only the cases the filter could not certify through the scalar
//! exact stages.

#![allow(
    unsafe_code,
    reason = "calls the AVX2 kernels after detecting the feature"
)]

use super::{det, orient2d, orient3d};
use crate::arith::exponent::in_range;
use crate::arith::lanes::{BLOCK, Block};
use crate::point::{IntoDVec2, IntoDVec3};
use crate::sign::Sign;
#[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
use glam::DVec2;

/// The sign of a certified `f64` determinant, without a branch.
#[inline(always)]
fn sign_bits(det: f64) -> Sign {
    Sign::from_i8((det > 0.0) as i8 - (det < 0.0) as i8)
}

/// [`orient2d`](super::orient2d) of every case `[a, b, c]` in `cases`,
/// written to `out`: `out[i]` is `orient2d(a, b, c)` of `cases[i]`. Answers
/// `min(cases.len(), out.len())` cases and returns that count (see the
/// [module docs](crate::predicates)).
///
/// ```
/// use exactray::predicates::orient2d_many;
/// use exactray::Sign;
/// let cases = [
///     [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
///     [[0.1, 0.1], [0.2, 0.2], [0.3, 0.3]],
///     [[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]],
/// ];
/// let mut out = [Sign::Zero; 3];
/// assert_eq!(orient2d_many(&cases, &mut out), 3);
/// assert_eq!(out, [Sign::Positive, Sign::Zero, Sign::Negative]);
/// // A shorter output slice: only the cases it has room for.
/// assert_eq!(orient2d_many(&cases, &mut out[..1]), 1);
/// ```
pub fn orient2d_many<P: IntoDVec2>(cases: &[[P; 3]], out: &mut [Sign]) -> usize {
    #[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
    if std::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, checked just above.
        return unsafe { orient2d_many_avx2(cases, out) };
    }
    orient2d_many_in(cases, out)
}

/// [`orient2d_many`] with AVX2 intrinsics, four cases per step: two cases
/// share a 256-bit register as `(x, y, x, y)`, so the two products of stage
/// 1 come from one multiplication, and `hsub`/`hadd` form `det = detleft -
/// detright` and `detsum = |detleft| + |detright|` with the same roundings
/// as the scalar filter (`orient2d::stage_a_lanes`); the certificate is the
/// same comparison, `|det| - A * detsum > UNDERFLOW_SLACK`.
#[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
#[target_feature(enable = "avx2")]
unsafe fn orient2d_many_avx2<P: IntoDVec2>(cases: &[[P; 3]], out: &mut [Sign]) -> usize {
    #[cfg(target_arch = "x86")]
    use core::arch::x86::*;
    #[cfg(target_arch = "x86_64")]
    use core::arch::x86_64::*;

    let n = cases.len().min(out.len());
    let (cases, out) = (&cases[..n], &mut out[..n]);
    let abs = _mm256_castsi256_pd(_mm256_set1_epi64x(i64::MAX));
    let bound = _mm256_set1_pd(orient2d::A);
    let slack = _mm256_set1_pd(orient2d::UNDERFLOW_SLACK);
    let zero = _mm256_setzero_pd();
    let mut groups = cases.chunks_exact(4);
    let mut outs = out.chunks_exact_mut(4);
    for (group, out) in (&mut groups).zip(&mut outs) {
        let pts = |k: usize| group[k].map(IntoDVec2::into_dvec2);
        // (detleft, detright, detleft, detright) of cases k and l.
        let products = |k: usize, l: usize| {
            let half = |v: DVec2| _mm_setr_pd(v.x, v.y);
            let pair = |i: usize| {
                let (p, q) = (group[k][i].into_dvec2(), group[l][i].into_dvec2());
                _mm256_set_m128d(half(q), half(p))
            };
            let (a, b, c) = (pair(0), pair(1), pair(2));
            let (u, v) = (_mm256_sub_pd(a, c), _mm256_sub_pd(b, c));
            _mm256_mul_pd(u, _mm256_permute_pd::<0b0101>(v))
        };
        let (p01, p23) = (products(0, 1), products(2, 3));
        // Lanes hold cases 0, 2, 1, 3.
        let det = _mm256_hsub_pd(p01, p23);
        let detsum = _mm256_hadd_pd(_mm256_and_pd(p01, abs), _mm256_and_pd(p23, abs));
        let margin = _mm256_sub_pd(_mm256_and_pd(det, abs), _mm256_mul_pd(bound, detsum));
        let certified = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(margin, slack));
        if certified == 0b1111 {
            let pos = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(det, zero));
            let neg = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LT_OQ>(det, zero));
            out.copy_from_slice(&SIGNS_0213[(pos | neg << 4) as usize]);
        } else {
            for (k, o) in out.iter_mut().enumerate() {
                let [a, b, c] = pts(k);
                *o = orient2d::orient2d(a, b, c);
            }
        }
    }
    for (case, o) in groups.remainder().iter().zip(outs.into_remainder()) {
        let [a, b, c] = case.map(IntoDVec2::into_dvec2);
        *o = orient2d::orient2d(a, b, c);
    }
    n
}

/// `SIGNS_0213[pos | neg << 4]`: the signs of cases 0 to 3 whose
/// determinants sit in lanes 0, 2, 1, 3 of a vector, given the lanes'
/// "positive" bits `pos` and "negative" bits `neg`.
#[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
const SIGNS_0213: [[Sign; 4]; 256] = {
    let lane = [0, 2, 1, 3];
    let mut t = [[Sign::Zero; 4]; 256];
    let mut i = 0;
    while i < 256 {
        let mut k = 0;
        while k < 4 {
            let (p, n) = ((i >> lane[k]) & 1, (i >> (lane[k] + 4)) & 1);
            t[i][k] = Sign::from_i8(p as i8 - n as i8);
            k += 1;
        }
        i += 1;
    }
    t
};

/// The body of [`orient2d_many`], inlined into each instruction-set variant.
#[inline(always)]
fn orient2d_many_in<P: IntoDVec2>(cases: &[[P; 3]], out: &mut [Sign]) -> usize {
    let n = cases.len().min(out.len());
    let (cases, out) = (&cases[..n], &mut out[..n]);
    let mut blocks = cases.chunks_exact(BLOCK);
    let mut outs = out.chunks_exact_mut(BLOCK);
    for (block, out) in (&mut blocks).zip(&mut outs) {
        // The two products per case (a vector operation within each case),
        // then the rest of the filter with one lane per case.
        let (mut left, mut right) = ([0.0; BLOCK], [0.0; BLOCK]);
        for (k, case) in block.iter().enumerate() {
            let [a, b, c] = case.map(IntoDVec2::into_dvec2);
            let p = orient2d::products(a, b, c);
            (left[k], right[k]) = (p.x, p.y);
        }
        let (det, detsum, margin) = orient2d::stage_a_lanes(Block(left), Block(right));
        let (det, detsum) = (det.0, detsum.0);
        let certified = margin.0.map(orient2d::certifies);
        if certified == [true; BLOCK] {
            for k in 0..BLOCK {
                out[k] = sign_bits(det[k]);
            }
            continue;
        }
        for k in 0..BLOCK {
            out[k] = if certified[k] {
                sign_bits(det[k])
            } else {
                let [a, b, c] = block[k].map(IntoDVec2::into_dvec2);
                orient2d::declined(a, b, c, detsum[k])
            };
        }
    }
    for (case, o) in blocks.remainder().iter().zip(outs.into_remainder()) {
        let [a, b, c] = case.map(IntoDVec2::into_dvec2);
        *o = orient2d::orient2d(a, b, c);
    }
    n
}

/// [`orient3d`](super::orient3d) of every case `[a, b, c, d]` in `cases`,
/// written to `out`: `out[i]` is `orient3d(a, b, c, d)` of `cases[i]`.
/// Answers `min(cases.len(), out.len())` cases and returns that count (see
/// the [module docs](crate::predicates)).
///
/// ```
/// use exactray::predicates::orient3d_many;
/// use exactray::Sign;
/// use glam::DVec3;
/// let (o, x, y, z) = (DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z);
/// let cases = [[o, x, y, z], [o, x, y, -z], [o, x, y, x + y]];
/// let mut out = [Sign::Zero; 3];
/// assert_eq!(orient3d_many(&cases, &mut out), 3);
/// assert_eq!(out, [Sign::Positive, Sign::Negative, Sign::Zero]);
/// ```
pub fn orient3d_many<P: IntoDVec3>(cases: &[[P; 4]], out: &mut [Sign]) -> usize {
    #[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
    if std::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, checked just above.
        return unsafe { orient3d_many_avx2(cases, out) };
    }
    orient3d_many_in(cases, out)
}

/// [`orient3d_many`] compiled for AVX2: four lanes per vector instruction.
#[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
#[target_feature(enable = "avx2")]
unsafe fn orient3d_many_avx2<P: IntoDVec3>(cases: &[[P; 4]], out: &mut [Sign]) -> usize {
    orient3d_many_in(cases, out)
}

/// The body of [`orient3d_many`], inlined into each instruction-set variant.
#[inline(always)]
fn orient3d_many_in<P: IntoDVec3>(cases: &[[P; 4]], out: &mut [Sign]) -> usize {
    let n = cases.len().min(out.len());
    let (cases, out) = (&cases[..n], &mut out[..n]);
    let mut blocks = cases.chunks_exact(BLOCK);
    let mut outs = out.chunks_exact_mut(BLOCK);
    for (block, out) in (&mut blocks).zip(&mut outs) {
        let mut p = [[Block([0.0; BLOCK]); 3]; 4];
        for (k, case) in block.iter().enumerate() {
            for (i, v) in case.iter().enumerate() {
                let v = v.into_dvec3();
                (p[i][0].0[k], p[i][1].0[k], p[i][2].0[k]) = (v.x, v.y, v.z);
            }
        }
        let (det, permanent, margin, zsum) = orient3d::stage_a_lanes(p[0], p[1], p[2], p[3]);
        let (det, permanent) = (det.0, permanent.0);
        let certified: [bool; BLOCK] =
            core::array::from_fn(|k| det::certifies(margin.0[k], zsum.0[k], 0.0));
        if certified == [true; BLOCK] {
            for k in 0..BLOCK {
                out[k] = sign_bits(det[k]);
            }
            continue;
        }
        for k in 0..BLOCK {
            out[k] = if certified[k] {
                sign_bits(det[k])
            } else {
                let points = block[k].map(IntoDVec3::into_dvec3);
                // A zero in range is likely exactly degenerate: the scalar
                // ladder's lattice stage answers it.
                if det[k] == 0.0 && in_range(permanent[k]) {
                    let [a, b, c, d] = points;
                    orient3d::from_the_start(a, b, c, d)
                } else {
                    orient3d::declined(&points, permanent[k])
                }
            };
        }
    }
    for (case, o) in blocks.remainder().iter().zip(outs.into_remainder()) {
        let [a, b, c, d] = case.map(IntoDVec3::into_dvec3);
        *o = orient3d::orient3d(a, b, c, d);
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{InputClass, SplitMix64, orient2d_case, orient3d_case};
    use glam::{DVec2, DVec3};

    /// Every class mixed in one slice, so blocks mix certified and
    /// uncertified cases; lengths that leave every remainder.
    #[test]
    fn batch_equals_scalar() {
        let mut rng = SplitMix64::new(99);
        let mut c2: [[DVec2; 3]; 203] = [[DVec2::ZERO; 3]; 203];
        let mut c3: [[DVec3; 4]; 203] = [[DVec3::ZERO; 4]; 203];
        for round in 0..40 {
            for (i, (a, b)) in c2.iter_mut().zip(c3.iter_mut()).enumerate() {
                let class = InputClass::ALL[(i + round) % 6];
                *a = orient2d_case(class, &mut rng);
                *b = orient3d_case(class, &mut rng);
            }
            // Non-finite coordinates answer Zero, as the scalar ones do.
            c2[round][1] = DVec2::new(f64::NAN, 0.0);
            c3[round + 7][2] = DVec3::new(0.0, f64::INFINITY, 0.0);
            for len in [0, 1, 3, 4, 7, 8, 9, 16, 17, 203] {
                let mut out = [Sign::Positive; 203];
                let mut out_in = [Sign::Positive; 203];
                assert_eq!(orient2d_many(&c2[..len], &mut out), len);
                assert_eq!(orient2d_many_in(&c2[..len], &mut out_in), len);
                for (k, [a, b, c]) in c2[..len].iter().enumerate() {
                    let want = crate::predicates::orient2d(*a, *b, *c);
                    assert_eq!((out[k], out_in[k]), (want, want), "orient2d case {k}");
                }
                assert_eq!(orient3d_many(&c3[..len], &mut out), len);
                assert_eq!(orient3d_many_in(&c3[..len], &mut out_in), len);
                for (k, [a, b, c, d]) in c3[..len].iter().enumerate() {
                    let want = crate::predicates::orient3d(*a, *b, *c, *d);
                    assert_eq!((out[k], out_in[k]), (want, want), "orient3d case {k}");
                }
            }
        }
    }

    #[test]
    fn mismatched_lengths_answer_the_shorter() {
        let cases = [[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]; 20];
        let mut out = [Sign::Zero; 11];
        assert_eq!(orient2d_many(&cases, &mut out), 11);
        assert!(out.iter().all(|&s| s == Sign::Positive));
        assert_eq!(orient2d_many(&cases[..5], &mut out), 5);
        let cases3 = [[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]; 3];
        assert_eq!(orient3d_many(&cases3, &mut out), 3);
        assert_eq!(orient3d_many(&cases3, &mut []), 0);
    }
}
