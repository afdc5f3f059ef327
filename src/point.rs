//! Conversions of caller point types into the `f64` vectors the crate computes
//! on. Every conversion is exact: an `f32` widens to `f64` without rounding.

use glam::{DVec2, DVec3, Vec2, Vec3, Vec3A};

/// A 2D point type the predicates accept: `DVec2`, `Vec2`, `[f64; 2]`,
/// `[f32; 2]`, `(f64, f64)`, and with the `mint` feature mint's `Point2`
/// and `Vector2` of `f64` or `f32`. The conversion to `DVec2` is exact.
///
/// ```
/// use exactray::prelude::*;
/// // f32 and f64 inputs mix freely; the f32 values widen exactly.
/// assert_eq!(orient2d(glam::Vec2::ZERO, [1.0f64, 0.0], (0.0, 1.0)), Sign::Positive);
/// ```
pub trait IntoDVec2: Copy {
    /// The point as `f64` coordinates.
    fn into_dvec2(self) -> DVec2;
}

/// A 3D point type the predicates accept: `DVec3`, `Vec3`, `Vec3A`,
/// `[f64; 3]`, `[f32; 3]`, `(f64, f64, f64)`, and with the `mint` feature
/// mint's `Point3` and `Vector3` of `f64` or `f32`. The conversion to
/// `DVec3` is exact.
pub trait IntoDVec3: Copy {
    /// The point as `f64` coordinates.
    fn into_dvec3(self) -> DVec3;
}

impl IntoDVec2 for DVec2 {
    #[inline]
    fn into_dvec2(self) -> DVec2 {
        self
    }
}
impl IntoDVec2 for Vec2 {
    #[inline]
    fn into_dvec2(self) -> DVec2 {
        self.as_dvec2()
    }
}
impl IntoDVec2 for [f64; 2] {
    #[inline]
    fn into_dvec2(self) -> DVec2 {
        DVec2::from_array(self)
    }
}
impl IntoDVec2 for [f32; 2] {
    #[inline]
    fn into_dvec2(self) -> DVec2 {
        Vec2::from_array(self).as_dvec2()
    }
}
impl IntoDVec2 for (f64, f64) {
    #[inline]
    fn into_dvec2(self) -> DVec2 {
        DVec2::new(self.0, self.1)
    }
}

impl IntoDVec3 for DVec3 {
    #[inline]
    fn into_dvec3(self) -> DVec3 {
        self
    }
}
impl IntoDVec3 for Vec3 {
    #[inline]
    fn into_dvec3(self) -> DVec3 {
        self.as_dvec3()
    }
}
impl IntoDVec3 for Vec3A {
    #[inline]
    fn into_dvec3(self) -> DVec3 {
        self.as_dvec3()
    }
}
impl IntoDVec3 for [f64; 3] {
    #[inline]
    fn into_dvec3(self) -> DVec3 {
        DVec3::from_array(self)
    }
}
impl IntoDVec3 for [f32; 3] {
    #[inline]
    fn into_dvec3(self) -> DVec3 {
        Vec3::from_array(self).as_dvec3()
    }
}
impl IntoDVec3 for (f64, f64, f64) {
    #[inline]
    fn into_dvec3(self) -> DVec3 {
        DVec3::new(self.0, self.1, self.2)
    }
}

/// mint's points and vectors (the `mint` feature), so that code on another
/// vector crate passes its points through mint without naming glam.
///
/// ```
/// # #[cfg(feature = "mint")] {
/// use exactray::prelude::*;
/// let p = |x, y| mint::Point2 { x, y };
/// assert_eq!(orient2d(p(0.0, 0.0), p(1.0, 0.0), mint::Vector2 { x: 0.0, y: 1.0 }), Sign::Positive);
/// # }
/// ```
#[cfg(feature = "mint")]
mod mint_points {
    use super::{IntoDVec2, IntoDVec3};
    use glam::{DVec2, DVec3};

    macro_rules! mint_2d {
        ($($ty:ty),*) => {$(
            impl IntoDVec2 for $ty {
                #[inline]
                fn into_dvec2(self) -> DVec2 {
                    // f32 widens to f64 exactly.
                    DVec2::new(self.x.into(), self.y.into())
                }
            }
        )*};
    }

    macro_rules! mint_3d {
        ($($ty:ty),*) => {$(
            impl IntoDVec3 for $ty {
                #[inline]
                fn into_dvec3(self) -> DVec3 {
                    DVec3::new(self.x.into(), self.y.into(), self.z.into())
                }
            }
        )*};
    }

    mint_2d!(
        mint::Point2<f64>,
        mint::Vector2<f64>,
        mint::Point2<f32>,
        mint::Vector2<f32>
    );
    mint_3d!(
        mint::Point3<f64>,
        mint::Vector3<f64>,
        mint::Point3<f32>,
        mint::Vector3<f32>
    );
}
