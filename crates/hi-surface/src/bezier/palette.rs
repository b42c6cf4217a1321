// SPDX-License-Identifier: MIT
//! A colour per patch, for meshes and renders of the patches.

use hi_mesh::srgb_to_linear;

/// A colour for patch `index`: hues spaced by the golden angle so that neighbours differ,
/// saturation and value fixed, as linear RGB.
#[must_use]
pub fn patch_color(index: usize) -> [f32; 3] {
    let hue = (index as f64 * 0.618_033_988_749_895).fract() * 6.0;
    let (s, v) = (0.55, 0.9);
    let c = v * s;
    let x = c * (1.0 - (hue % 2.0 - 1.0).abs());
    let (r, g, b) = match hue as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let m = v - c;
    [r, g, b].map(|k| srgb_to_linear((k + m) as f32))
}
