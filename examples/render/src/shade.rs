//! What both tracers do at a hit: which way the surface faces the ray, and
//! the mirror direction, plain (the Q3 failure) or kept above the
//! surface by the crate's helper.

use exactray::query::ray::Ray;
use exactray::scene::{SceneHit, reflect, reflect_above};
use glam::DVec3;

/// How a mirror reflects about a smooth mesh's interpolated normal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reflection {
    /// `reflect(d, shading normal)`: can point into the object (Q3).
    Plain,
    /// [`reflect_above`]: never below the geometric surface.
    AboveSurface,
}

/// The hit's shading normal turned to the side the ray came from (the
/// geometric normal decides the side: the shading normal of a smooth mesh
/// may lean past the facet's plane).
pub fn facing_normal(ray: &Ray, hit: &SceneHit) -> DVec3 {
    let n = hit.shading_normal();
    if ray.direction().dot(hit.hit.normal) > 0.0 {
        -n
    } else {
        n
    }
}

/// The mirror direction at `hit` for `ray`, by `rule`.
pub fn mirror_direction(ray: &Ray, hit: &SceneHit, rule: Reflection) -> DVec3 {
    let d = ray.direction().normalize_or_zero();
    match rule {
        Reflection::Plain => reflect(d, facing_normal(ray, hit)),
        Reflection::AboveSurface => reflect_above(d, hit.shading_normal(), hit.hit.normal),
    }
}
