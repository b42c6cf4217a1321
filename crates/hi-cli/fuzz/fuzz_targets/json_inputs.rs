// SPDX-License-Identifier: MIT
//! The JSON inputs of `hi`: the points of a curve (`hi curve …`), the grid of a surface
//! (`hi surface …`) and, through the same parser, the slices of `hi surface bspline-fit`. The
//! binary's own parsers are linked from its library (`hi_cli::parse_points`,
//! `hi_cli::parse_grid`), and whatever it accepts is built into the curve or surface the command would build and
//! evaluated, which must give a finite point. Any panic is a finding; an error is the expected
//! answer to bad input. `crates/hi-cli`'s tests replay the corpus with the same checks.

#![no_main]

use hi_curve::HarmonicCurve;
use hi_surface::HarmonicSurface;
use libfuzzer_sys::fuzz_target;

use hi_cli::{Points, parse_grid, parse_points};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(points) = parse_points(text) {
        // The command builds the harmonic curve through them and evaluates it.
        match points {
            Points::One(p) => {
                if let Ok(c) = HarmonicCurve::try_new(p) {
                    assert!(c.eval(0.37).is_finite());
                }
            }
            Points::Two(p) => {
                if let Ok(c) = HarmonicCurve::try_new(p) {
                    assert!(c.eval(0.37).is_finite());
                }
            }
            Points::Three(p) => {
                if let Ok(c) = HarmonicCurve::try_new(p) {
                    assert!(c.eval(0.37).is_finite());
                }
            }
        }
    }
    if let Ok(grid) = parse_grid(text) {
        assert!(grid.iter().flatten().all(|p| p.is_finite()));
        if let Ok(s) = HarmonicSurface::try_new(grid) {
            assert!(s.eval(0.37, 0.61).is_finite());
        }
    }
});
