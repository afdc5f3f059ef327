//! Triangle rasterization against an exact coverage oracle (num-bigint
//! orient2d at every pixel centre, with the top-left rule written out
//! independently), and the fill rule's promise: triangles sharing edges
//! cover each pixel of their union exactly once.

use exactray::InputError;
use exactray::raster::rasterize_triangle;
use exactray::testing::SplitMix64;
use exactray_oracle::oracle;
use proptest::prelude::*;

type P = [f64; 2];

/// Whether the centre `c` is covered by the triangle, exactly: inside all
/// three edges of the counterclockwise (orient2d > 0) order, or on an edge
/// that goes up the screen (y decreasing) or right along a horizontal.
fn oracle_covers(v: [P; 3], c: P) -> bool {
    let (a, b, d) = match oracle::orient2d(v[0], v[1], v[2]) {
        1 => (v[0], v[1], v[2]),
        -1 => (v[0], v[2], v[1]),
        _ => return false,
    };
    [(a, b), (b, d), (d, a)]
        .iter()
        .all(|&(p, q)| match oracle::orient2d(p, q, c) {
            1 => true,
            0 => q[1] < p[1] || (q[1] == p[1] && q[0] > p[0]),
            _ => false,
        })
}

/// Per-pixel coverage counts from the rasterizer.
fn counts(tris: &[[P; 3]], w: u32, h: u32) -> Vec<u32> {
    let mut c = vec![0u32; (w * h) as usize];
    for t in tris {
        let mut reported = 0;
        let mut last_row = None;
        let n = rasterize_triangle(t[0], t[1], t[2], w, h, |y, x0, x1| {
            assert!(x0 < x1 && x1 <= w && y < h);
            assert!(
                last_row.is_none_or(|r| r < y),
                "rows in increasing order, one span each"
            );
            last_row = Some(y);
            for x in x0..x1 {
                c[(y * w + x) as usize] += 1;
            }
            reported += (x1 - x0) as u64;
        })
        .unwrap();
        assert_eq!(n, reported);
    }
    c
}

/// A coordinate on the pixel-centre grid (so that centres fall exactly on
/// edges and vertices), on the pixel-corner grid, or anywhere.
fn coord(max: f64) -> impl Strategy<Value = f64> {
    prop_oneof![
        (0..(max as i64)).prop_map(|k| k as f64 + 0.5),
        (0..(max as i64)).prop_map(|k| k as f64),
        (0.0..max),
        (-2.0 * max..3.0 * max),
    ]
}

fn point(max: f64) -> impl Strategy<Value = P> {
    (coord(max), coord(max)).prop_map(|(x, y)| [x, y])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Coverage is exactly the oracle's, pixel by pixel.
    #[test]
    fn matches_exact_coverage(a in point(24.0), b in point(24.0), c in point(24.0)) {
        let (w, h) = (24, 20);
        let got = counts(&[[a, b, c]], w, h);
        for y in 0..h {
            for x in 0..w {
                let want = oracle_covers([a, b, c], [x as f64 + 0.5, y as f64 + 0.5]);
                prop_assert_eq!(got[(y * w + x) as usize] == 1, want, "pixel {} {}", x, y);
            }
        }
    }

    /// Two triangles sharing an edge (a quadrilateral split by a diagonal,
    /// convex or not, the diagonal inside or not): no pixel twice, and
    /// together exactly the pixels of either.
    #[test]
    fn shared_edge_covered_once(a in point(16.0), b in point(16.0), c in point(16.0), d in point(16.0)) {
        let (w, h) = (16, 16);
        let both = counts(&[[a, b, c], [a, c, d]], w, h);
        let each = [counts(&[[a, b, c]], w, h), counts(&[[a, c, d]], w, h)];
        for i in 0..(w * h) as usize {
            let (first, second) = (each[0][i], each[1][i]);
            prop_assert_eq!(both[i], first + second);
            // Opposite sides of the diagonal (a convex split): never both.
            if oracle::orient2d(a, c, b) * oracle::orient2d(a, c, d) < 0 {
                prop_assert!(both[i] <= 1, "pixel {} twice", i);
            }
        }
    }
}

/// A jittered grid of quads on the pixel-centre lattice and off it, split
/// into triangles: every pixel of the covered rectangle exactly once.
#[test]
fn tiled_mesh_covers_each_pixel_once() {
    let mut rng = SplitMix64::new(5);
    for trial in 0..20 {
        let (n, cell) = (6usize, 5.0);
        let jitter = |rng: &mut SplitMix64, k: usize| {
            if k == 0 || k == n {
                0.0
            } else if trial % 2 == 0 {
                // Half-pixel steps: vertices on pixel centres and corners.
                ((rng.next_u64() % 5) as f64 - 2.0) * 0.5
            } else {
                rng.next_f64() * 3.0 - 1.5
            }
        };
        let mut v = vec![[0.0; 2]; (n + 1) * (n + 1)];
        for j in 0..=n {
            for i in 0..=n {
                v[j * (n + 1) + i] = [
                    i as f64 * cell + jitter(&mut rng, i),
                    j as f64 * cell + jitter(&mut rng, j),
                ];
            }
        }
        let at = |i: usize, j: usize| v[j * (n + 1) + i];
        let mut tris = Vec::new();
        for j in 0..n {
            for i in 0..n {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                if (i + j + trial) % 2 == 0 {
                    tris.extend([[a, b, c], [a, c, d]]);
                } else {
                    tris.extend([[a, b, d], [b, c, d]]);
                }
            }
        }
        let side = (n as f64 * cell) as u32;
        let c = counts(&tris, side + 4, side + 4);
        for y in 0..side + 4 {
            for x in 0..side + 4 {
                let want = u32::from(x < side && y < side);
                assert_eq!(
                    c[(y * (side + 4) + x) as usize],
                    want,
                    "trial {trial}: pixel {x} {y}"
                );
            }
        }
    }
}

#[test]
fn degenerate_clipped_and_extreme() {
    let none = |t: [P; 3]| rasterize_triangle(t[0], t[1], t[2], 8, 8, |_, _, _| panic!("no pixel"));
    assert_eq!(none([[0.0, 0.0], [4.0, 4.0], [8.0, 8.0]]), Ok(0));
    assert_eq!(none([[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]]), Ok(0));
    // Entirely off the grid.
    assert_eq!(none([[-9.0, -9.0], [-1.0, -9.0], [-9.0, -1.0]]), Ok(0));
    assert_eq!(
        rasterize_triangle([0.0, 0.0], [f64::NAN, 0.0], [1.0, 1.0], 8, 8, |_, _, _| {}),
        Err(InputError::NonFinite { argument: "v1" })
    );
    // Vertices near the largest floats: the edge functions overflow in f64;
    // coverage is still exact (the whole 8 x 8 grid, or its half).
    let m = f64::MAX;
    assert_eq!(
        rasterize_triangle([-m, -m], [m, -m], [0.0, m], 8, 8, |_, _, _| {}),
        Ok(64)
    );
    let diagonal = rasterize_triangle([-m, -m], [m, m], [-m, m], 8, 8, |_, _, _| {});
    let want: u64 = (0..8u64).map(|y| y + 1).sum();
    // The centres on y = x lie on the edge from (-m, -m) to (m, m), which
    // goes down the screen with the triangle on its left: not owned.
    assert_eq!(diagonal, Ok(want - 8));
}
