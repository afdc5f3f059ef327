use super::super::{BvhBuilder, Item};
use super::*;
use alloc::vec::Vec;

/// A wide node with `[min, max]` in lane `at` and every other lane
/// empty, in the identity frame (`f32` bounds equal to the world's).
fn node(at: usize, min: [f32; 3], max: [f32; 3]) -> WideNode {
    let mut n = WideNode::EMPTY;
    for k in 0..3 {
        n.min[k][at] = min[k];
        n.max[k][at] = max[k];
    }
    n.count[at] = 1;
    n
}

const IDENTITY: Frame = Frame {
    centre: DVec3::ZERO,
    exp: 0,
};

/// Whether the frame test (`None` where it does not run) and the world
/// test keep lane `l` of `node` for the segment `[min, max]` of the
/// ray `o + t d`.
fn tests<const E: u32>(
    o: [f64; 3],
    d: [f64; 3],
    node: &WideNode,
    l: usize,
    min: f64,
    max: f64,
) -> (Option<bool>, bool) {
    let ray = Ray::new(o, d).unwrap();
    let fast = FrameRay::<E>::of(&ray, &IDENTITY)
        .map(|r| r.lanes(node, r.param(min, false), r.param(max, true)).1 & (1 << l) != 0);
    let r = BoxRay::<E>::of(&ray);
    let world = if r.divide {
        World::<E, true> {
            ray: r,
            frame: &IDENTITY,
        }
        .lanes(node, min, max)
    } else {
        World::<E, false> {
            ray: r,
            frame: &IDENTITY,
        }
        .lanes(node, min, max)
    };
    (fast, world.1 & (1 << l) != 0)
}

/// Whether both tests keep lane `l` (the frame test where it runs),
/// and whether both cull it.
fn kept_culled<const E: u32>(
    o: [f64; 3],
    d: [f64; 3],
    n: &WideNode,
    l: usize,
    (min, max): (f64, f64),
) -> (bool, bool) {
    let (fast, world) = tests::<E>(o, d, n, l, min, max);
    (
        fast.unwrap_or(true) && world,
        !fast.unwrap_or(false) && !world,
    )
}

/// Rays that touch the box only on a face, an edge or a corner, with
/// zero (and negative zero) direction coordinates whose slabs compute
/// `0 * inf = NaN`, and directions whose reciprocals overflow or are
/// subnormal (the dividing path), are kept in whichever lane the box
/// lies; rays beside the box, or whose range ends before it, are
/// culled; and the empty lanes beside it are culled for every ray,
/// range and path.
#[test]
fn slab_test_keeps_every_touching_ray() {
    let tiny = f64::from_bits(3);
    let huge = f64::MAX / 2.0;
    let keeps = [
        // Along a face, an edge and a corner line, axis-aligned.
        ([0.0, 0.5, -1.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, -1.0], [0.0, -0.0, 1.0]),
        ([1.0, 1.0, 2.0], [-0.0, 0.0, -1.0]),
        ([1.0, 1.0, 1.0], [-0.0, -0.0, -1.0]),
        // Grazing a face with a subnormal coordinate (1/d overflows).
        ([0.5, 1.0, -1.0], [0.0, -tiny, 1.0]),
        // A huge coordinate (1/d subnormal): enters at t = 1 / huge.
        ([-1.0, 0.5, 0.5], [huge, 0.0, 0.0]),
        // Touching the corner (1, 1, 1) exactly at t = 1.
        ([2.0, 2.0, 0.0], [-1.0, -1.0, 1.0]),
        // Huge negative, subnormal negative, and an origin inside.
        ([2.0, 0.5, 0.5], [-huge, -0.0, 0.0]),
        ([0.5, 0.0, 0.5], [-0.0, -tiny, -0.0]),
        ([0.5, 0.5, 0.5], [-1.0, 0.0, -0.0]),
    ];
    let culls = [
        ([1.0 + 1e-6, 0.5, -1.0], [0.0, 0.0, 1.0], f64::INFINITY),
        ([0.5, 0.5, -1.0], [0.0, 0.0, -1.0], f64::INFINITY),
        ([0.5, 0.5, -1.0], [0.0, 0.0, 1.0], 0.5),
        ([2.0, 2.0, 0.0], [-1.0, -1.0, 1.0], 0.99),
    ];
    for at in 0..WIDTH {
        let unit = node(at, [0.0; 3], [1.0; 3]);
        let others = (0..WIDTH).filter(|&l| l != at);
        for (o, d) in keeps {
            assert!(
                kept_culled::<0>(o, d, &unit, at, (0.0, f64::INFINITY)).0,
                "{o:?} {d:?}"
            );
            assert!(
                kept_culled::<1>(o, d, &unit, at, (0.0, f64::INFINITY)).0,
                "{o:?} {d:?}"
            );
            for (min, max) in [(0.0, f64::INFINITY), (f64::NEG_INFINITY, f64::INFINITY)] {
                for l in others.clone() {
                    assert!(
                        kept_culled::<0>(o, d, &unit, l, (min, max)).1,
                        "{o:?} {d:?} lane {l}"
                    );
                    assert!(
                        kept_culled::<1>(o, d, &unit, l, (min, max)).1,
                        "{o:?} {d:?} lane {l}"
                    );
                }
            }
        }
        for (o, d, max) in culls {
            assert!(
                kept_culled::<0>(o, d, &unit, at, (0.0, max)).1,
                "{o:?} {d:?}"
            );
        }
        // The touching corner ray with its range ending exactly at t = 1.
        assert!(kept_culled::<0>([2.0, 2.0, 0.0], [-1.0, -1.0, 1.0], &unit, at, (0.0, 1.0)).0);
    }
    // Every lane of a node of four touching boxes at once.
    let mut four = WideNode::EMPTY;
    for l in 0..WIDTH {
        for k in 0..3 {
            four.min[k][l] = l as f32;
            four.max[k][l] = l as f32 + 1.0;
        }
    }
    // Along the diagonal, through each box's corners.
    let diagonal = Ray::new([0.0; 3], [1.0; 3]).unwrap();
    let r = FrameRay::<0>::of(&diagonal, &IDENTITY).unwrap();
    let (lower, mask) = r.lanes(&four, 0.0, f32::INFINITY);
    assert_eq!(mask, 0xff);
    for (l, &entry) in lower.iter().enumerate() {
        assert!(
            kept_culled::<0>([0.0; 3], [1.0; 3], &four, l, (0.0, f64::INFINITY)).0,
            "lane {l}"
        );
        // `tau = t 2^p`: the direction `(1, 1, 1)` scaled by 2^-1.
        assert!(entry <= 2.0 * l as f32, "lane {l}");
    }
    // Which path each direction takes.
    let divides = |d: [f64; 3]| BoxRay::<0>::of(&Ray::new([0.0; 3], d).unwrap()).divide;
    assert!(divides([0.0, -tiny, 1.0]) && divides([huge, 0.0, 0.0]));
    assert!(!divides([0.0, -0.0, 1.0]) && !divides([-1.0, 2.0, 1e300]));
    let framed =
        |o: [f64; 3], d: [f64; 3]| FrameRay::<0>::of(&Ray::new(o, d).unwrap(), &IDENTITY).is_some();
    assert!(framed([0.0; 3], [0.0, -0.0, 1.0]) && framed([1e14, 0.0, 0.0], [huge, 0.0, 1e-300]));
    assert!(!framed([0.0; 3], [1e-15, 0.0, 1.0]) && !framed([1e15, 0.0, 0.0], [0.0, 0.0, 1.0]));
}

/// The AVX2 and SSE2 frame tests compute the portable one's entries
/// and mask, bit for bit: random boxes (empty lanes among them) and rays with
/// zero, negative-zero and tiny direction coordinates.
#[cfg(all(feature = "std", target_arch = "x86_64", not(target_feature = "avx2")))]
#[test]
fn avx2_lanes_equal_the_portable_ones() {
    if !std::is_x86_feature_detected!("avx2") {
        return;
    }
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let mut f = |r: i64| rng.int(r) as f32 / 8.0;
    for i in 0..20_000 {
        let mut node = WideNode::EMPTY;
        for l in 0..WIDTH - (i % 3) {
            for k in 0..3 {
                let (a, b) = (f(16), f(16));
                (node.min[k][l], node.max[k][l]) = (a.min(b), a.max(b));
            }
        }
        let o = [0, 1, 2].map(|_| f64::from(f(24)));
        let d = [0, 1, 2].map(|k| match (i + k) % 5 {
            0 => 0.0,
            1 => -0.0,
            _ => f64::from(f(8)) + 1e-3,
        });
        let Ok(ray) = Ray::new(o, d) else { continue };
        let Some(r) = FrameRay::<0>::of(&ray, &IDENTITY) else {
            continue;
        };
        let (lo, hi) = (r.param(0.0, false), r.param(f64::from(f(64)).abs(), true));
        let (a, ma) = r.portable_lanes(&node, lo, hi);
        // SAFETY: the CPU supports AVX2, checked above.
        let (b, mb) = unsafe { avx2_lanes(&r, &node, lo, hi) };
        // SAFETY: every x86_64 CPU supports SSE2.
        let (c, mc) = unsafe { sse2_lanes(&r, &node, lo, hi) };
        assert_eq!((ma, ma), (mb, mc), "{i}");
        assert_eq!(a.map(f32::to_bits), b.map(f32::to_bits), "{i}");
        assert_eq!(a.map(f32::to_bits), c.map(f32::to_bits), "{i}");
    }
}

/// A small deterministic generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    /// An integer in `[-r, r]`.
    fn int(&mut self, r: i64) -> i64 {
        (self.next() % (2 * r as u64 + 1)) as i64 - r
    }
}

/// A rational `num / den`, `den > 0`.
#[derive(Clone, Copy)]
struct Q(i128, i128);

impl Q {
    fn le(self, o: Q) -> bool {
        self.0 * o.1 <= o.0 * self.1
    }
}

/// Whether the exact segment `o + t d`, `t` in `[0, max]` (`None`: no
/// end), meets the closed box `[lo, hi]`; every coordinate an integer,
/// so the slab parameters are exact rationals.
fn exact_meets(
    lo: [i128; 3],
    hi: [i128; 3],
    o: [i128; 3],
    d: [i128; 3],
    max: Option<i128>,
) -> bool {
    let mut near = Q(0, 1);
    let mut far = max.map(|m| Q(m, 1));
    for k in 0..3 {
        if d[k] == 0 {
            if o[k] < lo[k] || o[k] > hi[k] {
                return false;
            }
            continue;
        }
        let (a, b) = (lo[k] - o[k], hi[k] - o[k]);
        let (enter, exit) = if d[k] > 0 {
            (Q(a, d[k]), Q(b, d[k]))
        } else {
            (Q(-b, -d[k]), Q(-a, -d[k]))
        };
        if near.le(enter) {
            near = enter;
        }
        if far.is_none_or(|f| exit.le(f)) {
            far = Some(exit);
        }
    }
    far.is_none_or(|f| near.le(f))
}

/// Records the leaves the walk reaches, never stopping it.
struct Leaves {
    max: f64,
    seen: Vec<u32>,
}

impl Visitor for Leaves {
    fn max(&self) -> f64 {
        self.max
    }

    fn leaf(&mut self, triangles: &[u32]) -> bool {
        self.seen.extend_from_slice(triangles);
        false
    }
}

/// The 8-wide walk reaches every leaf whose box the exact segment
/// meets: small integer triangles (so that boxes touch rays exactly
/// on faces, edges and corners) and integer rays (zero and `-0.0`
/// components among them), ranges with and without an end, against
/// exact rational slab tests of every leaf lane, with both builders
/// and the segment walk's extra rounding; and the same with every
/// coordinate of the mesh and the rays scaled by `2^k`, from `2^-1000`
/// to `2^1000` (the slab parameters, and so the exact answers, are
/// those of the integers).
#[test]
fn wide_walk_reaches_every_leaf_the_exact_segment_meets() {
    for k in [0, -1000, -600, -300, 300, 600, 1000] {
        walk_reaches_every_leaf_at(k);
    }
}

fn walk_reaches_every_leaf_at(k: i32) {
    let s = crate::arith::exponent::scale_pow2(1.0, k);
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut vertices = Vec::new();
    let mut integers = Vec::new();
    let mut triangles = Vec::new();
    for k in 0..600u32 {
        let base = [rng.int(12), rng.int(12), rng.int(12)];
        for _ in 0..3 {
            let v = [0, 1, 2].map(|i| base[i] + rng.int(2));
            vertices.push(v.map(|c| c as f64 * s));
            integers.push(v.map(i128::from));
        }
        triangles.push([3 * k, 3 * k + 1, 3 * k + 2]);
    }
    #[cfg_attr(not(feature = "ploc"), allow(unused_mut))]
    let mut builders = alloc::vec![BvhBuilder::BinnedSah];
    #[cfg(feature = "ploc")]
    builders.push(BvhBuilder::Ploc(super::super::PlocQuality::Fast));
    for builder in builders {
        let items = triangles
            .iter()
            .map(|t: &[u32; 3]| {
                let [a, b, c] = t.map(|i| DVec3::from(vertices[i as usize]));
                Item {
                    min: a.min(b).min(c),
                    max: a.max(b).max(c),
                    index: t[0] / 3,
                }
            })
            .collect();
        let bvh = &BoxBvh::build(items, builder);
        assert!(bvh.nodes.len() > 10);
        // Each leaf lane with the exact box of its triangles, in
        // integers: what its `f32` box stands for.
        let mut leaves = Vec::new();
        for n in &bvh.nodes {
            for l in 0..WIDTH {
                if n.count[l] > 0 {
                    let (start, count) = (n.link[l] as usize, n.count[l] as usize);
                    let (mut lo, mut hi) = ([i128::MAX; 3], [i128::MIN; 3]);
                    for &t in &bvh.order[start..start + count] {
                        for v in &integers[3 * t as usize..3 * t as usize + 3] {
                            for k in 0..3 {
                                lo[k] = lo[k].min(v[k]);
                                hi[k] = hi[k].max(v[k]);
                            }
                        }
                    }
                    leaves.push((lo, hi, start, count));
                }
            }
        }
        let (mut kept, mut world) = (0, 0);
        for i in 0..3000 {
            let mut o = [rng.int(16), rng.int(16), rng.int(16)];
            let mut d = [rng.int(3), rng.int(3), rng.int(3)];
            // (Scaled by 2^1000, 2^55 overflows: none such there.)
            let far_rays = k <= 960;
            if far_rays && i % 5 == 3 {
                // A direction coordinate 2^-55 of the largest: the
                // world test.
                d[0] = 1 << 55;
            } else if far_rays && i % 5 == 4 {
                // From 2^54 away, towards a point by the mesh (a
                // multiple of 4, so that every coordinate of the
                // direction is an `f64`): the world test, through the
                // mesh at t near 1.
                o = [0, 1, 2].map(|_| 4 * rng.int(4));
                let far = [rng.int(1), rng.int(1), 1].map(|c| c << 54);
                d = [0, 1, 2].map(|k| o[k] - far[k]);
                o = far;
            }
            if d == [0; 3] {
                d[2] = 1;
            }
            let df = d.map(|c| {
                if c == 0 && i % 2 == 0 {
                    -0.0
                } else {
                    c as f64 * s
                }
            });
            let ray = Ray::new(o.map(|c| c as f64 * s), df).unwrap();
            let max = (i % 3 != 0).then(|| rng.int(20).abs());
            let range = Interval::new(0.0, max.map_or(f64::INFINITY, |m| m as f64)).unwrap();
            let mut ours = Leaves {
                max: range.max(),
                seen: Vec::new(),
            };
            world += usize::from(FrameRay::<0>::of(&ray, &bvh.frame).is_none());
            walk::<_, 0>(bvh, &ray, range, &mut ours);
            let mut segment = Leaves {
                max: range.max(),
                seen: Vec::new(),
            };
            walk::<_, 1>(bvh, &ray, range, &mut segment);
            // The frame test compiled without AVX2 as well (`walk`
            // takes the AVX2 copy where the CPU has it).
            let mut portable = Leaves {
                max: range.max(),
                seen: Vec::new(),
            };
            if let Some(r) = FrameRay::<0>::of(&ray, &bvh.frame) {
                walk_in(bvh, &r, range, &mut portable);
            } else {
                walk::<_, 0>(bvh, &ray, range, &mut portable);
            }
            let (o, d) = (o.map(i128::from), d.map(i128::from));
            for &(lo, hi, start, count) in &leaves {
                if exact_meets(lo, hi, o, d, max.map(i128::from)) {
                    kept += 1;
                    for t in &bvh.order[start..start + count] {
                        assert!(ours.seen.contains(t), "ray {i}: leaf at {start} culled");
                        assert!(portable.seen.contains(t), "ray {i}: leaf culled");
                        assert!(
                            segment.seen.contains(t),
                            "segment {i}: leaf at {start} culled"
                        );
                    }
                }
            }
        }
        assert!(
            kept > 3000,
            "{kept} leaves met: the rays miss too often to test"
        );
        // Both tests ran: two rays in five take the world test.
        assert!(
            (1000..1500).contains(&world) || k > 960,
            "{world} world tests"
        );
    }
}
