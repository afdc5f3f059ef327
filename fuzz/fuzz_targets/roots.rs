//! The quadratic solver against exact arithmetic, on coefficients from raw
//! bit patterns (every finite value): it must never panic and must return
//! sorted roots; where its error bound applies (every non-zero coefficient
//! within `2^450` of the largest, so that no product of the scaled
//! coefficients reaches the subnormal range), the root count must equal the
//! exact discriminant's sign and every root must lie within 4 ulps of an
//! exact root.
#![no_main]

use exactray::roots::{Roots, solve_quadratic};
use exactray::testing::finite_f64_from_bits;
use exactray_oracle::oracle;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bits: [u64; 3]| {
    let [a, b, c] = bits.map(finite_f64_from_bits);
    let roots = solve_quadratic(a, b, c);
    if let Roots::Two(t0, t1) = roots {
        assert!(t0 < t1, "{a:e} {b:e} {c:e}: {roots:?}");
    }
    let m = a.abs().max(b.abs()).max(c.abs());
    let in_range = [a, b, c]
        .iter()
        .all(|v| *v == 0.0 || v.abs() >= m * 2f64.powi(-450));
    if a == 0.0 || !in_range {
        return;
    }
    let want = match oracle::discriminant_sign(a, b, c) {
        1 => Some(2),
        0 => Some(1),
        _ => Some(0),
    };
    assert_eq!(roots.count(), want, "{a:e} {b:e} {c:e}: {roots:?}");
    let ts = match roots {
        Roots::One(t) => vec![t],
        Roots::Two(t0, t1) => vec![t0, t1],
        _ => vec![],
    };
    for t in ts {
        assert!(t.is_finite(), "{a:e} {b:e} {c:e}: {roots:?}");
        assert!(
            oracle::quadratic_root_near(a, b, c, t, 4),
            "{a:e} {b:e} {c:e}: root {t:e} not within 4 ulps"
        );
    }
});
