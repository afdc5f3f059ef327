//! The exact ray–triangle cast against exact rational arithmetic, on
//! fuzzer-chosen coordinates: its hit or miss must equal the exact one (for
//! `t >= 0` and for the whole line; a crossing beyond `f64`'s range is no
//! hit, the crate's policy), and its `t` must be finite and lie within
//! `EXACT_T_ULPS` units of rounding of the exact parameter. The fast
//! variants must never panic and must report only finite `t` inside the
//! interval.
//!
//! The same ray prepared once (`ExactRay`) must answer as `cast_exact`
//! does on both intervals, and its bounded tier (`cast_bounded`) must hit
//! or miss as the oracle demands for a `t` within `BOUNDED_T_ULPS`, report
//! the precise tier's barycentrics, and return a bound of at most
//! `BOUNDED_T_ULPS` units of rounding that holds the exact parameter.
//!
//! The first byte picks how the case is built: raw bit patterns (every
//! finite value), or a generated case (ordinary, far, near an edge,
//! grazing) edited towards degeneracy: the ray aimed at a vertex or along
//! an edge, two vertices merged, every coordinate scaled by `2^k` for a `k`
//! from -1000 to 1000.
#![no_main]

use arbitrary::{Arbitrary, Unstructured};
use exactray::interval::Interval;
use exactray::query::ray::{BOUNDED_T_ULPS, EXACT_T_ULPS, ExactRay, Ray, TriangleHit};
use exactray::shape::Triangle;
use exactray::testing::finite_f64_from_bits;
use exactray::testing::{RayTriangleCase, RayTriangleClass, SplitMix64, ray_triangle_case};
use exactray_oracle::oracle;
use glam::DVec3;
use libfuzzer_sys::fuzz_target;

fn vec3(u: &mut Unstructured) -> arbitrary::Result<DVec3> {
    let b = <[u64; 3]>::arbitrary(u)?;
    Ok(DVec3::from_array(b.map(finite_f64_from_bits)))
}

fn case(u: &mut Unstructured) -> arbitrary::Result<RayTriangleCase> {
    let how = u8::arbitrary(u)?;
    if how % 2 == 0 {
        return Ok((vec3(u)?, vec3(u)?, [vec3(u)?, vec3(u)?, vec3(u)?]));
    }
    let mut rng = SplitMix64::new(u64::arbitrary(u)?);
    let class = RayTriangleClass::ALL[usize::from(how / 2) % 4];
    let (mut o, mut d, mut v) = ray_triangle_case(class, &mut rng);
    let k = (how / 8 % 3) as usize;
    match u8::arbitrary(u)? % 5 {
        0 => d = v[k] - o,
        1 => (o, d) = (v[k], v[(k + 1) % 3] - v[k]),
        2 => v[(k + 1) % 3] = v[k],
        3 => o = v[k] + (v[k] - v[(k + 2) % 3]),
        _ => {}
    }
    // 2^k for k in -1000..=1000, in two exact steps.
    let k = i32::from(i16::arbitrary(u)?) % 1001;
    let scale = |p: DVec3| p * 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
    Ok((scale(o), scale(d), v.map(scale)))
}

fn check(o: DVec3, d: DVec3, v: [DVec3; 3], prepared: &ExactRay, range: Interval) {
    let (Ok(ray), Ok(tri)) = (Ray::new(o, d), Triangle::new(v[0], v[1], v[2])) else {
        return;
    };
    for hit in [tri.cast_mt(&ray, range), tri.cast_watertight(&ray, range)]
        .into_iter()
        .flatten()
    {
        assert!(range.admits(hit.t), "{hit:?} outside {range:?}");
    }
    let got = tri.cast_exact(&ray, range);
    assert_eq!(
        prepared.cast(&tri, range),
        got,
        "{o:?} {d:?} {v:?} {range:?}"
    );
    let line = oracle::line_triangle(o.to_array(), d.to_array(), v.map(|p| p.to_array()));
    // The crate's policy: a hit only at a finite t (`Interval::admits`), so
    // a crossing beyond f64's range is no hit; within EXACT_T_ULPS of
    // f64::MAX either answer is right.
    let want = |units: f64| match &line.t {
        None => Some(false),
        Some((num, den)) => oracle::hit_policy(num, den, range.min(), range.max(), units as u32),
    };
    if let Some(want) = want(EXACT_T_ULPS) {
        assert_eq!(got.is_some(), want, "{o:?} {d:?} {v:?} {range:?}: {got:?}");
    }
    let bounded = prepared.cast_bounded(&tri, range);
    if let Some(want) = want(BOUNDED_T_ULPS) {
        assert_eq!(
            bounded.is_some(),
            want,
            "{o:?} {d:?} {v:?} {range:?}: {bounded:?}"
        );
    }
    if let (Some(b), Some((num, den))) = (bounded, &line.t) {
        let (lo, hi) = (b.hit.t - b.t_error, b.hit.t + b.t_error);
        assert!(
            range.admits(b.hit.t) && oracle::ratio_in(num, den, lo.next_down(), hi.next_up()),
            "{o:?} {d:?} {v:?}: {b:?}, exact {:e}",
            oracle::ratio_to_f64(num, den)
        );
        let most = BOUNDED_T_ULPS * f64::EPSILON / 2.0 * b.hit.t.abs() + f64::from_bits(2);
        assert!(b.t_error <= most, "{o:?} {d:?} {v:?}: {b:?}");
        if let Some(TriangleHit { u, v: w, .. }) = got {
            assert_eq!((b.hit.u, b.hit.v), (u, w), "{o:?} {d:?} {v:?}");
        }
    }
    if let (Some(hit), Some((num, den))) = (got, line.t) {
        assert!(hit.t.is_finite(), "{o:?} {d:?} {v:?}: {hit:?}");
        assert!(
            hit.t.abs() < f64::MIN_POSITIVE
                || oracle::within_units(hit.t, &num, &den, EXACT_T_ULPS as u32),
            "{o:?} {d:?} {v:?}: t = {:e}, exact {:e}",
            hit.t,
            oracle::ratio_to_f64(&num, &den)
        );
        assert!((0.0..=1.0).contains(&hit.u) && (0.0..=1.0).contains(&hit.v));
    }
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok((o, d, v)) = case(&mut u) else {
        return;
    };
    let Ok(ray) = Ray::new(o, d) else {
        return;
    };
    // One preparation for both intervals, as a scene reuses it.
    let prepared = ExactRay::new(&ray);
    check(o, d, v, &prepared, Interval::FORWARD);
    check(
        o,
        d,
        v,
        &prepared,
        Interval::new(f64::NEG_INFINITY, f64::INFINITY).expect("valid"),
    );
});
