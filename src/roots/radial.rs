//! The sphere-like problem `|w + t d|^2 = rr` that the sphere (`w = o - c`)
//! and the cylinder (`w`, `d` projected across the axis) share, filtered:
//! its half-form coefficients with error bounds, and the two evaluations
//! of its polynomial that certify the roots ([`Question`]); and, for the
//! default tier, the same coefficients from inputs rounded once
//! ([`rounded_sphere`], [`rounded_circle`]).
//!
//! In the precise tier each input is carried as a double-double `hi + lo` (the sphere's
//! `o - c` and `r^2` are exact that way; the cylinder's projections are
//! within `O(u^2)`), with a bound on what the pair still misses. That is
//! what lets the working-precision evaluation certify far origins: the
//! error of `w + t d` is then relative to the point near the surface, not
//! to `|w|`.

use super::certified::{Coeffs, ETA, Polynomial, Question, in_filter_range, norm1};
use crate::arith::double_double::DoubleDouble;
use crate::arith::roundoff::{U, gamma};
use crate::arith::std_or_libm::fma;
use glam::DVec3;

/// `|w + t d|^2 = rr`, with `w = wh + wl` to within `ew` (componentwise),
/// `d = dh + dl` to within `ed`, and `rr = rh + rl` to within `err`. With
/// `INEXACT` false, `w = wh + wl`, `d = dh` and `rr = rh + rl` exactly
/// (the sphere), and the bounds skip the terms that are zero then.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Circle<const INEXACT: bool> {
    pub wh: DVec3,
    pub wl: DVec3,
    pub ew: DVec3,
    pub dh: DVec3,
    pub dl: DVec3,
    pub ed: DVec3,
    pub rh: f64,
    pub rl: f64,
    pub err: f64,
}

impl<const INEXACT: bool> Circle<INEXACT> {
    /// The filtered answer to `q` (see [`Question`]), or `None` for the
    /// exact stage. The caller checks that the magnitudes are in the
    /// filter's range.
    #[inline(always)]
    pub fn answer<Q: Question>(&self, q: Q) -> Option<Q::Answer> {
        q.answer(&self.coeffs(), self)
    }

    /// `A = |d|^2`, `B = w . d`, `C = |w|^2 - rr` from the high parts, and
    /// the discriminant in Lagrange's form `rr |d|^2 - |w x d|^2`, which
    /// does not cancel for far origins the way `B^2 - A C` does.
    ///
    /// Error bounds (first order), in 1-norms, which cost a few additions
    /// and are loose only by small factors: a sum of `n` rounded products
    /// is within `n u` of its value relative to the sum of its terms'
    /// magnitudes (Higham ch. 3); an input error `δx_i` changes a product
    /// `x_i y_j` by at most `|δx_i| |y_j|`; each component of `w x d` is a
    /// difference of two products, two roundings relative to their
    /// magnitudes. Only the sign of the discriminant needs these bounds to
    /// be tight, and only for rays within about `10 u` of tangency.
    #[inline(always)]
    fn coeffs(&self) -> Coeffs {
        let (w, d) = (self.wh, self.dh);
        let (nw, nd) = (norm1(w), norm1(d));
        // What the high parts miss, in 1-norms: an error δw_i changes a
        // sum of products w_i y_i by at most |δw|_1 max|y_i|.
        let (ew1, ed1, err) = if INEXACT {
            (
                norm1(self.ew) + norm1(self.wl),
                norm1(self.ed) + norm1(self.dl),
                self.err + self.rl.abs(),
            )
        } else {
            (norm1(self.wl), 0.0, self.rl.abs())
        };
        let rr = self.rh;
        let a = d.dot(d);
        let e_a = 2.0 * nd * ed1 + 3.0 * U * a + ETA;
        let b = w.dot(d);
        let e_b = nw * ed1 + ew1 * nd + 3.0 * U * nw * nd + ETA;
        let c = w.dot(w) - rr;
        // From the errors of `w` and `rr`, the dot product's three
        // roundings and the difference's one.
        let e_c = 2.0 * nw * ew1 + ew1 * ew1 + err + 4.0 * U * (w.dot(w) + rr) + ETA;
        let cr = w.cross(d);
        // Summed over the components, |w_i d_j| + |w_j d_i| is at most
        // |w|_1 |d|_1, and so are the propagated errors.
        // Each component's two products may underflow: ETA each.
        let e_cr = nw * ed1 + ew1 * nd + 2.0 * U * nw * nd + 2.0 * ETA;
        let x = cr.dot(cr);
        let e_x = 2.0 * norm1(cr) * e_cr + e_cr * e_cr + 3.0 * U * x;
        let disc = fma(rr, a, -x);
        let e_disc = a * err + rr * e_a + e_x + U * disc.abs() + 8.0 * ETA;
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

impl<const INEXACT: bool> Polynomial for Circle<INEXACT> {
    /// `|x|^2 - rr` at `x = w + t d` in working precision, with a rigorous
    /// first-order error bound. `x_i = fma(t, dh_i, wh_i) + wl_i` rounds
    /// twice, each relative to a value of the size of `x_i` (near a root,
    /// of the size of the radius), however far `w` is; the dot product
    /// rounds within `3 u |x|^2` and the difference once more.
    #[inline(always)]
    fn eval_fast(&self, t: f64) -> (f64, f64) {
        let f = DVec3::new(
            fma(t, self.dh.x, self.wh.x),
            fma(t, self.dh.y, self.wh.y),
            fma(t, self.dh.z, self.wh.z),
        );
        let x = f + self.wl;
        let mut ex = (f.abs() + x.abs()) * U + DVec3::splat(2.0 * ETA);
        if INEXACT {
            ex += self.ew + (self.ed + self.dl.abs()) * t.abs();
        }
        let xx = x.dot(x);
        let diff = xx - self.rh;
        let p = diff - self.rl;
        let e = 2.0 * x.abs().dot(ex)
            + ex.dot(ex)
            + 3.0 * U * xx
            + self.err.abs()
            + U * (diff.abs() + p.abs())
            + 4.0 * ETA;
        (p, e)
    }

    /// `|x|^2 - rr` at `x = w + t d` in double-double: `t dh_i` and `x_i`'s
    /// high part by error-free transformations (Higham §4.3), the squares
    /// likewise, so only the low-order terms round, each at `u` relative
    /// to quantities of size `u |x|^2` or `u |w| |x|`: the bound is
    /// `O(u^2)` of the inputs' magnitudes.
    #[inline(always)]
    fn eval_precise(&self, t: f64) -> (f64, f64) {
        let mut hi = [0.0; 4];
        let mut lo_sum = 0.0;
        let mut lo_mag = 0.0;
        let mut e = self.err;
        for (i, square) in hi.iter_mut().take(3).enumerate() {
            let DoubleDouble { hi: ph, lo: pl } = DoubleDouble::product(t, self.dh[i]);
            let DoubleDouble { hi: sh, lo: sl } = DoubleDouble::sum(self.wh[i], ph);
            // x_i = sh + lo, lo from three low-order terms, two roundings.
            let (tail, mut e_lo) = if INEXACT {
                let tdl = t * self.dl[i];
                let tail = pl + self.wl[i] + tdl;
                let e = self.ew[i] + self.ed[i] * t.abs();
                (
                    tail,
                    e + 2.0 * U * (pl.abs() + self.wl[i].abs() + tdl.abs()),
                )
            } else {
                let tail = pl + self.wl[i];
                (tail, U * tail.abs())
            };
            let lo = sl + tail;
            e_lo += U * lo.abs() + 2.0 * ETA;
            let DoubleDouble { hi: qh, lo: cross } = DoubleDouble { hi: sh, lo }.square();
            *square = qh;
            lo_sum += cross;
            lo_mag += cross.abs();
            // Dropped lo^2, the error of lo carried through 2 sh lo, and the
            // fma's rounding.
            e += lo * lo + 2.0 * (sh.abs() + lo.abs()) * e_lo + e_lo * e_lo + U * cross.abs();
        }
        hi[3] = -self.rh;
        let DoubleDouble { hi: s1, lo: e1 } = DoubleDouble::sum(hi[0], hi[1]);
        let DoubleDouble { hi: s2, lo: e2 } = DoubleDouble::sum(s1, hi[2]);
        let DoubleDouble { hi: s3, lo: e3 } = DoubleDouble::sum(s2, hi[3]);
        let tail = lo_sum + ((e1 + e2) + e3) - self.rl;
        let p = s3 + tail;
        // The tail sums 7 terms: at most 7 roundings of partial sums, each
        // below the sum of the magnitudes.
        let mag = lo_mag + e1.abs() + e2.abs() + e3.abs() + self.rl.abs();
        e += 7.0 * U * mag + U * p.abs() + 8.0 * ETA;
        (p, e)
    }
}

/// The filtered answer for `|w + t d|^2 = r^2` with `w = wh + wl` and `d`
/// exact (the sphere, and the axis-aligned cylinder in its two other
/// coordinates), or `None` where the magnitudes leave the filter's range.
#[inline(always)]
pub(crate) fn circle_of<Q: Question>(
    wh: DVec3,
    wl: DVec3,
    d: DVec3,
    r: f64,
    q: Q,
) -> Option<Q::Answer> {
    let DoubleDouble { hi: rh, lo: rl } = DoubleDouble::product(r, r);
    let (nw, nd) = (norm1(wh), norm1(d));
    let a = nd * nd;
    if !(in_filter_range(a) && in_filter_range(nw * nd) && in_filter_range(rh * a)) {
        return None;
    }
    // r^2 is exact as a pair (in the filter's range it does not underflow).
    Circle::<false> {
        wh,
        wl,
        ew: DVec3::ZERO,
        dh: d,
        dl: DVec3::ZERO,
        ed: DVec3::ZERO,
        rh,
        rl,
        err: 0.0,
    }
    .answer(q)
}

/// `r^2 |a|^2` as a double-double `hi + lo` with a bound on its error: the
/// squares and the high parts' sums by error-free transformations, the
/// low-order terms rounding within a few units of their magnitudes.
pub(crate) fn scaled_square(r: f64, a: DVec3) -> (f64, f64, f64) {
    let DoubleDouble { hi: r2h, lo: r2l } = DoubleDouble::product(r, r);
    let DoubleDouble { hi: q0, lo: l0 } = DoubleDouble::product(a.x, a.x);
    let DoubleDouble { hi: q1, lo: l1 } = DoubleDouble::product(a.y, a.y);
    let DoubleDouble { hi: q2, lo: l2 } = DoubleDouble::product(a.z, a.z);
    let DoubleDouble { hi: s1, lo: f1 } = DoubleDouble::sum(q0, q1);
    let DoubleDouble { hi: ah, lo: f2 } = DoubleDouble::sum(s1, q2);
    let al = (l0 + l1 + l2) + (f1 + f2);
    let e_al = 5.0 * U * (l0.abs() + l1.abs() + l2.abs() + f1.abs() + f2.abs()) + 4.0 * ETA;
    let DoubleDouble { hi: ph, lo: pl } = DoubleDouble::product(r2h, ah);
    let (m1, m2) = (r2h * al, r2l * ah);
    let lo = pl + (m1 + m2);
    // r^2 = r2h + r2l to within ETA (exact unless r^2 underflows); that
    // error is scaled by |a|^2, which may be huge.
    let err = 4.0 * U * (pl.abs() + m1.abs() + m2.abs())
        + r2h.abs() * e_al
        + (r2l * al).abs() * (1.0 + 4.0 * U)
        + r2l.abs() * e_al
        + ETA * (ah + al.abs() + e_al)
        + 4.0 * ETA;
    (ph, lo, err)
}

/// The values the default tier's coefficients of `|w + t d|^2 = rr`
/// share, from rounded inputs (no double-double pairs, no FMA): `A = |d|^2`,
/// `B = w . d`, `C = |w|^2 - rr`, `X = |w x d|^2`, `rr A` and the
/// discriminant in Lagrange's form `rr A - X` (it does not cancel for far
/// origins as `B^2 - A C` does), and the 1-norms of `w`, `d` and `w x d`.
#[derive(Clone, Copy, Debug)]
struct RoundedCircle {
    a: f64,
    b: f64,
    c: f64,
    x: f64,
    ncr: f64,
    ra: f64,
    disc: f64,
    nw: f64,
    nd: f64,
}

impl RoundedCircle {
    /// The values, or `None` where the magnitudes leave the filter's range
    /// (as in [`circle_of`]): `|d|^2`, `|w|_1 |d|_1` and `rr |d|^2` within
    /// `1e±120`, so `rr` itself is normal and no product of two of the
    /// values the bounds combine leaves the normal range. A product of two
    /// components may still underflow: each loses at most `2^-1075`, and
    /// `ETA` (`2^-500`) per coefficient, carried through the same products
    /// as the error it covers, bounds any number of those.
    #[inline(always)]
    fn of(w: DVec3, d: DVec3, rr: f64) -> Option<RoundedCircle> {
        let (nw, nd) = (norm1(w), norm1(d));
        let a = d.dot(d);
        let ra = rr * a;
        if !(in_filter_range(a) && in_filter_range(nw * nd) && in_filter_range(ra)) {
            return None;
        }
        let cr = w.cross(d);
        let x = cr.dot(cr);
        Some(RoundedCircle {
            a,
            b: w.dot(d),
            c: w.dot(w) - rr,
            x,
            ncr: norm1(cr),
            ra,
            disc: ra - x,
            nw,
            nd,
        })
    }

    /// A bound on `X`'s error given `E`, the 1-norm of `w x d`'s error
    /// vector `δ`: `X` moves by `sum_k δ_k (2 x_k + δ_k)`, at most `2 |w x
    /// d|_1 E + E^2`, and rounds within `gamma(3) X`. `|w x d|` is `|d|`
    /// times the line's distance from the centre, so on a hit it is of the
    /// size of the radius, not of `|w|`: far origins' hits stay tight.
    #[inline(always)]
    fn e_x(&self, e_cr: f64) -> f64 {
        2.0 * self.ncr * e_cr + e_cr * e_cr + gamma(3) * self.x
    }
}

/// The margin of the discriminant's bound: its own roundings and the
/// computed norms'.
const DISC_MARGIN: f64 = 1.0 + gamma(16);

/// The margin of the other bounds: their own roundings and the computed
/// norms' (each within `gamma(2)` of the exact one of the computed vector).
const OWN_MARGIN: f64 = 1.0 + gamma(8);

/// The default tier's coefficients of the sphere's `|w + t d|^2 = r^2`
/// (also the axis-aligned cylinder's, in its two other coordinates): `w`
/// rounded once per component (`|δw|_1 <= u |w|_1`), `d` exact, `r^2`
/// rounded once. The bounds of [`rounded_circle`] with these errors,
/// collected (`P = |w|_1 |d|_1`): `e_A = gamma(3) A`; `e_B = gamma(4) P`;
/// `e_C = gamma(7) (|w|_1^2 + r^2)` (from `2 u |w|_1^2 + u^2 |w|_1^2 + u
/// r^2 + gamma(4) (|w|_1^2 + r^2)`); `E = gamma(4) P`; the discriminant's
/// `gamma(5) r^2 A + r^2 ETA + e_X + u |disc|` (from `A u r^2 + r^2 e_A +
/// u r^2 A` and the difference's rounding; `r^2 ETA` carries `e_A`'s
/// slack for underflow).
#[inline(always)]
pub(crate) fn rounded_sphere(w: DVec3, d: DVec3, r: f64) -> Option<Coeffs> {
    let rr = r * r;
    let k = RoundedCircle::of(w, d, rr)?;
    let p = k.nw * k.nd;
    let e_cr = gamma(4) * p + 2.0 * ETA;
    let e_disc = (gamma(5) * k.ra + rr * ETA + k.e_x(e_cr) + U * k.disc.abs()) * DISC_MARGIN + ETA;
    Some(Coeffs {
        a: k.a,
        e_a: gamma(3) * k.a * OWN_MARGIN + ETA,
        b: k.b,
        e_b: gamma(4) * p * OWN_MARGIN + ETA,
        c: k.c,
        e_c: gamma(7) * (k.nw * k.nw + rr) * OWN_MARGIN + ETA,
        disc: k.disc,
        e_disc,
    })
}

/// The default tier's coefficients of `|w + t d|^2 = rr` from inputs
/// rounded a few times, with bounds: the exact `w` within `ew1` of the
/// given one in the 1-norm, the exact `d` within `ed1`, the exact `rr`
/// within `err` (the general cylinder's projections).
///
/// Error bounds, first order, in 1-norms as in `Circle::coeffs` (Higham,
/// *Accuracy and Stability*, ch. 3: a sum of `n` rounded products is
/// within `gamma(n)` of the sum of their magnitudes): an input error
/// `δx_i` moves a product `x_i y_j` by `|δx_i| |y_j|`, summed over the
/// terms at most `|δx|_1 |y|_1`; with `P = |w|_1 |d|_1`:
/// - `A = |d|^2`: `2 |d|_1 ed1 + ed1^2 + gamma(3) A`;
/// - `B = w . d`: `|w|_1 ed1 + ew1 |d|_1 + ew1 ed1 + gamma(3) P`;
/// - `C = |w|^2 - rr`: `2 |w|_1 ew1 + ew1^2 + err + gamma(4) (|w|_1^2 +
///   rr)` (three roundings in the dot product, one in the difference;
///   `|w|^2 <= |w|_1^2`);
/// - `w x d`: the 1-norm of its error vector is at most `E = ew1 |d|_1 +
///   |w|_1 ed1 + ew1 ed1 + gamma(3) P` (two products and a difference per
///   component, and `sum_k |w_i d_j| + |w_j d_i| <= P`), and `X`'s error
///   follows ([`RoundedCircle::e_x`]);
/// - the discriminant, two roundings: `A err + rr e_a + err e_a + e_X + u
///   (rr A + |disc|)`.
///
/// `None` outside the filter's range ([`RoundedCircle::of`]); the caller's
/// precise tier decides there.
#[inline(always)]
pub(crate) fn rounded_circle(
    w: DVec3,
    ew1: f64,
    d: DVec3,
    ed1: f64,
    (rr, err): (f64, f64),
) -> Option<Coeffs> {
    let k = RoundedCircle::of(w, d, rr)?;
    let (nw, nd) = (k.nw, k.nd);
    let p = nw * nd;
    let e_a = (2.0 * nd * ed1 + ed1 * ed1 + gamma(3) * k.a) * OWN_MARGIN + ETA;
    let e_cr = nw * ed1 + ew1 * nd + ew1 * ed1 + gamma(3) * p;
    let e_disc =
        (k.a * err + rr * e_a + err * e_a + k.e_x(e_cr + 2.0 * ETA) + U * (k.ra + k.disc.abs()))
            * DISC_MARGIN
            + ETA;
    Some(Coeffs {
        a: k.a,
        e_a,
        b: k.b,
        e_b: e_cr * OWN_MARGIN + ETA,
        c: k.c,
        e_c: (2.0 * nw * ew1 + ew1 * ew1 + err + gamma(4) * (nw * nw + rr)) * OWN_MARGIN + ETA,
        disc: k.disc,
        e_disc,
    })
}
