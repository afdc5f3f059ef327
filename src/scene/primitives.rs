//! A [`Scene`] of primitives: triangle meshes and analytic shapes, each
//! with a stable [`PrimitiveId`], under a two-level hierarchy.
//!
//! [`Scene`]'s docs give the rule its queries follow and what its
//! hierarchy guarantees.

use super::mesh::walk_segment;
use super::spawn::Segment;
use super::{MeshHit, TriangleMesh};
use crate::arith::roundoff::gamma;
use crate::bvh::boxes::{BoxBvh, BvhBuilder, Item, Visitor, walk};
use crate::error::InputError;
use crate::interval::Interval;
use crate::point::IntoDVec3;
use crate::query::ray::{Hit, Ray, RayCast, TriangleTest, Watertight};
use crate::roots::BoundedRoot;
use crate::shape::{Aabb, Bounded, CappedCylinder, Cone, Cylinder, Disk, Plane, Quadric, Sphere};
use alloc::vec::Vec;
use core::marker::PhantomData;
use glam::DVec3;

/// Most primitives a scene holds: `2^31`, so that the nodes of its
/// hierarchy are indexed by `u32`.
pub const MAX_PRIMITIVES: usize = 1 << 31;

/// The id of a primitive in its [`Scene`]: its place in insertion order,
/// from 0 (what [`SceneBuilder::add`] returned), stable for the scene's
/// life; index your own material tables with it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PrimitiveId(pub u32);

impl PrimitiveId {
    /// The id as an index into [`Scene::primitives`].
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// An analytic shape of a scene, cast with its own [`RayCast`] (never
/// tessellated).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum AnalyticShape {
    /// A sphere.
    Sphere(Sphere),
    /// An infinite cylinder (unbounded: in the scene's flat list).
    Cylinder(Cylinder),
    /// A capped cylinder.
    CappedCylinder(CappedCylinder),
    /// A cone, capped or infinite (the second in the flat list).
    Cone(Cone),
    /// A general quadric (unbounded: in the flat list).
    Quadric(Quadric),
    /// A disk.
    Disk(Disk),
    /// A plane (unbounded: in the flat list).
    Plane(Plane),
}

/// `match` over every shape, binding it to `$s`.
macro_rules! each_shape {
    ($shape:expr, $s:ident => $e:expr) => {
        match $shape {
            AnalyticShape::Sphere($s) => $e,
            AnalyticShape::Cylinder($s) => $e,
            AnalyticShape::CappedCylinder($s) => $e,
            AnalyticShape::Cone($s) => $e,
            AnalyticShape::Quadric($s) => $e,
            AnalyticShape::Disk($s) => $e,
            AnalyticShape::Plane($s) => $e,
        }
    };
}

impl RayCast for AnalyticShape {
    /// The shape's own cast.
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        each_shape!(self, s => s.cast(ray, range))
    }

    /// The shape's own `cast_bounded`.
    #[inline]
    fn cast_bounded(&self, ray: &Ray, range: Interval) -> Option<BoundedRoot> {
        each_shape!(self, s => s.cast_bounded(ray, range))
    }

    /// The shape's own `cast_t`.
    #[inline]
    fn cast_t(&self, ray: &Ray, range: Interval) -> Option<f64> {
        each_shape!(self, s => s.cast_t(ray, range))
    }

    /// The shape's own `hits`.
    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        each_shape!(self, s => s.hits(ray, range))
    }
}

impl Bounded for AnalyticShape {
    /// The shape's own box (`None` for an unbounded shape).
    #[inline]
    fn aabb(&self) -> Option<Aabb> {
        each_shape!(self, s => s.aabb())
    }
}

/// A primitive of a scene: a triangle mesh or an analytic shape. Every
/// shape type and [`TriangleMesh`] converts into it (`From`), so
/// [`SceneBuilder::add`] takes them directly.
#[derive(Clone, Debug)]
pub enum Primitive {
    /// A triangle mesh with its own hierarchy.
    Mesh(TriangleMesh),
    /// An analytic shape.
    Shape(AnalyticShape),
}

impl From<TriangleMesh> for Primitive {
    #[inline]
    fn from(mesh: TriangleMesh) -> Primitive {
        Primitive::Mesh(mesh)
    }
}

impl From<AnalyticShape> for Primitive {
    #[inline]
    fn from(shape: AnalyticShape) -> Primitive {
        Primitive::Shape(shape)
    }
}

macro_rules! shape_conversions {
    ($($shape:ident),*) => {$(
        impl From<$shape> for AnalyticShape {
            #[inline]
            fn from(shape: $shape) -> AnalyticShape {
                AnalyticShape::$shape(shape)
            }
        }

        impl From<$shape> for Primitive {
            #[inline]
            fn from(shape: $shape) -> Primitive {
                Primitive::Shape(AnalyticShape::$shape(shape))
            }
        }
    )*};
}
shape_conversions!(Sphere, Cylinder, CappedCylinder, Cone, Quadric, Disk, Plane);

/// Collects primitives, then builds the [`Scene`]'s hierarchy once
/// ([`SceneBuilder::build`]).
#[derive(Clone, Debug, Default)]
pub struct SceneBuilder {
    primitives: Vec<Primitive>,
}

impl SceneBuilder {
    /// An empty builder.
    #[inline]
    pub fn new() -> SceneBuilder {
        SceneBuilder::default()
    }

    /// Adds a primitive (a [`TriangleMesh`], any shape, or a
    /// [`Primitive`]) and returns its id: the number of primitives added
    /// before it. Shapes and meshes are validated by their own
    /// constructors, so every one is accepted.
    ///
    /// # Errors
    /// [`InputError::TooManyItems`] when the builder already holds
    /// [`MAX_PRIMITIVES`]; nothing is added then.
    pub fn add(&mut self, primitive: impl Into<Primitive>) -> Result<PrimitiveId, InputError> {
        let id = self.primitives.len();
        if id >= MAX_PRIMITIVES {
            return Err(InputError::TooManyItems {
                max: MAX_PRIMITIVES,
            });
        }
        self.primitives.push(primitive.into());
        Ok(PrimitiveId(id as u32))
    }

    /// The scene, its top-level hierarchy built (see the module docs);
    /// an empty builder gives the empty scene, which no ray hits.
    pub fn build(self) -> Scene {
        let mut items = Vec::new();
        let mut unbounded = Vec::new();
        for (id, primitive) in self.primitives.iter().enumerate() {
            // Below MAX_PRIMITIVES: `add` checked.
            let index = id as u32;
            match primitive {
                // A mesh without a root has no hittable triangle: never
                // tested.
                Primitive::Mesh(mesh) => {
                    if let Some((min, max)) = mesh.bvh.bounds() {
                        items.push(Item { min, max, index });
                    }
                }
                Primitive::Shape(shape) => match shape
                    .aabb()
                    .filter(|b| b.min().is_finite() && b.max().is_finite())
                {
                    Some(b) => items.push(Item {
                        min: b.min(),
                        max: b.max(),
                        index,
                    }),
                    None => unbounded.push(index),
                },
            }
        }
        Scene {
            primitives: self.primitives,
            bvh: BoxBvh::build(items, BvhBuilder::BinnedSah),
            unbounded,
        }
    }
}

/// Meshes and analytic shapes under a two-level hierarchy, ready for ray
/// queries. Build it with [`SceneBuilder`]. It stores the primitives, the
/// top-level hierarchy and the ids of the unbounded primitives: what its
/// queries read.
///
/// # Two levels
/// A primitive with a finite box (a mesh's: the exact box of its
/// hittable triangles, its hierarchy's root; a bounded shape's:
/// [`Bounded::aabb`], rounded outward) is an item of the top-level
/// hierarchy, built by the meshes' own binned-SAH builder (`build.rs`)
/// and walked by their conservative walk (`traverse.rs`); a mesh's own
/// hierarchy is the second level. The others (planes, infinite cylinders
/// and cones, general quadrics, and any shape whose box overflows) are
/// kept in a flat list that every query tests first. Analytic shapes stay
/// analytic: their own [`RayCast`], never a tessellation. A mesh with no
/// hittable triangle is kept (its id stays valid) but never tested.
///
/// # What a query decides
/// The closest hit is the one of least `t` among every primitive's own
/// answer for the query's range, the lower id on ties: a shape's
/// [`RayCast::cast_t`], a mesh's [`TriangleMesh::closest_hit_with`] with
/// the query's triangle test. A mesh is asked for the range clipped to the
/// best `t` found so far (its hits depend on the range's lower end only,
/// so the clipped answer is its full answer whenever that can still win);
/// a shape is always asked for the whole range (a ray lying on a
/// cylinder's or a quadric's surface hits at the point of the range
/// nearest `t = 0`, which clipping the range would move).
///
/// # Culling
/// The walk keeps every box that the ray's exact segment meets (see
/// `traverse.rs`) for the segment `[lo, hi]` (`hi` the best `t` so far)
/// widened by `gamma(18) |lo| + 2^-1068` below and `gamma(18) |hi| +
/// 2^-1068` above: a hit at a
/// computed `t` in the range whose exact crossing lies within `gamma(16)
/// |t| + 2^-1070` of `t`, at a point of the primitive's box, is never
/// culled. That covers a mesh's triangles (certified `t`, 4 units of
/// rounding; with the watertight test, the mesh's own documented
/// exception at box-bounding vertices remains) and the quadric roots of
/// spheres, cylinders and cones (`gamma(16) |t|`, the casts' certified
/// bound). It does not cover, and a loop over every primitive may then
/// report a hit the scene culls with its box: a disk's, cap's or cone
/// base's plane parameter where the numerator cancels (an origin within
/// rounding of the disk's plane) and the crossing lies within that error
/// of the box's face; a rim decided in `f64` within a few ulps of where it
/// touches its box.
///
/// ```
/// use exactray::prelude::*;
/// let mut builder = SceneBuilder::new();
/// let floor = builder.add(Plane::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]).unwrap()).unwrap();
/// let ball = builder.add(Sphere::new([0.0, 0.0, 2.0], 1.0).unwrap()).unwrap();
/// let vertices = [[2.0, -1.0, 1.0], [4.0, -1.0, 1.0], [3.0, 1.0, 1.0]];
/// let tile = builder.add(TriangleMesh::new(&vertices, &[[0, 1, 2]]).unwrap()).unwrap();
/// let scene = builder.build();
///
/// let down = |x: f64| Ray::new([x, 0.0, 5.0], [0.0, 0.0, -1.0]).unwrap();
/// let hit = scene.closest_hit(&down(0.0), Interval::FORWARD).unwrap();
/// assert_eq!((hit.primitive, hit.hit.t), (ball, 2.0));
/// let hit = scene.closest_hit(&down(3.0), Interval::FORWARD).unwrap();
/// assert_eq!((hit.primitive, hit.hit.t, hit.triangle.unwrap().triangle), (tile, 4.0, 0));
/// assert_eq!(scene.closest_hit(&down(-3.0), Interval::FORWARD).unwrap().primitive, floor);
/// // Shadow rays: the ball blocks a light above it, not one beside it.
/// assert!(scene.occluded_between([0.0, 0.0, 0.5], [0.0, 0.0, 9.0]).unwrap());
/// assert!(!scene.occluded_between([0.0, 0.0, 0.5], [9.0, 0.0, 0.5]).unwrap());
/// ```
#[derive(Clone, Debug)]
pub struct Scene {
    primitives: Vec<Primitive>,
    bvh: BoxBvh,
    unbounded: Vec<u32>,
}

/// Where on a mesh's triangle a [`SceneHit`] lies (the parts of
/// [`MeshHit`] beside its [`Hit`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TrianglePoint {
    /// The index of the triangle in its mesh ([`MeshHit::triangle`]).
    pub triangle: u32,
    /// The barycentric coordinate of the triangle's second vertex.
    pub u: f64,
    /// The barycentric coordinate of its third vertex.
    pub v: f64,
    /// The interpolated unit shading normal, for a mesh with normals
    /// ([`MeshHit::shading_normal`]).
    pub shading_normal: Option<DVec3>,
}

/// The closest hit of a ray in a [`Scene`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SceneHit {
    /// The primitive hit.
    pub primitive: PrimitiveId,
    /// The certified hit: `t`, the point `ray.at(t)` with its per-axis
    /// error bound, the unit geometric normal (each primitive's own:
    /// [`MeshHit::hit`], a shape's [`RayCast::cast`]).
    pub hit: Hit,
    /// For a mesh, the triangle, its barycentrics and shading normal;
    /// `None` for an analytic shape.
    pub triangle: Option<TrianglePoint>,
}

impl SceneHit {
    /// The normal to shade with: the mesh's interpolated shading normal
    /// where it has one, the geometric normal otherwise.
    #[inline]
    pub fn shading_normal(&self) -> DVec3 {
        self.triangle
            .and_then(|p| p.shading_normal)
            .unwrap_or(self.hit.normal)
    }
}

impl From<(PrimitiveId, MeshHit)> for SceneHit {
    /// A mesh's hit as the scene's.
    #[inline]
    fn from((primitive, h): (PrimitiveId, MeshHit)) -> SceneHit {
        SceneHit {
            primitive,
            hit: h.hit,
            triangle: Some(TrianglePoint {
                triangle: h.triangle,
                u: h.u,
                v: h.v,
                shading_normal: h.shading_normal,
            }),
        }
    }
}

/// The bound `x` of a parameter segment moved outward (`outward` is
/// `+1.0` for an upper bound, `-1.0` for a lower one) by `gamma(18) |x| +
/// 2^-1068`; infinities stay.
///
/// A primitive's hit at a computed `t` in `[lo, hi]` has its exact
/// crossing within `gamma(16) |t| + 2^-1070` of `t` (the casts' bound,
/// see [`Scene`]), which is within the segment widened by `gamma(16)` of
/// each bound's own magnitude: for `0 <= t <= hi`, `t (1 + gamma(16)) <=
/// hi (1 + gamma(16))`; for `t < 0`, `t (1 - gamma(16)) <= hi (1 -
/// gamma(16)) <= hi + gamma(16) |hi|`; the lower end likewise. The
/// product and the sum here each round once, together at most `u |x| (1 +
/// gamma(18)) (1 + u)`, which `gamma(18) - gamma(16) >= 2u` covers; the
/// absolute part (`2^-1068 >= 2^-1070`) is exact below the normal range.
#[inline]
fn widen(x: f64, outward: f64) -> f64 {
    if x.is_finite() {
        x + outward * (gamma(18) * x.abs() + f64::from_bits(1 << 6))
    } else {
        x
    }
}

/// The range's lower end widened, as the interval the walk reads it from
/// (`[widen(lo), max]`).
#[inline]
fn walked(range: Interval) -> Interval {
    // `widen(lo) <= lo <= max`, neither NaN: the interval exists.
    Interval::new(widen(range.min(), -1.0), range.max()).unwrap_or(range)
}

/// What won so far: a mesh's hit, or a shape (shaded at the end).
#[derive(Clone, Copy)]
enum Winner<'a> {
    Mesh(MeshHit),
    Shape(&'a AnalyticShape),
}

/// The best hit so far: its `t`, primitive id and winner.
#[derive(Clone, Copy)]
struct Best<'a> {
    t: f64,
    id: u32,
    winner: Winner<'a>,
}

struct Closest<'s, 'r, T: TriangleTest> {
    scene: &'s Scene,
    ray: &'r Ray,
    range: Interval,
    best: Option<Best<'s>>,
    test: PhantomData<T>,
}

impl<'s, T: TriangleTest> Closest<'s, '_, T> {
    /// Tests primitive `id` (see the module docs for the range each kind
    /// is asked for) and keeps it if it is better.
    #[inline]
    fn consider(&mut self, id: u32) {
        let scene: &'s Scene = self.scene;
        let found = match &scene.primitives[id as usize] {
            Primitive::Mesh(mesh) => {
                let range = self
                    .best
                    .and_then(|b| Interval::new(self.range.min(), b.t).ok())
                    .unwrap_or(self.range);
                mesh.closest_hit_with::<T>(self.ray, range)
                    .map(|h| (h.hit.t, Winner::Mesh(h)))
            }
            Primitive::Shape(shape) => shape
                .cast_t(self.ray, self.range)
                .map(|t| (t, Winner::Shape(shape))),
        };
        if let Some((t, winner)) = found
            && self.best.is_none_or(|b| t < b.t || (t == b.t && id < b.id))
        {
            self.best = Some(Best { t, id, winner });
        }
    }
}

impl<T: TriangleTest> Visitor for Closest<'_, '_, T> {
    #[inline]
    fn max(&self) -> f64 {
        widen(self.best.map_or(self.range.max(), |b| b.t), 1.0)
    }

    #[inline]
    fn leaf(&mut self, ids: &[u32]) -> bool {
        for &id in ids {
            self.consider(id);
        }
        false
    }
}

/// The any-hit visitor: the walk stops at the first primitive `blocks`
/// says is met (by a ray, or by a segment).
struct AnyHit<F> {
    max: f64,
    found: bool,
    blocks: F,
}

impl<F: FnMut(u32) -> bool> Visitor for AnyHit<F> {
    const ORDERED: bool = false;

    #[inline]
    fn max(&self) -> f64 {
        self.max
    }

    #[inline]
    fn leaf(&mut self, ids: &[u32]) -> bool {
        self.found = ids.iter().any(|&id| (self.blocks)(id));
        self.found
    }
}

impl Scene {
    /// The primitives, indexed by [`PrimitiveId::index`].
    #[inline]
    pub fn primitives(&self) -> &[Primitive] {
        &self.primitives
    }

    /// Primitive `id`, or `None` for an id not from this scene's builder.
    #[inline]
    pub fn primitive(&self, id: PrimitiveId) -> Option<&Primitive> {
        self.primitives.get(id.index())
    }

    /// How many primitives the scene holds.
    #[inline]
    pub fn len(&self) -> usize {
        self.primitives.len()
    }

    /// Whether it holds none.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.primitives.is_empty()
    }

    /// The closest hit of `ray` for `t` in `range`, meshes with the
    /// watertight test ([`Watertight`]); see [`Scene::closest_hit_with`].
    #[inline]
    pub fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<SceneHit> {
        self.closest_hit_with::<Watertight>(ray, range)
    }

    /// The closest hit of `ray` for `t` in `range`, meshes with the
    /// triangle test `T`, or `None`: the least `t` over every primitive's
    /// own answer, the lower id on ties (the module docs give the rule and
    /// the hierarchy's guarantee). Never allocates; every `Ray` and
    /// `Interval` is valid input. The hit point and normal of a shape are
    /// computed once, for the winner.
    pub fn closest_hit_with<T: TriangleTest>(
        &self,
        ray: &Ray,
        range: Interval,
    ) -> Option<SceneHit> {
        let best = self.search::<T>(ray, range)?;
        let primitive = PrimitiveId(best.id);
        Some(match best.winner {
            Winner::Mesh(h) => SceneHit::from((primitive, h)),
            Winner::Shape(shape) => SceneHit {
                primitive,
                // The cast whose `t` won: the same first hit.
                hit: shape.cast(ray, range)?,
                triangle: None,
            },
        })
    }

    /// The winner of the closest-hit rule, unshaded.
    fn search<T: TriangleTest>(&self, ray: &Ray, range: Interval) -> Option<Best<'_>> {
        let mut v = Closest::<T> {
            scene: self,
            ray,
            range,
            best: None,
            test: PhantomData,
        };
        for &id in &self.unbounded {
            v.consider(id);
        }
        walk::<_, 0>(&self.bvh, ray, walked(range), &mut v);
        v.best
    }

    /// Whether `ray` meets the scene for some `t` in `range` (a shadow
    /// ray's question), meshes with the watertight test; see
    /// [`Scene::occluded_with`].
    #[inline]
    pub fn occluded(&self, ray: &Ray, range: Interval) -> bool {
        self.occluded_with::<Watertight>(ray, range)
    }

    /// Whether [`Scene::closest_hit_with`] would find a hit: the unbounded
    /// primitives first, then the walk, stopping at the first primitive
    /// hit (a shape's [`RayCast::hits`], a mesh's
    /// [`TriangleMesh::occluded_with`]). Never allocates.
    pub fn occluded_with<T: TriangleTest>(&self, ray: &Ray, range: Interval) -> bool {
        let mut v = AnyHit {
            max: widen(range.max(), 1.0),
            found: false,
            blocks: |id: u32| match &self.primitives[id as usize] {
                Primitive::Mesh(mesh) => mesh.occluded_with::<T>(ray, range),
                Primitive::Shape(shape) => shape.hits(ray, range),
            },
        };
        if !v.leaf(&self.unbounded) {
            walk::<_, 0>(&self.bvh, ray, walked(range), &mut v);
        }
        v.found
    }

    /// Whether the segment from `p` to `q` meets the scene (watertight
    /// test for meshes): the ray `p + t fl(q - p)` for `t` in `[0, 1]`, as
    /// [`TriangleMesh::occluded_between`]. Both ends count; to leave a
    /// surface use [`spawn_ray_to`](super::spawn_ray_to).
    ///
    /// # Errors
    /// As [`Scene::occluded_between_with`].
    #[inline]
    pub fn occluded_between(
        &self,
        p: impl IntoDVec3,
        q: impl IntoDVec3,
    ) -> Result<bool, InputError> {
        self.occluded_between_with::<Watertight>(p, q)
    }

    /// Whether the segment from `p` to `q` meets the scene, its meshes
    /// with the triangle test `T` as
    /// [`TriangleMesh::occluded_between_with`] decides (with [`Exact`],
    /// on the exact segment) and its shapes with their own
    /// [`RayCast::hits`] on the segment's ray. Every pair of finite ends
    /// is a segment (a difference that overflows is halved, as there).
    /// Both ends count; the walk stops at the first primitive met. Never
    /// allocates.
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
        let Some(segment) = Segment::new(p, q)? else {
            return Ok(false);
        };
        let s = &segment;
        let mut v = AnyHit {
            max: widen(s.end(), 1.0),
            found: false,
            blocks: |id: u32| match &self.primitives[id as usize] {
                Primitive::Mesh(mesh) => mesh.meets_segment::<T>(s),
                Primitive::Shape(shape) => shape.hits(&s.ray, s.range()),
            },
        };
        if !v.leaf(&self.unbounded) {
            walk_segment(&self.bvh, &segment, walked(segment.range()), &mut v);
        }
        Ok(v.found)
    }
}

impl RayCast for Scene {
    /// [`Scene::closest_hit`]'s certified hit.
    #[inline]
    fn cast(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.closest_hit(ray, range).map(|h| h.hit)
    }

    /// [`Scene::closest_hit`]'s `t`, without the winner's point and
    /// normal.
    #[inline]
    fn cast_t(&self, ray: &Ray, range: Interval) -> Option<f64> {
        self.search::<Watertight>(ray, range).map(|b| b.t)
    }

    /// [`Scene::occluded`].
    #[inline]
    fn hits(&self, ray: &Ray, range: Interval) -> bool {
        self.occluded(ray, range)
    }
}
