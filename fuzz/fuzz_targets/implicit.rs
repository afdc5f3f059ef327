//! The predicates on constructed points against the exact oracle
//! (`exactray_oracle::implicit_oracle`), on fuzzer-chosen inputs.
//!
//! The first byte picks the predicate (`orient3d_implicit`,
//! `orient2d_implicit`, `orient2d_projected`, `cmp_on_axis`,
//! `cmp_on_axis_2d`, `cmp_along_line`, `cmp_along_line_2d`) and the mode:
//! - raw: a pool of points from raw bit patterns (every finite `f64`);
//! - hard: a pool from the `testing` generators' cases of an input class
//!   (points on planes and lines, coinciding constructions, tiny, huge and
//!   mixed magnitudes), then edits (ulp nudges, copied coordinates, powers
//!   of two on everything or on one axis, raw bit patterns);
//! - the same with edits that may plant a NaN or an infinity.
//!
//! Each argument is then an explicit point of the pool or a construction on
//! pool points (`Lpi`: five of them, `Tpi`: nine, `Ssi`: four), so that
//! arguments share inputs and meet at exact degeneracies. A construction
//! the crate refuses must be one the oracle finds degenerate (or have a
//! non-finite input); a `try_` form must name a non-finite argument, and
//! the plain form answer `Zero` (`Equal`) for it.
//!
//! A failing input panics with the pool's bit patterns.
#![no_main]

use arbitrary::{Arbitrary, Result, Unstructured};
use core::cmp::Ordering;
use exactray::predicates::{self as p, AnyPoint2, AnyPoint3, Axis, Axis2, Lpi, Ssi, Tpi};
use exactray::testing::{
    InputClass, SplitMix64, finite_f64_from_bits, orient2d_ssi_case, orient3d_lpi_case,
    orient3d_tpi_case, step_ulps,
};
use exactray::{InputError, Sign};
use exactray_oracle::implicit_oracle::{self as oracle, Pt2, Pt3};
use glam::{DVec2, DVec3};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // Running out of bytes only ends the case early.
    let _ = run(data);
});

fn run(data: &[u8]) -> Result<()> {
    let mut u = Unstructured::new(data);
    let selector = u8::arbitrary(&mut u)?;
    let (pred, mode) = (selector % 7, selector / 7 % 3);
    let three = matches!(pred, 0 | 2 | 3 | 5);
    let dim = if three { 3 } else { 2 };
    let mut pool = if mode == 0 {
        let n = 4 + usize::from(u8::arbitrary(&mut u)? % 8);
        (0..n * dim)
            .map(|_| Ok(finite_f64_from_bits(u64::arbitrary(&mut u)?)))
            .collect::<Result<Vec<f64>>>()?
    } else {
        hard(three, &mut u)?
    };
    if mode != 0 {
        for _ in 0..u8::arbitrary(&mut u)? % 6 {
            edit(&mut pool, dim, mode == 2, &mut u)?;
        }
    }
    if three {
        check3(pred, &pool, &mut u)
    } else {
        check2(pred, &pool, &mut u)
    }
}

/// A pool of points from the generators: an `orient3d_lpi` and an
/// `orient3d_tpi` case (20 points), or two `orient2d_ssi` cases (12).
fn hard(three: bool, u: &mut Unstructured<'_>) -> Result<Vec<f64>> {
    let class = InputClass::ALL[usize::from(u8::arbitrary(u)? % 6)];
    let mut rng = SplitMix64::new(u64::arbitrary(u)?);
    Ok(if three {
        let a = orient3d_lpi_case(class, &mut rng);
        let b = orient3d_tpi_case(class, &mut rng);
        a.iter().chain(&b).flat_map(|v| v.to_array()).collect()
    } else {
        let a = orient2d_ssi_case(class, &mut rng);
        let b = orient2d_ssi_case(class, &mut rng);
        a.iter().chain(&b).flat_map(|v| v.to_array()).collect()
    })
}

/// `2^k` as two factors, so that `x * a * b` rounds once.
fn pow2_pair(k: i32) -> (f64, f64) {
    let p = |e: i32| f64::from_bits(((e.clamp(-1022, 1023) + 1023) as u64) << 52);
    (p(k / 2), p(k - k / 2))
}

/// One edit of the pool (points of `dim` coordinates).
fn edit(c: &mut [f64], dim: usize, non_finite: bool, u: &mut Unstructured<'_>) -> Result<()> {
    let n = c.len();
    let i = usize::from(u16::arbitrary(u)?) % n;
    let j = usize::from(u16::arbitrary(u)?) % n;
    match u8::arbitrary(u)? % 7 {
        0 => c[i] = step_ulps(c[i], i64::from(i8::arbitrary(u)? % 4)),
        1 => c[j] = c[i],
        2 => {
            let (s, t) = pow2_pair(i32::from(i16::arbitrary(u)? % 1100));
            c.iter_mut().for_each(|x| *x = *x * s * t);
        }
        3 => {
            // One axis of every point: signs of all but the order along a
            // line stay; a check that scaling keeps them would need exact
            // scaling, so the oracle decides.
            let (s, t) = pow2_pair(i32::from(i16::arbitrary(u)? % 1100));
            let axis = i % dim;
            c.iter_mut()
                .skip(axis)
                .step_by(dim)
                .for_each(|x| *x = *x * s * t);
        }
        4 => c[i] = finite_f64_from_bits(u64::arbitrary(u)?),
        5 => {
            // A whole point copied onto another.
            let (a, b) = (i / dim * dim, j / dim * dim);
            for k in 0..dim {
                c[b + k] = c[a + k];
            }
        }
        _ => {
            if non_finite {
                c[i] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY][j % 3];
            } else {
                c[i] = -c[i];
            }
        }
    }
    Ok(())
}

fn bits(c: &[f64]) -> Vec<String> {
    c.iter().map(|x| format!("{:#018x}", x.to_bits())).collect()
}

fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// An argument of a 3D predicate: the crate's point (`None` where the
/// construction is refused as it should be) and the oracle's.
fn point3(pool: &[f64], u: &mut Unstructured<'_>) -> Result<Option<(AnyPoint3, Pt3)>> {
    let n = pool.len() / 3;
    let kind = u8::arbitrary(u)? % 4;
    let mut pick = || -> Result<[f64; 3]> {
        let i = usize::from(u8::arbitrary(u)?) % n;
        Ok([pool[3 * i], pool[3 * i + 1], pool[3 * i + 2]])
    };
    let (made, pt) = match kind {
        0 | 1 => {
            let v = pick()?;
            return Ok(Some((AnyPoint3::Explicit(DVec3::from(v)), Pt3::E(v))));
        }
        2 => {
            let v: [[f64; 3]; 5] = [pick()?, pick()?, pick()?, pick()?, pick()?];
            let x = Lpi::new(v[0], v[1], v[2], v[3], v[4]).map(AnyPoint3::Lpi);
            (x, Pt3::Lpi(v))
        }
        _ => {
            let mut plane = || -> Result<[[f64; 3]; 3]> { Ok([pick()?, pick()?, pick()?]) };
            let v = [plane()?, plane()?, plane()?];
            (Tpi::new(v[0], v[1], v[2]).map(AnyPoint3::Tpi), Pt3::Tpi(v))
        }
    };
    Ok(accepted(made, || oracle::weight_sign3(&pt), pt, flat3(&pt)))
}

fn flat3(p: &Pt3) -> Vec<f64> {
    match p {
        Pt3::E(v) => v.to_vec(),
        Pt3::Lpi(v) => v.as_flattened().to_vec(),
        Pt3::Tpi(v) => v.as_flattened().as_flattened().to_vec(),
    }
}

/// A construction's verdict against the oracle's: refused as not one point
/// exactly when the oracle's weight is zero, as not finite exactly when an
/// input is not.
fn accepted<T, P>(
    made: core::result::Result<T, InputError>,
    weight: impl FnOnce() -> i8,
    pt: P,
    inputs: Vec<f64>,
) -> Option<(T, P)> {
    match made {
        Ok(x) => {
            assert!(
                finite(&inputs),
                "accepted a non-finite construction {:?}",
                bits(&inputs)
            );
            assert_ne!(
                weight(),
                0,
                "accepted a degenerate construction {:?}",
                bits(&inputs)
            );
            Some((x, pt))
        }
        Err(InputError::NonFinite { .. }) => {
            assert!(
                !finite(&inputs),
                "refused finite inputs {:?}",
                bits(&inputs)
            );
            None
        }
        Err(e) => {
            assert!(finite(&inputs), "{e:?} for non-finite inputs");
            assert_eq!(
                weight(),
                0,
                "refused a construction: {e:?} {:?}",
                bits(&inputs)
            );
            None
        }
    }
}

/// The name of the first explicit argument that is not finite.
fn first_bad<const K: usize>(
    names: [&'static str; K],
    explicit: [Option<&[f64]>; K],
) -> Option<InputError> {
    (0..K)
        .find(|&i| explicit[i].is_some_and(|v| !finite(v)))
        .map(|i| InputError::NonFinite { argument: names[i] })
}

fn explicit3(p: &Pt3) -> Option<&[f64]> {
    match p {
        Pt3::E(v) => Some(v),
        _ => None,
    }
}

fn check3(pred: u8, pool: &[f64], u: &mut Unstructured<'_>) -> Result<()> {
    let mut args = Vec::new();
    for _ in 0..4 {
        match point3(pool, u)? {
            Some(a) => args.push(a),
            None => return Ok(()),
        }
    }
    let (x, pt): (Vec<AnyPoint3>, Vec<Pt3>) = args.into_iter().unzip();
    let ctx = || format!("pred {pred} pool {:?} points {pt:?}", bits(pool));
    let e = |i: usize| explicit3(&pt[i]);
    let axis = usize::from(u8::arbitrary(u)? % 3);
    match pred {
        0 => {
            let bad = first_bad(["a", "b", "c", "d"], [e(0), e(1), e(2), e(3)]);
            let got = p::try_orient3d_implicit(&x[0], &x[1], &x[2], &x[3]);
            let plain = p::orient3d_implicit(&x[0], &x[1], &x[2], &x[3]);
            match bad {
                Some(err) => {
                    assert_eq!(got, Err(err), "{}", ctx());
                    assert_eq!(plain, Sign::Zero, "{}", ctx());
                }
                None => {
                    let want =
                        Sign::from_i8(oracle::orient3d([pt[0], pt[1], pt[2], pt[3]]).unwrap());
                    assert_eq!(got, Ok(want), "{}", ctx());
                    assert_eq!(
                        p::orient3d_implicit(&x[1], &x[0], &x[2], &x[3]),
                        -want,
                        "swapped: {}",
                        ctx()
                    );
                }
            }
        }
        2 => {
            let bad = first_bad(["a", "b", "c"], [e(0), e(1), e(2)]);
            let got = p::try_orient2d_projected(&x[0], &x[1], &x[2], Axis::ALL[axis]);
            match bad {
                Some(err) => assert_eq!(got, Err(err), "{}", ctx()),
                None => {
                    let want = oracle::orient2d_projected([pt[0], pt[1], pt[2]], axis).unwrap();
                    assert_eq!(got, Ok(Sign::from_i8(want)), "{}", ctx());
                }
            }
        }
        3 => {
            let bad = first_bad(["x", "y"], [e(0), e(1)]);
            let got = p::try_cmp_on_axis(&x[0], &x[1], Axis::ALL[axis]);
            match bad {
                Some(err) => {
                    assert_eq!(got, Err(err), "{}", ctx());
                    assert_eq!(
                        p::cmp_on_axis(&x[0], &x[1], Axis::ALL[axis]),
                        Ordering::Equal
                    );
                }
                None => assert_eq!(
                    got,
                    Ok(oracle::cmp_on_axis3(pt[0], pt[1], axis).unwrap()),
                    "{}",
                    ctx()
                ),
            }
        }
        _ => {
            // Along the line through the first two explicit pool points.
            let (a, b) = ([pool[0], pool[1], pool[2]], [pool[3], pool[4], pool[5]]);
            let got = p::try_cmp_along_line(a, b, &x[2], &x[3]);
            let bad = first_bad(
                ["p", "q", "x", "y"],
                [Some(&a[..]), Some(&b[..]), e(2), e(3)],
            );
            match (bad, a == b) {
                (Some(err), _) => assert_eq!(got, Err(err), "{}", ctx()),
                (None, true) => assert_eq!(got, Err(InputError::ZeroDirection), "{}", ctx()),
                (None, false) => {
                    let want = oracle::cmp_along3(a, b, pt[2], pt[3]).unwrap();
                    assert_eq!(got, Ok(want), "{}", ctx());
                }
            }
        }
    }
    Ok(())
}

/// An argument of a 2D predicate, as [`point3`].
fn point2(pool: &[f64], u: &mut Unstructured<'_>) -> Result<Option<(AnyPoint2, Pt2)>> {
    let n = pool.len() / 2;
    let explicit = u8::arbitrary(u)? % 3 == 0;
    let mut pick = || -> Result<[f64; 2]> {
        let i = usize::from(u8::arbitrary(u)?) % n;
        Ok([pool[2 * i], pool[2 * i + 1]])
    };
    if explicit {
        let v = pick()?;
        return Ok(Some((AnyPoint2::Explicit(DVec2::from(v)), Pt2::E(v))));
    }
    let v = [pick()?, pick()?, pick()?, pick()?];
    let made = Ssi::new(v[0], v[1], v[2], v[3]).map(AnyPoint2::Ssi);
    let pt = Pt2::Ssi(v);
    Ok(accepted(
        made,
        || oracle::weight_sign2(&pt),
        pt,
        v.as_flattened().to_vec(),
    ))
}

fn explicit2(p: &Pt2) -> Option<&[f64]> {
    match p {
        Pt2::E(v) => Some(v),
        _ => None,
    }
}

fn check2(pred: u8, pool: &[f64], u: &mut Unstructured<'_>) -> Result<()> {
    let mut args = Vec::new();
    for _ in 0..3 {
        match point2(pool, u)? {
            Some(a) => args.push(a),
            None => return Ok(()),
        }
    }
    let (x, pt): (Vec<AnyPoint2>, Vec<Pt2>) = args.into_iter().unzip();
    let ctx = || format!("pred {pred} pool {:?} points {pt:?}", bits(pool));
    let e = |i: usize| explicit2(&pt[i]);
    match pred {
        1 => {
            let bad = first_bad(["a", "b", "c"], [e(0), e(1), e(2)]);
            let got = p::try_orient2d_implicit(&x[0], &x[1], &x[2]);
            match bad {
                Some(err) => {
                    assert_eq!(got, Err(err), "{}", ctx());
                    assert_eq!(p::orient2d_implicit(&x[0], &x[1], &x[2]), Sign::Zero);
                }
                None => {
                    let want = Sign::from_i8(oracle::orient2d([pt[0], pt[1], pt[2]]).unwrap());
                    assert_eq!(got, Ok(want), "{}", ctx());
                }
            }
        }
        4 => {
            let axis = usize::from(u8::arbitrary(u)? % 2);
            let bad = first_bad(["x", "y"], [e(0), e(1)]);
            let got = p::try_cmp_on_axis_2d(&x[0], &x[1], [Axis2::X, Axis2::Y][axis]);
            match bad {
                Some(err) => assert_eq!(got, Err(err), "{}", ctx()),
                None => assert_eq!(
                    got,
                    Ok(oracle::cmp_on_axis2(pt[0], pt[1], axis).unwrap()),
                    "{}",
                    ctx()
                ),
            }
        }
        _ => {
            let (a, b) = ([pool[0], pool[1]], [pool[2], pool[3]]);
            let got = p::try_cmp_along_line_2d(a, b, &x[1], &x[2]);
            let bad = first_bad(
                ["p", "q", "x", "y"],
                [Some(&a[..]), Some(&b[..]), e(1), e(2)],
            );
            match (bad, a == b) {
                (Some(err), _) => assert_eq!(got, Err(err), "{}", ctx()),
                (None, true) => assert_eq!(got, Err(InputError::ZeroDirection), "{}", ctx()),
                (None, false) => {
                    let want = oracle::cmp_along2(a, b, pt[1], pt[2]).unwrap();
                    assert_eq!(got, Ok(want), "{}", ctx());
                }
            }
        }
    }
    Ok(())
}
