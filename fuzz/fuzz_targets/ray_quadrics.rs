//! Rays against spheres, cylinders, double cones and general quadrics, on every finite
//! input, checked against the exact line oracle: the root count must be
//! exact always, and every root whose correctly rounded value lies in the
//! normal range within 5 ulps of it (4 where the fast stage certifies it;
//! 5 is the exact stage's first-order bound). Half of the inputs are small
//! integers, so that tangent rays, rays on a cylinder and degenerate
//! degrees occur.
#![no_main]

use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::RayCast;
use exactray::roots::Roots;
use exactray::shape::{Cone, Cylinder, Quadric, Sphere};
use exactray::testing::finite_f64_from_bits;
use exactray_oracle::line_oracle::{Quadratic, ulps_between};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: (u8, [u64; 16])| {
    let (mode, bits) = input;
    let v: [f64; 16] = bits.map(|b| {
        if mode & 2 != 0 {
            (b % 17) as f64 - 8.0
        } else {
            finite_f64_from_bits(b)
        }
    });
    let o = [v[0], v[1], v[2]];
    let d = [v[3], v[4], v[5]];
    let Ok(ray) = Ray::new(o, d) else { return };
    let forward = Interval::FORWARD;
    let (got, first, want) = match mode % 4 {
        0 => {
            let (c, r) = ([v[6], v[7], v[8]], v[9].abs());
            let s = Sphere::new(c, r).expect("finite sphere");
            let first = s.cast_t(&ray, forward);
            (s.line_roots(&ray), first, Quadratic::sphere(o, d, c, r))
        }
        1 => {
            let (p, a, r) = ([v[6], v[7], v[8]], [v[9], v[10], v[11]], v[12].abs());
            let Ok(cyl) = Cylinder::new(p, a, r) else {
                return;
            };
            let first = cyl.cast_t(&ray, forward);
            (
                cyl.line_roots(&ray),
                first,
                Quadratic::cylinder(o, d, p, a, r),
            )
        }
        2 => {
            // The double cone: `cast_t` keeps one nappe, so the first
            // admitted root of both is not its answer; `line_roots` is
            // checked, and `cast_t` must not panic.
            let (p, a, r) = ([v[6], v[7], v[8]], [v[9], v[10], v[11]], v[12].abs());
            let Ok(cone) = Cone::infinite(p, a, r) else {
                return;
            };
            let _ = cone.cast_t(&ray, forward);
            let roots = cone.line_roots(&ray);
            (roots, None, Quadratic::cone(o, d, p, a, r))
        }
        _ => {
            let k: [f64; 10] = core::array::from_fn(|i| v[6 + i]);
            let Ok(q) = Quadric::new(k) else { return };
            let first = q.cast_t(&ray, forward);
            (q.line_roots(&ray), first, Quadratic::quadric(o, d, k))
        }
    };
    let want = want.answer();
    // cast_t certifies only the roots it needs, by its own path: the first
    // root t >= 0 (whose sign is exact), and by the crate's policy
    // (`Interval::admits`) never a root beyond f64's range.
    if want.count.is_some()
        && let Some(expected) = want.first_admitted(0.0, f64::INFINITY, 5)
    {
        assert_eq!(
            first.is_some(),
            expected.is_some(),
            "{v:?} mode {mode}: cast_t {first:?} vs {want:?}"
        );
        if let (Some(t), Some(w)) = (first, expected) {
            let normal = w == 0.0 || (2f64.powi(-1000)..2f64.powi(1000)).contains(&w.abs());
            assert!(
                !normal || ulps_between(t, w) <= 5,
                "{v:?} mode {mode}: cast_t {t:e} vs {w:e}"
            );
        }
    }
    assert_eq!(
        got.count(),
        want.count,
        "{v:?} mode {mode}: {got:?} vs {want:?}"
    );
    let roots = match got {
        Roots::One(t) => vec![t],
        Roots::Two(t0, t1) => {
            // Distinct roots less than an ulp apart round to one value, and
            // roots beyond f64's range both become infinities.
            assert!(t0 <= t1, "{v:?}: {got:?}");
            vec![t0, t1]
        }
        _ => vec![],
    };
    for (t, w) in roots.into_iter().zip(want.roots) {
        let normal = w == 0.0 || (2f64.powi(-1000)..2f64.powi(1000)).contains(&w.abs());
        if normal {
            assert!(
                ulps_between(t, w) <= 5,
                "{v:?} mode {mode}: root {t:e} vs {w:e}"
            );
        }
    }
});
