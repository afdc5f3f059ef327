//! Property tests of the predicates against the exact oracle, on every class
//! of hard input and on raw finite bit patterns, plus the symmetries an exact
//! predicate must keep bit for bit.
//!
//! Uses proptest directly (a dev-dependency) and the crate's always-built
//! `hard_inputs` generators, so it runs under plain `cargo test` without the
//! crate's `proptest` feature. A seed drives every class at once, so each
//! property covers each class on every case.

use exactray::testing::finite_f64_from_bits;
use exactray::testing::{
    InputClass, SplitMix64, incircle_case, insphere_case, orient2d_case, orient3d_case,
    plane_side_case,
};
use exactray::{
    InputError, Sign,
    predicates::{
        SideRelation, incircle, insphere, orient2d, orient3d, same_side, side_of_plane,
        try_incircle, try_insphere, try_orient2d, try_orient3d, try_same_side, try_side_of_plane,
    },
};
use exactray_oracle::oracle;
use glam::{DVec2, DVec3, Vec2, Vec3, Vec3A};
use proptest::prelude::*;
use proptest::test_runner::Config;

fn config(cases: u32) -> Config {
    // Failures are kept as exact bits in tests/regressions.rs instead of a
    // proptest-regressions file beside this one.
    Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    }
}

fn s(v: i8) -> Sign {
    Sign::from_i8(v)
}

fn relation(v: i8) -> SideRelation {
    match v {
        1 => SideRelation::Same,
        -1 => SideRelation::Opposite,
        _ => SideRelation::OnPlane,
    }
}

fn o2(p: [DVec2; 3]) -> Sign {
    s(oracle::orient2d(p[0].into(), p[1].into(), p[2].into()))
}
fn o3(p: [DVec3; 4]) -> Sign {
    s(oracle::orient3d(
        p[0].into(),
        p[1].into(),
        p[2].into(),
        p[3].into(),
    ))
}
fn ic(p: [DVec2; 4]) -> Sign {
    s(oracle::incircle(
        p[0].into(),
        p[1].into(),
        p[2].into(),
        p[3].into(),
    ))
}
fn is(p: [DVec3; 5]) -> Sign {
    s(oracle::insphere(
        p[0].into(),
        p[1].into(),
        p[2].into(),
        p[3].into(),
        p[4].into(),
    ))
}
fn ps(p: [DVec3; 5]) -> SideRelation {
    relation(oracle::plane_side(
        p[0].into(),
        p[1].into(),
        p[2].into(),
        p[3].into(),
        p[4].into(),
    ))
}

fn e_orient2d(p: [DVec2; 3]) -> Sign {
    orient2d(p[0], p[1], p[2])
}
fn e_orient3d(p: [DVec3; 4]) -> Sign {
    orient3d(p[0], p[1], p[2], p[3])
}
fn e_incircle(p: [DVec2; 4]) -> Sign {
    incircle(p[0], p[1], p[2], p[3])
}
fn e_insphere(p: [DVec3; 5]) -> Sign {
    insphere(p[0], p[1], p[2], p[3], p[4])
}
fn e_same_side(p: [DVec3; 5]) -> SideRelation {
    same_side(p[0], p[1], p[2], p[3], p[4])
}

/// Cases of every class from one seed, one stream per class so that a class
/// does not shift the others' cases.
fn by_class<T>(seed: u64, generate: fn(InputClass, &mut SplitMix64) -> T) -> Vec<(InputClass, T)> {
    InputClass::ALL
        .iter()
        .map(|&c| {
            (
                c,
                generate(
                    c,
                    &mut SplitMix64::new(seed ^ (c as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15)),
                ),
            )
        })
        .collect()
}

const SPECIALS: [f64; 8] = [
    0.0,
    -0.0,
    f64::from_bits(1),
    -f64::from_bits(1),
    f64::MIN_POSITIVE,
    f64::MAX,
    -f64::MAX,
    1.0 + f64::EPSILON,
];

/// A finite coordinate: mostly raw bit patterns (every finite value equally
/// likely), mixed with small integers and special values so that raw cases
/// also share coordinates and hit exact zeros.
fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => any::<u64>().prop_map(finite_f64_from_bits),
        1 => (-3i8..=3).prop_map(f64::from),
        1 => prop::sample::select(&SPECIALS[..]),
    ]
}

fn raw2() -> impl Strategy<Value = DVec2> {
    (coord(), coord()).prop_map(|(x, y)| DVec2::new(x, y))
}
fn raw3() -> impl Strategy<Value = DVec3> {
    (coord(), coord(), coord()).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

/// The exponent of the lowest set bit and of the highest set bit of `x`
/// (`x = m * 2^lo` with odd `m`, `2^hi <= |x| < 2^(hi+1)`), for `x != 0`.
fn bit_span(x: f64) -> Option<(i32, i32)> {
    if x == 0.0 {
        return None;
    }
    let bits = x.to_bits() & !(1 << 63);
    let field = (bits >> 52) as i32;
    let (m, e) = if field == 0 {
        (bits, -1074)
    } else {
        ((bits & ((1 << 52) - 1)) | (1 << 52), field - 1075)
    };
    Some((
        e + m.trailing_zeros() as i32,
        e + 63 - m.leading_zeros() as i32,
    ))
}

/// A power-of-two exponent `k` such that `x * 2^k` is exact for every
/// coordinate (no overflow, no bits lost in the subnormals), picked from the
/// whole allowed range by `pick`; `None` if all coordinates are zero.
fn exact_scale_exponent(coords: &[f64], pick: u64) -> Option<i32> {
    let spans: Vec<(i32, i32)> = coords.iter().filter_map(|&x| bit_span(x)).collect();
    let lo = spans.iter().map(|s| s.0).min()?;
    let hi = spans.iter().map(|s| s.1).max()?;
    let (kmin, kmax) = (-1074 - lo, 1023 - hi);
    assert!(kmin <= kmax);
    Some(kmin + (pick % (kmax - kmin + 1) as u64) as i32)
}

/// `x * 2^k` exactly (the caller has checked the range). `|k|` can exceed
/// 2046 (subnormal inputs scaled to the top), so it goes in steps of normal
/// powers of two; each intermediate lies between `x` and the result, so no
/// step rounds when the result is exact.
fn ldexp(mut x: f64, mut k: i32) -> f64 {
    while k != 0 {
        let step = k.clamp(-1022, 1023);
        x *= f64::from_bits(((step + 1023) as u64) << 52);
        k -= step;
    }
    x
}

fn scale2<const N: usize>(p: [DVec2; N], k: i32) -> [DVec2; N] {
    p.map(|v| DVec2::new(ldexp(v.x, k), ldexp(v.y, k)))
}
fn scale3<const N: usize>(p: [DVec3; N], k: i32) -> [DVec3; N] {
    p.map(|v| DVec3::new(ldexp(v.x, k), ldexp(v.y, k), ldexp(v.z, k)))
}

/// `x + t` when that sum is exact (Knuth's TwoSum error is zero), else `None`.
fn exact_add(x: f64, t: f64) -> Option<f64> {
    let s = x + t;
    if !s.is_finite() {
        return None;
    }
    let tv = s - x;
    let err = (x - (s - tv)) + (t - tv);
    (err == 0.0).then_some(s)
}

/// A translation vector on the grid of the inputs' lowest set bit, so that
/// translating is often exact.
fn translation(coords: &[f64], dims: usize, pick: u64) -> Vec<f64> {
    let lo = coords
        .iter()
        .filter_map(|&x| bit_span(x))
        .map(|s| s.0)
        .min()
        .unwrap_or(0);
    let mut rng = SplitMix64::new(pick);
    (0..dims)
        .map(|_| {
            let m = (rng.next_u64() % 33) as f64 - 16.0;
            let e = (lo + (rng.next_u64() % 40) as i32).clamp(-1074, 1000);
            ldexp(m, e)
        })
        .collect()
}

fn translate2<const N: usize>(p: [DVec2; N], t: &[f64]) -> Option<[DVec2; N]> {
    let mut out = p;
    for v in &mut out {
        *v = DVec2::new(exact_add(v.x, t[0])?, exact_add(v.y, t[1])?);
    }
    Some(out)
}
fn translate3<const N: usize>(p: [DVec3; N], t: &[f64]) -> Option<[DVec3; N]> {
    let mut out = p;
    for v in &mut out {
        *v = DVec3::new(
            exact_add(v.x, t[0])?,
            exact_add(v.y, t[1])?,
            exact_add(v.z, t[2])?,
        );
    }
    Some(out)
}

fn flat2(p: &[DVec2]) -> Vec<f64> {
    p.iter().flat_map(|v| v.to_array()).collect()
}
fn flat3(p: &[DVec3]) -> Vec<f64> {
    p.iter().flat_map(|v| v.to_array()).collect()
}

fn swapped<T: Copy, const N: usize>(p: [T; N], i: usize, j: usize) -> [T; N] {
    let mut q = p;
    q.swap(i, j);
    q
}

// ---------------------------------------------------------------- oracle

proptest! {
    #![proptest_config(config(400))]

    #[test]
    fn orient2d_matches_oracle_on_every_class(seed in any::<u64>()) {
        for (class, p) in by_class(seed, orient2d_case) {
            prop_assert_eq!(e_orient2d(p), o2(p), "class {}: {:?}", class.name(), p);
        }
    }

    #[test]
    fn orient3d_matches_oracle_on_every_class(seed in any::<u64>()) {
        for (class, p) in by_class(seed, orient3d_case) {
            prop_assert_eq!(e_orient3d(p), o3(p), "class {}: {:?}", class.name(), p);
        }
    }

    #[test]
    fn incircle_matches_oracle_on_every_class(seed in any::<u64>()) {
        for (class, p) in by_class(seed, incircle_case) {
            prop_assert_eq!(e_incircle(p), ic(p), "class {}: {:?}", class.name(), p);
        }
    }

    #[test]
    fn plane_side_matches_oracle_on_every_class(seed in any::<u64>()) {
        for (class, p) in by_class(seed, plane_side_case) {
            prop_assert_eq!(e_same_side(p), ps(p), "class {}: {:?}", class.name(), p);
            let side = s(oracle::orient3d(p[0].into(), p[1].into(), p[2].into(), p[3].into()));
            prop_assert_eq!(side_of_plane(p[0], p[1], p[2], p[3]), side, "class {}: {:?}", class.name(), p);
        }
    }
}

proptest! {
    // The oracle's 4x4 big-integer determinant dominates the file's runtime.
    #![proptest_config(config(200))]

    #[test]
    fn insphere_matches_oracle_on_every_class(seed in any::<u64>()) {
        for (class, p) in by_class(seed, insphere_case) {
            prop_assert_eq!(e_insphere(p), is(p), "class {}: {:?}", class.name(), p);
        }
    }
}

proptest! {
    #![proptest_config(config(1000))]

    #[test]
    fn orient2d_matches_oracle_on_raw_bits(a in raw2(), b in raw2(), c in raw2()) {
        prop_assert_eq!(e_orient2d([a, b, c]), o2([a, b, c]));
    }

    #[test]
    fn orient3d_matches_oracle_on_raw_bits(a in raw3(), b in raw3(), c in raw3(), d in raw3()) {
        prop_assert_eq!(e_orient3d([a, b, c, d]), o3([a, b, c, d]));
    }

    #[test]
    fn incircle_matches_oracle_on_raw_bits(a in raw2(), b in raw2(), c in raw2(), d in raw2()) {
        prop_assert_eq!(e_incircle([a, b, c, d]), ic([a, b, c, d]));
    }

    #[test]
    fn plane_side_matches_oracle_on_raw_bits(
        x0 in raw3(), x1 in raw3(), x2 in raw3(), p in raw3(), q in raw3()
    ) {
        prop_assert_eq!(e_same_side([x0, x1, x2, p, q]), ps([x0, x1, x2, p, q]));
    }
}

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn insphere_matches_oracle_on_raw_bits(
        a in raw3(), b in raw3(), c in raw3(), d in raw3(), e in raw3()
    ) {
        prop_assert_eq!(e_insphere([a, b, c, d, e]), is([a, b, c, d, e]));
    }
}

// ---------------------------------------------------------- antisymmetry
//
// Each determinant is an alternating function of its points (for incircle and
// insphere: of the lifted points), so every transposition negates the sign.
// A filter that reorders subtractions can break this on its own, even where
// it agrees with the oracle on the original order.

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn transpositions_negate(seed in any::<u64>()) {
        for (class, p) in by_class(seed, orient2d_case) {
            let want = e_orient2d(p);
            for (i, j) in [(0, 1), (0, 2), (1, 2)] {
                prop_assert_eq!(e_orient2d(swapped(p, i, j)), -want, "orient2d {} swap {}{}: {:?}", class.name(), i, j, p);
            }
            prop_assert_eq!(e_orient2d([p[1], p[2], p[0]]), want, "orient2d {} rotation", class.name());
        }
        for (class, p) in by_class(seed, orient3d_case) {
            let want = e_orient3d(p);
            for (i, j) in [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)] {
                prop_assert_eq!(e_orient3d(swapped(p, i, j)), -want, "orient3d {} swap {}{}: {:?}", class.name(), i, j, p);
            }
        }
        for (class, p) in by_class(seed, incircle_case) {
            let want = e_incircle(p);
            for (i, j) in [(0, 1), (0, 2), (1, 2), (0, 3), (2, 3)] {
                prop_assert_eq!(e_incircle(swapped(p, i, j)), -want, "incircle {} swap {}{}: {:?}", class.name(), i, j, p);
            }
        }
        for (class, p) in by_class(seed, insphere_case) {
            let want = e_insphere(p);
            for (i, j) in [(0, 1), (1, 2), (2, 3), (0, 3), (3, 4), (0, 4)] {
                prop_assert_eq!(e_insphere(swapped(p, i, j)), -want, "insphere {} swap {}{}: {:?}", class.name(), i, j, p);
            }
        }
    }
}

// ------------------------------------------------ exact transformations
//
// Scaling every coordinate by 2^k (k chosen so no bit is lost), negating
// them, swapping axes and translating by an exactly representable vector
// change the exact determinant by a known factor, so the sign must follow.

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn power_of_two_scaling_keeps_the_sign(seed in any::<u64>(), pick in any::<u64>()) {
        for (class, p) in by_class(seed, orient2d_case) {
            if let Some(k) = exact_scale_exponent(&flat2(&p), pick) {
                prop_assert_eq!(e_orient2d(scale2(p, k)), e_orient2d(p), "orient2d {} 2^{}: {:?}", class.name(), k, p);
            }
        }
        for (class, p) in by_class(seed, orient3d_case) {
            if let Some(k) = exact_scale_exponent(&flat3(&p), pick) {
                prop_assert_eq!(e_orient3d(scale3(p, k)), e_orient3d(p), "orient3d {} 2^{}: {:?}", class.name(), k, p);
            }
        }
        for (class, p) in by_class(seed, incircle_case) {
            if let Some(k) = exact_scale_exponent(&flat2(&p), pick) {
                prop_assert_eq!(e_incircle(scale2(p, k)), e_incircle(p), "incircle {} 2^{}: {:?}", class.name(), k, p);
            }
        }
        for (class, p) in by_class(seed, insphere_case) {
            if let Some(k) = exact_scale_exponent(&flat3(&p), pick) {
                prop_assert_eq!(e_insphere(scale3(p, k)), e_insphere(p), "insphere {} 2^{}: {:?}", class.name(), k, p);
            }
        }
        for (class, p) in by_class(seed, plane_side_case) {
            if let Some(k) = exact_scale_exponent(&flat3(&p), pick) {
                prop_assert_eq!(e_same_side(scale3(p, k)), e_same_side(p), "same_side {} 2^{}: {:?}", class.name(), k, p);
            }
        }
    }

    #[test]
    fn reflections_and_point_inversion(seed in any::<u64>()) {
        // In 2D, x -> -x is a rotation by pi (orientation kept) and swapping
        // the axes is a reflection (orientation negated). In 3D, x -> -x is a
        // reflection.
        let yx = |v: DVec2| DVec2::new(v.y, v.x);
        for (class, p) in by_class(seed, orient2d_case) {
            let want = e_orient2d(p);
            prop_assert_eq!(e_orient2d(p.map(|v| -v)), want, "orient2d {} negated", class.name());
            prop_assert_eq!(e_orient2d(p.map(yx)), -want, "orient2d {} axes swapped", class.name());
        }
        for (class, p) in by_class(seed, incircle_case) {
            let want = e_incircle(p);
            prop_assert_eq!(e_incircle(p.map(|v| -v)), want, "incircle {} negated", class.name());
            prop_assert_eq!(e_incircle(p.map(yx)), -want, "incircle {} axes swapped", class.name());
        }
        for (class, p) in by_class(seed, orient3d_case) {
            let want = e_orient3d(p);
            prop_assert_eq!(e_orient3d(p.map(|v| -v)), -want, "orient3d {} negated", class.name());
            prop_assert_eq!(e_orient3d(p.map(|v| DVec3::new(v.y, v.z, v.x))), want, "orient3d {} axes rotated", class.name());
        }
        for (class, p) in by_class(seed, insphere_case) {
            let want = e_insphere(p);
            prop_assert_eq!(e_insphere(p.map(|v| -v)), -want, "insphere {} negated", class.name());
            prop_assert_eq!(e_insphere(p.map(|v| DVec3::new(v.z, v.y, v.x))), -want, "insphere {} axes swapped", class.name());
        }
    }

    #[test]
    fn exact_translation_keeps_the_sign(seed in any::<u64>(), pick in any::<u64>()) {
        for (class, p) in by_class(seed, orient2d_case) {
            let t = translation(&flat2(&p), 2, pick);
            if let Some(q) = translate2(p, &t) {
                prop_assert_eq!(e_orient2d(q), e_orient2d(p), "orient2d {} by {:?}: {:?}", class.name(), t, p);
            }
        }
        for (class, p) in by_class(seed, incircle_case) {
            let t = translation(&flat2(&p), 2, pick);
            if let Some(q) = translate2(p, &t) {
                prop_assert_eq!(e_incircle(q), e_incircle(p), "incircle {} by {:?}: {:?}", class.name(), t, p);
            }
        }
        for (class, p) in by_class(seed, orient3d_case) {
            let t = translation(&flat3(&p), 3, pick);
            if let Some(q) = translate3(p, &t) {
                prop_assert_eq!(e_orient3d(q), e_orient3d(p), "orient3d {} by {:?}: {:?}", class.name(), t, p);
            }
        }
        for (class, p) in by_class(seed, insphere_case) {
            let t = translation(&flat3(&p), 3, pick);
            if let Some(q) = translate3(p, &t) {
                prop_assert_eq!(e_insphere(q), e_insphere(p), "insphere {} by {:?}: {:?}", class.name(), t, p);
            }
        }
    }
}

#[test]
fn scaling_helpers_reach_both_ends_exactly() {
    // The widest spans: the smallest subnormal to the top binade and back.
    let tiny = f64::from_bits(1);
    assert_eq!(exact_scale_exponent(&[tiny], 0), Some(0));
    assert_eq!(ldexp(tiny, 2097), 2f64.powi(1023));
    assert_eq!(ldexp(f64::MAX, -2045), f64::from_bits((1 << 53) - 1));
    let k = exact_scale_exponent(&[f64::MAX, 1.0], u64::MAX).unwrap();
    assert!((-1074..=0).contains(&k));
    assert!(ldexp(f64::MAX, k).is_finite() && ldexp(1.0, k) > 0.0);
}

#[test]
fn exact_translation_is_often_checked() {
    // Guards the property above against silently skipping every case.
    let mut checked = 0;
    for seed in 0..200u64 {
        for (_, p) in by_class(seed, orient3d_case) {
            let t = translation(&flat3(&p), 3, seed.wrapping_mul(31));
            checked += usize::from(translate3(p, &t).is_some());
        }
    }
    assert!(
        checked > 300,
        "only {checked} of 1200 translations were exact"
    );
}

// ------------------------------------------------------------ plane side

proptest! {
    #![proptest_config(config(400))]

    #[test]
    fn plane_side_is_consistent_with_orient3d(seed in any::<u64>()) {
        for (class, [x0, x1, x2, p, q]) in by_class(seed, plane_side_case) {
            let (sp, sq) = (orient3d(x0, x1, x2, p), orient3d(x0, x1, x2, q));
            prop_assert_eq!(side_of_plane(x0, x1, x2, p), sp);
            let want = match sp.product(sq) {
                Sign::Positive => SideRelation::Same,
                Sign::Negative => SideRelation::Opposite,
                Sign::Zero => SideRelation::OnPlane,
            };
            let got = same_side(x0, x1, x2, p, q);
            prop_assert_eq!(got, want, "class {}", class.name());
            prop_assert_eq!(same_side(x0, x1, x2, q, p), got, "class {}: p and q swapped", class.name());
            // Reversing the triangle flips both sides, not their relation.
            prop_assert_eq!(same_side(x1, x0, x2, p, q), got, "class {}: triangle reversed", class.name());
            prop_assert_eq!(got.as_i8(), sp.as_i8() * sq.as_i8());
        }
    }
}

// -------------------------------------------------------- try_ variants

fn bad_value(pick: u8) -> f64 {
    [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -f64::NAN][usize::from(pick % 4)]
}

fn poison2(p: &mut [DVec2], point: usize, axis: usize, v: f64) {
    p[point][axis] = v;
}
fn poison3(p: &mut [DVec3], point: usize, axis: usize, v: f64) {
    p[point][axis] = v;
}

proptest! {
    #![proptest_config(config(500))]

    #[test]
    fn try_variants_name_the_first_non_finite_argument(
        seed in any::<u64>(),
        first in 0usize..5,
        second in 0usize..5,
        axes in (0usize..3, 0usize..3),
        bad in (any::<u8>(), any::<u8>()),
        poison_second in any::<bool>(),
    ) {
        let names = ["a", "b", "c", "d", "e"];
        let plane_names = ["x0", "x1", "x2", "p", "q"];
        let class = InputClass::ALL[(seed % 6) as usize];
        let mut rng = SplitMix64::new(seed);
        // Poisons point `first` (and maybe `second`); the error names the
        // lower index of the two.
        let err = |n: usize, names: &[&'static str]| {
            let f = first % n;
            let lowest = if poison_second { f.min(second % n) } else { f };
            Some(InputError::NonFinite { argument: names[lowest] })
        };

        let mut p = orient2d_case(class, &mut rng);
        poison2(&mut p, first % 3, axes.0 % 2, bad_value(bad.0));
        if poison_second { poison2(&mut p, second % 3, axes.1 % 2, bad_value(bad.1)); }
        prop_assert_eq!(try_orient2d(p[0], p[1], p[2]).err(), err(3, &names));
        prop_assert_eq!(e_orient2d(p), Sign::Zero);

        let mut p = orient3d_case(class, &mut rng);
        poison3(&mut p, first % 4, axes.0, bad_value(bad.0));
        if poison_second { poison3(&mut p, second % 4, axes.1, bad_value(bad.1)); }
        prop_assert_eq!(try_orient3d(p[0], p[1], p[2], p[3]).err(), err(4, &names));
        prop_assert_eq!(try_side_of_plane(p[0], p[1], p[2], p[3]).err(), err(4, &plane_names));
        prop_assert_eq!(e_orient3d(p), Sign::Zero);
        prop_assert_eq!(side_of_plane(p[0], p[1], p[2], p[3]), Sign::Zero);

        let mut p = incircle_case(class, &mut rng);
        poison2(&mut p, first % 4, axes.0 % 2, bad_value(bad.0));
        if poison_second { poison2(&mut p, second % 4, axes.1 % 2, bad_value(bad.1)); }
        prop_assert_eq!(try_incircle(p[0], p[1], p[2], p[3]).err(), err(4, &names));
        prop_assert_eq!(e_incircle(p), Sign::Zero);

        let mut p = insphere_case(class, &mut rng);
        poison3(&mut p, first, axes.0, bad_value(bad.0));
        if poison_second { poison3(&mut p, second, axes.1, bad_value(bad.1)); }
        prop_assert_eq!(try_insphere(p[0], p[1], p[2], p[3], p[4]).err(), err(5, &names));
        prop_assert_eq!(e_insphere(p), Sign::Zero);

        let mut p = plane_side_case(class, &mut rng);
        poison3(&mut p, first, axes.0, bad_value(bad.0));
        if poison_second { poison3(&mut p, second, axes.1, bad_value(bad.1)); }
        prop_assert_eq!(try_same_side(p[0], p[1], p[2], p[3], p[4]).err(), err(5, &plane_names));
        prop_assert_eq!(e_same_side(p), SideRelation::OnPlane);
    }

    #[test]
    fn try_variants_agree_on_finite_input(seed in any::<u64>()) {
        for (_, p) in by_class(seed, orient2d_case) {
            prop_assert_eq!(try_orient2d(p[0], p[1], p[2]), Ok(e_orient2d(p)));
        }
        for (_, p) in by_class(seed, orient3d_case) {
            prop_assert_eq!(try_orient3d(p[0], p[1], p[2], p[3]), Ok(e_orient3d(p)));
            prop_assert_eq!(try_side_of_plane(p[0], p[1], p[2], p[3]), Ok(e_orient3d(p)));
        }
        for (_, p) in by_class(seed, incircle_case) {
            prop_assert_eq!(try_incircle(p[0], p[1], p[2], p[3]), Ok(e_incircle(p)));
        }
        for (_, p) in by_class(seed, insphere_case) {
            prop_assert_eq!(try_insphere(p[0], p[1], p[2], p[3], p[4]), Ok(e_insphere(p)));
        }
        for (_, p) in by_class(seed, plane_side_case) {
            prop_assert_eq!(try_same_side(p[0], p[1], p[2], p[3], p[4]), Ok(e_same_side(p)));
        }
    }
}

// ------------------------------------------------------------ f32 input
//
// An f32 widens to f64 exactly, so an f32 call must give the answer of the
// widened f64 call and of the oracle on the widened values.

/// Any finite f32, mostly raw bit patterns, sometimes small integers.
fn f32_coord() -> impl Strategy<Value = f32> {
    prop_oneof![
        3 => any::<u32>().prop_map(|b| {
            let v = f32::from_bits(b);
            // Clearing the lowest exponent bit makes an inf or NaN pattern finite.
            if v.is_finite() { v } else { f32::from_bits(b & !(1 << 23)) }
        }),
        1 => (-3i8..=3).prop_map(f32::from),
    ]
}

/// A hard f64 case rounded to f32: degenerate ones stay exactly degenerate
/// (their coordinates are short dyadics), near-degenerate ones stay close.
fn f32_case<const N: usize, const D: usize>(
    class_pick: u64,
    seed: u64,
    generate: fn(InputClass, &mut SplitMix64) -> [[f64; D]; N],
) -> [[f32; D]; N] {
    // Tiny, huge and mixed cases would leave the f32 range when rounded.
    let class = [
        InputClass::Uniform,
        InputClass::NearDegenerate,
        InputClass::Degenerate,
    ][(class_pick % 3) as usize];
    generate(class, &mut SplitMix64::new(seed)).map(|p| p.map(|x| x as f32))
}

fn widen2(p: [f32; 2]) -> [f64; 2] {
    p.map(f64::from)
}
fn widen3(p: [f32; 3]) -> [f64; 3] {
    p.map(f64::from)
}

proptest! {
    #![proptest_config(config(500))]

    #[test]
    fn f32_inputs_equal_their_exact_widening(
        c2 in prop::array::uniform8(f32_coord()),
        c3 in prop::array::uniform15(f32_coord()),
        seed in any::<u64>(),
        class_pick in any::<u64>(),
        hard in any::<bool>(),
    ) {
        let (p2, p3): ([[f32; 2]; 4], [[f32; 3]; 5]) = if hard {
            (
                f32_case(class_pick, seed, |c, r| incircle_case(c, r).map(|v| v.to_array())),
                f32_case(class_pick, seed, |c, r| insphere_case(c, r).map(|v| v.to_array())),
            )
        } else {
            (
                core::array::from_fn(|i| [c2[2 * i], c2[2 * i + 1]]),
                core::array::from_fn(|i| [c3[3 * i], c3[3 * i + 1], c3[3 * i + 2]]),
            )
        };
        let [a, b, c, d] = p2;
        let [wa, wb, wc, wd] = p2.map(widen2);
        let (va, vb, vc, vd) = (Vec2::from(a), Vec2::from(b), Vec2::from(c), Vec2::from(d));

        let want = s(oracle::orient2d(wa, wb, wc));
        prop_assert_eq!(orient2d(va, vb, vc), want);
        prop_assert_eq!(orient2d(a, b, c), want);
        prop_assert_eq!(orient2d(DVec2::from(wa), DVec2::from(wb), DVec2::from(wc)), want);

        let want = s(oracle::incircle(wa, wb, wc, wd));
        prop_assert_eq!(incircle(va, vb, vc, vd), want);
        prop_assert_eq!(incircle(a, b, c, d), want);

        let [a, b, c, d, e] = p3;
        let [wa, wb, wc, wd, we] = p3.map(widen3);
        let v = p3.map(Vec3::from);
        let va3 = p3.map(Vec3A::from);

        let want = s(oracle::orient3d(wa, wb, wc, wd));
        prop_assert_eq!(orient3d(v[0], v[1], v[2], v[3]), want);
        prop_assert_eq!(orient3d(va3[0], va3[1], va3[2], va3[3]), want);
        prop_assert_eq!(orient3d(a, b, c, d), want);
        prop_assert_eq!(side_of_plane(va3[0], v[1], c, DVec3::from(wd)), want);

        let want = s(oracle::insphere(wa, wb, wc, wd, we));
        prop_assert_eq!(insphere(v[0], v[1], v[2], v[3], v[4]), want);
        prop_assert_eq!(insphere(va3[0], va3[1], va3[2], va3[3], va3[4]), want);
        prop_assert_eq!(insphere(a, b, c, d, e), want);

        let want = relation(oracle::plane_side(wa, wb, wc, wd, we));
        prop_assert_eq!(same_side(v[0], va3[1], c, d, DVec3::from(we)), want);
    }
}
