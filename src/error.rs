//! Typed errors for input a query cannot answer.

use core::fmt;

/// Why an input was rejected. Every checked entry point of the crate
/// (`try_*` functions, validating constructors) returns this instead of
/// panicking or giving a meaningless answer.
///
/// ```
/// use exactray::{InputError, predicates::try_orient2d};
/// use glam::DVec2;
/// let err = try_orient2d(DVec2::ZERO, DVec2::new(f64::NAN, 0.0), DVec2::X).unwrap_err();
/// assert_eq!(err, InputError::NonFinite { argument: "b" });
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum InputError {
    /// A coordinate of the named argument is NaN or infinite.
    NonFinite {
        /// The parameter name of the offending argument, as in the function's
        /// signature (`"a"`, `"b"`, ...).
        argument: &'static str,
    },
    /// A radius or distance bound is negative or NaN.
    InvalidRadius {
        /// The parameter name of the offending argument.
        argument: &'static str,
    },
    /// A ray's direction is the zero vector.
    ZeroDirection,
    /// A shape parameter that makes the shape degenerate: a zero axis or
    /// normal, a zero cone radius.
    Degenerate {
        /// The parameter name of the offending argument.
        argument: &'static str,
    },
    /// A parameter that may be infinite but not NaN is NaN.
    NotANumber {
        /// The parameter name of the offending argument.
        argument: &'static str,
    },
    /// An interval whose lower bound exceeds its upper bound.
    ReversedInterval,
    /// Two slices that must have the same length do not.
    LengthMismatch {
        /// The length the first slice named in the function's docs has.
        expected: usize,
        /// The length of the other slice.
        got: usize,
    },
    /// More items than the structure can index (its documented maximum).
    TooManyItems {
        /// The largest number of items accepted.
        max: usize,
    },
    /// A constructed point that is not one point: the line and the plane
    /// of an [`Lpi`](crate::predicates::Lpi) are parallel (or the line's
    /// two points coincide, or the plane's three are collinear), the three
    /// planes of a [`Tpi`](crate::predicates::Tpi) do not meet in exactly
    /// one point, or the two lines of an [`Ssi`](crate::predicates::Ssi)
    /// are parallel. Decided exactly.
    NoUniqueIntersection {
        /// The construction: `"Lpi"`, `"Tpi"` or `"Ssi"`.
        construction: &'static str,
    },
    /// An index into a slice (a mesh triangle's vertex index) is not below
    /// the slice's length.
    IndexOutOfRange {
        /// The offending index.
        index: usize,
        /// The length of the slice it indexes.
        len: usize,
    },
    /// A query that needs a closed, consistently oriented mesh was asked
    /// of a mesh that is not one: some edge is not shared by exactly two
    /// triangles that run along it in opposite directions
    /// (`TriangleMesh::is_closed`, with `alloc`).
    OpenMesh,
}

impl InputError {
    /// `Ok` when a batch's two slices have the same length, else
    /// [`InputError::LengthMismatch`] with `expected` the first's (the
    /// batch queries of `bvh` and `scene`, with `alloc`).
    #[cfg(feature = "alloc")]
    #[inline]
    pub(crate) fn check_lengths(expected: usize, got: usize) -> Result<(), InputError> {
        if expected == got {
            Ok(())
        } else {
            Err(InputError::LengthMismatch { expected, got })
        }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputError::NonFinite { argument } => {
                write!(f, "argument `{argument}` has a NaN or infinite coordinate")
            }
            InputError::InvalidRadius { argument } => {
                write!(f, "argument `{argument}` is a negative or NaN radius")
            }
            InputError::ZeroDirection => write!(f, "the ray's direction is zero"),
            InputError::Degenerate { argument } => {
                write!(f, "argument `{argument}` makes the shape degenerate")
            }
            InputError::NotANumber { argument } => write!(f, "argument `{argument}` is NaN"),
            InputError::ReversedInterval => {
                write!(f, "the interval's lower bound exceeds its upper bound")
            }
            InputError::LengthMismatch { expected, got } => {
                write!(f, "slice lengths differ: {expected} and {got}")
            }
            InputError::TooManyItems { max } => write!(f, "more than {max} items"),
            InputError::NoUniqueIntersection { construction } => write!(
                f,
                "the lines or planes of the {construction} do not meet in exactly one point"
            ),
            InputError::IndexOutOfRange { index, len } => {
                write!(f, "index {index} out of range for length {len}")
            }
            InputError::OpenMesh => write!(
                f,
                "the mesh is not closed: some edge is not shared by two opposite triangles"
            ),
        }
    }
}

impl core::error::Error for InputError {}
