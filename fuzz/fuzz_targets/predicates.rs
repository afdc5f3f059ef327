//! Every predicate against the exact oracle, on fuzzer-chosen `f64` inputs.
//!
//! The first byte picks the predicate and how its input is built:
//! - raw: the crate's `Arbitrary` input types, every finite bit pattern;
//! - raw plus edits, or a `testing` generator's case plus edits: the edits (ulp
//!   nudges, shared coordinates, points on the line or plane of others,
//!   power-of-two scalings, tiny offsets) make the configuration nearly or
//!   exactly degenerate, so the fuzzer reaches the exact stages and not only
//!   the floating-point filter, which answers almost every raw input;
//! - the same with edits that may plant a NaN or an infinity, which the `try_`
//!   variants must reject by argument name and the plain ones answer `Zero`.
//!
//! A failing input panics with the coordinates' bit patterns, ready to be
//! copied into tests/regressions.rs.
#![no_main]

use arbitrary::{Arbitrary, Result, Unstructured};
use exactray::testing::{self, InputClass, SplitMix64, step_ulps};
use exactray::testing::{
    IncircleInput, InsphereInput, Orient2dInput, Orient3dInput, PlaneSideInput,
    finite_f64_from_bits,
};
use exactray::{InputError, Sign, predicates::SideRelation};
use exactray_oracle::oracle;
use glam::{DVec2, DVec3};
use libfuzzer_sys::fuzz_target;

#[derive(Clone, Copy, Debug)]
enum Pred {
    Orient2d,
    Orient3d,
    Incircle,
    Insphere,
    SameSide,
}

impl Pred {
    const ALL: [Pred; 5] = [
        Pred::Orient2d,
        Pred::Orient3d,
        Pred::Incircle,
        Pred::Insphere,
        Pred::SameSide,
    ];

    fn dims(self) -> usize {
        match self {
            Pred::Orient2d | Pred::Incircle => 2,
            _ => 3,
        }
    }

    fn points(self) -> usize {
        match self {
            Pred::Orient2d => 3,
            Pred::Orient3d | Pred::Incircle => 4,
            Pred::Insphere | Pred::SameSide => 5,
        }
    }

    fn names(self) -> [&'static str; 5] {
        match self {
            Pred::SameSide => ["x0", "x1", "x2", "p", "q"],
            _ => ["a", "b", "c", "d", "e"],
        }
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Mode {
    Raw,
    RawEdited,
    HardEdited,
    NonFinite,
}

fuzz_target!(|data: &[u8]| {
    // Running out of bytes only ends the case early.
    let _ = run(data);
});

fn run(data: &[u8]) -> Result<()> {
    let mut u = Unstructured::new(data);
    let selector = u8::arbitrary(&mut u)?;
    let pred = Pred::ALL[usize::from(selector % 5)];
    let mode = [
        Mode::Raw,
        Mode::RawEdited,
        Mode::HardEdited,
        Mode::NonFinite,
    ][usize::from(selector / 5 % 4)];

    let mut c: Vec<f64> = if mode == Mode::Raw || mode == Mode::RawEdited {
        raw(pred, &mut u)?
    } else {
        let class = InputClass::ALL[usize::from(u8::arbitrary(&mut u)? % 6)];
        let mut rng = SplitMix64::new(u64::arbitrary(&mut u)?);
        hard(pred, class, &mut rng)
    };
    if mode != Mode::Raw {
        let edits = u8::arbitrary(&mut u)? % 8;
        for _ in 0..edits {
            edit(&mut c, pred, mode == Mode::NonFinite, &mut u)?;
        }
    }
    check(pred, &c);
    Ok(())
}

fn raw(pred: Pred, u: &mut Unstructured<'_>) -> Result<Vec<f64>> {
    Ok(match pred {
        Pred::Orient2d => flat2(&Orient2dInput::arbitrary(u)?.to_array()),
        Pred::Orient3d => flat3(&Orient3dInput::arbitrary(u)?.to_array()),
        Pred::Incircle => flat2(&IncircleInput::arbitrary(u)?.to_array()),
        Pred::Insphere => flat3(&InsphereInput::arbitrary(u)?.to_array()),
        Pred::SameSide => flat3(&PlaneSideInput::arbitrary(u)?.to_array()),
    })
}

fn hard(pred: Pred, class: InputClass, rng: &mut SplitMix64) -> Vec<f64> {
    match pred {
        Pred::Orient2d => flat2(&testing::orient2d_case(class, rng)),
        Pred::Orient3d => flat3(&testing::orient3d_case(class, rng)),
        Pred::Incircle => flat2(&testing::incircle_case(class, rng)),
        Pred::Insphere => flat3(&testing::insphere_case(class, rng)),
        Pred::SameSide => flat3(&testing::plane_side_case(class, rng)),
    }
}

fn flat2(p: &[DVec2]) -> Vec<f64> {
    p.iter().flat_map(|v| v.to_array()).collect()
}

fn flat3(p: &[DVec3]) -> Vec<f64> {
    p.iter().flat_map(|v| v.to_array()).collect()
}

/// `2^k` as an exact factor pair, so `x * a * b` rounds once.
fn pow2_pair(k: i32) -> (f64, f64) {
    let p = |e: i32| f64::from_bits(((e.clamp(-1022, 1023) + 1023) as u64) << 52);
    (p(k / 2), p(k - k / 2))
}

/// One structural edit of the coordinates `c` (points of `pred.dims()`).
fn edit(c: &mut [f64], pred: Pred, non_finite: bool, u: &mut Unstructured<'_>) -> Result<()> {
    let (d, n) = (pred.dims(), pred.points());
    let i = usize::from(u8::arbitrary(u)?) % n;
    let j = usize::from(u8::arbitrary(u)?) % n;
    let k = usize::from(u8::arbitrary(u)?) % n;
    let axis = usize::from(u8::arbitrary(u)?) % d;
    match u8::arbitrary(u)? % 10 {
        0 => {
            // A few ulps: the classic way to leave a degenerate set barely.
            let steps = i64::from(i8::arbitrary(u)? % 5);
            c[i * d + axis] = step_ulps(c[i * d + axis], steps);
        }
        1 => c[j * d + axis] = c[i * d + axis],
        2 => {
            // Point j := point i, then a tiny offset on one axis.
            for a in 0..d {
                c[j * d + a] = c[i * d + a];
            }
            let m = f64::from(i16::arbitrary(u)?);
            let (s, t) = pow2_pair(-i32::from(u16::arbitrary(u)? % 1100));
            c[j * d + axis] += m * s * t;
        }
        3 => {
            // Point j := i + w (k - i) with a short dyadic weight: on the line
            // (plane, when repeated) of the others, exactly when no rounding
            // happens, nearly otherwise.
            let w = f64::from(i8::arbitrary(u)?) / 16.0;
            for a in 0..d {
                c[j * d + a] = c[i * d + a] + w * (c[k * d + a] - c[i * d + a]);
            }
        }
        4 => {
            // Every coordinate times 2^e: exact unless it leaves the range.
            let (s, t) = pow2_pair(i32::from(i16::arbitrary(u)? % 1100));
            c.iter_mut().for_each(|x| *x = *x * s * t);
        }
        5 => {
            // One point scaled: magnitudes far apart in one case.
            let (s, t) = pow2_pair(i32::from(i16::arbitrary(u)? % 1100));
            c[j * d..(j + 1) * d]
                .iter_mut()
                .for_each(|x| *x = *x * s * t);
        }
        6 => c[i * d + axis] = finite_f64_from_bits(u64::arbitrary(u)?),
        7 => {
            // A subnormal or zero: the smallest grain there is.
            c[i * d + axis] = f64::from(i8::arbitrary(u)?) * f64::from_bits(1);
        }
        8 => {
            // The same translation of every point, rounded per coordinate.
            let t = finite_f64_from_bits(u64::arbitrary(u)?);
            for p in 0..n {
                c[p * d + axis] += t;
            }
        }
        _ => {
            if non_finite {
                c[i * d + axis] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY][j % 3];
            } else {
                c[i * d + axis] = -c[i * d + axis];
            }
        }
    }
    Ok(())
}

fn bits(c: &[f64]) -> Vec<String> {
    c.iter().map(|x| format!("{:#018x}", x.to_bits())).collect()
}

fn check(pred: Pred, c: &[f64]) {
    let d = pred.dims();
    let first_bad =
        (0..pred.points()).find(|&i| c[i * d..(i + 1) * d].iter().any(|x| !x.is_finite()));
    let expect_err = first_bad.map(|i| InputError::NonFinite {
        argument: pred.names()[i],
    });
    let p2 = |i: usize| DVec2::new(c[2 * i], c[2 * i + 1]);
    let p3 = |i: usize| DVec3::new(c[3 * i], c[3 * i + 1], c[3 * i + 2]);
    let a2 = |i: usize| [c[2 * i], c[2 * i + 1]];
    let a3 = |i: usize| [c[3 * i], c[3 * i + 1], c[3 * i + 2]];
    let ctx = || format!("{pred:?} bits {:?} values {c:?}", bits(c));

    match pred {
        Pred::Orient2d => {
            let input = Orient2dInput {
                a: p2(0),
                b: p2(1),
                c: p2(2),
            };
            if let Some(e) = expect_err {
                assert_eq!(input.try_eval(), Err(e), "{}", ctx());
                assert_eq!(input.eval(), Sign::Zero, "{}", ctx());
                return;
            }
            let want = Sign::from_i8(oracle::orient2d(a2(0), a2(1), a2(2)));
            assert_eq!(input.try_eval(), Ok(want), "{}", ctx());
            // The batch variant, over enough copies to fill its blocks.
            let mut out = [Sign::Zero; 9];
            exactray::predicates::orient2d_many(&[[p2(0), p2(1), p2(2)]; 9], &mut out);
            assert_eq!(out, [want; 9], "batch: {}", ctx());
            assert_eq!(
                exactray::predicates::orient2d(p2(1), p2(0), p2(2)),
                -want,
                "swapped: {}",
                ctx()
            );
            assert_eq!(
                exactray::predicates::orient2d(p2(1), p2(2), p2(0)),
                want,
                "rotated: {}",
                ctx()
            );
        }
        Pred::Orient3d => {
            let input = Orient3dInput {
                a: p3(0),
                b: p3(1),
                c: p3(2),
                d: p3(3),
            };
            if let Some(e) = expect_err {
                assert_eq!(input.try_eval(), Err(e), "{}", ctx());
                assert_eq!(input.eval(), Sign::Zero, "{}", ctx());
                return;
            }
            let want = Sign::from_i8(oracle::orient3d(a3(0), a3(1), a3(2), a3(3)));
            assert_eq!(input.try_eval(), Ok(want), "{}", ctx());
            let mut out = [Sign::Zero; 9];
            exactray::predicates::orient3d_many(&[[p3(0), p3(1), p3(2), p3(3)]; 9], &mut out);
            assert_eq!(out, [want; 9], "batch: {}", ctx());
            assert_eq!(
                exactray::predicates::orient3d(p3(3), p3(1), p3(2), p3(0)),
                -want,
                "swapped: {}",
                ctx()
            );
        }
        Pred::Incircle => {
            let input = IncircleInput {
                a: p2(0),
                b: p2(1),
                c: p2(2),
                d: p2(3),
            };
            if let Some(e) = expect_err {
                assert_eq!(input.try_eval(), Err(e), "{}", ctx());
                assert_eq!(input.eval(), Sign::Zero, "{}", ctx());
                return;
            }
            let want = Sign::from_i8(oracle::incircle(a2(0), a2(1), a2(2), a2(3)));
            assert_eq!(input.try_eval(), Ok(want), "{}", ctx());
            // The lifted determinant alternates in all four points.
            assert_eq!(
                exactray::predicates::incircle(p2(3), p2(1), p2(2), p2(0)),
                -want,
                "swapped: {}",
                ctx()
            );
        }
        Pred::Insphere => {
            let input = InsphereInput {
                a: p3(0),
                b: p3(1),
                c: p3(2),
                d: p3(3),
                e: p3(4),
            };
            if let Some(e) = expect_err {
                assert_eq!(input.try_eval(), Err(e), "{}", ctx());
                assert_eq!(input.eval(), Sign::Zero, "{}", ctx());
                return;
            }
            let want = Sign::from_i8(oracle::insphere(a3(0), a3(1), a3(2), a3(3), a3(4)));
            assert_eq!(input.try_eval(), Ok(want), "{}", ctx());
            assert_eq!(
                exactray::predicates::insphere(p3(4), p3(1), p3(2), p3(3), p3(0)),
                -want,
                "swapped: {}",
                ctx()
            );
        }
        Pred::SameSide => {
            let input = PlaneSideInput {
                x0: p3(0),
                x1: p3(1),
                x2: p3(2),
                p: p3(3),
                q: p3(4),
            };
            if let Some(e) = expect_err {
                assert_eq!(input.try_eval(), Err(e), "{}", ctx());
                assert_eq!(input.eval(), SideRelation::OnPlane, "{}", ctx());
                return;
            }
            let sp = Sign::from_i8(oracle::orient3d(a3(0), a3(1), a3(2), a3(3)));
            let sq = Sign::from_i8(oracle::orient3d(a3(0), a3(1), a3(2), a3(4)));
            let want = match sp.product(sq) {
                Sign::Positive => SideRelation::Same,
                Sign::Negative => SideRelation::Opposite,
                Sign::Zero => SideRelation::OnPlane,
            };
            assert_eq!(input.try_eval(), Ok(want), "{}", ctx());
            assert_eq!(input.sides(), (sp, sq), "{}", ctx());
        }
    }
}
