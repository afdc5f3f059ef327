//! `Hit::error` against exact arithmetic: the exact point `ray.at(t_exact)`
//! of the crossing a cast returns lies inside `point +- error` on every
//! axis, for triangles, planes, disks, spheres, cylinders and quadrics, on
//! ordinary, far-from-origin, grazing, near-edge, tiny and huge inputs.
//!
//! Triangles and planes have a rational exact `t`, checked as such; for the
//! quadrics the exact root lies strictly between the neighbours of its
//! correct rounding (the line oracle's answer), and the points at both
//! neighbours must lie inside the box (the point is affine in `t`).

use exactray::prelude::*;
use exactray::testing::{RayTriangleClass, SplitMix64, ray_triangle_case};
use exactray_oracle::line_oracle::{Dyadic, Quadratic};
use exactray_oracle::oracle::exact_parts;
use glam::DVec3;
use num_bigint::BigInt;
use num_traits::Signed;

/// Values as integers at their common exponent.
fn common(values: &[f64]) -> Vec<BigInt> {
    let parts: Vec<(BigInt, i32)> = values.iter().map(|&v| exact_parts(v)).collect();
    let lo = parts.iter().map(|p| p.1).min().unwrap_or(0);
    parts
        .into_iter()
        .map(|(m, e)| m << (e - lo) as usize)
        .collect()
}

/// `|p - (o + d num / den)| <= e` exactly, on one axis.
fn inside_rational(p: f64, e: f64, o: f64, d: f64, num: &BigInt, den: &BigInt) -> bool {
    if e.is_infinite() {
        return true;
    }
    let v = common(&[p, e, o, d]);
    let lhs = ((&v[0] - &v[2]) * den - &v[3] * num).abs();
    lhs <= &v[1] * den.abs()
}

/// The hit's box holds `o + d num / den` on every axis.
fn holds_rational(hit: &Hit, o: DVec3, d: DVec3, num: &BigInt, den: &BigInt) -> bool {
    (0..3).all(|k| inside_rational(hit.point[k], hit.error[k], o[k], d[k], num, den))
}

/// `p - e <= o + d t <= p + e` exactly at `t = lo` and `t = hi`.
fn inside_bracket(p: f64, e: f64, o: f64, d: f64, lo: f64, hi: f64) -> bool {
    if e.is_infinite() {
        return true;
    }
    let f = Dyadic::from_f64;
    [lo, hi].iter().all(|&t| {
        let x = f(o).add(&f(d).mul(&f(t)));
        f(p).sub(&f(e)).sub(&x).sign() <= 0 && x.sub(&f(p).add(&f(e))).sign() <= 0
    })
}

fn scale(rng: &mut SplitMix64) -> f64 {
    [1.0, 2f64.powi(-500), 2f64.powi(500), 1e-3, 1e6][(rng.next_u64() % 5) as usize]
}

fn uniform(rng: &mut SplitMix64, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * ((rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
}

fn vec3(rng: &mut SplitMix64, r: f64) -> DVec3 {
    DVec3::new(
        uniform(rng, -r, r),
        uniform(rng, -r, r),
        uniform(rng, -r, r),
    )
}

/// `(num, den)` of the exact parameter where the line meets the plane of
/// `v`, every value taken at one scale.
fn plane_crossing(o: DVec3, d: DVec3, v: [DVec3; 3]) -> (BigInt, BigInt) {
    let flat: Vec<f64> = [o, d, v[0], v[1], v[2]]
        .iter()
        .flat_map(|p| p.to_array())
        .collect();
    let w = common(&flat);
    let at = |i: usize| [w[3 * i].clone(), w[3 * i + 1].clone(), w[3 * i + 2].clone()];
    let sub = |a: &[BigInt; 3], b: &[BigInt; 3]| [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]];
    let (o, d, v0, v1, v2) = (at(0), at(1), at(2), at(3), at(4));
    let (e1, e2) = (sub(&v1, &v0), sub(&v2, &v0));
    let n = [
        &e1[1] * &e2[2] - &e1[2] * &e2[1],
        &e1[2] * &e2[0] - &e1[0] * &e2[2],
        &e1[0] * &e2[1] - &e1[1] * &e2[0],
    ];
    let dot = |a: &[BigInt; 3]| &a[0] * &n[0] + &a[1] * &n[1] + &a[2] * &n[2];
    (dot(&sub(&v0, &o)), dot(&d))
}

#[test]
fn triangle_hit_points_hold_the_exact_crossing() {
    let mut checked = 0;
    for seed in 0..40_000u64 {
        let mut rng = SplitMix64::new(seed);
        let (o, d, v) = ray_triangle_case(RayTriangleClass::ALL[seed as usize % 4], &mut rng);
        let (Ok(ray), Ok(tri)) = (Ray::new(o, d), Triangle::new(v[0], v[1], v[2])) else {
            continue;
        };
        let Some(hit) = tri.cast(&ray, Interval::FORWARD) else {
            continue;
        };
        // The plane's crossing, exactly: t = det[v0 - o, e1, e2] / det[d, e1, e2]
        // (the watertight test may hit just outside the exact triangle, where
        // the crossing is still the plane's).
        let (num, den) = plane_crossing(o, d, v);
        assert!(
            holds_rational(&hit, o, d, &num, &den),
            "seed {seed}: {hit:?}"
        );
        checked += 1;
    }
    assert!(checked > 5_000, "{checked}");
}

#[test]
fn plane_and_disk_hit_points_hold_the_exact_crossing() {
    let mut checked = 0;
    for seed in 0..20_000u64 {
        let mut rng = SplitMix64::new(seed);
        let s = scale(&mut rng);
        let (p, n) = (vec3(&mut rng, 2.0) * s, vec3(&mut rng, 1.0));
        let far = if seed % 3 == 0 { 1e7 } else { 1.0 };
        let o = vec3(&mut rng, 6.0) * s * far;
        // Aimed near the plane's point; every fifth ray grazes the plane.
        let mut d = p + vec3(&mut rng, 1.0) * s - o;
        if seed % 5 == 0 {
            d -= n * (d.dot(n) / n.dot(n)) * (1.0 - 1e-12);
        }
        let (Ok(ray), Ok(plane), Ok(disk)) =
            (Ray::new(o, d), Plane::new(p, n), Disk::new(p, n, 2.0 * s))
        else {
            continue;
        };
        // t = ((p - o) . n) / (d . n), exactly, every value at one scale.
        let all = common(&[p.x, p.y, p.z, o.x, o.y, o.z, d.x, d.y, d.z, n.x, n.y, n.z]);
        let num = (0..3)
            .map(|k| (&all[k] - &all[k + 3]) * &all[k + 9])
            .sum::<BigInt>();
        let den = (0..3).map(|k| &all[k + 6] * &all[k + 9]).sum::<BigInt>();
        for hit in [
            plane.cast(&ray, Interval::FORWARD),
            disk.cast(&ray, Interval::FORWARD),
        ]
        .into_iter()
        .flatten()
        {
            assert!(
                holds_rational(&hit, o, d, &num, &den),
                "seed {seed}: {hit:?}"
            );
            checked += 1;
        }
    }
    assert!(checked > 5_000, "{checked}");
}

#[test]
fn quadric_hit_points_hold_the_exact_root() {
    let mut checked = 0;
    for seed in 0..20_000u64 {
        let mut rng = SplitMix64::new(seed);
        let s = scale(&mut rng);
        let far = if seed % 3 == 0 { 1e7 } else { 1.0 };
        let c = vec3(&mut rng, 2.0) * s;
        let r = uniform(&mut rng, 0.5, 2.0) * s;
        let o = c + vec3(&mut rng, 6.0) * s * far;
        let d = c + vec3(&mut rng, 1.3) * r - o;
        let Ok(ray) = Ray::new(o, d) else { continue };
        let axis = vec3(&mut rng, 1.0);
        let [x, y, z] = c.to_array();
        // An ellipsoid through the same region: 2x^2 + y^2 + 3z^2 = r^2 about c.
        let k = [
            2.0,
            1.0,
            3.0,
            0.0,
            0.0,
            0.0,
            -4.0 * x,
            -2.0 * y,
            -6.0 * z,
            2.0 * x * x + y * y + 3.0 * z * z - r * r,
        ];
        let shapes: [(Option<Hit>, Quadratic); 3] = [
            (
                Sphere::new(c, r).unwrap().cast(&ray, Interval::FORWARD),
                Quadratic::sphere(o.to_array(), d.to_array(), c.to_array(), r),
            ),
            (
                Cylinder::new(c, axis, r)
                    .ok()
                    .and_then(|cy| cy.cast(&ray, Interval::FORWARD)),
                Quadratic::cylinder(o.to_array(), d.to_array(), c.to_array(), axis.to_array(), r),
            ),
            (
                Quadric::new(k)
                    .ok()
                    .and_then(|q| q.cast(&ray, Interval::FORWARD)),
                Quadratic::quadric(o.to_array(), d.to_array(), k),
            ),
        ];
        for (got, exact) in shapes {
            let Some(hit) = got else { continue };
            let Some(Some(w)) = exact.answer().first_admitted(0.0, f64::INFINITY, 4) else {
                continue;
            };
            let (lo, hi) = (w.next_down(), w.next_up());
            for k in 0..3 {
                assert!(
                    inside_bracket(hit.point[k], hit.error[k], o[k], d[k], lo, hi),
                    "seed {seed}, axis {k}: {hit:?}, exact root near {w:e}"
                );
            }
            checked += 1;
        }
    }
    assert!(checked > 5_000, "{checked}");
}

#[test]
fn cone_hit_points_hold_an_exact_root() {
    let (mut checked, mut certified) = (0, 0);
    for seed in 0..20_000u64 {
        let mut rng = SplitMix64::new(seed);
        let s = scale(&mut rng);
        let far = if seed % 3 == 0 { 1e7 } else { 1.0 };
        let apex = vec3(&mut rng, 2.0) * s;
        let axis = vec3(&mut rng, 1.0) * s;
        let r = uniform(&mut rng, 0.2, 2.0) * s;
        let o = apex + vec3(&mut rng, 6.0) * s * far;
        let d = apex + axis * 0.5 + vec3(&mut rng, 1.0) * r - o;
        let (Ok(ray), Ok(cone)) = (Ray::new(o, d), Cone::new(apex, axis, r)) else {
            continue;
        };
        let Some(hit) = cone.cast(&ray, Interval::FORWARD) else {
            continue;
        };
        let exact = Quadratic::cone(
            o.to_array(),
            d.to_array(),
            apex.to_array(),
            axis.to_array(),
            r,
        );
        let roots = exact.answer().roots;
        // The lateral hit is near one of the exact roots (both nappes are
        // roots; the base disk's hits are checked as planes elsewhere).
        let holds = |w: f64| {
            (0..3).all(|k| {
                inside_bracket(
                    hit.point[k],
                    hit.error[k],
                    o[k],
                    d[k],
                    w.next_down(),
                    w.next_up(),
                )
            })
        };
        if hit.normal == axis.normalize() {
            continue;
        }
        checked += 1;
        if hit.error.is_finite() {
            assert!(
                roots.iter().any(|&w| holds(w)),
                "seed {seed}: {hit:?} vs {roots:?}"
            );
            certified += 1;
        }
    }
    // Most lateral hits are certified (two thirds here, 4,408 of 6,532,
    // since the cone's polynomial is scaled at every scale drawn; before, the
    // hits at 2^±500 were not found or not certified): not those near
    // tangency.
    println!("cone lateral hits certified: {certified} of {checked}");
    assert!(
        checked > 2_000 && certified * 3 > checked * 2,
        "{certified} of {checked}"
    );
}
