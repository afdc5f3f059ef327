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
    reason = "the walk's stack is left uninitialized, each slot read only after it is written"
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
}

/// The world test over a hierarchy's nodes: the ray and the frame its
/// boxes are taken out of.
struct World<'a, const E: u32, const DIVIDE: bool> {
    ray: BoxRay<E>,
    frame: &'a Frame,
}

impl<const E: u32, const DIVIDE: bool> Slabs for World<'_, E, DIVIDE> {
    type T = f64;

    #[inline(always)]
    fn param(&self, t: f64, _up: bool) -> f64 {
        t
    }

    #[inline(always)]
    fn lanes(&self, node: &WideNode, min: f64, max: f64) -> ([f64; WIDTH], u32) {
        let f = self.frame;
        let lo =
            core::array::from_fn(|k| core::array::from_fn(|l| f.world_down(node.min[k][l], k)));
        let hi = core::array::from_fn(|k| core::array::from_fn(|l| f.world_up(node.max[k][l], k)));
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
mod tests {
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
        let framed = |o: [f64; 3], d: [f64; 3]| {
            FrameRay::<0>::of(&Ray::new(o, d).unwrap(), &IDENTITY).is_some()
        };
        assert!(
            framed([0.0; 3], [0.0, -0.0, 1.0]) && framed([1e14, 0.0, 0.0], [huge, 0.0, 1e-300])
        );
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
}
