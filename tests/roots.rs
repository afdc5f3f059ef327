//! The quadratic solver against exact arithmetic (num-bigint): the root
//! count equals the exact discriminant's sign, and every root is within 4
//! ulps of an exact root, checked without square roots: the exact polynomial
//! has a root in `[t - 4 ulps, t + 4 ulps]` when it changes sign there or
//! when its vertex lies there with a non-negative discriminant.

use exactray::InputError;
use exactray::roots::{Roots, solve_quadratic, try_solve_quadratic};
use exactray::testing::step_ulps;
use exactray_oracle::oracle;
use proptest::prelude::*;

fn check(a: f64, b: f64, c: f64) -> Result<(), TestCaseError> {
    let roots = solve_quadratic(a, b, c);
    if a == 0.0 {
        let want = if b != 0.0 {
            Some(1)
        } else if c != 0.0 {
            Some(0)
        } else {
            None
        };
        prop_assert_eq!(roots.count(), want);
        return Ok(());
    }
    let want = match oracle::discriminant_sign(a, b, c) {
        1 => 2,
        0 => 1,
        _ => 0,
    };
    prop_assert_eq!(roots.count(), Some(want), "{} {} {}: {:?}", a, b, c, roots);
    let ts: Vec<f64> = match roots {
        Roots::One(t) => vec![t],
        Roots::Two(t0, t1) => {
            prop_assert!(t0 <= t1);
            vec![t0, t1]
        }
        _ => vec![],
    };
    for t in ts {
        prop_assert!(
            oracle::quadratic_root_near(a, b, c, t, 4),
            "{} {} {}: root {} not within 4 ulps",
            a,
            b,
            c,
            t
        );
    }
    Ok(())
}

/// A value of random sign with magnitude `2^e` times `[1, 2)`.
fn scaled() -> impl Strategy<Value = f64> {
    (1.0f64..2.0, -200i32..200, any::<bool>())
        .prop_map(|(m, e, neg)| m * 2f64.powi(e) * if neg { -1.0 } else { 1.0 })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn random_coefficients(a in scaled(), b in scaled(), c in scaled()) {
        check(a, b, c)?;
    }

    /// Coefficients of `(t - r1)(t - r2)` rounded: near-double roots when
    /// `r1` and `r2` are close, near-tangent discriminants.
    #[test]
    fn near_double_roots(r in scaled(), ulps in -40i64..40, a in scaled()) {
        let r2 = step_ulps(r, ulps);
        check(a, -a * (r + r2), a * r * r2)?;
    }

    /// `b^2 = 4ac` exactly, and one ulp away.
    #[test]
    fn tangent(a in scaled(), t in scaled(), ulps in -2i64..=2) {
        // a (t - r)^2 = a t^2 - 2 a r t + a r^2 with r a power of two keeps
        // every coefficient exact.
        let r = 2f64.powi(t.abs().log2().floor() as i32);
        let a = 2f64.powi(a.abs().log2().floor() as i32);
        check(a, -2.0 * a * r, step_ulps(a * r * r, ulps))?;
    }

    #[test]
    fn zero_coefficients(a in scaled(), b in scaled(), which in 0usize..3) {
        match which {
            0 => check(0.0, a, b)?,
            1 => check(a, 0.0, b)?,
            _ => check(a, b, 0.0)?,
        }
    }
}

#[test]
fn degenerate_and_bad_coefficients() {
    assert_eq!(solve_quadratic(0.0, 0.0, 0.0), Roots::All);
    assert_eq!(solve_quadratic(0.0, 0.0, 1.0), Roots::None);
    assert_eq!(solve_quadratic(1.0, 0.0, 1.0), Roots::None);
    assert_eq!(solve_quadratic(f64::NAN, 1.0, 1.0), Roots::None);
    assert_eq!(
        try_solve_quadratic(1.0, f64::INFINITY, 1.0),
        Err(InputError::NonFinite { argument: "b" })
    );
    assert_eq!(try_solve_quadratic(1.0, 2.0, 1.0), Ok(Roots::One(-1.0)));
    // The textbook formula returns 0 for the root of small magnitude here.
    let Roots::Two(small, large) = solve_quadratic(1.0, 1e200, 1.0) else {
        panic!()
    };
    assert_eq!((small, large), (-1e200, -1e-200));
}
