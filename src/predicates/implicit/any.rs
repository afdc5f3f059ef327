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
#[allow(
    clippy::large_enum_variant,
    reason = "kept by value so that it is Copy and needs no allocation; the predicates read it in place"
)]
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
/// [`IntoDVec3`] type (an explicit point, by value), and references to
/// [`Lpi`], [`Tpi`] and [`AnyPoint3`]. The predicates read a constructed
/// point where it is: a copy of its inputs into the call would cost more
/// than the filter.
pub trait AsAnyPoint3 {
    /// The point as an owned [`AnyPoint3`].
    fn to_any_point3(&self) -> AnyPoint3;
    /// The point as the predicates read it.
    #[doc(hidden)]
    fn view3(&self) -> View3<'_>;
}

/// What the implicit 2D predicates accept where they take a point: every
/// [`IntoDVec2`] type (by value), and references to [`Ssi`] and
/// [`AnyPoint2`].
pub trait AsAnyPoint2 {
    /// The point as an owned [`AnyPoint2`].
    fn to_any_point2(&self) -> AnyPoint2;
    /// The point as the predicates read it.
    #[doc(hidden)]
    fn view2(&self) -> View2<'_>;
}

/// A 3D point as the predicates read it: an explicit point's coordinates,
/// or a reference to a constructed one.
#[doc(hidden)]
#[derive(Clone, Copy, Debug)]
pub enum View3<'a> {
    Explicit(DVec3),
    Lpi(&'a Lpi),
    Tpi(&'a Tpi),
}

/// A 2D point as the predicates read it.
#[doc(hidden)]
#[derive(Clone, Copy, Debug)]
pub enum View2<'a> {
    Explicit(DVec2),
    Ssi(&'a Ssi),
}

impl<T: IntoDVec3> AsAnyPoint3 for T {
    #[inline(always)]
    fn to_any_point3(&self) -> AnyPoint3 {
        AnyPoint3::Explicit(self.into_dvec3())
    }
    #[inline(always)]
    fn view3(&self) -> View3<'_> {
        View3::Explicit(self.into_dvec3())
    }
}

impl<T: IntoDVec2> AsAnyPoint2 for T {
    #[inline(always)]
    fn to_any_point2(&self) -> AnyPoint2 {
        AnyPoint2::Explicit(self.into_dvec2())
    }
    #[inline(always)]
    fn view2(&self) -> View2<'_> {
        View2::Explicit(self.into_dvec2())
    }
}

macro_rules! as_any {
    ($tr:ident, $to:ident, $view:ident, $any:ident, $v:ident, $($ty:ident),*) => {
        $(
            impl $tr for &$ty {
                #[inline(always)]
                fn $to(&self) -> $any {
                    $any::$ty(**self)
                }
                #[inline(always)]
                fn $view(&self) -> $v<'_> {
                    $v::$ty(*self)
                }
            }
        )*
    };
}
as_any!(
    AsAnyPoint3,
    to_any_point3,
    view3,
    AnyPoint3,
    View3,
    Lpi,
    Tpi
);
as_any!(AsAnyPoint2, to_any_point2, view2, AnyPoint2, View2, Ssi);

impl AsAnyPoint3 for &AnyPoint3 {
    #[inline(always)]
    fn to_any_point3(&self) -> AnyPoint3 {
        **self
    }
    #[inline(always)]
    fn view3(&self) -> View3<'_> {
        match self {
            AnyPoint3::Explicit(v) => View3::Explicit(*v),
            AnyPoint3::Lpi(x) => View3::Lpi(x),
            AnyPoint3::Tpi(x) => View3::Tpi(x),
        }
    }
}

impl AsAnyPoint2 for &AnyPoint2 {
    #[inline(always)]
    fn to_any_point2(&self) -> AnyPoint2 {
        **self
    }
    #[inline(always)]
    fn view2(&self) -> View2<'_> {
        match self {
            AnyPoint2::Explicit(v) => View2::Explicit(*v),
            AnyPoint2::Ssi(x) => View2::Ssi(x),
        }
    }
}

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
    /// Whether it is an explicit point.
    fn is_explicit(&self) -> bool;
    /// Whether its coordinates are finite (a constructed point's always
    /// are: its construction checked them).
    fn is_finite(&self) -> bool {
        self.explicit()
            .is_none_or(|v| v.iter().all(|c| c.is_finite()))
    }
    /// The degrees of the point's homogeneous coordinates and weight.
    fn degrees(&self) -> Degrees;
    /// The exact sign of the point's weight (`Positive` for an explicit one).
    fn weight_sign(&self) -> Sign;
    /// One of the input points that define it: the origin the predicates
    /// measure from when no explicit point is at hand.
    fn anchor(&self) -> [f64; D];
    /// Calls `f` with every input point that defines it.
    fn for_each_input(&self, f: impl FnMut([f64; D]));
    /// The owned points this kind of view reads.
    type Owned: Point<D>;
    /// The same point with every input coordinate times `2^k` (rounded
    /// where that underflows); a constructed point keeps its weight's sign,
    /// which scaling by a power of two does not change.
    fn scaled(&self, k: i32) -> Self::Owned;
    /// Its rounded homogeneous coordinates relative to `o`, with bounds.
    fn approx(&self, o: [f64; D]) -> approx::Hom<D>;
    /// Its exact homogeneous coordinates relative to `o` on the grid `lo`.
    fn exact<const K: usize>(&self, o: &[exact::Int<K>; D], lo: [i32; D]) -> exact::IntHom<K, D>;
}

impl Point<3> for View3<'_> {
    type Owned = AnyPoint3;

    #[inline(always)]
    fn explicit(&self) -> Option<[f64; 3]> {
        match self {
            View3::Explicit(v) => Some(v.to_array()),
            _ => None,
        }
    }

    #[inline(always)]
    fn is_explicit(&self) -> bool {
        matches!(self, View3::Explicit(_))
    }

    #[inline(always)]
    fn degrees(&self) -> Degrees {
        match self {
            View3::Explicit(_) => Degrees { l: 1, w: 0 },
            View3::Lpi(_) => Degrees { l: 4, w: 3 },
            View3::Tpi(_) => Degrees { l: 7, w: 6 },
        }
    }

    #[inline(always)]
    fn weight_sign(&self) -> Sign {
        match self {
            View3::Explicit(_) => Sign::Positive,
            View3::Lpi(x) => x.w,
            View3::Tpi(x) => x.w,
        }
    }

    #[inline(always)]
    fn anchor(&self) -> [f64; 3] {
        match self {
            View3::Explicit(v) => v.to_array(),
            View3::Lpi(x) => x.p.to_array(),
            View3::Tpi(x) => x.planes[0][0].to_array(),
        }
    }

    fn for_each_input(&self, mut f: impl FnMut([f64; 3])) {
        match self {
            View3::Explicit(v) => f(v.to_array()),
            View3::Lpi(x) => [x.p, x.q, x.r, x.s, x.t]
                .iter()
                .for_each(|v| f(v.to_array())),
            View3::Tpi(x) => x.planes.iter().flatten().for_each(|v| f(v.to_array())),
        }
    }

    fn scaled(&self, k: i32) -> AnyPoint3 {
        match self {
            View3::Explicit(v) => AnyPoint3::Explicit(scale3(*v, k)),
            View3::Lpi(x) => AnyPoint3::Lpi(x.scaled(k)),
            View3::Tpi(x) => AnyPoint3::Tpi(x.scaled(k)),
        }
    }

    #[inline(always)]
    fn approx(&self, o: [f64; 3]) -> approx::Hom<3> {
        let o = DVec3::from_array(o);
        match self {
            View3::Explicit(x) => approx::explicit((*x - o).to_array()),
            View3::Lpi(x) => approx::lpi(x.p, x.q, &x.cache, o),
            View3::Tpi(x) => approx::tpi(&x.planes, &x.cache, o),
        }
    }

    fn exact<const K: usize>(&self, o: &[exact::Int<K>; 3], lo: [i32; 3]) -> exact::IntHom<K, 3> {
        match self {
            View3::Explicit(x) => exact::explicit(x.to_array(), o, lo),
            View3::Lpi(x) => exact::lpi([x.p, x.q, x.r, x.s, x.t], o, lo),
            View3::Tpi(x) => exact::tpi(&x.planes, o, lo),
        }
    }
}

impl Point<2> for View2<'_> {
    type Owned = AnyPoint2;

    #[inline(always)]
    fn explicit(&self) -> Option<[f64; 2]> {
        match self {
            View2::Explicit(v) => Some(v.to_array()),
            _ => None,
        }
    }

    #[inline(always)]
    fn is_explicit(&self) -> bool {
        matches!(self, View2::Explicit(_))
    }

    #[inline(always)]
    fn degrees(&self) -> Degrees {
        match self {
            View2::Explicit(_) => Degrees { l: 1, w: 0 },
            View2::Ssi(_) => Degrees { l: 3, w: 2 },
        }
    }

    #[inline(always)]
    fn weight_sign(&self) -> Sign {
        match self {
            View2::Explicit(_) => Sign::Positive,
            View2::Ssi(x) => x.w,
        }
    }

    #[inline(always)]
    fn anchor(&self) -> [f64; 2] {
        match self {
            View2::Explicit(v) => v.to_array(),
            View2::Ssi(x) => x.p.to_array(),
        }
    }

    fn for_each_input(&self, mut f: impl FnMut([f64; 2])) {
        match self {
            View2::Explicit(v) => f(v.to_array()),
            View2::Ssi(x) => [x.p, x.q, x.r, x.s].iter().for_each(|v| f(v.to_array())),
        }
    }

    fn scaled(&self, k: i32) -> AnyPoint2 {
        match self {
            View2::Explicit(v) => AnyPoint2::Explicit(scale2(*v, k)),
            View2::Ssi(x) => AnyPoint2::Ssi(x.scaled(k)),
        }
    }

    #[inline(always)]
    fn approx(&self, o: [f64; 2]) -> approx::Hom<2> {
        let o = DVec2::from_array(o);
        match self {
            View2::Explicit(x) => approx::explicit((*x - o).to_array()),
            View2::Ssi(x) => approx::ssi(x.p, x.q, &x.cache, o),
        }
    }

    fn exact<const K: usize>(&self, o: &[exact::Int<K>; 2], lo: [i32; 2]) -> exact::IntHom<K, 2> {
        match self {
            View2::Explicit(x) => exact::explicit(x.to_array(), o, lo),
            View2::Ssi(x) => exact::ssi([x.p, x.q, x.r, x.s], o, lo),
        }
    }
}

macro_rules! owned_point {
    ($d:literal, $owned:ident, $view:ident) => {
        impl Point<$d> for $owned {
            type Owned = $owned;
            fn explicit(&self) -> Option<[f64; $d]> {
                self.$view().explicit()
            }
            fn is_explicit(&self) -> bool {
                self.$view().is_explicit()
            }
            fn degrees(&self) -> Degrees {
                self.$view().degrees()
            }
            fn weight_sign(&self) -> Sign {
                self.$view().weight_sign()
            }
            fn anchor(&self) -> [f64; $d] {
                self.$view().anchor()
            }
            fn for_each_input(&self, f: impl FnMut([f64; $d])) {
                self.$view().for_each_input(f)
            }
            fn scaled(&self, k: i32) -> $owned {
                self.$view().scaled(k)
            }
            fn approx(&self, o: [f64; $d]) -> approx::Hom<$d> {
                self.$view().approx(o)
            }
            fn exact<const K: usize>(
                &self,
                o: &[exact::Int<K>; $d],
                lo: [i32; $d],
            ) -> exact::IntHom<K, $d> {
                self.$view().exact(o, lo)
            }
        }
    };
}
owned_point!(3, AnyPoint3, view3);
owned_point!(2, AnyPoint2, view2);

impl View3<'_> {
    /// `Err` naming `argument` when an explicit point is not finite.
    pub(super) fn check(&self, argument: &'static str) -> Result<(), InputError> {
        match self {
            View3::Explicit(v) => check_finite3(&[(argument, *v)]),
            _ => Ok(()),
        }
    }
}

impl View2<'_> {
    /// `Err` naming `argument` when an explicit point is not finite.
    pub(super) fn check(&self, argument: &'static str) -> Result<(), InputError> {
        match self {
            View2::Explicit(v) => check_finite2(&[(argument, *v)]),
            _ => Ok(()),
        }
    }
}
