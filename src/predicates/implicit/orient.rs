//! `orient3d` and `orient2d` (in the plane, and on a coordinate projection
//! of 3D points) with any of their points constructed.
//!
//! With the points as homogeneous rows `(l_i, w_i)`, `l_i = w_i (X_i - o)`,
//! the homogeneous determinant `det[l_i, w_i]` is `-orient3d` times the
//! product of the weights (`+orient2d` in the plane). Where a point `j` is
//! explicit it is the origin, its row is `(0, 1)`, and the determinant is
//! `(-1)^(j+1) det[l_i]` over the other points, in order (`(-1)^j` in the
//! plane): degree the sum of their degrees (`Lpi` 4, `Tpi` 7, `Ssi` 3, an
//! explicit point 1). Otherwise it is expanded along the weights, `sum_i
//! (-1)^(i+1) w_i det[l_k, k != i]` (`(-1)^i` in the plane): degree one
//! less than the sum of all of them.

use super::any::{Point, View2, View3};
use super::approx::{self, Hom, SAFETY, Verdict, certified, det2_bounded, det3_bounded};
use super::exact::{self, Exact, Grid, Int, IntHom};
use super::{Predicate, ladder, largest_scale, pivot, with_weights};
use crate::arith::magnitude::{larger, smaller};
use crate::arith::roundoff::U;
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// The other indices of `0..L + 1`, in order.
fn others<const L: usize>(j: usize) -> [usize; L] {
    core::array::from_fn(|i| i + (i >= j) as usize)
}

/// The degree of the determinant of rows of degrees `l` (see the module
/// docs).
fn degree<P: Point<D>, const D: usize, const K: usize>(p: &[P; K], pivot: Option<usize>) -> u32 {
    let sum: u32 = p.iter().map(|x| x.degrees().l).sum();
    match pivot {
        Some(j) => sum - p[j].degrees().l,
        None => sum - 1,
    }
}

/// `-1` to the power `n`, on a sign.
fn alternate(s: Sign, n: usize) -> Sign {
    if n % 2 == 1 { -s } else { s }
}

/// orient3d of any four points.
#[inline(always)]
pub(super) fn orient3d(p: [View3<'_>; 4]) -> Sign {
    if let [
        View3::Explicit(a),
        View3::Explicit(b),
        View3::Explicit(c),
        View3::Explicit(d),
    ] = p
    {
        return crate::predicates::orient3d::orient3d(a, b, c, d);
    }
    if let Some((j, [a, b, c])) = single_implicit3(&p)
        && let Some(s) = one_implicit3(a, b, c, &p[j])
    {
        // Moving the point from place `j` to the last passes `3 - j` others.
        return alternate(s, 3 - j);
    }
    ladder(&Orient3, p)
}

/// Where exactly one of four points is constructed (not all four
/// explicit): its place and the explicit points in order.
#[inline(always)]
fn single_implicit3(p: &[View3<'_>; 4]) -> Option<(usize, [DVec3; 3])> {
    use View3::Explicit as E;
    match *p {
        [E(a), E(b), E(c), _] => Some((3, [a, b, c])),
        [E(a), E(b), _, E(d)] => Some((2, [a, b, d])),
        [E(a), _, E(c), E(d)] => Some((1, [a, c, d])),
        [_, E(b), E(c), E(d)] => Some((0, [b, c, d])),
        _ => None,
    }
}

/// The filter for `orient3d(a, b, c, X)`, `X` constructed, straight-line:
/// [`Orient3`]'s with `a` the origin, the rows `u = b - a`, `v = c - a`
/// and `X`'s `l`. With `e_u = eps |u|`, `e_v = eps |v|` (`eps` the explicit
/// rows' bound, `u (1 + 2^-50)`), `det3_bounded`'s bound is `6 |u| |v|
/// [(2 eps + eps^2 + 5 u) |l| + (1 + eps)^2 E_l]`, below `6 |u| |v| (7 u
/// |l| + E_l) (1 + 2^-48)`: `SAFETY` covers the factor, and `|l|` is at
/// most `X`'s a-priori `lmax`.
#[inline(always)]
fn one_implicit3(a: DVec3, b: DVec3, c: DVec3, x: &View3<'_>) -> Option<Sign> {
    let h = x.approx(a.to_array());
    let (u, v, l) = (b - a, c - a, DVec3::from(h.l));
    let (ru, rv) = (approx::norm3(u), approx::norm3(v));
    // Zero rows fail the range too: the ladder takes them.
    let least = smaller(h.least, smaller(ru, rv));
    if !approx::scales_in_range(least, larger(h.scale, larger(ru, rv)), 2 + x.degrees().l) {
        return None;
    }
    let bound = 6.0 * (ru * rv) * (7.0 * U * h.lmax + h.el) * SAFETY;
    certified(u.dot(v.cross(l)), bound).map(|s| s.product(x.weight_sign()))
}

/// orient2d of any three points in the plane.
#[inline(always)]
pub(super) fn orient2d(p: [View2<'_>; 3]) -> Sign {
    if let [View2::Explicit(a), View2::Explicit(b), View2::Explicit(c)] = p {
        return crate::predicates::orient2d::orient2d(a, b, c);
    }
    use View2::Explicit as E;
    let single = match p {
        [E(a), E(b), _] => Some((2, a, b)),
        [E(a), _, E(c)] => Some((1, a, c)),
        [_, E(b), E(c)] => Some((0, b, c)),
        _ => None,
    };
    if let Some((j, a, b)) = single
        && let Some(s) = one_implicit2(a, b, &p[j])
    {
        // Moving the point from place `j` to the last passes `2 - j` others.
        return alternate(s, 2 - j);
    }
    ladder(&Planar { drop: None }, p)
}

/// The filter for `orient2d(a, b, X)`, `X` constructed, straight-line:
/// [`Planar`]'s with `a` the origin, the rows `u = b - a` and `X`'s `l`:
/// `det2_bounded`'s bound `2 [eps |u| |l| + (1 + eps) |u| E_l + 2 u |u|
/// |l|]` is below `2 |u| (3 u |l| + E_l) (1 + 2^-48)`, `|l|` at most
/// `lmax` (as for [`one_implicit3`]).
#[inline(always)]
fn one_implicit2(a: DVec2, b: DVec2, x: &View2<'_>) -> Option<Sign> {
    let h = x.approx(a.to_array());
    let (u, l) = (b - a, DVec2::from(h.l));
    let ru = approx::norm2(u);
    // A zero row fails the range too: the ladder takes it.
    if !approx::scales_in_range(smaller(h.least, ru), larger(h.scale, ru), 1 + x.degrees().l) {
        return None;
    }
    let bound = 2.0 * ru * (3.0 * U * h.lmax + h.el) * SAFETY;
    certified(u.perp_dot(l), bound).map(|s| s.product(x.weight_sign()))
}

/// orient2d of three 3D points projected along axis `drop` (onto the axes
/// `drop + 1`, `drop + 2`, cyclically).
#[inline(always)]
pub(super) fn orient2d_projected(p: [View3<'_>; 3], drop: usize) -> Sign {
    if let [View3::Explicit(a), View3::Explicit(b), View3::Explicit(c)] = p {
        let (i, j) = ((drop + 1) % 3, (drop + 2) % 3);
        let pr = |v: DVec3| DVec2::new(v[i], v[j]);
        return crate::predicates::orient2d::orient2d(pr(a), pr(b), pr(c));
    }
    ladder(&Planar { drop: Some(drop) }, p)
}

/// orient3d (see the module docs).
struct Orient3;

impl Predicate<3, 4> for Orient3 {
    #[inline(always)]
    fn filter<P: Point<3>>(&self, p: &[P; 4]) -> Verdict {
        let (o, pivot) = pivot(p);
        let h: [Hom<3>; 4] = [0, 1, 2, 3].map(|i| p[i].approx(o));
        if !approx::in_range(&h, degree(p, pivot)) {
            return Verdict::OutOfRange(largest_scale(&h));
        }
        let row = |i: usize| (h[i].l, h[i].el);
        let sign = match pivot {
            Some(j) => {
                let (det, bound) = det3_bounded(others::<3>(j).map(row));
                certified(det, bound).map(|s| alternate(s, j))
            }
            None => expanded(&h, |i| det3_bounded(others::<3>(i).map(row)), true).map(|s| -s),
        };
        match sign {
            Some(s) => Verdict::Certain(with_weights(s, p)),
            None => Verdict::Uncertain,
        }
    }

    fn exact<P: Point<3>>(&self, p: &[P; 4]) -> Sign {
        let (origin, pivot) = pivot(p);
        exact::run(&Orient3Exact {
            p: *p,
            grid: super::grid(p, false),
            origin,
            pivot,
        })
    }
}

/// `sum_i (-1)^(i + odd) w_i d_i` for the determinants `d_i` of the other
/// rows, each with its bound, certified: each term `w_i d_i` is off by `|w~_i|
/// B_i + (|d~_i| + B_i) E_w,i`, and rounds once, then the sum `K - 1`
/// times: `gamma(K)` of the terms' magnitudes.
#[inline(always)]
fn expanded<const D: usize, const K: usize>(
    h: &[Hom<D>; K],
    det: impl Fn(usize) -> (f64, f64),
    odd: bool,
) -> Option<Sign> {
    let (mut value, mut bound, mut sum) = (0.0, 0.0, 0.0);
    for (i, hi) in h.iter().enumerate() {
        let (d, b) = det(i);
        let t = hi.w * d;
        value += if (i % 2 == 1) == odd { t } else { -t };
        bound += hi.w.abs() * b + (d.abs() + b) * hi.ew;
        sum += t.abs();
    }
    certified(value, (bound + K as f64 * U * sum) * SAFETY)
}

struct Orient3Exact<P> {
    p: [P; 4],
    grid: Grid<3>,
    origin: [f64; 3],
    pivot: Option<usize>,
}

impl<P: Point<3>> Exact for Orient3Exact<P> {
    fn degree(&self) -> u32 {
        degree(&self.p, self.pivot)
    }

    fn grid_bits(&self) -> u32 {
        self.grid.bits
    }

    #[inline(never)]
    fn eval<const K: usize, const N: usize>(&self) -> Sign {
        let lo = self.grid.lo;
        let o = exact::ints::<K, 3>(self.origin, lo);
        let h: [IntHom<K, 3>; 4] = super::homs(&self.p, &o, lo);
        let rows = |i: usize| others::<3>(i).map(|k| &h[k].l);
        let s = match self.pivot {
            Some(j) => alternate(exact::det3::<K, N>(rows(j)).sign(), j),
            None => -expanded_exact(&h, |i| exact::det3::<K, N>(rows(i)), true),
        };
        with_weights(s, &self.p)
    }
}

/// The exact `sum_i (-1)^(i + odd) w_i d_i`.
fn expanded_exact<const K: usize, const N: usize, const D: usize, const L: usize>(
    h: &[IntHom<K, D>; L],
    det: impl Fn(usize) -> Int<N>,
    odd: bool,
) -> Sign {
    let mut sum = Int::<N>::ZERO;
    for (i, hi) in h.iter().enumerate() {
        let t: Int<N> = exact::mul(&hi.w, &det(i));
        sum = if (i % 2 == 1) == odd {
            sum.add(&t)
        } else {
            sum.sub(&t)
        };
    }
    sum.sign()
}

/// orient2d in the plane, or of 3D points projected along `drop`.
struct Planar {
    drop: Option<usize>,
}

impl Planar {
    /// The axes a point's coordinates come from.
    fn axes(&self) -> [usize; 2] {
        match self.drop {
            Some(drop) => [(drop + 1) % 3, (drop + 2) % 3],
            None => [0, 1],
        }
    }
}

impl<const D: usize> Predicate<D, 3> for Planar {
    #[inline(always)]
    fn filter<P: Point<D>>(&self, p: &[P; 3]) -> Verdict {
        let (o, pivot) = pivot(p);
        let h: [Hom<2>; 3] = [0, 1, 2].map(|i| p[i].approx(o).select(self.axes()));
        if !approx::in_range(&h, degree(p, pivot)) {
            return Verdict::OutOfRange(largest_scale(&h));
        }
        let row = |i: usize| (h[i].l, h[i].el);
        let sign = match pivot {
            Some(j) => {
                let (det, bound) = det2_bounded(others::<2>(j).map(row));
                certified(det, bound).map(|s| alternate(s, j))
            }
            None => expanded(&h, |i| det2_bounded(others::<2>(i).map(row)), false),
        };
        match sign {
            Some(s) => Verdict::Certain(with_weights(s, p)),
            None => Verdict::Uncertain,
        }
    }

    fn exact<P: Point<D>>(&self, p: &[P; 3]) -> Sign {
        let (origin, pivot) = pivot(p);
        exact::run(&PlanarExact {
            p: *p,
            grid: super::grid(p, false),
            origin,
            pivot,
            axes: self.axes(),
        })
    }
}

/// The exact planar determinant, with the weights' signs.
struct PlanarExact<P: Point<D>, const D: usize> {
    p: [P; 3],
    grid: Grid<D>,
    origin: [f64; D],
    pivot: Option<usize>,
    axes: [usize; 2],
}

impl<P: Point<D>, const D: usize> Exact for PlanarExact<P, D> {
    fn degree(&self) -> u32 {
        degree(&self.p, self.pivot)
    }

    fn grid_bits(&self) -> u32 {
        self.grid.bits
    }

    #[inline(never)]
    fn eval<const K: usize, const N: usize>(&self) -> Sign {
        let o = exact::ints::<K, D>(self.origin, self.grid.lo);
        let full: [IntHom<K, D>; 3] = super::homs(&self.p, &o, self.grid.lo);
        let h = full.map(|h| IntHom {
            l: [h.l[self.axes[0]], h.l[self.axes[1]]],
            w: h.w,
        });
        let rows = |i: usize| others::<2>(i).map(|k| &h[k].l);
        let s = match self.pivot {
            Some(j) => alternate(exact::det2::<K, N>(rows(j)).sign(), j),
            None => expanded_exact(&h, |i| exact::det2::<K, N>(rows(i)), false),
        };
        with_weights(s, &self.p)
    }
}
