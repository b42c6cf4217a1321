// SPDX-License-Identifier: MIT
//! Prints the §5.9 curvature comparison as a markdown table.

fn main() {
    println!(
        "| fig | surface | samples | points | max ΔK | RMS ΔK | max |K| | max ΔH | RMS ΔH | max |H| |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for s in hi_surface::test_surfaces() {
        let c = hi_surface::compare_curvature(&s, 64);
        println!(
            "| {} | {} | {}×{} | {} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} |",
            s.figure,
            s.title,
            s.samples.0,
            s.samples.1,
            c.n_points,
            c.gaussian_max,
            c.gaussian_rms,
            c.gaussian_scale,
            c.mean_max,
            c.mean_rms,
            c.mean_scale
        );
    }
}
