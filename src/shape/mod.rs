//! Shapes, by what they are: each type validates itself at construction
//! (typed [`InputError`]s for non-finite coordinates, negative or NaN
//! radii, zero axes or normals, degenerate cones), so every
//! query on it can rely on finite, meaningful parameters. What can be asked
//! of a shape lives in [`query`](crate::query).

mod cone;
mod cylinder;
mod plane;
mod quadric;
mod sphere;
pub mod triangle;

pub use cone::Cone;
pub use cylinder::{CappedCylinder, Cylinder};
pub use plane::{Disk, Plane};
pub use quadric::Quadric;
pub use sphere::Sphere;
pub use triangle::Triangle;

use crate::error::InputError;
use crate::point::IntoDVec3;
use glam::DVec3;

/// `v` if every coordinate is finite, else [`InputError::NonFinite`].
fn finite(argument: &'static str, v: impl IntoDVec3) -> Result<DVec3, InputError> {
    let v = v.into_dvec3();
    if v.is_finite() {
        Ok(v)
    } else {
        Err(InputError::NonFinite { argument })
    }
}

/// A finite, non-zero vector, else [`InputError::NonFinite`] or
/// [`InputError::Degenerate`].
fn nonzero(argument: &'static str, v: impl IntoDVec3) -> Result<DVec3, InputError> {
    let v = finite(argument, v)?;
    if v == DVec3::ZERO {
        Err(InputError::Degenerate { argument })
    } else {
        Ok(v)
    }
}

/// A radius `r >= 0`: NaN or negative is [`InputError::InvalidRadius`],
/// infinite is [`InputError::NonFinite`].
fn radius(argument: &'static str, r: f64) -> Result<f64, InputError> {
    if r.is_nan() || r < 0.0 {
        Err(InputError::InvalidRadius { argument })
    } else if r.is_infinite() {
        Err(InputError::NonFinite { argument })
    } else {
        Ok(r)
    }
}
