//! proptest strategies for hard inputs (being written).
