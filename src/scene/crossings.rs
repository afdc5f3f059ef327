//! Every crossing of a ray with a [`TriangleMesh`], in order along the
//! ray ([`TriangleMesh::all_hits`]), and which side of a closed mesh a
//! point lies on ([`TriangleMesh::side`]), both exact.
//!
//! # The ownership rule
//! A ray through a shared edge or vertex of a closed surface meets every
//! triangle there in their closed sets, but crosses the surface once. The
//! rule decides which triangle owns such a crossing by a symbolic
//! perturbation (Edelsbrunner and Mücke's simulation of simplicity): the
//! ray `o + t d` is moved to `o_ε = o + ε e_x' + ε² e_y'` for an
//! infinitesimal `ε > 0`, with `e_x'`, `e_y'` the unit vectors of the two
//! axes other than `d`'s largest coordinate `z'`, so that `d`, `e_x'`,
//! `e_y'` are linearly independent. The moved ray is a real ray, one for
//! every triangle alike, so counting its crossings is counting the
//! crossings of one ray. A triangle `v0 v1 v2` is hit when the three edge
//! determinants `E_pq = det[d, p - o, q - o]` (edges `v1 v2`, `v2 v0`,
//! `v0 v1`) of the moved ray have one non-zero sign. Expanding,
//!
//! `E_pq(ε) = E_pq - ε det[d, e_x', q - p] - ε² det[d, e_y', q - p]`,
//!
//! so its sign is the first non-zero one of `E_pq`, `-det[d, e_x', q -
//! p]`, `-det[d, e_y', q - p]`, each decided exactly (`orient_dir`). All
//! three vanish only for an edge parallel to `d`, whose triangle is then
//! parallel to the ray: the three `E_pq(ε)` sum to `det[d, v1 - v0, v2 -
//! v0] = 0` for every `ε`, so they never share one non-zero sign, and such
//! a triangle, like a triangle whose plane holds the ray and a degenerate
//! one, is never hit. An edge `p q` and its reverse `q p` get opposite
//! signs, at every order.
//!
//! Why each crossing of a closed, consistently oriented surface counts
//! once: the moved ray passes through no edge and no vertex (each `E_pq(ε)`
//! is non-zero but for edges parallel to it, which it cannot meet without
//! lying in their triangles' planes, which it is parallel to and, for
//! small enough `ε`, off), so it meets the surface only in triangles'
//! interiors, each a transversal crossing counted once; for small enough
//! `ε` its crossings are at the original ray's crossing points, since
//! each triangle's hit or miss is the sign pattern of polynomials in `ε`.
//! Where the original ray passes through an edge shared by `T1` (along
//! `p q`) and `T2` (along `q p`), the moved ray lies on one side of the
//! edge, in `T1` or `T2` alone when the surface crosses the ray there, in
//! both or neither when it only touches it. So, for a ray whose origin is
//! off the surface and whose range is `[0, ∞)`, the number of hits has the
//! parity of the number of times the surface winds around the origin
//! ([`TriangleMesh::side`]): odd inside a closed mesh that does not cross
//! itself, even outside it. (The range admits a hit by its certified `t`,
//! as every mesh query does: a crossing whose exact parameter is within
//! about `2^-1072` of `0`, an origin that close to the surface, may fall
//! on the other side of the range's start.) The hits' parameters are the exact
//! parameters of the original ray's crossings (the perturbation moves
//! none of them past another: they are compared exactly, unperturbed).
//!
//! The watertight test has no such rule: where a ray passes within
//! rounding of a shared edge, its one rounded edge sign puts the ray
//! inside both triangles or neither (never neither where the surface
//! crosses, but possibly both), so its crossings may count twice and the
//! parity fails there. The queries here always decide with exact signs.
//!
//! # Side of a point
//! [`TriangleMesh::side`] is the winding number of the mesh around the
//! point: the signed crossings of the ray from the point along `+x`, with
//! the point moved to `p + (0, ε, ε²)` (the rule above, for this ray),
//! so in the projection on the `y z` plane every edge sign is decided by
//! `orient2d`, then by comparisons of the edge's coordinates; whether the
//! crossing lies ahead of the point is the sign of `orient3d`. A point
//! off the surface is at a positive distance from it, so the moved point
//! has the point's own winding number; a point on the surface is found
//! first, exactly (`orient3d` zero and the point in the closed triangle).

use super::mesh::{MeshHit, TriangleMesh};
use crate::arith::roundoff::U;
use crate::bvh::boxes::{Visitor, walk};
use crate::error::InputError;
use crate::interval::Interval;
use crate::point::IntoDVec3;
use crate::predicates::orient_dir::orient_dir;
use crate::predicates::{orient2d, orient3d};
use crate::query::ray::{Exact, ExactRay, Ray, TriangleHit, TriangleTest};
use crate::shape::Triangle;
use crate::sign::Sign;
use core::iter::FusedIterator;
use core::ops::ControlFlow;
use glam::{DVec2, DVec3};

/// Where a point lies against a closed mesh ([`TriangleMesh::side`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum MeshSide {
    /// The mesh winds around the point a non-zero number of times: inside
    /// the solid a closed mesh that does not cross itself bounds.
    Inside,
    /// The mesh winds around the point zero times.
    Outside,
    /// The point lies on a triangle of the mesh (its closed set; the
    /// segment or point a degenerate triangle is).
    OnBoundary,
}

/// What [`TriangleMesh::all_hits_into`] wrote.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HitCount {
    /// The hits written, at the start of the buffer.
    pub count: usize,
    /// Whether the ray has more hits than the buffer holds (the ones
    /// written are then the first `count`).
    pub truncated: bool,
}

impl TriangleMesh {
    /// Whether the mesh is closed and consistently oriented: every edge
    /// `u v` of a triangle with three distinct vertex indices belongs to
    /// exactly one such triangle running along it from `u` to `v`, and to
    /// exactly one other running from `v` to `u` (triangles with a
    /// repeated index are left out of the count: they bound nothing).
    /// Decided on the indices when the mesh is built (a sort of its `3n`
    /// directed edges), so this is free.
    #[inline]
    pub fn is_closed(&self) -> bool {
        self.topology.closed
    }

    /// Where `point` lies against the mesh, exactly, for every finite
    /// point: [`MeshSide::OnBoundary`] when it lies on a triangle (closed
    /// sets, degenerate triangles included), else [`MeshSide::Inside`]
    /// when the mesh winds around it a non-zero number of times (its
    /// winding number, exact), else [`MeshSide::Outside`]. A closed mesh
    /// that does not cross itself winds once around every point inside
    /// the solid it bounds (`+1` with its triangles counterclockwise seen
    /// from outside, `-1` the other way round) and zero times around every
    /// point outside. The rule, and why it is exact: the module docs of
    /// `crossings.rs` (the ray from the point along `+x`, perturbed
    /// symbolically).
    ///
    /// Never allocates. The walk tests the triangles whose boxes the ray
    /// from the point along `+x` meets (each with exact `orient2d` and
    /// `orient3d` signs) and the few the hierarchy leaves out.
    ///
    /// ```
    /// use exactray::scene::{MeshSide, TriangleMesh};
    /// // The octahedron |x| + |y| + |z| <= 1, counterclockwise from outside.
    /// let v = [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
    ///          [0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]];
    /// let t = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
    ///          [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]];
    /// let mesh = TriangleMesh::new(&v, &t).unwrap();
    /// assert_eq!(mesh.side([0.0, 0.0, 0.0]), Ok(MeshSide::Inside));
    /// // On a vertex, an edge's midpoint, and just beyond a face.
    /// assert_eq!(mesh.side([1.0, 0.0, 0.0]), Ok(MeshSide::OnBoundary));
    /// assert_eq!(mesh.side([0.5, 0.5, 0.0]), Ok(MeshSide::OnBoundary));
    /// assert_eq!(mesh.side([0.5, 0.25, 0.25 + 1e-16]), Ok(MeshSide::Outside));
    /// ```
    ///
    /// # Errors
    /// [`InputError::NonFinite`] naming `"point"` for a NaN or infinite
    /// coordinate; [`InputError::OpenMesh`] when the mesh is not closed
    /// ([`TriangleMesh::is_closed`]).
    pub fn side(&self, point: impl IntoDVec3) -> Result<MeshSide, InputError> {
        let p = point.into_dvec3();
        if !p.is_finite() {
            return Err(InputError::NonFinite { argument: "point" });
        }
        if !self.topology.closed {
            return Err(InputError::OpenMesh);
        }
        let ray = Ray::new(p, DVec3::X)?;
        let mut v = SideWalk {
            mesh: self,
            p,
            winding: 0,
            on_boundary: false,
        };
        walk::<_, 0>(&self.bvh, &ray, Interval::FORWARD, &mut v);
        for &i in &self.topology.left_out {
            if v.on_boundary {
                break;
            }
            if let Some(tri) = self.triangle(i as usize) {
                v.visit(&tri.v, tri.degenerate);
            }
        }
        Ok(if v.on_boundary {
            MeshSide::OnBoundary
        } else if v.winding != 0 {
            MeshSide::Inside
        } else {
            MeshSide::Outside
        })
    }

    /// Every crossing of `ray` with the mesh for `t` in `range`, in the
    /// exact order of their parameters (the lower triangle index first
    /// where two are exactly equal), as an iterator that never allocates.
    ///
    /// A triangle is hit under the ownership rule of the module docs of
    /// `crossings.rs`: exact signs ([`Exact`]'s test) of the ray moved by
    /// a symbolic perturbation, so a ray through a shared edge or vertex
    /// of a closed, consistently oriented mesh reports that crossing once
    /// (none, or one from each side, where it only touches the surface
    /// there), and for a ray whose origin is off the surface, over
    /// [`Interval::FORWARD`], the number of hits is odd exactly when the
    /// origin is inside a closed mesh that does not cross itself. A
    /// triangle whose plane holds the ray, or that is parallel to it, is
    /// never hit (nor a degenerate one); a triangle too thin for the other
    /// queries (left out of the hierarchy) is, with a zero normal.
    /// Each hit's `t` is the certified crossing of its plane (within 4
    /// units of rounding of the exact one) and is admitted by `range`, as
    /// for [`TriangleMesh::closest_hit_with`] (so a crossing beyond `f64`'s
    /// range is none).
    ///
    /// Cost: each hit is one walk of the hierarchy for the least hit after
    /// the previous one (the walk starting there), so `k` hits cost `k + 1`
    /// walks, each with up to three exact edge signs per triangle it hits.
    ///
    /// There is no watertight form: the watertight test (the default of
    /// [`TriangleMesh::closest_hit`]) never lets a ray through a shared
    /// edge, but its one rounded sign there may put the ray in both
    /// triangles, counting a crossing twice, and a ray within rounding of
    /// an edge may be given the other triangle than the exact one.
    ///
    /// ```
    /// use exactray::prelude::*;
    /// use exactray::scene::TriangleMesh;
    /// // Two unit squares at z = 1 and z = 2, each two triangles.
    /// let v = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 1.0, 1.0],
    ///          [0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [1.0, 1.0, 2.0], [0.0, 1.0, 2.0]];
    /// let t = [[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]];
    /// let mesh = TriangleMesh::new(&v, &t).unwrap();
    /// // Through the shared diagonals: one hit per square.
    /// let ray = Ray::new([0.5, 0.5, 0.0], [0.0, 0.0, 1.0]).unwrap();
    /// let ts: Vec<f64> = mesh.all_hits(&ray, Interval::FORWARD).map(|h| h.hit.t).collect();
    /// assert_eq!(ts, [1.0, 2.0]);
    /// ```
    ///
    /// [`Exact`]: crate::query::ray::Exact
    pub fn all_hits(&self, ray: &Ray, range: Interval) -> MeshCrossings<'_> {
        MeshCrossings {
            mesh: self,
            ray: *ray,
            prepared: ExactRay::new(ray),
            axes: perturbation_axes(ray.direction()),
            range,
            after: None,
            done: false,
        }
    }

    /// [`TriangleMesh::all_hits`] through a visitor: `visit` is called with
    /// each hit in order until it returns [`ControlFlow::Break`]. Returns
    /// the number of hits visited. Never allocates.
    pub fn visit_all_hits<F: FnMut(MeshHit) -> ControlFlow<()>>(
        &self,
        ray: &Ray,
        range: Interval,
        mut visit: F,
    ) -> usize {
        let mut count = 0;
        for hit in self.all_hits(ray, range) {
            count += 1;
            if visit(hit).is_break() {
                break;
            }
        }
        count
    }

    /// [`TriangleMesh::all_hits`] written into `hits`, the first ones
    /// first: how many were written and whether more remain (one more walk
    /// finds out when `hits` fills). Never allocates.
    pub fn all_hits_into(&self, ray: &Ray, range: Interval, hits: &mut [MeshHit]) -> HitCount {
        let mut crossings = self.all_hits(ray, range);
        let mut count = 0;
        for slot in hits.iter_mut() {
            match crossings.next() {
                Some(hit) => *slot = hit,
                None => {
                    return HitCount {
                        count,
                        truncated: false,
                    };
                }
            }
            count += 1;
        }
        HitCount {
            count,
            truncated: crossings.next().is_some(),
        }
    }

    /// The vertices of triangle `index` (in range: every caller holds one
    /// from the mesh).
    #[inline(always)]
    pub(super) fn corners(&self, index: u32) -> [DVec3; 3] {
        self.triangles()[index as usize].map(|i| self.vertices()[i as usize])
    }
}

/// The hits of [`TriangleMesh::all_hits`], in order.
#[derive(Clone, Debug)]
pub struct MeshCrossings<'a> {
    mesh: &'a TriangleMesh,
    ray: Ray,
    prepared: ExactRay,
    axes: [usize; 2],
    range: Interval,
    /// The last hit given, as (certified `t`, triangle).
    after: Option<(f64, u32)>,
    done: bool,
}

impl Iterator for MeshCrossings<'_> {
    type Item = MeshHit;

    fn next(&mut self) -> Option<MeshHit> {
        if self.done {
            return None;
        }
        let mut v = NextHit {
            mesh: self.mesh,
            ray: &self.ray,
            prepared: &self.prepared,
            axes: self.axes,
            range: self.range,
            after: self.after,
            best: None,
        };
        // A hit after `(t, i)` has its exact parameter at least that of
        // `t`'s, so at least `t - e(t)` (`reach`): boxes before are culled.
        let start = self.after.map_or(self.range.min(), |(t, _)| {
            self.range.min().max(t - reach(t))
        });
        let walk_range = Interval::new(start, self.range.max()).unwrap_or(self.range);
        walk::<_, 0>(&self.mesh.bvh, &self.ray, walk_range, &mut v);
        for &i in &self.mesh.topology.left_out {
            // Degenerate ones are never hit (module docs): skipped.
            if let Some(tri) = self.mesh.triangle(i as usize).filter(|t| !t.degenerate) {
                v.consider(i, &tri);
            }
        }
        let Some((t, triangle, hit)) = v.best else {
            self.done = true;
            return None;
        };
        self.after = Some((t, triangle));
        Some(self.mesh.mesh_hit(&self.ray, t, triangle, &hit))
    }
}

impl FusedIterator for MeshCrossings<'_> {}

/// Twice a bound on the distance from a certified parameter `t` to its
/// exact one: `Exact::precedes` derives `|t - t*| <= 5u |t| + 2^-1072 =
/// E(t)` (within 4 units of rounding, `EXACT_T_ULPS`, and a subnormal
/// term). `fl(t ± 2 E(t))` is then beyond `t ± E(t)`: its rounding is at
/// most `u (|t| + 2 E(t)) < E(t)`.
#[inline]
fn reach(t: f64) -> f64 {
    /// `2^-1072`.
    const TINY4: f64 = f64::from_bits(4);
    2.0 * (5.0 * U * t.abs() + TINY4)
}

/// The walk for the least hit after `after`, under the ownership rule.
struct NextHit<'a> {
    mesh: &'a TriangleMesh,
    ray: &'a Ray,
    prepared: &'a ExactRay,
    axes: [usize; 2],
    range: Interval,
    after: Option<(f64, u32)>,
    best: Option<(f64, u32, TriangleHit)>,
}

impl NextHit<'_> {
    /// Keeps triangle `index` (not degenerate), `tri`, when the rule hits
    /// it after `after` and before the best so far.
    #[inline]
    fn consider(&mut self, index: u32, tri: &Triangle) {
        // A hit of the rule is a hit of the closed triangle (its signs are
        // the exact ones where those are non-zero), so the exact closed
        // test screens first, and gives `t`.
        let Some(hit) = self.prepared.cast_closed(tri, self.range) else {
            return;
        };
        let key = (hit.t, index);
        let (ray, range, mesh) = (self.ray, self.range, self.mesh);
        let shape = |i: u32| Triangle {
            v: mesh.corners(i),
            degenerate: false,
        };
        // A triangle is crossed once: the last one given is not after
        // itself (and its exact order with itself is not computed).
        let later = self
            .after
            .is_none_or(|a| a.1 != index && Exact::precedes(ray, range, a, key, shape));
        let sooner = self
            .best
            .is_none_or(|(t, i, _)| Exact::precedes(ray, range, key, (t, i), shape));
        if later && sooner && owns(ray, self.axes, tri) {
            self.best = Some((hit.t, index, hit));
        }
    }
}

impl Visitor for NextHit<'_> {
    /// The best hit so far, widened by its error (`reach`): a hit the
    /// exact order puts before it lies before that.
    #[inline]
    fn max(&self) -> f64 {
        self.best.map_or(self.range.max(), |(t, _, _)| {
            self.range.max().min(t + reach(t))
        })
    }

    #[inline]
    fn leaf(&mut self, triangles: &[u32]) -> bool {
        for &index in triangles {
            // In the hierarchy: not degenerate.
            let tri = Triangle {
                v: self.mesh.corners(index),
                degenerate: false,
            };
            self.consider(index, &tri);
        }
        false
    }
}

/// The axes `x'`, `y'` of the perturbation: the two other than that of
/// `d`'s largest coordinate, so that `d` and their unit vectors are
/// linearly independent.
#[inline]
fn perturbation_axes(d: DVec3) -> [usize; 2] {
    let a = d.abs();
    let z = if a.x >= a.y && a.x >= a.z {
        0
    } else if a.y >= a.z {
        1
    } else {
        2
    };
    [(z + 1) % 3, (z + 2) % 3]
}

/// Whether the ray moved by the ownership rule hits `tri`: the three
/// perturbed edge signs share one non-zero sign.
#[inline]
fn owns(ray: &Ray, axes: [usize; 2], tri: &Triangle) -> bool {
    let [a, b, c] = tri.v;
    let s = [(b, c), (c, a), (a, b)].map(|(p, q)| perturbed_edge_sign(ray, axes, p, q));
    s[0] != Sign::Zero && s[0] == s[1] && s[1] == s[2]
}

/// The sign of `E_pq(ε)` for the edge `p -> q` (module docs): that of
/// `det[d, p - o, q - o]`, else of `-det[d, e_x', q - p]`, else of
/// `-det[d, e_y', q - p]`; zero only for an edge parallel to `d`.
#[inline]
fn perturbed_edge_sign(ray: &Ray, axes: [usize; 2], p: DVec3, q: DVec3) -> Sign {
    let (o, d) = (ray.origin(), ray.direction());
    let exact = orient_dir(d, o, p, q);
    if exact != Sign::Zero {
        return exact;
    }
    for k in axes {
        let s = axis_term(d, k, p, q);
        if s != Sign::Zero {
            return -s;
        }
    }
    Sign::Zero
}

/// The exact sign of `det[d, e_k, q - p]`: `orient_dir(d, o', p, q) =
/// det[d, p - o', q - o']` with `o'` the point `p` moved along axis `k` to
/// its neighbouring `f64`, so `p - o' = δ e_k` exactly (in the exact
/// predicate) with `δ != 0`, and the determinant is `δ det[d, e_k, q - p]`
/// (`q - o' = q - p + δ e_k`, whose `e_k` part drops out).
#[inline]
fn axis_term(d: DVec3, k: usize, p: DVec3, q: DVec3) -> Sign {
    let mut o = p;
    // Below `p` (`δ > 0`) unless `p[k]` is the least `f64`.
    let below = p[k] > f64::MIN;
    o[k] = if below {
        p[k].next_down()
    } else {
        p[k].next_up()
    };
    let s = orient_dir(d, o, p, q);
    if below { s } else { -s }
}

/// The walk of [`TriangleMesh::side`]: the winding number so far, unless
/// the point was found on a triangle.
struct SideWalk<'a> {
    mesh: &'a TriangleMesh,
    p: DVec3,
    winding: i64,
    on_boundary: bool,
}

impl SideWalk<'_> {
    /// Adds the crossing of the triangle of vertices `v`; `true` (and
    /// `on_boundary`) when the point lies on it.
    #[inline]
    fn visit(&mut self, v: &[DVec3; 3], degenerate: bool) -> bool {
        let p = self.p;
        let (lo, hi) = (v[0].min(v[1]).min(v[2]), v[0].max(v[1]).max(v[2]));
        // Neither on the triangle nor crossed by the ray along +x from a
        // point outside its box's y z extent or beyond its largest x.
        if p.y < lo.y || p.y > hi.y || p.z < lo.z || p.z > hi.z || p.x > hi.x {
            return false;
        }
        if on_closed_triangle(p, v, degenerate) {
            self.on_boundary = true;
            return true;
        }
        if !degenerate {
            self.winding += x_ray_crossing(p, v);
        }
        false
    }
}

impl Visitor for SideWalk<'_> {
    const ORDERED: bool = false;

    #[inline]
    fn max(&self) -> f64 {
        f64::INFINITY
    }

    #[inline]
    fn leaf(&mut self, triangles: &[u32]) -> bool {
        triangles
            .iter()
            .any(|&i| self.visit(&self.mesh.corners(i), false))
    }
}

/// Whether `p` lies on the closed triangle `v` (a segment or a point when
/// `degenerate`), exactly: in its plane (`orient3d` zero) and inside or on
/// its three edges in a coordinate plane where its projection has an area.
pub(super) fn on_closed_triangle(p: DVec3, v: &[DVec3; 3], degenerate: bool) -> bool {
    if degenerate {
        return (0..3).any(|i| on_segment(p, v[i], v[(i + 1) % 3]));
    }
    if orient3d(v[0], v[1], v[2], p) != Sign::Zero {
        return false;
    }
    for (i, j) in [(1, 2), (2, 0), (0, 1)] {
        let proj = |q: DVec3| DVec2::new(q[i], q[j]);
        let area = orient2d(proj(v[0]), proj(v[1]), proj(v[2]));
        if area != Sign::Zero {
            return (0..3).all(|k| {
                let s = orient2d(proj(v[k]), proj(v[(k + 1) % 3]), proj(p));
                s == area || s == Sign::Zero
            });
        }
    }
    // Not reached: a triangle that is not degenerate has an area in some
    // coordinate plane.
    false
}

/// Whether `p` lies on the closed segment `a b`: in its box, and collinear
/// (the cross product of `b - a` and `p - a` vanishes exactly when its
/// three coordinate-plane projections, `orient2d`, do).
fn on_segment(p: DVec3, a: DVec3, b: DVec3) -> bool {
    let inside = p.cmpge(a.min(b)).all() && p.cmple(a.max(b)).all();
    inside
        && [(0, 1), (1, 2), (2, 0)].iter().all(|&(i, j)| {
            let proj = |q: DVec3| DVec2::new(q[i], q[j]);
            orient2d(proj(a), proj(b), proj(p)) == Sign::Zero
        })
}

/// The signed crossing of the ray from `p + (0, ε, ε²)` along `+x` with
/// the triangle `v` (not degenerate, and `p` not on it): `±1` (the sign
/// of the normal's `x` coordinate, `+1` leaving through a face that faces
/// `+x`) when the ray crosses it, else `0`.
///
/// In the `y z` projection the triangle has the orientation `n_x` (the `x`
/// coordinate of `(v1 - v0) x (v2 - v0)` is `orient2d` of the projected
/// vertices); zero is a triangle parallel to the ray, never crossed. The
/// moved point `q + (ε, ε²)` lies on the inner side of the projected edge
/// `a -> b` when `orient2d(a, b, q) + (b_z - a_z)(-ε) + (b_y - a_y) ε²`
/// has the sign of `n_x`: `orient2d(a, b, q)`, else `a_z - b_z`, else
/// `b_y - a_y`, never all zero (the projected vertices are distinct). The
/// crossing is at `t = -n . (p - v0) / n_x`, ahead when `orient3d(v0, v1,
/// v2, p) = sign(n . (p - v0))` is `-n_x` (never zero: the point moved
/// inside the projection but in the plane would be on the triangle).
fn x_ray_crossing(p: DVec3, v: &[DVec3; 3]) -> i64 {
    let proj = |q: DVec3| DVec2::new(q.y, q.z);
    let [a, b, c] = v.map(proj);
    let q = proj(p);
    let n_x = orient2d(a, b, c);
    if n_x == Sign::Zero {
        return 0;
    }
    let inside = [(a, b), (b, c), (c, a)]
        .iter()
        .all(|&(e0, e1)| perturbed_side(e0, e1, q) == n_x);
    if inside && orient3d(v[0], v[1], v[2], p) == -n_x {
        i64::from(n_x == Sign::Positive) - i64::from(n_x == Sign::Negative)
    } else {
        0
    }
}

/// The sign of `orient2d(a, b, q + (ε, ε²))` ([`x_ray_crossing`]).
#[inline]
fn perturbed_side(a: DVec2, b: DVec2, q: DVec2) -> Sign {
    let s = orient2d(a, b, q);
    if s != Sign::Zero {
        return s;
    }
    let by_order = |x: f64, y: f64| {
        if x > y {
            Sign::Positive
        } else if x < y {
            Sign::Negative
        } else {
            Sign::Zero
        }
    };
    match by_order(a.y, b.y) {
        Sign::Zero => by_order(b.x, a.x),
        s => s,
    }
}
