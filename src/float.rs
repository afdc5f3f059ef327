//! Correctly rounded `sqrt` and `fma` with or without `std`: IEEE 754
//! requires both to round correctly; `std` uses the hardware instructions,
//! `libm` the same instructions where the target has them (x86-64 has
//! `sqrtsd`; `fma` in software where FMA is not enabled).

use glam::DVec3;

/// `sqrt(x)`, correctly rounded.
#[inline(always)]
pub(crate) fn sqrt(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrt(x)
    }
}

/// `x * y + z` with one rounding.
#[inline(always)]
pub(crate) fn fma(x: f64, y: f64, z: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.mul_add(y, z)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::fma(x, y, z)
    }
}

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

/// `a` or `b`, whichever is larger: one `maxsd`, where `f64::max` also
/// handles NaN (for finite values, or values that overflowed to
/// infinity, the same).
#[inline(always)]
pub(crate) fn larger(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// The largest magnitude of a coordinate of `vs` (infinite where one
/// overflowed).
#[inline(always)]
pub(crate) fn largest_magnitude(vs: &[DVec3]) -> f64 {
    vs.iter().fold(0.0, |m, v| {
        let a = v.abs();
        larger(larger(larger(m, a.x), a.y), a.z)
    })
}

/// `a * b` as `(p, e)` with `p = fl(a b)` and `p + e = a b` exactly, when
/// the product neither overflows nor underflows (the error of a product is
/// a float then; Higham §4.3). One `fma`: a single instruction where
/// [`with_fma`] has enabled it.
#[inline(always)]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, fma(a, b, -p))
}

/// A computation to run compiled with hardware FMA where the CPU has it.
/// `run` must be `#[inline(always)]`, so that its body, and the `fma`
/// calls in it, are compiled inside [`with_fma`]'s FMA-enabled copy.
pub(crate) trait FmaKernel {
    /// What the computation returns.
    type Output;
    /// The computation.
    fn run(&self) -> Self::Output;
}

/// Runs `k` in a copy compiled with the `fma` target feature when the
/// build does not enable it already and the CPU has it (detected once and
/// cached by `std`), so an `fma` is one instruction instead of a call to
/// the C library's `fma`. The results are the same either way: `fma`
/// rounds once in both.
#[inline(always)]
pub(crate) fn with_fma<K: FmaKernel>(k: &K) -> K::Output {
    #[cfg(all(feature = "std", target_arch = "x86_64", not(target_feature = "fma")))]
    {
        if std::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU supports FMA, checked just above.
            return unsafe { run_with_fma(k) };
        }
    }
    k.run()
}

/// # Safety
/// The CPU must support the `fma` feature.
#[cfg(all(feature = "std", target_arch = "x86_64", not(target_feature = "fma")))]
#[target_feature(enable = "fma")]
#[inline(never)]
unsafe fn run_with_fma<K: FmaKernel>(k: &K) -> K::Output {
    k.run()
}
