//! Fixed hard inputs: hand-picked cases and every fuzzer finding.
//!
//! Expected signs are not typed in: each case is compared with the exact
//! oracle, so a case stays right if its input is edited. Fuzzer findings are
//! kept as exact bit patterns (`f64::to_bits`) together with the oracle's sign
//! at the time of the finding, which is re-checked against the oracle too.

use exactray::{
    Sign,
    predicates::{SideRelation, incircle, insphere, orient2d, orient3d, same_side, side_of_plane},
};
use exactray_oracle::oracle;
use glam::{DVec2, DVec3};

fn s(v: i8) -> Sign {
    Sign::from_i8(v)
}

fn check_orient2d(label: &str, [a, b, c]: [[f64; 2]; 3]) -> Sign {
    let want = s(oracle::orient2d(a, b, c));
    let (da, db, dc) = (DVec2::from(a), DVec2::from(b), DVec2::from(c));
    assert_eq!(
        orient2d(da, db, dc),
        want,
        "{label}: orient2d{:?}",
        (a, b, c)
    );
    // Every permutation is decided separately by the filter, so each can fail
    // on its own; odd permutations negate the sign.
    assert_eq!(orient2d(db, dc, da), want, "{label}: rotated");
    assert_eq!(orient2d(db, da, dc), -want, "{label}: swapped");
    want
}

fn check_orient3d(label: &str, [a, b, c, d]: [[f64; 3]; 4]) -> Sign {
    let want = s(oracle::orient3d(a, b, c, d));
    let [da, db, dc, dd] = [a, b, c, d].map(DVec3::from);
    assert_eq!(
        orient3d(da, db, dc, dd),
        want,
        "{label}: orient3d{:?}",
        (a, b, c, d)
    );
    assert_eq!(orient3d(db, da, dc, dd), -want, "{label}: swapped");
    assert_eq!(orient3d(dd, da, db, dc), -want, "{label}: rotated (odd)");
    want
}

fn check_incircle(label: &str, [a, b, c, d]: [[f64; 2]; 4]) -> Sign {
    let want = s(oracle::incircle(a, b, c, d));
    let [da, db, dc, dd] = [a, b, c, d].map(DVec2::from);
    assert_eq!(
        incircle(da, db, dc, dd),
        want,
        "{label}: incircle{:?}",
        (a, b, c, d)
    );
    assert_eq!(incircle(db, da, dc, dd), -want, "{label}: swapped");
    assert_eq!(incircle(db, dc, da, dd), want, "{label}: rotated");
    want
}

fn check_insphere(label: &str, [a, b, c, d, e]: [[f64; 3]; 5]) -> Sign {
    let want = s(oracle::insphere(a, b, c, d, e));
    let [da, db, dc, dd, de] = [a, b, c, d, e].map(DVec3::from);
    assert_eq!(
        insphere(da, db, dc, dd, de),
        want,
        "{label}: insphere{:?}",
        (a, b, c, d, e)
    );
    assert_eq!(insphere(db, da, dc, dd, de), -want, "{label}: swapped");
    want
}

fn check_plane_side(label: &str, [x0, x1, x2, p, q]: [[f64; 3]; 5]) -> SideRelation {
    let want = match oracle::plane_side(x0, x1, x2, p, q) {
        1 => SideRelation::Same,
        -1 => SideRelation::Opposite,
        _ => SideRelation::OnPlane,
    };
    let [d0, d1, d2, dp, dq] = [x0, x1, x2, p, q].map(DVec3::from);
    assert_eq!(
        same_side(d0, d1, d2, dp, dq),
        want,
        "{label}: same_side{:?}",
        (x0, x1, x2, p, q)
    );
    assert_eq!(
        side_of_plane(d0, d1, d2, dp),
        s(oracle::orient3d(x0, x1, x2, p)),
        "{label}: side of p"
    );
    want
}

/// One unit in the last place above `x` (towards +inf).
fn up(x: f64) -> f64 {
    if x == 0.0 {
        f64::from_bits(1)
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

const TINY: f64 = 5e-324; // 2^-1074, the smallest subnormal
const P: f64 = 1.0e-160; // products of two such underflow to subnormal or zero
const H: f64 = 1.0e160; // products of two such overflow

#[test]
fn orient2d_hand_picked() {
    check_orient2d("0.1 0.2 0.3", [[0.1, 0.1], [0.2, 0.2], [0.3, 0.3]]);
    // Shewchuk's classic: a point a few ulps from the line through (12, 12)
    // and (24, 24), where the naive determinant gets the sign wrong.
    for i in 0..4 {
        for j in 0..4 {
            let x = 0.5 + f64::from(i) * f64::EPSILON;
            let y = 0.5 + f64::from(j) * f64::EPSILON;
            check_orient2d("shewchuk grid", [[x, y], [12.0, 12.0], [24.0, 24.0]]);
        }
    }
    // All-subnormal: the determinant is far below the smallest subnormal.
    assert_eq!(
        check_orient2d("subnormal ccw", [[0.0, 0.0], [TINY, 0.0], [0.0, TINY]]),
        Sign::Positive
    );
    check_orient2d(
        "subnormal collinear",
        [
            [TINY, TINY],
            [2.0 * TINY, 2.0 * TINY],
            [3.0 * TINY, 3.0 * TINY],
        ],
    );
    check_orient2d(
        "subnormal off by one",
        [
            [TINY, TINY],
            [2.0 * TINY, 2.0 * TINY],
            [3.0 * TINY, 4.0 * TINY],
        ],
    );
    // Products of differences underflow to zero in plain arithmetic.
    assert_ne!(
        check_orient2d("underflowing", [[0.0, 0.0], [P, P], [2.0 * P, up(2.0 * P)]]),
        Sign::Zero
    );
    check_orient2d(
        "underflowing collinear",
        [[P, 3.0 * P], [2.0 * P, 6.0 * P], [4.0 * P, 12.0 * P]],
    );
    // Products overflow to infinity in plain arithmetic.
    assert_ne!(
        check_orient2d("overflowing", [[-H, -H], [H, H], [up(2.0 * H), 2.0 * H]]),
        Sign::Zero
    );
    check_orient2d(
        "overflow at max",
        [[-f64::MAX, -f64::MAX], [f64::MAX, f64::MAX], [0.0, 0.0]],
    );
    check_orient2d(
        "overflow at max, off",
        [[-f64::MAX, -f64::MAX], [f64::MAX, f64::MAX], [0.0, TINY]],
    );
    // Mixed magnitudes: a huge baseline and a subnormal offset.
    check_orient2d("mixed", [[1e300, 1e-300], [-1e300, -1e-300], [TINY, 0.0]]);
    check_orient2d(
        "mixed collinear",
        [[1e300, 0.0], [-1e300, 0.0], [TINY, 0.0]],
    );
    check_orient2d(
        "mixed, tiny side",
        [[1e300, 0.0], [-1e300, 0.0], [1.0, -TINY]],
    );
    // Signed zeros are the same number.
    assert_eq!(
        check_orient2d("signed zeros", [[-0.0, 0.0], [0.0, -0.0], [1.0, -0.0]]),
        Sign::Zero
    );
}

#[test]
fn orient3d_hand_picked() {
    let (a, b, c) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    assert_eq!(
        check_orient3d("above", [a, b, c, [0.3, 0.3, TINY]]),
        Sign::Positive
    );
    check_orient3d("below, subnormal", [a, b, c, [0.3, 0.3, -TINY]]);
    // Nearly coplanar through rounding: d = a + 0.1 (b - a) + 0.7 (c - a).
    let (a, b, c) = ([0.1, 0.2, 0.3], [1.7, -0.3, 2.9], [-0.4, 1.1, 0.6]);
    let d: [f64; 3] = core::array::from_fn(|k| a[k] + 0.1 * (b[k] - a[k]) + 0.7 * (c[k] - a[k]));
    check_orient3d("rounded plane", [a, b, c, d]);
    let scale = |p: [f64; 3], f: f64| p.map(|v| v * f);
    check_orient3d("rounded plane, huge", [a, b, c, d].map(|p| scale(p, H)));
    check_orient3d("rounded plane, tiny", [a, b, c, d].map(|p| scale(p, P)));
    check_orient3d(
        "rounded plane, subnormal",
        [a, b, c, d].map(|p| scale(p, 2f64.powi(-1060))),
    );
    check_orient3d(
        "max corners",
        [
            [f64::MAX, 0.0, 0.0],
            [0.0, f64::MAX, 0.0],
            [0.0, 0.0, f64::MAX],
            [-f64::MAX, -f64::MAX, -f64::MAX],
        ],
    );
    check_orient3d(
        "mixed",
        [
            [1e300, 0.0, 0.0],
            [0.0, 1e-300, 0.0],
            [0.0, 0.0, TINY],
            [1.0, 1.0, 1.0],
        ],
    );
}

#[test]
fn incircle_hand_picked() {
    // Exactly cocircular integer points (x² + y² = 25), then scaled to each
    // extreme, then one coordinate nudged by one ulp.
    let base = [[3.0, 4.0], [-5.0, 0.0], [0.0, -5.0], [4.0, -3.0]];
    for k in [0, -1070, -540, 500, 1019] {
        let f = 2f64.powi(k);
        let pts = base.map(|p| p.map(|v| v * f));
        assert_eq!(
            check_incircle(&format!("cocircular * 2^{k}"), pts),
            Sign::Zero
        );
        let mut nudged = pts;
        nudged[3][0] = up(nudged[3][0]);
        check_incircle(&format!("nudged * 2^{k}"), nudged);
    }
    // Rounded unit-circle points far from the origin.
    let c = [1e6, -3e6];
    let on = |t: f64| [c[0] + t.cos(), c[1] + t.sin()];
    check_incircle(
        "rounded circle far away",
        [on(0.1), on(2.0), on(4.0), on(5.5)],
    );
    check_incircle(
        "mixed",
        [[1e300, 0.0], [0.0, 1e300], [-1e300, 0.0], [TINY, -1e-300]],
    );
    check_incircle(
        "subnormal",
        [[TINY, 0.0], [0.0, TINY], [-TINY, 0.0], [0.0, -TINY]],
    );
}

#[test]
fn insphere_hand_picked() {
    // Exactly cospherical: permutations of (±1, ±2, ±2) have norm 3.
    let base = [
        [1.0, 2.0, 2.0],
        [-2.0, 1.0, 2.0],
        [2.0, -2.0, 1.0],
        [-2.0, -2.0, -1.0],
        [2.0, 2.0, -1.0],
    ];
    assert_ne!(
        check_orient3d("sphere tetrahedron", [base[0], base[1], base[2], base[3]]),
        Sign::Zero
    );
    for k in [0, -1070, -400, 400, 1020] {
        let f = 2f64.powi(k);
        let pts = base.map(|p| p.map(|v| v * f));
        assert_eq!(
            check_insphere(&format!("cospherical * 2^{k}"), pts),
            Sign::Zero
        );
        let mut nudged = pts;
        nudged[4][2] = up(nudged[4][2]);
        check_insphere(&format!("nudged * 2^{k}"), nudged);
    }
    check_insphere(
        "mixed",
        [
            [1e300, 0.0, 0.0],
            [0.0, 1e300, 0.0],
            [0.0, 0.0, 1e300],
            [-1e300, 0.0, 0.0],
            [TINY, 1e-300, 1.0],
        ],
    );
}

#[test]
fn plane_side_hand_picked() {
    let (x0, x1, x2) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    assert_eq!(
        check_plane_side(
            "opposite subnormal",
            [x0, x1, x2, [0.2, 0.2, 1.0], [0.0, 0.0, -TINY]]
        ),
        SideRelation::Opposite
    );
    assert_eq!(
        check_plane_side("on plane", [x0, x1, x2, [0.2, 0.2, 0.0], [0.0, 0.0, 1.0]]),
        SideRelation::OnPlane
    );
    let degenerate = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]];
    check_plane_side(
        "degenerate triangle",
        [
            degenerate[0],
            degenerate[1],
            degenerate[2],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
    );
    check_plane_side(
        "huge triangle, tiny points",
        [
            [H, 0.0, 0.0],
            [0.0, H, 0.0],
            [0.0, 0.0, H],
            [TINY, 0.0, 0.0],
            [0.0, -TINY, 0.0],
        ],
    );
    check_plane_side(
        "tiny triangle, huge points",
        [
            [P, 0.0, 0.0],
            [0.0, P, 0.0],
            [0.0, 0.0, P],
            [H, -H, 1.0],
            [-H, H, up(1.0)],
        ],
    );
}

#[derive(Clone, Copy, Debug)]
enum Pred {
    Orient2d,
    Orient3d,
    Incircle,
    Insphere,
    SameSide,
}

/// A failing input of the `predicates` fuzz target: the coordinates' bits in
/// argument order and the oracle's answer when it was found (a sign, or for
/// `SameSide` the relation as `1` same, `-1` opposite, `0` on the plane).
struct Finding {
    pred: Pred,
    oracle: i8,
    bits: &'static [u64],
}

/// Findings of `cargo +nightly fuzz run predicates` (fuzz/fuzz_targets/predicates.rs).
///
/// The first batch was found against the interim implementation (the
/// `robust` crate applied directly, whose error bounds assume no underflow or
/// overflow), within seconds: tiny (~1e-160), huge (~1e+270) and mixed
/// magnitudes where the plain filter's products underflow to zero or
/// overflow, so it answered `Zero` for a non-degenerate input.
const FINDINGS: &[Finding] = &[
    Finding {
        pred: Pred::Orient2d,
        oracle: -1,
        bits: &[
            0x1e5e22ee2a1c9320,
            0x9e59319da56b95e4,
            0x9e461a3079c5c0b0,
            0x9e54df5950782eb4,
            0x1e516104ceb245aa,
            0x9e5046a1dbef8d9e,
        ],
    },
    Finding {
        pred: Pred::Orient2d,
        oracle: -1,
        bits: &[
            0xeb82c00000000000,
            0xeb6f000000000000,
            0x806f07735762a12c,
            0x0000000000000000,
            0xeb72c00000000000,
            0xeb5f000000000000,
        ],
    },
    Finding {
        pred: Pred::Orient2d,
        oracle: -1,
        bits: &[
            0xfcc2fa2c7d5e00f8,
            0x4ebf2e89a079b10c,
            0x7c9a670735d78990,
            0x4eba568b91171208,
            0x7cbc05022a5eef90,
            0x4eb80271b6e1471a,
        ],
    },
    Finding {
        pred: Pred::Orient2d,
        oracle: 1,
        bits: &[
            0x62d0800000000000,
            0xe2dce00000000000,
            0x62ee400000000000,
            0xe2fa780000000000,
            0x018897ccf2331a82,
            0x0413965ebd2bddb8,
        ],
    },
    Finding {
        pred: Pred::Orient3d,
        oracle: -1,
        bits: &[
            0xc3a95759be2882b0,
            0xfa65cfa811ef5b6e,
            0x859835066a3aafdc,
            0x221f88a33beb2f34,
            0x7d21f0993eec17a6,
            0x8ee36177ff72af9a,
            0x8675d47188d2598c,
            0xececa26089ec3976,
            0xe157fadc06a70b80,
            0x36de475989838480,
            0x9036474b5250a88c,
            0xad953f8a63cf5080,
        ],
    },
    Finding {
        pred: Pred::Orient3d,
        oracle: 1,
        bits: &[
            0xec88000000000000,
            0xecba000000000000,
            0xec80000000000000,
            0xeca9000000000000,
            0xeccc400000000000,
            0xec9e000000000000,
            0x05bfdb18147b1e52,
            0x03a4144b9571e1c4,
            0x0000000000000000,
            0xec91400000000000,
            0xeccc680000000000,
            0xec89800000000000,
        ],
    },
    Finding {
        pred: Pred::Orient3d,
        oracle: 1,
        bits: &[
            0x7619ae5059ccc87e,
            0x75e07dc8c2128760,
            0xf6120622bf94b492,
            0xf607def78016a0c0,
            0x76073fb0b66255e8,
            0xf6174e60e5e48f86,
            0x761f8061ec41380e,
            0x75f88a5ee743bdb8,
            0xf5f01f9e4881cf48,
            0x760a326145ca07bf,
            0xf5e4bb0404bfe734,
            0xf623359cad396be7,
        ],
    },
    Finding {
        pred: Pred::Orient3d,
        oracle: -1,
        bits: &[
            0x1e5e22ee2a1c9320,
            0x9e59319da56b95e4,
            0x9e461a3079c5c0b0,
            0x9e54df5950782eb4,
            0x1e516104ceb245aa,
            0x9e5046a1dbef8d9e,
            0x1e5cee12230da32c,
            0x9e3a811322c34ec8,
            0x1e50b4c9b80156f6,
            0x1e188680ff82ef60,
            0x1e2c3eeaab307550,
            0x1e4aa7078b006624,
        ],
    },
    Finding {
        pred: Pred::Incircle,
        oracle: -1,
        bits: &[
            0x97e391b46fe3cd09,
            0x879a3ab1dafac262,
            0x97ee2cc05164968b,
            0x07983b48d3e47ca6,
            0x17e4e00e34a9974f,
            0x8777d126386baa43,
            0x17de77d8afe78632,
            0x07abd74795e0506a,
        ],
    },
    Finding {
        pred: Pred::Incircle,
        oracle: -1,
        bits: &[
            0xe3f3dedb30dd736b,
            0xbee073f6f71a416b,
            0xe3f3e18a1bb39231,
            0xbee0782dd2be1fec,
            0xe3f0e3b9f401ead3,
            0xbef405b0ffbe8665,
            0xe3f1dbc3bf45594e,
            0xbedc96e64d4cf980,
        ],
    },
    Finding {
        pred: Pred::Incircle,
        oracle: -1,
        bits: &[
            0x340e189919be8d24,
            0x18e3791d3a825da8,
            0x468e540b047bb04a,
            0xbc89aa2d40166b1c,
            0xeb3ba7f0e1317890,
            0xdc4c7bc16d587204,
            0x0672ea30452c09b8,
            0x935dedcd1c1343ce,
        ],
    },
    Finding {
        pred: Pred::Incircle,
        oracle: 1,
        bits: &[
            0xd9a8800000000000,
            0xd99c000000000000,
            0xd9a8000000000000,
            0xd9a2000000000000,
            0x80345eb605b58ce4,
            0x078d1e5b73949b70,
            0xd9a8000000000000,
            0xd994000000000000,
        ],
    },
    Finding {
        pred: Pred::Insphere,
        oracle: 1,
        bits: &[
            0x1e5e22ee2a1c9320,
            0x9e59319da56b95e4,
            0x9e461a3079c5c0b0,
            0x9e54df5950782eb4,
            0x1e516104ceb245aa,
            0x9e5046a1dbef8d9e,
            0x1e5cee12230da32c,
            0x9e3a811322c34ec8,
            0x1e50b4c9b80156f6,
            0x1e188680ff82ef60,
            0x1e2c3eeaab307550,
            0x1e4aa7078b006624,
            0x1e12ecfe5e5c7600,
            0x9e06b3ed1c556f80,
            0x1e50f3c5c40adfde,
        ],
    },
    Finding {
        pred: Pred::Insphere,
        oracle: -1,
        bits: &[
            0x7dbf5e3ee4a6f03c,
            0xfda2c5b15bcc3560,
            0xfdb824a9284badd0,
            0xfd9e0fe715c8d658,
            0x7dbc13b843c8e3a0,
            0x7db1b0588680350c,
            0x7db510aa9d86eba4,
            0x7daf8f253c075fa8,
            0xfd7409d7ff17b7c0,
            0xfd9e43e7cf740090,
            0x7dbdf4dcbd506040,
            0xfd89936613db95d0,
            0x7d7d710b4454dec0,
            0x7dbdcac57162ce14,
            0xfdbd0d39e22ed310,
        ],
    },
    Finding {
        pred: Pred::Insphere,
        oracle: -1,
        bits: &[
            0xe163b1626d166a58,
            0xe197c24203fb85f2,
            0xe19bb4f0ec9c68dc,
            0x614c879c7d01eae0,
            0x61adcafdb5173a42,
            0xe1a18c61ec793133,
            0x61b001b647736fe7,
            0xe16f5db6747b96aa,
            0xe1a03d350f955901,
            0xe184bc58e758db94,
            0xe1910d648cb476f4,
            0xe19857bea56564ce,
            0x61a0abf0ce8a4468,
            0x61a79d47056456f6,
            0xe1b14c46a441bb71,
        ],
    },
    Finding {
        pred: Pred::Insphere,
        oracle: 1,
        bits: &[
            0x68a7000000000000,
            0x68a8000000000000,
            0x6878000000000000,
            0x68af000000000000,
            0xe8b2000000000000,
            0x6896000000000000,
            0x03fdeca877c80150,
            0x024873cb27c2e7c8,
            0x800000000000366e,
            0x68c3c00000000000,
            0x68a0000000000000,
            0x68bf800000000000,
            0x0000000000000000,
            0x0000000000000000,
            0x0000000000000000,
        ],
    },
    Finding {
        pred: Pred::SameSide,
        oracle: 1,
        bits: &[
            0xec318761955e46a0,
            0xd3fe4ee8b9dffdb0,
            0x759e22ee2a1c9320,
            0xec59319da56b95e4,
            0xd3e61a3079c5c0b0,
            0xf594df5950782eb4,
            0x6c516104ceb245ac,
            0xd3f046a1dbef8da0,
            0x759cee12230da32e,
            0x6c531f804b38684c,
            0xd3f94cf76438deb3,
            0x75a68474b2cafac0,
            0x6c37115200795a93,
            0xd3f25b0912615e26,
            0x7594f0d148a35259,
        ],
    },
    Finding {
        pred: Pred::SameSide,
        oracle: 1,
        bits: &[
            0xed6e195ad7c3de4c,
            0xed6dd6af723eac3b,
            0xed778769dc38fc75,
            0xed6ec383b69dd528,
            0xed5cf95e80578858,
            0xed7fb0c1a5165aa6,
            0xed54bb12370f0db0,
            0x6d655822d66a83d8,
            0xed7e14279525d9f2,
            0xed68a4fc6eedfea2,
            0xed5c78392c479acf,
            0xed7a0de60398a846,
            0xed7cf732411dccc6,
            0xed8641d2815bbd3c,
            0xed74abf7065c9d6b,
        ],
    },
    Finding {
        pred: Pred::SameSide,
        oracle: 1,
        bits: &[
            0x790f000000000000,
            0xf922000000000000,
            0x7923800000000000,
            0x7914800000000000,
            0x78fe000000000000,
            0x7921400000000000,
            0x82b7a33e3ddb819c,
            0x0000000000000000,
            0x0357a41f7934ca66,
            0x7922b80000000000,
            0xf934040000000000,
            0x7937040000000000,
            0x7916d00000000000,
            0xf93e780000000000,
            0x7933b00000000000,
        ],
    },
    Finding {
        pred: Pred::SameSide,
        oracle: -1,
        bits: &[
            0xf5b5823e9fa5d9ac,
            0xf5a2c88f6faf387c,
            0x75bd7cd0bf51780a,
            0x75ab309b9bc49f80,
            0xf57acf7d39dc2f60,
            0x75abd05eee0c8e4c,
            0xf5b500c9c6cb4578,
            0x75bd1d3c26e268de,
            0xf5507cb0093b7f00,
            0xf597fd273b009818,
            0x75a409e5890eb8dc,
            0x75bd47979c080df0,
            0x75bf84b6ffb38a54,
            0x75bd2fb06b6b7368,
            0xf5b37bcdd90c1cb6,
        ],
    },
];

#[test]
fn fuzz_findings() {
    for (i, f) in FINDINGS.iter().enumerate() {
        let v: Vec<f64> = f.bits.iter().map(|&b| f64::from_bits(b)).collect();
        let label = format!("finding {i} ({:?})", f.pred);
        let p2 = |k: usize| [v[2 * k], v[2 * k + 1]];
        let p3 = |k: usize| [v[3 * k], v[3 * k + 1], v[3 * k + 2]];
        let (oracle_now, got) = match f.pred {
            Pred::Orient2d => {
                assert_eq!(v.len(), 6, "{label}");
                let pts = [p2(0), p2(1), p2(2)];
                (
                    oracle::orient2d(pts[0], pts[1], pts[2]),
                    check_orient2d(&label, pts).as_i8(),
                )
            }
            Pred::Orient3d => {
                assert_eq!(v.len(), 12, "{label}");
                let pts = [p3(0), p3(1), p3(2), p3(3)];
                (
                    oracle::orient3d(pts[0], pts[1], pts[2], pts[3]),
                    check_orient3d(&label, pts).as_i8(),
                )
            }
            Pred::Incircle => {
                assert_eq!(v.len(), 8, "{label}");
                let pts = [p2(0), p2(1), p2(2), p2(3)];
                (
                    oracle::incircle(pts[0], pts[1], pts[2], pts[3]),
                    check_incircle(&label, pts).as_i8(),
                )
            }
            Pred::Insphere => {
                assert_eq!(v.len(), 15, "{label}");
                let pts = [p3(0), p3(1), p3(2), p3(3), p3(4)];
                (
                    oracle::insphere(pts[0], pts[1], pts[2], pts[3], pts[4]),
                    check_insphere(&label, pts).as_i8(),
                )
            }
            Pred::SameSide => {
                assert_eq!(v.len(), 15, "{label}");
                let pts = [p3(0), p3(1), p3(2), p3(3), p3(4)];
                (
                    oracle::plane_side(pts[0], pts[1], pts[2], pts[3], pts[4]),
                    check_plane_side(&label, pts).as_i8(),
                )
            }
        };
        assert_eq!(oracle_now, f.oracle, "{label}: the oracle's answer changed");
        assert_eq!(got, f.oracle, "{label}");
    }
}

/// Disks, capped cylinders and capped cones at every scale from `1e-300`
/// to `1e300`: a ray a radius and a half outside the rim misses, one half a
/// radius inside hits. Their rim, height and nappe tests squared (or raised
/// to the fourth and sixth powers) lengths in `f64`, which underflowed
/// below about `1e-51` and overflowed above `1e51`; there every ray down
/// the axis's direction "hit", far outside the shape.
#[test]
fn rims_hold_at_every_scale() {
    use exactray::interval::Interval;
    use exactray::query::ray::{Ray, RayCast};
    use exactray::shape::{CappedCylinder, Cone, Disk};
    for s in [
        1e-300, 1e-200, 1e-100, 1e-51, 1.0, 1e51, 1e100, 1e200, 1e300,
    ] {
        let disk = Disk::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], s).unwrap();
        let cylinder = CappedCylinder::new([0.0, 0.0, 0.0], [0.0, 0.0, s], s).unwrap();
        let cone = Cone::new([0.0, 0.0, 0.0], [0.0, 0.0, s], s).unwrap();
        let down = |x: f64| Ray::new([x * s, 0.0, 2.0 * s], [0.0, 0.0, -1.0]).unwrap();
        let across = |y: f64| Ray::new([-3.0 * s, y * s, 0.5 * s], [1.0, 0.0, 0.0]).unwrap();
        let f = Interval::FORWARD;
        assert!(
            disk.cast(&down(0.5), f).is_some() && disk.cast(&down(1.5), f).is_none(),
            "disk {s}"
        );
        assert!(
            cylinder.cast(&down(0.5), f).is_some() && cylinder.cast(&down(1.5), f).is_none(),
            "cylinder cap {s}"
        );
        assert!(
            cylinder.cast(&across(0.5), f).is_some() && cylinder.cast(&across(1.5), f).is_none(),
            "cylinder side {s}"
        );
        assert!(
            cone.cast(&down(0.5), f).is_some() && cone.cast(&down(1.5), f).is_none(),
            "cone {s}"
        );
        // Above the cylinder's top cap, parallel to it: no hit on the side.
        let above = Ray::new([-3.0 * s, 0.0, 1.5 * s], [1.0, 0.0, 0.0]).unwrap();
        assert!(cylinder.cast(&above, f).is_none(), "above the cylinder {s}");
    }
}
