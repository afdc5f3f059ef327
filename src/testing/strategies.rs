//! proptest strategies for hard predicate inputs, for users' property tests.
//!
//! The per-family strategies ([`orient2d_inputs`], ...) draw a seed and run
//! the deterministic generators of [`testing`](crate::testing) for an
//! [`InputClass`]; for the predicates on constructed points,
//! [`orient3d_lpi_inputs`] and its siblings, and ready-made constructed
//! points near degeneracy ([`lpi_near_triangle`], [`tpi_near_triangle`],
//! [`ssi_near_line`], [`lpi_pair_near_equal`]); [`small_scenes`] and [`spawned_rays`] do the same for
//! scenes of meshes and analytic shapes and for secondary rays on them; [`finite_f64`] and the `finite_*` point strategies cover
//! every finite `f64` bit pattern. The thin wrappers ([`degenerate_orient2d`],
//! [`near_degenerate_incircle`], ...) name the classes most tests want.
//!
//! Generated cases do not shrink: a smaller seed is an unrelated case, not a
//! simpler one, so shrinking would only spend time.
//!
//! ```
//! use exactray::testing::InputClass;
//! use exactray::testing::{any_class, finite_dvec2, orient2d_inputs};
//! use exactray::prelude::*;
//! use proptest::prelude::*;
//!
//! proptest! {
//!     #![proptest_config(ProptestConfig::with_cases(64))]
//!     // In a test file each property also gets `#[test]`.
//!     // An odd permutation of the points negates the orientation.
//!     fn swap_negates([a, b, c] in any_class().prop_flat_map(orient2d_inputs)) {
//!         prop_assert_eq!(orient2d(a, b, c), -orient2d(b, a, c));
//!     }
//!
//!     // Degenerate cases are collinear by construction.
//!     fn degenerate_is_zero([a, b, c] in orient2d_inputs(InputClass::Degenerate)) {
//!         prop_assert_eq!(orient2d(a, b, c), Sign::Zero);
//!     }
//!
//!     // Any three finite points: the answer is one of the signs, never a panic.
//!     fn finite_never_panics(a in finite_dvec2(), b in finite_dvec2(), c in finite_dvec2()) {
//!         let _ = orient2d(a, b, c);
//!     }
//! }
//! # swap_negates();
//! # degenerate_is_zero();
//! # finite_never_panics();
//! ```

use crate::arith::exponent::scale_pow2;
use crate::predicates::{Lpi, Ssi, Tpi};
use crate::scene::Scene;
use crate::testing::finite_f64_from_bits;
use crate::testing::{
    InputClass, SCENE_PLACES, SpawnedRay, SplitMix64, incircle_case, insphere_case,
    less_on_axis_lpi_case, orient2d_case, orient2d_ssi_case, orient3d_case, orient3d_lpi_case,
    orient3d_tpi_case, plane_side_case, random_scene, spawned_ray,
};
use alloc::sync::Arc;
use glam::{DVec2, DVec3};
use proptest::prelude::*;

fn seeded<T: core::fmt::Debug>(
    class: InputClass,
    generate: fn(InputClass, &mut SplitMix64) -> T,
) -> impl Strategy<Value = T> {
    any::<u64>()
        .prop_map(move |seed| generate(class, &mut SplitMix64::new(seed)))
        .no_shrink()
}

/// Any [`InputClass`], uniformly; combine with a family strategy through
/// `prop_flat_map` to cover every class in one property.
pub fn any_class() -> impl Strategy<Value = InputClass> {
    proptest::sample::select(&InputClass::ALL[..])
}

/// Every finite `f64`, each bit pattern equally likely: subnormals, both
/// zeros and the extremes included, so most values are far from 1 (see
/// [`finite_f64_from_bits`] for where the non-finite patterns go). Shrinks
/// towards `0.0`.
pub fn finite_f64() -> impl Strategy<Value = f64> {
    any::<u64>().prop_map(finite_f64_from_bits)
}

/// A `DVec2` with coordinates from [`finite_f64`].
pub fn finite_dvec2() -> impl Strategy<Value = DVec2> {
    (finite_f64(), finite_f64()).prop_map(|(x, y)| DVec2::new(x, y))
}

/// A `DVec3` with coordinates from [`finite_f64`].
pub fn finite_dvec3() -> impl Strategy<Value = DVec3> {
    (finite_f64(), finite_f64(), finite_f64()).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

/// `orient2d` arguments `[a, b, c]` of the class (see
/// [`orient2d_case`](crate::testing::orient2d_case)).
pub fn orient2d_inputs(class: InputClass) -> impl Strategy<Value = [DVec2; 3]> {
    seeded(class, orient2d_case)
}

/// `orient3d` arguments `[a, b, c, d]` of the class (see
/// [`orient3d_case`](crate::testing::orient3d_case)).
pub fn orient3d_inputs(class: InputClass) -> impl Strategy<Value = [DVec3; 4]> {
    seeded(class, orient3d_case)
}

/// `incircle` arguments `[a, b, c, d]` of the class (see
/// [`incircle_case`](crate::testing::incircle_case)).
pub fn incircle_inputs(class: InputClass) -> impl Strategy<Value = [DVec2; 4]> {
    seeded(class, incircle_case)
}

/// `insphere` arguments `[a, b, c, d, e]` of the class (see
/// [`insphere_case`](crate::testing::insphere_case)).
pub fn insphere_inputs(class: InputClass) -> impl Strategy<Value = [DVec3; 5]> {
    seeded(class, insphere_case)
}

/// `same_side` / `side_of_plane` arguments `[x0, x1, x2, p, q]` of the class
/// (see [`plane_side_case`](crate::testing::plane_side_case)).
pub fn plane_side_inputs(class: InputClass) -> impl Strategy<Value = [DVec3; 5]> {
    seeded(class, plane_side_case)
}

/// Exactly collinear `orient2d` arguments: the exact answer is `Zero`.
pub fn degenerate_orient2d() -> impl Strategy<Value = [DVec2; 3]> {
    orient2d_inputs(InputClass::Degenerate)
}

/// Exactly coplanar `orient3d` arguments: the exact answer is `Zero`.
pub fn degenerate_orient3d() -> impl Strategy<Value = [DVec3; 4]> {
    orient3d_inputs(InputClass::Degenerate)
}

/// Exactly cocircular `incircle` arguments: the exact answer is `Zero`.
pub fn degenerate_incircle() -> impl Strategy<Value = [DVec2; 4]> {
    incircle_inputs(InputClass::Degenerate)
}

/// Exactly cospherical `insphere` arguments: the exact answer is `Zero`.
pub fn degenerate_insphere() -> impl Strategy<Value = [DVec3; 5]> {
    insphere_inputs(InputClass::Degenerate)
}

/// Nearly collinear `orient2d` arguments, where a plain `f64` determinant
/// often gets the sign wrong.
pub fn near_degenerate_orient2d() -> impl Strategy<Value = [DVec2; 3]> {
    orient2d_inputs(InputClass::NearDegenerate)
}

/// Nearly coplanar `orient3d` arguments.
pub fn near_degenerate_orient3d() -> impl Strategy<Value = [DVec3; 4]> {
    orient3d_inputs(InputClass::NearDegenerate)
}

/// Nearly cocircular `incircle` arguments.
pub fn near_degenerate_incircle() -> impl Strategy<Value = [DVec2; 4]> {
    incircle_inputs(InputClass::NearDegenerate)
}

/// Nearly cospherical `insphere` arguments.
pub fn near_degenerate_insphere() -> impl Strategy<Value = [DVec3; 5]> {
    insphere_inputs(InputClass::NearDegenerate)
}

/// `orient2d` arguments from every class, each equally likely.
pub fn hard_orient2d() -> impl Strategy<Value = [DVec2; 3]> {
    any_class().prop_flat_map(orient2d_inputs)
}

/// `orient3d` arguments from every class, each equally likely.
pub fn hard_orient3d() -> impl Strategy<Value = [DVec3; 4]> {
    any_class().prop_flat_map(orient3d_inputs)
}

/// `incircle` arguments from every class, each equally likely.
pub fn hard_incircle() -> impl Strategy<Value = [DVec2; 4]> {
    any_class().prop_flat_map(incircle_inputs)
}

/// `insphere` arguments from every class, each equally likely.
pub fn hard_insphere() -> impl Strategy<Value = [DVec3; 5]> {
    any_class().prop_flat_map(insphere_inputs)
}

/// Plane-side arguments from every class, each equally likely.
pub fn hard_plane_side() -> impl Strategy<Value = [DVec3; 5]> {
    any_class().prop_flat_map(plane_side_inputs)
}

/// `orient3d` with a line–plane point: `[a, b, c, p, q, r, s, t]` of the
/// class (see [`orient3d_lpi_case`](crate::testing::orient3d_lpi_case)).
pub fn orient3d_lpi_inputs(class: InputClass) -> impl Strategy<Value = [DVec3; 8]> {
    seeded(class, orient3d_lpi_case)
}

/// `orient3d` with a three-plane point: `[a, b, c, u0, u1, u2, v0, v1, v2,
/// w0, w1, w2]` of the class (see
/// [`orient3d_tpi_case`](crate::testing::orient3d_tpi_case)).
pub fn orient3d_tpi_inputs(class: InputClass) -> impl Strategy<Value = [DVec3; 12]> {
    seeded(class, orient3d_tpi_case)
}

/// `orient2d` with a line–line point: `[a, b, p, q, r, s]` of the class
/// (see [`orient2d_ssi_case`](crate::testing::orient2d_ssi_case)).
pub fn orient2d_ssi_inputs(class: InputClass) -> impl Strategy<Value = [DVec2; 6]> {
    seeded(class, orient2d_ssi_case)
}

/// Two line–plane points and an axis of the class (see
/// [`less_on_axis_lpi_case`](crate::testing::less_on_axis_lpi_case)).
pub fn less_on_axis_lpi_inputs(class: InputClass) -> impl Strategy<Value = ([DVec3; 10], usize)> {
    seeded(class, less_on_axis_lpi_case)
}

/// The classes whose constructed points lie on, or a few ulps off, the
/// explicit points' plane or line, at any scale: near-degenerate,
/// degenerate, tiny, huge and mixed.
fn near_degenerate_class() -> impl Strategy<Value = InputClass> {
    proptest::sample::select(&InputClass::ALL[1..])
}

/// A triangle and a line–plane point on its plane, or a few ulps off it,
/// at any scale (every class but `uniform`): where rounding the point gives
/// wrong orientations.
///
/// ```
/// use exactray::predicates::orient3d_implicit;
/// use exactray::testing::lpi_near_triangle;
/// use proptest::prelude::*;
/// proptest! {
///     #![proptest_config(ProptestConfig::with_cases(32))]
///     // Swapping two vertices negates the orientation, exactly.
///     fn swap_negates(([a, b, c], x) in lpi_near_triangle()) {
///         prop_assert_eq!(orient3d_implicit(a, b, c, &x), -orient3d_implicit(b, a, c, &x));
///     }
/// }
/// # swap_negates();
/// ```
pub fn lpi_near_triangle() -> impl Strategy<Value = ([DVec3; 3], Lpi)> {
    near_degenerate_class()
        .prop_flat_map(orient3d_lpi_inputs)
        .prop_filter_map("a construction that is one point", |c| {
            Lpi::new(c[3], c[4], c[5], c[6], c[7])
                .ok()
                .map(|x| ([c[0], c[1], c[2]], x))
        })
}

/// A triangle and a three-plane point on its plane, or a few ulps off it,
/// at any scale (as [`lpi_near_triangle`]).
pub fn tpi_near_triangle() -> impl Strategy<Value = ([DVec3; 3], Tpi)> {
    near_degenerate_class()
        .prop_flat_map(orient3d_tpi_inputs)
        .prop_filter_map("a construction that is one point", |c| {
            Tpi::new([c[3], c[4], c[5]], [c[6], c[7], c[8]], [c[9], c[10], c[11]])
                .ok()
                .map(|x| ([c[0], c[1], c[2]], x))
        })
}

/// Two points and a line–line point on their line, or a few ulps off it,
/// at any scale (as [`lpi_near_triangle`]).
pub fn ssi_near_line() -> impl Strategy<Value = ([DVec2; 2], Ssi)> {
    near_degenerate_class()
        .prop_flat_map(orient2d_ssi_inputs)
        .prop_filter_map("a construction that is one point", |c| {
            Ssi::new(c[2], c[3], c[4], c[5])
                .ok()
                .map(|x| ([c[0], c[1]], x))
        })
}

/// Two line–plane points whose coordinates along the axis are equal, or a
/// few ulps apart, at any scale, and the axis (0, 1 or 2).
pub fn lpi_pair_near_equal() -> impl Strategy<Value = (Lpi, Lpi, usize)> {
    near_degenerate_class()
        .prop_flat_map(less_on_axis_lpi_inputs)
        .prop_filter_map("constructions that are one point", |(c, axis)| {
            let x = Lpi::new(c[0], c[1], c[2], c[3], c[4]).ok()?;
            let y = Lpi::new(c[5], c[6], c[7], c[8], c[9]).ok()?;
            Some((x, y, axis))
        })
}

/// Scenes of 1 to 8 primitives from [`random_scene`]: spheres, capped and
/// infinite cylinders and cones, paraboloids, disks, planes, closed
/// octahedra with vertex normals and triangle soups, at one of the
/// [`SCENE_PLACES`] or, as often, at a scale `2^k` for any `k` from -1000
/// to 1000, at the origin or `2^20` or `2^27` times that scale from it.
/// Brute force over [`Scene::primitives`] is the oracle of their closest
/// hits.
///
/// ```
/// use exactray::prelude::*;
/// use exactray::testing::small_scenes;
/// use proptest::prelude::*;
/// proptest! {
///     #![proptest_config(ProptestConfig::with_cases(16))]
///     // A ray blocked by the scene is one with a closest hit.
///     fn occluded_is_a_hit(scene in small_scenes(), d in prop::array::uniform3(-1.0..1.0f64)) {
///         if let Ok(ray) = Ray::new([0.0; 3], d) {
///             let hit = scene.closest_hit(&ray, Interval::FORWARD);
///             prop_assert_eq!(scene.occluded(&ray, Interval::FORWARD), hit.is_some());
///         }
///     }
/// }
/// # occluded_is_a_hit();
/// ```
pub fn small_scenes() -> impl Strategy<Value = Scene> {
    let place = prop_oneof![
        proptest::sample::select(&SCENE_PLACES[..]),
        (-1000i32..=1000, proptest::sample::select(&[0, 20, 27][..])).prop_map(|(k, far)| {
            // Offsets only where the scene stays below 2^1010.
            let far = if k + far <= 1000 { far } else { 0 };
            let scale = scale_pow2(1.0, k);
            (
                scale,
                if far == 0 {
                    0.0
                } else {
                    scale_pow2(1.0, k + far)
                },
            )
        }),
    ];
    (any::<u64>(), 1usize..=8, place)
        .prop_map(|(seed, count, (scale, offset))| {
            let offset = DVec3::new(1.0, -0.7, 0.4) * offset;
            random_scene(&mut SplitMix64::new(seed), count, scale, offset)
        })
        .no_shrink()
}

/// Secondary rays on `scene` ([`spawned_ray`]): a primary ray's closest
/// hit, and a ray spawned from it at a random, often grazing, elevation,
/// on the side the primary came from or (one time in four) through the
/// surface. For a user's own scene; seeds whose eight primaries all miss
/// (or hit only where no ray can be spawned) are rejected, so a scene that
/// most rays miss makes proptest give up ("too many local rejects").
/// [`scenes_with_spawned_rays`] draws the scene too.
pub fn spawned_rays(scene: Arc<Scene>) -> impl Strategy<Value = SpawnedRay> {
    any::<u64>()
        .prop_filter_map("no primary ray hit the scene", move |seed| {
            spawned_ray(&mut SplitMix64::new(seed), &scene)
        })
        .no_shrink()
}

/// A scene of [`small_scenes`] and a secondary ray on it (as
/// [`spawned_rays`]); a pair whose primaries all miss is drawn again,
/// scene and all.
///
/// ```
/// use exactray::prelude::*;
/// use exactray::testing::scenes_with_spawned_rays;
/// use proptest::prelude::*;
/// proptest! {
///     #![proptest_config(ProptestConfig::with_cases(16))]
///     // A ray leaving a mesh's triangle never meets that triangle again.
///     fn no_self_hit((scene, s) in scenes_with_spawned_rays()) {
///         let next = scene.closest_hit(&s.ray, Interval::FORWARD);
///         if let (Some(next), Some(left)) = (next, s.hit.triangle) {
///             let same = next.primitive == s.hit.primitive
///                 && next.triangle.is_some_and(|p| p.triangle == left.triangle);
///             prop_assert!(!same, "{:?} -> {:?}", s, next);
///         }
///     }
/// }
/// # no_self_hit();
/// ```
pub fn scenes_with_spawned_rays() -> impl Strategy<Value = (Arc<Scene>, SpawnedRay)> {
    (small_scenes(), any::<u64>())
        .prop_filter_map("no primary ray hit the scene", |(scene, seed)| {
            let spawned = spawned_ray(&mut SplitMix64::new(seed), &scene)?;
            Some((Arc::new(scene), spawned))
        })
        .no_shrink()
}
