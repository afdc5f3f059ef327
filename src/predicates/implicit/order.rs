//! The order of two points, explicit or constructed: along an axis, and
//! along a line.
//!
//! Along axis `k`, `X_k - Y_k = (l_X,k w_Y - l_Y,k w_X) / (w_X w_Y)` for
//! the points' homogeneous coordinates relative to one origin: the sign of
//! a polynomial of degree `max(deg l_X + deg w_Y, deg l_Y + deg w_X)` (7
//! for two `Lpi`s, 13 for two `Tpi`s, 5 for two `Ssi`s; one point explicit
//! and the origin: `deg l` of the other), times the weights' signs.
//!
//! Along the line from `p` to `q`, `(Y - X) . (q - p) = sum_k (l_Y,k w_X -
//! l_X,k w_Y) (q_k - p_k) / (w_X w_Y)` with `p` the origin: one degree more
//! than along an axis.

use super::any::Point;
use super::approx::{self, Hom, SAFETY, Verdict, certified, cross_products_bounded};
use super::exact::{self, Exact, Grid, Int, IntHom};
use super::{Predicate, ladder, largest_scale, pivot, with_weights};
use crate::arith::magnitude::larger;
use crate::arith::roundoff::U;
use crate::sign::Sign;

/// The degree of `l_X w_Y - l_Y w_X`.
fn cross_degree<P: Point<D>, const D: usize>(x: &P, y: &P) -> u32 {
    let (x, y) = (x.degrees(), y.degrees());
    (x.l + y.w).max(y.l + x.w)
}

/// The sign of `X_axis - Y_axis`.
#[inline(always)]
pub(super) fn on_axis<P: Point<D>, const D: usize>(p: [P; 2], axis: usize) -> Sign {
    // (The caller has checked that explicit points are finite.)
    if let (Some(x), Some(y)) = (p[0].explicit(), p[1].explicit()) {
        // A rounded difference of finite values has the exact one's sign.
        let finite = x.iter().chain(&y).all(|c| c.is_finite());
        return if finite {
            Sign::of_f64(x[axis] - y[axis])
        } else {
            Sign::Zero
        };
    }
    ladder(&OnAxis(axis), p)
}

/// The order along an axis.
struct OnAxis(usize);

impl<const D: usize> Predicate<D, 2> for OnAxis {
    #[inline(always)]
    fn filter<P: Point<D>>(&self, p: &[P; 2]) -> Verdict {
        let (o, _) = pivot(p);
        let h: [Hom<D>; 2] = [p[0].approx(o), p[1].approx(o)];
        let deg = cross_degree(&p[0], &p[1]);
        if !approx::in_range(&h, deg) {
            return Verdict::OutOfRange(largest_scale(&h));
        }
        let ([x, y], k) = (h, self.0);
        let (v, b) =
            cross_products_bounded((x.l[k], x.el), (y.w, y.ew), (y.l[k], y.el), (x.w, x.ew));
        match certified(v, b) {
            Some(s) => Verdict::Certain(with_weights(s, p)),
            None => Verdict::Uncertain,
        }
    }

    fn exact<P: Point<D>>(&self, p: &[P; 2]) -> Sign {
        let (origin, _) = pivot(p);
        exact::run(&AxisExact {
            p: *p,
            grid: super::grid(p, false),
            origin,
            axis: self.0,
        })
    }
}

struct AxisExact<P: Point<D>, const D: usize> {
    p: [P; 2],
    grid: Grid<D>,
    origin: [f64; D],
    axis: usize,
}

impl<P: Point<D>, const D: usize> Exact for AxisExact<P, D> {
    fn degree(&self) -> u32 {
        cross_degree(&self.p[0], &self.p[1])
    }

    fn grid_bits(&self) -> u32 {
        self.grid.bits
    }

    #[inline(never)]
    fn eval<const K: usize, const N: usize>(&self) -> Sign {
        let lo = self.grid.lo;
        let o = exact::ints::<K, D>(self.origin, lo);
        let [x, y]: [IntHom<K, D>; 2] = super::homs(&self.p, &o, lo);
        let k = self.axis;
        let xy: Int<N> = exact::mul(&x.l[k], &y.w);
        let v = xy.sub(&exact::mul(&y.l[k], &x.w));
        with_weights(v.sign(), &self.p)
    }
}

/// The sign of `(Y - X) . (Q - P)` for the points `[P, Q, X, Y]`, `P` and
/// `Q` explicit.
#[inline(always)]
pub(super) fn along_line<P: Point<D>, const D: usize>(p: [P; 4]) -> Sign {
    ladder(&Along, p)
}

/// The order along a line.
struct Along;

impl<const D: usize> Predicate<D, 4> for Along {
    /// With `r_k = l_Y,k w_X - l_X,k w_Y`, each within `E_r`
    /// ([`cross_products_bounded`]), and `d = q - p` rounded within `E_d`:
    /// by the argument of `approx::det3_bounded`, `|r~ . d~ - r . d| <= D
    /// (R E_d + (|d~| + E_d) E_r)` (`R = |r~|`, largest components), and the
    /// dot product's `D` terms round `D` times at most: `gamma(D) D R |d~|`.
    #[inline(always)]
    fn filter<P: Point<D>>(&self, p: &[P; 4]) -> Verdict {
        let o = p[0].anchor();
        let h: [Hom<D>; 4] = [0, 1, 2, 3].map(|i| p[i].approx(o));
        let deg = cross_degree(&p[2], &p[3]) + 1;
        if !approx::in_range(&h, deg) {
            return Verdict::OutOfRange(largest_scale(&h));
        }
        let [_, d, x, y] = h;
        let (mut value, mut r, mut er) = (0.0, 0.0f64, 0.0f64);
        for k in 0..D {
            let (rk, bk) =
                cross_products_bounded((y.l[k], y.el), (x.w, x.ew), (x.l[k], x.el), (y.w, y.ew));
            value += rk * d.l[k];
            r = larger(r, rk.abs());
            er = larger(er, bk);
        }
        let n = D as f64;
        let bound = n * (r * d.el + (d.scale + d.el) * er) + n * n * U * r * d.scale;
        match certified(value, bound * SAFETY) {
            Some(s) => Verdict::Certain(with_weights(s, p)),
            None => Verdict::Uncertain,
        }
    }

    /// On one grain for all axes (a dot product mixes them).
    fn exact<P: Point<D>>(&self, p: &[P; 4]) -> Sign {
        exact::run(&AlongExact {
            p: *p,
            grid: super::grid(p, true),
        })
    }
}

struct AlongExact<P: Point<D>, const D: usize> {
    p: [P; 4],
    grid: Grid<D>,
}

impl<P: Point<D>, const D: usize> Exact for AlongExact<P, D> {
    fn degree(&self) -> u32 {
        cross_degree(&self.p[2], &self.p[3]) + 1
    }

    fn grid_bits(&self) -> u32 {
        self.grid.bits
    }

    #[inline(never)]
    fn eval<const K: usize, const N: usize>(&self) -> Sign {
        let lo = self.grid.lo;
        let o = exact::ints::<K, D>(self.p[0].anchor(), lo);
        let h: [IntHom<K, D>; 3] = super::homs(&self.p[1..], &o, lo);
        let [d, x, y] = &h;
        let mut v = Int::<N>::ZERO;
        for k in 0..D {
            let yx: Int<N> = exact::mul(&y.l[k], &x.w);
            let r = yx.sub(&exact::mul(&x.l[k], &y.w));
            v = v.add(&exact::mul(&r, &d.l[k]));
        }
        with_weights(v.sign(), &self.p)
    }
}
