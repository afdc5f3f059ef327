//! Deterministic generators of hard predicate inputs (being written).
