//! `SphereBvh` against an exact brute force (the num-bigint oracle), on
//! fuzzer-chosen point sets and queries.
//!
//! Coordinates come from raw bit patterns (every finite value, subnormals
//! included) or from a small grid scaled by a fuzzer-chosen power of two, and
//! some points are copies of others nudged by a few ulps, so exact ties and
//! near-ties are common. Checked: `nearest` (a true nearest, the smallest
//! index among exact ties), `nearest_k` (the exact order), `within_radius`
//! (exact membership). A failing input panics with the data.
#![no_main]

use arbitrary::{Arbitrary, Result, Unstructured};
use exactray::bvh::Nearest;
use exactray::bvh::SphereBvh;
use exactray::testing::finite_f64_from_bits;
use exactray::testing::step_ulps;
use exactray_oracle::oracle;
use glam::DVec3;
use libfuzzer_sys::fuzz_target;

#[derive(Debug)]
struct Case {
    points: Vec<DVec3>,
    /// Radii, for an index of balls (`from_spheres`); `None` for points.
    radii: Option<Vec<f64>>,
    queries: Vec<DVec3>,
}

fn coordinate(u: &mut Unstructured, scale: f64) -> Result<f64> {
    Ok(if u.arbitrary::<bool>()? {
        finite_f64_from_bits(u.arbitrary()?)
    } else {
        (u.int_in_range(-4i8..=4)? as f64) * 0.5 * scale
    })
}

fn point(u: &mut Unstructured, scale: f64, earlier: &[DVec3]) -> Result<DVec3> {
    if !earlier.is_empty() && u.arbitrary::<bool>()? {
        let p = earlier[u.choose_index(earlier.len())?];
        let k = u.int_in_range(-3i64..=3)?;
        return Ok(match u.int_in_range(0u8..=3)? {
            0 => p,
            1 => DVec3::new(step_ulps(p.x, k), p.y, p.z),
            2 => DVec3::new(p.x, step_ulps(p.y, k), step_ulps(p.z, -k)),
            _ => -p,
        });
    }
    Ok(DVec3::new(
        coordinate(u, scale)?,
        coordinate(u, scale)?,
        coordinate(u, scale)?,
    ))
}

impl<'a> Arbitrary<'a> for Case {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let scale = 2f64.powi(u.int_in_range(-1074..=1020)?);
        let n = u.int_in_range(1usize..=48)?;
        let mut points = Vec::with_capacity(n);
        for _ in 0..n {
            let p = point(u, scale, &points)?;
            points.push(p);
        }
        let mut queries = Vec::new();
        for _ in 0..u.int_in_range(1usize..=4)? {
            queries.push(point(u, scale, &points)?);
        }
        let radii = if u.ratio(1, 3)? {
            let mut radii = Vec::with_capacity(n);
            for _ in 0..n {
                radii.push(if u.arbitrary()? {
                    0.0
                } else {
                    coordinate(u, scale)?.abs()
                });
            }
            Some(radii)
        } else {
            None
        };
        Ok(Case {
            points,
            radii,
            queries,
        })
    }
}

/// The exact order of items `a` and `b` (indices) by distance from `q`,
/// then by index.
fn order(case: &Case, q: DVec3, a: usize, b: usize) -> core::cmp::Ordering {
    let (pa, pb) = (case.points[a].to_array(), case.points[b].to_array());
    match &case.radii {
        None => oracle::compare_distance(q.to_array(), pa, pb),
        Some(r) => oracle::compare_ball_distance(q.to_array(), (pa, r[a]), (pb, r[b])),
    }
    .then(a.cmp(&b))
}

/// Whether item `i` lies within `r` of `q`, exactly.
fn within(case: &Case, q: DVec3, i: usize, r: f64) -> bool {
    let p = case.points[i].to_array();
    match &case.radii {
        None => oracle::within(q.to_array(), p, r),
        Some(radii) => oracle::ball_within(q.to_array(), (p, radii[i]), r),
    }
}

fuzz_target!(|case: Case| {
    // An ulp step off the largest finite value gives infinity: such sets
    // must be refused, and nothing else may be.
    let finite = case.points.iter().all(|p| p.is_finite());
    let built = match &case.radii {
        None => SphereBvh::from_points(&case.points),
        Some(radii) => {
            let balls: Vec<(DVec3, f64)> = case
                .points
                .iter()
                .copied()
                .zip(radii.iter().copied())
                .collect();
            SphereBvh::from_spheres(&balls)
        }
    };
    let bvh = match built {
        Ok(bvh) => bvh,
        Err(e) => {
            assert!(!finite, "refused a finite set: {e}");
            return;
        }
    };
    assert!(finite, "accepted a non-finite set");
    if case.queries.iter().any(|q| !q.is_finite()) {
        return;
    }
    let mut sorted: Vec<usize> = (0..case.points.len()).collect();
    for &q in &case.queries {
        sorted.sort_by(|&a, &b| order(&case, q, a, b));
        let hit = bvh.nearest(q).unwrap();
        assert_eq!(hit.index, sorted[0], "nearest: {case:?} query {q:?}");
        let k = 3.min(sorted.len());
        let mut out = [Nearest {
            index: usize::MAX,
            point: DVec3::ZERO,
            distance: 0.0,
        }; 3];
        assert_eq!(bvh.nearest_k(q, &mut out), k);
        for j in 0..k {
            assert_eq!(out[j].index, sorted[j], "nearest_k: {case:?} query {q:?}");
        }
        let r = hit.distance;
        if r.is_finite() {
            let mut got = Vec::new();
            bvh.within_radius(q, r, |h| got.push(h.index)).unwrap();
            got.sort();
            let want: Vec<usize> = (0..case.points.len())
                .filter(|&i| within(&case, q, i, r))
                .collect();
            assert_eq!(got, want, "within_radius {r}: {case:?} query {q:?}");
        }
    }
});
