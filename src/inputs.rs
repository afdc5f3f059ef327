//! Predicate input types, with `Arbitrary` under the `arbitrary` feature (being written).
