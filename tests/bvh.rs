//! `SphereBvh` against exact brute force (the num-bigint oracle of
//! `exactray-oracle`, `tests/oracle/src/oracle.rs`) on random, clustered, collinear, all-equal,
//! grid (exact ties), near-tie, huge, tiny and mixed-magnitude point sets;
//! pruning against brute force's work; bad input; spade's nearest neighbour.

use core::cmp::Ordering;
use exactray::bvh::{Nearest, QueryStats};
use exactray::testing::{SplitMix64, step_ulps};
use exactray::{InputError, bvh::SphereBvh};
use exactray_oracle::oracle;
use glam::DVec3;
use proptest::prelude::*;

/// The kinds of point sets the properties run on.
#[derive(Clone, Copy, Debug)]
enum Set {
    Uniform,
    Clustered,
    Collinear,
    AllEqual,
    Grid,
    NearTies,
    Huge,
    Tiny,
    Mixed,
}

/// A value of random sign and magnitude `2^e`, `e` uniform in `lo..=hi`.
fn magnitude(rng: &mut SplitMix64, lo: i32, hi: i32) -> f64 {
    let e = lo + (rng.next_u64() % (hi - lo + 1) as u64) as i32;
    let m = 1.0 + rng.next_f64();
    let v = m * 2f64.powi(e.clamp(-1022, 1023)) * if e < -1022 { 2f64.powi(e + 1022) } else { 1.0 };
    if rng.next_u64() & 1 == 0 { v } else { -v }
}

fn uniform(rng: &mut SplitMix64) -> DVec3 {
    DVec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 2.0 - 1.0
}

/// A point set of `set`'s kind and queries against it (some of them equal
/// to points, some one ulp off a point, some far away).
fn case(set: Set, seed: u64, n: usize) -> (Vec<DVec3>, Vec<DVec3>) {
    let mut rng = SplitMix64::new(seed);
    let mut points: Vec<DVec3> = match set {
        Set::Uniform => (0..n).map(|_| uniform(&mut rng)).collect(),
        Set::Clustered => {
            let centres: Vec<DVec3> = (0..3).map(|_| uniform(&mut rng)).collect();
            (0..n)
                .map(|i| centres[i % 3] + uniform(&mut rng) * 1e-3)
                .collect()
        }
        Set::Collinear => {
            let (o, d) = (uniform(&mut rng), uniform(&mut rng));
            (0..n).map(|_| o + d * rng.next_f64()).collect()
        }
        Set::AllEqual => vec![uniform(&mut rng); n],
        Set::Grid => (0..n)
            .map(|i| DVec3::new((i % 5) as f64, (i / 5 % 5) as f64, (i / 25) as f64))
            .collect(),
        Set::NearTies => {
            let q = uniform(&mut rng);
            (0..n)
                .map(|i| {
                    let axis = [DVec3::X, DVec3::Y, DVec3::Z, -DVec3::X][i % 4];
                    let p = q + axis * 0.5;
                    let k = (rng.next_u64() % 7) as i64 - 3;
                    DVec3::new(step_ulps(p.x, k), p.y, step_ulps(p.z, k / 2))
                })
                .collect()
        }
        Set::Huge => (0..n).map(|_| uniform(&mut rng) * 1e290).collect(),
        Set::Tiny => (0..n)
            .map(|_| {
                DVec3::new(
                    magnitude(&mut rng, -1074, -1000),
                    magnitude(&mut rng, -1074, -1000),
                    magnitude(&mut rng, -1074, -1000),
                )
            })
            .collect(),
        Set::Mixed => (0..n)
            .map(|_| {
                DVec3::new(
                    magnitude(&mut rng, -1074, 1020),
                    magnitude(&mut rng, -1074, 1020),
                    magnitude(&mut rng, -1074, 1020),
                )
            })
            .collect(),
    };
    if let Set::Grid = set {
        points.retain(|p| p.z < 5.0);
    }
    let scale = match set {
        Set::Huge => 1e290,
        Set::Tiny => 1e-305,
        _ => 1.0,
    };
    let mut queries = Vec::new();
    for k in 0..6 {
        let p = points[(rng.next_u64() as usize) % points.len()];
        queries.push(match k {
            0 => p,
            1 => DVec3::new(step_ulps(p.x, 1), p.y, p.z),
            2 if matches!(set, Set::Grid) => (p + 0.5).floor() + DVec3::new(0.5, 0.5, 0.0),
            3 if matches!(set, Set::NearTies) => {
                // The centre the near-ties were built around.
                points[0] - DVec3::X * 0.5
            }
            4 => DVec3::new(1e200, -3e180, 7e150),
            _ => uniform(&mut rng) * scale,
        });
    }
    (points, queries)
}

/// Exact ordering of `(|a - q|, index_a)` against `(|b - q|, index_b)`.
fn exact_order(q: DVec3, (ia, a): (usize, DVec3), (ib, b): (usize, DVec3)) -> Ordering {
    oracle::compare_distance(q.to_array(), a.to_array(), b.to_array()).then(ia.cmp(&ib))
}

/// Every property for one point set and its queries.
fn check(points: &[DVec3], queries: &[DVec3]) -> Result<(), TestCaseError> {
    let bvh = SphereBvh::from_points(points).unwrap();
    prop_assert_eq!(bvh.len(), points.len());
    let indexed: Vec<(usize, DVec3)> = points.iter().copied().enumerate().collect();
    for &q in queries {
        let mut sorted = indexed.clone();
        sorted.sort_by(|&a, &b| exact_order(q, a, b));
        // nearest: the first of the exact order.
        let hit = bvh.nearest(q).unwrap();
        prop_assert_eq!(hit.index, sorted[0].0, "nearest to {:?}", q);
        prop_assert_eq!(hit.point, sorted[0].1);
        prop_assert_eq!(bvh.try_nearest(q), Ok(Some(hit)));
        // The distance is within 4 ulps (of a reference computed in a
        // rescaled frame, itself within 4 ulps) unless it is subnormal.
        let d = hit.point - q;
        let k = if d.is_finite() {
            d.abs().max_element()
        } else {
            f64::INFINITY
        };
        if k > 0.0 && k.is_finite() {
            let s = 2f64.powi(-(k.log2().floor() as i32).clamp(-1000, 1000));
            let exact = (d * s).length() / s;
            if exact.is_normal() {
                prop_assert!(
                    (hit.distance - exact).abs() <= 8.0 * f64::EPSILON * exact,
                    "distance {} vs {}",
                    hit.distance,
                    exact
                );
            }
        }
        // nearest_k: the first k of the exact order, in order.
        let k = 4.min(points.len());
        let mut out = [Nearest {
            index: usize::MAX,
            point: DVec3::ZERO,
            distance: 0.0,
        }; 4];
        prop_assert_eq!(bvh.nearest_k(q, &mut out), k);
        let got: Vec<usize> = out[..k].iter().map(|h| h.index).collect();
        let want: Vec<usize> = sorted[..k].iter().map(|h| h.0).collect();
        prop_assert_eq!(got, want, "nearest_k to {:?}", q);
        // within_radius with the radius of the k-th nearest: boundary cases.
        let r = (sorted[k - 1].1 - q).length();
        if r.is_finite() {
            let mut got = Vec::new();
            let n = bvh.within_radius(q, r, |h| got.push(h.index)).unwrap();
            got.sort();
            let want: Vec<usize> = indexed
                .iter()
                .filter(|(_, p)| oracle::within(q.to_array(), p.to_array(), r))
                .map(|(i, _)| *i)
                .collect();
            prop_assert_eq!(n, want.len());
            prop_assert_eq!(got, want, "within {} of {:?}", r, q);
        }
    }
    Ok(())
}

macro_rules! properties {
    ($($name:ident: $set:expr, $n:expr;)*) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(24))]
            $(
                #[test]
                fn $name(seed in any::<u64>(), n in 1usize..$n) {
                    let (points, queries) = case($set, seed, n);
                    check(&points, &queries)?;
                }
            )*
        }
    };
}

properties! {
    uniform_points: Set::Uniform, 200;
    clustered_points: Set::Clustered, 200;
    collinear_points: Set::Collinear, 120;
    all_equal_points: Set::AllEqual, 60;
    grid_points_with_exact_ties: Set::Grid, 125;
    near_tie_points: Set::NearTies, 60;
    huge_points: Set::Huge, 120;
    tiny_points: Set::Tiny, 120;
    mixed_magnitude_points: Set::Mixed, 120;
}

#[test]
fn pruning_visits_far_fewer_points_than_brute_force() {
    let n = 100_000;
    let (points, _) = case(Set::Uniform, 7, n);
    let bvh = SphereBvh::from_points(&points).unwrap();
    let mut rng = SplitMix64::new(8);
    let mut stats = QueryStats::default();
    let queries = 1000;
    for _ in 0..queries {
        bvh.nearest_with_stats(uniform(&mut rng), &mut stats)
            .unwrap();
    }
    let per_query = stats.distances_computed as f64 / queries as f64;
    let nodes = stats.nodes_visited as f64 / queries as f64;
    println!(
        "{n} uniform points: {per_query:.1} distances and {nodes:.1} nodes per query (brute force: {n} distances)"
    );
    // Brute force computes all n distances; the prune keeps it to a
    // few leaves.
    assert!(
        per_query < n as f64 / 500.0,
        "{per_query} distances per query"
    );
}

#[test]
fn bad_input_is_a_typed_error_and_empty_is_none() {
    let empty = SphereBvh::from_points::<DVec3>(&[]).unwrap();
    assert!(empty.is_empty());
    assert_eq!(empty.nearest(DVec3::ZERO), None);
    assert_eq!(empty.try_nearest(DVec3::ZERO), Ok(None));
    let mut out = [Nearest {
        index: 0,
        point: DVec3::ZERO,
        distance: 0.0,
    }; 2];
    assert_eq!(empty.nearest_k(DVec3::ZERO, &mut out), 0);
    assert_eq!(empty.within_radius(DVec3::ZERO, 1.0, |_| ()), Ok(0));

    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let err = SphereBvh::from_points(&[DVec3::ZERO, DVec3::new(1.0, bad, 0.0)]).unwrap_err();
        assert_eq!(err, InputError::NonFinite { argument: "points" });
        let bvh = SphereBvh::from_points(&[DVec3::ZERO]).unwrap();
        let q = DVec3::new(bad, 0.0, 0.0);
        assert_eq!(bvh.nearest(q), None);
        assert_eq!(
            bvh.try_nearest(q),
            Err(InputError::NonFinite { argument: "q" })
        );
        assert_eq!(bvh.nearest_k(q, &mut out), 0);
        assert_eq!(
            bvh.within_radius(q, 1.0, |_| ()),
            Err(InputError::NonFinite { argument: "q" })
        );
    }
    let bvh = SphereBvh::from_points(&[DVec3::ZERO]).unwrap();
    assert_eq!(
        bvh.within_radius(DVec3::ZERO, -1.0, |_| ()),
        Err(InputError::InvalidRadius { argument: "r" })
    );
    assert_eq!(
        bvh.within_radius(DVec3::ZERO, f64::NAN, |_| ()),
        Err(InputError::InvalidRadius { argument: "r" })
    );
    assert_eq!(
        bvh.within_radius(DVec3::ZERO, f64::INFINITY, |_| ()),
        Err(InputError::NonFinite { argument: "r" })
    );
    let mut none = [None; 1];
    assert_eq!(
        bvh.nearest_many(&[DVec3::ZERO, DVec3::X], &mut none),
        Err(InputError::LengthMismatch {
            expected: 2,
            got: 1
        })
    );
    assert_eq!(none, [None]);
}

#[test]
fn f32_points_widen_exactly_and_duplicates_are_kept() {
    let points = [
        glam::Vec3::new(0.1, 0.2, 0.3),
        glam::Vec3::new(0.1, 0.2, 0.3),
        glam::Vec3::ONE,
    ];
    let bvh = SphereBvh::from_points(&points).unwrap();
    let hit = bvh.nearest(glam::Vec3::new(0.1, 0.2, 0.3)).unwrap();
    assert_eq!((hit.index, hit.distance), (0, 0.0));
    assert_eq!(hit.point, points[0].as_dvec3());
    let mut out = [Nearest {
        index: 9,
        point: DVec3::ZERO,
        distance: 0.0,
    }; 3];
    assert_eq!(bvh.nearest_k(points[0], &mut out), 3);
    assert_eq!(out.map(|h| h.index), [0, 1, 2]);
}

#[test]
fn batch_matches_one_by_one() {
    let (points, _) = case(Set::Clustered, 3, 5000);
    let bvh = SphereBvh::from_points(&points).unwrap();
    let mut rng = SplitMix64::new(4);
    let mut queries: Vec<DVec3> = (0..3000).map(|_| uniform(&mut rng)).collect();
    queries[17] = DVec3::new(f64::NAN, 0.0, 0.0);
    let mut parallel = vec![None; queries.len()];
    let mut serial = vec![None; queries.len()];
    bvh.nearest_many(&queries, &mut parallel).unwrap();
    bvh.nearest_many_serial(&queries, &mut serial).unwrap();
    assert_eq!(parallel, serial);
    assert_eq!(parallel[17], None);
    for (q, hit) in queries.iter().zip(&parallel).take(100) {
        assert_eq!(bvh.nearest(*q), *hit);
    }
}

/// In the plane z = 0, the nearest point agrees with spade's Delaunay
/// nearest-neighbour lookup (exactly as near; ties may pick another point).
#[test]
fn agrees_with_spade_nearest_neighbour_in_2d() {
    use spade::{DelaunayTriangulation, Point2, Triangulation};
    let mut rng = SplitMix64::new(11);
    let points: Vec<DVec3> = (0..2000)
        .map(|_| DVec3::new(rng.next_f64() * 100.0, rng.next_f64() * 100.0, 0.0))
        .collect();
    let mut dt: DelaunayTriangulation<Point2<f64>> = DelaunayTriangulation::new();
    for p in &points {
        dt.insert(Point2::new(p.x, p.y)).unwrap();
    }
    let bvh = SphereBvh::from_points(&points).unwrap();
    for _ in 0..2000 {
        let q = DVec3::new(
            rng.next_f64() * 120.0 - 10.0,
            rng.next_f64() * 120.0 - 10.0,
            0.0,
        );
        let ours = bvh.nearest(q).unwrap().point;
        let theirs = dt
            .nearest_neighbor(Point2::new(q.x, q.y))
            .unwrap()
            .position();
        let theirs = [theirs.x, theirs.y, 0.0];
        assert_eq!(
            oracle::compare_distance(q.to_array(), ours.to_array(), theirs),
            Ordering::Equal,
            "query {q:?}: ours {ours:?}, spade {theirs:?}"
        );
    }
}

/// Leaf spheres enclose their points (checked exactly) and are close to
/// minimal: their radii against the Badoiu-Clarkson approximation of the
/// minimal enclosing sphere (2,000 iterations: within about 2.5% above the
/// minimal radius, so the ratio printed is, if anything, slightly low).
#[test]
fn leaf_spheres_enclose_their_points_and_are_tight() {
    for set in [Set::Uniform, Set::Clustered] {
        let (points, _) = case(set, 5, 20_000);
        let bvh = SphereBvh::from_points(&points).unwrap();
        // The leaves partition the points.
        let mut all: Vec<u32> = bvh
            .leaf_spheres()
            .flat_map(|(_, _, i)| i.to_vec())
            .collect();
        all.sort_unstable();
        assert!(all.iter().copied().eq(0..points.len() as u32));
        let (mut sum, mut count) = (0.0, 0);
        for (k, (c, r, indices)) in bvh.leaf_spheres().enumerate() {
            for &i in indices {
                assert!(
                    oracle::within(c.to_array(), points[i as usize].to_array(), r),
                    "point {i} outside its leaf"
                );
            }
            if k % 20 != 0 {
                continue;
            }
            let leaf: Vec<DVec3> = indices.iter().map(|&i| points[i as usize]).collect();
            let mut centre = leaf[0];
            let far = |c: DVec3| {
                leaf.iter()
                    .copied()
                    .max_by(|a, b| a.distance(c).total_cmp(&b.distance(c)))
                    .unwrap()
            };
            for step in 1..2000 {
                centre += (far(centre) - centre) / (step as f64 + 1.0);
            }
            let minimal = far(centre).distance(centre);
            if minimal > 0.0 {
                assert!(
                    r >= minimal * 0.97,
                    "a leaf sphere smaller than the minimal one"
                );
                sum += r / minimal;
                count += 1;
            }
        }
        println!(
            "{set:?}: mean leaf radius / minimal enclosing radius = {:.3} over {count} leaves",
            sum / count as f64
        );
    }
}

/// Fuzzer finding: a radius of zero around a query at the origin, points at
/// signed zeros and subnormals.
#[test]
fn zero_radius_at_signed_zeros() {
    let z = -0.0;
    let points = [
        DVec3::new(z, 0.0, z),
        DVec3::new(z, -1e-323, 1e-323),
        DVec3::new(z, 0.0, z),
        DVec3::new(z, z, z),
    ];
    let bvh = SphereBvh::from_points(&points).unwrap();
    let mut got = Vec::new();
    bvh.within_radius(DVec3::splat(z), 0.0, |h| got.push(h.index))
        .unwrap();
    got.sort();
    assert_eq!(got, [0, 2, 3]);
}

/// Balls of random radii (zero included), some containing the query, some
/// in exactly tied pairs around it.
fn ball_case(seed: u64, n: usize) -> (Vec<(DVec3, f64)>, Vec<DVec3>) {
    let mut rng = SplitMix64::new(seed);
    let mut balls: Vec<(DVec3, f64)> = (0..n)
        .map(|i| {
            let r = match i % 4 {
                0 => 0.0,
                _ => rng.next_f64() * 0.3,
            };
            (uniform(&mut rng), r)
        })
        .collect();
    let q = uniform(&mut rng);
    // An exact tie: mirror images of a ball through the query, when exact.
    let (c, r) = balls[0];
    let mirror = q * 2.0 - c;
    if (mirror + c) * 0.5 == q && mirror - q == q - c {
        balls.push((mirror, r));
    }
    // A ball one ulp of radius apart from another.
    let (c, r) = balls[n / 2];
    balls.push((c, step_ulps(r.max(0.25), 1)));
    let queries = vec![q, uniform(&mut rng), balls[1].0, DVec3::new(3.0, -2.0, 0.5)];
    (balls, queries)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    #[test]
    fn balls_against_exact_brute_force(seed in any::<u64>(), n in 1usize..80) {
        let (balls, queries) = ball_case(seed, n);
        let bvh = SphereBvh::from_spheres(&balls).unwrap();
        let arr = |(c, r): (DVec3, f64)| (c.to_array(), r);
        for &q in &queries {
            let mut sorted: Vec<usize> = (0..balls.len()).collect();
            sorted.sort_by(|&i, &j| {
                oracle::compare_ball_distance(q.to_array(), arr(balls[i]), arr(balls[j])).then(i.cmp(&j))
            });
            let hit = bvh.nearest(q).unwrap();
            prop_assert_eq!(hit.index, sorted[0], "nearest ball to {:?}", q);
            prop_assert_eq!(hit.point, balls[hit.index].0);
            let k = 4.min(balls.len());
            let mut out = [Nearest { index: 0, point: DVec3::ZERO, distance: 0.0 }; 4];
            prop_assert_eq!(bvh.nearest_k(q, &mut out), k);
            let got: Vec<usize> = out[..k].iter().map(|h| h.index).collect();
            prop_assert_eq!(&got[..], &sorted[..k]);
            let r = out[k - 1].distance;
            let mut got = Vec::new();
            bvh.within_radius(q, r, |h| got.push(h.index)).unwrap();
            got.sort();
            let want: Vec<usize> = (0..balls.len())
                .filter(|&i| oracle::ball_within(q.to_array(), arr(balls[i]), r))
                .collect();
            prop_assert_eq!(got, want);
        }
    }
}

#[test]
fn bad_spheres_are_typed_errors() {
    let ok = DVec3::ZERO;
    let err = |r: f64, c: DVec3| SphereBvh::from_spheres(&[(ok, 1.0), (c, r)]).unwrap_err();
    let invalid = InputError::InvalidRadius {
        argument: "spheres",
    };
    let non_finite = InputError::NonFinite {
        argument: "spheres",
    };
    assert_eq!(err(-1.0, ok), invalid);
    assert_eq!(err(f64::NAN, ok), invalid);
    assert_eq!(err(f64::INFINITY, ok), non_finite);
    assert_eq!(err(1.0, DVec3::new(0.0, f64::NAN, 0.0)), non_finite);
    assert!(
        SphereBvh::from_spheres::<DVec3>(&[])
            .unwrap()
            .nearest(ok)
            .is_none()
    );
}

/// Fuzzer finding: differences of coordinates near `f64::MAX` overflow, and
/// an overflowed (infinite) computed distance is not a large one. Point 1 is
/// nearest (about 1.82e308 away); point 0 (about 2.54e308) has a finite
/// computed distance.
#[test]
fn overflowing_differences_are_not_far() {
    let points = [
        DVec3::new(
            -1.7976922843523588e308,
            1.5573742111089948e-207,
            1.3758210268297398e-135,
        ),
        DVec3::new(
            -4.1274630804892193e-135,
            -2.7516420536594796e-135,
            -1.1848942823504931e306,
        ),
    ];
    let q = DVec3::new(
        2.7516420536594814e-135,
        1.7190769349208505e307,
        1.7976931348623157e308,
    );
    let bvh = SphereBvh::from_points(&points).unwrap();
    assert_eq!(bvh.nearest(q).unwrap().index, 1);
    let balls = points.map(|p| (p, 0.0));
    assert_eq!(
        SphereBvh::from_spheres(&balls)
            .unwrap()
            .nearest(q)
            .unwrap()
            .index,
        1
    );
}
