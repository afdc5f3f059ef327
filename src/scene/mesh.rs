//! [`TriangleMesh`]: an indexed triangle mesh over the box hierarchy
//! (`bvh::boxes`), its closest hit ([`MeshHit`]) and shadow-ray queries.
//!
//! # What a query decides
//! A triangle is hit when the chosen [`TriangleTest`] hits it (the
//! watertight test by default, [`Exact`] as an option) and the certified
//! parameter of the crossing of its plane ([`TriangleTest::certified_t`],
//! within 4 units of rounding of the exact one) is admitted by the range:
//! the same rule as `Triangle`'s [`RayCast`]. The closest hit is the one
//! with the least certified parameter, the lower triangle index on ties
//! ([`TriangleTest::precedes`]). Degenerate triangles, and triangles so
//! thin that their rounded normal vanishes, are left out of the
//! hierarchy: never hit.
//!
//! # The exact rule
//! With [`Exact`] the triangles are closed sets and every decision is
//! exact (`docs/fixture-format.md`'s `ray_mesh` rule): a ray lying in a triangle's plane
//! touches it along a segment and hits it where it enters (at the range's
//! start when it starts inside; [`Triangle::cast_exact_closed`]); two hits
//! whose certified parameters lie within their error of each other are
//! ordered by their exact parameters, compared in integers, the lower
//! index on exactly equal ones, so the winner contains the exact first
//! point met; and [`TriangleMesh::occluded_between_with`] decides on the
//! exact segment from `p` to `q`. The watertight default keeps its
//! rounded rules: a ray in a triangle's plane is a miss wherever its
//! determinant rounds to zero (it may be a hit where it does not), a ray
//! that only touches a silhouette edge or vertex (the triangles there face
//! it on different sides) may be a miss (the shared edge's one rounded
//! sign puts it inside both triangles or outside both), and near ties are
//! ordered by the certified parameters. Where the ray crosses the surface
//! at a shared edge or vertex of a closed or tiled part of a mesh, it is
//! never missed, at every finite scale (the watertight test evaluates
//! again at powers of two of its own where its products would overflow
//! or underflow: [`Triangle::cast_watertight`]).
//!
//! With [`Exact`], every hit is a crossing of the exact segment with the
//! triangle, so its box is never culled and the queries equal a loop over
//! every triangle. With [`Watertight`], a hit decided by rounding where the
//! exact ray passes within rounding outside the triangle, next to a vertex
//! that bounds the triangle's box, may be culled with the box (a loop over
//! every triangle would report it).
//!
//! [`Exact`]: crate::query::ray::Exact
//! [`Watertight`]: crate::query::ray::Watertight

use super::shading;
use super::spawn::Segment;
use super::topology::{Topology, in_hierarchy};
use crate::bvh::boxes::{BoxBvh, BvhBuilder, Item, Visitor, walk, walk_halved_segment};
use crate::error::InputError;
use crate::interval::Interval;
use crate::point::IntoDVec3;
use crate::query::ray::{Hit, Ray, RayCast, TriangleHit, TriangleTest, Watertight};
use crate::shape::Triangle;
use alloc::vec::Vec;
use core::marker::PhantomData;
use glam::DVec3;

/// Most triangles a mesh holds: `2^31`, so that the `2n - 1` nodes of its
/// hierarchy are indexed by `u32`.
pub const MAX_TRIANGLES: usize = 1 << 31;

/// its indices and its place in the hierarchy).
#[derive(Clone, Debug)]
pub struct TriangleMesh {
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    normals: Option<Vec<DVec3>>,
    pub(super) bvh: BoxBvh,
    /// Whether the mesh is closed, and the triangles the hierarchy leaves
    /// out (`topology.rs`).
    pub(super) topology: Topology,
}

/// The closest hit of a ray on a [`TriangleMesh`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MeshHit {
    /// The index of the triangle hit, in the slice the mesh was built from.
    pub triangle: u32,
    /// The certified hit: its `t` the crossing of the triangle's plane
    /// within 4 units of rounding of the exact one, the point `ray.at(t)`
    /// with its certified per-axis `error`, and the unit geometric normal
    /// `(v1 - v0) x (v2 - v0)` normalized (the front side, whichever side
    /// the ray comes from).
    pub hit: Hit,
    /// The barycentric coordinate of the triangle's second vertex, from the
    /// triangle test.
    pub u: f64,
    /// The barycentric coordinate of its third vertex.
    pub v: f64,
    /// For a mesh with normals, the unit shading normal: the vertex normals
    /// interpolated with the barycentrics `(1 - u - v, u, v)` and
    /// normalized (the geometric normal where that sum vanishes).
    pub shading_normal: Option<DVec3>,
}

impl TriangleMesh {
    /// The mesh of `vertices` (any [`IntoDVec3`]; `f32` widens exactly)
    /// and `triangles` (indices into `vertices`), with its hierarchy built.
    /// Degenerate triangles are accepted and never hit.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] naming `"vertices"` for a NaN or infinite
    /// coordinate; [`InputError::IndexOutOfRange`] for an index not below
    /// `vertices.len()`; [`InputError::TooManyItems`] for more than
    /// [`MAX_TRIANGLES`] triangles.
    pub fn new<P: IntoDVec3>(
        vertices: &[P],
        triangles: &[[u32; 3]],
    ) -> Result<TriangleMesh, InputError> {
        TriangleMesh::with_builder(vertices, triangles, BvhBuilder::default())
    }

    /// [`TriangleMesh::new`] with its hierarchy built by `builder`.
    ///
    /// # Errors
    /// As [`TriangleMesh::new`].
    pub fn with_builder<P: IntoDVec3>(
        vertices: &[P],
        triangles: &[[u32; 3]],
        builder: BvhBuilder,
    ) -> Result<TriangleMesh, InputError> {
        if triangles.len() > MAX_TRIANGLES {
            return Err(InputError::TooManyItems { max: MAX_TRIANGLES });
        }
        let vertices: Vec<DVec3> = vertices.iter().map(|p| p.into_dvec3()).collect();
        if !vertices.iter().all(|p| p.is_finite()) {
            return Err(InputError::NonFinite {
                argument: "vertices",
            });
        }
        let len = vertices.len();
        if let Some(&index) = triangles.iter().flatten().find(|&&i| i as usize >= len) {
            return Err(InputError::IndexOutOfRange {
                index: index as usize,
                len,
            });
        }
        let mut mesh = TriangleMesh {
            vertices,
            triangles: triangles.to_vec(),
            normals: None,
            bvh: BoxBvh::EMPTY,
            topology: Topology::EMPTY,
        };
        let items: Vec<Item> = (0..mesh.triangles.len() as u32)
            .filter_map(|index| {
                let tri = mesh.shape(index);
                // Never hit: left out (see the module docs).
                if !in_hierarchy(&tri) {
                    return None;
                }
                let [a, b, c] = tri.v;
                Some(Item {
                    min: a.min(b).min(c),
                    max: a.max(b).max(c),
                    index,
                })
            })
            .collect();
        mesh.bvh = BoxBvh::build(items, builder);
        mesh.topology = Topology::of(&mesh.triangles, &mesh.bvh.order);
        Ok(mesh)
    }

    /// The mesh with per-vertex `normals`, one per vertex, of any length
    /// (they are interpolated, then normalized: see
    /// [`MeshHit::shading_normal`]; a zero sum falls back to the geometric
    /// normal).
    ///
    /// # Errors
    /// [`InputError::LengthMismatch`] (`expected` the vertex count) when
    /// the counts differ; [`InputError::NonFinite`] naming `"normals"` for
    /// a NaN or infinite coordinate.
    pub fn with_normals<P: IntoDVec3>(mut self, normals: &[P]) -> Result<TriangleMesh, InputError> {
        if normals.len() != self.vertices.len() {
            return Err(InputError::LengthMismatch {
                expected: self.vertices.len(),
                got: normals.len(),
            });
        }
        let normals: Vec<DVec3> = normals.iter().map(|p| p.into_dvec3()).collect();
        if !normals.iter().all(|n| n.is_finite()) {
            return Err(InputError::NonFinite {
                argument: "normals",
            });
        }
        self.normals = Some(normals);
        Ok(self)
    }

    /// The vertices.
    #[inline]
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// The triangles, as given.
    #[inline]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The per-vertex normals, if any.
    #[inline]
    pub fn normals(&self) -> Option<&[DVec3]> {
        self.normals.as_deref()
    }

    /// Triangle `index` as a shape, or `None` for an index not below
    /// `triangles().len()`.
    pub fn triangle(&self, index: usize) -> Option<Triangle> {
        let i = u32::try_from(index).ok()?;
        (index < self.triangles.len()).then(|| self.shape(i))
    }

    /// Triangle `index` (in range: every caller holds one from the mesh);
    /// its degeneracy decided exactly, as `Triangle::new` does.
    #[inline]
    fn shape(&self, index: u32) -> Triangle {
        let [a, b, c] = self.triangles[index as usize].map(|i| self.vertices[i as usize]);
        // Finite: checked at construction.
        Triangle::new(a, b, c).unwrap_or(Triangle {
            v: [a, b, c],
            degenerate: true,
        })
    }

    /// Triangle `index` of the hierarchy (never degenerate: degenerate
    /// ones are left out).
    #[inline(always)]
    fn leaf_shape(&self, index: u32) -> Triangle {
        let v = self.triangles[index as usize].map(|i| self.vertices[i as usize]);
        Triangle {
            v,
            degenerate: false,
        }
    }

    /// The bytes the hierarchy takes beside the mesh (the 8-wide nodes the
    /// queries walk and the leaf order; the builder's binary tree is not
    /// kept), for tests and reports.
    pub fn bvh_bytes(&self) -> usize {
        self.bvh.bytes()
    }

    /// The closest hit of `ray` for `t` in `range`, with the watertight
    /// test ([`Watertight`]); see [`TriangleMesh::closest_hit_with`].
    #[inline]
    pub fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<MeshHit> {
        self.closest_hit_with::<Watertight>(ray, range)
    }

    /// The closest hit of `ray` for `t` in `range` with the triangle test
    /// `T` (the rule in the module docs), or `None`. Never allocates; every
    /// `Ray` and `Interval` is valid input.
    ///
    /// A hit's `t` is certified, so its point's error is
    /// ([`MeshHit::hit`]); the hit point and normal are computed once, for
    /// the winner.
    pub fn closest_hit_with<T: TriangleTest>(&self, ray: &Ray, range: Interval) -> Option<MeshHit> {
        self.closest_counted::<T>(ray, range, None)
    }

    /// [`TriangleMesh::closest_hit_with`], adding the work it did to
    /// `stats` (for tests, tuning and the report; the plain query counts
    /// nothing).
    pub fn closest_hit_with_stats<T: TriangleTest>(
        &self,
        ray: &Ray,
        range: Interval,
        stats: &mut TraceStats,
    ) -> Option<MeshHit> {
        self.closest_counted::<T>(ray, range, Some(stats))
    }

    /// The closest hit, its walk counted into `stats` when given (a
    /// separate instance of the walk, so the plain query has no counters).
    #[inline(always)]
    fn closest_counted<T: TriangleTest>(
        &self,
        ray: &Ray,
        range: Interval,
        stats: Option<&mut TraceStats>,
    ) -> Option<MeshHit> {
        let mut v = Closest::<T> {
            mesh: self,
            ray,
            prepared: T::prepare(ray),
            range,
            best: None,
            test: PhantomData,
        };
        match stats {
            None => walk::<_, 0>(&self.bvh, ray, range, &mut v),
            Some(stats) => walk::<_, 0>(
                &self.bvh,
                ray,
                range,
                &mut Counted {
                    inner: &mut v,
                    stats,
                },
            ),
        }
        let (t, triangle, th) = v.best?;
        Some(self.mesh_hit(ray, t, triangle, &th))
    }

    /// The [`MeshHit`] of `ray` on triangle `triangle` at the certified
    /// parameter `t` with the test's hit `th`: its point, normal and
    /// shading normal.
    #[inline]
    pub(super) fn mesh_hit(&self, ray: &Ray, t: f64, triangle: u32, th: &TriangleHit) -> MeshHit {
        let tri = self.leaf_shape(triangle);
        let normal = tri.normal();
        let shading_normal = self.normals.as_ref().map(|n| {
            let [a, b, c] = self.triangles[triangle as usize].map(|i| n[i as usize]);
            shading::interpolate(a, b, c, th.u, th.v, normal)
        });
        MeshHit {
            triangle,
            hit: Hit::at_plane_t(ray, t, normal),
            u: th.u,
            v: th.v,
            shading_normal,
        }
    }

    /// Whether `ray` meets the mesh for some `t` in `range` (a shadow
    /// ray's question), with the watertight test; see
    /// [`TriangleMesh::occluded_with`].
    #[inline]
    pub fn occluded(&self, ray: &Ray, range: Interval) -> bool {
        self.occluded_with::<Watertight>(ray, range)
    }

    /// Whether [`TriangleMesh::closest_hit_with`] would find a hit: the
    /// walk stops at the first triangle hit. Never allocates.
    pub fn occluded_with<T: TriangleTest>(&self, ray: &Ray, range: Interval) -> bool {
        let mut v = AnyHit::<T> {
            mesh: self,
            ray,
            prepared: T::prepare(ray),
            range,
            found: false,
            test: PhantomData,
        };
        walk::<_, 0>(&self.bvh, ray, range, &mut v);
        v.found
    }

    /// Whether the segment from `p` to `q` meets the mesh (watertight
    /// test): the ray `p + t fl(q - p)` for `t` in `[0, 1]`, whose end is
    /// `q` up to the rounding of the difference. Both ends count; to leave
    /// a surface use [`spawn_ray_to`](super::spawn_ray_to). See
    /// [`TriangleMesh::occluded_between_with`].
    ///
    /// # Errors
    /// As [`TriangleMesh::occluded_between_with`].
    #[inline]
    pub fn occluded_between(
        &self,
        p: impl IntoDVec3,
        q: impl IntoDVec3,
    ) -> Result<bool, InputError> {
        self.occluded_between_with::<Watertight>(p, q)
    }

    /// Whether the closed segment from `p` to `q` meets the mesh with the
    /// triangle test `T` ([`TriangleTest::segment_hit`]): for
    /// [`Watertight`] the ray `p + t fl(q - p)`, `t` in `[0, 1]`, whose end
    /// is `q` up to the rounding of the difference; for [`Exact`] the
    /// exact segment, decided exactly (its end is `q` itself, and a
    /// segment in a triangle's plane meets it where their closed sets
    /// meet). Both ends count; the walk stops at the first triangle met.
    /// Never allocates.
    ///
    /// Every pair of finite ends is a segment: where `q - p` overflows
    /// (ends on opposite sides of the range, farther apart than
    /// `f64::MAX` on some axis) the ray is `p + t d'` for `t` in `[0, 2]`,
    /// `d'` the difference halved (each half exact there) and rounded, so
    /// its end is again `q` up to one rounding of the difference.
    ///
    /// The boxes are culled with that ray, widened by one more rounding
    /// than a ray query's (`traverse.rs`): the exact segment's slab
    /// parameters are the ray's times `1 + δ`, `|δ| <= u`, so no box the
    /// exact segment meets is culled. A halved difference may also round
    /// a tiny coordinate by `2^-1075`; that walk moves every box bound one
    /// more step outward, which covers it.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] naming `"p"` or `"q"` for a NaN or
    /// infinite coordinate. `p == q` is no segment: `Ok(false)`.
    ///
    /// [`Exact`]: crate::query::ray::Exact
    pub fn occluded_between_with<T: TriangleTest>(
        &self,
        p: impl IntoDVec3,
        q: impl IntoDVec3,
    ) -> Result<bool, InputError> {
        Ok(Segment::new(p, q)?.is_some_and(|s| self.meets_segment::<T>(&s)))
    }

    /// Whether `segment` meets the mesh with the triangle test `T`: the
    /// walk of [`TriangleMesh::occluded_between_with`].
    pub(super) fn meets_segment<T: TriangleTest>(&self, segment: &Segment) -> bool {
        let mut v = SegmentHit::<T> {
            mesh: self,
            segment,
            prepared: T::prepare_segment(&segment.ray),
            found: false,
        };
        walk_segment(&self.bvh, segment, segment.range(), &mut v);
        v.found
    }
}

/// The walk over `bvh` that keeps every box `segment`'s exact segment
/// meets for the parameters `range`: one more rounding of the slab
/// parameters than a ray's, and every bound one more step outward for a
/// halved direction ([`Segment`]).
#[inline]
pub(super) fn walk_segment<V: Visitor>(
    bvh: &BoxBvh,
    segment: &Segment,
    range: Interval,
    v: &mut V,
) {
    if segment.halved {
        walk_halved_segment(bvh, &segment.ray, range, v);
    } else {
        walk::<_, 1>(bvh, &segment.ray, range, v);
    }
}

/// The hit of triangle `index` under the module's rule: the test's hit and
/// its certified parameter, admitted by `range`.
#[inline(always)]
fn certified_hit<T: TriangleTest>(
    mesh: &TriangleMesh,
    ray: &Ray,
    prepared: &T::Prepared,
    range: Interval,
    index: u32,
) -> Option<(f64, TriangleHit)> {
    let tri = mesh.leaf_shape(index);
    let hit = T::hit(prepared, &tri, range)?;
    let t = T::certified_t(ray, &tri, &hit);
    range.admits(t).then_some((t, hit))
}

/// The work one query did: see [`TriangleMesh::closest_hit_with_stats`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Nodes of the hierarchy the walk looked at: an 8-wide node (its
    /// children's box tests, in one pass), or a leaf (its triangles).
    pub nodes_visited: u64,
    /// Boxes tested: every lane of each wide node looked at (empty lanes
    /// too: a node's lanes are tested in one pass).
    pub boxes_tested: u64,
    /// Triangles tested in the leaves reached.
    pub triangles_tested: u64,
}

/// A visitor whose walk is counted into `stats`.
struct Counted<'a, V> {
    inner: &'a mut V,
    stats: &'a mut TraceStats,
}

impl<V: Visitor> Visitor for Counted<'_, V> {
    const ORDERED: bool = V::ORDERED;

    #[inline]
    fn max(&self) -> f64 {
        self.inner.max()
    }

    #[inline]
    fn leaf(&mut self, triangles: &[u32]) -> bool {
        self.stats.triangles_tested += triangles.len() as u64;
        self.inner.leaf(triangles)
    }

    #[inline]
    fn node(&mut self, boxes: usize) {
        self.stats.nodes_visited += 1;
        self.stats.boxes_tested += boxes as u64;
    }
}

struct Closest<'a, T: TriangleTest> {
    mesh: &'a TriangleMesh,
    ray: &'a Ray,
    prepared: T::Prepared,
    range: Interval,
    best: Option<(f64, u32, TriangleHit)>,
    test: PhantomData<T>,
}

impl<T: TriangleTest> Visitor for Closest<'_, T> {
    #[inline]
    fn max(&self) -> f64 {
        self.best.map_or(self.range.max(), |b| b.0)
    }

    #[inline]
    fn leaf(&mut self, triangles: &[u32]) -> bool {
        for &index in triangles {
            if let Some((t, hit)) =
                certified_hit::<T>(self.mesh, self.ray, &self.prepared, self.range, index)
            {
                let better = self.best.is_none_or(|(bt, bi, _)| {
                    T::precedes(self.ray, self.range, (t, index), (bt, bi), |i| {
                        self.mesh.leaf_shape(i)
                    })
                });
                if better {
                    self.best = Some((t, index, hit));
                }
            }
        }
        false
    }
}

struct AnyHit<'a, T: TriangleTest> {
    mesh: &'a TriangleMesh,
    ray: &'a Ray,
    prepared: T::Prepared,
    range: Interval,
    found: bool,
    test: PhantomData<T>,
}

impl<T: TriangleTest> Visitor for AnyHit<'_, T> {
    const ORDERED: bool = false;

    #[inline]
    fn max(&self) -> f64 {
        self.range.max()
    }

    #[inline]
    fn leaf(&mut self, triangles: &[u32]) -> bool {
        self.found = triangles.iter().any(|&index| {
            certified_hit::<T>(self.mesh, self.ray, &self.prepared, self.range, index).is_some()
        });
        self.found
    }
}

struct SegmentHit<'a, T: TriangleTest> {
    mesh: &'a TriangleMesh,
    segment: &'a Segment,
    prepared: T::Prepared,
    found: bool,
}

impl<T: TriangleTest> Visitor for SegmentHit<'_, T> {
    const ORDERED: bool = false;

    #[inline]
    fn max(&self) -> f64 {
        self.segment.end()
    }

    #[inline]
    fn leaf(&mut self, triangles: &[u32]) -> bool {
        let s = self.segment;
        self.found = triangles.iter().any(|&index| {
            let tri = self.mesh.leaf_shape(index);
            T::segment_hit(&s.ray, &self.prepared, s.q, s.range(), &tri)
        });
        self.found
    }
}

impl RayCast for TriangleMesh {
    /// [`TriangleMesh::closest_hit`]'s certified hit.
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.closest_hit(ray, range).map(|h| h.hit)
    }

    /// [`TriangleMesh::occluded`].
    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        self.occluded(ray, range)
    }
}

/// A mesh serializes as its vertices, triangles and shading normals (with
/// the `serde` feature); its hierarchy is rebuilt, by the default builder,
/// when it deserializes through [`TriangleMesh::new`] and
/// [`TriangleMesh::with_normals`], so bad data is an [`InputError`].
#[cfg(feature = "serde")]
impl serde::Serialize for TriangleMesh {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        #[derive(serde::Serialize)]
        #[serde(rename = "TriangleMesh")]
        struct Data<'a> {
            vertices: &'a [DVec3],
            triangles: &'a [[u32; 3]],
            normals: Option<&'a [DVec3]>,
        }
        Data {
            vertices: &self.vertices,
            triangles: &self.triangles,
            normals: self.normals.as_deref(),
        }
        .serialize(serializer)
    }
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for TriangleMesh {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        #[derive(serde::Deserialize)]
        #[serde(rename = "TriangleMesh", deny_unknown_fields)]
        struct Data {
            vertices: Vec<DVec3>,
            triangles: Vec<[u32; 3]>,
            #[serde(default)]
            normals: Option<Vec<DVec3>>,
        }
        let d = Data::deserialize(deserializer)?;
        let mesh = TriangleMesh::new(&d.vertices, &d.triangles);
        match d.normals {
            Some(normals) => mesh.and_then(|m| m.with_normals(&normals)),
            None => mesh,
        }
        .map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::bvh::boxes::{LEAF, MAX_DEPTH, WIDTH, WideNode};

    /// Whether lane `l` holds a box (empty lanes are inverted).
    fn used(n: &WideNode, l: usize) -> bool {
        n.min[0][l] <= n.max[0][l]
    }

    /// The wide tree's levels of nodes below `at`, `at`'s own included.
    fn depth(bvh: &BoxBvh, at: usize) -> usize {
        let n = &bvh.nodes[at];
        let below = (0..WIDTH)
            .filter(|&l| used(n, l) && n.count[l] == 0)
            .map(|l| depth(bvh, n.link[l] as usize));
        1 + below.max().unwrap_or(0)
    }

    /// The depth bound holds where the heuristic splits worst: triangles
    /// whose centres grow geometrically (each split peels off a few), and
    /// many identical triangles (no bin can split them).
    #[test]
    fn depth_stays_below_the_stack() {
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        for k in 0..3000u32 {
            let x = 1.5f64.powi(k as i32 % 1500);
            vertices.extend([[x, 0.0, 0.0], [x, 1.0, 0.0], [x, 0.0, 1.0]]);
            triangles.push([3 * k, 3 * k + 1, 3 * k + 2]);
        }
        for _ in 0..3000 {
            triangles.push([0, 1, 2]);
        }
        let mesh = TriangleMesh::new(&vertices, &triangles).unwrap();
        let bvh = &mesh.bvh;
        let d = depth(bvh, 0);
        // Fewer wide levels than MAX_DEPTH: the walk's stack of three
        // pending children per level holds them.
        assert!(d < MAX_DEPTH && d > 5, "{d}");
        let mut triangles_in_leaves = 0;
        for n in &bvh.nodes {
            for l in (0..WIDTH).filter(|&l| used(n, l)) {
                let lane = |k: usize| (n.min[k][l], n.max[k][l]);
                if n.count[l] == 0 {
                    // Every lane's box holds its child's lanes' boxes.
                    let child = &bvh.nodes[n.link[l] as usize];
                    for c in (0..WIDTH).filter(|&c| used(child, c)) {
                        for k in 0..3 {
                            assert!(lane(k).0 <= child.min[k][c] && child.max[k][c] <= lane(k).1);
                        }
                    }
                } else {
                    assert!(n.count[l] as usize <= LEAF);
                    triangles_in_leaves += n.count[l] as usize;
                    let start = n.link[l] as usize;
                    let mut want = (DVec3::INFINITY, DVec3::NEG_INFINITY);
                    for &t in &bvh.order[start..start + n.count[l] as usize] {
                        for p in mesh.shape(t).v {
                            want = (want.0.min(p), want.1.max(p));
                        }
                    }
                    // A leaf lane's box is its triangles' exact box
                    // rounded outward into the frame.
                    let f = &bvh.frame;
                    for k in 0..3 {
                        assert_eq!(lane(k), (f.down(want.0[k], k), f.up(want.1[k], k)));
                    }
                }
            }
            // Slots fill from the first: a node holds at least two
            // children unless it is a root leaf.
            let lanes = (0..WIDTH).filter(|&l| used(n, l)).count();
            assert!(lanes >= 2 || bvh.nodes.len() == 1);
            assert!((0..lanes).all(|l| used(n, l)));
        }
        assert_eq!(triangles_in_leaves, 6000);
    }

    /// One triangle: one wide node whose first lane is the leaf; the empty
    /// mesh: no node, and `bvh_bytes` counts the wide nodes.
    #[test]
    fn small_trees_collapse() {
        let vertices = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let one = TriangleMesh::new(&vertices, &[[0, 1, 2]]).unwrap();
        assert_eq!(one.bvh.nodes.len(), 1);
        assert_eq!(
            (one.bvh.nodes[0].count, one.bvh.nodes[0].link),
            ([1, 0, 0, 0, 0, 0, 0, 0], [0; WIDTH])
        );
        assert_eq!(one.bvh_bytes(), 256 + 4);
        let none = TriangleMesh::new(&vertices, &[[0, 0, 1]]).unwrap();
        assert!(none.bvh.nodes.is_empty() && none.bvh.bounds().is_none());
        let ray = Ray::new([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]).unwrap();
        assert_eq!(one.closest_hit(&ray, Interval::FORWARD).unwrap().hit.t, 1.0);
        assert!(none.closest_hit(&ray, Interval::FORWARD).is_none());
    }
}
