//! Ray against [`Quadric`]: exact root count, accurate roots.

use super::{Hit, Precise, RayCast, hit_at, unit_or};
use crate::arith::double_double::DoubleDouble;
use crate::arith::exponent::{Grain, pow2};
use crate::arith::fixed_int::{DEG1, DEG2, FixedInt};
use crate::arith::fma_dispatch::{FmaKernel, with_fma};
use crate::arith::roundoff::U;
use crate::arith::std_or_libm::fma;
use crate::interval::Interval;
use crate::query::ray::Ray;
use crate::roots::line_quadratic::{
    Coeffs, ETA, LineQuadratic, Polynomial, Question, SMALL_SPAN, Tier, exact_roots, first_in,
    in_filter_range, line_roots,
};
use crate::roots::{BoundedRoot, Roots};
use crate::shape::Quadric;
use glam::DVec3;

/// Limbs at the common grains: an input (below `2^2100`, doubled), then
/// degrees 2, 3 and 6.
const W1: usize = DEG1;
const W2: usize = DEG2;
/// A product of a degree-1 and a degree-2 value takes the limbs of both.
const W3: usize = W1 + W2;
/// A product of two degree-3 values takes the limbs of both.
const W6: usize = 2 * W3;

impl Quadric {
    /// Every real root in `t` of the quadric's equation at `o + t d`, over
    /// the whole line, sorted. The count is exact (a zero leading
    /// coefficient gives the linear root; an identically zero polynomial,
    /// as for a line on the quadric and for every line with all ten
    /// coefficients zero, gives [`Roots::All`]); roots carry the accuracy of
    /// [`Sphere::line_roots`](crate::shape::Sphere::line_roots).
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        line_roots(self, ray.origin(), ray.direction())
    }

    /// The first root in `range` from `tier`, bounded.
    #[inline(always)]
    fn first_in(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<BoundedRoot> {
        first_in(self, ray.origin(), ray.direction(), range, tier)
    }
}

/// No rounded coefficients: the default tier asks the filtered stage.
impl LineQuadratic for Quadric {
    #[inline]
    fn filtered<Q: Question>(&self, o: DVec3, d: DVec3, q: Q) -> Option<Q::Answer> {
        with_fma(&Filtered {
            k: &self.k,
            o,
            d,
            q,
        })
    }

    fn exact(&self, o: DVec3, d: DVec3) -> Roots {
        exact(&self.k, o, d)
    }
}

/// The symmetric 4x4 matrix `2 Q` of the quadric in homogeneous
/// coordinates, `x^T (2Q) x = 2 (equation)` for `x = (x, y, z, 1)`: every
/// entry is a coefficient or twice one, so it is exact.
#[inline(always)]
fn doubled_matrix(k: &[f64; 10]) -> [[f64; 4]; 4] {
    let [a, b, c, d, e, f, g, h, i, j] = *k;
    [
        [2.0 * a, d, e, g],
        [d, 2.0 * b, f, h],
        [e, f, 2.0 * c, i],
        [g, h, i, 2.0 * j],
    ]
}

/// `x^T M y` and the sum of the magnitudes of its 16 terms.
#[inline(always)]
fn bilinear(m: &[[f64; 4]; 4], x: [f64; 4], y: [f64; 4]) -> (f64, f64) {
    let (mut s, mut mag) = (0.0, 0.0);
    for i in 0..4 {
        for j in 0..4 {
            let term = x[i] * m[i][j] * y[j];
            s += term;
            mag += term.abs();
        }
    }
    (s, mag)
}

/// The filtered stage. With `x = (o, 1)`, `y = (d, 0)`: `A = y^T 2Q y`,
/// `B = y^T 2Q x`, `C = x^T 2Q x`, the half form of twice the equation.
/// Each is a sum of 16 products of three factors: 2 roundings per term and
/// 15 for the sum, so within `17 u` of the sum of the terms' magnitudes
/// (which the same loop computes, rounding upwards by at most that much
/// again; the bound uses 18).
struct Filtered<'a, Q> {
    k: &'a [f64; 10],
    o: DVec3,
    d: DVec3,
    q: Q,
}

impl<Q: Question> FmaKernel for Filtered<'_, Q> {
    type Output = Option<Q::Answer>;

    #[inline(always)]
    fn run(&self) -> Option<Q::Answer> {
        filtered(self.k, self.o, self.d, self.q)
    }
}

/// Whether every factor of the terms `x_i (2Q)_ij y_j` is zero or within
/// `2^±300` in magnitude: then no product of three (nor its double-double
/// error term) leaves the normal range, every rounding is relative, and the
/// filter's bounds hold. Outside it the filter declines. (A term whose
/// partial product `x_i m_ij` underflowed was once lost from both the sum
/// and its magnitude, and a wrong root count certified: a fuzzer finding,
/// `tests/ray_quadrics.rs`.)
#[inline(always)]
fn factors_in_range(k: &[f64; 10], o: DVec3, d: DVec3) -> bool {
    let (lo, hi) = (pow2(-300), pow2(300));
    let ok = |v: f64| v == 0.0 || (lo..=hi).contains(&v.abs());
    k.iter().all(|&v| ok(v)) && o.to_array().into_iter().chain(d.to_array()).all(ok)
}

#[inline(always)]
fn filtered<Q: Question>(k: &[f64; 10], o: DVec3, d: DVec3, q: Q) -> Option<Q::Answer> {
    if !factors_in_range(k, o, d) {
        return None;
    }
    let m = doubled_matrix(k);
    let x = [o.x, o.y, o.z, 1.0];
    let y = [d.x, d.y, d.z, 0.0];
    let (a, ma) = bilinear(&m, y, y);
    let (b, mb) = bilinear(&m, y, x);
    let (c, mc) = bilinear(&m, x, x);
    if !(in_filter_range(ma) && in_filter_range(mb) && in_filter_range(mc)) {
        return None;
    }
    let (e_a, e_b, e_c) = (18.0 * U * ma, 18.0 * U * mb, 18.0 * U * mc);
    let k2 = Coeffs::with_product_discriminant((a, e_a), (b, e_b), (c, e_c));
    // A leading coefficient that is (nearly) zero declines here and goes to
    // the exact stage, which handles degrees 1 and 0.
    q.answer(&k2, &Line { m, o, d })
}

/// The quadric's equation along the line `o + t d`.
struct Line {
    m: [[f64; 4]; 4],
    o: DVec3,
    d: DVec3,
}

impl Polynomial for Line {
    /// The working-precision bound is relative to the terms' magnitudes,
    /// which for a point far from the quadric's centre dwarf the value
    /// near a root: measured, it almost never certified a root.
    const TRY_FAST: bool = false;

    /// `x^T 2Q x` at `x = (o + t d, 1)`, with a rigorous first-order error
    /// bound: each coordinate `fma(t, d_i, o_i)` rounds once, and an error
    /// `δx_i` changes the form by at most `2 |(2Q |x|)_i| δx_i`; the form's
    /// own 16 products and sums round within `18 u` of the sum of its
    /// terms' magnitudes, as in [`filtered`].
    #[inline(always)]
    fn eval_fast(&self, t: f64) -> (f64, f64) {
        let (m, o, d) = (&self.m, self.o, self.d);
        let x = DVec3::new(fma(t, d.x, o.x), fma(t, d.y, o.y), fma(t, d.z, o.z));
        let ex = x.abs() * U + DVec3::splat(ETA);
        let xh = [x.x, x.y, x.z, 1.0];
        let (p, mag) = bilinear(m, xh, xh);
        let mut prop = 0.0;
        for i in 0..3 {
            let g: f64 = (0..4).map(|j| (m[i][j] * xh[j]).abs()).sum();
            prop += 2.0 * g * ex[i];
        }
        (p, prop + 18.0 * U * mag + 16.0 * ETA)
    }

    /// `x^T 2Q x` in double-double: each `x_i = hi + lo` from error-free
    /// transformations (Higham §4.3), each of the ten distinct terms
    /// `w m_ij x_i x_j` (`w` = 1 on the diagonal, 2 off it) split into an
    /// exact product of the high parts and low-order terms, the high parts
    /// summed exactly; only low-order terms (of relative size `u`) round.
    #[inline(always)]
    fn eval_precise(&self, t: f64) -> (f64, f64) {
        let (m, o, d) = (&self.m, self.o, self.d);
        let (mut xh, mut xl, mut ex) = ([1.0; 4], [0.0; 4], [0.0; 4]);
        for i in 0..3 {
            let DoubleDouble { hi: ph, lo: pl } = DoubleDouble::product(t, d[i]);
            let DoubleDouble { hi: sh, lo: sl } = DoubleDouble::sum(o[i], ph);
            xh[i] = sh;
            xl[i] = sl + pl;
            ex[i] = U * xl[i].abs() + 2.0 * ETA;
        }
        let (mut s, mut tail, mut mag, mut e) = (0.0, 0.0, 0.0, 0.0);
        for i in 0..4 {
            for j in i..4 {
                let w = if i == j { m[i][j] } else { 2.0 * m[i][j] };
                let DoubleDouble { hi: h, lo: l } = DoubleDouble::product(xh[i], xh[j]);
                let DoubleDouble { hi: big, lo: big_l } = DoubleDouble::product(w, h);
                let mixed = l + xh[i] * xl[j] + xl[i] * xh[j];
                let low = big_l + w * mixed;
                let DoubleDouble { hi: s2, lo: se } = DoubleDouble::sum(s, big);
                s = s2;
                tail += low + se;
                let mixed_mag = l.abs() + (xh[i] * xl[j]).abs() + (xl[i] * xh[j]).abs();
                mag += big_l.abs() + w.abs() * mixed_mag + se.abs() + low.abs();
                // The dropped xl_i xl_j and the errors of the low parts.
                let (ai, aj) = (xh[i].abs() + xl[i].abs(), xh[j].abs() + xl[j].abs());
                // The product of the high parts is exact unless it underflows
                // (ETA), an error that w scales.
                e += w.abs()
                    * ((xl[i] * xl[j]).abs() + ex[i] * aj + ex[j] * ai + ex[i] * ex[j] + ETA);
            }
        }
        let p = s + tail;
        // Per term, at most 6 roundings among its low-order quantities, and
        // 2 for the running tail: within 8 u of their magnitudes.
        (p, e + 8.0 * U * mag + U * p.abs() + 64.0 * ETA)
    }
}

/// The exact stage: the coefficients and `o` at one grain `lo <= 0` (so
/// the homogeneous `1` is an integer too), `d` at its own `ld`: `A` at
/// `lo + 2 ld`, `B` at `2 lo + ld`, `C` at `3 lo`. Small integers when the
/// spans allow (the doubled entries need one bit more).
fn exact(k: &[f64; 10], o: DVec3, d: DVec3) -> Roots {
    let mut values = [0.0; 14];
    values[..10].copy_from_slice(k);
    values[10..13].copy_from_slice(&o.to_array());
    values[13] = 1.0;
    let g = Grain::of(&values);
    let gd = Grain::of(&d.to_array());
    let lo = g.lo_min.min(0);
    if g.span().max(gd.span()) < SMALL_SPAN {
        exact_in::<2, 5, 7, 14>(k, o, d, lo, gd.lo_min)
    } else {
        exact_in::<W1, W2, W3, W6>(k, o, d, lo, gd.lo_min)
    }
}

fn exact_in<const N1: usize, const N2: usize, const N3: usize, const N6: usize>(
    k: &[f64; 10],
    o: DVec3,
    d: DVec3,
    lo: i32,
    ld: i32,
) -> Roots {
    // 2Q from the coefficients, doubled in integers: doubling in f64 would
    // overflow for coefficients near f64::MAX.
    let [a, b, c, d2, e, f, g, h, i, j] = k.map(|v| FixedInt::<N1>::from_f64(v, lo));
    let two = |v: &FixedInt<N1>| v.add(v);
    let mw: [[FixedInt<N1>; 4]; 4] = [
        [two(&a), d2, e, g],
        [d2, two(&b), f, h],
        [e, f, two(&c), i],
        [g, h, i, two(&j)],
    ];
    let x: [FixedInt<N1>; 4] =
        core::array::from_fn(|i| FixedInt::from_f64([o.x, o.y, o.z, 1.0][i], lo));
    let y: [FixedInt<N1>; 4] =
        core::array::from_fn(|i| FixedInt::from_f64([d.x, d.y, d.z, 0.0][i], ld));
    let times = |v: &[FixedInt<N1>; 4]| -> [FixedInt<N2>; 4] {
        core::array::from_fn(|i| {
            (0..4).fold(FixedInt::ZERO, |s, j| {
                s.add(&FixedInt::mul(&mw[i][j], &v[j]))
            })
        })
    };
    let dot = |u: &[FixedInt<N1>; 4], v: &[FixedInt<N2>; 4]| -> FixedInt<N3> {
        (0..4).fold(FixedInt::ZERO, |s, i| s.add(&FixedInt::mul(&u[i], &v[i])))
    };
    let (my, mx) = (times(&y), times(&x));
    let a = dot(&y, &my);
    let b = dot(&x, &my);
    let c = dot(&x, &mx);
    exact_roots::<N3, N6>((&a, lo + 2 * ld), (&b, 2 * lo + ld), (&c, 3 * lo))
}

impl RayCast for Quadric {
    /// The first hit in `range`; the normal is the normalized gradient
    /// (against the ray where the gradient vanishes, as at a cone's apex).
    /// A line on the quadric (every line, for all-zero coefficients) hits
    /// at the point of `range` nearest `t = 0`; with all-zero coefficients
    /// the gradient is zero everywhere, so the normal is the reversed ray
    /// direction, normalized.
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.cast_tier(ray, range, Tier::Default)
    }

    /// The default tier: hit or miss exact, `t` from the stable formula on
    /// the filtered coefficients with an a-priori bound
    /// (`roots/bounded.rs`); for a line on the quadric (every line, for
    /// all-zero coefficients) the point of `range` nearest `t = 0`, exact.
    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        self.first_in(ray, range, Tier::Default)
    }
}

impl Quadric {
    /// The first hit in `range` from `tier`'s root.
    #[inline]
    fn cast_tier(&self, ray: &Ray, range: Interval, tier: Tier) -> Option<Hit> {
        hit_at(self.first_in(ray, range, tier), ray, |point| {
            unit_or(self.gradient(point), -ray.direction())
        })
    }
}

impl RayCast for Precise<Quadric> {
    /// [`Quadric`]'s cast, its `t` within 4 ulps of the correctly rounded
    /// root ([`Quadric::line_roots`]' accuracy).
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.0.cast_tier(ray, range, Tier::Precise)
    }

    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        self.0.first_in(ray, range, Tier::Precise)
    }
}
