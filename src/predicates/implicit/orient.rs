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

use super::any::{AnyPoint2, AnyPoint3, Point};
use super::approx::{self, Hom, SAFETY, Verdict, certified, det2_bounded, det3_bounded};
use super::exact::{self, Exact, Grid, Int, IntHom};
use super::{ladder, largest_scale, pivot, with_weights};
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
pub(super) fn orient3d(p: [AnyPoint3; 4]) -> Sign {
    if let [
        AnyPoint3::Explicit(a),
        AnyPoint3::Explicit(b),
        AnyPoint3::Explicit(c),
        AnyPoint3::Explicit(d),
    ] = p
    {
        return crate::predicates::orient3d::orient3d(a, b, c, d);
    }
    ladder(p, filter3, |p| exact::run(&Orient3Exact::new(p)))
}

#[inline(always)]
fn filter3(p: &[AnyPoint3; 4]) -> Verdict {
    let (o, pivot) = pivot(p);
    let h: [Hom<3>; 4] = core::array::from_fn(|i| p[i].approx(o));
    if !approx::in_range(h.map(|x| (x.scale, x.explicit)), degree(p, pivot)) {
        return Verdict::OutOfRange(largest_scale(&h));
    }
    let row = |i: usize| (h[i].l, h[i].el);
    let sign = match pivot {
        Some(j) => {
            let (det, bound) = det3_bounded(others::<3>(j).map(row));
            certified(det, bound).map(|s| alternate(s, j))
        }
        None => {
            let (mut value, mut bound, mut sum) = (0.0, 0.0, 0.0);
            for i in 0..4 {
                let (d, b) = det3_bounded(others::<3>(i).map(row));
                let t = h[i].w * d;
                value += if i % 2 == 0 { -t } else { t };
                bound += h[i].w.abs() * b + (d.abs() + b) * h[i].ew;
                sum += t.abs();
            }
            // Each product rounds once and the sum three times: gamma(4).
            certified(value, (bound + 4.0 * U * sum) * SAFETY).map(|s| -s)
        }
    };
    match sign {
        Some(s) => Verdict::Certain(with_weights(s, p)),
        None => Verdict::Uncertain,
    }
}

struct Orient3Exact {
    p: [AnyPoint3; 4],
    grid: Grid<3>,
    origin: [f64; 3],
    pivot: Option<usize>,
}

impl Orient3Exact {
    fn new(p: &[AnyPoint3; 4]) -> Self {
        let (origin, pivot) = pivot(p);
        Orient3Exact {
            p: *p,
            grid: exact::grid(p, false),
            origin,
            pivot,
        }
    }
}

impl Exact for Orient3Exact {
    fn degree(&self) -> u32 {
        degree(&self.p, self.pivot)
    }

    fn grid_bits(&self) -> u32 {
        self.grid.bits
    }

    fn eval<const K: usize, const N: usize>(&self) -> Sign {
        let lo = self.grid.lo;
        let o = exact::ints::<K, 3>(self.origin, lo);
        let h: [IntHom<K, 3>; 4] = core::array::from_fn(|i| self.p[i].exact(&o, lo));
        let rows = |i: usize| others::<3>(i).map(|k| &h[k].l);
        let s = match self.pivot {
            Some(j) => alternate(exact::det3::<K, N>(rows(j)).sign(), j),
            None => {
                let mut det = Int::<N>::ZERO;
                for (i, hi) in h.iter().enumerate() {
                    let t = Int::<N>::mul(&hi.w, &exact::det3::<K, N>(rows(i)));
                    det = if i % 2 == 0 { det.sub(&t) } else { det.add(&t) };
                }
                -det.sign()
            }
        };
        with_weights(s, &self.p)
    }
}

/// orient2d of any three points in the plane.
#[inline(always)]
pub(super) fn orient2d(p: [AnyPoint2; 3]) -> Sign {
    if let [
        AnyPoint2::Explicit(a),
        AnyPoint2::Explicit(b),
        AnyPoint2::Explicit(c),
    ] = p
    {
        return crate::predicates::orient2d::orient2d(a, b, c);
    }
    ladder(
        p,
        |p| {
            let (o, pivot) = pivot(p);
            let h: [Hom<2>; 3] = core::array::from_fn(|i| p[i].approx(o));
            filter2(h, degree(p, pivot), pivot).map(|s| with_weights(s, p))
        },
        |p| exact::run(&PlanarExact::new(p, None)),
    )
}

/// orient2d of three 3D points projected along axis `drop` (onto the axes
/// `drop + 1`, `drop + 2`, cyclically).
#[inline(always)]
pub(super) fn orient2d_projected(p: [AnyPoint3; 3], drop: usize) -> Sign {
    let (i, j) = ((drop + 1) % 3, (drop + 2) % 3);
    if let [
        AnyPoint3::Explicit(a),
        AnyPoint3::Explicit(b),
        AnyPoint3::Explicit(c),
    ] = p
    {
        let pr = |v: DVec3| DVec2::new(v[i], v[j]);
        return crate::predicates::orient2d::orient2d(pr(a), pr(b), pr(c));
    }
    ladder(
        p,
        |p| {
            let (o, pivot) = pivot(p);
            let h: [Hom<2>; 3] = core::array::from_fn(|k| p[k].approx(o).project(drop));
            filter2(h, degree(p, pivot), pivot).map(|s| with_weights(s, p))
        },
        |p| exact::run(&PlanarExact::new(p, Some(drop))),
    )
}

/// The filter of the planar determinant, before the weights' signs.
#[inline(always)]
fn filter2(h: [Hom<2>; 3], deg: u32, pivot: Option<usize>) -> Verdict {
    if !approx::in_range(h.map(|x| (x.scale, x.explicit)), deg) {
        return Verdict::OutOfRange(largest_scale(&h));
    }
    let row = |i: usize| (h[i].l, h[i].el);
    let sign = match pivot {
        Some(j) => {
            let (det, bound) = det2_bounded(others::<2>(j).map(row));
            certified(det, bound).map(|s| alternate(s, j))
        }
        None => {
            let (mut value, mut bound, mut sum) = (0.0, 0.0, 0.0);
            for i in 0..3 {
                let (d, b) = det2_bounded(others::<2>(i).map(row));
                let t = h[i].w * d;
                value += if i % 2 == 0 { t } else { -t };
                bound += h[i].w.abs() * b + (d.abs() + b) * h[i].ew;
                sum += t.abs();
            }
            // Each product rounds once and the sum twice: gamma(3).
            certified(value, (bound + 3.0 * U * sum) * SAFETY)
        }
    };
    match sign {
        Some(s) => Verdict::Certain(s),
        None => Verdict::Uncertain,
    }
}

/// The exact planar determinant (in the plane, or of 3D points projected
/// along `drop`), with the weights' signs.
struct PlanarExact<P: Point<D>, const D: usize> {
    p: [P; 3],
    grid: Grid<D>,
    origin: [f64; D],
    pivot: Option<usize>,
    drop: Option<usize>,
}

impl<P: Point<D>, const D: usize> PlanarExact<P, D> {
    fn new(p: &[P; 3], drop: Option<usize>) -> Self {
        let (origin, pivot) = pivot(p);
        PlanarExact {
            p: *p,
            grid: exact::grid(p, false),
            origin,
            pivot,
            drop,
        }
    }

    /// A point's integers in the plane.
    fn planar<const K: usize>(&self, i: usize, o: &[Int<K>; D]) -> IntHom<K, 2> {
        let h = self.p[i].exact(o, self.grid.lo);
        let axis = |k: usize| match self.drop {
            Some(drop) => (drop + 1 + k) % 3,
            None => k,
        };
        IntHom {
            l: [h.l[axis(0)], h.l[axis(1)]],
            w: h.w,
        }
    }
}

impl<P: Point<D>, const D: usize> Exact for PlanarExact<P, D> {
    fn degree(&self) -> u32 {
        degree(&self.p, self.pivot)
    }

    fn grid_bits(&self) -> u32 {
        self.grid.bits
    }

    fn eval<const K: usize, const N: usize>(&self) -> Sign {
        let o = exact::ints::<K, D>(self.origin, self.grid.lo);
        let h: [IntHom<K, 2>; 3] = core::array::from_fn(|i| self.planar(i, &o));
        let rows = |i: usize| others::<2>(i).map(|k| &h[k].l);
        let s = match self.pivot {
            Some(j) => alternate(exact::det2::<K, N>(rows(j)).sign(), j),
            None => {
                let mut det = Int::<N>::ZERO;
                for (i, hi) in h.iter().enumerate() {
                    let t = Int::<N>::mul(&hi.w, &exact::det2::<K, N>(rows(i)));
                    det = if i % 2 == 0 { det.add(&t) } else { det.sub(&t) };
                }
                det.sign()
            }
        };
        with_weights(s, &self.p)
    }
}
