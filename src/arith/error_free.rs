//! Error-free transformations: a sum, a difference or a product as the
//! rounded result and its exact rounding error (Knuth's TwoSum, the FMA
//! TwoProduct; Higham, *Accuracy and Stability of Numerical Algorithms*,
//! 2nd ed., §4.3).

use super::std_or_libm::fma;
use glam::DVec3;

/// `a + b` as `(s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly
/// (Knuth's TwoSum; Higham, *Accuracy and Stability*, 2nd ed., §4.3), for
/// any finite inputs whose sum does not overflow.
#[inline(always)]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a - b` exactly, as a double-double `(hi, lo)` per component (TwoSum;
/// exact unless a difference overflows): the sphere's and the cylinder's
/// `o - point`, the triangle's rows.
#[inline(always)]
pub(crate) fn exact_difference(a: DVec3, b: DVec3) -> (DVec3, DVec3) {
    let (x, y, z) = (two_sum(a.x, -b.x), two_sum(a.y, -b.y), two_sum(a.z, -b.z));
    (DVec3::new(x.0, y.0, z.0), DVec3::new(x.1, y.1, z.1))
}

/// `a * b` as `(p, e)` with `p = fl(a b)` and `p + e = a b` exactly, when
/// the product neither overflows nor underflows (the error of a product is
/// a float then; Higham §4.3). One `fma`: a single instruction where
/// [`with_fma`](super::fma_dispatch::with_fma) has enabled it.
#[inline(always)]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, fma(a, b, -p))
}
