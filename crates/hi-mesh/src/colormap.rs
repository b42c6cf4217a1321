// SPDX-License-Identifier: MIT
//! Values → colour, after the curvature pictures of Hardy 2005, §5.9 (curvature as defined
//! in §4.6): "Blue indicates little or no curvature, and purple indicates high curvature."
//!
//! A [`ColorMap`] turns values (Gaussian curvature K, mean curvature H, or anything else) into
//! vertex colours and returns, with them, the [`ColorLegend`] it used: which value sits at each
//! end of the ramp, how many values were clamped at the ends and how many were not numbers at
//! all. Three scales:
//!
//! * [`ColorScale::Magnitude`] (the thesis): |x| from 0 (blue) to the extent a (purple);
//! * [`ColorScale::Symmetric`]: signed, centred on 0 (blue), from −a (teal) to +a (purple);
//! * [`ColorScale::MinMax`] and [`ColorScale::Fixed`]: from a low value (blue) to a high value
//!   (purple), taken from the data or given.
//!
//! The extent a (or the low and high values) comes from the data: by default the largest
//! magnitude (or the least and greatest value), or a quantile of them
//! ([`ColorMap::coverage`] < 1), so that a few huge values near a pole, where the curvature of
//! a harmonic surface is numerically unreliable (§5.9, figure 5.34), do not wash the rest of
//! the picture out. NaN and ±∞ (curvature at a degenerate point, where it is undefined) get
//! the neutral grey [`NEUTRAL_SRGB`] and are counted in [`ColorLegend::n_invalid`].
//!
//! The colours come from a [`Palette`]: the thesis's blue → purple ramp (the default), or the
//! perceptual maps a reader of a scientific figure expects, [`Palette::Viridis`] for
//! magnitudes and the diverging [`Palette::CoolWarm`] (grey at the centre) for signed values.
//!
//! The ramp is defined and interpolated in sRGB (what a legend or an SVG shows); the colours
//! returned are linear RGB, as glTF's `COLOR_0` and a renderer expect. [`srgb_to_linear`] and
//! [`linear_to_srgb`] convert.

use glam::DVec3;

use crate::Error;

/// The colour of zero (or of the low end): blue, in sRGB.
pub const LOW_SRGB: [f32; 3] = [0.12, 0.32, 0.95];
/// The colour of high curvature (the high end): purple, in sRGB.
pub const HIGH_SRGB: [f32; 3] = [0.58, 0.10, 0.70];
/// The colour of −a on the [`ColorScale::Symmetric`] scale: teal, in sRGB.
pub const NEGATIVE_SRGB: [f32; 3] = [0.05, 0.66, 0.56];
/// The colour of NaN and ±∞: mid grey, in sRGB.
pub const NEUTRAL_SRGB: [f32; 3] = [0.62, 0.62, 0.62];

/// Viridis (van der Walt and Smith, matplotlib 2.0's default map), sRGB at 17 equal steps:
/// lightness rises steadily from dark purple to yellow, and it reads the same to the
/// colour-blind and in grey.
const VIRIDIS: [[f32; 3]; 17] = [
    [0.2670, 0.0049, 0.3294],
    [0.2823, 0.0950, 0.4173],
    [0.2788, 0.1755, 0.4834],
    [0.2590, 0.2515, 0.5247],
    [0.2297, 0.3224, 0.5457],
    [0.1994, 0.3876, 0.5546],
    [0.1727, 0.4488, 0.5579],
    [0.1490, 0.5081, 0.5572],
    [0.1276, 0.5669, 0.5506],
    [0.1206, 0.6258, 0.5335],
    [0.1579, 0.6838, 0.5017],
    [0.2461, 0.7389, 0.4520],
    [0.3692, 0.7889, 0.3829],
    [0.5160, 0.8312, 0.2943],
    [0.6785, 0.8637, 0.1895],
    [0.8456, 0.8873, 0.0997],
    [0.9932, 0.9062, 0.1439],
];

/// Moreland's diverging cool–warm map ("Diverging color maps for scientific visualization",
/// 2009), sRGB at 17 equal steps: blue through a light grey centre to red, each half of
/// steadily changing lightness.
const COOLWARM: [[f32; 3]; 17] = [
    [0.2298, 0.2987, 0.7537],
    [0.3042, 0.4069, 0.8453],
    [0.3837, 0.5102, 0.9178],
    [0.4677, 0.6056, 0.9685],
    [0.5543, 0.6901, 0.9955],
    [0.6408, 0.7608, 0.9978],
    [0.7240, 0.8149, 0.9757],
    [0.8006, 0.8504, 0.9300],
    [0.8674, 0.8644, 0.8626],
    [0.9256, 0.8255, 0.7711],
    [0.9595, 0.7670, 0.6741],
    [0.9697, 0.6905, 0.5751],
    [0.9567, 0.5980, 0.4773],
    [0.9214, 0.4914, 0.3834],
    [0.8654, 0.3711, 0.2958],
    [0.7906, 0.2314, 0.2162],
    [0.7057, 0.0156, 0.1502],
];

/// The colours of a [`ColorMap`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Palette {
    /// The thesis's ramp (§5.9): blue ([`LOW_SRGB`]) to purple ([`HIGH_SRGB`]), and teal
    /// ([`NEGATIVE_SRGB`]) for −a on the [`ColorScale::Symmetric`] scale.
    #[default]
    Thesis,
    /// Viridis, dark purple (low) to yellow (high): for magnitudes.
    Viridis,
    /// Cool–warm, blue (low) through grey (the centre) to red (high): for signed values on the
    /// [`ColorScale::Symmetric`] scale, where the grey is 0.
    CoolWarm,
}

impl Palette {
    /// The sRGB colour at `s` ∈ [0, 1] from the low end to the high end (clamped), for the
    /// palettes given as tables; the thesis's ramp at `s` from blue to purple.
    #[must_use]
    pub fn srgb(self, s: f64) -> [f32; 3] {
        let table = match self {
            Palette::Thesis => return mix(LOW_SRGB, HIGH_SRGB, s),
            Palette::Viridis => &VIRIDIS,
            Palette::CoolWarm => &COOLWARM,
        };
        let x = s.clamp(0.0, 1.0) * (table.len() - 1) as f64;
        #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "in 0..=15")]
        let k = (x.floor() as usize).min(table.len() - 2);
        mix(table[k], table[k + 1], x - k as f64)
    }
}

/// How values are placed on the ramp.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ColorScale {
    /// The thesis's map (§5.9): |x| from 0 (blue) to the extent a (purple); the sign is lost.
    Magnitude,
    /// Signed, symmetric about 0: −a teal, 0 blue, +a purple.
    Symmetric,
    /// From the least finite value (blue) to the greatest (purple), or quantiles of them.
    MinMax,
    /// From `min` (blue) to `max` (purple) as given, whatever the data: one legend for several
    /// pictures. [`ColorMap::coverage`] is not used.
    Fixed {
        /// The value shown blue.
        min: f64,
        /// The value shown purple.
        max: f64,
    },
}

/// A curvature colour map: a [`ColorScale`], how much of the data it must cover, and the
/// [`Palette`] it paints with.
///
/// # Examples
///
/// ```
/// use hi_mesh::{ColorMap, ColorScale, Palette};
///
/// let map = ColorMap { scale: ColorScale::Magnitude, coverage: 1.0, palette: Palette::Thesis };
/// let out = map.try_apply(&[0.0, -0.5, 2.0, f64::NAN]).unwrap();
/// assert_eq!((out.legend.min, out.legend.max), (0.0, 2.0)); // |x| from 0 to the largest |x|
/// assert_eq!(out.legend.n_invalid, 1); // the NaN is grey and counted
/// assert_eq!(out.colors[2], hi_mesh::srgb_to_linear_rgb(hi_mesh::HIGH_SRGB));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ColorMap {
    /// The scale.
    pub scale: ColorScale,
    /// The fraction of the finite values the scale spans, in (0, 1]: 1 spans them all; 0.98
    /// lets the 2 % most extreme values (1 % at each end for [`ColorScale::MinMax`]) saturate.
    pub coverage: f64,
    /// The colours.
    pub palette: Palette,
}

impl Default for ColorMap {
    /// The thesis's map: [`ColorScale::Magnitude`] over all values, [`Palette::Thesis`].
    fn default() -> Self {
        ColorMap { scale: ColorScale::Magnitude, coverage: 1.0, palette: Palette::Thesis }
    }
}

/// Which values the ends of the ramp stand for, and what happened to the data: enough to draw
/// a legend beside a picture.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ColorLegend {
    /// The scale used ([`ColorScale::Fixed`] carries its bounds).
    pub scale: ColorScale,
    /// The palette used.
    pub palette: Palette,
    /// The value at the low end of the ramp: 0 for [`ColorScale::Magnitude`] (which shows
    /// |x|), −a for [`ColorScale::Symmetric`].
    pub min: f64,
    /// The value at the high (purple) end of the ramp.
    pub max: f64,
    /// The value at the middle of the ramp: 0 (blue) for [`ColorScale::Symmetric`], the
    /// midpoint of `min` and `max` otherwise.
    pub centre: f64,
    /// The least and greatest finite value in the data (NaN if there are none).
    pub data_min: f64,
    /// See `data_min`.
    pub data_max: f64,
    /// Number of values mapped.
    pub n_values: usize,
    /// Number of NaN or infinite values, shown in [`NEUTRAL_SRGB`].
    pub n_invalid: usize,
    /// Number of finite values beyond the ends of the ramp, shown in the end colours.
    pub n_clamped: usize,
}

/// Colours for a list of values, and the legend of the map that made them.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ColorMapping {
    /// One linear-RGB colour per value, each component in [0, 1].
    pub colors: Vec<[f32; 3]>,
    /// The scale and counts.
    pub legend: ColorLegend,
}

impl ColorMap {
    /// The colours of `values` and the legend of the scale used.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidValue`] if `coverage` is not in (0, 1], or if the bounds of
    /// [`ColorScale::Fixed`] are not finite with `min < max`.
    pub fn try_apply(&self, values: &[f64]) -> Result<ColorMapping, Error> {
        if !(self.coverage > 0.0 && self.coverage <= 1.0) {
            return Err(Error::InvalidValue {
                what: "colour map coverage",
                index: None,
                value: self.coverage,
                expected: "a fraction in (0, 1]",
            });
        }
        if let ColorScale::Fixed { min, max } = self.scale {
            for (what, value) in [("colour map minimum", min), ("colour map maximum", max)] {
                if !value.is_finite() {
                    return Err(Error::InvalidValue {
                        what,
                        index: None,
                        value,
                        expected: "a finite number",
                    });
                }
            }
            if min >= max {
                return Err(Error::InvalidValue {
                    what: "colour map maximum",
                    index: None,
                    value: max,
                    expected: "greater than the minimum",
                });
            }
        }
        let finite: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
        let (data_min, data_max) = if finite.is_empty() {
            (f64::NAN, f64::NAN)
        } else {
            finite
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| (lo.min(x), hi.max(x)))
        };
        let (min, max, centre) = match self.scale {
            ColorScale::Magnitude => {
                let a = quantile(finite.iter().map(|x| x.abs()).collect(), self.coverage);
                (0.0, a, 0.5 * a)
            }
            ColorScale::Symmetric => {
                let a = quantile(finite.iter().map(|x| x.abs()).collect(), self.coverage);
                (-a, a, 0.0)
            }
            ColorScale::MinMax => {
                let tail = 0.5 * (1.0 - self.coverage);
                let lo = -quantile(finite.iter().map(|x| -x).collect(), 1.0 - tail);
                let hi = quantile(finite.clone(), 1.0 - tail);
                (lo, hi, 0.5 * (lo + hi))
            }
            ColorScale::Fixed { min, max } => (min, max, 0.5 * (min + max)),
        };
        let mut legend = ColorLegend {
            scale: self.scale,
            palette: self.palette,
            min,
            max,
            centre,
            data_min,
            data_max,
            n_values: values.len(),
            n_invalid: values.len() - finite.len(),
            n_clamped: 0,
        };
        legend.n_clamped = finite.iter().filter(|&&x| legend.is_clamped(x)).count();
        let colors = values.iter().map(|&x| legend.linear_at(x)).collect();
        Ok(ColorMapping { colors, legend })
    }
}

impl ColorLegend {
    /// Where `value` falls on the ramp: 0 at the blue end, 1 at the purple end, −1 at the teal
    /// end of [`ColorScale::Symmetric`]; clamped to the ramp; `None` for NaN and ±∞.
    #[must_use]
    pub fn position(&self, value: f64) -> Option<f64> {
        if !value.is_finite() {
            return None;
        }
        let t = match self.scale {
            ColorScale::Magnitude => ratio(value.abs(), self.max).clamp(0.0, 1.0),
            ColorScale::Symmetric => ratio(value, self.max).clamp(-1.0, 1.0),
            ColorScale::MinMax | ColorScale::Fixed { .. } => {
                if self.max > self.min {
                    ((value - self.min) / (self.max - self.min)).clamp(0.0, 1.0)
                } else {
                    // All finite data equal: the middle of the ramp.
                    0.5
                }
            }
        };
        Some(t)
    }

    /// The sRGB colour of `value` (what a legend drawn beside the picture shows): the
    /// palette at the value's place between the ends of the ramp ([`ColorLegend::fraction`]).
    #[must_use]
    pub fn srgb_at(&self, value: f64) -> [f32; 3] {
        match (self.palette, self.position(value)) {
            (_, None) => NEUTRAL_SRGB,
            (Palette::Thesis, Some(t)) if t < 0.0 => mix(LOW_SRGB, NEGATIVE_SRGB, -t),
            (Palette::Thesis, Some(t)) => mix(LOW_SRGB, HIGH_SRGB, t),
            (palette, Some(_)) => palette.srgb(self.fraction(value).unwrap_or(0.0)),
        }
    }

    /// Where `value` falls between the low end (0) and the high end (1) of the ramp, clamped;
    /// on the [`ColorScale::Symmetric`] scale, −a is 0, 0 is ½ and a is 1. `None` for NaN and
    /// ±∞. This is where a colour bar drawn from `min` to `max` shows the value.
    #[must_use]
    pub fn fraction(&self, value: f64) -> Option<f64> {
        self.position(value).map(|t| match self.scale {
            ColorScale::Symmetric => 0.5 * (t + 1.0),
            _ => t,
        })
    }

    /// The linear-RGB colour of `value` (what the mesh stores and glTF's `COLOR_0` holds).
    #[must_use]
    pub fn linear_at(&self, value: f64) -> [f32; 3] {
        srgb_to_linear_rgb(self.srgb_at(value))
    }

    fn is_clamped(&self, x: f64) -> bool {
        match self.scale {
            ColorScale::Magnitude => x.abs() > self.max,
            ColorScale::Symmetric => x.abs() > self.max,
            ColorScale::MinMax | ColorScale::Fixed { .. } => x < self.min || x > self.max,
        }
    }
}

/// x/a for a > 0; 0 when a = 0 (all data zero: "no curvature", blue).
fn ratio(x: f64, a: f64) -> f64 {
    if a > 0.0 { x / a } else { 0.0 }
}

/// The smallest value v of `xs` such that a fraction ≥ q of them is ≤ v; 0 for no values.
fn quantile(mut xs: Vec<f64>, q: f64) -> f64 {
    if xs.is_empty() {
        return 0.0;
    }
    let n = xs.len();
    // ⌈q·n⌉ − 1, kept in range (q ∈ (0, 1]).
    let k = ((q * n as f64).ceil() as usize).clamp(1, n) - 1;
    *xs.select_nth_unstable_by(k, f64::total_cmp).1
}

fn mix(a: [f32; 3], b: [f32; 3], t: f64) -> [f32; 3] {
    let (a, b) = (DVec3::from(a.map(f64::from)), DVec3::from(b.map(f64::from)));
    a.lerp(b, t.clamp(0.0, 1.0)).as_vec3().to_array()
}

/// The sRGB transfer function, decoded: an sRGB component in [0, 1] → linear light;
/// the inverse of [`linear_to_srgb`].
///
/// ```
/// // ((0.5 + 0.055) / 1.055)^2.4 = 0.21404114
/// assert!((hi_mesh::srgb_to_linear(0.5) - 0.214_041_14).abs() < 1e-7);
/// assert!((hi_mesh::linear_to_srgb(hi_mesh::srgb_to_linear(0.5)) - 0.5).abs() < 1e-6);
/// ```
#[must_use]
pub fn srgb_to_linear(c: f32) -> f32 {
    let c = f64::from(c);
    let l = if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) };
    l.clamp(0.0, 1.0) as f32
}

/// The sRGB transfer function: linear light in [0, 1] → an sRGB component.
#[must_use]
pub fn linear_to_srgb(l: f32) -> f32 {
    let l = f64::from(l);
    let c = if l <= 0.003_130_8 { 12.92 * l } else { 1.055 * l.powf(1.0 / 2.4) - 0.055 };
    c.clamp(0.0, 1.0) as f32
}

/// [`srgb_to_linear`] on each component.
#[must_use]
pub fn srgb_to_linear_rgb(c: [f32; 3]) -> [f32; 3] {
    c.map(srgb_to_linear)
}

/// [`linear_to_srgb`] on each component.
#[must_use]
pub fn linear_to_srgb_rgb(c: [f32; 3]) -> [f32; 3] {
    c.map(linear_to_srgb)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantile_picks_order_statistics() {
        let xs = vec![5.0, 1.0, 3.0, 2.0, 4.0];
        assert_eq!(quantile(xs.clone(), 1.0), 5.0, "maximum");
        assert_eq!(quantile(xs.clone(), 0.2), 1.0, "lowest fifth");
        assert_eq!(quantile(xs, 0.5), 3.0, "median");
        assert_eq!(quantile(Vec::new(), 0.5), 0.0, "no data");
    }

    #[test]
    fn srgb_round_trip() {
        for i in 0..=100 {
            let c = i as f32 / 100.0;
            assert!((linear_to_srgb(srgb_to_linear(c)) - c).abs() < 1e-6, "{c}");
        }
        assert_eq!(srgb_to_linear(0.0), 0.0, "black");
        assert_eq!(srgb_to_linear(1.0), 1.0, "white");
    }

    /// Known values of the sRGB transfer function (IEC 61966-2-1), from its two pieces by hand:
    /// ((0.5 + 0.055)/1.055)^2.4 = 0.2140411405, 0.04/12.92 = 0.0030959752 (the linear piece),
    /// 1.055·0.18^(1/2.4) − 0.055 = 0.4613561295 (18 % grey), 1.055·0.5^(1/2.4) − 0.055 =
    /// 0.7353569831.
    #[test]
    fn srgb_known_values() {
        let close = |a: f32, b: f64| (f64::from(a) - b).abs() < 1e-7;
        assert!(close(srgb_to_linear(0.5), 0.214_041_140_5), "sRGB 0.5");
        assert!(close(srgb_to_linear(0.04), 0.003_095_975_2), "sRGB 0.04");
        assert!(close(linear_to_srgb(0.18), 0.461_356_129_5), "linear 0.18");
        assert!(close(linear_to_srgb(0.5), 0.735_356_983_1), "linear 0.5");
        let rgb = srgb_to_linear_rgb([0.5, 0.04, 1.0]);
        assert!(close(rgb[0], 0.214_041_140_5) && close(rgb[1], 0.003_095_975_2), "{rgb:?}");
        let back = linear_to_srgb_rgb(rgb);
        assert!(back.iter().zip([0.5, 0.04, 1.0]).all(|(a, b)| close(*a, b)), "{back:?}");
    }
}
