//! The parameter `t` where the line `o + t d` meets the plane of a
//! triangle `v0 v1 v2`: `det[v0 - o, e1, e2] / det[d, e1, e2]` with `e1 =
//! v1 - v0`, `e2 = v2 - v0` (Cramer's rule on `o + t d = v0 + β e1 + γ
//! e2`), rounded from its exact value. Two stages:
//!
//! - **filtered** ([`FilteredParameter`]): both determinants in
//!   double-double from error-free transformations, each certified within
//!   `1.45 u` of its value by a bound computed beside it;
//! - **exact** ([`exact_parameter`]): both determinants as integers.
//!
//! Either way the quotient is within `4 u` (`u = 2^-53`) of the exact `t`.

use super::grain::{pow2, to_integer_i64};
use super::orient_dir::{SMALL_SPAN, grains};
use super::orient3d::det3_wide;
use super::wide::Wide;
use crate::float::{FmaKernel, fma, larger, two_prod, two_sum, with_fma};
use crate::ray::Ray;
use glam::DVec3;

/// The parameter `t` where the line `o + t d` of `ray` meets the plane of
/// `v`: the relative error is below `4 * 2^-53` when the result is a
/// normal number, and below `2^-1073` absolutely when it is subnormal. A
/// result that would round to zero is the smallest subnormal of the exact
/// sign instead, so the sign is always exact. `NaN` when the line is
/// parallel to the plane (or the triangle degenerate), or for non-finite
/// input.
///
/// The filtered stage answers first, with hardware FMA where the CPU has
/// it; the exact stage where it cannot certify.
#[inline]
pub(crate) fn plane_parameter(ray: &Ray, v: &[DVec3; 3]) -> f64 {
    with_fma(&FilteredParameter { ray, v }).unwrap_or_else(|| {
        let [v0, v1, v2] = *v;
        exact_parameter(ray.origin(), ray.direction(), v0, v1, v2)
    })
}

/// The filtered stage: both determinants in double-double, each certified
/// within `1.45 u` of its value, then divided, so that the quotient is
/// within `(1.45 + 1.45 + 1) u < 4 u` of the exact one to first order (the
/// second-order terms are below `2^-100`). `None` where a bound does not
/// certify (a determinant below about `2^-45` of its permanent: a ray
/// nearly parallel to the plane, or an origin nearly on it), where a
/// magnitude exceeds `2^300` (below that no product of three overflows),
/// or where the quotient is not a normal number.
///
/// The rows are exact double-double differences (TwoSum, Higham,
/// *Accuracy and Stability of Numerical Algorithms*, 2nd ed., §4.3), the
/// normal `n = e1 x e2` a double-double within `25 u^2 P_i` per component
/// ([`cross_dd`]), each determinant `x . n` within `u |value| + 61 u^2 Σ
/// |x_i| P_i` ([`dot_dd`]); the certificate allows `128 u^2` of the
/// permanent, which also covers the rounding of the permanents
/// themselves. Underflowed products err by at most `2^-1075` each, far
/// below the absolute slack `2^-700`.
struct FilteredParameter<'a> {
    ray: &'a Ray,
    v: &'a [DVec3; 3],
}

/// `2^-53`, the unit roundoff.
const U: f64 = f64::EPSILON / 2.0;

/// The filtered stage's absolute slack for underflowed products: at most
/// thirty roundings of `2^-1075`, times a coordinate below `2^300`, is
/// below `2^-760`.
const SLACK: f64 = pow2(-700);

impl FmaKernel for FilteredParameter<'_> {
    type Output = Option<f64>;

    #[inline(always)]
    fn run(&self) -> Option<f64> {
        let [v0, v1, v2] = *self.v;
        let (o, d) = (self.ray.origin(), self.ray.direction());
        let (w, e1, e2) = (difference(v0, o), difference(v1, v0), difference(v2, v0));
        // Infinite where a difference overflowed (the inputs are finite).
        if largest_magnitude(&[w.0, e1.0, e2.0, lanes(d)]) > pow2(300) {
            return None;
        }
        let n = cross_dd(e1, e2);
        let (den, den_perm) = dot_dd(lanes(d), None, &n);
        let (num, num_perm) = dot_dd(w.0, Some(w.1), &n);
        // Each determinant within 1.45 u of its value: the u^2 terms and
        // the slack within 0.45 u of its magnitude.
        let certified = |v: f64, perm: f64| 128.0 * U * U * perm + SLACK <= 0.45 * U * v.abs();
        let t = num / den;
        (certified(den, den_perm) && certified(num, num_perm) && t.is_normal()).then_some(t)
    }
}

/// A vector's `x, y, z` and a zero: four lanes, which the compiler keeps
/// in one register of the FMA kernel, so that each step below is one
/// instruction for all three components.
type Lanes = [f64; 4];

#[inline(always)]
fn lanes(v: DVec3) -> Lanes {
    [v.x, v.y, v.z, 0.0]
}

/// `a - b` exactly, as a double-double `(hi, lo)` per lane (TwoSum; exact
/// unless a difference overflows).
#[inline(always)]
fn difference(a: DVec3, b: DVec3) -> (Lanes, Lanes) {
    let (a, b) = (lanes(a), lanes(b));
    let s = each(|i| two_sum(a[i], -b[i]));
    (each(|i| s[i].0), each(|i| s[i].1))
}

/// The largest magnitude of a lane of `vs` (infinite where one
/// overflowed).
#[inline(always)]
fn largest_magnitude(vs: &[Lanes]) -> f64 {
    vs.iter().flatten().fold(0.0, |m, x| larger(m, x.abs()))
}

/// `f` on each lane.
#[inline(always)]
fn each<T>(f: impl Fn(usize) -> T) -> [T; 4] {
    [f(0), f(1), f(2), f(3)]
}

/// Component `i` moved to lane `i - 1` (`j` of the cross product's `i, j,
/// k`) or, with `K`, to lane `i - 2` (`k`); the zero stays in place.
#[inline(always)]
fn rotated<const K: bool>(v: Lanes) -> Lanes {
    if K {
        [v[2], v[0], v[1], v[3]]
    } else {
        [v[1], v[2], v[0], v[3]]
    }
}

/// The normal `(ah + al) x (bh + bl)` as an unevaluated pair `hi + lo`, for
/// `|al| <= u |ah|` and `|bl| <= u |bh|` componentwise, with each
/// component's permanent `P_i = |ah_j bh_k| + |ah_k bh_j|` (rounded).
struct Normal {
    hi: Lanes,
    lo: Lanes,
    perm: Lanes,
}

/// [`Normal`]: `ah_j bh_k - ah_k bh_j` is exact as `hi_i` plus three error
/// terms (two TwoProducts and a TwoSum, each below `u` of `P_i`); with the
/// four cross terms `ah bl`, `al bh` (each below `u` of its product) they
/// sum to at most `4 u P_i` in `lo_i`, rounded six times: within `24 u^2
/// P_i`. The dropped `al bl` terms add `u^2 P_i`: so `|hi_i + lo_i - n_i|
/// <= 25 u^2 P_i` and `|lo_i| <= 4 u P_i`, to first order.
#[inline(always)]
fn cross_dd((ah, al): (Lanes, Lanes), (bh, bl): (Lanes, Lanes)) -> Normal {
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
fn dot_dd(xh: Lanes, xl: Option<Lanes>, n: &Normal) -> (f64, f64) {
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

/// [`plane_parameter`]'s exact stage: both determinants exact in integers.
#[cold]
#[inline(never)]
fn exact_parameter(o: DVec3, d: DVec3, v0: DVec3, v1: DVec3, v2: DVec3) -> f64 {
    if ![o, d, v0, v1, v2].iter().all(|v| v.is_finite()) {
        return f64::NAN;
    }
    let Some((lo, span)) = grains(&[o, d, v0, v1, v2]) else {
        return f64::NAN;
    };
    // Values below 2^span, rows (differences) below 2^(span + 1), minors
    // below 2^(2 span + 3), determinants below 2^(3 span + 5): the sizes
    // hold them with a sign bit to spare.
    let v = [v0, v1, v2];
    if span <= SMALL_SPAN {
        small_quotient(o, d, v, lo)
    } else if span <= 125 {
        quotient::<2, 4, 6>(o, d, v, lo)
    } else if span <= 253 {
        quotient::<4, 8, 12>(o, d, v, lo)
    } else if span <= 509 {
        quotient::<8, 16, 24>(o, d, v, lo)
    } else {
        // Every finite input, as in orient3d's last stage.
        quotient::<34, 67, 100>(o, d, v, lo)
    }
}

/// [`plane_parameter`] in native integers, for values below `2^61` at
/// the finest bit of each axis: rows in `i64` (below `2^62`), the normal
/// `e1 x e2` in `i128` (below `2^125`), the determinants as 189-bit sums.
fn small_quotient(o: DVec3, d: DVec3, v: [DVec3; 3], lo: [i32; 3]) -> f64 {
    let int = |p: DVec3| {
        [
            to_integer_i64(p.x, lo[0]),
            to_integer_i64(p.y, lo[1]),
            to_integer_i64(p.z, lo[2]),
        ]
    };
    let sub = |a: [i64; 3], b: [i64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let v0 = int(v[0]);
    let (e1, e2) = (sub(int(v[1]), v0), sub(int(v[2]), v0));
    let cross = |i: usize, j: usize| e1[i] as i128 * e2[j] as i128 - e1[j] as i128 * e2[i] as i128;
    let n = [cross(1, 2), cross(2, 0), cross(0, 1)];
    let num = dot_wide(sub(v0, int(o)), n);
    let den = dot_wide(int(d), n);
    // Both within `2^-53 (1 + 2^-11)` of the exact integers, far inside the
    // range of `f64`; the column scales cancel in the quotient.
    if den == 0.0 { f64::NAN } else { num / den }
}

/// `a . n` for `|a_k| < 2^62`, `|n_k| < 2^125`, rounded to `f64` within
/// `2^-53 (1 + 2^-11)` relative: the sum is kept exactly as a high `i128`
/// and a low `u64` word, `value = high 2^64 + low` (as in orient3d's small
/// stage), then converted from its magnitude.
fn dot_wide(a: [i64; 3], n: [i128; 3]) -> f64 {
    let mut high: i128 = 0;
    let mut low: u128 = 0;
    for k in 0..3 {
        let z = a[k] as i128;
        high += z * (n[k] >> 64);
        let zl = z * (n[k] as u64 as i128);
        high += zl >> 64;
        low += zl as u64 as u128;
    }
    high += (low >> 64) as i128;
    let low = low as u64;
    // The magnitude as `h 2^64 + l`, `h >= 0`.
    let neg = high < 0;
    let (h, l) = if neg {
        ((!high + (low == 0) as i128) as u128, low.wrapping_neg())
    } else {
        (high as u128, low)
    };
    let m = if h >> 64 == 0 {
        // Below 2^128: one correctly rounded conversion.
        ((h << 64) | l as u128) as f64
    } else {
        // `l` is below half an ulp of the rounded `h 2^64`: dropping it
        // moves the result by less than `2^-64` relative.
        h as f64 * 18446744073709551616.0
    };
    if neg { -m } else { m }
}

/// [`plane_parameter`] in `D`-limb rows, `M`-limb minors, `R`-limb
/// determinants.
fn quotient<const D: usize, const M: usize, const R: usize>(
    o: DVec3,
    d: DVec3,
    v: [DVec3; 3],
    lo: [i32; 3],
) -> f64 {
    let int = |p: DVec3| {
        [
            Wide::<D>::from_f64(p.x, lo[0]),
            Wide::from_f64(p.y, lo[1]),
            Wide::from_f64(p.z, lo[2]),
        ]
    };
    let sub =
        |a: &[Wide<D>; 3], b: &[Wide<D>; 3]| [a[0].sub(&b[0]), a[1].sub(&b[1]), a[2].sub(&b[2])];
    let (oi, v0) = (int(o), int(v[0]));
    let (e1, e2) = (sub(&int(v[1]), &v0), sub(&int(v[2]), &v0));
    let num = det3_wide::<D, M, R>(&[sub(&v0, &oi), e1, e2]);
    let den = det3_wide::<D, M, R>(&[int(d), e1, e2]);
    let ((mn, en), (md, ed)) = (num.rounded_parts(), den.rounded_parts());
    if md == 0.0 {
        return f64::NAN;
    }
    // Both scaled by the same power of two (the columns'), which cancels.
    // `mn / md` lies within [2^-64, 2^64] (or is zero) and is rounded once;
    // the scaling by `2^(en - ed)` in steps of the same sign is exact
    // unless the result is subnormal or overflows.
    let q = mn / md;
    let k = (en - ed).clamp(-2400, 2400);
    let third = k / 3;
    let t = q * pow2(third) * pow2(third) * pow2(k - 2 * third);
    if t == 0.0 && mn != 0.0 {
        f64::from_bits(1).copysign(q)
    } else {
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hard_inputs::{SplitMix64, step_ulps};
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
            let results = [dot_dd(lanes(d), None, &n), dot_dd(w.0, Some(w.1), &n)];
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
