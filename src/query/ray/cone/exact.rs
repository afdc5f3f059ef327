//! The exact stage: the lateral quadratic's coefficients as integers at
//! the inputs' grains, and its roots from them.

use crate::arith::exponent::Grain;
use crate::arith::fixed_int::{DEG1, DEG2, DEG4, FixedInt, cross3, limbs_of_degree};
use crate::roots::Roots;
use crate::roots::line_quadratic::{SMALL_SPAN, exact_roots};
use glam::DVec3;

/// Limbs at the common grains: an input or a difference of two (below
/// `2^2100`), then degrees 2, 4, 6 and 12.
const W1: usize = DEG1;
const W2: usize = DEG2;
const W4: usize = DEG4;
const W6: usize = limbs_of_degree(6);
/// A product of two degree-6 values takes the limbs of both.
const W12: usize = 2 * W6;

/// The exact stage at three grains (`o, apex`: `lo`; `d`: `ld`; `a, r`:
/// `la`), under which the equation keeps its roots: `A = s |v|^2 - r^2
/// q^2` at `2 ld + 4 la`, `B = s (u . v) - r^2 p q` at `lo + ld + 4 la`,
/// `C = s |u|^2 - r^2 p^2` at `2 lo + 4 la` (`s = |a|^2`, `u = w x a`,
/// `v = d x a`, `p = w . a`, `q = d . a`). Small integers when every span
/// allows: inputs below `2^126` make `C` below `2^765` (13 limbs) and the
/// discriminant below `2^1529` (26 limbs).
pub(super) fn exact(o: DVec3, d: DVec3, apex: DVec3, a: DVec3, r: f64) -> Roots {
    let g = Grain::of(&[o.x, o.y, o.z, apex.x, apex.y, apex.z]);
    let (gd, ga) = (Grain::of(&d.to_array()), Grain::of(&[a.x, a.y, a.z, r]));
    let lo = if g.all_zero() { 0 } else { g.lo_min };
    let grains = (lo, gd.lo_min, ga.lo_min);
    if g.span().max(gd.span()).max(ga.span()) <= SMALL_SPAN {
        exact_in::<2, 5, 9, 13, 26>([o, apex, d, a], r, grains)
    } else {
        exact_in::<W1, W2, W4, W6, W12>([o, apex, d, a], r, grains)
    }
}

fn exact_in<
    const N1: usize,
    const N2: usize,
    const N4: usize,
    const N6: usize,
    const N12: usize,
>(
    [o, apex, d, a]: [DVec3; 4],
    r: f64,
    (lo, ld, la): (i32, i32, i32),
) -> Roots {
    let int = |v: DVec3, g: i32| -> [FixedInt<N1>; 3] {
        core::array::from_fn(|k| FixedInt::from_f64(v[k], g))
    };
    let (ow, pw) = (int(o, lo), int(apex, lo));
    let w: [FixedInt<N1>; 3] = core::array::from_fn(|k| ow[k].sub(&pw[k]));
    let (dw, aw) = (int(d, ld), int(a, la));
    let rw = FixedInt::<N1>::from_f64(r, la);
    let dot = |x: &[FixedInt<N1>; 3], y: &[FixedInt<N1>; 3]| -> FixedInt<N2> {
        (0..3).fold(FixedInt::ZERO, |acc, k| {
            acc.add(&FixedInt::mul(&x[k], &y[k]))
        })
    };
    let dot2 = |x: &[FixedInt<N2>; 3], y: &[FixedInt<N2>; 3]| -> FixedInt<N4> {
        (0..3).fold(FixedInt::ZERO, |acc, k| {
            acc.add(&FixedInt::mul(&x[k], &y[k]))
        })
    };
    let (u, v) = (cross3::<N1, N2>(&w, &aw), cross3::<N1, N2>(&dw, &aw));
    let (s, rr) = (dot(&aw, &aw), FixedInt::<N2>::mul(&rw, &rw));
    let (p, q) = (dot(&w, &aw), dot(&dw, &aw));
    let coefficient = |x: FixedInt<N4>, m: &FixedInt<N2>, n: &FixedInt<N2>| -> FixedInt<N6> {
        let mn = FixedInt::<N4>::mul(m, n);
        FixedInt::<N6>::mul(&s, &x).sub(&FixedInt::mul(&rr, &mn))
    };
    let qa = coefficient(dot2(&v, &v), &q, &q);
    let qb = coefficient(dot2(&u, &v), &p, &q);
    let qc = coefficient(dot2(&u, &u), &p, &p);
    exact_roots::<N6, N12>(
        (&qa, 2 * ld + 4 * la),
        (&qb, lo + ld + 4 * la),
        (&qc, 2 * lo + 4 * la),
    )
}
