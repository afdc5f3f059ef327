//! The default tier of the ray–quadric casts: the roots of the half-form
//! quadratic `A t^2 + 2 B t + C` from the stable formula on the `f64`
//! coefficients of a [`Coeffs`], each with an **a-priori** bound on its
//! distance from the exact root, and the root count certified by the
//! discriminant's running bound. Where the bound cannot decide the count
//! (a near-tangent line) or where a root lies within its bound of an end
//! of the cast's interval, the caller runs the precise tier
//! (`certified.rs`: every root within 4 ulps of the correctly rounded
//! one, and the exact stage behind it).
//!
//! The bounds follow from the coefficients' bounds by perturbation of the
//! stable formula. Write `D = B^2 - A C` for the exact discriminant and
//! `σ` for the sign of the computed `b` (`+1` for `+0`). With the same `σ`,
//! `Q = -(B + σ sqrt(D))` gives the exact roots `Q / A` and `C / Q` for
//! either sign (their product is `C / A` and their sum `-2 B / A`), so the
//! computed `q = -(b + σ s)`, `s = fl(sqrt(disc))`, is compared with `Q`:
//!
//! - `|s - sqrt(D)| <= u s + |disc - D| / sqrt(disc) (1 + u)`: the square
//!   root rounds once, and `|sqrt(x) - sqrt(y)| = |x - y| / (sqrt(x) +
//!   sqrt(y))` with `y = D >= 0` (certified: `disc > e_disc`);
//! - `q` rounds once in the sum, whose terms share a sign: `u |q|`;
//! - so `|q - Q| <= e_q = e_b + e_disc / s + u (s + |q|)`, to first order,
//!   taken with `1 + gamma(8)` for the `1 + u` factors and the bound's own
//!   roundings. It is kept multiplied by `s`, `e_qs = e_b s + e_disc + u
//!   (s + |q|) s`, which needs no division.
//!
//! Each root is then a quotient of values with known errors (as in
//! [`quotient_error`]): `q / a` against `Q / A` and `c / q` against `C /
//! Q`, their bounds' numerators and denominators multiplied by `s` so
//! that each root costs one division for `t` and one for its bound. Which
//! of them is the smaller exact root follows from signs alone, so the
//! order is exact too: `(-B - σ sqrt(D)) / A` is the smaller root exactly
//! when `σ` and `A` share their sign.

use super::certified::{Coeffs, Polynomial, Question, certified_first};
use super::{Roots, first_in};
use crate::arith::roundoff::{U, gamma};
use crate::arith::std_or_libm::sqrt;
use crate::interval::Interval;

/// A ray parameter with a certified bound on its error: the exact value
/// lies in `[t - error, t + error]`. `error` is infinite where no bound
/// could be certified (a `t` beyond `f64`'s range).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BoundedRoot {
    /// The parameter, rounded.
    pub t: f64,
    /// A bound on `|t - t_exact|`.
    pub error: f64,
}

/// Absolute slack for the products of [`quotient_error`] that may
/// underflow: each loses at most `2^-1075`; eight of them stay below
/// `2^-1072`.
const UNDERFLOW: f64 = f64::from_bits(4); // 2^-1072

/// `|t - t_exact|` for `t = fl(num / den)` where the exact parameter is
/// `num_exact / den_exact`, `|num - num_exact| <= e_num` and `|den -
/// den_exact| <= e_den`: with `|den| > e_den`,
/// `|num/den - num_exact/den_exact| <= (e_num + |num/den| e_den) / (|den| -
/// e_den)` (write the difference over the common denominator), and the
/// division's rounding adds `u |t|`; `|num/den| <= |t| (1 + 2u)`. The
/// bound's own roundings (six) take `1 + gamma(6)`. An infinite bound
/// where `|den| <= e_den` (the denominator may vanish).
#[inline(always)]
pub(crate) fn quotient_error(t: f64, e_num: f64, den: f64, e_den: f64) -> f64 {
    let room = den.abs() - e_den;
    // Not positive, or NaN from an overflowed bound: no certified `t`.
    if room.is_nan() || room <= 0.0 {
        return f64::INFINITY;
    }
    ((e_num + t.abs() * (1.0 + 2.0 * U) * e_den) / room + U * t.abs()) * (1.0 + gamma(6))
        + UNDERFLOW
}

/// Which tier a cast runs: the default (exact hit or miss, the stable
/// formula's root with an a-priori bound) or the precise one (every root
/// within 4 ulps of the correctly rounded root).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Tier {
    /// The default tier.
    Default,
    /// The precise tier.
    Precise,
}

/// Where a bounded root lies against a cast's interval.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Place {
    /// Its whole bound lies below the interval.
    Below,
    /// Its whole bound lies strictly inside the interval (so the exact
    /// root is admitted, and `t` is finite).
    Inside,
    /// Its whole bound lies above the interval.
    Above,
    /// The bound meets an end of the interval, or is not finite.
    Undecided,
}

impl BoundedRoot {
    /// Where the exact root lies against `range`. The comparisons are
    /// strict: for a float `m`, `fl(x) > m` implies `x > m` (rounding is
    /// monotone), so a rounded `t - error` above `range.min()` certifies
    /// the exact one; likewise below `range.max()`.
    #[inline(always)]
    pub(crate) fn place(self, range: Interval) -> Place {
        let (lo, hi) = (self.t - self.error, self.t + self.error);
        if lo > range.min() && hi < range.max() {
            Place::Inside
        } else if hi < range.min() {
            Place::Below
        } else if lo > range.max() {
            Place::Above
        } else {
            Place::Undecided
        }
    }
}

/// Whether the running bound `e_disc` certifies that the discriminant
/// `disc` is negative, so that the quadratic has no real root (a zero
/// leading coefficient would make it `B^2 >= 0`); the margin is
/// [`stable_pair`]'s. A NaN or infinite bound (overflow) certifies
/// nothing. What a cast can check before it computes the coefficients.
#[inline(always)]
pub(crate) fn certified_negative(disc: f64, e_disc: f64) -> bool {
    let e_disc = e_disc * (1.0 + 64.0 * U);
    disc < -e_disc && e_disc < f64::INFINITY
}

/// Two distinct real roots, certified: what the stable formula's two
/// quotients share.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StablePair {
    q: f64,
    /// `sqrt(disc)`, rounded.
    s: f64,
    /// A bound on `|q - Q| s`.
    e_qs: f64,
    /// Whether `q / a` is the smaller exact root.
    q_over_a_first: bool,
}

/// The count: `Some(None)` where the running bound certifies that there
/// is no real root, `Some(Some(pair))` where it certifies two distinct
/// ones, `None` where it cannot tell or the leading coefficient may be
/// zero (the caller's precise tier decides). The margin `1 + 64 u` covers
/// the first-order bounds' neglected terms, as in `certified.rs`.
#[inline(always)]
pub(crate) fn stable_pair(k: &Coeffs) -> Option<Option<StablePair>> {
    let margin = 1.0 + 64.0 * U;
    // The comparisons are false for NaN: no certificate.
    let leading_nonzero = k.a.abs() > k.e_a * margin;
    if !leading_nonzero {
        return None;
    }
    let e_disc = k.e_disc * margin;
    let two_roots = k.disc > e_disc;
    if !two_roots {
        return certified_negative(k.disc, k.e_disc).then_some(None);
    }
    let s = sqrt(k.disc);
    let q = -(k.b + s.copysign(k.b));
    let e_qs = (k.e_b * s + e_disc + U * (s + q.abs()) * s) * (1.0 + gamma(8));
    Some(Some(StablePair {
        q,
        s,
        e_qs,
        q_over_a_first: k.a.is_sign_negative() == k.b.is_sign_negative(),
    }))
}

/// The bound of [`quotient_error`] for `t = fl(num / den)`, given `e_num
/// s` and `e_den s` (the errors of the numerator and the denominator
/// multiplied by `s > 0`, each an upper bound as computed, since `e_den
/// s` is subtracted): `(e_num s + |t| (1 + 2u) e_den s) / ((|den| -
/// e_den) s) + u |t|`. The denominator is taken low: `|den| s (1 - 2u)`
/// does not exceed the exact `|den| s` (its two roundings up are at most
/// `(1 + u)^2`), less `2^-1073` for a product that underflows; the rest
/// rounds within the final margin. Infinite where the denominator may
/// vanish.
///
/// The quotient is taken as a product with `1 / room`, which does not
/// wait for `t`: the two divisions run side by side rather than one after
/// the other (two more roundings, in the final `1 + gamma(10)`).
#[inline(always)]
fn scaled_quotient_error(t: f64, e_num_s: f64, den: f64, s: f64, e_den_s: f64) -> f64 {
    let room = den.abs() * s * (1.0 - 2.0 * U) - e_den_s - f64::from_bits(2);
    // Not positive, or NaN from an overflowed bound: no certified `t`.
    if room.is_nan() || room <= 0.0 {
        return f64::INFINITY;
    }
    let inv_room = 1.0 / room;
    // Two products in the numerator may underflow (`|t|` may be tiny):
    // `2^-1073` covers both.
    ((e_num_s + t.abs() * (1.0 + 2.0 * U) * e_den_s + f64::from_bits(2)) * inv_room + U * t.abs())
        * (1.0 + gamma(10))
        + UNDERFLOW
}

impl StablePair {
    /// `q / a` and its bound.
    #[inline(always)]
    fn over_a(&self, k: &Coeffs) -> BoundedRoot {
        let t = self.q / k.a;
        BoundedRoot {
            t,
            // `e_a s` rounded up: `(1 - u)^2 (1 + 4u) > 1`.
            error: scaled_quotient_error(
                t,
                self.e_qs,
                k.a,
                self.s,
                k.e_a * self.s * (1.0 + 4.0 * U),
            ),
        }
    }

    /// `c / q` and its bound.
    #[inline(always)]
    fn under_q(&self, k: &Coeffs) -> BoundedRoot {
        let t = k.c / self.q;
        BoundedRoot {
            t,
            error: scaled_quotient_error(t, k.e_c * self.s, self.q, self.s, self.e_qs),
        }
    }

    /// The smaller exact root's approximation and bound.
    #[inline(always)]
    pub(crate) fn smaller(&self, k: &Coeffs) -> BoundedRoot {
        if self.q_over_a_first {
            self.over_a(k)
        } else {
            self.under_q(k)
        }
    }

    /// The larger exact root's approximation and bound.
    #[inline(always)]
    pub(crate) fn larger(&self, k: &Coeffs) -> BoundedRoot {
        if self.q_over_a_first {
            self.under_q(k)
        } else {
            self.over_a(k)
        }
    }
}

/// The first root inside `range`, bounded: `Some(Some(root))` with the
/// exact root certified inside `range`, `Some(None)` when no exact root is
/// (certified), `None` where the count or a root's place is undecided.
/// The larger root is computed only when the smaller lies below `range`.
#[inline(always)]
pub(crate) fn first_bounded(k: &Coeffs, range: Interval) -> Option<Option<BoundedRoot>> {
    let Some(pair) = stable_pair(k)? else {
        return Some(None);
    };
    let small = pair.smaller(k);
    match small.place(range) {
        Place::Inside => Some(Some(small)),
        Place::Above => Some(None),
        Place::Undecided => None,
        Place::Below => {
            let large = pair.larger(k);
            match large.place(range) {
                Place::Inside => Some(Some(large)),
                Place::Below | Place::Above => Some(None),
                Place::Undecided => None,
            }
        }
    }
}

/// A default-tier cast from rounded coefficients: [`first_bounded`] on
/// `k` where it decides, else `precise()` (also where `k` is `None`, out
/// of the filter's range): the hit or miss is then the precise tier's.
#[inline(always)]
pub(crate) fn first_bounded_or(
    k: Option<Coeffs>,
    range: Interval,
    precise: impl FnOnce() -> Option<BoundedRoot>,
) -> Option<BoundedRoot> {
    match k.and_then(|k| first_bounded(&k, range)) {
        Some(first) => first,
        None => precise(),
    }
}

/// Both roots, bounded and in exact order: `Some(Some([smaller, larger]))`,
/// `Some(None)` for a certified miss of the whole line, `None` where the
/// count is undecided.
#[inline(always)]
pub(crate) fn both_bounded(k: &Coeffs) -> Option<Option<[BoundedRoot; 2]>> {
    Some(stable_pair(k)?.map(|pair| [pair.smaller(k), pair.larger(k)]))
}

/// `|t - t_exact|` for a root of the precise tier: within 4 ulps of the
/// correctly rounded root (the certified stage) or within 5 ulps of the
/// exact root (the exact stage's first-order bound, `certified.rs`): an
/// ulp of a normal `t` is at most `2u |t|`, so either is within `12u
/// |t_exact|`, and `16u |t_exact| <= gamma(16) |t|` leaves room for the
/// second-order terms; a subnormal root's ulps are `2^-1074` each.
#[inline]
pub(crate) fn precise_root_error(t: f64) -> f64 {
    gamma(16) * t.abs() + f64::from_bits(16)
}

/// A precise-tier root with its bound.
#[inline]
pub(crate) fn precise(t: f64) -> BoundedRoot {
    BoundedRoot {
        t,
        error: precise_root_error(t),
    }
}

/// The first root inside an interval with a certified bound: in the
/// default tier [`first_bounded`] where it decides, else (and in the
/// precise tier) the certified root ([`certified_first`]) on the same
/// coefficients, else (`None`) the exact stage.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BoundedFirstIn(pub Interval, pub Tier);

impl Question for BoundedFirstIn {
    type Answer = Option<BoundedRoot>;

    #[inline(always)]
    fn answer(self, k: &Coeffs, p: &impl Polynomial) -> Option<Option<BoundedRoot>> {
        let fast = match self.1 {
            Tier::Default => first_bounded(k, self.0),
            Tier::Precise => None,
        };
        fast.or_else(|| certified_first(k, p, self.0).map(|first| first.map(precise)))
    }

    #[inline(always)]
    fn exact_answer(self, roots: Roots) -> Option<BoundedRoot> {
        let t = first_in(roots, self.0)?;
        Some(match roots {
            // The point of the range nearest 0, exactly on the surface.
            Roots::All => BoundedRoot { t, error: 0.0 },
            _ => precise(t),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `(t - 1)(t - 3) = t^2 - 4 t + 3`: half form `A = 1`, `B = -2`,
    /// `C = 3`, exact coefficients (zero bounds) and both signs of `A`.
    fn exact(sign: f64) -> Coeffs {
        Coeffs {
            a: sign,
            e_a: 0.0,
            b: -2.0 * sign,
            e_b: 0.0,
            c: 3.0 * sign,
            e_c: 0.0,
            disc: 1.0,
            e_disc: 0.0,
        }
    }

    #[test]
    fn roots_in_exact_order_for_either_sign_of_the_leading_coefficient() {
        for sign in [1.0, -1.0] {
            let [small, large] = both_bounded(&exact(sign)).unwrap().unwrap();
            assert_eq!((small.t, large.t), (1.0, 3.0), "{sign}");
            assert!(small.error > 0.0 && small.error < 1e-15);
            assert!(large.error > 0.0 && large.error < 1e-15);
        }
    }

    #[test]
    fn places_against_the_interval() {
        let k = exact(1.0);
        let first = |min, max| first_bounded(&k, Interval::new(min, max).unwrap());
        assert_eq!(first(0.0, 10.0).unwrap().unwrap().t, 1.0);
        assert_eq!(first(2.0, 10.0).unwrap().unwrap().t, 3.0);
        assert_eq!(first(4.0, 10.0), Some(None));
        assert_eq!(first(-1.0, 0.5), Some(None));
        // A root at an end of the interval: the precise tier decides.
        assert_eq!(first(1.0, 10.0), None);
        assert_eq!(first(2.0, 3.0), None);
    }

    #[test]
    fn undecided_counts_go_to_the_precise_tier() {
        let mut k = exact(1.0);
        k.e_disc = 1.0;
        assert!(stable_pair(&k).is_none());
        k.disc = -2.0;
        assert!(matches!(stable_pair(&k), Some(None)));
        k.e_disc = f64::INFINITY;
        assert!(stable_pair(&k).is_none());
        let mut flat = exact(1.0);
        flat.e_a = 1.0;
        assert!(stable_pair(&flat).is_none());
    }
}
