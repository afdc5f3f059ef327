//! Rays against spheres, cylinders, cones and general quadrics, checked
//! against the exact oracle (`exactray_oracle::line_oracle`): the root count must
//! be exact and every root within the stated ulps of the correctly rounded
//! exact root, on ordinary rays and on the hard ones (far origins, grazing
//! and exactly tangent rays, origins on the surface, tiny and huge scales,
//! unnormalized directions).

use exactray::InputError;
use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::{Precise, RayCast};
use exactray::roots::Roots;
use exactray::shape::{CappedCylinder, Cone, Cylinder, Disk, Plane, Quadric, Sphere};
use exactray::testing::{
    ConeRayClass, CylinderRayClass, QuadricRayClass, SphereRayClass, SplitMix64, cone_ray_case,
    cylinder_ray_case, quadric_ray_case, sphere_ray_case,
};
use exactray_oracle::line_oracle::{
    Dyadic, LineAnswer, Quadratic, cross3, dot3, sub3, ulps_between, v3,
};
use proptest::prelude::*;

/// The tolerance the crate states against the correctly rounded root.
const ULPS: u64 = 4;

fn check(got: Roots, want: &LineAnswer, what: &str) -> Result<(), TestCaseError> {
    prop_assert_eq!(got.count(), want.count, "{}: {:?} vs {:?}", what, got, want);
    let roots: Vec<f64> = match got {
        Roots::One(t) => vec![t],
        Roots::Two(a, b) => vec![a, b],
        _ => vec![],
    };
    for (g, w) in roots.iter().zip(&want.roots) {
        prop_assert!(
            ulps_between(*g, *w) <= ULPS,
            "{}: root {} vs correctly rounded {} ({} ulps)",
            what,
            g,
            w,
            ulps_between(*g, *w)
        );
    }
    Ok(())
}

/// Both tiers' casts against the exact answer, for the forward range, the
/// whole line, and ranges starting between the roots and after the first
/// one (which make the cast look past the smaller root): the precise tier
/// (`Precise(shape).cast_t`) returns the first correctly rounded root
/// inside the range within [`ULPS`], or none; the default tier
/// (`cast_bounded`) the same hit or miss, with the exact root inside its
/// returned bound (decided exactly by the oracle), and `cast` and
/// `cast_t` agree with it. A range bound within a few ulps of a root may
/// fall on either side of it, so such ranges are skipped.
fn check_first<S: RayCast + Copy>(
    shape: &S,
    ray: &Ray,
    exact: &Quadratic,
    want: &LineAnswer,
    what: &str,
) -> Result<(), TestCaseError>
where
    Precise<S>: RayCast,
{
    let mut ranges = vec![
        Interval::FORWARD,
        Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap(),
    ];
    if let [a, b] = want.roots[..]
        && a.is_finite()
        && b.is_finite()
    {
        let mid = 0.5 * a + 0.5 * b;
        ranges.push(Interval::new(mid, f64::INFINITY).unwrap());
        ranges.push(Interval::new(f64::NEG_INFINITY, mid).unwrap());
    }
    for range in ranges {
        let near = |bound: f64| {
            want.roots
                .iter()
                .any(|&w| bound.is_finite() && ulps_between(w, bound) <= 2 * ULPS)
        };
        if near(range.min()) || near(range.max()) || want.count.is_none() {
            continue;
        }
        // The crate's policy: a root beyond f64's range is no hit.
        let Some(expected) = want.first_admitted(range.min(), range.max(), ULPS as u32) else {
            continue;
        };
        let got = Precise(*shape).cast_t(ray, range);
        match (got, expected) {
            (None, None) => {}
            (Some(g), Some(w)) => prop_assert!(
                ulps_between(g, w) <= ULPS,
                "{}: precise cast_t in {:?}: {} vs correctly rounded {}",
                what,
                range,
                g,
                w
            ),
            _ => prop_assert!(
                false,
                "{}: precise cast_t in {:?}: {:?}, want {:?}",
                what,
                range,
                got,
                expected
            ),
        }
        let bounded = shape.cast_bounded(ray, range);
        match (bounded, expected) {
            (None, None) => {}
            (Some(b), Some(w)) => {
                let index = want
                    .roots
                    .iter()
                    .position(|&r| r == w)
                    .expect("the expected root is one of the roots");
                prop_assert!(
                    exact.root_within(index, b.t, b.error),
                    "{}: cast_bounded in {:?}: {:?}, the exact root (rounded: {}) outside",
                    what,
                    range,
                    b,
                    w
                );
            }
            _ => prop_assert!(
                false,
                "{}: cast_bounded in {:?}: {:?}, want {:?}",
                what,
                range,
                bounded,
                expected
            ),
        }
        prop_assert_eq!(shape.cast_t(ray, range), bounded.map(|b| b.t));
        let hit = shape.cast(ray, range).map(|h| (h.t, h.t_error));
        prop_assert_eq!(hit, bounded.map(|b| (b.t, b.error)));
    }
    Ok(())
}

fn vec3(range: f64) -> impl Strategy<Value = [f64; 3]> {
    [-range..range, -range..range, -range..range]
}

fn pow2(k: i32) -> f64 {
    2f64.powi(k)
}

/// A ray aimed at `target` from `origin`, with the direction scaled.
fn aimed(origin: [f64; 3], target: [f64; 3], scale: f64) -> [f64; 3] {
    core::array::from_fn(|k| (target[k] - origin[k]) * scale)
}

fn sphere_case(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64) -> Result<(), TestCaseError> {
    prop_assume!(d != [0.0; 3]);
    let s = Sphere::new(c, r).unwrap();
    let ray = Ray::new(o, d).unwrap();
    let exact = Quadratic::sphere(o, d, c, r);
    let want = exact.answer();
    let what = format!("sphere {o:?} {d:?} {c:?} {r}");
    check(s.line_roots(&ray), &want, &what)?;
    check_first(&s, &ray, &exact, &want, &what)
}

fn cylinder_case(
    o: [f64; 3],
    d: [f64; 3],
    p: [f64; 3],
    a: [f64; 3],
    r: f64,
) -> Result<(), TestCaseError> {
    prop_assume!(d != [0.0; 3] && a != [0.0; 3]);
    let cyl = Cylinder::new(p, a, r).unwrap();
    let ray = Ray::new(o, d).unwrap();
    let exact = Quadratic::cylinder(o, d, p, a, r);
    let want = exact.answer();
    let what = format!("cylinder {o:?} {d:?} {p:?} {a:?} {r}");
    check(cyl.line_roots(&ray), &want, &what)?;
    check_first(&cyl, &ray, &exact, &want, &what)
}

fn quadric_case(o: [f64; 3], d: [f64; 3], k: [f64; 10]) -> Result<(), TestCaseError> {
    prop_assume!(d != [0.0; 3]);
    let q = Quadric::new(k).unwrap();
    let ray = Ray::new(o, d).unwrap();
    let exact = Quadratic::quadric(o, d, k);
    let want = exact.answer();
    let what = format!("quadric {o:?} {d:?} {k:?}");
    check(q.line_roots(&ray), &want, &what)?;
    check_first(&q, &ray, &exact, &want, &what)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn sphere_ordinary(o in vec3(4.0), d in vec3(2.0), c in vec3(1.0), r in 0.0..2.0) {
        sphere_case(o, d, c, r)?;
    }

    #[test]
    fn sphere_far(dir in vec3(1.0), k in 20i32..27, aim in vec3(1.2), c in vec3(1.0), s in -20i32..20) {
        let o: [f64; 3] = core::array::from_fn(|i| dir[i] * pow2(k) + c[i]);
        let target: [f64; 3] = core::array::from_fn(|i| c[i] + aim[i]);
        sphere_case(o, aimed(o, target, pow2(s) * 0.37), c, 1.0)?;
    }

    #[test]
    fn sphere_grazing(x in -8.0f64..8.0, h in -2.0f64..2.0, ulps in -4i64..4, s in -30i32..30) {
        // A ray along x at height r moved by a few ulps: tangent or a near miss.
        let r = 1.0 + h.abs();
        let y = f64::from_bits((r.to_bits() as i64 + ulps) as u64);
        sphere_case([x * pow2(s), y * pow2(s), 0.0], [1.0, 0.0, 0.0], [0.0; 3], r * pow2(s))?;
    }

    #[test]
    fn sphere_scaled(o in vec3(4.0), d in vec3(2.0), c in vec3(1.0), r in 0.01..2.0, s in -1000i32..1000, sd in -1000i32..1000) {
        let sc = |v: [f64; 3], k: i32| v.map(|x| x * pow2(k));
        sphere_case(sc(o, s), sc(d, sd), sc(c, s), r * pow2(s))?;
    }

    #[test]
    fn sphere_origin_on_surface(c in vec3(3.0), m in 1i32..20, n in 1i32..20, d in vec3(2.0)) {
        // Pythagorean points (m^2 - n^2, 2mn) / (m^2 + n^2) on the unit circle.
        let (m, n) = (m as f64, n as f64);
        let r = m * m + n * n;
        let o = [c[0].round() + (m * m - n * n), c[1].round() + 2.0 * m * n, c[2].round()];
        sphere_case(o, d, [c[0].round(), c[1].round(), c[2].round()], r)?;
    }

    #[test]
    fn cylinder_ordinary(o in vec3(4.0), d in vec3(2.0), p in vec3(1.0), a in vec3(2.0), r in 0.0..2.0) {
        cylinder_case(o, d, p, a, r)?;
    }

    #[test]
    fn cylinder_axis_aligned(o in vec3(4.0), d in vec3(2.0), p in vec3(1.0), k in 0usize..3, s in -4.0f64..4.0, r in 0.0..2.0) {
        // The cast's cheaper path for an axis along a coordinate axis.
        let mut a = [0.0; 3];
        a[k] = s;
        cylinder_case(o, d, p, a, r)?;
    }

    #[test]
    fn cylinder_exam(o in vec3(5.0), d in vec3(2.0)) {
        cylinder_case(o, d, [0.0; 3], [0.0, 1.0, 0.0], 1.0)?;
    }

    #[test]
    fn cylinder_parallel(o in vec3(3.0), p in vec3(1.0), a in vec3(2.0), k in -3i32..3, on in any::<bool>()) {
        // d an exact multiple of a: degree zero; an origin on the axis's
        // parallel at exactly r gives every t.
        let a = a.map(|x| (x * 8.0).round() / 8.0);
        prop_assume!(a != [0.0; 3]);
        let d = a.map(|x| x * pow2(k));
        let o = if on { [p[0] + 1.0, p[1], p[2]] } else { o };
        let ax = [1.0, 0.0, 0.0];
        cylinder_case(o, d, p, a, 1.0)?;
        cylinder_case(p.map(|x| x + 0.5), ax.map(|x| x * 3.0), p, ax, 0.5)?;
    }

    #[test]
    fn cylinder_far_and_grazing(dir in vec3(1.0), k in 10i32..27, ulps in -3i64..3, a in vec3(1.0)) {
        prop_assume!(a != [0.0; 3]);
        // Far along a direction perpendicular-ish to the axis, aimed to pass
        // at distance 1 (moved by ulps) from the y axis.
        let y = f64::from_bits((1f64.to_bits() as i64 + ulps) as u64);
        let o = [-pow2(k), dir[1], y];
        cylinder_case(o, [1.0, dir[0] * 1e-3, 0.0], [0.0; 3], [0.0, 1.0, 0.0], 1.0)?;
        cylinder_case(o, [1.0, 0.0, dir[2]], [0.0; 3], a, 1.0)?;
    }

    #[test]
    fn cylinder_scaled(o in vec3(4.0), d in vec3(2.0), p in vec3(1.0), a in vec3(2.0), r in 0.01..2.0, s in -900i32..900, sd in -900i32..900, sa in -900i32..900) {
        let sc = |v: [f64; 3], k: i32| v.map(|x| x * pow2(k));
        cylinder_case(sc(o, s), sc(d, sd), sc(p, s), sc(a, sa), r * pow2(s))?;
    }

    #[test]
    fn quadric_random(o in vec3(3.0), d in vec3(2.0), k in prop::array::uniform10(-2.0f64..2.0)) {
        quadric_case(o, d, k)?;
    }

    #[test]
    fn quadric_degenerate_degrees(o in vec3(3.0), t in vec3(2.0), s in -3i32..3) {
        // The paraboloid z = x^2 + y^2 along its axis: degree one. The cone
        // x^2 + y^2 = z^2 along a ruling: degree one or zero.
        let para = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0];
        quadric_case(o, [0.0, 0.0, pow2(s)], para)?;
        let cone = [1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let ruling = [t[0].round(), t[1].round(), 0.0];
        let len2 = ruling[0] * ruling[0] + ruling[1] * ruling[1];
        prop_assume!(len2 > 0.0);
        // (3, 4, 5) style rulings are exact for Pythagorean pairs; others
        // give a near-ruling, which is degree two.
        quadric_case([0.0; 3], [ruling[0], ruling[1], len2.sqrt()], cone)?;
        quadric_case([3.0, 4.0, 5.0], [3.0, 4.0, 5.0], cone)?;
    }

    #[test]
    fn quadric_scaled(o in vec3(3.0), d in vec3(2.0), k in prop::array::uniform10(-2.0f64..2.0), s in -300i32..300, sd in -900i32..900) {
        // Scaling space by 2^s scales the quadratic part's coefficients by
        // 2^-2s and the linear part's by 2^-s.
        let o = o.map(|x| x * pow2(s));
        let mut k = k;
        for (i, v) in k.iter_mut().enumerate() {
            *v *= match i { 0..=5 => pow2(-2 * s), 6..=8 => pow2(-s), _ => 1.0 };
        }
        quadric_case(o, d.map(|x| x * pow2(sd)), k)?;
    }

    #[test]
    fn cone_ordinary(o in vec3(3.0), d in vec3(2.0), p in vec3(1.0), a in vec3(2.0), r in 0.1..2.0) {
        cone_case(o, d, p, a, r)?;
    }

    /// Small integers: rays through the apex (a double root), along a
    /// ruling (every t) or parallel to one (degree one), and tangent
    /// planes' lines, all decided exactly.
    #[test]
    fn cone_small_integers(o in int3(), d in int3(), p in int3(), a in int3(), r in 1..4i32) {
        cone_case(o, d, p, a, f64::from(r))?;
    }

    /// The same at powers of two from `2^-600` to `2^600`, each group (the
    /// points, the direction, the axis and radius) at its own.
    #[test]
    fn cone_small_integers_scaled(
        o in int3(), d in int3(), p in int3(), a in int3(), r in 1..4i32,
        (s, sd, sa) in (-600..600i32, -600..600i32, -600..600i32),
    ) {
        let at = |v: [f64; 3], k: i32| v.map(|x| x * 2f64.powi(k));
        cone_case(at(o, s), at(d, sd), at(p, s), at(a, sa), f64::from(r) * 2f64.powi(sa))?;
    }

    /// Capped cones (the lateral surface below the cap and the base disk),
    /// ordinary: the default tier's first crossing against the exact one.
    #[test]
    fn capped_cone_ordinary(o in vec3(3.0), d in vec3(2.0), p in vec3(1.0), a in vec3(2.0), r in 0.1..2.0) {
        capped_cone_case(o, d, p, a, r)?;
    }

    /// The same with each group (the points, the direction, the axis and
    /// radius) at its own power of two from `2^-600` to `2^600`: the casts
    /// at the cone's own scales.
    #[test]
    fn capped_cone_scaled(
        o in vec3(3.0), d in vec3(2.0), p in vec3(1.0), a in vec3(2.0), r in 0.1..2.0,
        (s, sd, sa) in (-600..600i32, -600..600i32, -600..600i32),
    ) {
        let at = |v: [f64; 3], k: i32| v.map(|x| x * 2f64.powi(k));
        capped_cone_case(at(o, s), at(d, sd), at(p, s), at(a, sa), r * 2f64.powi(sa))?;
    }
}

/// A capped cone's first crossing `t >= 0` against the exact one: the
/// lateral roots correctly rounded (`Quadratic::cone`), their nappe and
/// cap decided at the rounded root, the base plane's parameter exact and
/// its rim decided at its rounding, as the report's oracle does (those
/// decisions are `f64` in the cast too, so a case where one lies within
/// `1e-9` of its threshold is skipped, as is one whose crossings lie
/// within a few ulps of 0). Both tiers the same hit or miss
/// and on the same surface; the default tier's exact crossing inside its
/// bound (a lateral root by the line oracle, the base by exact signs),
/// the precise tier's lateral root within [`ULPS`].
fn capped_cone_case(
    o: [f64; 3],
    d: [f64; 3],
    p: [f64; 3],
    a: [f64; 3],
    r: f64,
) -> Result<(), TestCaseError> {
    prop_assume!(d != [0.0; 3] && a != [0.0; 3]);
    let cone = Cone::new(p, a, r).unwrap();
    let ray = Ray::new(o, d).unwrap();
    let exact = Quadratic::cone(o, d, p, a, r);
    let want = exact.answer();
    prop_assume!(want.count.is_some());
    let what = format!("capped cone {o:?} {d:?} {p:?} {a:?} {r}");
    let (ov, dv, pv, av) = (v3(o), v3(d), v3(p), v3(a));
    let w = sub3(&ov, &pv);
    let s = dot3(&av, &av);
    let abs = |x: Dyadic| if x.sign() < 0 { x.neg() } else { x };
    let scaled = |x: &Dyadic, k: f64| x.mul(&Dyadic::from_f64(k));
    // The cast's `f64` decisions err by a few units of roundoff of the
    // magnitudes they are computed from: the heights of `w` and of `t d`
    // along `a` (and `|a|^2`), the point's distance from the apex for the
    // rim. Cases within `1e-9` of those of a threshold are skipped.
    let (wn, dn) = (
        (0..3)
            .map(|k| abs(w[k].clone()))
            .fold(Dyadic::int(0), |x, y| x.add(&y)),
        (0..3)
            .map(|k| abs(dv[k].clone()))
            .fold(Dyadic::int(0), |x, y| x.add(&y)),
    );
    let an = (0..3)
        .map(|k| abs(av[k].clone()))
        .fold(Dyadic::int(0), |x, y| x.add(&y));
    // A crossing within a few ulps of the range's end 0 may go either way
    // (`Precise`'s docs); so may a base crossing, whose place is `f64`'s.
    let near_zero = |t: f64| ulps_between(t, 0.0) <= 2 * ULPS;
    let mut lateral = None;
    for (i, &t) in want.roots.iter().enumerate() {
        prop_assume!(t.is_finite() && !near_zero(t));
        let t_d = Dyadic::from_f64(t);
        let x: [Dyadic; 3] = core::array::from_fn(|k| w[k].add(&dv[k].mul(&t_d)));
        let h = dot3(&x, &av);
        let reach = wn.add(&abs(t_d.clone()).mul(&dn)).mul(&an);
        let apart = |edge: &Dyadic| {
            let (x, margin) = (h.sub(edge), scaled(&reach.add(edge), 1e-9));
            x.sub(&margin).sign() * x.add(&margin).sign() > 0
        };
        prop_assume!(apart(&Dyadic::int(0)) && apart(&s));
        if t >= 0.0 && h.sign() > 0 && h.sub(&s).sign() < 0 {
            lateral = Some((i, t));
            break;
        }
    }
    // The base plane's parameter `num / den`, exactly, and its rim: the
    // point's distance from the axis, `|X x a| / (|den| |a|)` with `X =
    // den (w - a) + num d`, against `r`.
    let num = s.sub(&dot3(&w, &av));
    let den = dot3(&dv, &av);
    let mut base = None;
    if den.sign() != 0 {
        // For the messages: the decisions are exact.
        let [o, d, p, a] = [o, d, p, a].map(glam::DVec3::from);
        let t = (a.dot(a) - (o - p).dot(a)) / d.dot(a);
        // `|num / den|` against `x`.
        let above = |x: f64| {
            abs(num.clone())
                .sub(&Dyadic::from_f64(x).mul(&abs(den.clone())))
                .sign()
        };
        prop_assume!(above(f64::from_bits(2 * ULPS)) > 0);
        // Beyond f64's range no crossing is a hit (the module's policy);
        // near `f64::MAX` it may go either way.
        let finite = above(f64::MAX / 4.0) < 0;
        prop_assume!(finite || above(f64::MAX) > 0);
        let x: [Dyadic; 3] =
            core::array::from_fn(|k| den.mul(&w[k].sub(&av[k])).add(&num.mul(&dv[k])));
        let c = cross3(&x, &av);
        let radial = dot3(&c, &c);
        // In units of `|den|`: the distance `|X x a| / |a|` against `r
        // |den|`, the margin `1e-9 (|w| |den| + |num| |d| + r |den|)`.
        let rd = Dyadic::from_f64(r).mul(&abs(den.clone()));
        let margin = scaled(
            &wn.mul(&abs(den.clone()))
                .add(&abs(num.clone()).mul(&dn))
                .add(&rd),
            1e-9,
        );
        let squared = |x: Dyadic| {
            let x = if x.sign() < 0 { Dyadic::int(0) } else { x };
            x.mul(&x).mul(&s)
        };
        let (lo, hi) = (squared(rd.sub(&margin)), squared(rd.add(&margin)));
        prop_assume!(radial.sub(&lo).sign() * radial.sub(&hi).sign() > 0);
        let rr = |r: f64| {
            let r = Dyadic::from_f64(r);
            r.mul(&r).mul(&s).mul(&den).mul(&den)
        };
        let ahead = finite && num.sign() * den.sign() >= 0;
        if ahead && radial.sub(&rr(r)).sign() <= 0 {
            base = Some(t);
        }
    }
    // Which comes first, the base's exact parameter or the lateral root.
    let base_first = |tl: f64| {
        let tl = Dyadic::from_f64(tl);
        num.sub(&tl.mul(&den)).sign() * den.sign() < 0
    };
    let first = match (lateral, base) {
        (Some((_, tl)), Some(tb)) if base_first(tl) => Some((None, tb)),
        (Some((i, tl)), _) => Some((Some(i), tl)),
        (None, b) => b.map(|tb| (None, tb)),
    };
    let bounded = cone.cast_bounded(&ray, Interval::FORWARD);
    let precise = Precise(cone).cast_bounded(&ray, Interval::FORWARD);
    match (first, bounded, precise) {
        (None, None, None) => {}
        (Some((index, t)), Some(b), Some(pr)) => {
            let within = |b: exactray::roots::BoundedRoot| match index {
                Some(i) => exact.root_within(i, b.t, b.error),
                None => {
                    let side = |x: f64| {
                        let x = Dyadic::from_f64(x);
                        num.sub(&x.mul(&den)).sign() * den.sign()
                    };
                    side(b.t - b.error) >= 0 && side(b.t + b.error) <= 0
                }
            };
            prop_assert!(
                within(b),
                "{}: cast_bounded {:?}, first crossing {} ({:?})",
                what,
                b,
                t,
                index
            );
            prop_assert!(
                within(pr),
                "{}: precise {:?}, first crossing {} ({:?})",
                what,
                pr,
                t,
                index
            );
            if index.is_some() {
                prop_assert!(
                    ulps_between(pr.t, t) <= ULPS,
                    "{}: precise {:?} vs {}",
                    what,
                    pr,
                    t
                );
            }
        }
        _ => prop_assert!(
            false,
            "{}: cast_bounded {:?}, precise {:?}, want {:?}",
            what,
            bounded,
            precise,
            first
        ),
    }
    Ok(())
}

fn int3() -> impl Strategy<Value = [f64; 3]> {
    proptest::array::uniform3(-3..=3i32).prop_map(|v| v.map(f64::from))
}

/// The double cone's line roots against the exact oracle: count exact,
/// roots within [`ULPS`].
fn cone_case(
    o: [f64; 3],
    d: [f64; 3],
    p: [f64; 3],
    a: [f64; 3],
    r: f64,
) -> Result<(), TestCaseError> {
    prop_assume!(d != [0.0; 3] && a != [0.0; 3]);
    let cone = Cone::infinite(p, a, r).unwrap();
    let ray = Ray::new(o, d).unwrap();
    let exact = Quadratic::cone(o, d, p, a, r);
    let want = exact.answer();
    let what = format!("cone {o:?} {d:?} {p:?} {a:?} {r}");
    check(cone.line_roots(&ray), &want, &what)?;
    // The casts keep the cone's own nappe (decided in f64): each tier's hit
    // is one of the line's roots, the default tier's exact root inside its
    // bound, the precise tier's within ULPS of the correctly rounded root.
    let whole = Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap();
    for range in [Interval::FORWARD, whole] {
        if let (Some(b), Some(n)) = (cone.cast_bounded(&ray, range), want.count) {
            prop_assert!(
                (0..n).any(|i| exact.root_within(i, b.t, b.error)),
                "{}: cast_bounded in {:?}: {:?}, roots {:?}",
                what,
                range,
                b,
                want.roots
            );
        }
        if let Some(t) = Precise(cone).cast_t(&ray, range) {
            prop_assert!(
                want.roots.iter().any(|&w| ulps_between(t, w) <= ULPS),
                "{}: precise cast_t in {:?}: {}, roots {:?}",
                what,
                range,
                t,
                want.roots
            );
        }
    }
    Ok(())
}

/// A case check outside proptest: a failure panics, a rejected case (a
/// zero direction) is skipped.
fn must_pass(result: Result<(), TestCaseError>) {
    if let Err(TestCaseError::Fail(why)) = result {
        panic!("{why}");
    }
}

/// The report's hard rays (`exactray::testing`: grazing within 1e-12 of
/// the radius, origins 1e6 to 1e8 away, exactly tangent, along the axis,
/// degree one and zero), 500 of each class: counts exact, roots and first
/// hits within [`ULPS`].
#[test]
fn seeded_hard_rays() {
    let mut rng = SplitMix64::new(13);
    for _ in 0..500 {
        for class in SphereRayClass::ALL {
            let c = sphere_ray_case(class, &mut rng);
            must_pass(sphere_case(c.origin, c.direction, c.center, c.radius));
        }
        for class in CylinderRayClass::ALL {
            let c = cylinder_ray_case(class, &mut rng);
            must_pass(cylinder_case(
                c.origin,
                c.direction,
                c.point,
                c.axis,
                c.radius,
            ));
        }
        for class in QuadricRayClass::ALL {
            let c = quadric_ray_case(class, &mut rng);
            must_pass(quadric_case(c.origin, c.direction, c.coefficients));
        }
        for class in ConeRayClass::ALL {
            let c = cone_ray_case(class, &mut rng);
            let (apex, axis) = (c.apex().to_array(), c.axis().to_array());
            must_pass(cone_case(c.origin, c.direction, apex, axis, c.radius));
            must_pass(capped_cone_case(
                c.origin,
                c.direction,
                apex,
                axis,
                c.radius,
            ));
        }
    }
}

#[test]
fn exam_q1_cylinder() {
    // x^2 + z^2 = 1 along y: a ray through it and one parallel to the axis.
    let cyl = Cylinder::new([0.0; 3], [0.0, 1.0, 0.0], 1.0).unwrap();
    let ray = Ray::new([-2.0, 0.0, 0.0], [1.0, 0.5, 0.0]).unwrap();
    assert_eq!(cyl.line_roots(&ray), Roots::Two(1.0, 3.0));
    let range = Interval::new(1.5, 10.0).unwrap();
    let hit = cyl.cast(&ray, range).unwrap();
    assert_eq!((hit.t, hit.normal.to_array()), (3.0, [1.0, 0.0, 0.0]));
    let inside = Ray::new([0.5, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    assert_eq!(cyl.line_roots(&inside), Roots::None);
    assert!(!cyl.hits(&inside, Interval::FORWARD));
}

#[test]
fn capped_shapes_and_disks() {
    let can = CappedCylinder::new([0.0; 3], [0.0, 0.0, 2.0], 1.0).unwrap();
    let side = Ray::new([-3.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap();
    let hit = can.cast(&side, Interval::FORWARD).unwrap();
    assert_eq!((hit.t, hit.normal.to_array()), (2.0, [-1.0, 0.0, 0.0]));
    // Above the can: misses the side, and parallel to the caps.
    let above = Ray::new([-3.0, 0.0, 3.0], [1.0, 0.0, 0.0]).unwrap();
    assert!(can.cast(&above, Interval::FORWARD).is_none());
    // Up from below through the base disk.
    let up = Ray::new([0.5, 0.0, -1.0], [0.0, 0.0, 1.0]).unwrap();
    let hit = can.cast(&up, Interval::FORWARD).unwrap();
    assert_eq!((hit.t, hit.normal.to_array()), (1.0, [0.0, 0.0, -1.0]));
    // The capped cone's base disk, from above.
    let cone = Cone::new([0.0; 3], [0.0, 0.0, 1.0], 1.0).unwrap();
    let down = Ray::new([0.25, 0.0, 3.0], [0.0, 0.0, -1.0]).unwrap();
    let hit = cone.cast(&down, Interval::FORWARD).unwrap();
    assert_eq!((hit.t, hit.normal.to_array()), (2.0, [0.0, 0.0, 1.0]));
    // The other nappe does not count.
    let below = Ray::new([-3.0, 0.0, -0.5], [1.0, 0.0, 0.0]).unwrap();
    assert!(cone.cast(&below, Interval::FORWARD).is_none());
    let plane = Plane::new([0.0; 3], [0.0, 1.0, 0.0]).unwrap();
    let parallel = Ray::new([0.0, 1.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    assert!(plane.cast(&parallel, Interval::FORWARD).is_none());
    let disk = Disk::new([0.0; 3], [0.0, 1.0, 0.0], 2.0).unwrap();
    let slant = Ray::new([0.0, 1.0, 0.0], [1.0, -1.0, 0.0]).unwrap();
    assert_eq!(disk.cast(&slant, Interval::FORWARD).unwrap().t, 1.0);
    assert!(
        disk.cast(&slant, Interval::new(0.0, 0.5).unwrap())
            .is_none()
    );
}

#[test]
fn constructors_reject_bad_input() {
    let nan = f64::NAN;
    assert_eq!(
        Sphere::new([0.0; 3], nan),
        Err(InputError::InvalidRadius { argument: "radius" })
    );
    assert_eq!(
        Sphere::new([nan, 0.0, 0.0], 1.0),
        Err(InputError::NonFinite { argument: "center" })
    );
    assert_eq!(
        Sphere::new([0.0; 3], f64::INFINITY),
        Err(InputError::NonFinite { argument: "radius" })
    );
    assert_eq!(
        Cylinder::new([0.0; 3], [0.0; 3], 1.0),
        Err(InputError::Degenerate { argument: "axis" })
    );
    assert_eq!(
        Cylinder::new([0.0; 3], [1.0, 0.0, 0.0], -1.0),
        Err(InputError::InvalidRadius { argument: "radius" })
    );
    assert_eq!(
        CappedCylinder::new([f64::INFINITY, 0.0, 0.0], [1.0, 0.0, 0.0], 1.0),
        Err(InputError::NonFinite { argument: "base" })
    );
    assert_eq!(
        Cone::new([0.0; 3], [0.0, 0.0, 1.0], 0.0),
        Err(InputError::Degenerate { argument: "radius" })
    );
    assert_eq!(
        Cone::infinite([0.0; 3], [0.0, nan, 1.0], 1.0),
        Err(InputError::NonFinite { argument: "axis" })
    );
    // All-zero coefficients are the quadric every point lies on, not an
    // error (see `all_zero_quadric_holds_every_line`).
    assert!(Quadric::new([0.0; 10]).is_ok());
    assert!(Quadric::new([-0.0; 10]).is_ok());
    let mut k = [1.0; 10];
    k[9] = nan;
    assert_eq!(
        Quadric::new(k),
        Err(InputError::NonFinite {
            argument: "coefficients"
        })
    );
    assert_eq!(
        Plane::new([0.0; 3], [0.0; 3]),
        Err(InputError::Degenerate { argument: "normal" })
    );
    assert_eq!(
        Disk::new([0.0; 3], [0.0, 0.0, 1.0], nan),
        Err(InputError::InvalidRadius { argument: "radius" })
    );
}

/// Where the surface has no normal (a point sphere), a cast's normal is the
/// reversed ray direction, a unit vector even when the direction's squared
/// length underflows or overflows.
#[test]
fn fallback_normals_are_unit_for_tiny_and_huge_directions() {
    let point = Sphere::new([0.0; 3], 0.0).unwrap();
    for (o, d) in [
        ([-1e-310, 0.0, 0.0], [5e-324, 0.0, 0.0]),
        ([-f64::MAX, 0.0, 0.0], [f64::MAX, 0.0, 0.0]),
        ([-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
    ] {
        let ray = Ray::new(o, d).unwrap();
        let hit = point.cast(&ray, Interval::FORWARD).unwrap();
        assert_eq!(hit.normal.to_array(), [-1.0, 0.0, 0.0], "{ray:?}");
    }
}

/// All ten coefficients zero: every line lies on the quadric. `line_roots`
/// is `Roots::All` (the oracle's identically zero polynomial), and a cast
/// behaves as for a line lying on any surface (here a ruling of the cone
/// `x^2 + y^2 = z^2` through its apex): the point of the range nearest
/// `t = 0`, with the reversed ray direction as normal (the gradient is zero).
#[test]
fn all_zero_quadric_holds_every_line() {
    let mut signed_zeros = [0.0; 10];
    signed_zeros[3] = -0.0;
    signed_zeros[9] = -0.0;
    let cone = Quadric::new([1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    let ruling = Ray::new([0.0; 3], [3.0, 4.0, 5.0]).unwrap();
    let rays = [
        ruling,
        Ray::new([1.0, -2.0, 0.5], [0.25, 3.0, -1.0]).unwrap(),
        Ray::new([1e300, -1e-300, 0.0], [5e-324, 0.0, -1e-310]).unwrap(),
        Ray::new([-f64::MAX, 0.0, f64::MAX], [f64::MAX, -f64::MAX, 1.0]).unwrap(),
    ];
    let ranges = [
        (Interval::FORWARD, Some(0.0)),
        (
            Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap(),
            Some(0.0),
        ),
        (Interval::new(2.0, 3.0).unwrap(), Some(2.0)),
        (Interval::new(-5.0, -1.0).unwrap(), Some(-1.0)),
        (
            Interval::new(f64::NEG_INFINITY, -1e308).unwrap(),
            Some(-1e308),
        ),
        (Interval::new(f64::INFINITY, f64::INFINITY).unwrap(), None),
    ];
    for k in [[0.0; 10], signed_zeros] {
        let q = Quadric::new(k).unwrap();
        for ray in &rays {
            let (o, d) = (ray.origin().to_array(), ray.direction().to_array());
            assert_eq!(q.line_roots(ray), Roots::All, "{ray:?}");
            assert_eq!(Quadratic::quadric(o, d, k).answer().count, None);
            for (range, want) in ranges {
                assert_eq!(q.cast_t(ray, range), want, "{ray:?} in {range:?}");
                assert_eq!(q.hits(ray, range), want.is_some());
                let hit = q.cast(ray, range);
                assert_eq!(hit.map(|h| h.t), want);
                if let Some(h) = hit {
                    assert_eq!(h.point, ray.at(h.t));
                    // Exactly -d / |d| for these directions (after scaling by a
                    // power of two where |d|^2 would underflow or overflow).
                    let d = -ray.direction();
                    let m = d.abs().max_element();
                    let k = if m < 1e-100 {
                        2f64.powi(1000)
                    } else if m > 1e100 {
                        2f64.powi(-1000)
                    } else {
                        1.0
                    };
                    assert_eq!(h.normal, (d * k).normalize());
                }
            }
        }
    }
    // The same ranges on a line lying on a non-zero quadric.
    assert_eq!(cone.line_roots(&ruling), Roots::All);
    for (range, want) in ranges {
        assert_eq!(
            cone.cast_t(&ruling, range),
            want,
            "cone ruling in {range:?}"
        );
    }
}

/// A fuzz finding of the `ray_quadrics` target (mode 214, small integers):
/// the target held a double cone's cast to the line's first root but
/// never computed the cast (the casts keep one nappe, so the target now
/// checks their bounds only). Here the first root lies on the cone's own
/// nappe: both tiers' hits and the line roots against the exact line.
#[test]
fn cone_cast_keeps_its_nappe() {
    let v = [
        5.0, -8.0, -8.0, 2.0, 4.0, 5.0, 6.0, 8.0, 4.0, 7.0, -8.0, 6.0, 7.0,
    ];
    let (o, d, p, a, r) = (
        [v[0], v[1], v[2]],
        [v[3], v[4], v[5]],
        [v[6], v[7], v[8]],
        [v[9], v[10], v[11]],
        v[12],
    );
    must_pass(cone_case(o, d, p, a, r));
    let cone = Cone::infinite(p, a, r).unwrap();
    let ray = Ray::new(o, d).unwrap();
    let exact = Quadratic::cone(o, d, p, a, r);
    let want = exact.answer();
    assert_eq!(want.count, Some(2));
    // The first root lies on the cone's own nappe: both tiers hit there.
    let b = cone.cast_bounded(&ray, Interval::FORWARD).unwrap();
    assert!(exact.root_within(0, b.t, b.error), "{b:?} vs {want:?}");
    let t = Precise(cone).cast_t(&ray, Interval::FORWARD).unwrap();
    assert!(ulps_between(t, want.roots[0]) <= ULPS, "{t} vs {want:?}");
}

#[test]
fn fuzz_findings() {
    // Coefficients near f64::MAX: doubling them in f64 overflowed.
    let v: [f64; 16] = [
        -1.7976926272613756e308,
        -1.7976931348623157e308,
        -1.7976931348623157e308,
        -1.7976931348623157e308,
        2.925e-321,
        -1.7976931348623157e308,
        -1.7976931348623157e308,
        -1.7976931348623157e308,
        -1.7976931348623157e308,
        -1.7976931348623157e308,
        1.06099789543e-313,
        -1.7976922776554302e308,
        -1.7976931348623157e308,
        -1.7976931348623157e308,
        -1.7976931348623157e308,
        3.4790120992875e-310,
    ];
    let (o, d) = ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
    let k: [f64; 10] = core::array::from_fn(|i| v[6 + i]);
    let got = Quadric::new(k)
        .unwrap()
        .line_roots(&Ray::new(o, d).unwrap());
    let want = Quadratic::quadric(o, d, k).answer();
    assert_eq!(got.count(), want.count);
    // Roots beyond f64's range are infinities, and no hit.
    let s = Sphere::new([0.0; 3], 1.0).unwrap();
    let ray = Ray::new([-1e308, 0.0, 0.0], [f64::from_bits(1), 0.0, 0.0]).unwrap();
    assert!(matches!(s.line_roots(&ray), Roots::Two(a, b) if a.is_infinite() && b.is_infinite()));
    assert!(s.cast(&ray, Interval::FORWARD).is_none());
}

/// Regression (found by the `ray_quadrics` fuzz target): origin, point and
/// radius all zero left the exact stage's grain empty, and its span
/// overflowed in debug builds.
#[test]
fn all_zero_position_data_reaches_the_exact_stage_safely() {
    let ray = Ray::new([0.0, 0.0, 0.0], [1.0, 2.0, 3.0]).unwrap();
    // The line meets the zero-radius cylinder (its axis) and sphere (a
    // point) only at t = 0.
    let c = Cylinder::new([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], 0.0).unwrap();
    assert_eq!(c.line_roots(&ray), Roots::One(0.0));
    let s = Sphere::new([0.0, 0.0, 0.0], 0.0).unwrap();
    assert_eq!(s.line_roots(&ray), Roots::One(0.0));
}

/// Regression (shrunk by `cylinder_scaled`): `r^2` underflows to a
/// subnormal while `|a|^2` is huge, so the underflow's absolute error,
/// scaled by `|a|^2`, must be in the filtered stage's bound on
/// `r^2 |a|^2`; without it a root came out 8 ulps off.
#[test]
fn cylinder_with_underflowing_radius_squared_and_huge_axis() {
    let sc = |v: [f64; 3], k: i32| v.map(|x| x * pow2(k));
    let o = [0.0; 3];
    let d = [0.0, 0.0, -0.7301729602635897];
    let p = [0.0, 0.0, 0.6123698048235435];
    let a = [0.0, 0.7746040293581781, 0.0];
    let (s, sd, sa) = (-510, -292, 306);
    cylinder_case(sc(o, s), sc(d, sd), sc(p, s), sc(a, sa), 0.01 * pow2(s)).unwrap();
}

/// A fuzzer finding (`ray_quadrics`, seed 7, from an empty corpus): an
/// origin near `-f64::MAX`, direction coordinates from `1e-318` to `1e289`
/// and coefficients `E = 5.5e-10`, `F = 8.4e-15`, `G = 2.1e-314`. The term
/// `d_z E o_x` of `B` (`-9.7e-20`, its largest) underflowed in its partial
/// product `d_z E` and vanished from the filter's sum and magnitude alike,
/// which then certified no roots; there are two.
#[test]
fn partial_products_that_underflow_decline_the_filter() {
    let v: [f64; 16] = [
        -1.7976922809928584e308,
        -1.7959812927113727e308,
        6.392894393e-314,
        5.014105033036297e-293,
        -2.3159452160917045e289,
        9.75167e-319,
        0.0,
        0.0,
        0.0,
        0.0,
        5.529727790709637e-10,
        8.442919566090597e-15,
        2.0970311356e-314,
        0.0,
        0.0,
        0.0,
    ];
    let (o, d) = ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
    let k: [f64; 10] = core::array::from_fn(|i| v[6 + i]);
    let ray = Ray::new(o, d).unwrap();
    let exact = Quadratic::quadric(o, d, k);
    let want = exact.answer();
    assert_eq!(want.count, Some(2));
    check(Quadric::new(k).unwrap().line_roots(&ray), &want, "finding").unwrap();
    check_first(&Quadric::new(k).unwrap(), &ray, &exact, &want, "finding").unwrap();
}
