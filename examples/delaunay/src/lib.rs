#![deny(missing_docs)]
//! # exactray-delaunay
//!
//! A real client of exactray's predicates: a small incremental Delaunay
//! triangulator of the kind people write against the `robust` crate,
//! generic over the two signs it asks ([`Predicates`]: `orient2d` and
//! `incircle`), run on exactray's ([`Exactray`]), on robust's
//! ([`Robust`]) and on the exact big-integer oracle's ([`Oracle`]). The
//! speed-against-error report's `delaunay` family times it and
//! [`audit()`]s every output exactly.
//!
//! spade, the Rust triangulator users reach for, hard-wires its own copy
//! of Shewchuk's predicates (its `DelaunayTriangulation` is generic over
//! vertex, edge and face data and a hint generator, not over predicates),
//! and refuses coordinates outside `2^-142 ..= 2^201`; so the triangulator
//! here is written for the purpose:
//!
//! - insertion in a biased randomized order along a Hilbert curve over the
//!   coordinates' ranks ([`order`]);
//! - point location by a visibility walk from the last insertion, with a
//!   random first edge per step;
//! - Bowyer–Watson cavities, with ghost triangles for the outside of the
//!   hull (no super-triangle: nothing but input coordinates is ever
//!   compared);
//! - duplicates skipped and listed, collinear inputs and points on the
//!   hull handled;
//! - no panic on any input, and no endless loop on any predicates: a walk
//!   longer than the triangulation or a cavity that is not a disk ends the
//!   run with a [`TriangulationError`].
//!
//! ```
//! use exactray_delaunay::{Exactray, audit, triangulate};
//! use glam::DVec2;
//! let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]].map(DVec2::from_array);
//! let t = triangulate::<Exactray>(&square)?;
//! assert_eq!(t.triangles.len(), 2);
//! assert_eq!(t.duplicates.len(), 1); // the second (1, 0)
//! assert_eq!(audit(&square, &t)?.errors(), 0);
//! # Ok::<(), exactray_delaunay::TriangulationError>(())
//! ```

pub mod audit;
pub mod order;
mod predicates;
mod triangulate;

pub use audit::{Audit, audit};
pub use predicates::{Exactray, Oracle, Predicates, Robust};
pub use triangulate::{MAX_POINTS, Triangulation, TriangulationError, triangle_set, triangulate};
