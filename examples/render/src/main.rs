//! Writes the README's pictures to `docs/` and prints the time each took:
//! `cargo run --release -p exactray-render` (from the repository root).
//! `--quick` renders at a quarter of the size, with fewer paths; `--out
//! DIR` writes there instead of `docs/`.

use exactray_render::path::PathTracer;
use exactray_render::plot::log_log_svg;
use exactray_render::room::cornell_room;
use exactray_render::shade::Reflection;
use exactray_render::whitted::RayTracer;
use exactray_render::zbuffer;
use std::time::Instant;

fn main() -> std::io::Result<()> {
    let quick = std::env::args().any(|a| a == "--quick");
    let (w, h) = if quick { (128, 96) } else { (512, 384) };
    let args: Vec<String> = std::env::args().collect();
    let docs = match args
        .iter()
        .position(|a| a == "--out")
        .and_then(|i| args.get(i + 1))
    {
        Some(dir) => std::path::PathBuf::from(dir),
        None => std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs"),
    };
    std::fs::create_dir_all(&docs)?;
    let room = cornell_room(w, h);
    let threads = rayon::current_num_threads();
    println!("| picture | size | time | rays | rays per second |\n|---|---|---|---|---|");

    let start = Instant::now();
    let (raster, vis) = zbuffer::render(&room, w, h);
    let s = start.elapsed().as_secs_f64();
    let tris: usize = room.raster.iter().map(|m| m.triangles.len()).sum();
    println!(
        "| Z-buffer ({tris} triangles, {} fragments, one core) | {w}x{h} | {:.1} ms | – | – |",
        vis.fragments,
        s * 1e3
    );
    raster.write_png(docs.join("render-raster.png"))?;

    // Q6: a camera inside the room, whose walls reach behind it.
    let inside = exactray_render::camera::Camera::new(
        glam::DVec3::new(0.0, 1.0, 0.6),
        glam::DVec3::new(0.0, 0.7, -1.0),
        glam::DVec3::Y,
        75.0,
        w,
        h,
    )
    .expect("valid camera");
    let (unclipped, bad) = zbuffer::render_from(&room, &inside, zbuffer::Clipping::None);
    let (clipped, good) = zbuffer::render_from(&room, &inside, zbuffer::Clipping::Frustum);
    let wrong = bad
        .pixels
        .iter()
        .zip(&good.pixels)
        .filter(|(a, b)| a.map(|v| (v.mesh, v.triangle)) != b.map(|v| (v.mesh, v.triangle)))
        .count();
    println!(
        "| Q6: Z-buffer from inside the room, divided without clipping: {wrong} pixels show another triangle than with clipping | {w}x{h} | – | – | – |"
    );
    unclipped
        .beside(&clipped, 6)
        .write_png(docs.join("q6-clipping.png"))?;

    let tracer = RayTracer::default();
    let start = Instant::now();
    let (traced, counts) = tracer.render(&room, w, h);
    let s = start.elapsed().as_secs_f64();
    println!(
        "| ray traced, shadow rays ({threads} threads) | {w}x{h} | {:.1} ms | {} | {:.2} M |",
        s * 1e3,
        counts.total(),
        counts.total() as f64 / s / 1e6
    );
    traced.write_png(docs.join("render-raytraced.png"))?;

    let plain = RayTracer {
        reflection: Reflection::Plain,
        ..tracer
    };
    let (plain_image, plain_counts) = plain.render(&room, w, h);
    let differ = plain_image
        .pixels()
        .iter()
        .zip(traced.pixels())
        .filter(|(a, b)| a != b)
        .count();
    println!(
        "\nQ3: plain reflection sent {} of the frame's mirror reflections below the surface ({differ} pixels differ); reflect_above sent {}.\n",
        plain_counts.below_surface, counts.below_surface
    );
    // The crop around the smooth sphere, from its vertices' projections.
    let camera = room.camera.with_size(w, h);
    let smooth = room
        .raster
        .iter()
        .find(|m| m.primitive == room.smooth_sphere);
    let corners = smooth
        .into_iter()
        .flat_map(|m| &m.vertices)
        .filter_map(|&v| camera.project(v));
    let (x0, y0, x1, y1) = corners.fold(
        (f64::MAX, f64::MAX, 0.0f64, 0.0f64),
        |(a, b, c, d), (x, y)| (a.min(x), b.min(y), c.max(x), d.max(y)),
    );
    let pad = 4.0;
    let (cx, cy) = ((x0 - pad).max(0.0) as u32, (y0 - pad).max(0.0) as u32);
    let (cw, ch) = ((x1 - x0 + 2.0 * pad) as u32, (y1 - y0 + 2.0 * pad) as u32);
    let zoom = if quick { 2 } else { 3 };
    let q3 = plain_image
        .crop(cx, cy, cw, ch)
        .enlarged(zoom)
        .beside(&traced.crop(cx, cy, cw, ch).enlarged(zoom), 6);
    q3.write_png(docs.join("q3-reflections.png"))?;

    let samples = if quick { 16 } else { 256 };
    let paths = PathTracer {
        samples,
        ..PathTracer::default()
    };
    let start = Instant::now();
    let rendered = paths.render(&room, w, h);
    let s = start.elapsed().as_secs_f64();
    println!(
        "| path traced, {samples} paths per pixel ({threads} threads) | {w}x{h} | {:.1} s | {} | {:.2} M |",
        s,
        rendered.rays,
        rendered.rays as f64 / s / 1e6
    );
    rendered
        .image
        .write_png(docs.join("render-pathtraced.png"))?;

    // Convergence: error against a long reference render of another seed.
    let (cw, ch) = if quick { (32, 24) } else { (96, 72) };
    let reference_samples = if quick { 256 } else { 4096 };
    let reference = PathTracer {
        samples: reference_samples,
        seed: 99,
        ..paths
    }
    .render(&room, cw, ch);
    let mut points = Vec::new();
    println!("\n| paths per pixel | RMS error against {reference_samples} paths |\n|---|---|");
    for k in 0..=if quick { 4 } else { 8 } {
        let spp = 1u32 << k;
        let image = PathTracer {
            samples: spp,
            ..paths
        }
        .render(&room, cw, ch)
        .image;
        let error = image.rms_difference(&reference.image);
        println!("| {spp} | {error:.4} |");
        points.push((spp as f64, error));
    }
    let title =
        format!("Path tracer convergence, {cw}x{ch}, against {reference_samples} paths per pixel");
    let svg = log_log_svg(&title, "paths per pixel", "RMS error", &points);
    std::fs::write(docs.join("path-convergence.svg"), svg)?;
    Ok(())
}
