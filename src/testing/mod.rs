//! Hard inputs for tests, benchmarks and fuzz targets: the crate's own and
//! its users'. One door for three kinds of thing:
//!
//! - deterministic generators of uniform, near-degenerate, degenerate,
//!   tiny, huge and mixed-magnitude cases ([`InputClass`], [`SplitMix64`],
//!   [`orient2d_case`], ...), the same on every platform for a seed;
//! - one predicate call as a struct ([`Orient2dInput`], ...), with
//!   `arbitrary::Arbitrary` under the `arbitrary` feature, every coordinate
//!   a finite `f64` from a raw bit pattern ([`finite_f64_from_bits`]);
//! - proptest strategies over both (`orient2d_inputs`, `finite_dvec3`, ...)
//!   under the `proptest` feature.
//!
//! On the side of the floors: nothing in the library's queries imports it.
//!
//! ```
//! use exactray::prelude::*;
//! use exactray::testing::{orient3d_case, InputClass, SplitMix64};
//! let mut rng = SplitMix64::new(7);
//! for class in InputClass::ALL {
//!     let [a, b, c, d] = orient3d_case(class, &mut rng);
//!     let _ = orient3d(a, b, c, d);
//! }
//! ```

mod cases;
mod generators;
#[cfg(feature = "proptest")]
mod strategies;

pub use cases::*;
pub use generators::*;
#[cfg(feature = "proptest")]
pub use strategies::*;
