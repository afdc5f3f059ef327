//! Criterion benchmarks of the predicates (being written).
fn main() {}
