//! Deterministic generators of hard inputs for the predicates on
//! constructed points: the inputs of `orient3d` with a line–plane or a
//! three-plane point, `orient2d` with a line–line point, and the
//! comparison of two line–plane points along an axis, in the order of the
//! fixture format's lines (`orient3d_lpi`, `orient3d_tpi`, `orient2d_ssi`,
//! `less_on_axis_lpi`).
//!
//! Every case defines its constructions (no line parallel to its plane, no
//! three planes without one common point, no parallel lines). Per
//! [`InputClass`]: `Degenerate` puts the constructed point exactly on the
//! plane or line of the explicit points (the line, or the plane, lies in
//! it; or two constructions meet at the same dyadic point on it), on
//! coordinates of few bits so that nothing rounds; `NearDegenerate` builds
//! the same with rounded weights and nudges a coordinate by a few ulps;
//! `Tiny` and `Huge` scale any of those by one power of two; `Mixed`
//! scales each axis by its own (which leaves every sign of these
//! predicates as it was, up to what underflows).
//!
//! ```
//! use exactray::predicates::{Lpi, orient3d_implicit};
//! use exactray::testing::{InputClass, SplitMix64, orient3d_lpi_case};
//! let mut rng = SplitMix64::new(3);
//! let [a, b, c, p, q, r, s, t] = orient3d_lpi_case(InputClass::Degenerate, &mut rng);
//! let x = Lpi::new(p, q, r, s, t).unwrap();
//! assert_eq!(orient3d_implicit(a, b, c, &x), exactray::Sign::Zero);
//! ```

use super::generators::{InputClass, SplitMix64, scale, step_ulps};
use crate::predicates::{Lpi, Ssi, Tpi};
use glam::{DVec2, DVec3};

/// How close to degenerate a case at unit scale is.
#[derive(Clone, Copy, PartialEq)]
enum Closeness {
    Uniform,
    Near,
    Exact,
}

/// A point with coordinates uniform in `[-1, 1)`, or with `exact` a
/// multiple of `2^-6` there.
fn point<const D: usize>(exact: bool, rng: &mut SplitMix64) -> [f64; D] {
    core::array::from_fn(|_| {
        if exact {
            rng.int(-64, 63) as f64 / 64.0
        } else {
            rng.signed()
        }
    })
}

/// An affine combination of `base` (the first point plus weighted
/// differences to the others): with `exact`, weights that are multiples of
/// `1/8` in `[-2, 2]` (nothing rounds on dyadic points); otherwise uniform
/// in `[-1.5, 1.5)` (rounded).
fn combination<const D: usize>(base: &[[f64; D]], exact: bool, rng: &mut SplitMix64) -> [f64; D] {
    let mut p = base[0];
    for q in &base[1..] {
        let w = if exact {
            rng.int(-16, 16) as f64 / 8.0
        } else {
            1.5 * rng.signed()
        };
        for k in 0..D {
            p[k] += w * (q[k] - base[0][k]);
        }
    }
    p
}

/// `x0 + d` and `x0 - m d` for a short dyadic `d` and `m`: a line through
/// `x0` (exactly, on dyadic points).
fn line_through<const D: usize>(x0: [f64; D], rng: &mut SplitMix64) -> [[f64; D]; 2] {
    let d: [f64; D] = point(true, rng);
    let m = rng.int(1, 8) as f64 / 4.0;
    [
        core::array::from_fn(|k| x0[k] + d[k]),
        core::array::from_fn(|k| x0[k] - m * d[k]),
    ]
}

/// Three points whose centroid is `x0`: a plane through it.
fn plane_through(x0: [f64; 3], rng: &mut SplitMix64) -> [[f64; 3]; 3] {
    let (u, v): ([f64; 3], [f64; 3]) = (point(true, rng), point(true, rng));
    [
        core::array::from_fn(|k| x0[k] + u[k]),
        core::array::from_fn(|k| x0[k] + v[k]),
        core::array::from_fn(|k| x0[k] - u[k] - v[k]),
    ]
}

/// Moves one coordinate of one point by up to 3 ulps, three times in four.
fn nudge<const D: usize, const N: usize>(pts: &mut [[f64; D]; N], rng: &mut SplitMix64) {
    if rng.int(0, 3) > 0 {
        let (i, k) = (
            rng.int(0, N as i64 - 1) as usize,
            rng.int(0, D as i64 - 1) as usize,
        );
        pts[i][k] = step_ulps(pts[i][k], rng.int(-3, 3));
    }
}

/// The class's scaling of a unit-scale case: one power of two (`Tiny`,
/// `Huge`) or one per axis (`Mixed`), the closeness drawn as the other
/// generators draw it.
fn scaled<const D: usize, const N: usize>(
    class: InputClass,
    rng: &mut SplitMix64,
    unit: impl Fn(Closeness, &mut SplitMix64) -> [[f64; D]; N],
) -> [[f64; D]; N] {
    let any = |rng: &mut SplitMix64| match rng.int(0, 3) {
        0 => Closeness::Uniform,
        1 => Closeness::Exact,
        _ => Closeness::Near,
    };
    match class {
        InputClass::Uniform => unit(Closeness::Uniform, rng),
        InputClass::NearDegenerate => unit(Closeness::Near, rng),
        InputClass::Degenerate => unit(Closeness::Exact, rng),
        InputClass::Tiny => {
            let k = if rng.int(0, 3) == 0 {
                rng.int(1000, 1064)
            } else {
                rng.int(520, 560)
            };
            let c = any(rng);
            unit(c, rng).map(|p| p.map(|x| scale(x, -k)))
        }
        InputClass::Huge => {
            let k = rng.int(520, 1000);
            let c = any(rng);
            unit(c, rng).map(|p| p.map(|x| scale(x, k)))
        }
        InputClass::Mixed => {
            let c = any(rng);
            let mut pts = unit(c, rng);
            for k in 0..D {
                let e = rng.int(-1000, 1000);
                pts.iter_mut().for_each(|p| p[k] = scale(p[k], e));
            }
            pts
        }
    }
}

/// Draws `generate` until `valid` holds (a handful of tries at most: a
/// random construction is almost never degenerate), then falls back to
/// `fallback`.
fn valid_case<T>(
    rng: &mut SplitMix64,
    generate: impl Fn(&mut SplitMix64) -> T,
    valid: impl Fn(&T) -> bool,
    fallback: T,
) -> T {
    for _ in 0..64 {
        let c = generate(rng);
        if valid(&c) {
            return c;
        }
    }
    fallback
}

fn v3(p: [[f64; 3]; 8]) -> [DVec3; 8] {
    p.map(DVec3::from_array)
}

/// A unit-scale `orient3d_lpi` case `a, b, c, p, q, r, s, t`.
fn unit_lpi(c: Closeness, rng: &mut SplitMix64) -> [[f64; 3]; 8] {
    let exact = c == Closeness::Exact;
    if c == Closeness::Uniform {
        return [(); 8].map(|_| point(false, rng));
    }
    let tri = [(); 3].map(|_| point(exact, rng));
    let comb = |rng: &mut SplitMix64| combination(&tri, exact, rng);
    let mut pts = match rng.int(0, 2) {
        // The line lies in the triangle's plane.
        0 => {
            let (p, q) = (comb(rng), comb(rng));
            let [r, s, t] = [(); 3].map(|_| point(false, rng));
            [tri[0], tri[1], tri[2], p, q, r, s, t]
        }
        // The plane is the triangle's.
        1 => {
            let [p, q] = [(); 2].map(|_| point(false, rng));
            let [r, s, t] = [(); 3].map(|_| comb(rng));
            [tri[0], tri[1], tri[2], p, q, r, s, t]
        }
        // The line and the plane meet at a point of the triangle's plane.
        _ => {
            let x0 = combination(&tri, true, rng);
            let [p, q] = line_through(x0, rng);
            let [r, s, t] = plane_through(x0, rng);
            [tri[0], tri[1], tri[2], p, q, r, s, t]
        }
    };
    if c == Closeness::Near {
        nudge(&mut pts, rng);
    }
    pts
}

/// `orient3d` of a triangle and a line–plane point: `[a, b, c, p, q, r,
/// s, t]`, the point the line through `p`, `q` meets the plane through `r`,
/// `s`, `t` (the `orient3d_lpi` fixture's order).
pub fn orient3d_lpi_case(class: InputClass, rng: &mut SplitMix64) -> [DVec3; 8] {
    let valid = |c: &[DVec3; 8]| Lpi::new(c[3], c[4], c[5], c[6], c[7]).is_ok();
    let fallback = v3(unit_lpi(Closeness::Uniform, &mut SplitMix64::new(1)));
    valid_case(rng, |rng| v3(scaled(class, rng, unit_lpi)), valid, fallback)
}

/// A unit-scale `orient3d_tpi` case `a, b, c` and three planes.
fn unit_tpi(c: Closeness, rng: &mut SplitMix64) -> [[f64; 3]; 12] {
    let exact = c == Closeness::Exact;
    if c == Closeness::Uniform {
        return [(); 12].map(|_| point(false, rng));
    }
    let tri = [(); 3].map(|_| point(exact, rng));
    let planes = match rng.int(0, 1) {
        // One plane is the triangle's.
        0 => {
            let own = [(); 3].map(|_| combination(&tri, exact, rng));
            let [u, v] = [(); 2].map(|_| [(); 3].map(|_| point(false, rng)));
            let mut planes = [own, u, v];
            planes.rotate_left(rng.int(0, 2) as usize);
            planes
        }
        // Three planes through a point of the triangle's plane.
        _ => {
            let x0 = combination(&tri, true, rng);
            [(); 3].map(|_| plane_through(x0, rng))
        }
    };
    let f = planes.as_flattened();
    let mut pts = [
        tri[0], tri[1], tri[2], f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8],
    ];
    if c == Closeness::Near {
        nudge(&mut pts, rng);
    }
    pts
}

/// `orient3d` of a triangle and a three-plane point: `[a, b, c, u0, u1,
/// u2, v0, v1, v2, w0, w1, w2]` (the `orient3d_tpi` fixture's order).
pub fn orient3d_tpi_case(class: InputClass, rng: &mut SplitMix64) -> [DVec3; 12] {
    let valid = |c: &[DVec3; 12]| {
        Tpi::new([c[3], c[4], c[5]], [c[6], c[7], c[8]], [c[9], c[10], c[11]]).is_ok()
    };
    let fallback = unit_tpi(Closeness::Uniform, &mut SplitMix64::new(2)).map(DVec3::from_array);
    valid_case(
        rng,
        |rng| scaled(class, rng, unit_tpi).map(DVec3::from_array),
        valid,
        fallback,
    )
}

/// A unit-scale `orient2d_ssi` case `a, b, p, q, r, s`.
fn unit_ssi(c: Closeness, rng: &mut SplitMix64) -> [[f64; 2]; 6] {
    let exact = c == Closeness::Exact;
    if c == Closeness::Uniform {
        return [(); 6].map(|_| point(false, rng));
    }
    let seg = [(); 2].map(|_| point(exact, rng));
    let mut pts = if rng.int(0, 1) == 0 {
        // One line lies on the line through a and b.
        let [p, q] = [(); 2].map(|_| combination(&seg, exact, rng));
        let [r, s] = [(); 2].map(|_| point(false, rng));
        [seg[0], seg[1], p, q, r, s]
    } else {
        // The lines cross at a point of that line.
        let x0 = combination(&seg, true, rng);
        let [p, q] = line_through(x0, rng);
        let [r, s] = line_through(x0, rng);
        [seg[0], seg[1], p, q, r, s]
    };
    if c == Closeness::Near {
        nudge(&mut pts, rng);
    }
    pts
}

/// `orient2d` of two points and a line–line point: `[a, b, p, q, r, s]`,
/// the point the line through `p`, `q` meets the line through `r`, `s`
/// (the `orient2d_ssi` fixture's order).
pub fn orient2d_ssi_case(class: InputClass, rng: &mut SplitMix64) -> [DVec2; 6] {
    let valid = |c: &[DVec2; 6]| Ssi::new(c[2], c[3], c[4], c[5]).is_ok();
    let fallback = unit_ssi(Closeness::Uniform, &mut SplitMix64::new(3)).map(DVec2::from_array);
    valid_case(
        rng,
        |rng| scaled(class, rng, unit_ssi).map(DVec2::from_array),
        valid,
        fallback,
    )
}

/// A unit-scale `less_on_axis_lpi` case (two line–plane points) and its
/// axis.
fn unit_two_lpi(c: Closeness, axis: usize, rng: &mut SplitMix64) -> [[f64; 3]; 10] {
    if c == Closeness::Uniform {
        return [(); 10].map(|_| point(false, rng));
    }
    let exact = c == Closeness::Exact;
    let mut pts = if rng.int(0, 1) == 0 {
        // Both points at one dyadic point.
        let x0 = point(true, rng);
        let [[p, q], [p2, q2]] = [(); 2].map(|_| line_through(x0, rng));
        let [[r, s, t], [r2, s2, t2]] = [(); 2].map(|_| plane_through(x0, rng));
        [p, q, r, s, t, p2, q2, r2, s2, t2]
    } else {
        // Both on one plane `x[axis] = h`, the planes perpendicular to it
        // or the lines in it.
        let h = rng.int(-64, 63) as f64 / 64.0;
        let mut on = || {
            let mut v: [f64; 3] = point(exact, rng);
            v[axis] = h;
            v
        };
        let [r, s, t, r2, s2, t2] = [(); 6].map(|_| on());
        let [p, q, p2, q2] = [(); 4].map(|_| point(false, rng));
        [p, q, r, s, t, p2, q2, r2, s2, t2]
    };
    if c == Closeness::Near {
        nudge(&mut pts, rng);
    }
    pts
}

/// Two line–plane points and an axis: `([p, q, r, s, t, p', q', r', s',
/// t'], axis)`, in the `less_on_axis_lpi` fixture's order.
pub fn less_on_axis_lpi_case(class: InputClass, rng: &mut SplitMix64) -> ([DVec3; 10], usize) {
    let axis = rng.int(0, 2) as usize;
    let valid = |c: &[DVec3; 10]| {
        Lpi::new(c[0], c[1], c[2], c[3], c[4]).is_ok()
            && Lpi::new(c[5], c[6], c[7], c[8], c[9]).is_ok()
    };
    let fallback =
        unit_two_lpi(Closeness::Uniform, 0, &mut SplitMix64::new(4)).map(DVec3::from_array);
    let pts = valid_case(
        rng,
        |rng| scaled(class, rng, |c, rng| unit_two_lpi(c, axis, rng)).map(DVec3::from_array),
        valid,
        fallback,
    );
    (pts, axis)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::predicates::{orient2d_implicit, orient3d_implicit};
    use crate::sign::Sign;

    #[test]
    fn degenerate_cases_are_exactly_degenerate() {
        let mut rng = SplitMix64::new(8);
        for _ in 0..500 {
            let [a, b, c, p, q, r, s, t] = orient3d_lpi_case(InputClass::Degenerate, &mut rng);
            let x = Lpi::new(p, q, r, s, t).unwrap();
            assert_eq!(orient3d_implicit(a, b, c, &x), Sign::Zero);
            let [a, b, p, q, r, s] = orient2d_ssi_case(InputClass::Degenerate, &mut rng);
            assert_eq!(
                orient2d_implicit(a, b, &Ssi::new(p, q, r, s).unwrap()),
                Sign::Zero
            );
        }
    }
}
