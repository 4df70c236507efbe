//! The RGB8 image, its PNG encoding and contact sheets.

use std::io::Write;
use std::path::PathBuf;

use crate::mesh::MeshError;
use crate::mesh::Result;

/// The largest image side [`Image::check_size`] (and so every render) accepts.
pub const MAX_IMAGE_SIDE: u32 = 8192;

/// Pixels between neighbouring cells of a [`Image::contact_sheet`].
pub const CONTACT_SHEET_GAP: u32 = 4;

/// An RGB8 image, rows top to bottom, three bytes per pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 3` bytes, row-major, top row first.
    pub rgb: Vec<u8>,
}

impl Image {
    /// An image filled with `background`.
    ///
    /// # Panics
    /// If `width * height * 3` bytes cannot be allocated; renders check the size first with
    /// [`Image::check_size`].
    #[must_use]
    pub fn new(width: u32, height: u32, background: [u8; 3]) -> Image {
        let n = width as usize * height as usize;
        let mut rgb = Vec::with_capacity(3 * n);
        for _ in 0..n {
            rgb.extend_from_slice(&background);
        }
        Image { width, height, rgb }
    }

    /// `Ok` when a `width x height` render is allowed: both sides in `1..=MAX_IMAGE_SIDE`.
    pub fn check_size(width: u32, height: u32) -> Result<()> {
        if width == 0 || height == 0 || width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
            return Err(MeshError::InvalidArgument(format!(
                "image size {width}x{height}: both sides must be in 1..={MAX_IMAGE_SIDE}"
            )));
        }
        Ok(())
    }

    /// The colour at column `x`, row `y` (row 0 at the top).
    ///
    /// # Panics
    /// If `x >= width` or `y >= height`.
    #[inline]
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside the image"
        );
        let i = 3 * (y as usize * self.width as usize + x as usize);
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// Sets the colour at column `x`, row `y`.
    ///
    /// # Panics
    /// If `x >= width` or `y >= height`.
    #[inline]
    pub fn set_pixel(&mut self, x: u32, y: u32, c: [u8; 3]) {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside the image"
        );
        let i = 3 * (y as usize * self.width as usize + x as usize);
        self.rgb[i..i + 3].copy_from_slice(&c);
    }

    /// Encodes the image as an 8-bit RGB PNG into any writer. Errors from the writer (and a
    /// zero-sized or inconsistent image, which PNG cannot hold) are [`MeshError::Io`] with the
    /// path `<png>`.
    pub fn write_png_to(&self, w: impl Write) -> Result<()> {
        let expected = 3 * self.width as usize * self.height as usize;
        if self.rgb.len() != expected {
            return Err(MeshError::DimensionMismatch {
                what: "image bytes",
                expected,
                got: self.rgb.len(),
            });
        }
        let mut encoder = png::Encoder::new(w, self.width, self.height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().map_err(png_error)?;
        writer.write_image_data(&self.rgb).map_err(png_error)?;
        writer.finish().map_err(png_error)
    }

    /// The PNG encoding as bytes.
    pub fn to_png_bytes(&self) -> Result<Vec<u8>> {
        let mut out = Vec::new();
        self.write_png_to(&mut out)?;
        Ok(out)
    }

    /// The images side by side in a grid of `columns` (at least 1) columns, row by row. Every
    /// cell has the size of the largest image; each image is centred in its cell; cells are
    /// [`CONTACT_SHEET_GAP`] pixels apart, with `background` in the gaps and around smaller
    /// images. No images gives a 0x0 image.
    ///
    /// # Panics
    /// If a side of the sheet would exceed `u32::MAX` pixels, or an image's `rgb` does not hold
    /// `width * height * 3` bytes.
    #[must_use]
    pub fn contact_sheet(images: &[Image], columns: usize, background: [u8; 3]) -> Image {
        if images.is_empty() {
            return Image::new(0, 0, background);
        }
        let cols = columns.clamp(1, images.len());
        let rows = images.len().div_ceil(cols);
        let cw = images.iter().map(|i| i.width).max().unwrap_or(0);
        let ch = images.iter().map(|i| i.height).max().unwrap_or(0);
        let width = sheet_side(cols, cw);
        let height = sheet_side(rows, ch);
        let mut sheet = Image::new(width, height, background);
        for (k, img) in images.iter().enumerate() {
            let (c, r) = ((k % cols) as u32, (k / cols) as u32);
            let x0 = c * (cw + CONTACT_SHEET_GAP) + (cw - img.width) / 2;
            let y0 = r * (ch + CONTACT_SHEET_GAP) + (ch - img.height) / 2;
            sheet.blit(img, x0, y0);
        }
        sheet
    }

    /// Fills the `width x height` rectangle with its top-left corner at `(x, y)` (which may lie
    /// outside the image) with `color`; what falls outside the image is skipped.
    pub fn fill_rect(&mut self, x: i64, y: i64, width: u32, height: u32, color: [u8; 3]) {
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let (x0, y0) = (x.clamp(0, w), y.clamp(0, h));
        let x1 = x.saturating_add(i64::from(width)).clamp(0, w);
        let y1 = y.saturating_add(i64::from(height)).clamp(0, h);
        for yy in y0..y1 {
            for xx in x0..x1 {
                self.set_pixel(xx as u32, yy as u32, color);
            }
        }
    }

    /// Draws the one-pixel outline of the `width x height` rectangle at `(x, y)`, clipped.
    pub fn outline_rect(&mut self, x: i64, y: i64, width: u32, height: u32, color: [u8; 3]) {
        if width == 0 || height == 0 {
            return;
        }
        let (right, bottom) = (x + i64::from(width) - 1, y + i64::from(height) - 1);
        self.fill_rect(x, y, width, 1, color);
        self.fill_rect(x, bottom, width, 1, color);
        self.fill_rect(x, y, 1, height, color);
        self.fill_rect(right, y, 1, height, color);
    }

    /// Copies `src` with its top-left corner at `(x, y)`; what falls outside is skipped.
    pub fn paste(&mut self, src: &Image, x: i64, y: i64) {
        for sy in 0..src.height {
            let ty = y + i64::from(sy);
            if ty < 0 || ty >= i64::from(self.height) {
                continue;
            }
            for sx in 0..src.width {
                let tx = x + i64::from(sx);
                if tx >= 0 && tx < i64::from(self.width) {
                    self.set_pixel(tx as u32, ty as u32, src.pixel(sx, sy));
                }
            }
        }
    }

    /// Copies `src` with its top-left corner at `(x0, y0)` (the caller makes it fit).
    fn blit(&mut self, src: &Image, x0: u32, y0: u32) {
        let row = 3 * src.width as usize;
        for y in 0..src.height as usize {
            let s = y * row;
            let d = 3 * ((y0 as usize + y) * self.width as usize + x0 as usize);
            self.rgb[d..d + row].copy_from_slice(&src.rgb[s..s + row]);
        }
    }
}

/// `n` cells of `cell` pixels with gaps between them.
fn sheet_side(n: usize, cell: u32) -> u32 {
    let n = n as u64;
    let side = n * u64::from(cell) + (n - 1) * u64::from(CONTACT_SHEET_GAP);
    u32::try_from(side).expect("contact sheet side exceeds u32::MAX pixels")
}

fn png_error(e: png::EncodingError) -> MeshError {
    let source = match e {
        png::EncodingError::IoError(io) => io,
        other => std::io::Error::other(other.to_string()),
    };
    MeshError::Io {
        path: PathBuf::from("<png>"),
        source,
    }
}
