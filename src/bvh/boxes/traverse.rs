//! The conservative walk: a slab test that never culls a box the ray's
//! exact segment meets, run on the eight children of a wide node at once,
//! and the stack walk every query shares.
//!
//! A node's boxes are `f32` bounds in the hierarchy's frame (`frame.rs`),
//! each below (`min`) or above (`max`) the exact bound it stands for. The
//! walk tests them in `f32` in that frame (the frame test below) for every
//! ray whose frame values stay in a range where nothing overflows, and
//! otherwise in `f64` in world coordinates, the bounds taken back out of
//! the frame outward (the world test): a ray far outside the hierarchy's
//! box, relative to its size, or with a direction coordinate below
//! `2^-48` of its largest (but not zero). Either test keeps every box
//! whose exact segment meets the exact box it stands for, hence every box
//! the exact segment meets of the items below it.
//!
//! # The world test
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
//! Here the bounds `b` are the node's, taken back into world coordinates
//! outward (`Frame::world_down`, `Frame::world_up`): below and above the
//! exact ones. The entry `t_near = max(range.min, lo_x, lo_y, lo_z)` and exit `t_far =
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
//! Where an origin coordinate exceeds `2^969` in magnitude, `b - o_k`
//! may overflow for a finite bound on the other side of the range (below
//! `2^969`, `|b - o_k| < f64::MAX + 2^970`, which rounds to at most
//! `f64::MAX`). On such an axis the slab is computed as `2 fl(fl(fl(b /
//! 2) - o_k / 2) * fl(1 / d_k))` (or `/ d_k`): `o_k / 2` is exact, the
//! doubling exact unless it overflows (an entry beyond `f64::MAX`, as
//! above), and `fl(b / 2)` off by at most `2^-1075` where `b` is below
//! `2^-1021`, which next to `|o_k / 2| > 2^968` is a relative error below
//! `2^-2040` of the difference: `θ` grows by less than `2^-2039`, far
//! inside the margin between `gamma(3) / (1 - gamma(3))` and `gamma(4)`
//! (about `u`). The bound and the widening are unchanged.
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
//! # The frame test
//! The ray is written in the frame: a point `x` is `x' = (x - c) 2^e`,
//! so the ray is `o' + t d 2^e = o' + tau D` with `D = d 2^s` (`s` the
//! power of two bringing `d`'s largest coordinate into `[1/2, 1)`, so `D`
//! is exact where the test runs) and `tau = t 2^p`, `p = e - s`: the exact slabs in `tau` are
//! those in `t` scaled by the power of two `2^p`, and a range `[t_0,
//! t_1]` is `[t_0 2^p, t_1 2^p]`, rounded outward to `f32`
//! ([`frame::down`], [`frame::up`], which bracket the exactly scaled
//! value). The origin's frame coordinate `o'_k` is bracketed the same way,
//! `lo_k < o'_k < hi_k` in `f32` (`frame.rs`), and Ize's argument is
//! extended to that rounding by choosing the side per bound rather than
//! padding: the slab's entry for a direction of clear sign bit is `(b -
//! o'_k) / D_k` at its lower bound `b`, and `(b - hi_k) / D_k` is below it
//! (`hi_k > o'_k`, `D_k >= 0`); its exit, at its upper bound, is computed
//! from `lo_k` and is above the exact one; for a set sign bit the sides
//! swap with the bounds. A zero `D_k` gives `±inf` and, where `b` equals
//! the chosen origin bound, NaN, which is dropped as in the world test; as
//! `lo_k < o'_k < hi_k` strictly, an origin inside the slab gives an
//! entry of `-inf` and an exit of `+inf` or NaN: kept.
//!
//! What remains is the arithmetic on those values:
//! `fl(fl(b - o) * fl32(fl64(1 / D_k)))`, four roundings, each within
//! `u = 2^-24` relative (the `f64` division within `2^-53`), so the
//! computed `tau'` is `tau (1 + θ)` with `|θ| <= gamma(4)`, and `|tau -
//! tau'| <= gamma(5) |tau'|`, plus at most `2^-150` where the product
//! underflows (a difference that underflows is exact). The entry and exit
//! are then widened as in the world test, `W = gamma(9 + E)`, for the
//! five, the widening's own three roundings, and the certified parameters
//! a closest-hit query compares (within `4 * 2^-53` of the exact ones, less
//! than one more `u`); it is stored as `(10 + E) 2^-24`, at least
//! `gamma(9 + E)` (`n u / (1 - n u) <= (n + 1) u` when `n (n + 1) u <= 1`),
//! and `S = 2^-126` covers the underflows.
//!
//! The frame test runs only where nothing overflows and `D` is exact:
//! `|o'_k| <= 2^48` (infinite where `o_k - c_k` overflowed: then it does
//! not run), every `D_k` zero or at least `2^-48` in magnitude, and `p` in
//! `[-2044, 2046]` (the range's scaling, `scale_pow2`, whose two factors
//! `2^(p/2)` and `2^(p - p/2)` must be normal). The box bounds lie within
//! `[-2, 2]`, so `|b - o| < 2^49` and `|1 / D_k| <= 2^48`: every slab
//! parameter is below `2^97`, far from `f32::MAX`.
//!
//! # Eight lanes
//! A wide node (`wide.rs`) holds its children's boxes side by side, and
//! the walk tests them in one pass: the tests above, lane by lane, on
//! `[f32; 8]` rows (one AVX register each where the CPU has AVX2, which
//! `std` builds detect at run time and walk with a copy compiled for it;
//! two SSE registers otherwise; the world test's `[f64; 8]` rows, the
//! bounds taken out of the frame first, four). Every lane computes the same
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
//! dropped if `e > M' + (W |M'| + S)` (in the frame test, `M'` rounded up
//! into the frame's parameter). That is the test above with the
//! box's own exits left out of the minimum: `e` is unchanged (the entry
//! does not depend on the range's end), and the widened `M'` is above
//! every parameter the query still admits (the range's bound is widened
//! as an exit is). If the exact segment ending at `M'` meets the box, its
//! exact entry is at most its exact exit, at most the range's end, so `e`
//! (below the exact entry) is at most the widened `M'`: the child is kept.
//!
//! # The stack
//! Expanding a wide node pushes at most eight children (nearest on top for
//! a closest-hit walk, in lane order for an any-hit one), and the walk
//! then pops from that group only until it expands one of
//! them (entries pushed by the nodes below are all popped first). So when
//! a node is expanded the stack holds at most seven entries for each wide
//! node above it on its path. Each wide node of a path is collapsed from
//! a binary internal node strictly deeper than its parent's (`wide.rs`),
//! and the builders' binary internal nodes lie at depths 0 to
//! `MAX_DEPTH - 2` (leaves at most `MAX_DEPTH - 1`, `build.rs`,
//! `ploc.rs`): a path has at most `MAX_DEPTH - 1` wide nodes, and the
//! stack at most `7 (MAX_DEPTH - 2) + 8 < 7 MAX_DEPTH` entries, its size.

#![allow(
    unsafe_code,
    reason = "the walk's stack is left uninitialized (each slot read only after it is written), and its node tests use SSE2 and AVX2 intrinsics (the AVX2 walk only where the CPU has it)"
)]

use super::frame::{self, Frame};
use super::wide::{WIDTH, WideNode};
use super::{BoxBvh, MAX_DEPTH};
use crate::arith::exponent::{pow2, scale_pow2, unit_scale};
use crate::arith::roundoff::gamma;
use crate::interval::Interval;
use crate::query::ray::Ray;
use core::mem::MaybeUninit;
use glam::DVec3;

/// The absolute widening `S` of the world test, `2^-1070`.
const SLACK: f64 = f64::from_bits(1 << 4);

/// The absolute widening `S` of the frame test, `2^-126`.
const SLACK_32: f32 = f32::MIN_POSITIVE;

/// The origin coordinate above which the world test halves `b - o_k`,
/// `2^969`: below it no difference with a finite bound overflows (see the
/// module docs).
const HALVE_ABOVE: f64 = pow2(969);

/// The frame test's limit on the origin's frame coordinates and on the
/// reciprocals of the scaled direction, `2^48` (see the module docs).
const FRAME_LIMIT: f64 = pow2(48);

/// What a slab test gives the walk: per lane the widened entry and the
/// mask of lanes kept, in its own parameter.
trait Slabs {
    /// The parameter the test computes in: `f32` in the frame, `f64` in
    /// world coordinates.
    type T: Copy + PartialOrd;
    /// A bound of the query's range as the test's parameter, rounded down
    /// (`up` false) or up, so that it brackets the exact one.
    fn param(&self, t: f64, up: bool) -> Self::T;
    /// The lanes of `node` whose boxes the exact segment `[min, max]` may
    /// meet (bit `l` of the mask), and per lane the widened entry.
    fn lanes(&self, node: &WideNode, min: Self::T, max: Self::T) -> ([Self::T; WIDTH], u32);
    /// An exit widened upward, `x + (W |x| + S)`.
    fn widen_up(&self, x: Self::T) -> Self::T;
}

/// A ray prepared for the world test; `E` more roundings of each slab
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
    /// The relative widening `W` of the world test, `gamma(7 + E)`: `E`
    /// more roundings of the slab parameters (each relative `u`, so
    /// `|t - t'| <= gamma(4 + E) |t'|`) and the widening's own three.
    const WIDEN: f64 = gamma(7 + E);

    fn of(ray: &Ray) -> BoxRay<E> {
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

    /// The world test on the boxes `[min[k][l], max[k][l]]` (world
    /// coordinates, `min` below and `max` above the exact bounds): the
    /// lanes whose boxes the exact segment `[tmin, tmax]` of the ray may
    /// meet, and per lane the widened entry `t_near - (W |t_near| + S)`.
    /// `DIVIDE` is `self.divide`, taken once per walk rather than once per
    /// axis and node. Straight-line lane-wise operations on fixed-size
    /// arrays, which the compiler turns into vector subtractions,
    /// products, `maxpd`, `minpd` and comparisons.
    #[inline(always)]
    fn world_lanes<const DIVIDE: bool>(
        &self,
        min: &[[f64; WIDTH]; 3],
        max: &[[f64; WIDTH]; 3],
        tmin: f64,
        tmax: f64,
    ) -> ([f64; WIDTH], u32) {
        let mut near = [tmin; WIDTH];
        let mut far = [tmax; WIDTH];
        for k in 0..3 {
            // The slab's entry is at the box's `min` for a direction of
            // clear sign bit and at its `max` otherwise (`-0.0` too).
            let (enter, exit) = if self.negative[k] {
                (&max[k], &min[k])
            } else {
                (&min[k], &max[k])
            };
            let o = self.origin[k];
            let (d, inv) = (self.direction[k], self.inv[k]);
            let (lo, hi): ([f64; WIDTH], [f64; WIDTH]) = if o.abs() > HALVE_ABOVE {
                // `b - o` may overflow: halved (see the module docs).
                let o = o * 0.5;
                let t = |b: f64| {
                    let x = b * 0.5 - o;
                    2.0 * if DIVIDE { x / d } else { x * inv }
                };
                (
                    core::array::from_fn(|l| t(enter[l])),
                    core::array::from_fn(|l| t(exit[l])),
                )
            } else {
                let t = |b: f64| if DIVIDE { (b - o) / d } else { (b - o) * inv };
                (
                    core::array::from_fn(|l| t(enter[l])),
                    core::array::from_fn(|l| t(exit[l])),
                )
            };
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
}

/// The world test over a hierarchy's nodes: the ray and the frame its
/// boxes are taken out of; with `PAD`, every bound one more step outward
/// (a halved segment's, [`walk_halved_segment`]).
struct World<'a, const E: u32, const DIVIDE: bool, const PAD: bool = false> {
    ray: BoxRay<E>,
    frame: &'a Frame,
}

impl<const E: u32, const DIVIDE: bool, const PAD: bool> Slabs for World<'_, E, DIVIDE, PAD> {
    type T = f64;

    #[inline(always)]
    fn param(&self, t: f64, _up: bool) -> f64 {
        t
    }

    #[inline(always)]
    fn lanes(&self, node: &WideNode, min: f64, max: f64) -> ([f64; WIDTH], u32) {
        let f = self.frame;
        let down = |b: f32, k: usize| {
            let x = f.world_down(b, k);
            if PAD { x.next_down() } else { x }
        };
        let up = |b: f32, k: usize| {
            let x = f.world_up(b, k);
            if PAD { x.next_up() } else { x }
        };
        let lo = core::array::from_fn(|k| core::array::from_fn(|l| down(node.min[k][l], k)));
        let hi = core::array::from_fn(|k| core::array::from_fn(|l| up(node.max[k][l], k)));
        self.ray.world_lanes::<DIVIDE>(&lo, &hi, min, max)
    }

    #[inline(always)]
    fn widen_up(&self, x: f64) -> f64 {
        BoxRay::<E>::widen_up(x)
    }
}

/// A ray prepared for the frame test (see the module docs); `E` as for
/// [`BoxRay`].
#[derive(Clone, Copy, Debug)]
struct FrameRay<const E: u32> {
    /// Per axis, the origin bound the entry is computed from (`hi_k` for
    /// a clear sign bit, `lo_k` for a set one) and the one the exit is.
    enter: [f32; 3],
    exit: [f32; 3],
    /// Per axis, `fl32(fl64(1 / D_k))`, `±inf` for a zero `D_k`.
    inv: [f32; 3],
    /// Per axis, whether the direction's sign bit is set.
    negative: [bool; 3],
    /// The power of two `p` of `tau = t 2^p`.
    p: i32,
}

impl<const E: u32> FrameRay<E> {
    /// The relative widening `W` of the frame test, `(10 + E) 2^-24 >=
    /// gamma(9 + E)` in `f32` (see the module docs).
    const WIDEN: f32 = (10 + E) as f32 * (f32::EPSILON / 2.0);

    /// The ray in `frame`, or `None` where the frame test does not run
    /// (see the module docs).
    #[inline(always)]
    fn of(ray: &Ray, frame: &Frame) -> Option<FrameRay<E>> {
        let d = ray.direction();
        let s = unit_scale(&[d.x, d.y, d.z]);
        let p = frame.exp - s;
        if !(-2044..=2046).contains(&p) {
            return None;
        }
        let mut r = FrameRay {
            enter: [0.0; 3],
            exit: [0.0; 3],
            inv: [0.0; 3],
            negative: [false; 3],
            p,
        };
        for k in 0..3 {
            let dk = scale_pow2(d[k], s);
            let x = frame.coordinate(ray.origin()[k], k);
            let small = dk != 0.0 && dk.abs() * FRAME_LIMIT < 1.0;
            if small || x.abs() > FRAME_LIMIT || x.is_nan() {
                return None;
            }
            let (lo, hi) = (frame::down(x), frame::up(x));
            r.negative[k] = dk.is_sign_negative();
            (r.enter[k], r.exit[k]) = if r.negative[k] { (lo, hi) } else { (hi, lo) };
            r.inv[k] = (1.0 / dk) as f32;
        }
        Some(r)
    }
}

impl<const E: u32> Slabs for FrameRay<E> {
    type T = f32;

    #[inline(always)]
    fn param(&self, t: f64, up: bool) -> f32 {
        let tau = scale_pow2(t, self.p);
        if up { frame::up(tau) } else { frame::down(tau) }
    }

    /// The frame test on the lanes of `node`: SSE2 intrinsics on x86_64
    /// (two halves of four lanes, [`sse2_lanes`]), the portable lane-wise
    /// code elsewhere; the same values either way.
    #[inline(always)]
    fn lanes(&self, node: &WideNode, min: f32, max: f32) -> ([f32; WIDTH], u32) {
        #[cfg(target_arch = "x86_64")]
        {
            // SAFETY: every x86_64 CPU supports SSE2.
            unsafe { sse2_lanes(self, node, min, max) }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            self.portable_lanes(node, min, max)
        }
    }

    #[inline(always)]
    fn widen_up(&self, x: f32) -> f32 {
        x + (Self::WIDEN * x.abs() + SLACK_32)
    }
}

impl<const E: u32> FrameRay<E> {
    /// The frame test in straight-line lane-wise operations on `f32` rows,
    /// as the world test's.
    #[cfg_attr(
        target_arch = "x86_64",
        allow(dead_code, reason = "the tests' reference")
    )]
    #[inline(always)]
    fn portable_lanes(&self, node: &WideNode, min: f32, max: f32) -> ([f32; WIDTH], u32) {
        let mut near = [min; WIDTH];
        let mut far = [max; WIDTH];
        for k in 0..3 {
            let (enter, exit) = if self.negative[k] {
                (&node.max[k], &node.min[k])
            } else {
                (&node.min[k], &node.max[k])
            };
            let (oe, ox, inv) = (self.enter[k], self.exit[k], self.inv[k]);
            let lo: [f32; WIDTH] = core::array::from_fn(|l| (enter[l] - oe) * inv);
            let hi: [f32; WIDTH] = core::array::from_fn(|l| (exit[l] - ox) * inv);
            near = core::array::from_fn(|l| if lo[l] > near[l] { lo[l] } else { near[l] });
            far = core::array::from_fn(|l| if hi[l] < far[l] { hi[l] } else { far[l] });
        }
        let lower: [f32; WIDTH] =
            core::array::from_fn(|l| near[l] - (Self::WIDEN * near[l].abs() + SLACK_32));
        let upper: [f32; WIDTH] = core::array::from_fn(|l| self.widen_up(far[l]));
        let mut mask = 0;
        for l in 0..WIDTH {
            mask |= u32::from(lower[l] <= upper[l]) << l;
        }
        (lower, mask)
    }
}

/// The frame test in SSE2 intrinsics (every x86_64 CPU has them), two
/// halves of four lanes: the same operations as
/// [`FrameRay::portable_lanes`] (see [`Avx2`] for the correspondence), so
/// the same values and mask.
///
/// # Safety
/// The CPU must support SSE2: every x86_64 CPU does (the target's
/// baseline), so this is never in doubt where it compiles.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "sse2")]
#[inline]
unsafe fn sse2_lanes<const E: u32>(
    r: &FrameRay<E>,
    node: &WideNode,
    min: f32,
    max: f32,
) -> ([f32; WIDTH], u32) {
    use core::arch::x86_64::*;
    const _: () = assert!(WIDTH == 8);
    let load = |row: &[f32; WIDTH], half: usize| {
        // SAFETY: lanes `4 half .. 4 half + 4` of an eight-lane row, read
        // unaligned.
        unsafe { _mm_loadu_ps(row.as_ptr().add(4 * half)) }
    };
    let abs = |x: __m128| _mm_and_ps(x, _mm_castsi128_ps(_mm_set1_epi32(0x7fff_ffff)));
    let widen = |x: __m128| {
        _mm_add_ps(
            _mm_mul_ps(_mm_set1_ps(FrameRay::<E>::WIDEN), abs(x)),
            _mm_set1_ps(SLACK_32),
        )
    };
    let mut out = [0.0; WIDTH];
    let mut mask = 0;
    for half in 0..2 {
        let mut near = _mm_set1_ps(min);
        let mut far = _mm_set1_ps(max);
        for k in 0..3 {
            let (enter, exit) = if r.negative[k] {
                (&node.max[k], &node.min[k])
            } else {
                (&node.min[k], &node.max[k])
            };
            let inv = _mm_set1_ps(r.inv[k]);
            let lo = _mm_mul_ps(_mm_sub_ps(load(enter, half), _mm_set1_ps(r.enter[k])), inv);
            let hi = _mm_mul_ps(_mm_sub_ps(load(exit, half), _mm_set1_ps(r.exit[k])), inv);
            near = _mm_max_ps(lo, near);
            far = _mm_min_ps(hi, far);
        }
        let lower = _mm_sub_ps(near, widen(near));
        let upper = _mm_add_ps(far, widen(far));
        mask |= (_mm_movemask_ps(_mm_cmple_ps(lower, upper)) as u32) << (4 * half);
        // SAFETY: lanes `4 half .. 4 half + 4` of `out`, written unaligned.
        unsafe { _mm_storeu_ps(out.as_mut_ptr().add(4 * half), lower) };
    }
    (out, mask)
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
    /// for a visitor that is not [`Visitor::ORDERED`]; it changes only in
    /// [`Visitor::leaf`]).
    fn max(&self) -> f64;
    /// Looks at a leaf's items `order[start .. start + count]` (a mesh's
    /// triangles, a scene's primitives); `true` stops the walk.
    fn leaf(&mut self, triangles: &[u32]) -> bool;
    /// Called once per node the walk looks at, with the boxes it tests
    /// there (a wide node's lanes, all in one pass; none at a leaf), to
    /// count them; nothing for an ordinary query.
    #[inline(always)]
    fn node(&mut self, _boxes: usize) {}
}

/// A child the walk will come back to: its widened entry and its lane's
/// `link` and `count`.
#[derive(Clone, Copy)]
struct Pending<T> {
    entry: T,
    link: u32,
    count: u32,
}

/// The walk's stack: seven pending children per wide level (see the
/// module docs).
const STACK: usize = (WIDTH - 1) * MAX_DEPTH;

/// Walks every leaf whose box the exact segment `[range.min,
/// visitor.max()]` of `ray` meets, a node's children of smaller entry
/// first for an [ordered](Visitor::ORDERED) visitor, in lane order
/// otherwise; `E` more roundings of the slab parameters covered (1 for a
/// segment's exact end). The stack holds up to seven pending children per
/// wide level: `7 * MAX_DEPTH` entries, which the builders' depth bound
/// never exceeds (see the module docs).
#[inline(always)]
pub(crate) fn walk<V: Visitor, const E: u32>(bvh: &BoxBvh, ray: &Ray, range: Interval, v: &mut V) {
    if bvh.nodes.is_empty() {
        return;
    }
    if let Some(r) = FrameRay::<E>::of(ray, &bvh.frame) {
        #[cfg(all(feature = "std", target_arch = "x86_64", not(target_feature = "avx2")))]
        {
            if std::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU supports AVX2, checked just above.
                return unsafe { walk_avx2(bvh, &r, range, v) };
            }
        }
        return walk_in(bvh, &r, range, v);
    }
    let r = BoxRay::<E>::of(ray);
    let frame = &bvh.frame;
    if r.divide {
        walk_in(bvh, &World::<E, true> { ray: r, frame }, range, v);
    } else {
        walk_in(bvh, &World::<E, false> { ray: r, frame }, range, v);
    }
}

/// [`walk`] for a segment whose ray has the halved difference of its
/// ends as direction (`scene::spawn::Segment`), over `range` within `[0,
/// 2]`: the ray strays from the exact segment by one relative rounding
/// of each direction coordinate (the `E = 1` widening, as for any
/// segment) and by at most `2^-1074` per axis more (a halved coordinate
/// below `2^-1021` rounded once, by at most `2^-1075`, times `t <= 2`). A
/// point of the exact segment inside an exact box is then within
/// `2^-1074` per axis of the ray's point at the same `t`, inside the box
/// grown by `2^-1074` on every side, which one more `next_down` or
/// `next_up` of each world bound (a step of at least `2^-1074`) covers;
/// the world test then keeps it as it keeps any box its segment meets.
/// The frame test is not used: its bounds are `f32` steps of the frame,
/// which may be far finer than `2^-1074` in world units. Rare (only ends
/// beyond `f64::MAX` apart take it), so one test, unspecialised.
#[inline(never)]
pub(crate) fn walk_halved_segment<V: Visitor>(bvh: &BoxBvh, ray: &Ray, range: Interval, v: &mut V) {
    if bvh.nodes.is_empty() {
        return;
    }
    let r = BoxRay::<1>::of(ray);
    let frame = &bvh.frame;
    if r.divide {
        walk_in(bvh, &World::<1, true, true> { ray: r, frame }, range, v);
    } else {
        walk_in(bvh, &World::<1, false, true> { ray: r, frame }, range, v);
    }
}

/// [`walk_in`] compiled with AVX2, so that each row of the frame test's
/// eight lanes is one instruction (the same operations, rounded alike).
///
/// # Safety
/// The CPU must support the `avx2` feature.
#[cfg(all(feature = "std", target_arch = "x86_64", not(target_feature = "avx2")))]
#[target_feature(enable = "avx2")]
#[inline(never)]
unsafe fn walk_avx2<V: Visitor, const E: u32>(
    bvh: &BoxBvh,
    slabs: &FrameRay<E>,
    range: Interval,
    v: &mut V,
) {
    walk_in(bvh, &Avx2(*slabs), range, v);
}

/// The frame test in AVX2 intrinsics, made only by [`walk_avx2`] (so only
/// where the CPU has AVX2): the same operations on the same operands in
/// the same order as [`FrameRay`]'s lanes (`vsubps`, `vmulps`; `vmaxps`
/// and `vminps`, which return their second operand where the comparison
/// fails, a NaN dropped as the portable select drops it; the widening's
/// product, sum and difference; `<=` as an ordered comparison), so the
/// same values and mask, bit for bit, and the same derivation.
#[cfg(all(feature = "std", target_arch = "x86_64", not(target_feature = "avx2")))]
struct Avx2<const E: u32>(FrameRay<E>);

#[cfg(all(feature = "std", target_arch = "x86_64", not(target_feature = "avx2")))]
impl<const E: u32> Slabs for Avx2<E> {
    type T = f32;

    #[inline(always)]
    fn param(&self, t: f64, up: bool) -> f32 {
        self.0.param(t, up)
    }

    #[inline(always)]
    fn lanes(&self, node: &WideNode, min: f32, max: f32) -> ([f32; WIDTH], u32) {
        // SAFETY: an `Avx2` is made only in `walk_avx2`, which runs only
        // where the CPU supports AVX2.
        unsafe { avx2_lanes(&self.0, node, min, max) }
    }

    #[inline(always)]
    fn widen_up(&self, x: f32) -> f32 {
        self.0.widen_up(x)
    }
}

/// See [`Avx2`].
///
/// # Safety
/// The CPU must support the `avx2` feature.
#[cfg(all(feature = "std", target_arch = "x86_64", not(target_feature = "avx2")))]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn avx2_lanes<const E: u32>(
    r: &FrameRay<E>,
    node: &WideNode,
    min: f32,
    max: f32,
) -> ([f32; WIDTH], u32) {
    use core::arch::x86_64::*;
    const _: () = assert!(WIDTH == 8);
    let load = |row: &[f32; WIDTH]| {
        // SAFETY: a row is eight `f32`s, read unaligned.
        unsafe { _mm256_loadu_ps(row.as_ptr()) }
    };
    let mut near = _mm256_set1_ps(min);
    let mut far = _mm256_set1_ps(max);
    for k in 0..3 {
        let (enter, exit) = if r.negative[k] {
            (&node.max[k], &node.min[k])
        } else {
            (&node.min[k], &node.max[k])
        };
        let inv = _mm256_set1_ps(r.inv[k]);
        let lo = _mm256_mul_ps(_mm256_sub_ps(load(enter), _mm256_set1_ps(r.enter[k])), inv);
        let hi = _mm256_mul_ps(_mm256_sub_ps(load(exit), _mm256_set1_ps(r.exit[k])), inv);
        near = _mm256_max_ps(lo, near);
        far = _mm256_min_ps(hi, far);
    }
    let abs = |x: __m256| _mm256_and_ps(x, _mm256_castsi256_ps(_mm256_set1_epi32(0x7fff_ffff)));
    let widen = |x: __m256| {
        _mm256_add_ps(
            _mm256_mul_ps(_mm256_set1_ps(FrameRay::<E>::WIDEN), abs(x)),
            _mm256_set1_ps(SLACK_32),
        )
    };
    let lower = _mm256_sub_ps(near, widen(near));
    let upper = _mm256_add_ps(far, widen(far));
    let mask = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(lower, upper)) as u32;
    let mut out = [0.0; WIDTH];
    // SAFETY: `out` holds eight `f32`s, written unaligned.
    unsafe { _mm256_storeu_ps(out.as_mut_ptr(), lower) };
    (out, mask)
}

/// [`walk`] with the slab test `slabs`.
#[inline(always)]
fn walk_in<V: Visitor, S: Slabs>(bvh: &BoxBvh, slabs: &S, range: Interval, v: &mut V) {
    let lo = slabs.param(range.min(), false);
    // The visitor's bound as the test's parameter, rounded up; it changes
    // only when a leaf is visited.
    let mut hi = slabs.param(v.max(), true);
    // Left uninitialized: zeroing it took nearly a third of a short
    // query's time (a terrain's primary rays: 53 ns against 37 in the
    // report's closest_hit), and a slot is read only after it is written.
    let mut stack = [const { MaybeUninit::<Pending<S::T>>::uninit() }; STACK];
    let mut top = 0;
    let mut at = 0usize;
    loop {
        v.node(WIDTH);
        let node = &bvh.nodes[at];
        let (lower, mut mask) = slabs.lanes(node, lo, hi);
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
        if V::ORDERED {
            // The lanes kept, sorted by entry, farthest first: pushed in
            // that order, the nearest is popped first.
            let mut kept = [(lower[0], 0usize); WIDTH];
            let mut n = 0;
            while mask != 0 {
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
                // At most seven entries per wide level stay on the stack
                // and the wide tree is shallower than MAX_DEPTH, so a slot
                // is always free (see the module docs).
                stack[top] = MaybeUninit::new(Pending {
                    entry,
                    link: node.link[l],
                    count: node.count[l],
                });
                top += 1;
            }
        } else {
            // Any hit: the lanes kept in lane order, no sorting.
            while mask != 0 {
                let l = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                // A slot is free, as above.
                stack[top] = MaybeUninit::new(Pending {
                    entry: lower[l],
                    link: node.link[l],
                    count: node.count[l],
                });
                top += 1;
            }
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
            if V::ORDERED && p.entry > slabs.widen_up(hi) {
                continue;
            }
            if p.count == 0 {
                break p.link as usize;
            }
            v.node(0);
            let start = p.link as usize;
            let items = bvh.order.get(start..start + p.count as usize);
            if v.leaf(items.unwrap_or(&[])) {
                return;
            }
            if V::ORDERED {
                hi = slabs.param(v.max(), true);
            }
        };
    }
}

#[cfg(test)]
mod tests;
