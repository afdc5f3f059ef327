//! Floor 1, above the vocabulary of floor 0 (errors, signs, points,
//! intervals): number machinery only, no geometry. Error-free
//! transformations, the FMA and its runtime dispatch, the unit roundoff,
//! exponents and scaling by powers of two, values of unbounded exponent,
//! fixed-capacity stack integers, double-double rows, Shewchuk's
//! floating-point expansions, sparse exact sums and
//! the lanes the filters compute in. Private: the public API speaks of
//! signs, roots and hits, never of these.

pub(crate) mod double_double;
pub(crate) mod error_free;
pub(crate) mod expansion;
pub(crate) mod exponent;
pub(crate) mod fixed_int;
pub(crate) mod fma_dispatch;
pub(crate) mod lanes;
pub(crate) mod magnitude;
pub(crate) mod roundoff;
pub(crate) mod scaled_float;
pub(crate) mod sparse_sum;
pub(crate) mod std_or_libm;
