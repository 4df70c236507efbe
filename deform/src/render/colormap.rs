//! A perceptual colormap for scalar fields.

/// Nine evenly spaced stops of matplotlib's viridis (dark purple to yellow), as sRGB8. Its
/// lightness and its green channel rise monotonically.
const VIRIDIS: [[u8; 3]; 9] = [
    [0x44, 0x01, 0x54],
    [0x47, 0x2d, 0x7b],
    [0x3b, 0x52, 0x8b],
    [0x2c, 0x72, 0x8e],
    [0x21, 0x90, 0x8c],
    [0x27, 0xad, 0x81],
    [0x5d, 0xc8, 0x63],
    [0xaa, 0xdc, 0x32],
    [0xfd, 0xe7, 0x25],
];

/// The viridis-like colour of `t` in `[0, 1]` (clamped; NaN gives the colour of 0), as linear
/// interpolation between nine stops of matplotlib's viridis, in floating point.
///
/// ```
/// use deform::render::viridis;
/// assert_eq!(viridis(0.0), [68.0, 1.0, 84.0]);
/// assert_eq!(viridis(1.0), [253.0, 231.0, 37.0]);
/// assert!(viridis(0.6)[1] > viridis(0.4)[1]);
/// ```
#[must_use]
pub fn viridis(t: f64) -> [f64; 3] {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (VIRIDIS.len() - 1) as f64;
    let k = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    [0, 1, 2].map(|c| f64::from(a[c]) + f * (f64::from(b[c]) - f64::from(a[c])))
}

/// Maps `value` in `[min, max]` to `[0, 1]` (clamped); a zero-width range maps to 0.5.
#[inline]
pub(crate) fn normalize(value: f64, min: f64, max: f64) -> f64 {
    if max > min {
        // Halved so that finite inputs never overflow.
        ((0.5 * value - 0.5 * min) / (0.5 * max - 0.5 * min)).clamp(0.0, 1.0)
    } else {
        0.5
    }
}
