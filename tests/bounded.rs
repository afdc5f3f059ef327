//! `Bounded` boxes against exact arithmetic: each box holds the exact
//! extreme coordinates of its shape (centres and end points as exact sums,
//! plus or minus the radius), on every magnitude from subnormal to near
//! `f64::MAX`, including sums that cancel.

use exactray::prelude::*;
use exactray::testing::SplitMix64;
use exactray_oracle::oracle::exact_parts;
use glam::DVec3;
use num_bigint::BigInt;

/// `sum of terms` compared exactly with `bound`: `Less`, `Equal` or
/// `Greater` (an infinite bound is beyond every finite sum).
fn cmp_sum(terms: &[f64], bound: f64) -> core::cmp::Ordering {
    if bound.is_infinite() {
        return if bound > 0.0 {
            core::cmp::Ordering::Less
        } else {
            core::cmp::Ordering::Greater
        };
    }
    let parts: Vec<(BigInt, i32)> = terms
        .iter()
        .chain([&bound])
        .map(|&v| exact_parts(v))
        .collect();
    let lo = parts.iter().map(|p| p.1).min().unwrap();
    let scaled: Vec<BigInt> = parts.iter().map(|(m, e)| m << (e - lo) as usize).collect();
    let (sum, b) = (
        scaled[..terms.len()].iter().sum::<BigInt>(),
        &scaled[terms.len()],
    );
    sum.cmp(b)
}

/// The box holds `sum(terms) - r` and `sum(terms) + r` on axis `k`, exactly.
fn holds(b: &Aabb, k: usize, terms: &[f64], r: f64) -> bool {
    let mut lo = terms.to_vec();
    lo.push(-r);
    let mut hi = terms.to_vec();
    hi.push(r);
    cmp_sum(&lo, b.min()[k]).is_ge() && cmp_sum(&hi, b.max()[k]).is_le()
}

fn coordinate(rng: &mut SplitMix64) -> f64 {
    let m = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64 + 0.5;
    let e = (rng.next_u64() % 2000) as i32 - 1000;
    let v = m * 2f64.powi(e.clamp(-1022, 1000));
    if rng.next_u64().is_multiple_of(2) {
        v
    } else {
        -v
    }
}

#[test]
fn boxes_hold_their_exact_shapes() {
    let mut rng = SplitMix64::new(0xb0c5);
    for case in 0..20_000u32 {
        let r = coordinate(&mut rng).abs();
        let mut v = || {
            DVec3::new(
                coordinate(&mut rng),
                coordinate(&mut rng),
                coordinate(&mut rng),
            )
        };
        let (p, mut a) = (v(), v());
        // Every fourth case cancels: the axis undoes the base point but
        // for a tiny remainder.
        if case.is_multiple_of(4) {
            a = -p + DVec3::splat(r);
        }
        let sphere = Sphere::new(p, r).unwrap().aabb().unwrap();
        let Ok(cyl) = CappedCylinder::new(p, a, r) else {
            continue;
        };
        let cyl = cyl.aabb().unwrap();
        let cone = Cone::new(p, a, r.max(f64::MIN_POSITIVE))
            .unwrap()
            .aabb()
            .unwrap();
        let rc = r.max(f64::MIN_POSITIVE);
        for k in 0..3 {
            assert!(holds(&sphere, k, &[p[k]], r), "sphere {p} {r}");
            assert!(
                holds(&cyl, k, &[p[k]], r) && holds(&cyl, k, &[p[k], a[k]], r),
                "cylinder {p} {a} {r}"
            );
            assert!(
                holds(&cone, k, &[p[k]], 0.0) && holds(&cone, k, &[p[k], a[k]], rc),
                "cone {p} {a} {r}"
            );
        }
    }
}

#[test]
fn unbounded_shapes_have_no_box_and_triangles_their_vertices() {
    assert!(
        Plane::new([0.0; 3], [0.0, 0.0, 1.0])
            .unwrap()
            .aabb()
            .is_none()
    );
    assert!(
        Cylinder::new([0.0; 3], [0.0, 1.0, 0.0], 1.0)
            .unwrap()
            .aabb()
            .is_none()
    );
    assert!(
        Cone::infinite([0.0; 3], [0.0, 1.0, 0.0], 1.0)
            .unwrap()
            .aabb()
            .is_none()
    );
    let q = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]).unwrap();
    assert!(q.aabb().is_none());
    let t = Triangle::new([0.0, 5.0, -1.0], [2.0, 0.0, 0.0], [1.0, 1.0, 3.0]).unwrap();
    let b = t.aabb().unwrap();
    assert_eq!(
        (b.min().to_array(), b.max().to_array()),
        ([0.0, 0.0, -1.0], [2.0, 5.0, 3.0])
    );
    let d = Disk::new([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 0.5)
        .unwrap()
        .aabb()
        .unwrap();
    assert!(d.contains([1.5, 2.0, 3.0]) && d.contains([1.0, 1.5, 3.0]));
}
