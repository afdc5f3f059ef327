//! Exact predicates on constructed points: orientation and order of
//! line–plane ([`Lpi`]), three-plane ([`Tpi`]) and line–line ([`Ssi`])
//! intersection points, exact for every finite `f64` input, without
//! constructing the points.
//!
//! A constructed point is its input points. Its construction decides
//! exactly that they define one point, and keeps the exact sign of its
//! weight. Relative to an origin `o` its homogeneous coordinates
//! `l = w (X - o)` and its weight `w` are polynomials in the input coordinates: of
//! degrees 4 and 3 for an `Lpi`, 7 and 6 for a `Tpi`, 3 and 2 for an `Ssi`
//! (an explicit point: `x - o`, degree 1, over the weight 1). Each
//! predicate is the sign of a polynomial in those (its degree stated with
//! it), times the signs of the weights.
//!
//! Each predicate runs the crate's ladder:
//! 1. **filtered**: the points' coordinates in `f64` relative to an input
//!    point, each with an a-priori bound on its error (`c u M^d`, `M` the
//!    largest input difference the point is built from; the constants are
//!    derived beside them in `approx.rs`), and the predicate's polynomial
//!    with a bound on its error computed from those (also derived there).
//!    It runs while every `M` lies where nothing overflows and underflow is
//!    negligible, `[2^-R, 2^R]` with `R = 800 / degree`.
//! 2. **scaled filter**: out of that range, every input is scaled by one
//!    power of two, which leaves every sign unchanged, and the filter runs
//!    again.
//! 3. **exact**: every input coordinate as an integer at its axis's finest
//!    bit, the points' homogeneous coordinates and the polynomial in
//!    fixed-capacity stack integers as wide as its degree and the inputs'
//!    span need (`exact.rs`).
//!
//! No stage allocates. The exact stage's integers live on the stack, as
//! wide as the degree and the inputs' span need: under 16 KiB at ordinary
//! scales; in release builds about 256 KiB for a line–plane point whose
//! inputs span the whole `f64` range and about 320 KiB for four three-plane
//! points that do (measured; `tests/implicit.rs` runs such cases in a
//! thread of 512 KiB).

mod any;
mod api;
mod approx;
mod exact;
mod order;
mod orient;
mod points;

pub use any::{AnyPoint2, AnyPoint3, AsAnyPoint2, AsAnyPoint3};
pub use api::*;
pub use points::{Lpi, Ssi, Tpi};

use crate::sign::Sign;
use any::Point;
use approx::Verdict;

/// The origin the predicates measure from and their pivot: the first
/// explicit point, or where there is none, an input point of the first.
#[inline(always)]
fn pivot<P: Point<D>, const D: usize>(p: &[P]) -> ([f64; D], Option<usize>) {
    match p.iter().position(|x| x.is_explicit()) {
        Some(j) => (p[j].anchor(), Some(j)),
        None => (p[0].anchor(), None),
    }
}

/// `s` times the signs of every point's weight.
#[inline(always)]
fn with_weights<P: Point<D>, const D: usize>(s: Sign, p: &[P]) -> Sign {
    p.iter().fold(s, |s, x| s.product(x.weight_sign()))
}

/// A predicate on `K` points of `D` dimensions, as the ladder runs it.
trait Predicate<const D: usize, const K: usize> {
    /// The filter on `p` (the points as given, or scaled).
    fn filter<P: Point<D>>(&self, p: &[P; K]) -> Verdict;
    /// The exact sign on `p`.
    fn exact<P: Point<D>>(&self, p: &[P; K]) -> Sign;
}

/// The ladder (see the module docs): the filter on the points, then on the
/// points scaled by a power of two when a scale was out of range, then the
/// exact stage on the points as given.
#[inline(always)]
fn ladder<Q: Predicate<D, K>, P: Point<D>, const D: usize, const K: usize>(
    q: &Q,
    p: [P; K],
) -> Sign {
    match q.filter(&p) {
        Verdict::Certain(s) => s,
        verdict => declined(q, p, verdict),
    }
}

/// The ladder after the filter declined. A NaN or infinite explicit
/// point ends here, as `Zero`: no filter certifies a sign from one (every
/// coordinate enters the filter's value through products, so such a point
/// makes the value NaN or infinite, or its bound infinite).
#[cold]
#[inline(never)]
fn declined<Q: Predicate<D, K>, P: Point<D>, const D: usize, const K: usize>(
    q: &Q,
    p: [P; K],
    verdict: Verdict,
) -> Sign {
    if !p.iter().all(|x| x.is_finite()) {
        return Sign::Zero;
    }
    if let Verdict::OutOfRange(largest) = verdict {
        let largest_coordinate = || {
            let mut m = 0.0f64;
            for x in &p {
                x.for_each_input(|v| v.iter().for_each(|c| m = m.max(c.abs())));
            }
            m
        };
        if let Some(k) = approx::rescaling(largest, largest_coordinate)
            && let Verdict::Certain(s) = q.filter(&p.map(|x| x.scaled(k)))
        {
            return s;
        }
    }
    q.exact(&p)
}

/// The grid of a set of points' inputs (`exact`): per axis, or with
/// `common` one grain for all axes.
fn grid<P: Point<D>, const D: usize>(points: &[P], common: bool) -> exact::Grid<D> {
    let mut g = exact::GridBuilder::new();
    for p in points {
        p.for_each_input(|v| g.add(v));
    }
    g.build(common)
}

/// Every point's exact homogeneous coordinates relative to the origin `o`,
/// one at a time (each point's integers are built in their own frame, then
/// copied in).
#[inline(never)]
fn homs<P: Point<D>, const K: usize, const D: usize, const L: usize>(
    p: &[P],
    o: &[exact::Int<K>; D],
    lo: [i32; D],
) -> [exact::IntHom<K, D>; L] {
    let mut h = [exact::IntHom {
        l: [exact::Int::ZERO; D],
        w: exact::Int::ZERO,
    }; L];
    for (h, p) in h.iter_mut().zip(p) {
        *h = p.exact(o, lo);
    }
    h
}

/// The largest scale of a filter's points.
#[inline(always)]
fn largest_scale<const D: usize>(h: &[approx::Hom<D>]) -> f64 {
    h.iter().fold(0.0, |m, x| m.max(x.scale))
}

#[cfg(test)]
mod bound_tests;
