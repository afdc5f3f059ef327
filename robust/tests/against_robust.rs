//! The drop-in against the `robust` crate it replaces (`robust_ref`, the
//! registry's 1.2.0) and against the exact oracle (`exactray-oracle`, big
//! integers):
//! - ordinary inputs: the same sign as `robust` everywhere and, almost
//!   everywhere, the same value to the bit;
//! - hard inputs (near-degenerate, degenerate, tiny, huge and mixed
//!   configurations of `exactray::testing`) moved to every scale
//!   `2^-1000..2^1000`, and the largest finite values: the exact sign, and
//!   the value within `2^-39` of the exact determinant where that is a
//!   normal number (the crate docs' rule elsewhere);
//! - the interface: the same derives and generic bounds as `robust`'s.

use exactray::testing::{
    InputClass, SplitMix64, incircle_case, insphere_case, orient2d_case, orient3d_case,
};
use exactray_oracle::oracle::{
    self, ExactValue, incircle_value, insphere_value, orient2d_value, orient3d_value, ratio_to_f64,
    within_units,
};
use num_bigint::BigInt;
use robust::{Coord, Coord3D};

/// One case of each predicate: the drop-in's value, robust's value and the
/// exact determinant in Shewchuk's convention.
type Answers = (f64, f64, ExactValue);

fn c2([x, y]: [f64; 2]) -> (Coord<f64>, robust_ref::Coord<f64>) {
    (Coord { x, y }, robust_ref::Coord { x, y })
}

fn c3([x, y, z]: [f64; 3]) -> (Coord3D<f64>, robust_ref::Coord3D<f64>) {
    (Coord3D { x, y, z }, robust_ref::Coord3D { x, y, z })
}

fn negated((n, e): ExactValue) -> ExactValue {
    (-n, e)
}

fn on_orient2d(p: [[f64; 2]; 3]) -> Answers {
    let [a, b, c] = p.map(c2);
    (
        robust::orient2d(a.0, b.0, c.0),
        robust_ref::orient2d(a.1, b.1, c.1),
        orient2d_value(p[0], p[1], p[2]),
    )
}

fn on_orient3d(p: [[f64; 3]; 4]) -> Answers {
    let [a, b, c, d] = p.map(c3);
    (
        robust::orient3d(a.0, b.0, c.0, d.0),
        robust_ref::orient3d(a.1, b.1, c.1, d.1),
        // The oracle's is CGAL's orientation, Shewchuk's negated.
        negated(orient3d_value(p[0], p[1], p[2], p[3])),
    )
}

fn on_incircle(p: [[f64; 2]; 4]) -> Answers {
    let [a, b, c, d] = p.map(c2);
    (
        robust::incircle(a.0, b.0, c.0, d.0),
        robust_ref::incircle(a.1, b.1, c.1, d.1),
        incircle_value(p[0], p[1], p[2], p[3]),
    )
}

fn on_insphere(p: [[f64; 3]; 5]) -> Answers {
    let [a, b, c, d, e] = p.map(c3);
    (
        robust::insphere(a.0, b.0, c.0, d.0, e.0),
        robust_ref::insphere(a.1, b.1, c.1, d.1, e.1),
        // The oracle's is CGAL's oriented sphere, Shewchuk's negated.
        negated(insphere_value(p[0], p[1], p[2], p[3], p[4])),
    )
}

/// Whether `v` is the value the crate docs promise for the exact
/// determinant `n * 2^e`: the exact sign; within `2^-39` (`2^14` units of
/// `2^-53`) of it where it is a normal number; within two subnormal steps of
/// it below that, and never zero unless it is; an infinity beyond
/// `f64::MAX`.
fn promised(v: f64, (n, e): &ExactValue) -> bool {
    let (num, den) = if *e >= 0 {
        (n << *e as usize, BigInt::from(1))
    } else {
        (n.clone(), BigInt::from(1) << (-*e) as usize)
    };
    let nearest = ratio_to_f64(&num, &den);
    if nearest == 0.0 && n.bits() == 0 {
        return v.to_bits() == 0.0f64.to_bits();
    }
    if nearest.is_infinite() {
        return v == nearest;
    }
    if nearest.abs() < f64::MIN_POSITIVE {
        let step = f64::from_bits(1);
        let same_sign = (v > 0.0) == (n.sign() == num_bigint::Sign::Plus);
        return v != 0.0 && same_sign && (v - nearest).abs() <= 2.0 * step;
    }
    within_units(v, &num, &den, 1 << 14)
}

fn assert_promised((ours, _, exact): &Answers, what: &str) {
    assert!(
        promised(*ours, exact),
        "{what}: returned {ours:e}, exact {:?}",
        exact
    );
}

/// Coordinates uniform in `[-1000, 1000)`: robust is exact here, and the
/// drop-in agrees with it on every sign and, almost everywhere, to the bit.
#[test]
fn same_as_robust_on_ordinary_inputs() {
    let mut rng = SplitMix64::new(1_2_0);
    let mut coordinate = move || 2000.0 * rng.next_f64() - 1000.0;
    let (cases, mut identical) = (5_000, 0);
    for _ in 0..cases {
        let p2: [[f64; 2]; 4] = core::array::from_fn(|_| [coordinate(), coordinate()]);
        let p3: [[f64; 3]; 5] =
            core::array::from_fn(|_| [coordinate(), coordinate(), coordinate()]);
        for answers in [
            on_orient2d([p2[0], p2[1], p2[2]]),
            on_incircle(p2),
            on_orient3d([p3[0], p3[1], p3[2], p3[3]]),
            on_insphere(p3),
        ] {
            let (ours, theirs, _) = answers;
            assert_eq!(ours > 0.0, theirs > 0.0, "{p2:?} {p3:?}");
            assert_eq!(ours < 0.0, theirs < 0.0, "{p2:?} {p3:?}");
            assert_promised(&answers, "uniform");
            identical += usize::from(ours.to_bits() == theirs.to_bits());
        }
    }
    // 98.9% with this seed; the rest are where robust's first stage is
    // not within 2^-40 of itself.
    assert!(identical * 100 >= 4 * cases * 97, "{identical}");
}

/// Every hard class of `exactray::testing`, moved by `2^k` for `k` across
/// `-1000..=1000` (each predicate's points scaled together, so the
/// configuration keeps its shape): the exact sign and the promised value on
/// every case; robust's wrong signs are counted.
#[test]
fn exact_on_hard_inputs_at_every_scale() {
    let mut robust_wrong = 0;
    let mut cases = 0;
    for class in InputClass::ALL {
        let mut rng = SplitMix64::for_inputs("robust-drop-in", class.name());
        for i in 0..1_200 {
            let k = (i % 201 - 100) * 10;
            // Scaled by 2^k where every coordinate stays finite.
            let scaled = |v: f64| v * 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
            let moved = |p: &[f64]| p.iter().all(|&v| scaled(v).is_finite());
            let at = |v: f64, p: &[f64]| if moved(p) { scaled(v) } else { v };
            let o2 = orient2d_case(class, &mut rng).map(|p| p.to_array());
            let ic = incircle_case(class, &mut rng).map(|p| p.to_array());
            let o3 = orient3d_case(class, &mut rng).map(|p| p.to_array());
            let is = insphere_case(class, &mut rng).map(|p| p.to_array());
            let (f2, fc) = (o2.concat(), ic.concat());
            let (f3, fs) = (o3.concat(), is.concat());
            for answers in [
                on_orient2d(o2.map(|p| p.map(|v| at(v, &f2)))),
                on_incircle(ic.map(|p| p.map(|v| at(v, &fc)))),
                on_orient3d(o3.map(|p| p.map(|v| at(v, &f3)))),
                on_insphere(is.map(|p| p.map(|v| at(v, &fs)))),
            ] {
                assert_promised(&answers, class.name());
                let exact_sign = answers.2.0.sign();
                let theirs = answers.1;
                let theirs_sign = theirs.partial_cmp(&0.0).map(|o| o as i8);
                let exact = match exact_sign {
                    num_bigint::Sign::Plus => 1,
                    num_bigint::Sign::Minus => -1,
                    num_bigint::Sign::NoSign => 0,
                };
                robust_wrong += usize::from(theirs_sign != Some(exact));
                cases += 1;
            }
        }
    }
    println!("robust 1.2.0 wrong on {robust_wrong} of {cases} hard cases");
    assert!(robust_wrong > 0);
}

/// The largest finite values and their neighbours, where every product
/// and most differences overflow: the exact sign and the promised value.
#[test]
fn largest_values() {
    let m = f64::MAX;
    let values = [m, -m, m / 2.0, -m / 3.0, 0.0, 1.0, f64::MIN_POSITIVE, 1e300];
    let mut rng = SplitMix64::new(7);
    let mut pick = || values[(rng.next_u64() % values.len() as u64) as usize];
    for _ in 0..2_000 {
        let p2: [[f64; 2]; 4] = core::array::from_fn(|_| [pick(), pick()]);
        let p3: [[f64; 3]; 5] = core::array::from_fn(|_| [pick(), pick(), pick()]);
        assert_promised(&on_orient2d([p2[0], p2[1], p2[2]]), "orient2d");
        assert_promised(&on_incircle(p2), "incircle");
        assert_promised(&on_orient3d([p3[0], p3[1], p3[2], p3[3]]), "orient3d");
        assert_promised(&on_insphere(p3), "insphere");
    }
}

/// Where robust's products underflow it answers "collinear"; the drop-in
/// answers the exact sign, with the determinant's value rounded.
#[test]
fn underflow_robust_gets_wrong() {
    let (a, b, c) = ([0.0, 0.0], [1e-200, 0.0], [0.0, 1e-200]);
    let (ours, theirs, exact) = on_orient2d([a, b, c]);
    assert_eq!(theirs, 0.0);
    assert_eq!(oracle::orient2d(a, b, c), 1);
    assert!(ours > 0.0);
    assert!(promised(ours, &exact));
    // 1e-170 * 1e-170 is below the smallest subnormal: that subnormal.
    let ours = robust::orient2d(
        Coord { x: 0.0, y: 0.0 },
        Coord { x: 1e-170, y: 0.0 },
        Coord { x: 0.0, y: 1e-170 },
    );
    assert_eq!(ours, f64::from_bits(1));
}

/// An exact zero is `+0.0`, where robust may return `-0.0`.
#[test]
fn zero_is_positive_zero() {
    let (ours, theirs, exact) = on_orient2d([[0.0, 0.0], [1.0, -1.0], [0.0, 0.0]]);
    assert_eq!(exact.0.bits(), 0);
    assert_eq!(theirs.to_bits(), (-0.0f64).to_bits());
    assert_eq!(ours.to_bits(), 0.0f64.to_bits());
}

/// robust's derives and bounds: the types are `Copy`, `Clone`, `Debug`
/// and `PartialEq`, generic over `T: Into<f64>`, and the functions take
/// `f32` and integer points; the `Debug` output is robust's.
#[test]
fn interface_is_robusts() {
    let p = Coord { x: 1.5f32, y: -2.0 };
    let q = p;
    assert_eq!(p, q.clone());
    assert_eq!(
        format!("{p:?}"),
        format!("{:?}", robust_ref::Coord { x: 1.5f32, y: -2.0 })
    );
    let t = Coord3D { x: 1u8, y: 2, z: 3 };
    assert_eq!(
        format!("{t:?}"),
        format!("{:?}", robust_ref::Coord3D { x: 1u8, y: 2, z: 3 })
    );
    let i = |x: i32, y: i32| Coord { x, y };
    assert!(robust::orient2d(i(0, 0), i(1, 0), i(0, 1)) > 0.0);
    assert_eq!(robust::incircle(i(1, 0), i(0, 1), i(-1, 0), i(0, -1)), 0.0);
    let f = |x: f32, y: f32, z: f32| Coord3D { x, y, z };
    let (a, b, c) = (f(0.0, 0.0, 0.0), f(1.0, 0.0, 0.0), f(0.0, 1.0, 0.0));
    assert_eq!(robust::orient3d(a, b, c, f(0.0, 0.0, 1.0)), -1.0);
    let d = f(0.0, 0.0, -1.0);
    assert!(robust::insphere(a, b, c, d, f(0.25, 0.25, -0.25)) > 0.0);
    let as_pointer: fn(Coord<f64>, Coord<f64>, Coord<f64>) -> f64 = robust::orient2d;
    let o = Coord { x: 0.0, y: 0.0 };
    assert_eq!(
        as_pointer(o, Coord { x: 2.0, y: 0.0 }, Coord { x: 0.0, y: 3.0 }),
        6.0
    );
}
