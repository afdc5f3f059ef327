//! What the fuzz targets share: small meshes decoded from the fuzzer's
//! bytes, on a lattice at a power-of-two scale or from raw bit patterns.

use arbitrary::{Arbitrary, Unstructured};
use exactray::testing::lattice_point;
use glam::DVec3;

/// A mesh of 3 to 8 vertices and 1 to 8 triangles over them (shared edges
/// and vertices, degenerate triangles at times).
pub struct LatticeMesh {
    /// Raw bit patterns (mode byte `% 8 == 7`) rather than the lattice.
    pub raw: bool,
    /// The scale's exponent, in `-1000..=1000`.
    pub k: i32,
    /// `2^k`.
    pub scale: f64,
    /// The vertices.
    pub vertices: Vec<DVec3>,
    /// The triangles, indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
}

impl LatticeMesh {
    /// Decodes a mode byte (`% 8 == 7`: raw; `3 + mode / 8 % 6`
    /// vertices), an `i16` for `k`, the vertices (`lattice_point` with a
    /// step of `2 scale`, so that midpoints are exact), a
    /// triangle-count byte (`1 + b % 8`) and three index bytes per
    /// triangle; `None` when the bytes run out.
    pub fn decode(u: &mut Unstructured) -> Option<LatticeMesh> {
        let mode = u8::arbitrary(u).ok()?;
        let raw = mode % 8 == 7;
        // 2^k for k in -1000..=1000, in two exact steps.
        let k = i32::from(i16::arbitrary(u).unwrap_or(0)) % 1001;
        let scale = 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
        let nv = 3 + usize::from(mode / 8 % 6);
        let mut vertices = Vec::with_capacity(nv);
        for _ in 0..nv {
            vertices.push(lattice_point(u, raw, 2.0 * scale).ok()?);
        }
        let nt = 1 + usize::from(u8::arbitrary(u).unwrap_or(0) % 8);
        let mut triangles = Vec::with_capacity(nt);
        for _ in 0..nt {
            let t = <[u8; 3]>::arbitrary(u).ok()?;
            triangles.push(t.map(|i| u32::from(i) % nv as u32));
        }
        Some(LatticeMesh {
            raw,
            k,
            scale,
            vertices,
            triangles,
        })
    }
}
