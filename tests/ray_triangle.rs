//! Ray–triangle intersection against exact arithmetic (num-bigint): the
//! exact variant's hit or miss equals the exact answer on every input and
//! its `t` is within 4 units of rounding of the exact parameter; the
//! watertight and exact variants never let a ray aimed at a shared edge or
//! vertex of a tiled mesh through; all variants stay defined on every
//! finite input.

use exactray::interval::Interval;
use exactray::query::ray::{BOUNDED_T_ULPS, EXACT_T_ULPS, ExactRay, Ray, RayCast, TriangleHit};
use exactray::shape::Triangle;
use exactray::testing::{
    RayTriangleCase as Case, RayTriangleClass, SplitMix64, TiledMesh, ray_triangle_case, step_ulps,
};
use exactray_oracle::oracle;
use glam::DVec3;
use proptest::prelude::*;

/// The exact crossing of the ray's line with the triangle, `(num, den)`
/// for `t = num / den` (a coplanar ray is a miss, as the crate documents).
fn exact_crossing(c: &Case) -> Option<(num_bigint::BigInt, num_bigint::BigInt)> {
    let (o, d, v) = c;
    oracle::line_triangle(o.to_array(), d.to_array(), v.map(|p| p.to_array())).t
}

/// Whether a cast hit (`hit`) as the oracle demands for the exact
/// `crossing`, for a `t` within `units` units of rounding
/// (`oracle::hit_policy`): where either answer is right, no demand.
fn check_hit(
    c: &Case,
    range: Interval,
    hit: bool,
    crossing: &Option<(num_bigint::BigInt, num_bigint::BigInt)>,
    units: f64,
) -> Result<(), TestCaseError> {
    let want = match crossing {
        None => Some(false),
        Some((num, den)) => oracle::hit_policy(num, den, range.min(), range.max(), units as u32),
    };
    if let Some(want) = want {
        prop_assert_eq!(hit, want, "{:?} {:?}", c, range);
    }
    Ok(())
}

/// The exact variant agrees with the oracle on the hit (the crate's policy,
/// `oracle::hit_policy`: a crossing beyond `f64`'s range is no hit), its
/// `t` is within the documented bound, and its barycentrics are in
/// `[0, 1]`. The range's finite non-zero bounds are compared with the
/// returned `t` (documented), so they are checked only away from the exact
/// `t`.
fn check_exact(c: &Case, range: Interval) -> Result<(), TestCaseError> {
    let (o, d, v) = *c;
    let (Ok(ray), Ok(tri)) = (Ray::new(o, d), Triangle::new(v[0], v[1], v[2])) else {
        return Ok(());
    };
    let got = tri.cast_exact(&ray, range);
    let crossing = exact_crossing(c);
    check_hit(c, range, got.is_some(), &crossing, EXACT_T_ULPS)?;
    if let (Some(hit), Some((num, den))) = (got, crossing) {
        prop_assert!(hit.t.is_finite(), "{:?}: {:?}", c, hit);
        prop_assert!(
            oracle::within_units(hit.t, &num, &den, EXACT_T_ULPS as u32)
                || hit.t.abs() < f64::MIN_POSITIVE,
            "t = {} off the exact {}: {:?}",
            hit.t,
            oracle::ratio_to_f64(&num, &den),
            c
        );
        prop_assert!((0.0..=1.0).contains(&hit.u) && (0.0..=1.0).contains(&hit.v));
        prop_assert!(hit.u + hit.v <= 1.0 + 4.0 * f64::EPSILON);
    }
    check_bounded(c, &ray, &tri, range, got)
}

/// The bounded tier ([`ExactRay::cast_bounded`]) on the same case: the hit
/// the oracle demands (the crate's policy for a `t` within
/// `BOUNDED_T_ULPS`), the precise tier's barycentrics, and the exact `t`
/// inside the returned bound, itself within `BOUNDED_T_ULPS` units of
/// rounding. `precise` is `cast_exact`'s answer, which a prepared ray
/// repeats.
fn check_bounded(
    c: &Case,
    ray: &Ray,
    tri: &Triangle,
    range: Interval,
    precise: Option<TriangleHit>,
) -> Result<(), TestCaseError> {
    let prepared = ExactRay::new(ray);
    prop_assert_eq!(prepared.cast(tri, range), precise);
    let got = prepared.cast_bounded(tri, range);
    let crossing = exact_crossing(c);
    check_hit(c, range, got.is_some(), &crossing, BOUNDED_T_ULPS)?;
    let (Some(b), Some((num, den))) = (got, crossing) else {
        return Ok(());
    };
    if let Some(p) = precise {
        prop_assert_eq!((b.hit.u, b.hit.v), (p.u, p.v));
    }
    prop_assert!(b.hit.t.is_finite() && range.admits(b.hit.t), "{:?}", b);
    let (lo, hi) = (b.hit.t - b.t_error, b.hit.t + b.t_error);
    prop_assert!(
        oracle::ratio_in(&num, &den, lo.next_down(), hi.next_up()),
        "exact t {} outside {:?}: {:?}",
        oracle::ratio_to_f64(&num, &den),
        b,
        c
    );
    // 2^-1073 for a subnormal `t` (the precise tier's).
    let most = BOUNDED_T_ULPS * f64::EPSILON / 2.0 * b.hit.t.abs() + f64::from_bits(2);
    prop_assert!(b.t_error <= most, "{:?}", b);
    Ok(())
}

/// The fast variants never panic and report only `t` inside the range.
fn check_fast(c: &Case, range: Interval) -> Result<(), TestCaseError> {
    let (o, d, v) = *c;
    let (Ok(ray), Ok(tri)) = (Ray::new(o, d), Triangle::new(v[0], v[1], v[2])) else {
        return Ok(());
    };
    for hit in [tri.cast_mt(&ray, range), tri.cast_watertight(&ray, range)]
        .into_iter()
        .flatten()
    {
        prop_assert!(range.admits(hit.t), "{:?}", hit);
    }
    if let Some(hit) = tri.cast(&ray, range) {
        prop_assert!((hit.normal.length() - 1.0).abs() < 1e-12);
    }
    Ok(())
}

fn case_from(seed: u64, kind: u8) -> Case {
    let mut rng = SplitMix64::new(seed);
    ray_triangle_case(RayTriangleClass::ALL[kind as usize % 4], &mut rng)
}

/// Every coordinate of a case scaled by `2^k` (exact unless it leaves the
/// normal range, which only makes the case another valid one).
fn scaled((o, d, v): Case, k: i32) -> Case {
    let s = |p: DVec3| p * 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
    (s(o), s(d), v.map(s))
}

/// Whether scaling `c` by `2^k` is exact and keeps every value the
/// watertight test computes from it normal: every coordinate, every
/// difference of a vertex and the origin, and every direction coordinate
/// is zero or, scaled, between `2^-960` and `2^1000` (the margin covers
/// the shear's products with direction ratios down to `2^-60`).
fn scales_normally((o, d, v): &Case, k: i32) -> bool {
    let ok = |x: f64| {
        let s = x.abs() * 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
        x == 0.0 || (2f64.powi(-960)..=2f64.powi(1000)).contains(&s)
    };
    let ratios = d.abs().min_element() == 0.0
        || d.abs().min_element() >= d.abs().max_element() * 2f64.powi(-60);
    let values = [*o, *d]
        .into_iter()
        .chain(v.iter().copied())
        .chain(v.iter().map(|p| *p - *o));
    ratios && values.flat_map(|p| p.to_array()).all(ok)
}

/// A coordinate moved by a few ulps.
fn nudge(x: f64, n: i64) -> f64 {
    step_ulps(x, n)
}

fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1e3..1e3f64,
        any::<u64>()
            .prop_map(f64::from_bits)
            .prop_filter("finite", |x| x.is_finite()),
        Just(0.0),
    ]
}

fn any_dvec3() -> impl Strategy<Value = DVec3> {
    (any_f64(), any_f64(), any_f64()).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn exact_matches_oracle_on_generated_cases(seed: u64, kind: u8, k in -1000i32..1000) {
        let c = case_from(seed, kind);
        check_exact(&c, Interval::FORWARD)?;
        check_exact(&scaled(c, k), Interval::FORWARD)?;
        check_fast(&c, Interval::FORWARD)?;
        check_fast(&scaled(c, k), Interval::FORWARD)?;
    }

    /// The watertight test answers a case scaled by `2^k` as it answers
    /// the case itself, bit for bit (`t`, `u`, `v`), wherever the scaling
    /// and the test's intermediate values stay normal (a subnormal rounds
    /// on a coarser grid): at `2^±600` and beyond its products leave the
    /// normal range and it evaluates at powers of two of its own, which
    /// must not change an answer.
    #[test]
    fn watertight_answers_scaled_copies_alike(seed: u64, kind: u8, k in -1000i32..=1000) {
        let c = case_from(seed, kind);
        let s = scaled(c, k);
        prop_assume!(scales_normally(&c, k));
        let (Ok(ray), Ok(tri)) = (Ray::new(c.0, c.1), Triangle::new(c.2[0], c.2[1], c.2[2])) else {
            return Ok(());
        };
        let (ray_s, tri_s) = (Ray::new(s.0, s.1).unwrap(), Triangle::new(s.2[0], s.2[1], s.2[2]).unwrap());
        for range in [Interval::FORWARD, Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap()] {
            let want = tri.cast_watertight(&ray, range);
            prop_assert_eq!(tri_s.cast_watertight(&ray_s, range), want, "{:?} at 2^{}", c, k);
            // The origin and vertices scaled, the direction not: `t` scales.
            let ray_t = Ray::new(s.0, c.1).unwrap();
            let got = tri_s.cast_watertight(&ray_t, range);
            let want = want.map(|h| TriangleHit { t: h.t * 2f64.powi(k / 2) * 2f64.powi(k - k / 2), ..h });
            prop_assert_eq!(got.map(|h| (h.u, h.v)), want.map(|h| (h.u, h.v)), "{:?} at 2^{}", c, k);
            if let (Some(g), Some(w)) = (got, want) && w.t.abs() >= f64::MIN_POSITIVE {
                prop_assert_eq!(g.t, w.t, "{:?} at 2^{}", c, k);
            }
        }
    }

    /// The origin moved `2^j` times farther along the ray, aimed at the
    /// same point: the bits the case spans grow with `j`, through every
    /// integer width the exact parameter is computed in.
    #[test]
    fn exact_across_spans(seed: u64, kind: u8, j in 0..900i32, k in -100i32..100) {
        let (o, d, v) = case_from(seed, kind);
        let target = o + d;
        let far = target + (o - target) * 2f64.powi(j);
        let c = (far, target - far, v);
        check_exact(&c, Interval::FORWARD)?;
        check_exact(&scaled(c, k), Interval::FORWARD)?;
    }

    #[test]
    fn exact_matches_oracle_on_any_coordinates(
        o in any_dvec3(), d in any_dvec3(), a in any_dvec3(), b in any_dvec3(), c in any_dvec3(),
    ) {
        let case = (o, d, [a, b, c]);
        check_exact(&case, Interval::FORWARD)?;
        check_exact(&case, Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap())?;
        check_fast(&case, Interval::FORWARD)?;
    }

    /// Rays through a vertex or along an edge's line, and coplanar rays,
    /// built from the triangle's own coordinates: exact zeros.
    #[test]
    fn exact_on_degenerate_configurations(seed: u64, kind: u8, n in -2i64..=2) {
        let (o, _, v) = case_from(seed, kind);
        let k = (seed % 3) as usize;
        let cases = [
            // Through a vertex (the direction rounded, then nudged).
            (o, (v[k] - o).to_array().map(|x| nudge(x, n)).into(), v),
            // Along an edge, from a vertex: the line is the edge's line.
            (v[k], v[(k + 1) % 3] - v[k], v),
            // From a vertex towards another vertex's mirror: in the plane.
            (v[k], v[k] - v[(k + 2) % 3], v),
            // A degenerate triangle: two coincident vertices.
            (o, v[0] - o, [v[0], v[1], v[1]]),
        ];
        for c in cases {
            check_exact(&c, Interval::FORWARD)?;
            check_fast(&c, Interval::FORWARD)?;
        }
    }

    /// Finite bounds other than 0: the answer may differ from the exact one
    /// only when the exact `t` lies within the documented bound of one.
    #[test]
    fn exact_with_finite_bounds(seed: u64, kind: u8, lo in -5.0..5.0f64, len in 0.0..5.0f64) {
        let c = case_from(seed, kind);
        let range = Interval::new(lo, lo + len).unwrap();
        let (o, d, v) = c;
        let tri = Triangle::new(v[0], v[1], v[2]).unwrap();
        let got = tri.cast_exact(&Ray::new(o, d).unwrap(), range).is_some();
        let line = oracle::line_triangle(o.to_array(), d.to_array(), v.map(|p| p.to_array()));
        if let Some((num, den)) = line.t {
            let near = |b: f64| {
                let e = EXACT_T_ULPS * f64::EPSILON * b.abs().max(f64::MIN_POSITIVE);
                oracle::ratio_in(&num, &den, b - e, b + e)
            };
            if !near(range.min()) && !near(range.max()) {
                prop_assert_eq!(got, oracle::ratio_in(&num, &den, range.min(), range.max()));
            }
        } else {
            prop_assert!(!got);
        }
    }
}

/// One prepared ray ([`ExactRay`]) answers each of many triangles as
/// `cast_exact` and `cast_exact_closed` do (preparing the ray afresh), on
/// every input class and scaled to tiny, huge and subnormal coordinates;
/// its bounded tier holds on each (`check_bounded`), and on ordinary rays
/// it is the cheap formula's bound that answers, not only the precise
/// tier's.
#[test]
fn a_prepared_ray_answers_as_fresh_ones() {
    let whole = Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap();
    let mut cheap = 0;
    for class in RayTriangleClass::ALL {
        let mut rng = SplitMix64::new(0x9e1);
        let cases: Vec<Case> = (0..200)
            .map(|_| ray_triangle_case(class, &mut rng))
            .collect();
        for k in [0, -600, 600, -1040] {
            for (i, c) in cases.iter().enumerate() {
                let (o, d, _) = scaled(*c, k);
                let Ok(ray) = Ray::new(o, d) else {
                    continue;
                };
                let prepared = ExactRay::new(&ray);
                // Its own triangle, then the next cases' (mostly misses).
                for j in 0..6 {
                    let (_, _, v) = scaled(cases[(i + j) % cases.len()], k);
                    let Ok(tri) = Triangle::new(v[0], v[1], v[2]) else {
                        continue;
                    };
                    for range in [Interval::FORWARD, whole] {
                        let fresh = tri.cast_exact(&ray, range);
                        assert_eq!(prepared.cast(&tri, range), fresh);
                        assert_eq!(
                            prepared.cast_closed(&tri, range),
                            tri.cast_exact_closed(&ray, range)
                        );
                        check_bounded(&(o, d, v), &ray, &tri, range, fresh).unwrap();
                        let bounded = prepared.cast_bounded(&tri, range);
                        cheap += bounded.is_some_and(|b| {
                            b.t_error > 4.0 * f64::EPSILON * b.hit.t.abs() + f64::from_bits(2)
                        }) as u32;
                    }
                }
            }
        }
    }
    assert!(cheap > 500, "{cheap}");
}

/// Origins within about `2^-56` of a tilted triangle's plane, relative to
/// its size (found by nudging a rounded point of the plane and keeping the
/// nudges the oracle puts nearest): the numerator of `t` cancels to below
/// the double-double evaluation's error bound there, so only the filtered
/// stage's certificate keeps `t` within 4 units of rounding (without it,
/// `t` is off by far more).
#[test]
fn origins_nearly_on_the_plane() {
    let mut rng = SplitMix64::new(0x0f1a7e);
    let mut found = 0;
    for _ in 0..4000 {
        let (_, _, v) = ray_triangle_case(RayTriangleClass::Uniform, &mut rng);
        let (a, b) = (rng.next_f64() * 0.5, rng.next_f64() * 0.5);
        let p = v[0] + (v[1] - v[0]) * a + (v[2] - v[0]) * b;
        let d = DVec3::new(rng.next_f64() - 0.5, rng.next_f64() - 0.5, 1.0);
        for k in -2..=2 {
            let o = DVec3::new(p.x, p.y, step_ulps(p.z, k));
            let c = (o, d, v);
            let line = oracle::line_triangle(o.to_array(), d.to_array(), v.map(|p| p.to_array()));
            let Some((num, den)) = line.t else { continue };
            let t = oracle::ratio_to_f64(&num, &den).abs();
            if t != 0.0 && t < 2f64.powi(-56) {
                found += 1;
                check_exact(&c, Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap()).unwrap();
            }
        }
    }
    assert!(found >= 20, "only {found} origins near the plane");
}

/// `2^k` as a factor, for `|k| <= 2046`.
fn pow2(k: i32) -> f64 {
    2f64.powi(k / 2) * 2f64.powi(k - k / 2)
}

/// Scales for the watertight tests: from where vertex coordinates are
/// near `2^-1000` to where an origin's coordinates (up to 10 in the tiled
/// mesh's rays) approach `f64::MAX`.
const SCALES: [i32; 11] = [0, -1000, -800, -600, -400, 400, 600, 800, 1000, 1018, 1020];

/// Rays aimed at the interior edges and vertices of a tiled height field,
/// the whole configuration scaled by `2^k` (exactly, where it stays normal;
/// otherwise it is another valid case, which the oracle judges as it is):
/// the exact variant hits exactly the triangles the oracle hits, and the
/// watertight and the exact variant hit at least one triangle of the mesh
/// for every ray that passes through the surface there (its exact line
/// meets the triangles around the target from the front; a ray that only
/// touches a ridge may pass over it within rounding).
fn shared_edges_hold_at(k: i32) {
    let mut rng = SplitMix64::new(7);
    let mesh = TiledMesh::new(&mut rng, 6);
    let (edges, inner) = (mesh.interior_edges(), mesh.interior_vertices());
    let s = pow2(k);
    let vertices = |t: usize| mesh.triangle(t).map(|p| p * s);
    let tris: Vec<Triangle> = (0..mesh.triangles.len())
        .map(|t| {
            let v = vertices(t);
            Triangle::new(v[0], v[1], v[2]).unwrap()
        })
        .collect();
    let (mut double_hits, mut crossing) = (0, 0);
    for _ in 0..3000 {
        let (o, d, around) = mesh.shared_edge_ray(&mut rng, &edges, &inner);
        let (o, d) = (o * s, d * s);
        let ray = Ray::new(o, d).unwrap();
        let mut exact_hits = 0;
        let mut watertight_hits = 0;
        for (t, tri) in tris.iter().enumerate() {
            let case = (o, d, vertices(t));
            let want = exact_crossing(&case)
                .is_some_and(|(num, den)| oracle::ratio_in(&num, &den, 0.0, f64::MAX));
            let got = tri.cast_exact(&ray, Interval::FORWARD).is_some();
            assert_eq!(got, want, "2^{k}: triangle {t}, ray {o:?} {d:?}");
            exact_hits += got as u32;
            watertight_hits += tri.cast_watertight(&ray, Interval::FORWARD).is_some() as u32;
        }
        let lines: Vec<_> = around
            .iter()
            .map(|&t| {
                let v = vertices(t).map(|p| p.to_array());
                oracle::line_triangle(o.to_array(), d.to_array(), v)
            })
            .collect();
        let meets = lines.iter().any(|l| l.t.is_some());
        if meets && lines.iter().all(|l| l.t.is_none() || l.front) {
            crossing += 1;
            assert!(
                exact_hits >= 1 && watertight_hits >= 1,
                "2^{k}: slipped through: {o:?} {d:?} ({exact_hits} {watertight_hits})"
            );
        }
        double_hits += (exact_hits >= 2) as u32;
    }
    // Nearly every ray passes through the surface at its target.
    assert!(crossing > 2500, "2^{k}: {crossing}");
    // The aim is close enough that rays do meet shared edges exactly (a hit
    // on both triangles): otherwise the test would not test edges.
    assert!(double_hits > 0, "2^{k}");
}

#[test]
fn no_ray_slips_through_shared_edges() {
    for k in SCALES {
        shared_edges_hold_at(k);
    }
}

/// The same on a closed mesh, an octahedron scaled by `2^k`: rays from
/// outside through its edges and vertices into its interior hit at least
/// two faces (in and out). Origins lie up to 3.9 from the centre on an
/// axis: at `2^1022`, the difference of an origin and the vertex on the
/// far side (up to 4.9 times `2^1022`) overflows. Returns how many rays met such
/// a difference.
fn octahedron_holds_at(k: i32) -> usize {
    let s = pow2(k);
    let p = [
        DVec3::X,
        DVec3::Y,
        -DVec3::X,
        -DVec3::Y,
        DVec3::Z * 1.3,
        -DVec3::Z * 0.7,
    ];
    let faces: Vec<Triangle> = (0..4)
        .flat_map(|i| {
            let (a, b) = (p[i] * s, p[(i + 1) % 4] * s);
            [
                Triangle::new(a, b, p[4] * s).unwrap(),
                Triangle::new(b, a, p[5] * s).unwrap(),
            ]
        })
        .collect();
    let mut rng = SplitMix64::new(11);
    let mut overflows = 0;
    for _ in 0..5000 {
        let (i, f) = ((rng.next_u64() % 4) as usize, rng.next_f64());
        let apex = if rng.next_u64() & 1 == 0 { p[4] } else { p[5] };
        // A point on an edge (rounded): around the equator or up to an apex.
        let target = match rng.next_u64() % 3 {
            0 => p[i] + (p[(i + 1) % 4] - p[i]) * f,
            1 => p[i] + (apex - p[i]) * f,
            _ => p[i],
        };
        // From outside, through the edge point towards a point inside: the
        // line crosses the interior, so it meets at least two faces (a line
        // through an edge point at random could only touch the edge).
        let inner = DVec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 0.4 - 0.2;
        // Up to 3.9 from the centre on some axis (below `2^1024` at `2^1022`).
        let out = target - inner;
        let reach = (3.9 - target.abs().max_element()) / out.abs().max_element();
        let o = target + out * (0.05 + (reach - 0.05) * rng.next_f64());
        let ray = Ray::new(o * s, (target - o) * s).unwrap();
        overflows += p.iter().any(|&v| !(v * s - o * s).is_finite()) as usize;
        let line = Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap();
        let count = |f: &dyn Fn(&Triangle) -> bool| faces.iter().filter(|t| f(t)).count();
        let exact = count(&|t| t.cast_exact(&ray, line).is_some());
        let watertight = count(&|t| t.cast_watertight(&ray, line).is_some());
        assert!(
            exact >= 2 && watertight >= 2,
            "2^{k}: {o:?} {target:?}: {exact} {watertight}"
        );
    }
    overflows
}

#[test]
fn closed_octahedron_is_watertight() {
    for k in SCALES {
        octahedron_holds_at(k);
    }
    assert!(octahedron_holds_at(1022) > 100);
}

#[test]
fn degenerate_triangles_and_coplanar_rays_miss() {
    let line = Triangle::new([0.0; 3], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]).unwrap();
    let point = Triangle::new([1.0; 3], [1.0; 3], [1.0; 3]).unwrap();
    let ray = Ray::new([0.5, 0.0, 1.0], [0.0, 1.0, -0.5]).unwrap();
    // Exactly collinear (doubling is exact) but with rounded differences:
    // no variant may hit it, whatever its rounding says.
    let p = DVec3::new(0.1, 0.3, 0.7);
    let thin = Triangle::new(p, p * 2.0, p * 4.0).unwrap();
    let through = Ray::new(
        [0.3, 0.0, 0.0],
        DVec3::new(0.3, 0.9, 2.1) - DVec3::new(0.3, 0.0, 0.0),
    )
    .unwrap();
    for (tri, ray) in [(line, ray), (point, ray), (thin, through)] {
        assert!(tri.is_degenerate());
        let all = Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap();
        assert!(tri.cast_exact(&ray, all).is_none());
        assert!(tri.cast_mt(&ray, all).is_none());
        assert!(tri.cast_watertight(&ray, all).is_none());
        assert!(tri.cast(&ray, all).is_none() && !tri.hits(&ray, all));
    }
    assert_eq!(line.normal(), DVec3::ZERO);
    assert_eq!(point.normal(), DVec3::ZERO);
    let tri = Triangle::new([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    assert!(!tri.is_degenerate());
    // In the plane z = 0, through the triangle.
    let coplanar = Ray::new([-1.0, 0.25, 0.0], [1.0, 0.0, 0.0]).unwrap();
    assert!(tri.cast_exact(&coplanar, Interval::FORWARD).is_none());
    assert!(tri.cast_mt(&coplanar, Interval::FORWARD).is_none());
    assert!(tri.cast_watertight(&coplanar, Interval::FORWARD).is_none());
}

#[test]
fn hits_behind_the_origin_and_reported_fields() {
    let tri = Triangle::new([0.0; 3], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]).unwrap();
    let ray = Ray::new([0.5, 0.5, -1.0], [0.0, 0.0, -1.0]).unwrap();
    let all = Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap();
    for cast in [
        Triangle::cast_mt,
        Triangle::cast_watertight,
        Triangle::cast_exact,
    ] {
        assert!(cast(&tri, &ray, Interval::FORWARD).is_none());
        let hit = cast(&tri, &ray, all).unwrap();
        // Every value here is exact in f64, so all variants compute it.
        assert_eq!((hit.t, hit.u, hit.v), (-1.0, 0.25, 0.25));
        assert_eq!(hit.point(&tri), DVec3::new(0.5, 0.5, 0.0));
    }
    let hit = tri
        .cast(&Ray::new([0.5, 0.5, 3.0], [0.0, 0.0, -2.0]).unwrap(), all)
        .unwrap();
    assert_eq!(
        (hit.t, hit.point, hit.normal),
        (1.5, DVec3::new(0.5, 0.5, 0.0), DVec3::Z)
    );
    assert!(tri.hits(&Ray::new([0.5, 0.5, 3.0], [0.0, 0.0, -2.0]).unwrap(), all));
}

#[test]
fn extreme_magnitudes() {
    // Products of these coordinates underflow or overflow in f64; the exact
    // variant still answers exactly.
    for s in [1e-300, 1e-160, 1e160, 1e300, 5e-324] {
        let v = [DVec3::ZERO, DVec3::X * s, DVec3::Y * s];
        let inside = (DVec3::new(0.25 * s, 0.25 * s, s), DVec3::new(0.0, 0.0, -s));
        let outside = (DVec3::new(0.75 * s, 0.75 * s, s), DVec3::new(0.0, 0.0, -s));
        for (o, d) in [inside, outside] {
            check_exact(&(o, d, v), Interval::FORWARD).unwrap();
        }
    }
    // Mixed: a huge triangle, a tiny ray direction.
    let v = [
        DVec3::new(-1e300, -1e300, 1.0),
        DVec3::new(1e300, -1e300, 1.0),
        DVec3::new(0.0, 1e300, 1.0),
    ];
    check_exact(
        &(DVec3::ZERO, DVec3::new(1e-300, 0.0, 1e-310), v),
        Interval::FORWARD,
    )
    .unwrap();
    check_exact(
        &(DVec3::ZERO, DVec3::new(0.0, 0.0, 5e-324), v),
        Interval::FORWARD,
    )
    .unwrap();
}

#[test]
fn triangle_validation() {
    use exactray::InputError;
    assert_eq!(
        Triangle::new([0.0; 3], [0.0; 3], [f64::INFINITY, 0.0, 0.0]).unwrap_err(),
        InputError::NonFinite { argument: "v2" }
    );
    assert!(Triangle::new([0.0; 3], [0.0; 3], [f64::MAX; 3]).is_ok());
    // The normal of a huge triangle does not overflow.
    let big = Triangle::new(
        [-f64::MAX, 0.0, 0.0],
        [f64::MAX, 0.0, 0.0],
        [0.0, f64::MAX, 0.0],
    )
    .unwrap();
    assert_eq!(big.normal(), DVec3::Z);
}

/// A fuzzer finding: subnormal, tiny and huge coordinates in one
/// case, and an exact `t` (about 2^1177) beyond `f64`'s range. The exact
/// crossing lies outside the triangle (u about -834): a miss, which
/// `cast_exact` once reported as a hit at `t = inf`.
#[test]
fn mixed_subnormal_and_huge_coordinates() {
    let (o, d, v) =
        exactray::testing::ray_triangle_finding(0).expect("the recorded fuzzer finding");
    for range in [
        Interval::FORWARD,
        Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap(),
    ] {
        check_exact(&(o, d, v), range).unwrap();
    }
}

/// A fuzzer finding against the tests' own oracle (the same runs): the
/// exact `t` is `-f64::MAX (1 + 5e-100 u)`, beyond `f64`'s range by far less
/// than half an ulp, so its correct rounding is `-f64::MAX` and a hit there
/// is right; the oracle once demanded a miss for every `t` beyond the range.
#[test]
fn crossing_just_beyond_the_largest_f64() {
    let o = DVec3::new(
        9.124881235244392e192,
        -1.3804585926447793e-306,
        9.916182190166406e-309,
    );
    let d = DVec3::new(1.0, 2.427115224027714e-285, 1.352488177583646e-257);
    let v = [
        DVec3::new(
            2.6096653751819e-310,
            -1.9738789546379644e238,
            1.06236848274838e-309,
        ),
        DVec3::new(6.1976e-320, 1.6296927674613e-311, -1.7976931348622648e308),
        DVec3::new(-f64::MAX, 8.48947806985973e-306, 0.0),
    ];
    let (num, den) = exact_crossing(&(o, d, v)).expect("the line crosses the plane");
    let whole = Interval::new(f64::NEG_INFINITY, f64::INFINITY).unwrap();
    assert_eq!(
        oracle::hit_policy(&num, &den, whole.min(), whole.max(), 4),
        None
    );
    check_exact(&(o, d, v), whole).unwrap();
    let hit = Triangle::new(v[0], v[1], v[2])
        .unwrap()
        .cast_exact(&Ray::new(o, d).unwrap(), whole);
    assert_eq!(hit.map(|h| h.t), Some(-f64::MAX));
}
