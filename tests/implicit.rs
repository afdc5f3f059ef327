//! The predicates on constructed points against the exact oracle
//! (`exactray_oracle::implicit_oracle`): every input class of the
//! generators, every combination of explicit and constructed points, every
//! scale from `2^-1000` to `2^1000` and mixed magnitudes in one case, and
//! the typed errors.

use core::cmp::Ordering;
use exactray::predicates::{
    AnyPoint2, AnyPoint3, Axis, Axis2, Lpi, Ssi, Tpi, cmp_along_line, cmp_along_line_2d,
    cmp_on_axis, cmp_on_axis_2d, less_on_axis, orient2d_implicit, orient2d_projected,
    orient3d_implicit, try_cmp_along_line, try_cmp_on_axis, try_orient2d_implicit,
    try_orient3d_implicit,
};
use exactray::testing::{
    InputClass, SplitMix64, less_on_axis_lpi_case, orient2d_ssi_case, orient3d_lpi_case,
    orient3d_tpi_case,
};
use exactray::{InputError, Sign};
use exactray_oracle::implicit_oracle::{self as oracle, Pt2, Pt3};
use glam::{DVec2, DVec3};

const AXES: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

fn a3(v: DVec3) -> [f64; 3] {
    v.to_array()
}

fn lpi_pt(c: &[DVec3]) -> Pt3 {
    Pt3::Lpi([a3(c[0]), a3(c[1]), a3(c[2]), a3(c[3]), a3(c[4])])
}

fn tpi_pt(c: &[DVec3]) -> Pt3 {
    let f = |i: usize| [a3(c[i]), a3(c[i + 1]), a3(c[i + 2])];
    Pt3::Tpi([f(0), f(3), f(6)])
}

fn lpi(c: &[DVec3]) -> Lpi {
    Lpi::new(c[0], c[1], c[2], c[3], c[4]).expect("the generators' constructions are valid")
}

fn tpi(c: &[DVec3]) -> Tpi {
    Tpi::new([c[0], c[1], c[2]], [c[3], c[4], c[5]], [c[6], c[7], c[8]]).expect("valid")
}

fn sign(s: i8) -> Sign {
    Sign::from_i8(s)
}

/// `2^k` for `|k| <= 1000`, as two factors so that scaling rounds once.
fn pow2(k: i32) -> (f64, f64) {
    let p = |e: i32| f64::from_bits(((e + 1023) as u64) << 52);
    (p(k / 2), p(k - k / 2))
}

#[test]
fn orient3d_lpi_every_class() {
    let mut rng = SplitMix64::new(11);
    for class in InputClass::ALL {
        let mut zeros = 0;
        for _ in 0..3000 {
            let c = orient3d_lpi_case(class, &mut rng);
            let want = oracle::orient3d([
                Pt3::E(a3(c[0])),
                Pt3::E(a3(c[1])),
                Pt3::E(a3(c[2])),
                lpi_pt(&c[3..]),
            ]);
            let want = sign(want.expect("valid construction"));
            let x = lpi(&c[3..]);
            assert_eq!(
                orient3d_implicit(c[0], c[1], c[2], &x),
                want,
                "{class:?} {c:?}"
            );
            // The point in every position (orient3d alternates).
            assert_eq!(
                orient3d_implicit(&x, c[1], c[2], c[0]),
                -want,
                "{class:?} {c:?}"
            );
            assert_eq!(
                orient3d_implicit(c[0], &x, c[2], c[1]),
                -want,
                "{class:?} {c:?}"
            );
            zeros += (want == Sign::Zero) as u32;
        }
        if class == InputClass::Degenerate {
            assert_eq!(zeros, 3000);
        }
    }
}

#[test]
fn orient3d_tpi_every_class() {
    let mut rng = SplitMix64::new(12);
    for class in InputClass::ALL {
        for _ in 0..1500 {
            let c = orient3d_tpi_case(class, &mut rng);
            let want = oracle::orient3d([
                Pt3::E(a3(c[0])),
                Pt3::E(a3(c[1])),
                Pt3::E(a3(c[2])),
                tpi_pt(&c[3..]),
            ]);
            let want = sign(want.expect("valid construction"));
            let x = tpi(&c[3..]);
            assert_eq!(
                orient3d_implicit(c[0], c[1], c[2], &x),
                want,
                "{class:?} {c:?}"
            );
            if class == InputClass::Degenerate {
                assert_eq!(want, Sign::Zero);
            }
        }
    }
}

#[test]
fn orient2d_ssi_every_class() {
    let mut rng = SplitMix64::new(13);
    for class in InputClass::ALL {
        for _ in 0..3000 {
            let c = orient2d_ssi_case(class, &mut rng);
            let a2 = |i: usize| c[i].to_array();
            let x = Pt2::Ssi([a2(2), a2(3), a2(4), a2(5)]);
            let want = sign(oracle::orient2d([Pt2::E(a2(0)), Pt2::E(a2(1)), x]).expect("valid"));
            let s = Ssi::new(c[2], c[3], c[4], c[5]).unwrap();
            assert_eq!(orient2d_implicit(c[0], c[1], &s), want, "{class:?} {c:?}");
            assert_eq!(orient2d_implicit(&s, c[1], c[0]), -want, "{class:?} {c:?}");
        }
    }
}

#[test]
fn less_on_axis_lpi_every_class() {
    let mut rng = SplitMix64::new(14);
    for class in InputClass::ALL {
        for _ in 0..3000 {
            let (c, axis) = less_on_axis_lpi_case(class, &mut rng);
            let want = oracle::cmp_on_axis3(lpi_pt(&c[..5]), lpi_pt(&c[5..]), axis).unwrap();
            let (x, y) = (lpi(&c[..5]), lpi(&c[5..]));
            assert_eq!(
                cmp_on_axis(&x, &y, AXES[axis]),
                want,
                "{class:?} {c:?} {axis}"
            );
            assert_eq!(less_on_axis(&x, &y, AXES[axis]), want == Ordering::Less);
            assert_eq!(cmp_on_axis(&y, &x, AXES[axis]), want.reverse());
        }
    }
}

/// A random point of any kind, drawn from the generators' cases of `class`.
fn any_point(class: InputClass, rng: &mut SplitMix64) -> (AnyPoint3, Pt3) {
    match rng.next_u64() % 3 {
        0 => {
            let c = orient3d_lpi_case(class, rng);
            (AnyPoint3::Lpi(lpi(&c[3..])), lpi_pt(&c[3..]))
        }
        1 => {
            let c = orient3d_tpi_case(class, rng);
            (AnyPoint3::Tpi(tpi(&c[3..])), tpi_pt(&c[3..]))
        }
        _ => {
            let c = orient3d_lpi_case(class, rng);
            let i = (rng.next_u64() % 8) as usize;
            (AnyPoint3::Explicit(c[i]), Pt3::E(a3(c[i])))
        }
    }
}

/// Four points from one case: constructed points built on the same inputs
/// share them, which puts many combinations at exact degeneracies.
fn related_points(class: InputClass, rng: &mut SplitMix64) -> [(AnyPoint3, Pt3); 4] {
    let c = orient3d_lpi_case(class, rng);
    let t = orient3d_tpi_case(class, rng);
    let options = |rng: &mut SplitMix64| -> (AnyPoint3, Pt3) {
        match rng.next_u64() % 5 {
            0 => (AnyPoint3::Lpi(lpi(&c[3..])), lpi_pt(&c[3..])),
            1 => (AnyPoint3::Tpi(tpi(&t[3..])), tpi_pt(&t[3..])),
            2 => {
                // The same plane, another line through two of the triangle's points.
                let d = [c[0], c[1], c[5], c[6], c[7]];
                match Lpi::new(d[0], d[1], d[2], d[3], d[4]) {
                    Ok(x) => (AnyPoint3::Lpi(x), lpi_pt(&d)),
                    Err(_) => (AnyPoint3::Explicit(c[0]), Pt3::E(a3(c[0]))),
                }
            }
            _ => {
                let i = (rng.next_u64() % 3) as usize;
                (AnyPoint3::Explicit(c[i]), Pt3::E(a3(c[i])))
            }
        }
    };
    [(); 4].map(|_| options(rng))
}

#[test]
fn every_combination_of_points() {
    let mut rng = SplitMix64::new(15);
    for i in 0..6000 {
        let class = InputClass::ALL[i % 6];
        let p = if i % 2 == 0 {
            related_points(class, &mut rng)
        } else {
            [(); 4].map(|_| any_point(class, &mut rng))
        };
        let (pts, pt) = (p.map(|x| x.0), p.map(|x| x.1));
        let want = sign(oracle::orient3d(pt).unwrap());
        assert_eq!(
            orient3d_implicit(&pts[0], &pts[1], &pts[2], &pts[3]),
            want,
            "{pt:?}"
        );
        let drop = i % 3;
        let want = sign(oracle::orient2d_projected([pt[0], pt[1], pt[2]], drop).unwrap());
        assert_eq!(
            orient2d_projected(&pts[0], &pts[1], &pts[2], AXES[drop]),
            want,
            "{pt:?} {drop}"
        );
        let want = oracle::cmp_on_axis3(pt[0], pt[1], drop).unwrap();
        assert_eq!(
            cmp_on_axis(&pts[0], &pts[1], AXES[drop]),
            want,
            "{pt:?} {drop}"
        );
        let c = orient3d_lpi_case(class, &mut rng);
        let want = oracle::cmp_along3(a3(c[0]), a3(c[1]), pt[2], pt[3]).unwrap();
        assert_eq!(
            cmp_along_line(c[0], c[1], &pts[2], &pts[3]),
            want,
            "{pt:?} {c:?}"
        );
    }
}

/// Points of the plane from the `orient2d_ssi` generator.
fn any_point2(class: InputClass, rng: &mut SplitMix64) -> (AnyPoint2, Pt2) {
    let c = orient2d_ssi_case(class, rng);
    let a2 = |i: usize| c[i].to_array();
    if rng.next_u64().is_multiple_of(3) {
        (AnyPoint2::Explicit(c[0]), Pt2::E(a2(0)))
    } else {
        let s = Ssi::new(c[2], c[3], c[4], c[5]).unwrap();
        (AnyPoint2::Ssi(s), Pt2::Ssi([a2(2), a2(3), a2(4), a2(5)]))
    }
}

#[test]
fn every_combination_in_the_plane() {
    let mut rng = SplitMix64::new(16);
    for i in 0..8000 {
        let class = InputClass::ALL[i % 6];
        let p = [(); 3].map(|_| any_point2(class, &mut rng));
        let (pts, pt) = (p.map(|x| x.0), p.map(|x| x.1));
        let want = sign(oracle::orient2d(pt).unwrap());
        assert_eq!(orient2d_implicit(&pts[0], &pts[1], &pts[2]), want, "{pt:?}");
        let axis = [Axis2::X, Axis2::Y][i % 2];
        let want = oracle::cmp_on_axis2(pt[0], pt[1], i % 2).unwrap();
        assert_eq!(cmp_on_axis_2d(&pts[0], &pts[1], axis), want, "{pt:?}");
        // Along one of the lines the first point's construction uses.
        let c = orient2d_ssi_case(class, &mut rng);
        let want = oracle::cmp_along2(c[2].to_array(), c[3].to_array(), pt[1], pt[2]).unwrap();
        assert_eq!(
            cmp_along_line_2d(c[2], c[3], &pts[1], &pts[2]),
            want,
            "{pt:?} {c:?}"
        );
    }
}

/// Scaling every input by `2^k` leaves every sign as it is, from `2^-1000`
/// to `2^1000` (cases whose scaling would round are skipped).
#[test]
fn every_scale() {
    let mut rng = SplitMix64::new(17);
    for i in 0..4000 {
        let class = [
            InputClass::Uniform,
            InputClass::NearDegenerate,
            InputClass::Degenerate,
        ][i % 3];
        let c = orient3d_lpi_case(class, &mut rng);
        let want = orient3d_implicit(c[0], c[1], c[2], &lpi(&c[3..]));
        let k = (rng.next_u64() % 2001) as i32 - 1000;
        let (s, t) = pow2(k);
        let d = c.map(|v| v * s * t);
        if d.iter().zip(&c).any(|(x, y)| (*x / s / t) != *y) {
            continue;
        }
        let Ok(x) = Lpi::new(d[3], d[4], d[5], d[6], d[7]) else {
            panic!("scaled construction {d:?}");
        };
        assert_eq!(orient3d_implicit(d[0], d[1], d[2], &x), want, "2^{k} {c:?}");
        let t3 = orient3d_tpi_case(class, &mut rng);
        let want = orient3d_implicit(t3[0], t3[1], t3[2], &tpi(&t3[3..]));
        let d = t3.map(|v| v * s * t);
        if d.iter().zip(&t3).all(|(x, y)| (*x / s / t) == *y) {
            assert_eq!(
                orient3d_implicit(d[0], d[1], d[2], &tpi(&d[3..])),
                want,
                "2^{k} {t3:?}"
            );
        }
    }
}

#[test]
fn degenerate_constructions_are_errors() {
    let err = |c| InputError::NoUniqueIntersection { construction: c };
    let o = [0.0; 3];
    // Parallel line and plane, a line in its plane, p == q, a collinear plane.
    assert_eq!(
        Lpi::new(
            o,
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [0.0, 1.0, 1.0]
        )
        .unwrap_err(),
        err("Lpi")
    );
    assert_eq!(
        Lpi::new(o, [1.0, 0.0, 0.0], o, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap_err(),
        err("Lpi")
    );
    assert_eq!(
        Lpi::new(o, o, o, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap_err(),
        err("Lpi")
    );
    assert_eq!(
        Lpi::new(o, [0.0, 0.0, 1.0], o, [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]).unwrap_err(),
        err("Lpi")
    );
    // Nearly parallel by one ulp at 2^-1000: one point.
    let tiny = f64::from_bits(((1023 - 1000) as u64) << 52);
    assert!(
        Lpi::new(
            o,
            [tiny, 0.0, tiny * f64::EPSILON],
            [0.0, 0.0, tiny],
            [tiny, 0.0, tiny],
            [0.0, tiny, tiny]
        )
        .is_ok()
    );
    // Three planes through one line; two parallel planes.
    let plane = |z: f64| [[0.0, 0.0, z], [1.0, 0.0, z], [0.0, 1.0, z]];
    let xz = [[0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
    let yz = [[0.0; 3], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let diag = [[0.0; 3], [1.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    assert_eq!(Tpi::new(xz, yz, diag).unwrap_err(), err("Tpi"));
    assert_eq!(
        Tpi::new(plane(0.0), plane(1e-300), xz).unwrap_err(),
        err("Tpi")
    );
    assert!(Tpi::new(plane(0.0), xz, yz).is_ok());
    // Parallel and identical lines in the plane.
    assert_eq!(
        Ssi::new([0.0, 0.0], [1.0, 1e300], [1.0, 0.0], [2.0, 1e300]).unwrap_err(),
        err("Ssi")
    );
    assert_eq!(
        Ssi::new([0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]).unwrap_err(),
        err("Ssi")
    );
}

#[test]
fn non_finite_inputs_are_errors() {
    let o = [0.0; 3];
    let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let b = [0.5, bad, 0.0];
        let e = |argument| InputError::NonFinite { argument };
        assert_eq!(Lpi::new(o, z, b, x, y), Err(e("r")));
        assert_eq!(Tpi::new([o, x, y], [o, z, b], [o, y, z]), Err(e("v")));
        assert_eq!(
            Ssi::new([0.0, 0.0], [1.0, 1.0], [bad, 0.0], [0.0, 1.0]),
            Err(e("r"))
        );
        let p = Lpi::new(o, z, [0.0, 0.0, 0.5], [1.0, 0.0, 0.5], [0.0, 1.0, 0.5]).unwrap();
        assert_eq!(try_orient3d_implicit(o, b, y, &p), Err(e("b")));
        assert_eq!(orient3d_implicit(o, b, y, &p), Sign::Zero);
        assert_eq!(try_cmp_on_axis(&p, b, Axis::X), Err(e("y")));
        assert_eq!(cmp_on_axis(&p, b, Axis::X), Ordering::Equal);
        assert_eq!(try_cmp_along_line(b, o, &p, &p), Err(e("p")));
        let s = Ssi::new([0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]).unwrap();
        assert_eq!(
            try_orient2d_implicit([0.0, bad], [1.0, 0.0], &s),
            Err(e("a"))
        );
    }
    let p = Lpi::new(o, z, [0.0, 0.0, 0.5], [1.0, 0.0, 0.5], [0.0, 1.0, 0.5]).unwrap();
    assert_eq!(
        try_cmp_along_line(x, x, &p, o),
        Err(InputError::ZeroDirection)
    );
    assert_eq!(cmp_along_line(x, x, &p, o), Ordering::Equal);
}

/// Mixed magnitudes inside one construction: the line's points near
/// `2^1000` apart, the plane's `2^-1000` wide, or the reverse.
#[test]
fn mixed_magnitudes_inside_constructions() {
    let mut rng = SplitMix64::new(18);
    for _ in 0..3000 {
        let c = orient3d_lpi_case(InputClass::NearDegenerate, &mut rng);
        let (k1, k2) = (
            (rng.next_u64() % 2001) as i32 - 1000,
            (rng.next_u64() % 2001) as i32 - 1000,
        );
        let (s1, t1) = pow2(k1);
        let (s2, t2) = pow2(k2);
        let mut d = c;
        d[3..5].iter_mut().for_each(|v| *v = *v * s1 * t1);
        d[5..].iter_mut().for_each(|v| *v = *v * s2 * t2);
        d[..3].iter_mut().for_each(|v| *v = *v * s1 * t1);
        let Ok(x) = Lpi::new(d[3], d[4], d[5], d[6], d[7]) else {
            continue;
        };
        let want = oracle::orient3d([
            Pt3::E(a3(d[0])),
            Pt3::E(a3(d[1])),
            Pt3::E(a3(d[2])),
            lpi_pt(&d[3..]),
        ]);
        assert_eq!(
            orient3d_implicit(d[0], d[1], d[2], &x),
            sign(want.unwrap()),
            "{d:?}"
        );
    }
}

#[test]
fn the_round_trip_example() {
    // The docs' example: a point on a plane that its rounding is not on.
    let x = Lpi::new(
        [0.0; 3],
        [1.0, 3.0, 7.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    )
    .unwrap();
    let (a, b, c) = ([0.0; 3], [0.0, 0.0, 1.0], [1.0, 3.0, 0.0]);
    assert_eq!(orient3d_implicit(a, b, c, &x), Sign::Zero);
    let pt = [
        Pt3::E(a),
        Pt3::E(b),
        Pt3::E(c),
        Pt3::Lpi([
            [0.0; 3],
            [1.0, 3.0, 7.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ]),
    ];
    assert_eq!(oracle::orient3d(pt), Some(0));
    let _ = DVec2::ZERO;
}

/// The widest exact stages (inputs spanning the whole range on an axis, so
/// the integers are thousands of bits wide) fit in a thread of 512 KiB of
/// stack in a release build (debug frames are several times larger).
#[test]
fn the_widest_exact_stages_fit_their_stack() {
    let stack = if cfg!(debug_assertions) {
        16 << 20
    } else {
        512 << 10
    };
    let run = std::thread::Builder::new().stack_size(stack).spawn(|| {
        let mut rng = SplitMix64::new(9);
        let spread = |i: usize| {
            if i.is_multiple_of(2) {
                2f64.powi(900)
            } else {
                2f64.powi(-900)
            }
        };
        // One line–plane point beside three explicit points.
        for _ in 0..20 {
            let mut c = orient3d_lpi_case(InputClass::NearDegenerate, &mut rng);
            c.iter_mut().enumerate().for_each(|(i, v)| v.x *= spread(i));
            let Ok(x) = Lpi::new(c[3], c[4], c[5], c[6], c[7]) else {
                continue;
            };
            let pt = [
                Pt3::E(a3(c[0])),
                Pt3::E(a3(c[1])),
                Pt3::E(a3(c[2])),
                lpi_pt(&c[3..]),
            ];
            assert_eq!(
                orient3d_implicit(c[0], c[1], c[2], &x),
                sign(oracle::orient3d(pt).unwrap())
            );
        }
        // Four three-plane points: the determinant of degree 27.
        let mut points = Vec::new();
        while points.len() < 4 {
            let c = orient3d_tpi_case(InputClass::Uniform, &mut rng);
            let mut p = c[3..].to_vec();
            for (i, v) in p.iter_mut().enumerate() {
                v.x *= spread(i);
                v.z *= spread(i + 1);
            }
            if let Ok(t) = Tpi::new([p[0], p[1], p[2]], [p[3], p[4], p[5]], [p[6], p[7], p[8]]) {
                points.push((t, tpi_pt(&p)));
            }
        }
        let want = oracle::orient3d([points[0].1, points[1].1, points[2].1, points[3].1]).unwrap();
        let got = orient3d_implicit(&points[0].0, &points[1].0, &points[2].0, &points[3].0);
        assert_eq!(got, sign(want));
    });
    run.expect("a thread")
        .join()
        .expect("no stack overflow, and the oracle's answers");
}
