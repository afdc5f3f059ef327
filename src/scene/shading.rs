//! Shading normals (question Q3 of `docs/pictures.md`): barycentric interpolation of
//! vertex normals, and a reflection about a shading normal that never
//! leaves towards the inside of the geometric surface.

use crate::arith::roundoff::gamma;
use crate::query::ray::unit_or;
use glam::DVec3;

/// `(1 - u - v) a + u b + v c`, normalized; `fallback` (normalized) where
/// the sum vanishes.
#[inline]
pub(super) fn interpolate(a: DVec3, b: DVec3, c: DVec3, u: f64, v: f64, fallback: DVec3) -> DVec3 {
    unit_or(a * (1.0 - u - v) + b * u + c * v, fallback)
}

/// The mirror reflection of the direction `d` about the unit normal `n`,
/// `d - 2 (d . n) n` (rounded). Any finite input gives a finite result
/// (NaN in, NaN out); nothing is normalized.
#[inline]
pub fn reflect(d: DVec3, n: DVec3) -> DVec3 {
    d - n * (2.0 * d.dot(n))
}

/// Whether the exact dot product of `r` and `n` is positive, certified:
/// the computed `r . n` (three products, two sums) is within `gamma(3)
/// Σ |r_k n_k|` of the exact one (Higham, *Accuracy and Stability*, §3.1),
/// plus `3 * 2^-1075` for underflowed products; the bound is taken with
/// `gamma(4)` and `2^-1072` for its own roundings.
#[inline]
fn certainly_above(r: DVec3, n: DVec3) -> bool {
    r.dot(n) > gamma(4) * r.abs().dot(n.abs()) + f64::from_bits(4)
}

/// The reflection of the incident direction `d` about the shading normal
/// `shading`, kept above the geometric surface of unit normal `geometric`.
///
/// "Above" is the side of the geometric plane the ray came from: `side =
/// -geometric` when the computed `d . geometric` is positive, `geometric`
/// otherwise. Plain reflection about an interpolated normal can point
/// below it (question Q3: a coarse sphere with smooth normals sends
/// grazing reflections into the object). The rule, in order:
///
/// 1. `r = reflect(d, shading)` when it is certainly above.
/// 2. Otherwise `r` folded up, mirrored about the geometric plane: `r - 2
///    (r . side) side`, which keeps its tangential part and its length and
///    agrees with `r` where `r` lies in the plane (so the result varies
///    continuously where the fold starts); when it is certainly above.
/// 3. Otherwise (`r` within rounding of the plane) the reflection about
///    the geometric normal, whose elevation is the incident one; when it is
///    certainly above.
/// 4. Otherwise (a grazing incident direction) `side` itself.
///
/// **Guarantee**: for finite `d`, `shading` and a nonzero finite
/// `geometric`, the exact dot product of the returned direction with
/// `side` is positive (each step's sign is certified by a derived error
/// bound, and `side . side > 0` exactly for a unit vector). Nothing else is
/// promised of the result's length. For a NaN or infinite input the result
/// may be NaN; nothing panics.
///
/// This folds the reflected direction; Blender Cycles'
/// `ensure_valid_specular_reflection` instead bends the shading normal
/// towards the geometric one in closed form so that the reflection stays a
/// small angle above the surface.
///
/// ```
/// use exactray::scene::{reflect, reflect_above};
/// use glam::DVec3;
/// // A grazing ray on a flat face whose shading normal leans 45 degrees.
/// let (d, ng) = (DVec3::new(1.0, 0.0, -0.1), DVec3::Z);
/// let ns = DVec3::new(1.0, 0.0, 1.0).normalize();
/// assert!(reflect(d, ns).z < 0.0); // into the object
/// assert!(reflect_above(d, ns, ng).z > 0.0);
/// ```
pub fn reflect_above(d: DVec3, shading: DVec3, geometric: DVec3) -> DVec3 {
    let side = if d.dot(geometric) > 0.0 {
        -geometric
    } else {
        geometric
    };
    let r = reflect(d, shading);
    if certainly_above(r, side) {
        return r;
    }
    let folded = r - side * (2.0 * r.dot(side));
    if certainly_above(folded, side) {
        return folded;
    }
    let mirrored = reflect(d, side);
    if certainly_above(mirrored, side) {
        return mirrored;
    }
    side
}
