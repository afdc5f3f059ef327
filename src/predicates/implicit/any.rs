//! The points a predicate takes, explicit or constructed ([`AnyPoint3`],
//! [`AnyPoint2`]), the conversions into them, and what the predicates'
//! ladders need of them ([`Point`]).

use super::approx;
use super::exact;
use super::points::{Lpi, Ssi, Tpi, scale2, scale3};
use crate::error::InputError;
use crate::point::{IntoDVec2, IntoDVec3};
use crate::predicates::{check_finite2, check_finite3};
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// A 3D point a predicate takes: an input point, or a point constructed
/// from input points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AnyPoint3 {
    /// An input point, its coordinates exact as given.
    Explicit(DVec3),
    /// A line–plane intersection.
    Lpi(Lpi),
    /// A three-plane intersection.
    Tpi(Tpi),
}

/// A 2D point a predicate takes: an input point, or the intersection of two
/// lines.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AnyPoint2 {
    /// An input point, its coordinates exact as given.
    Explicit(DVec2),
    /// A line–line intersection.
    Ssi(Ssi),
}

/// What the implicit predicates accept where they take a 3D point: every
/// [`IntoDVec3`] type (an explicit point), [`Lpi`], [`Tpi`], [`AnyPoint3`]
/// and references to those three.
pub trait IntoAnyPoint3: Copy {
    /// The point as an [`AnyPoint3`].
    fn into_any_point3(self) -> AnyPoint3;
}

/// What the implicit 2D predicates accept where they take a point: every
/// [`IntoDVec2`] type, [`Ssi`], [`AnyPoint2`] and references to those two.
pub trait IntoAnyPoint2: Copy {
    /// The point as an [`AnyPoint2`].
    fn into_any_point2(self) -> AnyPoint2;
}

impl<T: IntoDVec3> IntoAnyPoint3 for T {
    #[inline]
    fn into_any_point3(self) -> AnyPoint3 {
        AnyPoint3::Explicit(self.into_dvec3())
    }
}

impl<T: IntoDVec2> IntoAnyPoint2 for T {
    #[inline]
    fn into_any_point2(self) -> AnyPoint2 {
        AnyPoint2::Explicit(self.into_dvec2())
    }
}

macro_rules! into_any {
    ($tr:ident, $f:ident, $any:ident, $($ty:ident => $variant:ident),*) => {
        $(
            impl $tr for $ty {
                #[inline]
                fn $f(self) -> $any {
                    $any::$variant(self)
                }
            }
            impl $tr for &$ty {
                #[inline]
                fn $f(self) -> $any {
                    $any::$variant(*self)
                }
            }
        )*
        impl $tr for $any {
            #[inline]
            fn $f(self) -> $any {
                self
            }
        }
        impl $tr for &$any {
            #[inline]
            fn $f(self) -> $any {
                *self
            }
        }
    };
}
into_any!(IntoAnyPoint3, into_any_point3, AnyPoint3, Lpi => Lpi, Tpi => Tpi);
into_any!(IntoAnyPoint2, into_any_point2, AnyPoint2, Ssi => Ssi);

impl From<Lpi> for AnyPoint3 {
    fn from(x: Lpi) -> Self {
        AnyPoint3::Lpi(x)
    }
}

impl From<Tpi> for AnyPoint3 {
    fn from(x: Tpi) -> Self {
        AnyPoint3::Tpi(x)
    }
}

impl From<DVec3> for AnyPoint3 {
    fn from(x: DVec3) -> Self {
        AnyPoint3::Explicit(x)
    }
}

impl From<Ssi> for AnyPoint2 {
    fn from(x: Ssi) -> Self {
        AnyPoint2::Ssi(x)
    }
}

impl From<DVec2> for AnyPoint2 {
    fn from(x: DVec2) -> Self {
        AnyPoint2::Explicit(x)
    }
}

/// The degrees of a point's homogeneous coordinates and of its weight in
/// the input coordinates (an explicit point: `x - o` over the weight 1).
#[derive(Clone, Copy)]
pub(super) struct Degrees {
    pub(super) l: u32,
    pub(super) w: u32,
}

/// What the predicates' ladders need of a point in `D` dimensions.
pub(super) trait Point<const D: usize>: Copy {
    /// The coordinates of an explicit point.
    fn explicit(&self) -> Option<[f64; D]>;
    /// The degrees of the point's homogeneous coordinates and weight.
    fn degrees(&self) -> Degrees;
    /// The exact sign of the point's weight (`Positive` for an explicit one).
    fn weight_sign(&self) -> Sign;
    /// One of the input points that define it: the origin the predicates
    /// measure from when no explicit point is at hand.
    fn anchor(&self) -> [f64; D];
    /// Calls `f` with every input point that defines it.
    fn for_each_input(&self, f: impl FnMut([f64; D]));
    /// The same point with every input coordinate times `2^k` (rounded
    /// where that underflows); a constructed point keeps its weight's sign,
    /// which scaling by a power of two does not change.
    fn scaled(&self, k: i32) -> Self;
    /// Its rounded homogeneous coordinates relative to `o`, with bounds.
    fn approx(&self, o: [f64; D]) -> approx::Hom<D>;
    /// Its exact homogeneous coordinates relative to `o` on the grid `lo`.
    fn exact<const K: usize>(&self, o: &[exact::Int<K>; D], lo: [i32; D]) -> exact::IntHom<K, D>;
}

impl Point<3> for AnyPoint3 {
    fn explicit(&self) -> Option<[f64; 3]> {
        match self {
            AnyPoint3::Explicit(v) => Some(v.to_array()),
            _ => None,
        }
    }

    fn degrees(&self) -> Degrees {
        match self {
            AnyPoint3::Explicit(_) => Degrees { l: 1, w: 0 },
            AnyPoint3::Lpi(_) => Degrees { l: 4, w: 3 },
            AnyPoint3::Tpi(_) => Degrees { l: 7, w: 6 },
        }
    }

    fn weight_sign(&self) -> Sign {
        match self {
            AnyPoint3::Explicit(_) => Sign::Positive,
            AnyPoint3::Lpi(x) => x.w,
            AnyPoint3::Tpi(x) => x.w,
        }
    }

    fn anchor(&self) -> [f64; 3] {
        match self {
            AnyPoint3::Explicit(v) => v.to_array(),
            AnyPoint3::Lpi(x) => x.p.to_array(),
            AnyPoint3::Tpi(x) => x.planes[0][0].to_array(),
        }
    }

    fn for_each_input(&self, mut f: impl FnMut([f64; 3])) {
        match self {
            AnyPoint3::Explicit(v) => f(v.to_array()),
            AnyPoint3::Lpi(x) => [x.p, x.q, x.r, x.s, x.t]
                .iter()
                .for_each(|v| f(v.to_array())),
            AnyPoint3::Tpi(x) => x.planes.iter().flatten().for_each(|v| f(v.to_array())),
        }
    }

    fn scaled(&self, k: i32) -> AnyPoint3 {
        match self {
            AnyPoint3::Explicit(v) => AnyPoint3::Explicit(scale3(*v, k)),
            AnyPoint3::Lpi(x) => AnyPoint3::Lpi(x.scaled(k)),
            AnyPoint3::Tpi(x) => AnyPoint3::Tpi(x.scaled(k)),
        }
    }

    #[inline(always)]
    fn approx(&self, o: [f64; 3]) -> approx::Hom<3> {
        approx::hom3(self, DVec3::from_array(o))
    }

    fn exact<const K: usize>(&self, o: &[exact::Int<K>; 3], lo: [i32; 3]) -> exact::IntHom<K, 3> {
        exact::hom3(self, o, lo)
    }
}

impl Point<2> for AnyPoint2 {
    fn explicit(&self) -> Option<[f64; 2]> {
        match self {
            AnyPoint2::Explicit(v) => Some(v.to_array()),
            _ => None,
        }
    }

    fn degrees(&self) -> Degrees {
        match self {
            AnyPoint2::Explicit(_) => Degrees { l: 1, w: 0 },
            AnyPoint2::Ssi(_) => Degrees { l: 3, w: 2 },
        }
    }

    fn weight_sign(&self) -> Sign {
        match self {
            AnyPoint2::Explicit(_) => Sign::Positive,
            AnyPoint2::Ssi(x) => x.w,
        }
    }

    fn anchor(&self) -> [f64; 2] {
        match self {
            AnyPoint2::Explicit(v) => v.to_array(),
            AnyPoint2::Ssi(x) => x.p.to_array(),
        }
    }

    fn for_each_input(&self, mut f: impl FnMut([f64; 2])) {
        match self {
            AnyPoint2::Explicit(v) => f(v.to_array()),
            AnyPoint2::Ssi(x) => [x.p, x.q, x.r, x.s].iter().for_each(|v| f(v.to_array())),
        }
    }

    fn scaled(&self, k: i32) -> AnyPoint2 {
        match self {
            AnyPoint2::Explicit(v) => AnyPoint2::Explicit(scale2(*v, k)),
            AnyPoint2::Ssi(x) => AnyPoint2::Ssi(x.scaled(k)),
        }
    }

    #[inline(always)]
    fn approx(&self, o: [f64; 2]) -> approx::Hom<2> {
        approx::hom2(self, DVec2::from_array(o))
    }

    fn exact<const K: usize>(&self, o: &[exact::Int<K>; 2], lo: [i32; 2]) -> exact::IntHom<K, 2> {
        exact::hom2(self, o, lo)
    }
}

impl AnyPoint3 {
    /// `Err` naming `argument` when an explicit point is not finite.
    pub(super) fn check(&self, argument: &'static str) -> Result<(), InputError> {
        match self {
            AnyPoint3::Explicit(v) => check_finite3(&[(argument, *v)]),
            _ => Ok(()),
        }
    }
}

impl AnyPoint2 {
    /// `Err` naming `argument` when an explicit point is not finite.
    pub(super) fn check(&self, argument: &'static str) -> Result<(), InputError> {
        match self {
            AnyPoint2::Explicit(v) => check_finite2(&[(argument, *v)]),
            _ => Ok(()),
        }
    }
}
