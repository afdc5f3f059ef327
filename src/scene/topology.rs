//! Whether a mesh is closed and consistently oriented, and which of its
//! triangles its hierarchy leaves out ([`Topology`]): found once when a
//! [`TriangleMesh`](super::TriangleMesh) is built, for the queries of
//! `crossings.rs`.

use crate::shape::Triangle;
use alloc::vec;
use alloc::vec::Vec;
use glam::DVec3;

/// Whether a mesh is closed, and the triangles its hierarchy leaves out,
/// found once when the mesh is built.
#[derive(Clone, Debug)]
pub(super) struct Topology {
    /// Every edge `u v` of a triangle with three distinct indices is an
    /// edge of exactly one such triangle, and `v u` of exactly one other.
    pub(super) closed: bool,
    /// The triangles left out of the hierarchy ([`in_hierarchy`]):
    /// degenerate, or too thin for a unit normal.
    pub(super) left_out: Vec<u32>,
}

impl Topology {
    /// No triangles: the empty mesh's topology.
    pub(super) const EMPTY: Topology = Topology {
        closed: true,
        left_out: Vec::new(),
    };

    /// The topology of the mesh of `triangles` whose hierarchy holds the
    /// triangles `held_in_hierarchy`: a sort of its directed edges,
    /// `O(n log n)` for `n` triangles.
    pub(super) fn of(triangles: &[[u32; 3]], held_in_hierarchy: &[u32]) -> Topology {
        let mut held = vec![false; triangles.len()];
        for &i in held_in_hierarchy {
            held[i as usize] = true;
        }
        let left_out = (0..triangles.len() as u32)
            .filter(|&i| !held[i as usize])
            .collect();
        let key = |u: u32, v: u32| (u64::from(u) << 32) | u64::from(v);
        let mut edges: Vec<u64> = triangles
            .iter()
            .filter(|[a, b, c]| a != b && b != c && c != a)
            .flat_map(|&[a, b, c]| [key(a, b), key(b, c), key(c, a)])
            .collect();
        edges.sort_unstable();
        let unique = edges.windows(2).all(|w| w[0] != w[1]);
        let paired = || {
            edges
                .iter()
                .all(|&e| edges.binary_search(&e.rotate_left(32)).is_ok())
        };
        Topology {
            closed: unique && paired(),
            left_out,
        }
    }
}

/// Whether the hierarchy holds `tri`: it is not degenerate and its unit
/// normal is not lost to rounding (the others are never hit by the
/// hierarchy's queries).
#[inline]
pub(super) fn in_hierarchy(tri: &Triangle) -> bool {
    !tri.degenerate && tri.normal() != DVec3::ZERO
}
