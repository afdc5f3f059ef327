//! Linear-radiance images, their sRGB bytes and PNG files.

use glam::DVec3;
use std::io;
use std::path::Path;

/// A `width` x `height` image of linear RGB radiance, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    width: u32,
    height: u32,
    pixels: Vec<DVec3>,
}

impl Image {
    /// A black image.
    pub fn new(width: u32, height: u32) -> Image {
        Image::from_pixels(
            width,
            height,
            vec![DVec3::ZERO; width as usize * height as usize],
        )
    }

    /// An image from its pixels, row by row; a wrong count is padded with
    /// black or cut.
    pub fn from_pixels(width: u32, height: u32, mut pixels: Vec<DVec3>) -> Image {
        pixels.resize(width as usize * height as usize, DVec3::ZERO);
        Image {
            width,
            height,
            pixels,
        }
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The pixels, row by row.
    pub fn pixels(&self) -> &[DVec3] {
        &self.pixels
    }

    /// Pixel `(x, y)` (black outside the image).
    pub fn get(&self, x: u32, y: u32) -> DVec3 {
        if x < self.width && y < self.height {
            self.pixels[(y * self.width + x) as usize]
        } else {
            DVec3::ZERO
        }
    }

    /// The `w` x `h` crop whose top-left pixel is `(x, y)` (black where it
    /// leaves the image).
    pub fn crop(&self, x: u32, y: u32, w: u32, h: u32) -> Image {
        let pixels = (0..h)
            .flat_map(|j| (0..w).map(move |i| (x + i, y + j)))
            .map(|(i, j)| self.get(i, j))
            .collect();
        Image::from_pixels(w, h, pixels)
    }

    /// `self` and `other` side by side, a `gap`-pixel white bar between.
    pub fn beside(&self, other: &Image, gap: u32) -> Image {
        let (w, h) = (
            self.width + gap + other.width,
            self.height.max(other.height),
        );
        let pixels = (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .map(|(i, j)| match i {
                i if i < self.width => self.get(i, j),
                i if i < self.width + gap => DVec3::ONE,
                i => other.get(i - self.width - gap, j),
            })
            .collect();
        Image::from_pixels(w, h, pixels)
    }

    /// Every pixel scaled `factor` times larger, nearest neighbour (for
    /// crops shown at a readable size).
    pub fn enlarged(&self, factor: u32) -> Image {
        let f = factor.max(1);
        let pixels = (0..self.height * f)
            .flat_map(|j| (0..self.width * f).map(move |i| (i / f, j / f)))
            .map(|(i, j)| self.get(i, j))
            .collect();
        Image::from_pixels(self.width * f, self.height * f, pixels)
    }

    /// The mean radiance over all pixels.
    pub fn mean(&self) -> DVec3 {
        self.pixels.iter().sum::<DVec3>() / self.pixels.len().max(1) as f64
    }

    /// The root-mean-square difference from `other` over every channel of
    /// every pixel (`inf` for images of different sizes).
    pub fn rms_difference(&self, other: &Image) -> f64 {
        if (self.width, self.height) != (other.width, other.height) {
            return f64::INFINITY;
        }
        let sum: f64 = self
            .pixels
            .iter()
            .zip(&other.pixels)
            .map(|(a, b)| (*a - *b).length_squared())
            .sum();
        (sum / (3 * self.pixels.len().max(1)) as f64).sqrt()
    }

    /// 8-bit sRGB bytes, RGB row by row: radiance clamped to `[0, 1]`,
    /// then the sRGB transfer curve (IEC 61966-2-1).
    pub fn srgb_bytes(&self) -> Vec<u8> {
        let encode = |c: f64| {
            let c = c.clamp(0.0, 1.0);
            let s = if c <= 0.003_130_8 {
                12.92 * c
            } else {
                1.055 * c.powf(1.0 / 2.4) - 0.055
            };
            (s * 255.0).round() as u8
        };
        self.pixels
            .iter()
            .flat_map(|p| [encode(p.x), encode(p.y), encode(p.z)])
            .collect()
    }

    /// The PNG file of [`srgb_bytes`](Self::srgb_bytes): the same image
    /// gives the same bytes.
    pub fn png_bytes(&self) -> io::Result<Vec<u8>> {
        let mut out = Vec::new();
        let mut encoder = png::Encoder::new(&mut out, self.width, self.height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().map_err(io::Error::other)?;
        writer
            .write_image_data(&self.srgb_bytes())
            .map_err(io::Error::other)?;
        writer.finish().map_err(io::Error::other)?;
        Ok(out)
    }

    /// Writes [`png_bytes`](Self::png_bytes) to `path`.
    pub fn write_png(&self, path: impl AsRef<Path>) -> io::Result<()> {
        std::fs::write(path, self.png_bytes()?)
    }
}
