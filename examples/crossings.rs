//! A client of the predicates on constructed points: every crossing of a
//! few thousand segments in the plane, sorted along each segment, as a
//! segment arrangement or a polygon clipper does before it splits the
//! segments.
//!
//! Twice: with the crossings kept as [`Ssi`] points and sorted with
//! `cmp_along_line_2d` (exact), and with the crossings constructed in
//! `f64` and sorted by their rounded parameter along the segment (what
//! code does without them). Both orders are then checked against exact
//! rationals (`exactray_oracle::implicit_oracle`): a misordering is two
//! neighbours in the wrong order; a missed coincidence two neighbours that
//! are the same exact point but got different parameters; a false one two
//! neighbours with the same parameter that are different points.
//!
//! The segments: uniform ones, pencils of segments through one dyadic point
//! (their crossings coincide exactly), pencils through a point that their
//! rounded ends miss by an ulp or so (crossings a few ulps apart), and
//! nearly parallel pairs.
//!
//! ```text
//! cargo run --release --example crossings [-- SEGMENTS]
//! ```

use core::cmp::Ordering;
use exactray::predicates::{Ssi, cmp_along_line_2d, orient2d};
use exactray::testing::SplitMix64;
use exactray_oracle::implicit_oracle::{self as oracle, Pt2};
use glam::DVec2;
use std::time::Instant;

/// A crossing on a segment: the other segment's index, the exact point and
/// the rounded parameter along this segment.
struct Crossing {
    other: usize,
    exact: Ssi,
    t: f64,
}

fn uniform(rng: &mut SplitMix64) -> f64 {
    2.0 * ((rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64) - 1.0
}

/// The segments: a quarter each uniform, exact pencils, near pencils and
/// nearly parallel pairs.
fn segments(n: usize, rng: &mut SplitMix64) -> Vec<[DVec2; 2]> {
    let mut out = Vec::with_capacity(n);
    let point = |rng: &mut SplitMix64| DVec2::new(uniform(rng), uniform(rng));
    let dyadic = |rng: &mut SplitMix64| {
        DVec2::new(
            (rng.next_u64() % 128) as f64 / 64.0 - 1.0,
            (rng.next_u64() % 128) as f64 / 64.0 - 1.0,
        )
    };
    while out.len() < n {
        match out.len() * 4 / n {
            0 => out.push([point(rng), point(rng)]),
            1 => {
                // Eight segments through one dyadic point: c + d and c - m d,
                // all dyadic, so their lines meet at c exactly.
                let c = dyadic(rng) * 0.5;
                for _ in 0..8 {
                    let d = dyadic(rng) * 0.5;
                    let m = (1 + rng.next_u64() % 4) as f64 / 2.0;
                    out.push([c + d, c - d * m]);
                }
            }
            2 => {
                // Eight segments through an arbitrary point, their ends
                // rounded: they pass it by an ulp or so.
                let c = point(rng) * 0.5;
                for _ in 0..8 {
                    let d = point(rng) * 0.5;
                    out.push([c + d, c - d * 0.7]);
                }
            }
            _ => {
                // Nearly parallel pairs, crossing at a shallow angle.
                let (p, d) = (point(rng), point(rng));
                let e = d + DVec2::new(uniform(rng), uniform(rng)) * 1e-9;
                out.push([p - d, p + d]);
                out.push([p - e * 0.9, p + e * 1.1]);
            }
        }
    }
    out.truncate(n);
    out
}

/// Whether the closed segments cross at one point (not collinear).
fn cross(s: &[DVec2; 2], t: &[DVec2; 2]) -> bool {
    let o = |a, b, c| orient2d(a, b, c).as_i8();
    let (d1, d2) = (o(s[0], s[1], t[0]), o(s[0], s[1], t[1]));
    let (d3, d4) = (o(t[0], t[1], s[0]), o(t[0], t[1], s[1]));
    !(d1 == 0 && d2 == 0) && d1 * d2 <= 0 && d3 * d4 <= 0
}

/// The rounded parameter of the crossing along `s`: `(r - p) x f / (q - p)
/// x f` for `s = [p, q]`, the other segment `[r, r + f]`.
fn rounded_t(s: &[DVec2; 2], t: &[DVec2; 2]) -> f64 {
    let (e, f) = (s[1] - s[0], t[1] - t[0]);
    (t[0] - s[0]).perp_dot(f) / e.perp_dot(f)
}

/// Misorderings, missed and false coincidences of the neighbours in
/// `order` along segment `s`, against the exact rationals; `same` is the
/// method's own verdict that two crossings are one point.
fn audit(
    s: &[DVec2; 2],
    order: &[&Crossing],
    segs: &[[DVec2; 2]],
    same: impl Fn(&Crossing, &Crossing) -> bool,
) -> [usize; 3] {
    let pt = |c: &Crossing| {
        let o = &segs[c.other];
        Pt2::Ssi([
            s[0].to_array(),
            s[1].to_array(),
            o[0].to_array(),
            o[1].to_array(),
        ])
    };
    let mut counts = [0; 3];
    for w in order.windows(2) {
        let exact = oracle::cmp_along2(s[0].to_array(), s[1].to_array(), pt(w[0]), pt(w[1]))
            .expect("crossings are points");
        match (exact, same(w[0], w[1])) {
            (Ordering::Greater, _) => counts[0] += 1,
            (Ordering::Equal, false) => counts[1] += 1,
            (Ordering::Less, true) => counts[2] += 1,
            _ => {}
        }
    }
    counts
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(2000);
    let mut rng = SplitMix64::new(2026);
    let segs = segments(n, &mut rng);

    let start = Instant::now();
    let mut on: Vec<Vec<Crossing>> = (0..n).map(|_| Vec::new()).collect();
    for i in 0..n {
        for j in i + 1..n {
            if !cross(&segs[i], &segs[j]) {
                continue;
            }
            for (a, b) in [(i, j), (j, i)] {
                let (s, t) = (&segs[a], &segs[b]);
                let Ok(exact) = Ssi::new(s[0], s[1], t[0], t[1]) else {
                    continue;
                };
                on[a].push(Crossing {
                    other: b,
                    exact,
                    t: rounded_t(s, t),
                });
            }
        }
    }
    let crossings: usize = on.iter().map(Vec::len).sum::<usize>() / 2;
    println!(
        "{n} segments, {crossings} crossings ({:.2} s to find them)",
        start.elapsed().as_secs_f64()
    );

    let mut exact_orders = Vec::with_capacity(n);
    let t = Instant::now();
    for (s, list) in segs.iter().zip(&on) {
        let mut order: Vec<&Crossing> = list.iter().collect();
        order.sort_by(|x, y| cmp_along_line_2d(s[0], s[1], &x.exact, &y.exact));
        exact_orders.push(order);
    }
    let exact_time = t.elapsed().as_secs_f64();
    let mut rounded_orders = Vec::with_capacity(n);
    let t = Instant::now();
    for list in &on {
        let mut order: Vec<&Crossing> = list.iter().collect();
        order.sort_by(|x, y| x.t.total_cmp(&y.t));
        rounded_orders.push(order);
    }
    let rounded_time = t.elapsed().as_secs_f64();

    // The exact order's ties are the exact coincidences: count them.
    let mut ties = 0;
    for (s, order) in segs.iter().zip(&exact_orders) {
        ties += order
            .windows(2)
            .filter(|w| cmp_along_line_2d(s[0], s[1], &w[0].exact, &w[1].exact) == Ordering::Equal)
            .count();
    }
    let mut e = [0; 3];
    let mut r = [0; 3];
    for (k, s) in segs.iter().enumerate() {
        let exact_same = |x: &Crossing, y: &Crossing| {
            cmp_along_line_2d(s[0], s[1], &x.exact, &y.exact) == Ordering::Equal
        };
        let rounded_same = |x: &Crossing, y: &Crossing| x.t == y.t;
        let (a, b) = (
            audit(s, &exact_orders[k], &segs, exact_same),
            audit(s, &rounded_orders[k], &segs, rounded_same),
        );
        for i in 0..3 {
            e[i] += a[i];
            r[i] += b[i];
        }
    }
    let entries = 2 * crossings;
    println!(
        "sorting {entries} crossings along their segments (pairs of neighbours checked against exact rationals):"
    );
    println!(
        "  method            ns/crossing  misordered  missed coincidences  false coincidences"
    );
    for (name, time, c) in [
        ("exact (Ssi)", exact_time, e),
        ("rounded f64", rounded_time, r),
    ] {
        println!(
            "  {name:<16}  {:>11.1}  {:>10}  {:>19}  {:>18}",
            time * 1e9 / entries as f64,
            c[0],
            c[1],
            c[2]
        );
    }
    println!("  exact ties (coinciding crossings next to each other): {ties}");
    assert_eq!(
        e, [0; 3],
        "the exact order and coincidences are never wrong"
    );
}
