//! The quadratic in `t` that every ray–quadric cast solves, in half form
//! `A t^2 + 2 B t + C = 0` with discriminant `B^2 - A C`, at two levels:
//!
//! - **filtered**: the coefficients in `f64` beside a running bound on
//!   their absolute errors (Wilkinson's running error analysis; N. Higham,
//!   *Accuracy and Stability of Numerical Algorithms*, 2nd ed., ch. 3).
//!   It answers "no root" when the bound certifies that the discriminant
//!   is negative, and otherwise when each computed root it needs is
//!   certified, a posteriori, to have an exact root within 3 ulps (so
//!   within 4 ulps of the correctly rounded root): one evaluation of the
//!   exact polynomial with a rigorous error bound, in working precision
//!   or, where that bound is too loose, in double-double, and a lower
//!   bound on the derivative (the mean value theorem, [`root_within`]); a
//!   root a few ulps off is first corrected by one Newton step from the
//!   double-double value. A certified bracket holds a simple root, so the
//!   certificates also settle the count, and the derivative's sign tells
//!   which of the two roots a bracket holds ([`computed_count`]). A cast
//!   that wants only the first root inside an interval certifies only the
//!   roots it looks at ([`certified_first`]). The filtered stages run with
//!   hardware FMA where the CPU has it (`arith::fma_dispatch::with_fma`);
//! - **exact**: the coefficients as exact integers (`arith::fixed_int`), the
//!   discriminant's sign exact, each coefficient rounded once to 53 bits
//!   with an unbounded exponent ([`ScaledFloat`]) and the roots from the
//!   stable formula: four more roundings (sqrt, the sum of same-sign terms,
//!   the division, and the final conversion), so each root is within
//!   `4.5u` relative of the exact root to first order (at most 5 ulps).
//!
//! Both use the stable pair `t1 = q / A`, `t2 = C / q` with
//! `q = -(B + sign(B) sqrt(B^2 - A C))`: no cancellation in `q`.

use crate::arith::fixed_int::FixedInt;
use crate::arith::roundoff::U;
use crate::arith::scaled_float::ScaledFloat;
use crate::arith::std_or_libm::{fma, sqrt};
use crate::interval::Interval;
use crate::roots::Roots;
use crate::sign::Sign;
use glam::DVec3;

/// The largest grain span (bits from a set's finest to its coarsest bit)
/// for which the exact stages use 2-limb inputs: a difference of two such
/// values needs at most 128 bits with its sign.
pub(crate) const SMALL_SPAN: i32 = 126;

/// Half-form coefficients with bounds on the absolute errors of `A`, `B`
/// and `C`, and the discriminant `disc ≈ B^2 - A C` with its bound
/// `e_disc`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Coeffs {
    pub a: f64,
    pub e_a: f64,
    pub b: f64,
    pub e_b: f64,
    pub c: f64,
    pub e_c: f64,
    pub disc: f64,
    pub e_disc: f64,
}

impl Coeffs {
    /// The coefficients `A`, `B`, `C` with bounds on their errors, and the
    /// discriminant as `fma(-A, C, B^2)`: `B^2` rounds once inside the
    /// fma's addend, the fma once; the coefficients' errors propagate
    /// through the products, to second order included (`e_b^2`, `e_a e_c`:
    /// where `B` cancels they are the whole bound). The general quadric's
    /// form, whose coefficients carry no structure the discriminant could
    /// use (the sphere's, the cylinder's and the cone's have one that does
    /// not cancel for far origins).
    #[inline(always)]
    pub(crate) fn with_product_discriminant(
        (a, e_a): (f64, f64),
        (b, e_b): (f64, f64),
        (c, e_c): (f64, f64),
    ) -> Coeffs {
        let disc = fma(-a, c, b * b);
        let e_disc = 2.0 * b.abs() * e_b
            + a.abs() * e_c
            + c.abs() * e_a
            + e_b * e_b
            + e_a * e_c
            + U * b * b
            + U * disc.abs();
        Coeffs {
            a,
            e_a,
            b,
            e_b,
            c,
            e_c,
            disc,
            e_disc,
        }
    }
}

/// How far, in ulps, a certified root may lie from the exact root: with
/// the correctly rounded root half an ulp further at most, every certified
/// root is within 4 ulps of it (3.5, rounded to whole ulps).
pub(crate) const CERTIFIED_ULPS: i64 = 3;

/// An absolute slack for results that underflow, where a rounding error
/// is bounded by half the smallest subnormal (`2^-1075`) rather than
/// relatively: added once per operation that could underflow. It is
/// `2^-500`, far above that, so that neither it nor its square (which the
/// second-order error terms form) is subnormal: an operation with a
/// subnormal operand or result costs a microcode assist on x86, about a
/// hundred cycles. The filter's magnitudes start near `1e-120`, so the
/// slack never decides a certificate.
pub(crate) const ETA: f64 = 3.054936363499605e-151; // 2^-500

/// The exact polynomial of a cast, evaluated with a rigorous error bound.
/// Implementations mark both methods `#[inline(always)]`: they run inside
/// the FMA-enabled copy of the filtered stage (`arith::fma_dispatch::with_fma`).
pub(crate) trait Polynomial {
    /// Whether [`Polynomial::eval_fast`]'s bound is tight enough to be
    /// worth trying first; where it almost never certifies (the general
    /// quadric's, whose terms are as large as `|o|^2` however near the
    /// surface the point is), the double-double evaluation runs alone.
    const TRY_FAST: bool = true;
    /// The value at `t` in working precision and a bound on its error.
    fn eval_fast(&self, t: f64) -> (f64, f64);
    /// The value at `t` in double-double and a bound on its error.
    fn eval_precise(&self, t: f64) -> (f64, f64);
}

/// What a cast asks of a filtered stage: every root of the line
/// ([`AllRoots`]) or only the first inside an interval (`BoundedFirstIn`
/// in `bounded.rs`, which certifies only the roots it needs). `answer` gives `None` where the
/// filter cannot certify, and the caller runs the exact stage, whose roots
/// `exact_answer` turns into the same kind of answer.
pub(crate) trait Question: Copy {
    /// The answer: the roots, or the first root inside the interval.
    type Answer;
    /// The certified answer, or `None` for the exact stage.
    fn answer(self, k: &Coeffs, p: &impl Polynomial) -> Option<Self::Answer>;
    /// The answer from the exact stage's roots.
    fn exact_answer(self, roots: Roots) -> Self::Answer;
}

/// Every real root of the line, sorted ([`certified_roots`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct AllRoots;

impl Question for AllRoots {
    type Answer = Roots;

    #[inline(always)]
    fn answer(self, k: &Coeffs, p: &impl Polynomial) -> Option<Roots> {
        certified_roots(k, p)
    }

    #[inline(always)]
    fn exact_answer(self, roots: Roots) -> Roots {
        roots
    }
}

/// `Some(Some(sqrt(disc)))` where the computed discriminant is positive,
/// `Some(None)` where the running bound certifies that there is no real
/// root, `None` where it cannot tell (a near-tangent line) or the leading
/// coefficient may be zero.
///
/// A positive discriminant is not checked against its bound here: the
/// roots' certificates settle the count. A bracket certified by
/// [`root_within`] holds a simple root (the polynomial changes sign and
/// its derivative does not vanish), so the discriminant is positive; no
/// bracket can be certified for a tangent line or one that misses. Only a
/// claimed miss needs the bound, so the bound costs nothing on hits where
/// the compiler sinks it into that branch.
#[inline(always)]
fn computed_count(k: &Coeffs) -> Option<Option<f64>> {
    // The bounds are first order; the factor covers the O(u^2) terms.
    let margin = 1.0 + 64.0 * U;
    // False for NaN too.
    let leading_nonzero = k.a.abs() > k.e_a * margin;
    if !leading_nonzero {
        return None;
    }
    if k.disc > 0.0 {
        return Some(Some(sqrt(k.disc)));
    }
    // A NaN or infinite bound (overflow) fails the test.
    let e_disc = k.e_disc * margin;
    (k.disc < -e_disc && e_disc < f64::INFINITY).then_some(None)
}

/// The two computed roots, sorted, from the stable pair.
#[inline(always)]
fn stable_pair(k: &Coeffs, s: f64) -> (f64, f64) {
    let q = -(k.b + s.copysign(k.b));
    let (t1, t2) = (q / k.a, k.c / q);
    if t1 <= t2 { (t1, t2) } else { (t2, t1) }
}

/// The first root inside `range`, as [`super::first_in`] would take it from
/// [`certified_roots`]' answer, certifying only the roots it looks at: the
/// smaller one, and the larger only when the smaller lies below `range`.
/// `None` asks for the exact stage.
///
/// Which exact root a certified bracket holds follows from [`root_side`];
/// a bracket that holds the other root than the one expected (the
/// computed roots out of order) declines.
#[inline(always)]
pub(crate) fn certified_first(
    k: &Coeffs,
    p: &impl Polynomial,
    range: Interval,
) -> Option<Option<f64>> {
    let Some(s) = computed_count(k)? else {
        return Some(None);
    };
    let (t1, t2) = stable_pair(k, s);
    let t1 = certified_root(k, t1, p)?;
    if root_side(k, t1) != Side::Smaller {
        return None;
    }
    if t1 >= range.min() {
        return Some(range.admits(t1).then_some(t1));
    }
    let t2 = certified_root(k, t2, p)?;
    if root_side(k, t2) != Side::Larger {
        return None;
    }
    Some(range.admits(t2).then_some(t2))
}

/// Which of the two roots a certified bracket around `t` holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    Smaller,
    Larger,
    /// `A t + B` computes as zero or NaN: not a certified bracket.
    Unknown,
}

/// The root a bracket certified by [`root_within`] around `t` holds, from
/// the sign of `A t + B` there, which that check certifies: the sign of
/// `-A` at the smaller root and of `A` at the larger (`A s + B =
/// ∓sqrt(B^2 - A C)` there).
#[inline(always)]
fn root_side(k: &Coeffs, t: f64) -> Side {
    let ga = (k.a * t + k.b) * k.a;
    if ga < 0.0 {
        Side::Smaller
    } else if ga > 0.0 {
        Side::Larger
    } else {
        Side::Unknown
    }
}

/// The roots when the running bound on the discriminant certifies that
/// there are none, or when each computed root is certified within
/// [`CERTIFIED_ULPS`] of a different exact root (which certifies the count
/// two, see [`computed_count`]); `None` asks for the exact stage.
///
/// A root is certified from one evaluation of the exact polynomial with a
/// rigorous error bound: first in working precision, then, where its
/// bound is too loose, in double-double; see [`certified_root`] and
/// [`root_within`]. This a-posteriori check is what makes the filtered
/// stage both fast and tight: an a-priori bound on the stable formula
/// costs several units of roundoff for every rounding it passes through,
/// while the actual errors are about one.
#[inline(always)]
pub(crate) fn certified_roots(k: &Coeffs, p: &impl Polynomial) -> Option<Roots> {
    let Some(s) = computed_count(k)? else {
        return Some(Roots::None);
    };
    let (t1, t2) = stable_pair(k, s);
    let t1 = certified_root(k, t1, p)?;
    let t2 = certified_root(k, t2, p)?;
    // Brackets around different roots: the derivative's certified signs
    // differ ([`root_side`]), so the count is two.
    let sides = (root_side(k, t1), root_side(k, t2));
    (sides == (Side::Smaller, Side::Larger) && t1 <= t2).then_some(Roots::Two(t1, t2))
}

/// `t`, or `t` after one Newton step, certified within [`CERTIFIED_ULPS`]
/// of an exact root (in the bracket of [`radius`]), or `None`. The working-precision evaluation settles most roots; where its
/// bound is too loose, the double-double one certifies `t` or, where `t`
/// itself is a few ulps off, corrects it by a Newton step from the
/// accurate value (quadratic convergence: the step lands within about
/// half an ulp) and certifies the result.
#[inline(always)]
fn certified_root<P: Polynomial>(k: &Coeffs, t: f64, p: &P) -> Option<f64> {
    let r = radius(t);
    if P::TRY_FAST && root_within(k, t, r, p.eval_fast(t)) {
        return Some(t);
    }
    let (v, e) = p.eval_precise(t);
    if root_within(k, t, r, (v, e)) {
        return Some(t);
    }
    let newton = t - v / (2.0 * (k.a * t + k.b));
    root_within(k, newton, radius(newton), p.eval_precise(newton)).then_some(newton)
}

/// The largest `r` with `[t - r, t + r]` inside the [`CERTIFIED_ULPS`]
/// floats on either side of `t`: that many spacings below `|t|`, which
/// are at most the spacings above; halved when `|t|` lies within that
/// many floats above a power of two, where the floats below it are
/// twice as dense. Zero for `t = 0`, infinite or NaN for such `t`.
#[inline(always)]
fn radius(t: f64) -> f64 {
    let bits = t.abs().to_bits();
    let spacing = t.abs() - f64::from_bits(bits.saturating_sub(1));
    let near_power = (bits & ((1 << 52) - 1)) < CERTIFIED_ULPS as u64;
    CERTIFIED_ULPS as f64 * if near_power { 0.5 * spacing } else { spacing }
}

/// Whether the exact polynomial `p(s) = A s^2 + 2 B s + C` has a root
/// within [`CERTIFIED_ULPS`] floats of `t`, given `p(t)` within `v ± e`:
/// whether it has one in `[t - r, t + r]`, `r = radius(t)`.
///
/// By the mean value theorem: on the interval `|p'(s)| = 2 |A s + B| >=
/// 2 (|A t + B| - |A| r) =: m`; where `m > 0` and `|p(t)| < m r`, `p` is
/// monotone there and moves by more than `|p(t)|` on either side of `t`,
/// so it changes sign. `A t + B` is computed as `g` within
/// `e_a |t| + e_b` (the coefficients' errors) plus two roundings.
#[inline(always)]
fn root_within(k: &Coeffs, t: f64, r: f64, (v, e): (f64, f64)) -> bool {
    let at = k.a * t;
    let g = at + k.b;
    let e_g = (k.e_a * t.abs() + k.e_b + U * (at.abs() + g.abs())) * (1.0 + 8.0 * U) + ETA;
    let half_m = (g.abs() - e_g - (k.a.abs() + k.e_a) * r) * (1.0 - 4.0 * U);
    // NaN anywhere fails the comparisons.
    half_m > 0.0 && (v.abs() + e) * (1.0 + 64.0 * U) < 2.0 * half_m * r * (1.0 - 4.0 * U)
}

/// The roots of `A t^2 + 2 B t + C` from exact integer coefficients:
/// `A = a * 2^ea` and so on, with `2 eb = ea + ec` (each caller's scaling
/// makes the three terms of the discriminant share one exponent). `M` must
/// hold `B^2` and `A C`.
pub(crate) fn exact_roots<const N: usize, const M: usize>(
    (a, ea): (&FixedInt<N>, i32),
    (b, eb): (&FixedInt<N>, i32),
    (c, ec): (&FixedInt<N>, i32),
) -> Roots {
    debug_assert_eq!(2 * eb, ea + ec);
    let (xa, xb, xc) = (a.as_extended(ea), b.as_extended(eb), c.as_extended(ec));
    if xa.is_zero() {
        // Linear: 2 B t + C = 0.
        return if !xb.is_zero() {
            Roots::One(xc.div(xb.mul(ScaledFloat::new(-2.0, 0))).to_f64())
        } else if xc.is_zero() {
            Roots::All
        } else {
            Roots::None
        };
    }
    let disc = FixedInt::<M>::mul(b, b).sub(&FixedInt::<M>::mul(a, c));
    match disc.sign() {
        Sign::Negative => Roots::None,
        Sign::Zero => Roots::One(xb.neg().div(xa).to_f64()),
        Sign::Positive => {
            let s = disc.as_extended(2 * eb).sqrt();
            let q = if xb.is_negative() {
                s.add(xb.neg())
            } else {
                s.add(xb).neg()
            };
            let (t1, t2) = (q.div(xa).to_f64(), xc.div(q).to_f64());
            if t1 <= t2 {
                Roots::Two(t1, t2)
            } else {
                Roots::Two(t2, t1)
            }
        }
    }
}

/// `|v|_1`, an upper bound on the Euclidean norm that needs no square root.
#[inline(always)]
pub(crate) fn norm1(v: DVec3) -> f64 {
    v.x.abs() + v.y.abs() + v.z.abs()
}

/// Whether `v` lies where the filtered stage's bounds hold: products of the
/// magnitudes involved neither overflow nor reach the subnormal range
/// (where rounding errors become absolute rather than relative).
#[inline(always)]
pub(crate) fn in_filter_range(v: f64) -> bool {
    (1e-120..1e120).contains(&v)
}
