// SPDX-License-Identifier: MIT
//! Figures 5.27–5.30 and the table of §5.7's schemes: harmonic surfaces as Bézier patches
//! (`hi_surface::bezier`), as binary glTF models, and the basis error of each scheme for
//! n = 4 … 128 (`hi_curve::bezier`).

use std::fmt::Write as _;

use anyhow::{Result, ensure};
use glam::DVec3;
use hi_curve::HarmonicCurve;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_geomimage::{ErrorMeasure, FitOptions, Layout, Method, Smoothing, fit};
use hi_mesh::TriangleMesh;
use hi_surface::bezier::SurfaceBezier;
use hi_surface::{HarmonicSurface, MeshOptions, torus};

use super::glb::glb;
use super::scans::{ensure_outward, face_up, head_scan, turned_back};
use super::{Figure, Format, Panel, Table};

/// Samples per patch side in the meshes.
const SAMPLES: usize = 6;

/// Samples per patch side in the meshes of the heads (more patches).
const HEAD_SAMPLES: usize = 3;

/// The reduced geometry image of the heads, rows × columns (sampled at twice this, §5.8).
const HEAD_IMAGE: usize = 24;

/// The torus of figures 5.27–5.28: the thesis's 4×4 torus grid.
fn the_torus() -> HarmonicSurface<DVec3> {
    torus(2.0, 1.0)
}

/// The mesh of `patches`, coloured per patch or plain.
fn patch_mesh(
    patches: &SurfaceBezier<DVec3>,
    k: usize,
    indices: &[usize],
    colored: bool,
) -> Result<TriangleMesh> {
    let mesh = patches.to_triangle_mesh_of(k, indices)?;
    Ok(if colored { mesh } else { mesh.without_colors() })
}

/// Figure 5.27(a): the harmonic torus itself.
fn harmonic_torus() -> Result<Vec<u8>> {
    let options = MeshOptions { n_u: 24, n_v: 48, ..MeshOptions::default() };
    glb(&the_torus().to_mesh(&options)?)
}

/// The torus as patches by `scheme` (Hermite: within 1e-3 of the bounding-box diagonal),
/// checked: the thesis's 16 patches pass through the 16 points; every deviation is within its
/// bound.
fn torus_patches(scheme: BezierScheme) -> Result<SurfaceBezier<DVec3>> {
    let s = the_torus();
    let tolerance = 1e-3 * 6.0; // the 4×4 torus grid spans 6 × 6 × 2: diagonal ≈ 8.7
    let b = s.to_bezier(scheme, hi_curve::bezier::Tolerance::Absolute(tolerance))?;
    ensure!(
        b.report.max_deviation <= b.report.bound,
        "{}: deviation above its bound",
        scheme.name()
    );
    if scheme == BezierScheme::ThesisCubic {
        ensure!(b.report.patches == 16, "the thesis's 16 patches");
        for j in 0..4 {
            for k in 0..4 {
                let d = (b.eval(j as f64 / 4.0, k as f64 / 4.0) - s.point(j, k)).length();
                ensure!(d < 1e-12, "point ({j}, {k}) missed by {d:e}");
            }
        }
    }
    Ok(b)
}

/// A torus figure panel.
fn torus_figure(scheme: BezierScheme, colored: bool) -> Result<Vec<u8>> {
    let b = torus_patches(scheme)?;
    let all: Vec<usize> = (0..b.patches.len()).collect();
    glb(&patch_mesh(&b, SAMPLES, &all, colored)?)
}

/// A head scan through §5.8's pipeline ("combined results"): its scan, a flattened
/// octahedron image of contours of located points (Theorem 5.3 to the columns), Gaussian
/// smoothing, a reduction to a quarter by Theorem 5.3, and the thesis's cubic patches; the
/// patches of one cover. The head is fitted turned to look up, so that the layout's seams run
/// over the back of the head, and its surface turned back.
fn head_patches(pointed: bool) -> Result<(SurfaceBezier<DVec3>, Vec<usize>)> {
    // Turned to look up, so that the flattened octahedron's seams run over the back of the
    // head, not down its face; the surface turned back ([`super::scans::face_up`]).
    let scan = face_up(head_scan(pointed)?);
    let options = FitOptions {
        method: Method::Contours,
        layout: Layout::FlatOctahedron,
        resolution: Some((2 * HEAD_IMAGE, 2 * HEAD_IMAGE)),
        smoothing: Some(Smoothing::Gaussian { sigma: 1.0 }),
        reduce: Some(0.25),
        error: ErrorMeasure::Off,
        ..FitOptions::thesis()
    };
    let fitted = fit(&scan, &options, &mut |_| {})?;
    ensure!(fitted.report.non_star_fraction < 0.05, "the head is not star-shaped about its centre");
    ensure!(fitted.report.surface_size == (HEAD_IMAGE, HEAD_IMAGE), "reduced to a quarter");
    let b = turned_back(&fitted.largest().surface)?
        .to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)?;
    ensure!(b.report.max_deviation <= b.report.bound, "deviation above its bound");
    let u = Layout::FlatOctahedron.covering_window();
    let once = b.patches_in(u);
    Ok((b, once))
}

/// A head figure panel.
fn head_figure(pointed: bool, colored: bool) -> Result<Vec<u8>> {
    let (b, once) = head_patches(pointed)?;
    let mesh = patch_mesh(&b, HEAD_SAMPLES, &once, colored)?;
    ensure_outward(&mesh, 0.99, "the head")?;
    glb(&mesh)
}

/// What the head figures draw.
const HEAD_DRAWN: &str = "§5.8's combined pipeline on the head's scan: a 48×48 flattened-octahedron image whose rows are \
    contours through the scan points the rays located, made rectangular by Theorem 5.3 (`hi fit --texels contours`), \
    smoothed by a Gaussian of σ = 1 texel, reduced to 24×24 by Theorem 5.3, and converted to the thesis's bicubic \
    patches (§5.7, 576 in all, the 288 of one cover drawn): (a) shaded, (b) one colour per patch. Each patch is \
    sampled 4×4 with its own vertices. The head is fitted turned to look up, so that the layout's seams run over the \
    back of the head rather than down the face, and its surface turned back.";

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (5, 27),
        caption: "Approximation of harmonic tensor product surface",
        drawn: "(a) The harmonic torus through the 4×4 grid, meshed with 24×48 quads; (b) its approximation by the \
                thesis's 16 bicubic Bézier patches (§5.7: one cubic per interval through 4 equally spaced samples of \
                each σₖ), each patch sampled 7×7. The patches pass through the 16 points (checked) and are C0: their \
                normals jump at the patch edges.",
        data: "the exact 4×4 torus grid of docs/math.md §3 (`hi_surface::torus(2, 1)`).",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Harmonic surface", draw: |_| harmonic_torus() },
            Panel {
                suffix: "b",
                title: "(b) Bézier approximation",
                draw: |_| torus_figure(BezierScheme::ThesisCubic, false),
            },
        ],
    },
    Figure {
        number: (5, 28),
        caption: "Bézier patches used to approximate figure 5.27 (colour coded)",
        drawn: "(a) The thesis's 16 patches of figure 5.27(b), one colour per patch; (b) ours: C1 bicubic Hermite \
                patches from the surface's value, pᵤ, pᵥ and twist at the corners, refined until the guaranteed bound \
                is below 6e-3 (1e-3 of the torus's width; the report of each conversion is in the table below).",
        data: "the exact 4×4 torus grid of docs/math.md §3.",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) The thesis's cubic scheme",
                draw: |_| torus_figure(BezierScheme::ThesisCubic, true),
            },
            Panel {
                suffix: "b",
                title: "(b) C1 Hermite patches",
                draw: |_| torus_figure(BezierScheme::Hermite(HermiteDegree::Cubic), true),
            },
        ],
    },
    Figure {
        number: (5, 29),
        caption: "Final rendering of mannequin head formed from Bézier patches",
        drawn: HEAD_DRAWN,
        data: "stand-in for the thesis's mannequin scan (not available): the scan of figure 5.10 (60 000 points on \
               Lee Perry-Smith's head scan, CC BY 3.0, ±0.3% noise).",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel {
                suffix: "a", title: "(a) Bézier patches", draw: |_| head_figure(false, false)
            },
            Panel { suffix: "b", title: "(b) Colour coded", draw: |_| head_figure(false, true) },
        ],
    },
    Figure {
        number: (5, 30),
        caption: "Final rendering of Spock formed from Bézier patches",
        drawn: HEAD_DRAWN,
        data: "stand-in for the thesis's Spock scan (not available): the scan of figure 5.11 (60 000 points on Lee \
               Perry-Smith's head scan with pointed ears, ±0.3% noise).",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Bézier patches", draw: |_| head_figure(true, false) },
            Panel { suffix: "b", title: "(b) Colour coded", draw: |_| head_figure(true, true) },
        ],
    },
];

/// The tables of this module.
pub(crate) const TABLES: &[Table] = &[
    Table {
        anchor: "bezier-schemes",
        title: "The Bézier schemes of §5.7 on the basis σ",
        about: "Each scheme applied to σ₀ of size n (the curve through the points δ₀ₖ; every σₖ is a shift of it): the \
            largest deviation on 33 parameters per piece, the guaranteed bound (interval arithmetic on the Fourier \
            series, see `hi_curve::bezier`), and the continuity. The thesis's cubic scheme has a plateau of about 6e-3 \
            (docs/math.md §4) and jumps in the derivative of about 12% of max|σ′|; its quintic scheme a plateau of about \
            3e-4, and it does not pass exactly through the nodes; the Hermite scheme reaches the tolerance 1e-4 with C1 \
            joins, its pieces growing like n.",
        make: scheme_table,
    },
    Table {
        anchor: "bezier-torus",
        title: "The torus of figures 5.27–5.28 as patches",
        about: "Each scheme on the 4×4 torus grid (the Hermite ones to 6e-3, 1e-3 of its width): patches, the \
            deviation measured on 9×9 parameters per patch and its guaranteed bound, and the largest angle between \
            the normals of neighbouring patches along their edges.",
        make: torus_table,
    },
];

/// The relative derivative jump of a 1-D spline at its joins: max |S′(t⁻) − S′(t⁺)| / max|σ′|.
fn derivative_jump(spline: &hi_curve::bezier::BezierSpline<f64>, n: usize) -> f64 {
    let sigma = hi_curve::Sigma::new(n);
    let max_d =
        (0..4096).map(|i| sigma.deriv(0, i as f64 / 4096.0, 1).abs()).fold(0.0_f64, f64::max);
    let segs = spline.segments();
    let breaks = spline.breaks();
    let mut worst: f64 = 0.0;
    for a in 0..segs.len() {
        let b = (a + 1) % segs.len();
        let (ha, hb) = (breaks[a + 1] - breaks[a], breaks[b + 1] - breaks[b]);
        let (l, r) = (segs[a].eval_deriv(1.0, 1) / ha, segs[b].eval_deriv(0.0, 1) / hb);
        worst = worst.max((l - r).abs());
    }
    worst / max_d
}

/// The table of the basis schemes.
fn scheme_table() -> Result<String> {
    let mut s = String::from(
        "| n | thesis cubic: deviation | bound | derivative jump / max\\|σ′\\| | thesis quintic: deviation | bound | \
         Hermite C1 to 1e-4: pieces | deviation | bound |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for n in [4usize, 8, 16, 32, 64, 128] {
        let delta: Vec<f64> = (0..n).map(|k| f64::from(u8::from(k == 0))).collect();
        let curve = HarmonicCurve::try_new(delta)?;
        let cubic =
            curve.to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)?;
        let quintic =
            curve.to_bezier(BezierScheme::ThesisQuintic, hi_curve::bezier::DEFAULT_TOLERANCE)?;
        let hermite = curve.to_bezier(
            BezierScheme::Hermite(HermiteDegree::Cubic),
            hi_curve::bezier::Tolerance::Absolute(1e-4),
        )?;
        for r in [&cubic.report, &quintic.report, &hermite.report] {
            ensure!(r.max_deviation <= r.bound, "n = {n}: a deviation above its bound");
        }
        let _ = writeln!(
            s,
            "| {n} | {:.2e} | {:.2e} | {:.1}% | {:.2e} | {:.2e} | {} | {:.2e} | {:.2e} |",
            cubic.report.max_deviation,
            cubic.report.bound,
            100.0 * derivative_jump(&cubic.spline, n),
            quintic.report.max_deviation,
            quintic.report.bound,
            hermite.report.pieces,
            hermite.report.max_deviation,
            hermite.report.bound,
        );
    }
    Ok(s)
}

/// The table of the torus conversions.
fn torus_table() -> Result<String> {
    let mut s = String::from(
        "| scheme | patches | degree | deviation | bound | normal jump (°) |\n|---|---|---|---|---|---|\n",
    );
    for scheme in [
        BezierScheme::ThesisCubic,
        BezierScheme::ThesisQuintic,
        BezierScheme::Hermite(HermiteDegree::Cubic),
        BezierScheme::Hermite(HermiteDegree::Quintic),
    ] {
        let r = torus_patches(scheme)?.report;
        let _ = writeln!(
            s,
            "| {} | {} | {}×{} | {:.2e} | {:.2e} | {:.3} |",
            scheme.name(),
            r.patches,
            r.degree.0,
            r.degree.1,
            r.max_deviation,
            r.bound,
            r.max_normal_jump.to_degrees()
        );
    }
    Ok(s)
}
