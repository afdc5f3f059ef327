//! Ray against [`Quadric`]: exact root count, accurate roots.

use super::quadratic::{Coeffs, SMALL_SPAN, U, certified_roots, exact_roots, in_filter_range};
use super::{Hit, RayCast, first_hit, first_in, unit_or};
use crate::predicates::grain::Grain;
use crate::predicates::wide::Wide;
use crate::ray::{Interval, Ray};
use crate::roots::Roots;
use crate::shape::Quadric;
use glam::DVec3;

/// Limbs at the common grains: an input (below `2^2100`, doubled), then
/// degrees 2, 3 and 6.
const W1: usize = 34;
const W2: usize = 67;
const W3: usize = 101;
const W6: usize = 202;

impl Quadric {
    /// Every real root in `t` of the quadric's equation at `o + t d`, over
    /// the whole line, sorted. The count is exact (a zero leading
    /// coefficient gives the linear root; an identically zero polynomial
    /// gives [`Roots::All`]); roots carry the accuracy of
    /// [`Sphere::line_roots`](crate::shape::Sphere::line_roots).
    pub fn line_roots(&self, ray: &Ray) -> Roots {
        let (o, d) = (ray.origin(), ray.direction());
        if let Some(roots) = filtered(&self.k, o, d) {
            return roots;
        }
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
#[inline]
fn filtered(k: &[f64; 10], o: DVec3, d: DVec3) -> Option<Roots> {
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
    let disc = crate::float::fma(-a, c, b * b);
    // B^2 rounds once inside the fma's addend, the fma once; the inputs'
    // errors propagate through the products.
    let e_disc = 2.0 * b.abs() * e_b + a.abs() * e_c + c.abs() * e_a + U * b * b + U * disc.abs();
    let k2 = Coeffs {
        a,
        e_a,
        b,
        c,
        disc,
        e_disc,
    };
    // A leading coefficient that is (nearly) zero declines here and goes to
    // the exact stage, which handles degrees 1 and 0.
    certified_roots(&k2, |t| eval(&m, o, d, t))
}

/// `x^T 2Q x` at `x = (o + t d, 1)`, with a rigorous first-order error
/// bound: each coordinate of `o + t d` rounds twice (product and sum), and
/// an error `δx_i` changes the form by at most `2 |(2Q |x|)_i| δx_i`; the
/// form's own 16 products and sums round within `18 u` of the sum of its
/// terms' magnitudes, as in [`filtered`].
#[inline(always)]
fn eval(m: &[[f64; 4]; 4], o: DVec3, d: DVec3, t: f64) -> (f64, f64) {
    let td = d * t;
    let x = o + td;
    let ex = (td.abs() + x.abs()) * U;
    let xh = [x.x, x.y, x.z, 1.0];
    let (p, mag) = bilinear(m, xh, xh);
    let mut prop = 0.0;
    for i in 0..3 {
        let g: f64 = (0..4).map(|j| (m[i][j] * xh[j]).abs()).sum();
        prop += 2.0 * g * ex[i];
    }
    (p, prop + 18.0 * U * mag)
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
    let [a, b, c, d2, e, f, g, h, i, j] = k.map(|v| Wide::<N1>::from_f64(v, lo));
    let two = |v: &Wide<N1>| v.add(v);
    let mw: [[Wide<N1>; 4]; 4] = [
        [two(&a), d2, e, g],
        [d2, two(&b), f, h],
        [e, f, two(&c), i],
        [g, h, i, two(&j)],
    ];
    let x: [Wide<N1>; 4] = core::array::from_fn(|i| Wide::from_f64([o.x, o.y, o.z, 1.0][i], lo));
    let y: [Wide<N1>; 4] = core::array::from_fn(|i| Wide::from_f64([d.x, d.y, d.z, 0.0][i], ld));
    let times = |v: &[Wide<N1>; 4]| -> [Wide<N2>; 4] {
        core::array::from_fn(|i| {
            (0..4).fold(Wide::ZERO, |s, j| s.add(&Wide::mul(&mw[i][j], &v[j])))
        })
    };
    let dot = |u: &[Wide<N1>; 4], v: &[Wide<N2>; 4]| -> Wide<N3> {
        (0..4).fold(Wide::ZERO, |s, i| s.add(&Wide::mul(&u[i], &v[i])))
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
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        first_hit(self.line_roots(ray), ray, range, |point| {
            unit_or(self.gradient(point), -ray.direction())
        })
    }

    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        first_in(self.line_roots(ray), range).is_some()
    }
}
