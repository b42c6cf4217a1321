// SPDX-License-Identifier: MIT
//! The curvature colour map (§5.9: blue for little or no curvature, purple for high): end
//! colours of each scale, the legend it reports, clamping, and NaN/∞ handling.

use hi_mesh::Error;
use hi_mesh::{
    ColorMap, ColorScale, HIGH_SRGB, LOW_SRGB, NEGATIVE_SRGB, NEUTRAL_SRGB, srgb_to_linear_rgb,
};
use proptest::prelude::*;

fn apply(scale: ColorScale, coverage: f64, values: &[f64]) -> hi_mesh::ColorMapping {
    ColorMap { scale, coverage, palette: hi_mesh::Palette::Thesis }.try_apply(values).unwrap()
}

fn close(a: [f32; 3], b: [f32; 3]) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-6)
}

#[test]
fn magnitude_scale_runs_from_zero_blue_to_the_largest_magnitude_purple() {
    let out = apply(ColorScale::Magnitude, 1.0, &[0.0, 1.0, -3.0, 3.0, 1.5]);
    let l = out.legend;
    assert_eq!((l.min, l.max, l.centre), (0.0, 3.0, 1.5), "|x| ∈ [0, 3]");
    assert_eq!((l.data_min, l.data_max), (-3.0, 3.0), "data range keeps signs");
    assert_eq!(out.colors[0], srgb_to_linear_rgb(LOW_SRGB), "0 is blue");
    assert_eq!(out.colors[2], srgb_to_linear_rgb(HIGH_SRGB), "−3 is purple");
    assert_eq!(out.colors[2], out.colors[3], "the sign is lost");
    assert_eq!(l.srgb_at(1.5), l.srgb_at(-1.5), "symmetric legend");
    assert_eq!((l.n_values, l.n_invalid, l.n_clamped), (5, 0, 0), "counts");
}

#[test]
fn symmetric_scale_is_centred_on_zero() {
    let out = apply(ColorScale::Symmetric, 1.0, &[-2.0, 0.0, 1.0, 2.0]);
    let l = out.legend;
    assert_eq!((l.min, l.max, l.centre), (-2.0, 2.0, 0.0), "±a");
    assert_eq!(out.colors[0], srgb_to_linear_rgb(NEGATIVE_SRGB), "−a teal");
    assert_eq!(out.colors[1], srgb_to_linear_rgb(LOW_SRGB), "0 blue");
    assert_eq!(out.colors[3], srgb_to_linear_rgb(HIGH_SRGB), "+a purple");
    assert_eq!(l.position(1.0), Some(0.5), "halfway up");
    assert_eq!(l.position(-1.0), Some(-0.5), "halfway down");
}

#[test]
fn min_max_and_fixed_scales() {
    let out = apply(ColorScale::MinMax, 1.0, &[1.0, 4.0, 2.5]);
    assert_eq!((out.legend.min, out.legend.max, out.legend.centre), (1.0, 4.0, 2.5), "data range");
    assert_eq!(out.colors[0], srgb_to_linear_rgb(LOW_SRGB), "min blue");
    assert_eq!(out.colors[1], srgb_to_linear_rgb(HIGH_SRGB), "max purple");
    // All data equal: the middle of the ramp, not a division by zero.
    let flat = apply(ColorScale::MinMax, 1.0, &[0.25; 4]);
    assert_eq!(flat.legend.position(0.25), Some(0.5), "middle");
    // A fixed scale clamps and counts what lies outside.
    let fixed = apply(ColorScale::Fixed { min: -1.0, max: 1.0 }, 1.0, &[-5.0, 0.0, 0.5, 7.0]);
    assert_eq!(fixed.legend.n_clamped, 2, "−5 and 7");
    assert_eq!(fixed.colors[0], srgb_to_linear_rgb(LOW_SRGB), "clamped low");
    assert_eq!(fixed.colors[3], srgb_to_linear_rgb(HIGH_SRGB), "clamped high");
    assert_eq!((fixed.legend.min, fixed.legend.max), (-1.0, 1.0), "as given");
}

#[test]
fn nan_and_infinities_are_grey_and_counted() {
    let values = [1.0, f64::NAN, f64::INFINITY, -2.0, f64::NEG_INFINITY];
    for scale in [ColorScale::Magnitude, ColorScale::Symmetric, ColorScale::MinMax] {
        let out = apply(scale, 1.0, &values);
        let grey = srgb_to_linear_rgb(NEUTRAL_SRGB);
        assert_eq!(out.legend.n_invalid, 3, "{scale:?}");
        assert_eq!([out.colors[1], out.colors[2], out.colors[4]], [grey; 3], "{scale:?}");
        assert!(
            out.legend.max.is_finite() && out.legend.min.is_finite(),
            "{scale:?}: scale from finite data"
        );
        assert_eq!((out.legend.data_min, out.legend.data_max), (-2.0, 1.0), "{scale:?}");
    }
    // Nothing finite at all: everything grey, the legend degenerate but finite.
    let out = apply(ColorScale::MinMax, 1.0, &[f64::NAN; 3]);
    assert_eq!(out.legend.n_invalid, 3, "all invalid");
    assert!(out.legend.data_min.is_nan(), "no data range");
    assert!(out.legend.min.is_finite() && out.legend.max.is_finite(), "finite legend");
    let empty = apply(ColorScale::Magnitude, 1.0, &[]);
    assert!(empty.colors.is_empty() && empty.legend.n_values == 0, "empty input");
}

#[test]
fn coverage_lets_outliers_saturate() {
    // 99 values in [0, 1) and one huge value near a pole.
    let mut values: Vec<f64> = (0..99).map(|i| i as f64 / 99.0).collect();
    values.push(1e9);
    let all = apply(ColorScale::Magnitude, 1.0, &values);
    assert_eq!(all.legend.max, 1e9, "coverage 1: the outlier sets the scale");
    let most = apply(ColorScale::Magnitude, 0.99, &values);
    assert!(most.legend.max < 1.0, "coverage 0.99: {}", most.legend.max);
    assert_eq!(most.legend.n_clamped, 1, "the outlier saturates");
    assert!(close(most.colors[99], srgb_to_linear_rgb(HIGH_SRGB)), "purple");
    let min_max = apply(ColorScale::MinMax, 0.98, &values);
    assert!(min_max.legend.max < 1.0 && min_max.legend.min > 0.0, "{:?}", min_max.legend);
}

#[test]
fn invalid_maps_are_errors() {
    for coverage in [0.0, -0.5, 1.5, f64::NAN] {
        let r =
            ColorMap { scale: ColorScale::Magnitude, coverage, palette: hi_mesh::Palette::Thesis }
                .try_apply(&[1.0]);
        assert!(matches!(r, Err(Error::InvalidValue { .. })), "coverage {coverage}");
    }
    for (min, max) in [(1.0, 1.0), (2.0, 1.0), (f64::NAN, 1.0), (0.0, f64::INFINITY)] {
        let r = ColorMap {
            scale: ColorScale::Fixed { min, max },
            coverage: 1.0,
            palette: hi_mesh::Palette::Thesis,
        }
        .try_apply(&[1.0]);
        let e = r.expect_err("invalid fixed bounds");
        assert!(matches!(e, Error::InvalidValue { .. }), "[{min}, {max}]: {e:?}");
        assert!(!e.to_string().contains('\n'), "one line");
    }
}

proptest! {
    /// Any values, any scale: one colour per value, components in [0, 1], counts add up.
    #[test]
    fn colours_are_always_valid(
        values in prop::collection::vec(
            prop_oneof![-1e6f64..1e6, Just(f64::NAN), Just(f64::INFINITY), Just(0.0)], 0..60),
        coverage in 0.01f64..=1.0,
        which in 0usize..4,
    ) {
        let scale = [ColorScale::Magnitude, ColorScale::Symmetric, ColorScale::MinMax,
            ColorScale::Fixed { min: -10.0, max: 10.0 }][which];
        let out = ColorMap { scale, coverage, palette: hi_mesh::Palette::Thesis }.try_apply(&values).unwrap();
        prop_assert_eq!(out.colors.len(), values.len());
        for c in &out.colors {
            prop_assert!(c.iter().all(|x| (0.0..=1.0).contains(x)));
        }
        let finite = values.iter().filter(|x| x.is_finite()).count();
        prop_assert_eq!(out.legend.n_invalid, values.len() - finite);
        prop_assert!(out.legend.n_clamped <= finite);
        prop_assert!(out.legend.min <= out.legend.max);
    }
}

/// CIELAB lightness L* of an sRGB colour (D65), from the sRGB and CIE definitions.
fn lightness(c: [f32; 3]) -> f64 {
    let lin = |v: f32| {
        let v = f64::from(v);
        if v <= 0.04045 { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) }
    };
    let y = 0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2]);
    let f = if y > (6.0f64 / 29.0).powi(3) {
        y.cbrt()
    } else {
        y / (3.0 * (6.0f64 / 29.0).powi(2)) + 4.0 / 29.0
    };
    116.0 * f - 16.0
}

#[test]
fn the_perceptual_palettes_have_their_published_ends_and_even_lightness() {
    use hi_mesh::Palette;
    let close = |a: [f32; 3], hex: [u8; 3]| {
        // Within 1.5 of 255 (the tables are sampled from matplotlib's, whose cool–warm centre
        // is (221.2, 220.4, 220.0)).
        a.iter().zip(hex).all(|(x, h)| (f64::from(*x) - f64::from(h) / 255.0).abs() < 1.5 / 255.0)
    };
    // Viridis: #440154 to #fde725 (matplotlib's published ends).
    assert!(close(Palette::Viridis.srgb(0.0), [0x44, 0x01, 0x54]));
    assert!(close(Palette::Viridis.srgb(1.0), [0xfd, 0xe7, 0x25]));
    // Moreland's cool–warm: (59, 76, 192), (221, 221, 221) at the centre, (180, 4, 38).
    assert!(close(Palette::CoolWarm.srgb(0.0), [59, 76, 192]));
    assert!(close(Palette::CoolWarm.srgb(0.5), [221, 221, 221]));
    assert!(close(Palette::CoolWarm.srgb(1.0), [180, 4, 38]));
    // Lightness: rising all the way for viridis; rising to the centre and falling after it
    // for cool–warm.
    let steps = 400;
    let l = |p: Palette, k: usize| lightness(p.srgb(k as f64 / steps as f64));
    for k in 0..steps {
        assert!(l(Palette::Viridis, k + 1) > l(Palette::Viridis, k), "viridis at {k}");
        if 2 * k < steps {
            assert!(l(Palette::CoolWarm, k + 1) > l(Palette::CoolWarm, k), "cool–warm at {k}");
        } else {
            assert!(l(Palette::CoolWarm, k + 1) < l(Palette::CoolWarm, k), "cool–warm at {k}");
        }
    }
}

#[test]
fn a_diverging_map_puts_zero_at_its_centre() {
    use hi_mesh::Palette;
    let map = ColorMap { scale: ColorScale::Symmetric, coverage: 1.0, palette: Palette::CoolWarm };
    let out = map.try_apply(&[-2.0, 0.0, 2.0, 1.0, f64::NAN]).unwrap();
    let legend = out.legend;
    assert_eq!((legend.min, legend.max), (-2.0, 2.0));
    assert_eq!(legend.fraction(-2.0), Some(0.0));
    assert_eq!(legend.fraction(0.0), Some(0.5));
    assert_eq!(legend.fraction(1.0), Some(0.75));
    assert_eq!(legend.fraction(f64::NAN), None);
    assert_eq!(legend.srgb_at(0.0), Palette::CoolWarm.srgb(0.5));
    assert_eq!(legend.srgb_at(-2.0), Palette::CoolWarm.srgb(0.0));
    assert_eq!(legend.srgb_at(2.0), Palette::CoolWarm.srgb(1.0));
    assert_eq!(out.colors[4], srgb_to_linear_rgb(NEUTRAL_SRGB));
}
