//! Rays against spheres, cylinders, double cones and general quadrics, on every finite
//! input, checked against the exact line oracle: the root count must be
//! exact always, and every root whose correctly rounded value lies in the
//! normal range within 5 ulps of it (4 where the fast stage certifies it;
//! 5 is the exact stage's first-order bound); the precise tier's first
//! hit likewise; the default tier's first hit the same hit or miss, with
//! the exact root inside its returned bound. Half of the inputs are small
//! integers, so that tangent rays, rays on a cylinder and degenerate
//! degrees occur.
#![no_main]

use exactray::interval::Interval;
use exactray::query::ray::Ray;
use exactray::query::ray::{Precise, RayCast};
use exactray::roots::{BoundedRoot, Roots};
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
    // The line's roots, both tiers' first hits in `forward` (the precise
    // tier's `t`, the default tier's bounded root), and the exact line.
    // The double cone's casts keep one nappe, so their first hit is not
    // the line's first admitted root: only their bounds are checked.
    let (got, casts, want) = match mode % 4 {
        0 => {
            let (c, r) = ([v[6], v[7], v[8]], v[9].abs());
            let s = Sphere::new(c, r).expect("finite sphere");
            let casts = tiers(&s, &ray, forward);
            (
                s.line_roots(&ray),
                Some(casts),
                Quadratic::sphere(o, d, c, r),
            )
        }
        1 => {
            let (p, a, r) = ([v[6], v[7], v[8]], [v[9], v[10], v[11]], v[12].abs());
            let Ok(cyl) = Cylinder::new(p, a, r) else {
                return;
            };
            let casts = tiers(&cyl, &ray, forward);
            (
                cyl.line_roots(&ray),
                Some(casts),
                Quadratic::cylinder(o, d, p, a, r),
            )
        }
        2 => {
            let (p, a, r) = ([v[6], v[7], v[8]], [v[9], v[10], v[11]], v[12].abs());
            let Ok(cone) = Cone::infinite(p, a, r) else {
                return;
            };
            let exact = Quadratic::cone(o, d, p, a, r);
            if let (Some(b), Some(n)) = (cone.cast_bounded(&ray, forward), exact.count()) {
                assert!(
                    (0..n).any(|i| exact.root_within(i, b.t, b.error)),
                    "{v:?} mode {mode}: cone cast_bounded {b:?} holds no root"
                );
            }
            let _ = Precise(cone).cast_t(&ray, forward);
            (cone.line_roots(&ray), None, exact)
        }
        _ => {
            let k: [f64; 10] = core::array::from_fn(|i| v[6 + i]);
            let Ok(q) = Quadric::new(k) else { return };
            let casts = tiers(&q, &ray, forward);
            (q.line_roots(&ray), Some(casts), Quadratic::quadric(o, d, k))
        }
    };
    let exact = want;
    let want = exact.answer();
    // The casts certify only the roots they need, by their own paths: the
    // first root t >= 0 (whose sign is exact), and by the crate's policy
    // (`Interval::admits`) never a root beyond f64's range.
    if let Some((first, bounded)) = casts
        && want.count.is_some()
        && let Some(expected) = want.first_admitted(0.0, f64::INFINITY, 5)
    {
        assert_eq!(
            first.is_some(),
            expected.is_some(),
            "{v:?} mode {mode}: precise cast_t {first:?} vs {want:?}"
        );
        assert_eq!(
            bounded.is_some(),
            expected.is_some(),
            "{v:?} mode {mode}: cast_bounded {bounded:?} vs {want:?}"
        );
        if let (Some(t), Some(w)) = (first, expected) {
            let normal = w == 0.0 || (2f64.powi(-1000)..2f64.powi(1000)).contains(&w.abs());
            assert!(
                !normal || ulps_between(t, w) <= 5,
                "{v:?} mode {mode}: precise cast_t {t:e} vs {w:e}"
            );
        }
        if let (Some(b), Some(w)) = (bounded, expected) {
            let index = want.roots.iter().position(|&r| r == w).expect("a root");
            assert!(
                exact.root_within(index, b.t, b.error),
                "{v:?} mode {mode}: cast_bounded {b:?}, exact root near {w:e} outside"
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

/// The precise tier's first `t` in `range` and the default tier's bounded
/// first root; `cast_t` and `cast` must agree with the latter.
fn tiers<S: RayCast + Copy>(
    shape: &S,
    ray: &Ray,
    range: Interval,
) -> (Option<f64>, Option<BoundedRoot>)
where
    Precise<S>: RayCast,
{
    let bounded = shape.cast_bounded(ray, range);
    assert_eq!(shape.cast_t(ray, range), bounded.map(|b| b.t));
    let hit = shape.cast(ray, range).map(|h| (h.t, h.t_error));
    assert_eq!(hit, bounded.map(|b| (b.t, b.error)));
    (Precise(*shape).cast_t(ray, range), bounded)
}
