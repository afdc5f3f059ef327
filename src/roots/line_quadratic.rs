//! The door between a quadric shape and the root finders: what a shape
//! supplies ([`LineQuadratic`]: its equation along a line as a quadratic,
//! in each stage) and the one driver that turns it into the line's roots
//! and into a cast's first root in either tier ([`line_roots`],
//! [`first_in`], [`crossings`]).
//!
//! A shape implements two stages and may add a third:
//! - **filtered**: the `f64` coefficients of `A t^2 + 2 B t + C` with their
//!   running bounds (a [`Coeffs`]) and the exact polynomial evaluated with
//!   a rigorous bound (a [`Polynomial`]); [`Question::answer`] certifies the
//!   roots from them, or declines;
//! - **exact**: the coefficients as integers at the inputs' common grains,
//!   whose roots [`exact_roots`] counts exactly and rounds correctly;
//! - **rounded** (optional): coefficients from rounded inputs with
//!   a-priori bounds, for the default tier's stable-formula root
//!   (`bounded.rs`); a shape without it answers the default tier from the
//!   filtered stage.
//!
//! The bounds each stage needs are derived beside the shape's own
//! coefficients; the driver adds no rounding of its own. The module also
//! re-exports what a shape's stages are built from (the coefficients'
//! range checks and slack, the exact roots, a quotient's error bound), so
//! that a cast reaches `roots` through this one door; the sphere-like
//! problems of `radial.rs` are the other, for shapes that reduce to them.

pub(crate) use super::bounded::quotient_error;
pub(crate) use super::bounded::{BoundedFirstIn, Tier};
use super::bounded::{Place, both_bounded, first_bounded_or, precise};
pub(crate) use super::certified::{
    AllRoots, Coeffs, ETA, Polynomial, Question, SMALL_SPAN, exact_roots, in_filter_range, norm1,
};
use super::{BoundedRoot, Roots};
use crate::interval::Interval;
use glam::DVec3;

/// A quadric shape's equation along the line `o + t d`, as a quadratic in
/// `t`, in the stages of the module docs.
pub(crate) trait LineQuadratic {
    /// Whether [`LineQuadratic::rounded`] gives the default tier's
    /// coefficients; where not, the default tier asks the filtered stage.
    const ROUNDED: bool = false;

    /// The filtered stage: `q`'s answer, or `None` where it cannot be
    /// certified (the exact stage then answers).
    fn filtered<Q: Question>(&self, o: DVec3, d: DVec3, q: Q) -> Option<Q::Answer>;

    /// The exact stage: every real root, the count exact.
    fn exact(&self, o: DVec3, d: DVec3) -> Roots;

    /// The default tier's coefficients from rounded inputs, with a-priori
    /// bounds; `None` where they leave the range the bounds hold in (the
    /// precise tier then answers). Used only where `ROUNDED`.
    #[inline(always)]
    fn rounded(&self, o: DVec3, d: DVec3) -> Option<Coeffs> {
        let _ = (o, d);
        None
    }

    /// Both roots of the line in the default tier, bounded and in exact
    /// order; `Some(None)` for a certified miss; `None` where the precise
    /// tier decides (a near-tangent or degenerate line). Provided from
    /// [`LineQuadratic::rounded`]; a shape that scales the line overrides
    /// it to scale the roots back.
    #[inline]
    fn bounded_pair(&self, o: DVec3, d: DVec3) -> Option<Option<[BoundedRoot; 2]>> {
        if !Self::ROUNDED {
            return None;
        }
        both_bounded(&self.rounded(o, d)?)
    }
}

/// The filtered stage's answer to `q`, or the exact stage's.
#[inline]
pub(crate) fn solve<S: LineQuadratic, Q: Question>(s: &S, o: DVec3, d: DVec3, q: Q) -> Q::Answer {
    s.filtered(o, d, q)
        .unwrap_or_else(|| q.exact_answer(s.exact(o, d)))
}

/// Every real root of the line, sorted, the count exact.
#[inline]
pub(crate) fn line_roots<S: LineQuadratic>(s: &S, o: DVec3, d: DVec3) -> Roots {
    solve(s, o, d, AllRoots)
}

/// The first root inside `range`, bounded: in the default tier from the
/// rounded coefficients where they decide (else the precise tier), or
/// from the filtered stage asked for the default tier; in the precise tier
/// within 4 ulps of the correctly rounded root.
#[inline(always)]
pub(crate) fn first_in<S: LineQuadratic>(
    s: &S,
    o: DVec3,
    d: DVec3,
    range: Interval,
    tier: Tier,
) -> Option<BoundedRoot> {
    match tier {
        Tier::Default if S::ROUNDED => {
            first_bounded_or(s.rounded(o, d), range, || precise_first(s, o, d, range))
        }
        _ => solve(s, o, d, BoundedFirstIn(range, tier)),
    }
}

/// The precise tier's first root in `range`, bounded.
#[inline]
fn precise_first<S: LineQuadratic>(
    s: &S,
    o: DVec3,
    d: DVec3,
    range: Interval,
) -> Option<BoundedRoot> {
    solve(s, o, d, BoundedFirstIn(range, Tier::Precise))
}

/// The roots of the line a cast of a bounded surface considers, sorted,
/// each inside `range`: in the default tier the bounded roots certified
/// inside it where every root's place is decided; otherwise (and in the
/// precise tier) the precise roots that `range` admits. A line lying on
/// the surface has none: the caller's caps or rims decide it.
#[inline]
pub(crate) fn crossings<S: LineQuadratic>(
    s: &S,
    o: DVec3,
    d: DVec3,
    range: Interval,
    tier: Tier,
) -> [Option<BoundedRoot>; 2] {
    if tier == Tier::Default
        && let Some(found) = s.bounded_pair(o, d)
    {
        let Some(roots) = found else {
            return [None, None];
        };
        let places = roots.map(|root| root.place(range));
        if !places.contains(&Place::Undecided) {
            return [0, 1].map(|i| (places[i] == Place::Inside).then_some(roots[i]));
        }
    }
    let admitted = |t: f64| range.admits(t).then(|| precise(t));
    match line_roots(s, o, d) {
        Roots::One(t) => [admitted(t), None],
        Roots::Two(t1, t2) => [admitted(t1), admitted(t2)],
        Roots::None | Roots::All => [None, None],
    }
}
