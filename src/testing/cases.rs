//! Predicate input types, for users' fuzz targets and tests.
//!
//! Each type holds the arguments of one predicate call and evaluates it with
//! [`eval`](Orient2dInput::eval). With the `arbitrary` feature every type
//! implements `arbitrary::Arbitrary`: each coordinate is a finite `f64`
//! drawn from a raw 64-bit pattern (see [`finite_f64_from_bits`]), so a fuzzer
//! reaches every finite value, subnormals and both zeros included, and never
//! produces a NaN or an infinity.
//!
//! ```
//! use exactray::testing::Orient2dInput;
//! use exactray::Sign;
//! use glam::DVec2;
//! let input = Orient2dInput { a: DVec2::ZERO, b: DVec2::X, c: DVec2::Y };
//! assert_eq!(input.eval(), Sign::Positive);
//! ```
//!
//! A fuzz target built on these types (with the `arbitrary` feature):
//!
//! ```
//! # #[cfg(feature = "arbitrary")]
//! # {
//! use arbitrary::{Arbitrary, Unstructured};
//! use exactray::testing::InsphereInput;
//! use exactray::Sign;
//!
//! let fuzz_bytes = [0x5au8; 120];
//! let mut u = Unstructured::new(&fuzz_bytes);
//! let input = InsphereInput::arbitrary(&mut u).unwrap();
//! assert!(input.e.is_finite());
//! // Five equal points are cospherical.
//! assert_eq!(input.eval(), Sign::Zero);
//! # }
//! ```

use crate::error::InputError;
use crate::predicates::{self, SideRelation};
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// The `f64` with bit pattern `bits` when that is finite; otherwise (an
/// infinity or a NaN) the finite value with the same sign and fraction bits
/// and the largest finite exponent.
///
/// Every finite `f64` is the image of its own bit pattern, so a uniformly
/// random `u64` reaches every finite value, including subnormals and `-0.0`.
///
/// ```
/// use exactray::testing::finite_f64_from_bits;
/// assert_eq!(finite_f64_from_bits(1.5f64.to_bits()), 1.5);
/// assert_eq!(finite_f64_from_bits(1).to_bits(), 1); // smallest subnormal
/// assert_eq!(finite_f64_from_bits(f64::INFINITY.to_bits()), 2f64.powi(1023));
/// assert!(finite_f64_from_bits(f64::NAN.to_bits()).is_finite());
/// ```
#[inline]
pub const fn finite_f64_from_bits(bits: u64) -> f64 {
    // Exponent field 0x7ff is the only non-finite one; clearing its lowest
    // bit lands on 0x7fe, a finite binade, and leaves finite patterns alone.
    const EXP_MASK: u64 = 0x7ff << 52;
    if bits & EXP_MASK == EXP_MASK {
        f64::from_bits(bits & !(1 << 52))
    } else {
        f64::from_bits(bits)
    }
}

/// Arguments of [`orient2d`](crate::predicates::orient2d).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orient2dInput {
    /// First point.
    pub a: DVec2,
    /// Second point.
    pub b: DVec2,
    /// Third point.
    pub c: DVec2,
}

impl Orient2dInput {
    /// `orient2d(a, b, c)`.
    #[inline]
    pub fn eval(&self) -> Sign {
        predicates::orient2d(self.a, self.b, self.c)
    }

    /// `try_orient2d(a, b, c)`: an error for a non-finite coordinate.
    #[inline]
    pub fn try_eval(&self) -> Result<Sign, InputError> {
        predicates::try_orient2d(self.a, self.b, self.c)
    }

    /// The points in argument order.
    #[inline]
    pub const fn to_array(&self) -> [DVec2; 3] {
        [self.a, self.b, self.c]
    }
}

impl From<[DVec2; 3]> for Orient2dInput {
    #[inline]
    fn from([a, b, c]: [DVec2; 3]) -> Self {
        Orient2dInput { a, b, c }
    }
}

/// Arguments of [`orient3d`](crate::predicates::orient3d).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orient3dInput {
    /// First point.
    pub a: DVec3,
    /// Second point.
    pub b: DVec3,
    /// Third point.
    pub c: DVec3,
    /// Fourth point, the one tested against the plane of the other three.
    pub d: DVec3,
}

impl Orient3dInput {
    /// `orient3d(a, b, c, d)`.
    #[inline]
    pub fn eval(&self) -> Sign {
        predicates::orient3d(self.a, self.b, self.c, self.d)
    }

    /// `try_orient3d(a, b, c, d)`: an error for a non-finite coordinate.
    #[inline]
    pub fn try_eval(&self) -> Result<Sign, InputError> {
        predicates::try_orient3d(self.a, self.b, self.c, self.d)
    }

    /// The points in argument order.
    #[inline]
    pub const fn to_array(&self) -> [DVec3; 4] {
        [self.a, self.b, self.c, self.d]
    }
}

impl From<[DVec3; 4]> for Orient3dInput {
    #[inline]
    fn from([a, b, c, d]: [DVec3; 4]) -> Self {
        Orient3dInput { a, b, c, d }
    }
}

/// Arguments of [`incircle`](crate::predicates::incircle).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IncircleInput {
    /// First point on the circle.
    pub a: DVec2,
    /// Second point on the circle.
    pub b: DVec2,
    /// Third point on the circle.
    pub c: DVec2,
    /// The point tested against the circle.
    pub d: DVec2,
}

impl IncircleInput {
    /// `incircle(a, b, c, d)`.
    #[inline]
    pub fn eval(&self) -> Sign {
        predicates::incircle(self.a, self.b, self.c, self.d)
    }

    /// `try_incircle(a, b, c, d)`: an error for a non-finite coordinate.
    #[inline]
    pub fn try_eval(&self) -> Result<Sign, InputError> {
        predicates::try_incircle(self.a, self.b, self.c, self.d)
    }

    /// The points in argument order.
    #[inline]
    pub const fn to_array(&self) -> [DVec2; 4] {
        [self.a, self.b, self.c, self.d]
    }
}

impl From<[DVec2; 4]> for IncircleInput {
    #[inline]
    fn from([a, b, c, d]: [DVec2; 4]) -> Self {
        IncircleInput { a, b, c, d }
    }
}

/// Arguments of [`insphere`](crate::predicates::insphere).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InsphereInput {
    /// First point on the sphere.
    pub a: DVec3,
    /// Second point on the sphere.
    pub b: DVec3,
    /// Third point on the sphere.
    pub c: DVec3,
    /// Fourth point on the sphere.
    pub d: DVec3,
    /// The point tested against the sphere.
    pub e: DVec3,
}

impl InsphereInput {
    /// `insphere(a, b, c, d, e)`.
    #[inline]
    pub fn eval(&self) -> Sign {
        predicates::insphere(self.a, self.b, self.c, self.d, self.e)
    }

    /// `try_insphere(a, b, c, d, e)`: an error for a non-finite coordinate.
    #[inline]
    pub fn try_eval(&self) -> Result<Sign, InputError> {
        predicates::try_insphere(self.a, self.b, self.c, self.d, self.e)
    }

    /// The points in argument order.
    #[inline]
    pub const fn to_array(&self) -> [DVec3; 5] {
        [self.a, self.b, self.c, self.d, self.e]
    }
}

impl From<[DVec3; 5]> for InsphereInput {
    #[inline]
    fn from([a, b, c, d, e]: [DVec3; 5]) -> Self {
        InsphereInput { a, b, c, d, e }
    }
}

/// Arguments of [`same_side`](crate::predicates::same_side): a triangle `x0, x1, x2` and
/// two points `p`, `q`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneSideInput {
    /// First triangle vertex.
    pub x0: DVec3,
    /// Second triangle vertex.
    pub x1: DVec3,
    /// Third triangle vertex.
    pub x2: DVec3,
    /// First tested point.
    pub p: DVec3,
    /// Second tested point.
    pub q: DVec3,
}

impl PlaneSideInput {
    /// `same_side(x0, x1, x2, p, q)`.
    #[inline]
    pub fn eval(&self) -> SideRelation {
        predicates::same_side(self.x0, self.x1, self.x2, self.p, self.q)
    }

    /// `try_same_side(x0, x1, x2, p, q)`: an error for a non-finite
    /// coordinate.
    #[inline]
    pub fn try_eval(&self) -> Result<SideRelation, InputError> {
        predicates::try_same_side(self.x0, self.x1, self.x2, self.p, self.q)
    }

    /// `(side_of_plane(x0, x1, x2, p), side_of_plane(x0, x1, x2, q))`.
    #[inline]
    pub fn sides(&self) -> (Sign, Sign) {
        (
            predicates::side_of_plane(self.x0, self.x1, self.x2, self.p),
            predicates::side_of_plane(self.x0, self.x1, self.x2, self.q),
        )
    }

    /// The points in argument order.
    #[inline]
    pub const fn to_array(&self) -> [DVec3; 5] {
        [self.x0, self.x1, self.x2, self.p, self.q]
    }
}

impl From<[DVec3; 5]> for PlaneSideInput {
    #[inline]
    fn from([x0, x1, x2, p, q]: [DVec3; 5]) -> Self {
        PlaneSideInput { x0, x1, x2, p, q }
    }
}

#[cfg(feature = "arbitrary")]
pub use arbitrary_impls::lattice_point;

#[cfg(feature = "arbitrary")]
mod arbitrary_impls {
    use super::{
        IncircleInput, InsphereInput, Orient2dInput, Orient3dInput, PlaneSideInput,
        finite_f64_from_bits,
    };
    use arbitrary::{Arbitrary, Result, Unstructured};
    use glam::{DVec2, DVec3};

    // Raw bits rather than `f64::arbitrary`, which yields NaN and infinities
    // and would make every target filter them.
    fn coord(u: &mut Unstructured<'_>) -> Result<f64> {
        Ok(finite_f64_from_bits(u64::arbitrary(u)?))
    }

    fn dvec2(u: &mut Unstructured<'_>) -> Result<DVec2> {
        Ok(DVec2::new(coord(u)?, coord(u)?))
    }

    fn dvec3(u: &mut Unstructured<'_>) -> Result<DVec3> {
        Ok(DVec3::new(coord(u)?, coord(u)?, coord(u)?))
    }

    /// A point for a fuzz target's mesh or ray: three raw bit patterns
    /// made finite ([`finite_f64_from_bits`]) when `raw`, else three `i8`s
    /// times `step`, a small lattice on which points coincide, edges are
    /// shared and midpoints are exact.
    ///
    /// # Errors
    /// When `u` runs out of data.
    pub fn lattice_point(u: &mut Unstructured<'_>, raw: bool, step: f64) -> Result<DVec3> {
        if raw {
            return dvec3(u);
        }
        let c = <[i8; 3]>::arbitrary(u)?;
        Ok(DVec3::from_array(c.map(|x| f64::from(x) * step)))
    }

    const fn exact_hint(coords: usize) -> (usize, Option<usize>) {
        (coords * 8, Some(coords * 8))
    }

    impl<'a> Arbitrary<'a> for Orient2dInput {
        fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
            Ok(Orient2dInput {
                a: dvec2(u)?,
                b: dvec2(u)?,
                c: dvec2(u)?,
            })
        }
        fn size_hint(_depth: usize) -> (usize, Option<usize>) {
            exact_hint(6)
        }
    }

    impl<'a> Arbitrary<'a> for Orient3dInput {
        fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
            Ok(Orient3dInput {
                a: dvec3(u)?,
                b: dvec3(u)?,
                c: dvec3(u)?,
                d: dvec3(u)?,
            })
        }
        fn size_hint(_depth: usize) -> (usize, Option<usize>) {
            exact_hint(12)
        }
    }

    impl<'a> Arbitrary<'a> for IncircleInput {
        fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
            Ok(IncircleInput {
                a: dvec2(u)?,
                b: dvec2(u)?,
                c: dvec2(u)?,
                d: dvec2(u)?,
            })
        }
        fn size_hint(_depth: usize) -> (usize, Option<usize>) {
            exact_hint(8)
        }
    }

    impl<'a> Arbitrary<'a> for InsphereInput {
        fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
            Ok(InsphereInput {
                a: dvec3(u)?,
                b: dvec3(u)?,
                c: dvec3(u)?,
                d: dvec3(u)?,
                e: dvec3(u)?,
            })
        }
        fn size_hint(_depth: usize) -> (usize, Option<usize>) {
            exact_hint(15)
        }
    }

    impl<'a> Arbitrary<'a> for PlaneSideInput {
        fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
            Ok(PlaneSideInput {
                x0: dvec3(u)?,
                x1: dvec3(u)?,
                x2: dvec3(u)?,
                p: dvec3(u)?,
                q: dvec3(u)?,
            })
        }
        fn size_hint(_depth: usize) -> (usize, Option<usize>) {
            exact_hint(15)
        }
    }
}
