//! The conservative walk: a slab test that never culls a box the ray's
//! exact segment meets, run on the four children of a wide node at once,
//! and the stack walk every query shares.
//!
//! # The slab test
//! For axis `k` the ray `o + t d` is inside the slab `[b_lo, b_hi]` for
//! `t` between `(b_lo - o_k) / d_k` and `(b_hi - o_k) / d_k`. Each is
//! computed as `fl(fl(b - o_k) * fl(1 / d_k))`: three roundings, so the
//! computed `t'` is `t (1 + θ)` with `|θ| <= gamma(3)` (Higham, Lemma
//! 3.1), and `|t - t'| <= gamma(3) / (1 - gamma(3)) |t'| <= gamma(4) |t'|`,
//! plus at most `2^-1075` where the product underflows. Where `1 / d_k`
//! is not a normal number (`|d_k| > 2^1022`, or `|d_k| < 2^-1024` where it
//! overflows), every slab of the ray is computed as `fl(fl(b - o_k) /
//! d_k)` instead: two roundings, inside the same bound.
//!
//! The entry `t_near = max(range.min, lo_x, lo_y, lo_z)` and exit `t_far =
//! min(range.max, hi_x, hi_y, hi_z)` are then widened, `t_near -
//! (W |t_near| + S)` and `t_far + (W |t_far| + S)`, and the box is kept
//! when the first is at most the second. `x - c |x|` is increasing in `x`
//! (for `c < 1`), so widening the maximum is the maximum of the widened
//! terms, each of which is below its exact value: the widened entry is
//! below the exact entry, the widened exit above the exact exit, and a box
//! whose exact slabs meet the range is never culled. `W = gamma(7)`
//! covers `gamma(4)` and the three roundings of the widening itself
//! (each within `u` of `|t'|`); `S = 2^-1070` covers the underflows.
//! This is Ize's ("Robust BVH Ray Traversal", JCGT 2(2), 2013) padding
//! of `t_far` by `1 + 2 gamma(3)`, written for entries and exits of either sign (a
//! query's range may start below zero) and for `f64`. The range's own
//! bounds are widened too: a closest-hit query compares certified
//! parameters within `4u` of the exact ones, and `W` covers that as well.
//!
//! A segment query culls with the ray `p + t fl(q - p)` for its exact
//! segment from `p` to `q`: each exact slab parameter `(b - p_k) / (q_k -
//! p_k)` is the ray's `(b - p_k) / fl(q_k - p_k)` times `1 + δ`, `|δ| <= u`
//! (and `fl(q_k - p_k)` is zero exactly when `q_k = p_k`, with the same
//! sign otherwise): one more rounding, so its walk widens by `gamma(8)`
//! (`BoxRay<1>`).
//!
//! A zero direction coordinate has an infinite reciprocal: the slab's `t`
//! are `±inf` (the origin outside the slab: empty; inside: every `t`), and
//! `0 * inf` is NaN where the origin lies on the slab's face. The bounds
//! are ordered by the sign bit of `d_k` (so `-0.0` swaps them as a
//! negative coordinate does), and a NaN bound is dropped: it fails the
//! comparisons that would take it as the entry or exit, so the origin on a face is
//! inside the closed slab, for every `t`. An entry of `+inf` (an empty
//! slab, or an entry beyond `f64::MAX`, where no hit is admitted) culls:
//! its widened entry is `inf - inf = NaN`, which fails the comparison.
//!
//! # Four lanes
//! A wide node (`wide.rs`) holds its children's boxes side by side, and
//! the walk tests them in one pass: the test above, lane by lane, on
//! `[f64; 4]` rows (two SSE2 registers each). Every lane computes the same
//! operations on the same operands in the same order as the one-box test
//! (`fl(fl(b - o_k) * inv_k)` or `fl(fl(b - o_k) / d_k)`, the same
//! comparison-and-select for the entry and exit, the same widening), and
//! vector arithmetic rounds each lane as the scalar operation does (IEEE
//! 754, no contraction into FMA): the per-slab bound and the argument
//! above hold in every lane, so no lane whose box the exact segment meets
//! is culled. The divide-or-multiply choice is the ray's, made once per
//! walk. An empty lane holds the inverted box `[+inf, -inf]`: every slab
//! gives it the entry `+inf` (`wide.rs`), so it is culled by construction.
//!
//! # Culling again on the way back
//! A child is pushed with its widened entry `e`; when it is popped, after
//! leaves may have lowered the visitor's bound from `M` to `M'`, it is
//! dropped if `e > M' + (W |M'| + S)`. That is the test above with the
//! box's own exits left out of the minimum: `e` is unchanged (the entry
//! does not depend on the range's end), and the widened `M'` is above
//! every parameter the query still admits (the range's bound is widened
//! as an exit is). If the exact segment ending at `M'` meets the box, its
//! exact entry is at most its exact exit, at most the range's end, so `e`
//! (below the exact entry) is at most the widened `M'`: the child is kept.
//!
//! # The stack
//! Expanding a wide node pushes at most four children (nearest on top for
//! a closest-hit walk, in lane order for an any-hit one), and the walk
//! then pops from that group only until it expands one of
//! them (entries pushed by the nodes below are all popped first). So when
//! a node is expanded the stack holds at most three entries for each wide
//! node above it on its path. Each wide node of a path is collapsed from
//! a binary internal node strictly deeper than its parent's (`wide.rs`),
//! and the builders' binary internal nodes lie at depths 0 to
//! `MAX_DEPTH - 2` (leaves at most `MAX_DEPTH - 1`, `build.rs`,
//! `ploc.rs`): a path has at most `MAX_DEPTH - 1` wide nodes, and the
//! stack at most `3 (MAX_DEPTH - 2) + 4 < 3 MAX_DEPTH` entries, its size.

#![allow(
    unsafe_code,
    reason = "the walk's stack is left uninitialized, each slot read only after it is written"
)]

use super::wide::{WIDTH, WideNode};
use super::{BoxBvh, MAX_DEPTH};
use crate::arith::roundoff::gamma;
use crate::interval::Interval;
use crate::query::ray::Ray;
use core::mem::MaybeUninit;
use glam::DVec3;

/// The absolute widening `S` of the module docs, `2^-1070`.
const SLACK: f64 = f64::from_bits(1 << 4);

/// A ray prepared for the slab test; `E` more roundings of each slab
/// parameter covered (1 for a segment's exact end, see
/// `TriangleMesh::occluded_between_with`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct BoxRay<const E: u32 = 0> {
    origin: DVec3,
    direction: DVec3,
    inv: DVec3,
    /// Divide by the direction instead of multiplying by `inv`.
    divide: bool,
    /// Per axis, whether the direction's sign bit is set.
    negative: [bool; 3],
}

impl<const E: u32> BoxRay<E> {
    /// The relative widening `W` of the module docs, `gamma(7 + E)`: `E`
    /// more roundings of the slab parameters (each relative `u`, so
    /// `|t - t'| <= gamma(4 + E) |t'|`) and the widening's own three.
    const WIDEN: f64 = gamma(7 + E);

    pub(crate) fn of(ray: &Ray) -> BoxRay<E> {
        let d = ray.direction();
        let inv = DVec3::ONE / d;
        let divide = (0..3).any(|k| d[k] != 0.0 && !inv[k].is_normal());
        BoxRay {
            origin: ray.origin(),
            direction: d,
            inv,
            divide,
            negative: [
                d.x.is_sign_negative(),
                d.y.is_sign_negative(),
                d.z.is_sign_negative(),
            ],
        }
    }

    /// An exit `x` widened upward, `x + (W |x| + S)` (see the module docs).
    #[inline(always)]
    fn widen_up(x: f64) -> f64 {
        x + (Self::WIDEN * x.abs() + SLACK)
    }

    /// The lanes of `node` whose boxes the exact segment `[min, max]` of
    /// the ray may meet (bit `l` of the mask; always set when it does, see
    /// the module docs), and per lane the widened entry parameter `t_near
    /// - (W |t_near| + S)`. `DIVIDE` is `self.divide`, taken once per walk
    /// rather than once per axis and node. Straight-line lane-wise
    /// operations on fixed-size arrays, which the compiler turns into
    /// vector subtractions, products, `maxpd`, `minpd` and comparisons.
    #[inline(always)]
    fn lanes<const DIVIDE: bool>(
        &self,
        node: &WideNode,
        min: f64,
        max: f64,
    ) -> ([f64; WIDTH], u32) {
        let mut near = [min; WIDTH];
        let mut far = [max; WIDTH];
        for k in 0..3 {
            // The slab's entry is at the box's `min` for a direction of
            // clear sign bit and at its `max` otherwise (`-0.0` too): the
            // bounds swap as `(tb, ta)` did in the binary walk.
            let (enter, exit) = if self.negative[k] {
                (&node.max[k], &node.min[k])
            } else {
                (&node.min[k], &node.max[k])
            };
            let o = self.origin[k];
            let (d, inv) = (self.direction[k], self.inv[k]);
            let t = |b: f64| if DIVIDE { (b - o) / d } else { (b - o) * inv };
            let lo: [f64; WIDTH] = core::array::from_fn(|l| t(enter[l]));
            let hi: [f64; WIDTH] = core::array::from_fn(|l| t(exit[l]));
            // A NaN bound (the origin on a face of a zero-direction slab)
            // fails the comparison and is dropped, as `f64::max` and
            // `f64::min` would drop it (`near` and `far` are never NaN);
            // the comparison and select are one `maxpd` or `minpd`.
            near = core::array::from_fn(|l| if lo[l] > near[l] { lo[l] } else { near[l] });
            far = core::array::from_fn(|l| if hi[l] < far[l] { hi[l] } else { far[l] });
        }
        let lower: [f64; WIDTH] =
            core::array::from_fn(|l| near[l] - (Self::WIDEN * near[l].abs() + SLACK));
        let upper: [f64; WIDTH] = core::array::from_fn(|l| Self::widen_up(far[l]));
        // A NaN `lower` (an entry of `+inf`: an empty slab, an empty lane,
        // or an entry beyond `f64::MAX`, where no hit is admitted) fails
        // the comparison.
        let mut mask = 0;
        for l in 0..WIDTH {
            mask |= u32::from(lower[l] <= upper[l]) << l;
        }
        (lower, mask)
    }

    /// Whether the exact segment `[min, max]` of the ray may meet lane `l`
    /// of `node` (never `false` when it does; see the module docs).
    #[cfg(test)]
    pub(super) fn meets(&self, node: &WideNode, l: usize, min: f64, max: f64) -> bool {
        let (_, mask) = if self.divide {
            self.lanes::<true>(node, min, max)
        } else {
            self.lanes::<false>(node, min, max)
        };
        mask & (1 << l) != 0
    }
}

/// What a walk does at the leaves.
pub(crate) trait Visitor {
    /// Whether the walk visits a node's children nearest first and culls a
    /// pending child again when [`Visitor::max`] has shrunk: a closest-hit
    /// query's walk. An any-hit query, whose bound never shrinks and which
    /// stops at its first hit wherever it lies, sets it to `false`: its
    /// walk neither sorts nor culls on the way back.
    const ORDERED: bool = true;
    /// The current upper bound of the parameters still wanted (constant
    /// for a visitor that is not [`Visitor::ORDERED`]).
    fn max(&self) -> f64;
    /// Looks at a leaf's items `order[start .. start + count]` (a mesh's
    /// triangles, a scene's primitives); `true` stops the walk.
    fn leaf(&mut self, triangles: &[u32]) -> bool;
    /// Called once per node the walk looks at (to count them; nothing for
    /// an ordinary query).
    #[inline(always)]
    fn node(&mut self) {}
}

/// A child the walk will come back to: its widened entry and its lane's
/// `link` and `count`.
#[derive(Clone, Copy)]
struct Pending {
    entry: f64,
    link: u32,
    count: u32,
}

/// The walk's stack: three pending children per wide level (see the
/// module docs).
const STACK: usize = 3 * MAX_DEPTH;

/// Walks every leaf whose box the ray's exact segment `[range.min,
/// visitor.max()]` meets, a node's children of smaller entry first for an
/// [ordered](Visitor::ORDERED) visitor, in lane order otherwise. The
/// stack holds up to three pending children per wide level: `3 *
/// MAX_DEPTH` entries, which the builders' depth bound never exceeds (see
/// the module docs).
#[inline(always)]
pub(crate) fn walk<V: Visitor, const E: u32>(
    bvh: &BoxBvh,
    ray: &BoxRay<E>,
    range: Interval,
    v: &mut V,
) {
    if ray.divide {
        walk_in::<V, E, true>(bvh, ray, range, v);
    } else {
        walk_in::<V, E, false>(bvh, ray, range, v);
    }
}

/// [`walk`], with `DIVIDE` the ray's `divide`.
fn walk_in<V: Visitor, const E: u32, const DIVIDE: bool>(
    bvh: &BoxBvh,
    ray: &BoxRay<E>,
    range: Interval,
    v: &mut V,
) {
    if bvh.nodes.is_empty() {
        return;
    }
    let lo = range.min();
    // Left uninitialized: zeroing its 3 KiB took nearly a third of a short
    // query's time (a terrain's primary rays: 53 ns against 37 in the
    // report's closest_hit), and a slot is read only after it is written.
    let mut stack = [const { MaybeUninit::<Pending>::uninit() }; STACK];
    let mut top = 0;
    let mut at = 0usize;
    loop {
        v.node();
        let node = &bvh.nodes[at];
        let (lower, mut mask) = ray.lanes::<DIVIDE>(node, lo, v.max());
        // One internal child kept (the common case near the leaves of a
        // coherent ray): straight to it, without the stack's round trip
        // (its pop test would compare against the same bound).
        if mask.is_power_of_two() {
            let l = mask.trailing_zeros() as usize;
            if node.count[l] == 0 {
                at = node.link[l] as usize;
                continue;
            }
        }
        if !V::ORDERED {
            // Any hit: the lanes kept in lane order, no sorting.
            while mask != 0 {
                let l = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                // A slot is free, as below (see the module docs).
                stack[top] = MaybeUninit::new(Pending {
                    entry: lower[l],
                    link: node.link[l],
                    count: node.count[l],
                });
                top += 1;
            }
        }
        // The lanes kept, sorted by entry, farthest first: pushed in that
        // order, the nearest is popped first.
        let mut kept = [(0.0, 0usize); WIDTH];
        let mut n = 0;
        while V::ORDERED && mask != 0 {
            let l = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            let x = (lower[l], l);
            let mut j = n;
            while j > 0 && kept[j - 1].0 < x.0 {
                kept[j] = kept[j - 1];
                j -= 1;
            }
            kept[j] = x;
            n += 1;
        }
        for &(entry, l) in &kept[..n] {
            // At most three entries per wide level stay on the stack and
            // the wide tree is shallower than MAX_DEPTH, so a slot is
            // always free (see the module docs).
            stack[top] = MaybeUninit::new(Pending {
                entry,
                link: node.link[l],
                count: node.count[l],
            });
            top += 1;
        }
        at = loop {
            if top == 0 {
                return;
            }
            top -= 1;
            // SAFETY: every slot below `top` was written by the push
            // above before `top` passed it, and `top` only moves down
            // here, past slots so written.
            let p = unsafe { stack[top].assume_init() };
            // Culled again when the range has shrunk below its entry since
            // it was pushed (see the module docs).
            if V::ORDERED && p.entry > BoxRay::<E>::widen_up(v.max()) {
                continue;
            }
            if p.count == 0 {
                break p.link as usize;
            }
            v.node();
            let start = p.link as usize;
            let items = bvh.order.get(start..start + p.count as usize);
            if v.leaf(items.unwrap_or(&[])) {
                return;
            }
        };
    }
}

#[cfg(test)]
mod tests {
    use super::super::{BvhBuilder, Item};
    use super::*;
    use alloc::vec::Vec;

    /// A wide node with `[min, max]` in lane `at` and every other lane
    /// empty.
    fn node(at: usize, min: [f64; 3], max: [f64; 3]) -> WideNode {
        let mut n = WideNode::EMPTY;
        for k in 0..3 {
            n.min[k][at] = min[k];
            n.max[k][at] = max[k];
        }
        n.count[at] = 1;
        n
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
            ([1.0 + 1e-9, 0.5, -1.0], [0.0, 0.0, 1.0], f64::INFINITY),
            ([0.5, 0.5, -1.0], [0.0, 0.0, -1.0], f64::INFINITY),
            ([0.5, 0.5, -1.0], [0.0, 0.0, 1.0], 0.5),
            ([2.0, 2.0, 0.0], [-1.0, -1.0, 1.0], 0.99),
        ];
        for at in 0..WIDTH {
            let unit = node(at, [0.0; 3], [1.0; 3]);
            let others = (0..WIDTH).filter(|&l| l != at);
            for (o, d) in keeps {
                let ray = BoxRay::<0>::of(&Ray::new(o, d).unwrap());
                assert!(ray.meets(&unit, at, 0.0, f64::INFINITY), "{o:?} {d:?}");
                let segment = BoxRay::<1>::of(&Ray::new(o, d).unwrap());
                assert!(segment.meets(&unit, at, 0.0, f64::INFINITY), "{o:?} {d:?}");
                for (min, max) in [(0.0, f64::INFINITY), (f64::NEG_INFINITY, f64::INFINITY)] {
                    for l in others.clone() {
                        assert!(!ray.meets(&unit, l, min, max), "{o:?} {d:?} lane {l}");
                        assert!(!segment.meets(&unit, l, min, max), "{o:?} {d:?} lane {l}");
                    }
                }
            }
            for (o, d, max) in culls {
                let ray = BoxRay::<0>::of(&Ray::new(o, d).unwrap());
                assert!(!ray.meets(&unit, at, 0.0, max), "{o:?} {d:?}");
            }
            // The touching corner ray with its range ending exactly at t = 1.
            let corner = BoxRay::<0>::of(&Ray::new([2.0, 2.0, 0.0], [-1.0, -1.0, 1.0]).unwrap());
            assert!(corner.meets(&unit, at, 0.0, 1.0));
        }
        // Every lane of a node of four touching boxes at once.
        let mut four = WideNode::EMPTY;
        for l in 0..WIDTH {
            for k in 0..3 {
                four.min[k][l] = l as f64;
                four.max[k][l] = l as f64 + 1.0;
            }
        }
        // Along the diagonal, through each box's corners.
        let diagonal = BoxRay::<0>::of(&Ray::new([0.0; 3], [1.0; 3]).unwrap());
        let (lower, mask) = diagonal.lanes::<false>(&four, 0.0, f64::INFINITY);
        assert_eq!(mask, 0b1111);
        for (l, &entry) in lower.iter().enumerate() {
            assert!(diagonal.meets(&four, l, 0.0, f64::INFINITY), "lane {l}");
            assert!(entry <= l as f64, "lane {l}");
        }
        // Which path each direction takes.
        let divides = |d: [f64; 3]| BoxRay::<0>::of(&Ray::new([0.0; 3], d).unwrap()).divide;
        assert!(divides([0.0, -tiny, 1.0]) && divides([huge, 0.0, 0.0]));
        assert!(!divides([0.0, -0.0, 1.0]) && !divides([-1.0, 2.0, 1e300]));
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

    /// The 4-wide walk reaches every leaf whose box the exact segment
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
        let mut triangles = Vec::new();
        for k in 0..600u32 {
            let base = [rng.int(12), rng.int(12), rng.int(12)];
            for _ in 0..3 {
                vertices.push([0, 1, 2].map(|i| (base[i] + rng.int(2)) as f64 * s));
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
            let mut leaves = Vec::new();
            for n in &bvh.nodes {
                for l in 0..WIDTH {
                    if n.count[l] > 0 {
                        let lo = [0, 1, 2].map(|k| (n.min[k][l] / s) as i128);
                        let hi = [0, 1, 2].map(|k| (n.max[k][l] / s) as i128);
                        leaves.push((lo, hi, n.link[l] as usize, n.count[l] as usize));
                    }
                }
            }
            let mut kept = 0;
            for i in 0..3000 {
                let o = [rng.int(16), rng.int(16), rng.int(16)];
                let mut d = [rng.int(3), rng.int(3), rng.int(3)];
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
                walk(bvh, &BoxRay::<0>::of(&ray), range, &mut ours);
                let mut segment = Leaves {
                    max: range.max(),
                    seen: Vec::new(),
                };
                walk(bvh, &BoxRay::<1>::of(&ray), range, &mut segment);
                let (o, d) = (o.map(i128::from), d.map(i128::from));
                for &(lo, hi, start, count) in &leaves {
                    if exact_meets(lo, hi, o, d, max.map(i128::from)) {
                        kept += 1;
                        for t in &bvh.order[start..start + count] {
                            assert!(ours.seen.contains(t), "ray {i}: leaf at {start} culled");
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
        }
    }
}
