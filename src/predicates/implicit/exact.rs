//! The exact stage: every input coordinate as an integer at its axis's
//! finest bit, each point's homogeneous coordinates and weight as exact
//! integers relative to an input point, and the predicates' polynomials
//! evaluated on them in fixed-capacity stack integers (`arith::fixed_int`),
//! whatever the inputs' exponents.
//!
//! # Why per-axis integers are exact
//! Scaling axis `k` by a positive `s_k` maps lines, planes and their
//! intersections to lines, planes and intersections, and multiplies every
//! predicate's polynomial by a positive monomial in the `s_k` (each of its
//! terms has the same number of factors from each axis). With `s_k = 2^-lo_k`,
//! `lo_k` the finest bit of axis `k` over every input, every coordinate is
//! an integer, and the sign of the polynomial on those integers is the
//! sign of the polynomial on the inputs. The order along a line is the one
//! predicate this does not hold for (a dot product mixes the axes); it
//! takes one grain for all axes (`GridBuilder::build` with `common`).
//!
//! # Widths
//! A difference of two coordinates is below `2^S` (`S` the grid's
//! `bits`, at most `2100` for `f64`); a value of degree `d` in the
//! differences is below `2^(d S)` times the sum of its polynomial's
//! coefficients, below `2^32` for every value here (the largest, the
//! determinant of four three-plane points, has at most `4 * 48 * 6 *
//! 144^3 < 2^32`). [`run`] picks the narrowest integers that hold `d S +
//! 48` bits for the predicate's degree `d`: the points' own values (degree
//! 7 at most) in `K` limbs, the predicate's in `N`.

use crate::arith::exponent::split;
use crate::arith::fixed_int::FixedInt;
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// The finest bit of every axis over a set of inputs, and the bits of a
/// difference of two of them as integers at those bits.
#[derive(Clone, Copy, Debug)]
pub(super) struct Grid<const D: usize> {
    pub(super) lo: [i32; D],
    pub(super) bits: u32,
}

/// Collects the finest and coarsest bits of every axis.
pub(super) struct GridBuilder<const D: usize> {
    lo: [i32; D],
    hi: [i32; D],
}

impl<const D: usize> GridBuilder<D> {
    pub(super) fn new() -> Self {
        GridBuilder {
            lo: [i32::MAX; D],
            hi: [i32::MIN; D],
        }
    }

    /// Takes one input point (finite).
    pub(super) fn add(&mut self, v: [f64; D]) {
        for (k, x) in v.into_iter().enumerate() {
            let (m, e) = split(x);
            if m != 0 {
                let mag = m.unsigned_abs();
                self.lo[k] = self.lo[k].min(e + mag.trailing_zeros() as i32);
                self.hi[k] = self.hi[k].max(e + 63 - mag.leading_zeros() as i32);
            }
        }
    }

    /// The grid: per axis, or with `common` one grain for all axes.
    pub(super) fn build(self, common: bool) -> Grid<D> {
        let (mut lo, mut hi) = (self.lo, self.hi);
        if common {
            let l = lo.iter().copied().min().unwrap_or(i32::MAX);
            let h = hi.iter().copied().max().unwrap_or(i32::MIN);
            (lo, hi) = ([l; D], [h; D]);
        }
        let mut span = 0;
        for k in 0..D {
            if lo[k] == i32::MAX {
                // Every coordinate of the axis is zero.
                lo[k] = 0;
            } else {
                span = span.max(hi[k] - lo[k] + 1);
            }
        }
        Grid {
            lo,
            bits: span as u32 + 1,
        }
    }
}

/// An exact evaluation, run at the width its degree needs.
pub(super) trait Exact {
    /// The degree of its polynomial in the input differences.
    fn degree(&self) -> u32;
    /// The bits of a difference on its grid.
    fn grid_bits(&self) -> u32;
    /// Its sign, with the points' values in `K` limbs and its own in `N`.
    fn eval<const K: usize, const N: usize>(&self) -> Sign;
}

/// The bits a `FixedInt<N>` holds with a sign (`fixed_int::limbs_for`).
const fn capacity(limbs: usize) -> u32 {
    64 * (limbs as u32 - 1) - 1
}

/// Runs `e` at the narrowest width that holds it (see the module docs). The
/// widest, 900 limbs (7.2 KB per integer), holds degree 27 at the full
/// `2100`-bit span; the points' values then stay in 256 limbs.
pub(super) fn run(e: &impl Exact) -> Sign {
    let need = e.degree() * e.grid_bits() + 48;
    if need <= capacity(4) {
        e.eval::<4, 4>()
    } else if need <= capacity(8) {
        e.eval::<8, 8>()
    } else if need <= capacity(16) {
        e.eval::<16, 16>()
    } else if need <= capacity(64) {
        e.eval::<64, 64>()
    } else if need <= capacity(256) {
        e.eval::<256, 256>()
    } else {
        e.eval::<256, 900>()
    }
}

/// Integers of `K` limbs.
pub(super) type Int<const K: usize> = FixedInt<K>;

/// A point's exact homogeneous coordinates `w (X - o)` and weight `w`, on
/// the grid.
#[derive(Clone, Copy)]
pub(super) struct IntHom<const K: usize, const D: usize> {
    pub(super) l: [Int<K>; D],
    pub(super) w: Int<K>,
}

/// The coordinates of `v` as integers at the grid's bits.
pub(super) fn ints<const K: usize, const D: usize>(v: [f64; D], lo: [i32; D]) -> [Int<K>; D] {
    core::array::from_fn(|k| Int::from_f64(v[k], lo[k]))
}

fn sub<const K: usize, const D: usize>(a: &[Int<K>; D], b: &[Int<K>; D]) -> [Int<K>; D] {
    core::array::from_fn(|k| a[k].sub(&b[k]))
}

fn dot<const K: usize>(a: &[Int<K>; 3], b: &[Int<K>; 3]) -> Int<K> {
    mul(&a[0], &b[0])
        .add(&mul(&a[1], &b[1]))
        .add(&mul(&a[2], &b[2]))
}

fn cross<const K: usize>(a: &[Int<K>; 3], b: &[Int<K>; 3]) -> [Int<K>; 3] {
    core::array::from_fn(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        mul::<K, K, K>(&a[i], &b[j]).sub(&mul(&a[j], &b[i]))
    })
}

fn perp<const K: usize>(a: &[Int<K>; 2], b: &[Int<K>; 2]) -> Int<K> {
    mul(&a[0], &b[1]).sub(&mul(&a[1], &b[0]))
}

/// `a s - b t`, componentwise.
fn combine<const K: usize, const D: usize>(
    a: &[Int<K>; D],
    s: &Int<K>,
    b: &[Int<K>; D],
    t: &Int<K>,
) -> [Int<K>; D] {
    core::array::from_fn(|k| mul(&a[k], s).sub(&mul(&b[k], t)))
}

/// An explicit point relative to the origin `o` (integers on the grid
/// `lo`): `x - o` over the weight 1.
pub(super) fn explicit<const K: usize, const D: usize>(
    x: [f64; D],
    o: &[Int<K>; D],
    lo: [i32; D],
) -> IntHom<K, D> {
    IntHom {
        l: sub(&ints(x, lo), o),
        w: Int::from_i64(1),
    }
}

/// An `Lpi` (its inputs `p, q, r, s, t`) relative to the origin `o`. Each
/// construction is its own function (and a `Tpi` a plane at a time), so
/// that their integers are never on the stack together.
#[inline(never)]
pub(super) fn lpi<const K: usize>(
    [p, q, r, s, t]: [DVec3; 5],
    o: &[Int<K>; 3],
    lo: [i32; 3],
) -> IntHom<K, 3> {
    let n = cross(&difference(s, r, lo), &difference(t, r, lo));
    let e = difference(q, p, lo);
    let d = dot(&n, &e);
    let pp = dot(&n, &difference(p, r, lo));
    IntHom {
        l: combine(&sub(&ints(p.to_array(), lo), o), &d, &e, &pp),
        w: d,
    }
}

/// `a - b` as integers on the grid `lo`.
#[inline(never)]
fn difference<const K: usize>(a: DVec3, b: DVec3, lo: [i32; 3]) -> [Int<K>; 3] {
    sub(&ints(a.to_array(), lo), &ints(b.to_array(), lo))
}

/// A `Tpi` (its planes) relative to the origin `o`.
#[inline(never)]
pub(super) fn tpi<const K: usize>(
    planes: &[[DVec3; 3]; 3],
    o: &[Int<K>; 3],
    lo: [i32; 3],
) -> IntHom<K, 3> {
    let mut n = [[Int::ZERO; 3]; 3];
    let mut h = [Int::ZERO; 3];
    for (i, plane) in planes.iter().enumerate() {
        (n[i], h[i]) = plane_normal(plane, o, lo);
    }
    let c = [
        cross(&n[1], &n[2]),
        cross(&n[2], &n[0]),
        cross(&n[0], &n[1]),
    ];
    let l = core::array::from_fn(|k| {
        mul(&c[0][k], &h[0])
            .add(&mul(&c[1][k], &h[1]))
            .add(&mul(&c[2][k], &h[2]))
    });
    IntHom {
        l,
        w: dot(&n[0], &c[0]),
    }
}

/// A plane's normal `n = (p1 - p0) x (p2 - p0)` and offset `h = n . (p0 -
/// o)`.
#[inline(never)]
fn plane_normal<const K: usize>(
    plane: &[DVec3; 3],
    o: &[Int<K>; 3],
    lo: [i32; 3],
) -> ([Int<K>; 3], Int<K>) {
    let [p0, p1, p2] = *plane;
    let n = cross(&difference(p1, p0, lo), &difference(p2, p0, lo));
    let h = dot(&n, &sub(&ints(p0.to_array(), lo), o));
    (n, h)
}

/// An `Ssi` (its inputs `p, q, r, s`) relative to the origin `o`.
pub(super) fn ssi<const K: usize>(
    [p, q, r, s]: [DVec2; 4],
    o: &[Int<K>; 2],
    lo: [i32; 2],
) -> IntHom<K, 2> {
    let int = |v: DVec2| ints::<K, 2>(v.to_array(), lo);
    let [p, q, r, s] = [p, q, r, s].map(int);
    let (e, f) = (sub(&q, &p), sub(&s, &r));
    let d = perp(&e, &f);
    let t = perp(&sub(&r, &p), &f);
    // D (p - o) + T e = D (p - o) - (-T) e.
    IntHom {
        l: combine(&sub(&p, o), &d, &e, &t.neg()),
        w: d,
    }
}

/// `a b` into `N` limbs, out of line: the product's scratch (two
/// magnitudes and a list of non-zero limbs, up to 22 KB at the widest) is
/// then on the stack once, not at every call site the optimizer would
/// inline it into.
#[inline(never)]
pub(super) fn mul<const N: usize, const A: usize, const B: usize>(
    a: &Int<A>,
    b: &Int<B>,
) -> Int<N> {
    Int::<N>::mul(a, b)
}

/// `det[x0, x1, x2] = x0 . (x1 x x2)` of integer rows.
#[inline(never)]
pub(super) fn det3<const K: usize, const N: usize>(rows: [&[Int<K>; 3]; 3]) -> Int<N> {
    let [x, y, z] = rows;
    let minor = |i: usize, j: usize| mul::<N, K, K>(&y[i], &z[j]).sub(&mul(&y[j], &z[i]));
    mul::<N, K, N>(&x[0], &minor(1, 2))
        .add(&mul(&x[1], &minor(2, 0)))
        .add(&mul(&x[2], &minor(0, 1)))
}

/// `det[x0, x1]` of integer rows.
#[inline(never)]
pub(super) fn det2<const K: usize, const N: usize>(rows: [&[Int<K>; 2]; 2]) -> Int<N> {
    let [x, y] = rows;
    mul::<N, K, K>(&x[0], &y[1]).sub(&mul(&x[1], &y[0]))
}

/// The grid of a set of input points.
fn grid_of<const D: usize>(points: &[[f64; D]]) -> Grid<D> {
    let mut g = GridBuilder::new();
    points.iter().for_each(|&v| g.add(v));
    g.build(false)
}

/// The exact sign of a `Tpi`'s weight (of its planes).
pub(super) fn tpi_weight_sign(planes: &[[DVec3; 3]; 3]) -> Sign {
    struct Weight<'a>(&'a [[DVec3; 3]; 3], Grid<3>);
    impl Exact for Weight<'_> {
        fn degree(&self) -> u32 {
            6
        }
        fn grid_bits(&self) -> u32 {
            self.1.bits
        }
        #[inline(never)]
        fn eval<const K: usize, const N: usize>(&self) -> Sign {
            let o = [Int::ZERO; 3];
            let n = self.0.map(|p| plane_normal::<K>(&p, &o, self.1.lo).0);
            det3::<K, N>([&n[0], &n[1], &n[2]]).sign()
        }
    }
    let points: [[f64; 3]; 9] = core::array::from_fn(|i| planes[i / 3][i % 3].to_array());
    let grid = grid_of(&points);
    run(&Weight(planes, grid))
}

/// The exact sign of `det[a0 - b0, a1 - b1, a2 - b2]` (the weight of an
/// `Lpi`), where the sparse terms did not fit.
pub(super) fn det3_of_differences(rows: [(DVec3, DVec3); 3]) -> Sign {
    let points = rows.map(|(a, b)| [a.to_array(), b.to_array()]);
    let grid = grid_of(points.as_flattened());
    let int = |v: DVec3| ints::<34, 3>(v.to_array(), grid.lo);
    let d = rows.map(|(a, b)| sub(&int(a), &int(b)));
    det3::<34, 100>([&d[0], &d[1], &d[2]]).sign()
}

/// The exact sign of `(a0 - b0) x (a1 - b1)` (the weight of an `Ssi`),
/// where the sparse terms did not fit.
pub(super) fn cross_of_differences(e: (DVec2, DVec2), f: (DVec2, DVec2)) -> Sign {
    let grid = grid_of(&[e.0, e.1, f.0, f.1].map(|v| v.to_array()));
    let int = |v: DVec2| ints::<34, 2>(v.to_array(), grid.lo);
    let (x, y) = (sub(&int(e.0), &int(e.1)), sub(&int(f.0), &int(f.1)));
    det2::<34, 67>([&x, &y]).sign()
}
