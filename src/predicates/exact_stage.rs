//! Exact stages shared by the predicates (in progress).
