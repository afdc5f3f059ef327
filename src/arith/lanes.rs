//! Lanes: what the filters compute with, one `f64` (the scalar
//! predicates) or a block of them, one per case (the batch variants), and
//! pairs of them (`Pair`) for a filter whose operations pair up.

#![allow(
    unsafe_code,
    reason = "SSE2 intrinsics for `Pair`, part of the x86-64 baseline"
)]

use core::ops::{Add, Mul, Sub};

/// How many cases the filter pass handles at once.
///
/// ```
/// assert!(exactray::predicates::BLOCK >= 4);
/// ```
pub const BLOCK: usize = 8;

/// What stage 1 computes with: one `f64` (the scalar predicates) or a
/// block of them, one per case (the batch variants). Every operation is the
/// `f64` operation lane by lane, so the error bounds derived for `f64`
/// hold in every lane.
pub(crate) trait Lanes:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self>
{
    /// The same value in every lane.
    fn splat(v: f64) -> Self;
    /// `|self|` in every lane.
    fn abs(self) -> Self;
}

impl Lanes for f64 {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        v
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
}

/// One `f64` per case of a block. Operations are element-wise loops that
/// the compiler turns into vector instructions.
#[derive(Clone, Copy)]
pub(crate) struct Block(pub(crate) [f64; BLOCK]);

impl Lanes for Block {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        Block([v; BLOCK])
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Block(self.0.map(f64::abs))
    }
}

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for Block {
            type Output = Block;
            #[inline(always)]
            fn $f(self, o: Block) -> Block {
                Block(core::array::from_fn(|k| self.0[k] $op o.0[k]))
            }
        }
    };
}
lanewise!(Add, add, +);
lanewise!(Sub, sub, -);
lanewise!(Mul, mul, *);

/// Two `f64` lanes in one SSE2 register (x86-64, where SSE2 is part of
/// the baseline), or in an array elsewhere: for filters whose operations
/// pair up. Every operation is the `f64` operation lane by lane.
#[derive(Clone, Copy)]
pub(crate) struct Pair(
    #[cfg(target_arch = "x86_64")] __m128d,
    #[cfg(not(target_arch = "x86_64"))] [f64; 2],
);

#[cfg(target_arch = "x86_64")]
use core::arch::x86_64::{
    __m128d, _mm_add_pd, _mm_and_pd, _mm_castsi128_pd, _mm_cvtsd_f64, _mm_max_pd, _mm_mul_pd,
    _mm_set_pd, _mm_set1_epi64x, _mm_shuffle_pd, _mm_sub_pd, _mm_unpackhi_pd, _mm_unpacklo_pd,
};

#[cfg(target_arch = "x86_64")]
impl Pair {
    /// `[lo, hi]`.
    #[inline(always)]
    pub(crate) fn new(lo: f64, hi: f64) -> Self {
        // SAFETY: SSE2, which every x86-64 target enables.
        Pair(unsafe { _mm_set_pd(hi, lo) })
    }
    /// `[hi, lo]`.
    #[inline(always)]
    pub(crate) fn swap(self) -> Self {
        // SAFETY: SSE2, which every x86-64 target enables.
        Pair(unsafe { _mm_shuffle_pd::<1>(self.0, self.0) })
    }
    /// `[self.lo, other.lo]`.
    #[inline(always)]
    pub(crate) fn lows(self, other: Self) -> Self {
        // SAFETY: SSE2, which every x86-64 target enables.
        Pair(unsafe { _mm_unpacklo_pd(self.0, other.0) })
    }
    /// `[self.hi, other.hi]`.
    #[inline(always)]
    pub(crate) fn highs(self, other: Self) -> Self {
        // SAFETY: SSE2, which every x86-64 target enables.
        Pair(unsafe { _mm_unpackhi_pd(self.0, other.0) })
    }
    /// The low lane.
    #[inline(always)]
    pub(crate) fn lo(self) -> f64 {
        // SAFETY: SSE2, which every x86-64 target enables.
        unsafe { _mm_cvtsd_f64(self.0) }
    }
    /// The high lane.
    #[inline(always)]
    pub(crate) fn hi(self) -> f64 {
        self.swap().lo()
    }
    /// `|self|` in both lanes.
    #[inline(always)]
    pub(crate) fn abs(self) -> Self {
        // SAFETY: SSE2, which every x86-64 target enables.
        Pair(unsafe { _mm_and_pd(self.0, _mm_castsi128_pd(_mm_set1_epi64x(i64::MAX))) })
    }
    /// The larger of `self` and `o` in each lane (`o` where either is NaN).
    #[inline(always)]
    pub(crate) fn larger(self, o: Self) -> Self {
        // SAFETY: SSE2, which every x86-64 target enables.
        Pair(unsafe { _mm_max_pd(self.0, o.0) })
    }
}

#[cfg(target_arch = "x86_64")]
macro_rules! pairwise {
    ($tr:ident, $f:ident, $intrinsic:ident) => {
        impl $tr for Pair {
            type Output = Pair;
            #[inline(always)]
            fn $f(self, o: Pair) -> Pair {
                // SAFETY: SSE2, which every x86-64 target enables.
                Pair(unsafe { $intrinsic(self.0, o.0) })
            }
        }
    };
}
#[cfg(target_arch = "x86_64")]
pairwise!(Add, add, _mm_add_pd);
#[cfg(target_arch = "x86_64")]
pairwise!(Sub, sub, _mm_sub_pd);
#[cfg(target_arch = "x86_64")]
pairwise!(Mul, mul, _mm_mul_pd);

#[cfg(not(target_arch = "x86_64"))]
impl Pair {
    /// `[lo, hi]`.
    #[inline(always)]
    pub(crate) fn new(lo: f64, hi: f64) -> Self {
        Pair([lo, hi])
    }
    /// `[hi, lo]`.
    #[inline(always)]
    pub(crate) fn swap(self) -> Self {
        Pair([self.0[1], self.0[0]])
    }
    /// `[self.lo, other.lo]`.
    #[inline(always)]
    pub(crate) fn lows(self, other: Self) -> Self {
        Pair([self.0[0], other.0[0]])
    }
    /// `[self.hi, other.hi]`.
    #[inline(always)]
    pub(crate) fn highs(self, other: Self) -> Self {
        Pair([self.0[1], other.0[1]])
    }
    /// The low lane.
    #[inline(always)]
    pub(crate) fn lo(self) -> f64 {
        self.0[0]
    }
    /// The high lane.
    #[inline(always)]
    pub(crate) fn hi(self) -> f64 {
        self.0[1]
    }
    /// `|self|` in both lanes.
    #[inline(always)]
    pub(crate) fn abs(self) -> Self {
        Pair(self.0.map(f64::abs))
    }
    /// The larger of `self` and `o` in each lane (`o` where either is NaN).
    #[inline(always)]
    pub(crate) fn larger(self, o: Self) -> Self {
        Pair([0, 1].map(|k| {
            if self.0[k] > o.0[k] {
                self.0[k]
            } else {
                o.0[k]
            }
        }))
    }
}

#[cfg(not(target_arch = "x86_64"))]
macro_rules! pairwise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for Pair {
            type Output = Pair;
            #[inline(always)]
            fn $f(self, o: Pair) -> Pair {
                Pair([self.0[0] $op o.0[0], self.0[1] $op o.0[1]])
            }
        }
    };
}
#[cfg(not(target_arch = "x86_64"))]
pairwise!(Add, add, +);
#[cfg(not(target_arch = "x86_64"))]
pairwise!(Sub, sub, -);
#[cfg(not(target_arch = "x86_64"))]
pairwise!(Mul, mul, *);
