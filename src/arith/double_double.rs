//! Determinants `x . (a x b)` whose rows are input vectors or exact
//! differences of input points, in double-double: the rows as exact pairs
//! (TwoSum), the products as exact pairs (TwoProduct; N. Higham, *Accuracy
//! and Stability of Numerical Algorithms*, 2nd ed., §4.3), only the
//! second-order terms rounded, with a bound on the error of the result
//! relative to the determinant's permanent: `u |value| + 61 u^2 Σ |x_i|
//! P_i` ([`dot_dd`]). The filtered stages of the ray–triangle tests
//! (`query::ray::triangle`'s plane parameter, `predicates::orient_dir`) use them inside `fma_dispatch::with_fma`'s
//! kernel, where each `fma` is one instruction and the lanes are vector
//! registers.

use super::error_free::{exact_difference, two_prod, two_sum};
use super::exponent::pow2;
use super::roundoff::U;
use super::std_or_libm::fma;
use glam::DVec3;

/// The absolute slack for underflowed products: at most thirty roundings
/// of `2^-1075`, times a coordinate below `2^300` ([`MAX_MAGNITUDE`]), is
/// below `2^-760`.
pub(crate) const SLACK: f64 = pow2(-700);

/// The largest magnitude of a row the bounds hold for: below it, no
/// product of three coordinates overflows.
const MAX_MAGNITUDE: f64 = pow2(300);

/// A row of a determinant: a vector's `x, y, z` and a zero, four lanes
/// which the compiler keeps in one register of the FMA kernel, so that
/// each step below is one instruction for all three components.
pub(crate) type Row = [f64; 4];

/// `v` as a [`Row`].
#[inline(always)]
pub(crate) fn row(v: DVec3) -> Row {
    [v.x, v.y, v.z, 0.0]
}

/// `a - b` exactly, as a double-double `(hi, lo)` per lane
/// ([`exact_difference`]).
#[inline(always)]
pub(crate) fn difference(a: DVec3, b: DVec3) -> (Row, Row) {
    let (hi, lo) = exact_difference(a, b);
    (row(hi), row(lo))
}

/// Whether every lane of `rows` is at most [`MAX_MAGNITUDE`] in magnitude:
/// false where a difference overflowed (or for NaN).
#[inline(always)]
pub(crate) fn in_range(rows: &[Row]) -> bool {
    rows.iter()
        .flatten()
        .fold(true, |ok, x| ok & (x.abs() <= MAX_MAGNITUDE))
}

/// `f` on each lane.
#[inline(always)]
pub(crate) fn each<T>(f: impl Fn(usize) -> T) -> [T; 4] {
    [f(0), f(1), f(2), f(3)]
}

/// Component `i` moved to lane `i - 1` (`j` of the cross product's `i, j,
/// k`) or, with `K`, to lane `i - 2` (`k`); the zero stays in place.
#[inline(always)]
fn rotated<const K: bool>(v: Row) -> Row {
    if K {
        [v[2], v[0], v[1], v[3]]
    } else {
        [v[1], v[2], v[0], v[3]]
    }
}

/// The normal `(ah + al) x (bh + bl)` as an unevaluated pair `hi + lo`, for
/// `|al| <= u |ah|` and `|bl| <= u |bh|` componentwise, with each
/// component's permanent `P_i = |ah_j bh_k| + |ah_k bh_j|` (rounded).
pub(crate) struct Normal {
    pub hi: Row,
    pub lo: Row,
    pub perm: Row,
}

/// [`Normal`]: `ah_j bh_k - ah_k bh_j` is exact as `hi_i` plus three error
/// terms (two TwoProducts and a TwoSum, each below `u` of `P_i`); with the
/// four cross terms `ah bl`, `al bh` (each below `u` of its product) they
/// sum to at most `4 u P_i` in `lo_i`, rounded six times: within `24 u^2
/// P_i`. The dropped `al bl` terms add `u^2 P_i`: so `|hi_i + lo_i - n_i|
/// <= 25 u^2 P_i` and `|lo_i| <= 4 u P_i`, to first order.
#[inline(always)]
pub(crate) fn cross_dd((ah, al): (Row, Row), (bh, bl): (Row, Row)) -> Normal {
    let (ahj, ahk, alj, alk) = (
        rotated::<false>(ah),
        rotated::<true>(ah),
        rotated::<false>(al),
        rotated::<true>(al),
    );
    let (bhj, bhk, blj, blk) = (
        rotated::<false>(bh),
        rotated::<true>(bh),
        rotated::<false>(bl),
        rotated::<true>(bl),
    );
    let p = each(|i| two_prod(ahj[i], bhk[i]));
    let q = each(|i| two_prod(ahk[i], bhj[i]));
    let s = each(|i| two_sum(p[i].0, -q[i].0));
    Normal {
        hi: each(|i| s[i].0),
        lo: each(|i| {
            let tail = (p[i].1 - q[i].1) + s[i].1;
            let tail = fma(ahj[i], blk[i], tail);
            let tail = fma(alj[i], bhk[i], tail);
            let tail = fma(-ahk[i], blj[i], tail);
            fma(-alk[i], bhj[i], tail)
        }),
        perm: each(|i| p[i].0.abs() + q[i].0.abs()),
    }
}

/// `(xh + xl) . n` rounded (`xl` zero where `None`), for `|xl| <= u |xh|`,
/// and the determinant's permanent `Σ |xh_i| P_i` (rounded), which bounds
/// its error. The three high products are exact (TwoProduct) and summed
/// exactly (TwoSum); the low terms (the products' errors, the TwoSums'
/// errors, `xh n.lo` and `xl n.hi`) sum to at most `8 u Σ |xh_i| P_i` and
/// are rounded at most four times on the way to any of them (each lane
/// twice, then a tree of sums): `32 u^2`. The dropped `xl n.lo` adds `4
/// u^2`, and `n`'s own error `25 u^2`, times `|x_i|`; the final sum rounds
/// once more. So the result is within `u |value| + 61 u^2 Σ |xh_i| P_i` to
/// first order.
#[inline(always)]
pub(crate) fn dot_dd(xh: Row, xl: Option<Row>, n: &Normal) -> (f64, f64) {
    let h = each(|i| two_prod(xh[i], n.hi[i]));
    let lo = each(|i| {
        let lo = fma(xh[i], n.lo[i], h[i].1);
        match xl {
            Some(xl) => fma(xl[i], n.hi[i], lo),
            None => lo,
        }
    });
    let (s1, b1) = two_sum(h[0].0, h[1].0);
    let (s2, b2) = two_sum(s1, h[2].0);
    let lo = (lo[0] + lo[1]) + (lo[2] + (b1 + b2));
    let perm = xh[0].abs() * n.perm[0] + xh[1].abs() * n.perm[1] + xh[2].abs() * n.perm[2];
    (s2 + lo, perm)
}

/// An unevaluated double-double `hi + lo`: the one pair type of the
/// double-double evaluations (the cone's and the sphere's precise tiers;
/// the determinant rows above are its four-lane form). Each operation
/// states what it rounds; none renormalizes unless it says so.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct DoubleDouble {
    pub hi: f64,
    pub lo: f64,
}

impl DoubleDouble {
    /// `a + b` exactly (TwoSum; Higham, *Accuracy and Stability*, 2nd ed.,
    /// §4.3), for a sum that does not overflow: `hi = fl(a + b)`.
    #[inline(always)]
    pub(crate) fn sum(a: f64, b: f64) -> DoubleDouble {
        let (hi, lo) = two_sum(a, b);
        DoubleDouble { hi, lo }
    }

    /// `a b` exactly (TwoProduct, one FMA), unless the product underflows
    /// (then off by at most `2^-1075`) or overflows: `hi = fl(a b)`.
    #[inline(always)]
    pub(crate) fn product(a: f64, b: f64) -> DoubleDouble {
        let (hi, lo) = two_prod(a, b);
        DoubleDouble { hi, lo }
    }

    /// The pair renormalized, exactly (TwoSum): `|lo| <= u |hi|` after.
    #[inline(always)]
    pub(crate) fn renormalized(self) -> DoubleDouble {
        DoubleDouble::sum(self.hi, self.lo)
    }

    /// The square: `hi^2` exactly as a pair (TwoProduct), its low part
    /// with `2 hi lo` in one FMA. Rounds once (`u` of the low part) and
    /// drops `lo^2`. Not normalized.
    #[inline(always)]
    pub(crate) fn square(self) -> DoubleDouble {
        let q = DoubleDouble::product(self.hi, self.hi);
        DoubleDouble {
            hi: q.hi,
            lo: fma(2.0 * self.hi, self.lo, q.lo),
        }
    }

    /// The product: `hi hi'` exactly as a pair, the cross terms added to
    /// its low part by two FMAs. Rounds twice (each within `u` of the
    /// partial low part) and drops `lo lo'`. Not normalized.
    #[inline(always)]
    pub(crate) fn times(self, x: DoubleDouble) -> DoubleDouble {
        let p = DoubleDouble::product(self.hi, x.hi);
        DoubleDouble {
            hi: p.hi,
            lo: fma(self.hi, x.lo, fma(self.lo, x.hi, p.lo)),
        }
    }

    /// The product by an `f64`: `hi a` exactly as a pair, `lo a` added to
    /// its low part by one FMA. Rounds once. Not normalized.
    #[inline(always)]
    pub(crate) fn times_f64(self, a: f64) -> DoubleDouble {
        let p = DoubleDouble::product(self.hi, a);
        DoubleDouble {
            hi: p.hi,
            lo: fma(self.lo, a, p.lo),
        }
    }

    /// The sum of three: the high parts exactly (TwoSum), the five
    /// low-order terms in a tree of depth three (three roundings on any
    /// term's path). Not normalized.
    #[inline(always)]
    pub(crate) fn sum3([x, y, z]: [DoubleDouble; 3]) -> DoubleDouble {
        let s1 = DoubleDouble::sum(x.hi, y.hi);
        let s2 = DoubleDouble::sum(s1.hi, z.hi);
        DoubleDouble {
            hi: s2.hi,
            lo: (x.lo + y.lo) + (z.lo + (s1.lo + s2.lo)),
        }
    }

    /// `self - x` rounded to one `f64`: the high parts exactly (TwoSum),
    /// the low-order terms with two roundings, the result once more.
    #[inline(always)]
    pub(crate) fn minus(self, x: DoubleDouble) -> f64 {
        let f = DoubleDouble::sum(self.hi, -x.hi);
        f.hi + ((self.lo - x.lo) + f.lo)
    }

    /// `|hi| + |lo|`.
    #[inline(always)]
    pub(crate) fn magnitude(self) -> f64 {
        self.hi.abs() + self.lo.abs()
    }
}

/// A double-double within `err` of the exact value it stands for.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Approximate {
    pub value: DoubleDouble,
    pub err: f64,
}

impl Approximate {
    /// The square ([`DoubleDouble::square`]) with its bound: the low
    /// part's one rounding (`u` of it), the dropped `lo^2`, and the error
    /// `δ` carried through `(v + δ)^2 - v^2 = δ (2 v + δ)`.
    #[inline(always)]
    pub(crate) fn square(self) -> Approximate {
        let (v, e) = (self.value, self.err);
        let sq = v.square();
        Approximate {
            value: sq,
            err: U * sq.lo.abs() + v.lo * v.lo + e * (2.0 * v.magnitude() + e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{SplitMix64, step_ulps};
    use num_bigint::BigInt;

    /// `v` as `m 2^e` with an integer `m`.
    fn parts(v: f64) -> (BigInt, i32) {
        if v == 0.0 {
            return (BigInt::from(0), -1074);
        }
        let bits = v.to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i32;
        let frac = bits & ((1 << 52) - 1);
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1 << 52), exp - 1075)
        };
        let m = BigInt::from(m);
        (if v < 0.0 { -m } else { m }, e)
    }

    /// `v` as an integer multiple of `2^lo` (`lo` at most `v`'s exponent).
    fn at(v: f64, lo: i32) -> BigInt {
        let (m, e) = parts(v);
        m << (e - lo) as usize
    }

    /// Whether `|value - exact 2^(3 lo)| <= bound` exactly.
    fn within(value: f64, exact: &BigInt, lo: i32, bound: f64) -> bool {
        let low = [value, bound]
            .iter()
            .map(|&x| parts(x).1)
            .min()
            .unwrap()
            .min(3 * lo);
        let exact = exact << (3 * lo - low) as usize;
        let err = at(value, low) - exact;
        let err = if err < BigInt::from(0) { -err } else { err };
        err <= at(bound, low)
    }

    fn det3(r: [[BigInt; 3]; 3]) -> BigInt {
        let m =
            |i: usize, j: usize, k: usize| &r[0][i] * (&r[1][j] * &r[2][k] - &r[1][k] * &r[2][j]);
        m(0, 1, 2) + m(1, 2, 0) + m(2, 0, 1)
    }

    /// A triangle and a ray at random scales and offsets, some nearly
    /// parallel to the plane and some with the origin nearly on it.
    fn case(rng: &mut SplitMix64) -> (DVec3, DVec3, [DVec3; 3]) {
        let point = |rng: &mut SplitMix64, r: f64| {
            DVec3::new(
                rng.next_f64() - 0.5,
                rng.next_f64() - 0.5,
                rng.next_f64() - 0.5,
            ) * r
        };
        let scale = 2f64.powi((rng.next_u64() % 80) as i32 - 40);
        // Half the triangles about the origin, where their edges are
        // rarely exact differences; the others offset, where they often are.
        let far = 2f64.powi((rng.next_u64() % 30) as i32);
        let offset = point(rng, scale * far) * (rng.next_u64() % 2) as f64;
        let v = [0; 3].map(|_| {
            let size = 2f64.powi((rng.next_u64() % 8) as i32);
            offset + point(rng, scale * size)
        });
        let far = 2f64.powi((rng.next_u64() % 40) as i32);
        let o = offset + point(rng, scale * far);
        let target = v[0] + (v[1] - v[0]) * rng.next_f64() + (v[2] - v[0]) * rng.next_f64();
        let d = match rng.next_u64() % 3 {
            // Nearly parallel to the plane: along an edge, nudged.
            0 => (v[1] - v[0])
                .to_array()
                .map(|x| step_ulps(x, (rng.next_u64() % 9) as i64 - 4)),
            _ => (target - o).to_array(),
        };
        (o, DVec3::from_array(d), v)
    }

    /// Each determinant is within the stated bound of the exact one:
    /// `u |value| + 61 u^2` of the permanent (with a little room for the
    /// rounding of the permanent itself).
    #[test]
    fn double_double_determinants_within_their_bounds() {
        let mut rng = SplitMix64::new(0x5eed);
        for _ in 0..20_000 {
            let (o, d, [v0, v1, v2]) = case(&mut rng);
            let (w, e1, e2) = (difference(v0, o), difference(v1, v0), difference(v2, v0));
            let n = cross_dd(e1, e2);
            let results = [dot_dd(row(d), None, &n), dot_dd(w.0, Some(w.1), &n)];
            let all = [o, d, v0, v1, v2].map(|p| p.to_array()).concat();
            let lo = all.iter().map(|&x| parts(x).1).min().unwrap();
            let int = |p: DVec3| p.to_array().map(|x| at(x, lo));
            let sub = |a: [BigInt; 3], b: [BigInt; 3]| [0, 1, 2].map(|i| &a[i] - &b[i]);
            let (e1x, e2x) = (sub(int(v1), int(v0)), sub(int(v2), int(v0)));
            let exact = [
                det3([int(d), e1x.clone(), e2x.clone()]),
                det3([sub(int(v0), int(o)), e1x, e2x]),
            ];
            for ((value, perm), exact) in results.iter().zip(&exact) {
                let bound = U * value.abs() * (1.0 + 4.0 * U) + 64.0 * U * U * perm;
                assert!(
                    within(*value, exact, lo, bound),
                    "{o:?} {d:?} {v0:?} {v1:?} {v2:?}: {value} beyond {bound}"
                );
            }
        }
    }
}
