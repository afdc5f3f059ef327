//! The cone's bounds against exact arithmetic.

use super::*;
use crate::roots::line_quadratic::Polynomial;
use crate::testing::{ConeRayClass, SplitMix64, cone_ray_case, step_ulps};
use exactray_oracle::line_oracle::{Dyadic, Quadratic};
use std::vec::Vec;

/// The scaled line of a cone and a ray, and its exact polynomial in
/// `tau` (`w = wh + wl` as `wh - (-wl)`).
fn scaled_case(o: DVec3, d: DVec3, apex: DVec3, a: DVec3, r: f64) -> (ScaledLine, Quadratic) {
    let cone = Cone::infinite(apex, a, r).unwrap();
    let line = cone.scaled(o, d).unwrap();
    let exact = Quadratic::cone(
        line.wh.to_array(),
        line.d.to_array(),
        (-line.wl).to_array(),
        line.a.to_array(),
        line.r,
    );
    (line, exact)
}

/// Whether `|P(tau) - value| <= e`, decided exactly.
fn holds(exact: &Quadratic, tau: f64, (value, e): (f64, f64)) -> bool {
    if e == f64::INFINITY {
        return true;
    }
    let t = Dyadic::from_f64(tau);
    let p = exact.a.mul(&t).add(&exact.b).mul(&t).add(&exact.c);
    let diff = p.sub(&Dyadic::from_f64(value));
    let e = Dyadic::from_f64(e);
    diff.sub(&e).sign() <= 0 && diff.add(&e).sign() >= 0
}

/// Whether `|exact - value| <= e`, decided exactly.
fn within(exact: &Dyadic, value: f64, e: f64) -> bool {
    let diff = exact.sub(&Dyadic::from_f64(value));
    let e = Dyadic::from_f64(e);
    diff.sub(&e).sign() <= 0 && diff.add(&e).sign() >= 0
}

/// The coefficients' and the discriminant's bounds hold against the
/// exact ones (`Quadratic::cone`'s `a t^2 + b t + c` is `A t^2 + 2 B t +
/// C`), on ordinary lines (`w` rounded once) and scaled ones (`w` as
/// its high part): the report's rays, grazing ones (the exact
/// discriminant near zero), rays along the axis and across it, and
/// components far below the largest (products that underflow).
#[test]
fn coefficient_bounds_hold() {
    let mut rng = SplitMix64::new(9);
    for case in 0..3000 {
        let c = cone_ray_case(ConeRayClass::ALL[case % 2], &mut rng);
        let (mut o, mut d) = (DVec3::from(c.origin), DVec3::from(c.direction));
        let (apex, a, r) = (c.apex(), c.axis(), c.radius);
        match case % 6 {
            // Along the axis, and across it through the apex.
            1 => d = a * (1.0 + rng.next_f64()),
            2 => o = apex + a.any_orthogonal_vector() * 3.0,
            // Through a point of the rim: tangent or nearly so.
            3 => d = apex + a + a.any_orthogonal_vector().normalize() * r - o,
            4 => d.y = 1e-300,
            _ => {}
        }
        let cone = Cone::new(apex, a, r).unwrap();
        let ray = Ray::new(o, d).unwrap();
        let exact = Quadratic::cone(o.into(), d.into(), apex.into(), a.into(), r);
        let scaled = cone.scaled(ray.origin(), ray.direction()).unwrap();
        let (_, from_scaled) = scaled_case(o, d, apex, a, r);
        let lines = [
            (cone.ordinary(&ray), &exact),
            (Some(scaled.line()), &from_scaled),
        ];
        for (line, q) in lines {
            let Some((k, _)) = line.and_then(|l| l.filtered()) else {
                continue;
            };
            let half_b = q.b.half();
            let disc = half_b.mul(&half_b).sub(&q.a.mul(&q.c));
            assert!(within(&q.a, k.a, k.e_a), "A {case}: {k:?}");
            assert!(within(&half_b, k.b, k.e_b), "B {case}: {k:?}");
            assert!(within(&q.c, k.c, k.e_c), "C {case}: {k:?}");
            assert!(within(&disc, k.disc, k.e_disc), "D {case}: {k:?}");
        }
    }
}

/// Both evaluations' bounds hold at the exact roots' roundings and a
/// few ulps off them, and at points along the line, for the report's
/// rays, the same at scales `2^±600` per group, and needle-thin and
/// flat cones; at the roots the double-double bound is `O(u^2)` of
/// the terms (it certifies roots the working-precision one cannot,
/// whose bound is `O(u)` of them).
#[test]
fn evaluations_bound_their_errors() {
    let mut rng = SplitMix64::new(5);
    let mut tight = 0;
    let mut roots = 0;
    for case in 0..600 {
        let c = cone_ray_case(ConeRayClass::ALL[case % 2], &mut rng);
        let (so, sd, sa) = match case % 5 {
            0 | 1 => (0, 0, 0),
            2 => (600, -600, 300),
            3 => (-600, 300, -300),
            _ => (0, 0, 0),
        };
        let thin = match case % 7 {
            0 => 1e-200,
            1 => 1e100,
            _ => 1.0,
        };
        let at = |v: DVec3, k: i32| v * 2f64.powi(k);
        let (line, exact) = scaled_case(
            at(DVec3::from(c.origin), so),
            at(DVec3::from(c.direction), sd),
            at(c.apex(), so),
            at(c.axis(), sa),
            c.radius * thin * 2f64.powi(sa),
        );
        let lateral = Lateral::of(&line);
        let answer = exact.answer();
        let mut taus: Vec<f64> = (0..3).map(|_| rng.next_f64() * 8.0 - 4.0).collect();
        for &root in &answer.roots {
            for k in [-3, 0, 2] {
                taus.push(step_ulps(root, k));
            }
        }
        for &tau in &taus {
            let fast = lateral.eval_fast(tau);
            let precise = lateral.eval_precise(tau);
            assert!(holds(&exact, tau, fast), "fast {case} {tau}: {fast:?}");
            assert!(holds(&exact, tau, precise), "dd {case} {tau}: {precise:?}");
        }
        if thin == 1.0 && (so, sd, sa) == (0, 0, 0) {
            for &root in &answer.roots {
                let (x, _) = lateral.point(root);
                let xx: f64 = x.iter().map(|c| c.hi * c.hi).sum();
                let scale = lateral.ss.value.hi * xx;
                roots += 1;
                // `O(u^2)` of the terms, times `|w| / |x|` (up to `2^27`
                // for far origins) from the point's own error.
                let limit = if case % 2 == 0 { pow2(-95) } else { pow2(-70) };
                tight += usize::from(lateral.eval_precise(root).1 <= scale * limit);
            }
        }
    }
    assert!(tight == roots && roots > 100, "{tight} of {roots}");
}
