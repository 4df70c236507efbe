//! Captions of previews: a title band above an image and a colour legend below it (the
//! colormap as a bar, the scalar's name and its range), drawn with the bitmap font.

use super::font::{text_width, ADVANCE, GLYPH_HEIGHT, LINE_HEIGHT};
use super::{viridis, Image};
use crate::mesh::numbers::short_number;

/// The colour of caption text.
pub const TEXT_COLOR: [u8; 3] = [25, 25, 25];

/// The colour legend of a per-vertex scalar: its name and the values at the colormap's ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Legend<'a> {
    /// What the colour shows, e.g. `displacement`.
    pub name: &'a str,
    /// The value shown as the colormap's start.
    pub min: f64,
    /// The value shown as the colormap's end.
    pub max: f64,
}

impl<'a> Legend<'a> {
    /// The legend of `values` over their finite range (as [`super::Coloring::scalar`] maps
    /// them).
    #[must_use]
    pub fn of(name: &'a str, values: &[f64]) -> Legend<'a> {
        match super::Coloring::scalar(values) {
            super::Coloring::Scalar { min, max, .. } => Legend { name, min, max },
            super::Coloring::Uniform(_) => Legend {
                name,
                min: 0.0,
                max: 1.0,
            },
        }
    }
}

/// The text scale for an image `width` pixels wide: font pixels twice as large from 560
/// pixels on, so captions stay readable at the preview's size.
#[must_use]
pub fn text_scale(width: u32) -> u32 {
    if width >= 560 {
        2
    } else {
        1
    }
}

/// `text` in lines of at most `max_chars` characters, broken at spaces (a longer word is
/// cut).
#[must_use]
pub fn wrap(text: &str, max_chars: usize) -> Vec<String> {
    let max_chars = max_chars.max(1);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let (n, w) = (line.chars().count(), word.chars().count());
        if n > 0 && n + 1 + w > max_chars {
            lines.push(std::mem::take(&mut line).trim_end().to_string());
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
        while line.chars().count() > max_chars {
            let head: String = line.chars().take(max_chars).collect();
            line = line.chars().skip(max_chars).collect();
            lines.push(head);
        }
    }
    if !line.trim().is_empty() || lines.is_empty() {
        lines.push(line.trim_end().to_string());
    }
    lines
}

/// `image` with `title` (wrapped to its width) in a band above it and, when given, the
/// `legend` in a band below it, both on `background`. An empty title adds no band.
#[must_use]
pub fn annotate(image: &Image, title: &str, legend: Option<&Legend>, background: [u8; 3]) -> Image {
    let s = text_scale(image.width);
    let margin = 6 * s;
    let max_chars = ((image.width.saturating_sub(2 * margin)) / (ADVANCE * s)).max(1);
    let lines = if title.trim().is_empty() {
        Vec::new()
    } else {
        wrap(title, max_chars as usize)
    };
    let top = if lines.is_empty() {
        0
    } else {
        lines.len() as u32 * LINE_HEIGHT * s + 4 * s
    };
    let bottom = if legend.is_some() { 24 * s } else { 0 };
    let mut out = Image::new(image.width, image.height + top + bottom, background);
    for (k, line) in lines.iter().enumerate() {
        let y = 3 * s + k as u32 * LINE_HEIGHT * s;
        out.draw_text(i64::from(margin), i64::from(y), line, TEXT_COLOR, s);
    }
    out.paste(image, 0, i64::from(top));
    if let Some(legend) = legend {
        draw_legend(&mut out, legend, top + image.height, s);
    }
    out
}

/// The legend in the band starting at row `y0`: the name, then the colour bar with the
/// range's ends under its ends.
fn draw_legend(out: &mut Image, legend: &Legend, y0: u32, s: u32) {
    let margin = 6 * s;
    let bar_h = GLYPH_HEIGHT * s;
    let y = i64::from(y0 + 3 * s);
    out.draw_text(i64::from(margin), y, legend.name, TEXT_COLOR, s);
    let x0 = margin + text_width(legend.name, s) + 2 * margin;
    let x1 = (x0 + 220 * s).min(out.width.saturating_sub(margin));
    if x1 <= x0 + 8 {
        return;
    }
    let span = f64::from(x1 - x0 - 1).max(1.0);
    for x in x0..x1 {
        let c = viridis(f64::from(x - x0) / span).map(|c| c.round().clamp(0.0, 255.0) as u8);
        out.fill_rect(i64::from(x), y, 1, bar_h, c);
    }
    out.outline_rect(i64::from(x0) - 1, y - 1, x1 - x0 + 2, bar_h + 2, TEXT_COLOR);
    let label_y = y + i64::from(bar_h + 3 * s);
    let (lo, hi) = (short_number(legend.min), short_number(legend.max));
    out.draw_text(i64::from(x0), label_y, &lo, TEXT_COLOR, s);
    let hi_x = i64::from(x1) - i64::from(text_width(&hi, s));
    out.draw_text(hi_x, label_y, &hi, TEXT_COLOR, s);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn titles_wrap_at_spaces() {
        assert_eq!(wrap("ab cd ef", 5), ["ab cd", "ef"]);
        assert_eq!(wrap("abcdefgh", 3), ["abc", "def", "gh"]);
        assert_eq!(wrap("", 3), [""]);
        for line in wrap("arap  spokes-and-rims  3 iter  max move 4.1% of diag", 20) {
            assert!(line.chars().count() <= 20, "{line:?}");
        }
    }

    #[test]
    fn bands_are_added_and_carry_text_and_the_colormap() {
        let bg = [235, 235, 235];
        let image = Image::new(320, 100, [9, 9, 9]);
        let legend = Legend {
            name: "displacement",
            min: 0.0,
            max: 2.5,
        };
        let out = annotate(&image, "arap  rotor", Some(&legend), bg);
        assert_eq!(out.width, 320);
        let top = LINE_HEIGHT + 4;
        assert_eq!(out.height, 100 + top + 24);
        // The title's pixels are dark; the image sits below the band, unchanged.
        let dark = (0..top)
            .flat_map(|y| (0..320).map(move |x| (x, y)))
            .filter(|&(x, y)| out.pixel(x, y) == TEXT_COLOR)
            .count();
        assert!(dark > 40, "{dark} title pixels");
        assert_eq!(out.pixel(0, top), [9, 9, 9]);
        assert_eq!(out.pixel(319, top + 99), [9, 9, 9]);
        // The bar runs from the colormap's start to its end.
        let row = top + 100 + 6;
        let bar: Vec<[u8; 3]> = (0..320)
            .map(|x| out.pixel(x, row))
            .filter(|&c| c != bg && c != TEXT_COLOR)
            .collect();
        assert!(bar.len() > 150, "{} bar pixels", bar.len());
        let start = viridis(0.0).map(|c| c.round() as u8);
        let end = viridis(1.0).map(|c| c.round() as u8);
        assert_eq!((bar[0], bar[bar.len() - 1]), (start, end));
        // No title and no legend: the image itself.
        assert_eq!(annotate(&image, "", None, bg), image);
    }
}
