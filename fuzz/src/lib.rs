//! What the fuzz targets share: small meshes decoded from the fuzzer's
//! bytes, on a lattice at a power-of-two scale or from raw bit patterns.

use arbitrary::{Arbitrary, Unstructured};
use exactray::testing::finite_f64_from_bits;
use glam::DVec3;

/// A point: three raw bit patterns (any finite `f64`), or three `i8` on
/// the lattice of even multiples of `scale` (so that midpoints of lattice
/// points are exact).
pub fn lattice(u: &mut Unstructured, raw: bool, scale: f64) -> arbitrary::Result<DVec3> {
    if raw {
        let b = <[u64; 3]>::arbitrary(u)?;
        return Ok(DVec3::from_array(b.map(finite_f64_from_bits)));
    }
    let c = <[i8; 3]>::arbitrary(u)?;
    Ok(DVec3::from_array(c.map(|x| f64::from(x) * 2.0 * scale)))
}

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
    /// vertices), an `i16` for `k`, the vertices ([`lattice`]), a
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
            vertices.push(lattice(u, raw, scale).ok()?);
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
