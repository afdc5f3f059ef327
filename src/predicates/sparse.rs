//! Exact signs of determinants over coordinates that span thousands of bits
//! but have few significant ones: sparse exact terms with explicit exponents.
//!
//! A finite `f64` is `m * 2^e` with `|m| < 2^53`. The difference of two of
//! them is one such term when their exponents are close, and otherwise
//! exactly the two terms themselves (no rounding: the difference is never
//! formed). A product of `K <= 3` differences is a sum of at most `2^K`
//! exact products of terms, each a magnitude below `2^189` (three limbs)
//! times a power of two. A determinant is a signed sum of such products, so
//! its sign is the sign of a sum of at most [`MAX_TERMS`] exact terms whose
//! exponents may lie thousands of bits apart.
//!
//! That sign comes from the top *cluster* of terms: sort the terms by their
//! top bit, and gather terms from the top until the next term's top bit
//! lies so far below the lowest bit of the gathered ones that the rest
//! cannot reach it (see [`sign_of_sum`]). The cluster's exact sum, when not
//! zero, decides the sign; when zero, the next cluster does. A cluster is
//! summed in a fixed accumulator of [`ACC_LIMBS`] limbs; a wider one makes
//! the function decline (`None`) and the caller uses its dense integers.
//!
//! For the hard mixed-magnitude inputs (a configuration near `2^1000`
//! decided by offsets near `2^-1000`) this costs a few dozen small integer
//! products instead of products of dense 2,000-bit integers.

use crate::arith::sparse_sum::{Diff, MAX_TERMS, Terms, diff, sign_of_sum};
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// The exact sign of `(b - a) x (c - a)` for finite input, or `None` when
/// the terms do not fit the accumulators.
pub(super) fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Option<Sign> {
    let (bx, by) = (diff(b.x, a.x), diff(b.y, a.y));
    let (cx, cy) = (diff(c.x, a.x), diff(c.y, a.y));
    let mut terms = Terms::<8>::new();
    terms.push_product(false, [bx, cy]);
    terms.push_product(true, [by, cx]);
    sign_of_sum(&mut terms)
}

/// The exact sign of `det[b - a, c - a, d - a]` for finite input, or `None`
/// when the terms do not fit the accumulators.
pub(super) fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Option<Sign> {
    let rel = |p: DVec3| [diff(p.x, a.x), diff(p.y, a.y), diff(p.z, a.z)];
    det3(rel(b), rel(c), rel(d))
}

/// The exact sign of `det[d, p - o, q - o]` for finite input (a ray's
/// direction `d` and two points seen from its origin `o`), or `None` when
/// the terms do not fit the accumulators.
pub(super) fn orient_dir(d: DVec3, o: DVec3, p: DVec3, q: DVec3) -> Option<Sign> {
    let rel = |p: DVec3| [diff(p.x, o.x), diff(p.y, o.y), diff(p.z, o.z)];
    // `d - 0` is the one exact term `d` (a zero difference has none).
    let dir = [diff(d.x, 0.0), diff(d.y, 0.0), diff(d.z, 0.0)];
    det3(dir, rel(p), rel(q))
}

/// The exact sign of `det[b, c, d]` for rows of exact differences.
fn det3(b: [Diff; 3], c: [Diff; 3], d: [Diff; 3]) -> Option<Sign> {
    let mut terms = Terms::<MAX_TERMS>::new();
    // Expanded along z: z_u * (x_v y_w - x_w y_v) over (u, v, w) cyclic.
    for (u, v, w) in [(b, c, d), (c, d, b), (d, b, c)] {
        terms.push_product(false, [u[2], v[0], w[1]]);
        terms.push_product(true, [u[2], w[0], v[1]]);
    }
    sign_of_sum(&mut terms)
}

#[cfg(test)]
mod tests {
    use super::super::{orient2d as o2, orient3d as o3};
    use super::*;
    use crate::arith::exponent::{Grain, pow2};
    use crate::arith::fixed_int::{DEG1, DEG2, DEG3};
    use crate::testing::{InputClass, SplitMix64, orient2d_case, orient3d_case};

    /// A coordinate built to cancel: a few shared anchors at scattered
    /// exponents, moved by a few ulps or by a tiny offset, or zero.
    fn coord(rng: &mut SplitMix64, anchors: &[f64; 4]) -> f64 {
        let pick = (rng.next_u64() % 4) as usize;
        let base = anchors[pick];
        match rng.next_u64() % 8 {
            0 => 0.0,
            1 => f64::from_bits(rng.next_u64() >> 12), // subnormal or tiny
            2 => base + base * f64::EPSILON * ((rng.next_u64() % 5) as f64 - 2.0),
            3 => -base,
            4 => base * pow2((rng.next_u64() % 200) as i32 - 100),
            5 => base + pow2(-1074 + (rng.next_u64() % 2000) as i32),
            _ => base,
        }
    }

    fn anchors(rng: &mut SplitMix64) -> [f64; 4] {
        core::array::from_fn(|_| {
            let e = (rng.next_u64() % 2040) as i32 - 1020;
            (rng.next_f64() + 0.5) * pow2(e)
        })
    }

    fn dense2(p: [DVec2; 3]) -> Sign {
        let gx = Grain::of(&[p[0].x, p[1].x, p[2].x]);
        let gy = Grain::of(&[p[0].y, p[1].y, p[2].y]);
        if gx.all_zero() || gy.all_zero() {
            return Sign::Zero;
        }
        o2::big_integer(p[0], p[1], p[2], gx.lo_min, gy.lo_min)
    }

    fn dense3(p: [DVec3; 4]) -> Sign {
        let axis = |k: usize| [p[0][k], p[1][k], p[2][k], p[3][k]];
        let g = [0, 1, 2].map(|k| Grain::of(&axis(k)));
        if g.iter().any(|g| g.all_zero()) {
            return Sign::Zero;
        }
        o3::integer::<DEG1, DEG2, DEG3>(&p, g.map(|g| g.lo_min))
    }

    #[test]
    fn matches_dense_integers() {
        let mut rng = SplitMix64::new(2024);
        let (mut declined, mut zero) = (0, 0);
        for i in 0..60_000 {
            let (p2, p3) = if i % 3 == 0 {
                let class = InputClass::ALL[i % 6];
                (
                    orient2d_case(class, &mut rng),
                    orient3d_case(class, &mut rng),
                )
            } else {
                let an = anchors(&mut rng);
                let mut c = || coord(&mut rng, &an);
                (
                    [(); 3].map(|_| DVec2::new(c(), c())),
                    [(); 4].map(|_| DVec3::new(c(), c(), c())),
                )
            };
            match orient2d(p2[0], p2[1], p2[2]) {
                Some(s) => assert_eq!(s, dense2(p2), "{p2:?}"),
                None => declined += 1,
            }
            match orient3d(p3[0], p3[1], p3[2], p3[3]) {
                Some(s) => {
                    assert_eq!(s, dense3(p3), "{p3:?}");
                    zero += (s == Sign::Zero) as u32;
                }
                None => declined += 1,
            }
        }
        // The generator does reach exact cancellation.
        assert!(zero > 100, "{zero}");
        assert!(declined < 1000, "{declined}");
    }
}
