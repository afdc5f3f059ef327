//! Shapes, by what they are: each type validates itself at construction
//! (typed [`InputError`](crate::InputError)s for negative or NaN radii, zero
//! axes, degenerate angles, non-finite coordinates), so every query on it can
//! rely on finite, meaningful parameters. What can be asked of a shape lives
//! in [`query`](crate::query).

pub mod triangle;

pub use triangle::Triangle;
