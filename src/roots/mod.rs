//! Real roots of `a t^2 + b t + c = 0`, computed stably: the solver every
//! ray–quadric routine shares.
//!
//! Two classic sources of error are removed:
//! - the discriminant `b^2 - 4ac` is computed with Kahan's fused
//!   multiply-add algorithm, accurate to 2 ulps of the discriminant itself
//!   however much `b^2` and `4ac` cancel (W. Kahan, "On the Cost of
//!   Floating-Point Computation Without Extra-Precise Arithmetic", 2004;
//!   S. Boldo, "Kahan's algorithm for a correct discriminant computation at
//!   last formally proven", IEEE Trans. Computers 58(2), 2009), so the root
//!   count is exact and near-double roots keep their accuracy;
//! - the root of smaller magnitude comes from Vieta's formula `c / q` with
//!   `q = -(b + sign(b) sqrt(D)) / 2`, never from the cancelling
//!   `-b + sqrt(D)` (the "citardauq" form; Press et al., *Numerical
//!   Recipes*, 3rd ed., section 5.6).
//!
//! Error bound: when no intermediate value overflows or falls below
//! `2^-1022` (coefficients within about `2^±250` of each other, after the
//! solver's own power-of-two scaling), each root is within 4 ulps of the
//! exact root: `D` carries 2 ulps, `sqrt` halves that and rounds once more,
//! the sum `b + sign(b) sqrt(D)` (no cancellation) and the division round
//! once each. `tests/roots.rs` checks the bound exactly: the exact
//! polynomial changes sign within 4 ulps of each returned root.

use crate::arith::exponent::unit_pow2;
use crate::arith::std_or_libm::{fma, sqrt};
use crate::error::InputError;
use crate::interval::Interval;

pub(crate) mod bounded;
pub(crate) mod certified;
pub(crate) mod line_quadratic;
pub(crate) mod radial;

pub use bounded::BoundedRoot;

/// The real roots of a quadratic (or lower-degree) polynomial.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Roots {
    /// No real root.
    None,
    /// One root: a double root of a quadratic, or the root of a linear
    /// polynomial.
    One(f64),
    /// Two distinct roots, the smaller first. (From the ray casts the
    /// count is exact while the roots are rounded: two roots less than an
    /// ulp apart may round to the same value, and roots beyond `f64`'s
    /// range come out as infinities.)
    Two(f64, f64),
    /// Every `t` is a root: all coefficients are zero.
    All,
}

impl Roots {
    /// How many distinct real roots: `None` for [`Roots::All`].
    ///
    /// ```
    /// use exactray::roots::{solve_quadratic, Roots};
    /// assert_eq!(solve_quadratic(1.0, 0.0, -4.0).count(), Some(2));
    /// assert_eq!(Roots::All.count(), None);
    /// ```
    #[inline]
    pub fn count(self) -> Option<usize> {
        match self {
            Roots::None => Some(0),
            Roots::One(_) => Some(1),
            Roots::Two(..) => Some(2),
            Roots::All => None,
        }
    }
}

/// The real roots of `a t^2 + b t + c = 0`, sorted (see the [module
/// docs](self) for the method). `a = 0` solves the linear equation; all
/// zero gives [`Roots::All`]. A NaN or infinite coefficient gives
/// [`Roots::None`] (see [`try_solve_quadratic`]).
///
/// # Accuracy
/// Each root within 4 ulps of the exact root, and the count exact, when no
/// intermediate value overflows or falls below `2^-1022` (coefficients
/// within about `2^±250` of each other after the solver's power-of-two
/// scaling; the module docs derive it).
///
/// ```
/// use exactray::roots::{solve_quadratic, Roots};
/// assert_eq!(solve_quadratic(1.0, -3.0, 2.0), Roots::Two(1.0, 2.0));
/// assert_eq!(solve_quadratic(1.0, -2.0, 1.0), Roots::One(1.0));
/// assert_eq!(solve_quadratic(0.0, 2.0, -1.0), Roots::One(0.5));
/// // The textbook formula loses the small root to cancellation here.
/// let Roots::Two(small, _) = solve_quadratic(1.0, -1e9, 1.0) else { panic!() };
/// assert_eq!(small, 1e-9);
/// ```
pub fn solve_quadratic(a: f64, b: f64, c: f64) -> Roots {
    if !(a.is_finite() && b.is_finite() && c.is_finite()) {
        return Roots::None;
    }
    // Scale by the power of two that brings the largest coefficient near 1:
    // exact (unless a much smaller coefficient falls below 2^-1022) and
    // the roots do not change.
    let m = a.abs().max(b.abs()).max(c.abs());
    if m == 0.0 {
        return Roots::All;
    }
    let k = unit_pow2(m);
    let (a, b, c) = (a * k, b * k, c * k);
    if a == 0.0 {
        return if b == 0.0 {
            Roots::None
        } else {
            Roots::One(-c / b)
        };
    }
    let d = discriminant(a, b, c);
    if d < 0.0 {
        return Roots::None;
    }
    if d == 0.0 {
        return Roots::One(-b / (2.0 * a));
    }
    let s = sqrt(d);
    let q = -0.5 * (b + s.copysign(b));
    let (r1, r2) = (q / a, c / q);
    if r1 <= r2 {
        Roots::Two(r1, r2)
    } else {
        Roots::Two(r2, r1)
    }
}

/// [`solve_quadratic`], checked: the same answer for finite input.
///
/// # Errors
/// [`InputError::NonFinite`] for a NaN or infinite coefficient, naming it (`"a"`, `"b"` or `"c"`).
pub fn try_solve_quadratic(a: f64, b: f64, c: f64) -> Result<Roots, InputError> {
    for (argument, v) in [("a", a), ("b", b), ("c", c)] {
        if !v.is_finite() {
            return Err(InputError::NonFinite { argument });
        }
    }
    Ok(solve_quadratic(a, b, c))
}

/// `b^2 - 4ac` to within 2 ulps of itself (Kahan's algorithm with fused
/// multiply-adds; Boldo 2009 proves the bound, given no underflow or
/// overflow): the rounding errors of `b*b` and `4ac` are recovered exactly
/// by `fma` and added back when the two products nearly cancel.
#[inline]
fn discriminant(a: f64, b: f64, c: f64) -> f64 {
    let p = b * b;
    let q = 4.0 * a * c;
    let d = p - q;
    // Kahan's test: without heavy cancellation the plain difference is
    // already within 2 ulps.
    if 3.0 * d.abs() >= p + q {
        return d;
    }
    let dp = fma(b, b, -p);
    let dq = fma(4.0 * a, c, -q);
    (p - q) + (dp - dq)
}

/// The smallest root that `range` admits ([`Interval::admits`]: a root
/// beyond `f64`'s range, returned as an infinity, is no hit); for
/// [`Roots::All`] (the line lies on the surface) the point of `range`
/// nearest `t = 0`.
#[inline]
pub(crate) fn first_in(roots: Roots, range: Interval) -> Option<f64> {
    let inside = |t: f64| range.admits(t);
    match roots {
        Roots::None => None,
        Roots::One(t) => inside(t).then_some(t),
        Roots::Two(t1, t2) => {
            if inside(t1) {
                Some(t1)
            } else {
                inside(t2).then_some(t2)
            }
        }
        Roots::All => {
            let t = range.min().max(range.max().min(0.0));
            t.is_finite().then_some(t)
        }
    }
}
