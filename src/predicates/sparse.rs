//! Exact signs of determinants over coordinates that span thousands of bits
//! but have few significant ones: sparse exact terms with explicit exponents.
//!
//! A finite `f64` is `m * 2^e` with `|m| < 2^53`. The difference of two of
//! them is one such term when their exponents are close, and otherwise
//! exactly the two terms themselves (no rounding: the difference is never
//! formed). A product of `K <= 5` differences is a sum of at most `2^K`
//! exact products of terms, each a magnitude below `2^(63 K)` times a
//! power of two. A determinant is a signed sum of such products, so its
//! sign is the sign of a sum of exact terms whose exponents may lie
//! thousands of bits apart.
//!
//! That sign comes from the largest terms: taken from the top down, each
//! is multiplied out only when reached and added into a running sum of a
//! few limbs that slides down with them, until the running sum is too
//! large for the terms left to change its sign (see [`sign_of_sum`]).
//!
//! For the hard mixed-magnitude inputs (a configuration near `2^1000`
//! decided by offsets near `2^-1000`, or coordinates each at its own
//! exponent) this costs some dozens to hundreds of small integer products
//! instead of products of dense integers thousands of bits wide.
//!
//! Each predicate builds its own terms beside it (`sparse_sign` in its
//! file); this module holds what they share: the expansions of the
//! lifted determinants, the cheapest origin, and the 2x2 and 3x3
//! determinants of exact differences.

use crate::arith::scaled_float::ScaledFloat;
use crate::arith::sparse_sum::{Diff, MAX_TERMS, Terms, diff, sign_of_sum, value_of_sum};
use crate::sign::Sign;

/// An expansion of a determinant into signed products of `K` differences.
pub(super) trait Expansion<const K: usize> {
    /// Calls `push` with each signed product (`true`: negated).
    fn products(&self, push: &mut impl FnMut(bool, [Diff; K]));
}

/// The exact sign of the sum of an expansion's products, negated with
/// `negate`; `None` when they do not fit.
pub(super) fn lifted_sign<const N: usize, const L: usize, const K: usize>(
    expansion: impl Expansion<K>,
    negate: bool,
) -> Option<Sign> {
    sign_of_sum(&mut lifted_terms::<N, L, K>(expansion)).map(|s| if negate { -s } else { s })
}

/// The sum of an expansion's products within a relative `2^-52`
/// ([`value_of_sum`]), negated with `negate`; `None` when they do not fit.
pub(super) fn lifted_value<const N: usize, const L: usize, const K: usize>(
    expansion: impl Expansion<K>,
    negate: bool,
) -> Option<ScaledFloat> {
    value_of_sum(&mut lifted_terms::<N, L, K>(expansion)).map(|v| if negate { v.neg() } else { v })
}

/// An expansion's products as the terms of a sum.
fn lifted_terms<const N: usize, const L: usize, const K: usize>(
    expansion: impl Expansion<K>,
) -> Terms<N, L> {
    let mut terms = Terms::<N, L>::new();
    expansion.products(&mut |neg, f| terms.push_product(neg, &f));
    terms
}

/// One of two expansions of one determinant, whichever a predicate picked.
pub(super) enum Either<A, B> {
    First(A),
    Second(B),
}

impl<const K: usize, A: Expansion<K>, B: Expansion<K>> Expansion<K> for Either<A, B> {
    fn products(&self, push: &mut impl FnMut(bool, [Diff; K])) {
        match self {
            Either::First(a) => a.products(push),
            Either::Second(b) => b.products(push),
        }
    }
}

/// How many terms the products of an expansion add up to.
pub(super) fn product_terms<const K: usize>(expansion: &impl Expansion<K>) -> usize {
    let mut n = 0;
    expansion.products(&mut |_, f| n += f.iter().map(Diff::len).product::<usize>());
    n
}

/// The products of the determinant of the `N x N` matrix whose row `i` is
/// `(p_i, |p_i|^2, 1)`, `p_i` a point of `D = N - 2` coordinates, over the
/// coordinates themselves: for each permutation, `D` coordinates times one
/// squared coordinate of the lift (`K = D + 2` factors, each the one-term
/// "difference" `v - 0`), with the permutation's sign.
pub(super) fn lifted_monomials<const N: usize, const D: usize>(
    p: &[[f64; D]; N],
) -> Monomials<N, D> {
    Monomials(p.map(|q| q.map(|x| diff(x, 0.0))))
}

/// The coordinates of [`lifted_monomials`], as one-term differences.
pub(super) struct Monomials<const N: usize, const D: usize>([[Diff; D]; N]);

impl<const N: usize, const D: usize, const K: usize> Expansion<K> for Monomials<N, D> {
    fn products(&self, push: &mut impl FnMut(bool, [Diff; K])) {
        const { assert!(K == D + 2 && N == D + 2) };
        let v = &self.0;
        // `perm[c]` is the row of column `c`. Heap's algorithm: each
        // permutation differs from the last by one swap, so the parity
        // alternates.
        let mut perm: [usize; N] = core::array::from_fn(|i| i);
        let mut odd = false;
        let mut c = [0usize; N];
        let mut visit = |perm: &[usize; N], odd: bool| {
            let lift = perm[D];
            for j in 0..D {
                let f: [Diff; K] =
                    core::array::from_fn(|t| if t < D { v[perm[t]][t] } else { v[lift][j] });
                push(odd, f);
            }
        };
        visit(&perm, odd);
        let mut i = 1;
        while i < N {
            if c[i] < i {
                perm.swap(if i % 2 == 0 { 0 } else { c[i] }, i);
                odd = !odd;
                visit(&perm, odd);
                c[i] += 1;
                i = 1;
            } else {
                c[i] = 0;
                i += 1;
            }
        }
    }
}

/// The point whose coordinate differences to the others split into the
/// fewest two-term parts (see [`diff`]): the cheapest origin.
pub(super) fn reference<const N: usize, const D: usize>(p: &[[f64; D]; N]) -> usize {
    let mut parts = [0usize; N];
    for i in 0..N {
        for j in i + 1..N {
            let two = (0..D)
                .filter(|&c| diff(p[i][c], p[j][c]).len() == 2)
                .count();
            parts[i] += two;
            parts[j] += two;
        }
    }
    (0..N).min_by_key(|&i| parts[i]).unwrap_or(N - 1)
}

/// The exact sign of `e x f` for exact differences `e`, `f`, or `None`
/// when the terms do not fit.
pub(super) fn cross2_of(e: [Diff; 2], f: [Diff; 2]) -> Option<Sign> {
    sign_of_sum(&mut cross2_terms(e, f))
}

/// The terms of `e x f`, for [`cross2_of`] and its value.
pub(super) fn cross2_terms(e: [Diff; 2], f: [Diff; 2]) -> Terms<8, 2> {
    let mut terms = Terms::<8, 2>::new();
    terms.push_product(false, &[e[0], f[1]]);
    terms.push_product(true, &[e[1], f[0]]);
    terms
}

/// The exact sign of `det[b, c, d]` for rows of exact differences (also
/// the implicit points' weights).
pub(super) fn det3(b: [Diff; 3], c: [Diff; 3], d: [Diff; 3]) -> Option<Sign> {
    sign_of_sum(&mut det3_terms(b, c, d))
}

/// The terms of `det[b, c, d]`, for [`det3`] and its value.
pub(super) fn det3_terms(b: [Diff; 3], c: [Diff; 3], d: [Diff; 3]) -> Terms<MAX_TERMS, 3> {
    let mut terms = Terms::<MAX_TERMS, 3>::new();
    // Expanded along z: z_u * (x_v y_w - x_w y_v) over (u, v, w) cyclic.
    for (u, v, w) in [(b, c, d), (c, d, b), (d, b, c)] {
        terms.push_product(false, &[u[2], v[0], w[1]]);
        terms.push_product(true, &[u[2], w[0], v[1]]);
    }
    terms
}

#[cfg(test)]
mod tests {
    use super::super::incircle::{self, incircle_translated};
    use super::super::insphere::{self, insphere_translated};
    use super::super::{orient2d as o2, orient3d as o3};
    use super::*;
    use crate::arith::exponent::pow2;
    use crate::testing::{
        InputClass, SplitMix64, incircle_case, insphere_case, orient2d_case, orient3d_case,
    };
    use glam::{DVec2, DVec3};

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

    /// Test case `i` of a 2D and a 3D predicate: every third from their
    /// input classes, the others built to cancel.
    fn case<const M: usize, const N: usize>(
        i: usize,
        rng: &mut SplitMix64,
        two: fn(InputClass, &mut SplitMix64) -> [DVec2; M],
        three: fn(InputClass, &mut SplitMix64) -> [DVec3; N],
    ) -> ([DVec2; M], [DVec3; N]) {
        if i.is_multiple_of(3) {
            let class = InputClass::ALL[i % 6];
            (two(class, rng), three(class, rng))
        } else {
            let an = anchors(rng);
            let mut c = || coord(rng, &an);
            (
                [(); M].map(|_| DVec2::new(c(), c())),
                [(); N].map(|_| DVec3::new(c(), c(), c())),
            )
        }
    }

    #[test]
    fn matches_dense_integers() {
        let mut rng = SplitMix64::new(2024);
        let (mut declined, mut zero) = (0, 0);
        for i in 0..60_000 {
            let (p2, p3) = case(i, &mut rng, orient2d_case, orient3d_case);
            match o2::sparse_sign(p2[0], p2[1], p2[2]) {
                Some(s) => assert_eq!(s, o2::dense(p2[0], p2[1], p2[2]), "{p2:?}"),
                None => declined += 1,
            }
            match o3::sparse_sign(p3[0], p3[1], p3[2], p3[3]) {
                Some(s) => {
                    assert_eq!(s, o3::dense(p3), "{p3:?}");
                    zero += (s == Sign::Zero) as u32;
                }
                None => declined += 1,
            }
        }
        // The generator does reach exact cancellation.
        assert!(zero > 100, "{zero}");
        assert!(declined < 1000, "{declined}");
    }

    /// Every expansion of the lifted predicates (with each point as the
    /// origin, and over the coordinates) against the dense integers, on
    /// every input class and on coordinates built to cancel.
    #[test]
    fn lifted_matches_dense_integers() {
        let mut rng = SplitMix64::new(99);
        let (mut declined, mut zero) = (0, 0);
        for i in 0..3_000 {
            let (p2, p3) = case(i, &mut rng, incircle_case, insphere_case);
            let exact2 = incircle::dense(p2);
            let c2 = p2.map(|v| [v.x, v.y]);
            let ways2: [Option<Sign>; 6] = core::array::from_fn(|k| match k {
                0..4 => lifted_sign::<48, 4, 4>(incircle_translated(&c2, k), k % 2 == 0),
                4 => lifted_sign::<48, 4, 4>(lifted_monomials::<4, 2>(&c2), false),
                _ => incircle::sparse_sign(p2),
            });
            let exact3 = insphere::dense(p3);
            let c3 = p3.map(|v| v.to_array());
            let ways3: [Option<Sign>; 7] = core::array::from_fn(|k| match k {
                0..5 => {
                    lifted_sign::<360, 5, 5>(insphere_translated(&c3, k), k % 2 == 1).map(|s| -s)
                }
                5 => lifted_sign::<360, 5, 5>(lifted_monomials::<5, 3>(&c3), false).map(|s| -s),
                _ => insphere::sparse_sign(p3),
            });
            // The expansion over the coordinates always fits, and so does
            // the one the predicates pick; a translated one with a poor
            // origin may not.
            assert!(ways2[4..].iter().chain(&ways3[5..]).all(Option::is_some));
            for s in ways2 {
                match s {
                    Some(s) => assert_eq!(s, exact2, "{p2:?}"),
                    None => declined += 1,
                }
            }
            for s in ways3 {
                match s {
                    Some(s) => assert_eq!(s, exact3, "{p3:?}"),
                    None => declined += 1,
                }
            }
            zero += (exact2 == Sign::Zero) as u32 + (exact3 == Sign::Zero) as u32;
        }
        assert!(zero > 200, "{zero}");
        assert!(declined < 20_000, "{declined}");
    }
}
