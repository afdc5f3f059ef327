//! Runtime FMA dispatch: a kernel compiled a second time with the `fma`
//! target feature and chosen once the CPU is known.

#![allow(
    unsafe_code,
    reason = "calls the FMA-compiled copy after detecting the feature"
)]

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
