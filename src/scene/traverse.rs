//! The conservative walk: a slab test that never culls a box the ray's
//! exact segment meets, and the stack walk every query shares.
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
//! slab, or an entry beyond `f64::MAX`, where no hit is admitted) culls.

use super::{MAX_DEPTH, Node, TriangleBvh};
use crate::arith::roundoff::gamma;
use crate::interval::Interval;
use crate::query::ray::Ray;
use glam::DVec3;

/// The absolute widening `S` of the module docs, `2^-1070`.
const SLACK: f64 = f64::from_bits(1 << 4);

/// A ray prepared for the slab test; `E` more roundings of each slab
/// parameter covered (1 for a segment's exact end, see
/// `TriangleMesh::occluded_between_with`).
#[derive(Clone, Copy, Debug)]
pub(super) struct BoxRay<const E: u32 = 0> {
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

    pub(super) fn of(ray: &Ray) -> BoxRay<E> {
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

    /// Whether the exact segment `[min, max]` of the ray may meet the box
    /// (never `false` when it does; see the module docs).
    #[inline(always)]
    pub(super) fn meets(&self, node: &Node, min: f64, max: f64) -> bool {
        self.entry(node, min, max).is_some()
    }

    /// The widened entry parameter of the box when the exact segment
    /// `[min, max]` of the ray may meet it (always when it does; see the
    /// module docs), `None` when it certainly does not.
    #[inline(always)]
    pub(super) fn entry(&self, node: &Node, min: f64, max: f64) -> Option<f64> {
        let (mut near, mut far) = (min, max);
        for k in 0..3 {
            let (a, b) = (node.min[k] - self.origin[k], node.max[k] - self.origin[k]);
            let (ta, tb) = if self.divide {
                (a / self.direction[k], b / self.direction[k])
            } else {
                (a * self.inv[k], b * self.inv[k])
            };
            let (lo, hi) = if self.negative[k] { (tb, ta) } else { (ta, tb) };
            // A NaN bound (the origin on a face of a zero-direction slab)
            // fails both comparisons and is dropped, as `f64::max` and
            // `f64::min` would drop it (`near` and `far` are never NaN);
            // a comparison and a select are fewer instructions.
            if lo > near {
                near = lo;
            }
            if hi < far {
                far = hi;
            }
        }
        if near == f64::INFINITY {
            return None;
        }
        let lower = near - (Self::WIDEN * near.abs() + SLACK);
        (lower <= far + (Self::WIDEN * far.abs() + SLACK)).then_some(lower)
    }
}

/// What a walk does at the leaves.
pub(super) trait Visitor {
    /// The current upper bound of the parameters still wanted.
    fn max(&self) -> f64;
    /// Looks at a leaf's items `order[start .. start + count]` (a mesh's
    /// triangles, a scene's primitives); `true` stops the walk.
    fn leaf(&mut self, triangles: &[u32]) -> bool;
    /// Called once per node the walk looks at (to count them; nothing for
    /// an ordinary query).
    #[inline(always)]
    fn node(&mut self) {}
}

/// Walks every leaf whose box the ray's exact segment `[range.min,
/// visitor.max()]` meets, the child of the smaller entry first. The stack holds
/// one pending child per level: [`MAX_DEPTH`] entries, which the builder's
/// depth bound never exceeds.
pub(super) fn walk<V: Visitor, const E: u32>(
    bvh: &TriangleBvh,
    ray: &BoxRay<E>,
    range: Interval,
    v: &mut V,
) {
    let Some(root) = bvh.nodes.first() else {
        return;
    };
    let lo = range.min();
    if !ray.meets(root, lo, v.max()) {
        return;
    }
    let mut stack = [0u32; MAX_DEPTH];
    let mut top = 0;
    let mut at = 0usize;
    loop {
        v.node();
        let node = &bvh.nodes[at];
        let next = if node.count > 0 {
            let start = node.link as usize;
            let items = bvh.order.get(start..start + node.count as usize);
            if v.leaf(items.unwrap_or(&[])) {
                return;
            }
            None
        } else {
            let (a, b) = (at + 1, node.link as usize);
            let max = v.max();
            let (ea, eb) = (
                ray.entry(&bvh.nodes[a], lo, max),
                ray.entry(&bvh.nodes[b], lo, max),
            );
            match (ea, eb) {
                (Some(ta), Some(tb)) => {
                    let (near, far) = if tb < ta { (b, a) } else { (a, b) };
                    // The builder bounds the depth below MAX_DEPTH, so a
                    // slot is always free (see `build.rs`).
                    stack[top] = far as u32;
                    top += 1;
                    Some(near)
                }
                (Some(_), None) => Some(a),
                (None, Some(_)) => Some(b),
                (None, None) => None,
            }
        };
        at = match next {
            Some(n) => n,
            None => loop {
                if top == 0 {
                    return;
                }
                top -= 1;
                let n = stack[top] as usize;
                if ray.meets(&bvh.nodes[n], lo, v.max()) {
                    break n;
                }
            },
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(min: [f64; 3], max: [f64; 3]) -> Node {
        Node {
            min,
            max,
            link: 0,
            count: 1,
        }
    }

    /// Rays that touch the box only on a face, an edge or a corner, with
    /// zero (and negative zero) direction coordinates whose slabs compute
    /// `0 * inf = NaN`, and directions whose reciprocals overflow or are
    /// subnormal (the dividing path), are kept; rays beside the box, or
    /// whose range ends before it, are culled.
    #[test]
    fn slab_test_keeps_every_touching_ray() {
        let unit = node([0.0; 3], [1.0; 3]);
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
        ];
        for (o, d) in keeps {
            let ray = BoxRay::<0>::of(&Ray::new(o, d).unwrap());
            assert!(ray.meets(&unit, 0.0, f64::INFINITY), "{o:?} {d:?}");
        }
        let culls = [
            ([1.0 + 1e-9, 0.5, -1.0], [0.0, 0.0, 1.0], f64::INFINITY),
            ([0.5, 0.5, -1.0], [0.0, 0.0, -1.0], f64::INFINITY),
            ([0.5, 0.5, -1.0], [0.0, 0.0, 1.0], 0.5),
            ([2.0, 2.0, 0.0], [-1.0, -1.0, 1.0], 0.99),
        ];
        for (o, d, max) in culls {
            let ray = BoxRay::<0>::of(&Ray::new(o, d).unwrap());
            assert!(!ray.meets(&unit, 0.0, max), "{o:?} {d:?}");
        }
        // The touching corner ray with its range ending exactly at t = 1.
        let corner = BoxRay::<0>::of(&Ray::new([2.0, 2.0, 0.0], [-1.0, -1.0, 1.0]).unwrap());
        assert!(corner.meets(&unit, 0.0, 1.0));
        // Which path each direction takes.
        let divides = |d: [f64; 3]| BoxRay::<0>::of(&Ray::new([0.0; 3], d).unwrap()).divide;
        assert!(divides([0.0, -tiny, 1.0]) && divides([huge, 0.0, 0.0]));
        assert!(!divides([0.0, -0.0, 1.0]) && !divides([-1.0, 2.0, 1e300]));
    }
}
