//! Visibility: the Z-buffer rasterizer and the ray tracer
//! (primary rays through pixel centres, the exact triangle variant) agree
//! on the visible surface at every pixel of the room, drawn with triangles
//! only (the analytic shapes replaced by their tessellations, so that both
//! renderers see the same surfaces).
//!
//! Where can they differ? The ray test is exact on the world triangles;
//! the rasterizer's coverage is exact on the *projected* vertices, which
//! are rounded (the clip-space matrix, the divide, the viewport), and its
//! depth test compares interpolated, rounded depths. So a disagreement can
//! only sit where a pixel centre is within rounding of a projected edge or
//! where two surfaces' depths are within rounding of each other, that is
//! on a boundary of the rasterizer's visible-surface map. The test counts
//! the disagreements and checks that each one is on such a boundary (a
//! pixel next to one whose visible surface differs): one inside a surface
//! would be a real error of coverage or depth.

use exactray::interval::Interval;
use exactray::query::ray::Exact;
use exactray::scene::{SceneBuilder, TriangleMesh};
use exactray_render::room::cornell_room;
use exactray_render::zbuffer::visibility;

/// Per pixel, `(mesh, triangle)` from both renderers for a `w` x `h`
/// frame, and whether the pixel's exact ray meets the rasterizer's
/// triangle at the ray tracer's `t` (a tie; see the module docs).
type Both = (Vec<Option<(u32, u32)>>, Vec<Option<(u32, u32)>>, Vec<bool>);

fn both(w: u32, h: u32) -> Both {
    let room = cornell_room(w, h);
    let meshes: Vec<_> = room
        .raster
        .iter()
        .map(|m| TriangleMesh::new(&m.vertices, &m.triangles).unwrap())
        .collect();
    let mut builder = SceneBuilder::new();
    for m in &meshes {
        builder.add(m.clone()).unwrap();
    }
    let scene = builder.build();
    let raster: Vec<_> = visibility(&room.raster, &room.camera)
        .pixels
        .iter()
        .map(|v| v.map(|v| (v.mesh, v.triangle)))
        .collect();
    let rays = (0..h)
        .flat_map(|j| (0..w).map(move |i| (i, j)))
        .map(|(i, j)| {
            let hit =
                scene.closest_hit_with::<Exact>(&room.camera.pixel_ray(i, j), Interval::FORWARD)?;
            Some((hit.primitive.0, hit.triangle?.triangle))
        })
        .collect::<Vec<_>>();
    let tie = |k: usize| {
        let (Some((m, t)), Some(_)) = (raster[k], rays[k]) else {
            return false;
        };
        let ray = room.camera.pixel_ray(k as u32 % w, k as u32 / w);
        let one = meshes[m as usize].triangle(t as usize).unwrap();
        let single = TriangleMesh::new(&one.vertices(), &[[0, 1, 2]]).unwrap();
        let (Some(a), Some(b)) = (
            single.closest_hit_with::<Exact>(&ray, Interval::FORWARD),
            scene.closest_hit_with::<Exact>(&ray, Interval::FORWARD),
        ) else {
            return false;
        };
        ulps_apart(a.hit.t, b.hit.t) <= 8
    };
    let ties = (0..raster.len()).map(tie).collect();
    (raster, rays, ties)
}

/// How many doubles lie between two positive finite `a` and `b`.
fn ulps_apart(a: f64, b: f64) -> u64 {
    a.to_bits().abs_diff(b.to_bits())
}

/// Whether pixel `k` of a `w` x `h` map has a neighbour (8-connected)
/// whose key differs.
fn on_boundary<K: PartialEq>(map: &[K], w: usize, k: usize) -> bool {
    let (x, y) = ((k % w) as i64, (k / w) as i64);
    let h = (map.len() / w) as i64;
    (-1..=1)
        .flat_map(|dy| (-1..=1).map(move |dx| (x + dx, y + dy)))
        .any(|(i, j)| {
            (0..w as i64).contains(&i)
                && (0..h).contains(&j)
                && map[(j * w as i64 + i) as usize] != map[k]
        })
}

#[test]
fn rasterizer_and_ray_tracer_see_the_same_surfaces() {
    let (w, h) = (256, 192);
    let (raster, rays, ties) = both(w, h);
    let mesh_of = |v: &Option<(u32, u32)>| v.map(|(m, _)| m);
    let raster_meshes: Vec<_> = raster.iter().map(mesh_of).collect();
    let (mut primitive_differs, mut triangle_differs, mut tied) = (0, 0, 0);
    for k in 0..raster.len() {
        if raster[k] != rays[k] && ties[k] {
            tied += 1;
            assert!(on_boundary(&raster, w as usize, k));
        } else if mesh_of(&raster[k]) != mesh_of(&rays[k]) {
            primitive_differs += 1;
            assert!(
                on_boundary(&raster_meshes, w as usize, k),
                "pixel {k}: {:?} vs {:?}",
                raster[k],
                rays[k]
            );
        } else if raster[k] != rays[k] {
            triangle_differs += 1;
            assert!(
                on_boundary(&raster, w as usize, k),
                "pixel {k}: {:?} vs {:?}",
                raster[k],
                rays[k]
            );
        }
    }
    let covered = raster.iter().filter(|v| v.is_some()).count();
    let boundary = (0..raster.len())
        .filter(|&k| on_boundary(&raster, w as usize, k))
        .count();
    println!(
        "{w}x{h}: {covered} pixels covered, {boundary} on a boundary of the rasterizer's map; \
         exact ties {tied}; visible primitive differs at {primitive_differs}, triangle of the same primitive at {triangle_differs}"
    );
    assert!(covered > (w * h) as usize / 2);
}
