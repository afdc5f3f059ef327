//! Self-test of the exact oracle's conventions.
mod common;
