//! Property tests of the predicates on constructed points against the exact
//! oracle: every input class, each case then scaled by a power of two from
//! `2^-1000` to `2^1000`, or each axis by its own, or built on raw finite
//! bit patterns; and the symmetries an exact predicate keeps.
//!
//! Uses proptest directly (a dev-dependency) and the crate's always-built
//! generators, so it runs under plain `cargo test`.

use core::cmp::Ordering;
use exactray::predicates::{
    Axis, Lpi, Ssi, Tpi, cmp_along_line_2d, cmp_on_axis, orient2d_implicit, orient3d_implicit,
};
use exactray::testing::{
    InputClass, SplitMix64, finite_f64_from_bits, less_on_axis_lpi_case, orient2d_ssi_case,
    orient3d_lpi_case, orient3d_tpi_case,
};
use exactray::{InputError, Sign};
use exactray_oracle::implicit_oracle::{self as oracle, Pt2, Pt3};
use glam::{DVec2, DVec3};
use proptest::prelude::*;
use proptest::test_runner::Config;

fn config(cases: u32) -> Config {
    Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    }
}

/// `x 2^k`, rounded once (`|k| <= 2000`).
fn scale(x: f64, k: i32) -> f64 {
    let p = |e: i32| f64::from_bits(((e.clamp(-1022, 1023) + 1023) as u64) << 52);
    x * p(k / 2) * p(k - k / 2)
}

/// Each axis `a` of every point times `2^k[a]` (one `k` for all: uniform).
fn scaled<const N: usize, const D: usize>(p: [[f64; D]; N], k: [i32; D]) -> [[f64; D]; N] {
    p.map(|v| core::array::from_fn(|a| scale(v[a], k[a])))
}

fn exponents(rng: &mut SplitMix64, uniform: bool) -> [i32; 3] {
    let mut e = || (rng.next_u64() % 2001) as i32 - 1000;
    if uniform {
        let k = e();
        [k; 3]
    } else {
        [e(), e(), e()]
    }
}

fn sign(s: i8) -> Sign {
    Sign::from_i8(s)
}

proptest! {
    #![proptest_config(config(1500))]

    /// orient3d with a line–plane point, every class, at every scale.
    #[test]
    fn orient3d_lpi_at_every_scale(seed in any::<u64>(), class in 0usize..6, uniform in any::<bool>()) {
        let mut rng = SplitMix64::new(seed);
        let c = orient3d_lpi_case(InputClass::ALL[class], &mut rng).map(|v| v.to_array());
        let c = scaled(c, exponents(&mut rng, uniform));
        prop_assume!(c.as_flattened().iter().all(|x| x.is_finite()));
        let v = c.map(DVec3::from);
        let pt = [Pt3::E(c[0]), Pt3::E(c[1]), Pt3::E(c[2]), Pt3::Lpi([c[3], c[4], c[5], c[6], c[7]])];
        match Lpi::new(v[3], v[4], v[5], v[6], v[7]) {
            Ok(x) => {
                let want = sign(oracle::orient3d(pt).expect("the crate accepted it"));
                prop_assert_eq!(orient3d_implicit(v[0], v[1], v[2], &x), want);
                prop_assert_eq!(orient3d_implicit(v[1], v[0], v[2], &x), -want);
            }
            // Scaling may flush a construction into one that is not a point.
            Err(e) => {
                prop_assert_eq!(e, InputError::NoUniqueIntersection { construction: "Lpi" });
                prop_assert_eq!(oracle::weight_sign3(&pt[3]), 0);
            }
        }
    }

    /// orient3d with a three-plane point, every class, at every scale.
    #[test]
    fn orient3d_tpi_at_every_scale(seed in any::<u64>(), class in 0usize..6, uniform in any::<bool>()) {
        let mut rng = SplitMix64::new(seed);
        let c = orient3d_tpi_case(InputClass::ALL[class], &mut rng).map(|v| v.to_array());
        let c = scaled(c, exponents(&mut rng, uniform));
        prop_assume!(c.as_flattened().iter().all(|x| x.is_finite()));
        let planes = [[c[3], c[4], c[5]], [c[6], c[7], c[8]], [c[9], c[10], c[11]]];
        let pt = [Pt3::E(c[0]), Pt3::E(c[1]), Pt3::E(c[2]), Pt3::Tpi(planes)];
        if let Ok(x) = Tpi::new(planes[0], planes[1], planes[2]) {
            let want = sign(oracle::orient3d(pt).expect("the crate accepted it"));
            prop_assert_eq!(orient3d_implicit(c[0], c[1], c[2], &x), want);
        } else {
            prop_assert_eq!(oracle::weight_sign3(&pt[3]), 0);
        }
    }

    /// orient2d with a line–line point and the order along its first line,
    /// every class, at every scale.
    #[test]
    fn ssi_at_every_scale(seed in any::<u64>(), class in 0usize..6, uniform in any::<bool>()) {
        let mut rng = SplitMix64::new(seed);
        let c = orient2d_ssi_case(InputClass::ALL[class], &mut rng).map(|v| v.to_array());
        let e = exponents(&mut rng, uniform);
        let c = scaled(c, [e[0], e[1]]);
        prop_assume!(c.as_flattened().iter().all(|x| x.is_finite()));
        let x = Pt2::Ssi([c[2], c[3], c[4], c[5]]);
        if let Ok(s) = Ssi::new(c[2], c[3], c[4], c[5]) {
            let want = sign(oracle::orient2d([Pt2::E(c[0]), Pt2::E(c[1]), x]).unwrap());
            prop_assert_eq!(orient2d_implicit(c[0], c[1], &s), want);
            if c[2] != c[3] {
                let want = oracle::cmp_along2(c[2], c[3], x, Pt2::E(c[0])).unwrap();
                prop_assert_eq!(cmp_along_line_2d(c[2], c[3], &s, c[0]), want);
            }
        } else {
            prop_assert_eq!(oracle::weight_sign2(&x), 0);
        }
    }

    /// Two line–plane points along an axis, every class, at every scale.
    #[test]
    fn less_on_axis_at_every_scale(seed in any::<u64>(), class in 0usize..6, uniform in any::<bool>()) {
        let mut rng = SplitMix64::new(seed);
        let (c, axis) = less_on_axis_lpi_case(InputClass::ALL[class], &mut rng);
        let c = scaled(c.map(|v| v.to_array()), exponents(&mut rng, uniform));
        prop_assume!(c.as_flattened().iter().all(|x| x.is_finite()));
        let lpi = |i: usize| Lpi::new(c[i], c[i + 1], c[i + 2], c[i + 3], c[i + 4]);
        let pt = |i: usize| Pt3::Lpi([c[i], c[i + 1], c[i + 2], c[i + 3], c[i + 4]]);
        if let (Ok(x), Ok(y)) = (lpi(0), lpi(5)) {
            let want = oracle::cmp_on_axis3(pt(0), pt(5), axis).unwrap();
            prop_assert_eq!(cmp_on_axis(&x, &y, Axis::ALL[axis]), want);
            prop_assert_eq!(cmp_on_axis(&y, &x, Axis::ALL[axis]), want.reverse());
        }
    }

    /// Constructions on raw finite bit patterns (every finite `f64`, most
    /// far from 1), the construction's verdict and the predicate against
    /// the oracle.
    #[test]
    fn raw_bit_patterns(bits in prop::array::uniform32(any::<u64>()), share in 0usize..4) {
        let v: [f64; 32] = bits.map(finite_f64_from_bits);
        let mut p: [[f64; 3]; 8] = core::array::from_fn(|i| [v[3 * i], v[3 * i + 1], v[3 * i + 2]]);
        // Shared points make degenerate configurations likely.
        if share > 0 {
            p[3 + share] = p[share - 1];
        }
        let pt = Pt3::Lpi([p[3], p[4], p[5], p[6], p[7]]);
        match Lpi::new(p[3], p[4], p[5], p[6], p[7]) {
            Ok(x) => {
                let want = oracle::orient3d([Pt3::E(p[0]), Pt3::E(p[1]), Pt3::E(p[2]), pt]).unwrap();
                prop_assert_eq!(orient3d_implicit(p[0], p[1], p[2], &x), sign(want));
                let want = oracle::cmp_on_axis3(pt, Pt3::E(p[0]), share % 3).unwrap();
                prop_assert_eq!(cmp_on_axis(&x, p[0], Axis::ALL[share % 3]), want);
            }
            Err(_) => prop_assert_eq!(oracle::weight_sign3(&pt), 0),
        }
    }
}

/// A constructed point compared with itself is `Equal` along every axis,
/// and on the plane of any three of its own plane's points.
#[test]
fn a_point_against_itself() {
    let mut rng = SplitMix64::new(5);
    for class in InputClass::ALL {
        for _ in 0..500 {
            let c = orient3d_lpi_case(class, &mut rng);
            let x = Lpi::new(c[3], c[4], c[5], c[6], c[7]).unwrap();
            for axis in Axis::ALL {
                assert_eq!(cmp_on_axis(&x, &x, axis), Ordering::Equal);
            }
            assert_eq!(orient3d_implicit(c[5], c[6], c[7], &x), Sign::Zero, "{c:?}");
            let _ = DVec2::ZERO;
        }
    }
}
