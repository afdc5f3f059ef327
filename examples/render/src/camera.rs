//! A pinhole camera whose rays and whose clip-space matrix describe the
//! same projection: the ray through a pixel centre is the line the
//! rasterizer's matrix maps onto that centre (up to the matrix's
//! rounding), so the two renderers can be compared pixel by pixel.

use exactray::query::ray::Ray;
use glam::dcamera::rh;
use glam::{DMat4, DVec3};

/// A perspective camera of `width` x `height` pixels.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    eye: DVec3,
    forward: DVec3,
    right: DVec3,
    up: DVec3,
    fov_y: f64,
    /// `tan(fov_y / 2)`: the half-height of the image plane at distance 1.
    half_height: f64,
    width: u32,
    height: u32,
}

/// The near and far planes of the clip-space matrix. Only the near plane
/// matters to the pictures (it is where clipping happens); the far plane
/// lies beyond every scene here.
const NEAR: f64 = 0.05;
const FAR: f64 = 100.0;

impl Camera {
    /// A camera at `eye` looking at `target`, `up` towards the top of the
    /// image, with a vertical field of view of `fov_y_degrees`. Returns
    /// `None` for a zero or non-finite view direction, an `up` parallel to
    /// it, a field of view outside `(0, 180)`, or an empty image.
    pub fn new(
        eye: DVec3,
        target: DVec3,
        up: DVec3,
        fov_y_degrees: f64,
        width: u32,
        height: u32,
    ) -> Option<Camera> {
        let forward = (target - eye).try_normalize()?;
        let right = forward.cross(up).try_normalize()?;
        let fov_ok = fov_y_degrees > 0.0 && fov_y_degrees < 180.0;
        if !fov_ok || width == 0 || height == 0 || !eye.is_finite() {
            return None;
        }
        let fov_y = fov_y_degrees.to_radians();
        Some(Camera {
            eye,
            forward,
            right,
            up: right.cross(forward),
            fov_y,
            half_height: (fov_y / 2.0).tan(),
            width,
            height,
        })
    }

    /// The image's width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The image's height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The eye point.
    pub fn eye(&self) -> DVec3 {
        self.eye
    }

    /// The same camera with another image size (the field of view and the
    /// aspect follow the new size).
    pub fn with_size(&self, width: u32, height: u32) -> Camera {
        Camera {
            width: width.max(1),
            height: height.max(1),
            ..*self
        }
    }

    fn aspect(&self) -> f64 {
        self.width as f64 / self.height as f64
    }

    /// The primary ray through the image point `(x, y)` in pixel units
    /// (`x` right, `y` down; pixel `(i, j)`'s centre is `(i + 0.5, j +
    /// 0.5)`), from the eye. Its direction is not normalized: at `t = 1`
    /// it is on the image plane at distance 1.
    pub fn ray(&self, x: f64, y: f64) -> Ray {
        let ndc_x = 2.0 * x / self.width as f64 - 1.0;
        let ndc_y = 1.0 - 2.0 * y / self.height as f64;
        let d = self.forward
            + self.right * (ndc_x * self.half_height * self.aspect())
            + self.up * (ndc_y * self.half_height);
        // `forward` is a unit vector orthogonal to the other two terms, so
        // the direction has length at least 1: never zero, and finite for
        // finite `x`, `y`.
        Ray::new(self.eye, d).expect("a camera ray's direction has length at least 1")
    }

    /// The ray through the centre of pixel `(i, j)`.
    pub fn pixel_ray(&self, i: u32, j: u32) -> Ray {
        self.ray(i as f64 + 0.5, j as f64 + 0.5)
    }

    /// Where the point `p` appears in the image, in pixel units (`None`
    /// behind the eye's plane).
    pub fn project(&self, p: DVec3) -> Option<(f64, f64)> {
        let c = self.clip_from_world() * p.extend(1.0);
        (c.w > 0.0).then(|| {
            let (x, y) = (c.x / c.w, c.y / c.w);
            (
                (x + 1.0) * 0.5 * self.width as f64,
                (1.0 - y) * 0.5 * self.height as f64,
            )
        })
    }

    /// World to clip space: glam's right-handed view and Direct3D-style
    /// projection (`dcamera::rh::proj::directx::perspective`: visible where
    /// `0 <= z <= w` and `-w <= x, y <= w`, NDC `y` up), the rasterizer's
    /// matrix for the rays of [`ray`](Self::ray).
    pub fn clip_from_world(&self) -> DMat4 {
        let view = rh::view::look_to_mat4(self.eye, self.forward, self.up);
        rh::proj::directx::perspective(self.fov_y, self.aspect(), NEAR, FAR) * view
    }
}
