//! Lanes: what the filters compute with, one `f64` (the scalar
//! predicates) or a block of them, one per case (the batch variants).

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
