//! The pictures of `docs/pictures.md` on exactray's scene layer: one
//! Cornell-box-like room built in code ([`room`]), three renderers over it
//! and the images that answer the graphics questions Q2–Q6.
//!
//! - [`zbuffer`]: a Z-buffer rasterizer on the crate's homogeneous
//!   clipping (before the divide) and exact-coverage rasterization.
//! - [`whitted`]: a ray tracer with one shadow ray per light (Q5) and
//!   mirror reflections kept above the surface (Q3).
//! - [`path`]: a path tracer with next-event estimation (Q4), rayon over
//!   pixels, reproducible from its seed.
//!
//! Every secondary ray leaves its surface by the hit's certified point
//! error (`exactray::scene::spawn_ray`): no epsilon anywhere. `cargo run
//! --release -p exactray-render` writes the README's pictures to `docs/`.

pub mod camera;
pub mod image;
pub mod path;
pub mod plot;
pub mod room;
pub mod shade;
pub mod whitted;
pub mod zbuffer;
