// SPDX-License-Identifier: MIT
//! Figures 5.10, 5.11 and 5.13–5.24: scans fitted through geometry images (§5.3, §5.4) — the
//! images themselves as PNG, the surfaces they make (texels joined directly, and harmonic
//! interpolation of them) as glTF models, before and after smoothing, in the spherical,
//! octahedral and flattened-octahedral layouts — and a table of how well each fits its scan.
//!
//! The thesis's scans (Hoppe's mannequin head, Spock, and the public models of figures
//! 5.21–5.23) are not available, so the scans are made in code: a head ([`head_point`]: skull,
//! jaw and neck, nose, eye sockets, brow, cheekbones, lips, chin and ears) and the same head with
//! Spock's pointed ears stand in for the mannequin and Spock, three star-shaped solids for the
//! public models, each sampled with 60 000 points and given
//! a deterministic noise of ±0.3% of its size along the direction from its centre, as a scanner
//! would. Figure 5.24 fits the head's coarse control mesh (146 vertices), whose points are too
//! few for the rays, once as it is and once resampled on its triangles as the thesis did. The
//! real models are fitted by `cargo xtask bench fit` (Table 5.1) and by `hi fit`.

use std::f64::consts::PI;
use std::fmt::Write as _;
use std::io::Cursor;

use anyhow::{Context, Result, ensure};
use glam::{DVec2, DVec3};
use hi_geomimage::{ErrorMeasure, Fit, FitOptions, GeometryImage, Layout, Smoothing, fit};
use hi_mesh::TriangleMesh;
use hi_mesh::subdivision::PolyMesh;
use hi_scan::scan::Scan;
use hi_surface::{HarmonicSurface, MeshOptions};

use super::glb::glb;
use super::subdivision::head_with;
use super::{Figure, Format, Panel, Table};
use hi_surface::{ParamRange, ParamWindow};

/// Rows and columns of every geometry image here.
const IMAGE: usize = 64;
/// Points of each stand-in scan.
const SCAN_POINTS: usize = 60_000;
/// The scanner noise: ± this fraction of the scan's mean radius, along the ray from its centre.
const NOISE: f64 = 0.003;
/// σ of the Gaussian smoothing (in texels) of the "after smoothing" figures.
const SIGMA: f64 = 1.0;
/// Each texel of a PNG geometry image is a square of this many pixels.
const PIXELS_PER_TEXEL: u32 = 4;

/// The stand-in scans.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Model {
    /// The head stand-in (the mannequin), [`head_point`].
    Head,
    /// The head with pointed ears (Spock).
    Pointed,
    /// r = 1 + 0.15 sin 5θ cos 3φ.
    Bumpy,
    /// The rounded cube x⁴ + y⁴ + z⁴ = 1.
    RoundedCube,
    /// Two lobes along z: r = 0.7 + 0.5 z².
    Peanut,
}

impl Model {
    const fn name(self) -> &'static str {
        match self {
            Self::Head => "head (mannequin stand-in)",
            Self::Pointed => "head with pointed ears (Spock stand-in)",
            Self::Bumpy => "bumpy solid",
            Self::RoundedCube => "rounded cube",
            Self::Peanut => "peanut",
        }
    }
}

/// splitmix64: a deterministic stream of well-mixed bits.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A number in [−1, 1) from `k`.
fn noise(k: usize) -> f64 {
    (mix(k as u64) >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// `n` directions spread evenly over the unit sphere (a Fibonacci lattice).
fn directions(n: usize) -> impl Iterator<Item = DVec3> {
    let golden = PI * (3.0 - 5f64.sqrt());
    (0..n).map(move |k| {
        let z = 1.0 - (2 * k + 1) as f64 / n as f64;
        let s = (1.0 - z * z).sqrt();
        let phi = k as f64 * golden;
        DVec3::new(s * phi.cos(), s * phi.sin(), z)
    })
}

/// Moves each point along its direction from the centroid by ±[`NOISE`] of the mean radius.
fn with_noise(points: Vec<DVec3>) -> Vec<DVec3> {
    let centre = points.iter().sum::<DVec3>() / points.len() as f64;
    let radius = points.iter().map(|p| p.distance(centre)).sum::<f64>() / points.len() as f64;
    points
        .into_iter()
        .enumerate()
        .map(|(k, p)| p + (p - centre).normalize_or_zero() * (NOISE * radius * noise(k)))
        .collect()
}

/// The scan of a stand-in model.
fn scan(model: Model) -> Result<Scan> {
    let radial = |r: &dyn Fn(DVec3) -> f64| -> Vec<DVec3> {
        directions(SCAN_POINTS).map(|d| d * r(d)).collect()
    };
    let points = match model {
        Model::Head | Model::Pointed => {
            let pointed = model == Model::Pointed;
            directions(SCAN_POINTS).map(|d| head_point(d, pointed)).collect()
        }
        Model::Bumpy => radial(&|d| {
            let (theta, phi) = (d.z.acos(), d.y.atan2(d.x));
            1.0 + 0.15 * (5.0 * theta).sin() * (3.0 * phi).cos()
        }),
        Model::RoundedCube => radial(&|d| (d.x.powi(4) + d.y.powi(4) + d.z.powi(4)).powf(-0.25)),
        Model::Peanut => radial(&|d| 0.7 + 0.5 * d.z * d.z),
    };
    Ok(Scan { points: with_noise(points), ..Scan::default() })
}

/// A bump of height `h` on the unit sphere about the unit direction `centre`, `across` wide
/// horizontally and `along` high (both in radians, roughly: the tangent components of `dir` are
/// taken for the angles), falling off as exp(−ρ^(2·`flat`)) with ρ the scaled distance: `flat`
/// 1 is a Gaussian, more is flatter on top with a steeper edge. Zero on the far hemisphere.
fn bump(dir: DVec3, centre: DVec3, (across, along): (f64, f64), h: f64, flat: i32) -> f64 {
    let c = centre.normalize();
    if dir.dot(c) <= 0.0 {
        return 0.0;
    }
    let east = DVec3::Z.cross(c).try_normalize().unwrap_or(DVec3::X);
    let north = c.cross(east);
    let (a, b) = (dir.dot(east) / across, dir.dot(north) / along);
    h * (-(a * a + b * b).powi(flat)).exp()
}

/// The head stand-in: the point of its surface in the unit direction `dir` (it is star-shaped
/// about the origin, as the thesis's algorithm 2 needs), facing +y with +z up, about 1.6 wide,
/// 1.8 deep and 2.4 high. A radius 1 + Σ bumps ([`bump`]: nose bridge, tip and wings, eye
/// sockets, brow, cheekbones, lips and the mouth's line between them, chin, ears with a hollow
/// inside the rim, `pointed` ears rising to a tip for Spock) on an egg-shaped skull, narrowed
/// to a jaw and a neck below.
pub(crate) fn head_point(dir: DVec3, pointed: bool) -> DVec3 {
    let v = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
    let mut r = 1.0;
    // The nose: a ridge from the bridge down to a rounded tip, and its wings.
    r += bump(dir, v(0.0, 0.99, 0.0), (0.075, 0.17), 0.1, 2);
    r += bump(dir, v(0.0, 0.95, -0.2), (0.09, 0.08), 0.2, 1);
    for side in [-1.0, 1.0] {
        r += bump(dir, v(0.1 * side, 0.95, -0.21), (0.05, 0.045), 0.07, 1);
        // Eye sockets under the brow with the eyes in them, cheekbones below and outside.
        r -= bump(dir, v(0.3 * side, 0.92, 0.12), (0.13, 0.08), 0.08, 2);
        r += bump(dir, v(0.3 * side, 0.93, 0.11), (0.07, 0.045), 0.05, 1);
        r += bump(dir, v(0.5 * side, 0.82, -0.08), (0.13, 0.09), 0.05, 1);
        // The ears: a flat oval with a hollow inside its rim.
        r += bump(dir, v(side, -0.08, 0.05), (0.1, 0.2), 0.2, 2);
        r -= bump(dir, v(side, -0.05, 0.06), (0.05, 0.12), 0.07, 2);
        if pointed {
            // Spock's: the rim drawn up and back to a point well above the ear.
            r += bump(dir, v(side, -0.13, 0.32), (0.07, 0.14), 0.21, 1);
            r += bump(dir, v(side, -0.19, 0.5), (0.04, 0.09), 0.2, 1);
        }
    }
    r += bump(dir, v(0.0, 0.92, 0.3), (0.42, 0.06), 0.05, 2); // brow
    // Lips, parted by the line of the mouth, and the chin.
    r += bump(dir, v(0.0, 0.9, -0.37), (0.14, 0.04), 0.045, 2);
    r += bump(dir, v(0.0, 0.88, -0.45), (0.12, 0.04), 0.04, 2);
    r -= bump(dir, v(0.0, 0.89, -0.41), (0.14, 0.014), 0.02, 1);
    r += bump(dir, v(0.0, 0.78, -0.6), (0.15, 0.1), 0.08, 1);
    // An egg-shaped skull, narrower at the jaw (a smoothed 0.22·max(−z, 0)), and a neck.
    let down = -dir.z;
    let jaw = 1.0 - 0.11 * (down + (down * down + 0.02).sqrt());
    let t = ((down - 0.75) / 0.25).clamp(0.0, 1.0);
    let neck = 1.0 - 0.3 * t * t * (3.0 - 2.0 * t);
    DVec3::new(0.78 * jaw * neck * dir.x, 0.9 * jaw * neck * dir.y, 1.1 * dir.z) * r
}

/// The scan of the head stand-in (mannequin), or of the head with pointed ears (Spock).
pub(crate) fn head_scan(pointed: bool) -> Result<Scan> {
    scan(if pointed { Model::Pointed } else { Model::Head })
}

/// The triangles of a triangle mesh.
fn mesh_triangles(mesh: &PolyMesh) -> Result<Vec<[u32; 3]>> {
    mesh.faces()
        .map(|f| <[u32; 3]>::try_from(f).context("the head's faces are triangles"))
        .collect()
}

/// The head's coarse control mesh as a scan with faces (figure 5.24).
fn coarse_head() -> Result<Scan> {
    let mesh = head_with(false)?;
    Ok(Scan {
        points: mesh.positions().to_vec(),
        triangles: mesh_triangles(&mesh)?,
        ..Scan::default()
    })
}

/// How a figure fits its scan.
#[derive(Clone, Copy, Debug)]
struct Setup {
    layout: Layout,
    smooth: bool,
    /// Resample a mesh on its triangles when it has too few points (the fit's default).
    densify: bool,
}

const SPHERE: Setup = Setup { layout: Layout::Sphere, smooth: false, densify: true };
const SPHERE_SMOOTH: Setup = Setup { smooth: true, ..SPHERE };
const OCTAHEDRON: Setup = Setup { layout: Layout::Octahedron, ..SPHERE };
const OCTAHEDRON_SMOOTH: Setup = Setup { layout: Layout::Octahedron, ..SPHERE_SMOOTH };
const FLAT: Setup = Setup { layout: Layout::FlatOctahedron, ..SPHERE };
const FLAT_SMOOTH: Setup = Setup { layout: Layout::FlatOctahedron, ..SPHERE_SMOOTH };

/// Fits `scan` as `setup` says, measuring the error when `measure`.
fn fitted(scan: &Scan, setup: Setup, measure: bool) -> Result<Fit> {
    let options = FitOptions {
        layout: setup.layout,
        resolution: Some((IMAGE, IMAGE)),
        smoothing: setup.smooth.then_some(Smoothing::Gaussian { sigma: SIGMA }),
        densify: if setup.densify { FitOptions::default().densify } else { 0 },
        error: if measure { ErrorMeasure::Sampled(4) } else { ErrorMeasure::Off },
        ..FitOptions::thesis()
    };
    Ok(fit(scan, &options, &mut |_| {})?)
}

/// The mesh of `surface` over the window that covers the object once, `per_texel` quads per
/// texel along each axis; its triangles must face outwards (every layout makes pᵤ × pᵥ point
/// outwards), all but a few at the octahedron's seams.
fn covering_mesh(
    surface: &HarmonicSurface<DVec3>,
    layout: Layout,
    per_texel: usize,
) -> Result<TriangleMesh> {
    let u = layout.covering_window();
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "the window is ½ or 1 of a period of 64 rows"
    )]
    let n_u = (u.width() * surface.m() as f64).round() as usize * per_texel;
    let options = MeshOptions {
        n_u,
        n_v: surface.n() * per_texel,
        window: ParamWindow::new(u, ParamRange::UNIT),
        ..MeshOptions::default()
    };
    let mesh = surface.to_mesh(&options)?;
    ensure_outward(&mesh, 0.9, "the fitted surface")?;
    Ok(mesh)
}

/// Fails unless more than the fraction `min` of the triangles of `mesh` (`what`) are wound to
/// face away from the centroid of its vertices: the check of a closed, roughly star-shaped
/// model's orientation.
pub(crate) fn ensure_outward(mesh: &TriangleMesh, min: f64, what: &str) -> Result<()> {
    let p = mesh.positions();
    let centre = p.iter().sum::<DVec3>() / p.len() as f64;
    let outward = mesh
        .triangles()
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|k| p[k as usize]);
            (b - a).cross(c - a).dot((a + b + c) / 3.0 - centre) > 0.0
        })
        .count() as f64
        / mesh.triangles().len() as f64;
    ensure!(outward > min, "only {:.1}% of the triangles of {what} face outwards", 100.0 * outward);
    Ok(())
}

/// The harmonic surface of a fit, meshed with 2×2 quads per texel.
fn harmonic_glb(model: Model, setup: Setup) -> Result<Vec<u8>> {
    let result = fitted(&scan(model)?, setup, false)?;
    glb(&covering_mesh(&result.largest().surface, setup.layout, 2)?)
}

/// The image size of the real models' fits: below what `hi fit` picks for them, so that each
/// figure file stays under a megabyte (the scans themselves live in
/// `fixtures/models`).
const REAL_IMAGE: (usize, usize) = (160, 160);

/// The fit of the real model `file` of `fixtures/models` (stood up and turned to the viewer:
/// its files have +y up and face −z, the figures have +z up and are seen from −y) by
/// `hi fit`'s defaults (the parameterisation of each part of its mesh, no smoothing) at
/// [`REAL_IMAGE`] (shared by the parts by area), meshed as `hi fit` writes them: one vertex per
/// texel, welded into closed surfaces checked to enclose a positive volume (wound outwards), or
/// open sheets; the parts in one mesh.
fn real_glb(file: &str) -> Result<Vec<u8>> {
    let path = crate::project_root().join("fixtures/models").join(file);
    let scan = hi_scan::scan::read_scan(&path).with_context(|| format!("reading {file}"))?;
    let points = scan.points.iter().map(|p| DVec3::new(-p.x, p.z, p.y)).collect();
    let scan = Scan { points, ..scan };
    let options = FitOptions {
        resolution: Some(REAL_IMAGE),
        error: ErrorMeasure::Off,
        ..FitOptions::default()
    };
    let result = fit(&scan, &options, &mut |_| {})?;
    ensure!(
        result.report.method == hi_geomimage::Method::Mesh,
        "{file}: fitted by {}, not by its mesh ({})",
        result.report.method.name(),
        result.report.method_reason
    );
    // Every part, as `hi fit` writes them, in one mesh.
    let (mut positions, mut normals, mut uvs, mut triangles) = (vec![], vec![], vec![], vec![]);
    for part in &result.parts {
        let mesh = hi_geomimage::layout_mesh::layout_mesh(&part.surface, part.domain, 1)?.mesh;
        if part.domain.is_closed() {
            let volume = mesh.signed_volume();
            ensure!(volume > 0.0, "{file}: a fitted part is wound inwards (volume {volume})");
        }
        let offset = u32::try_from(positions.len())?;
        positions.extend_from_slice(mesh.positions());
        normals.extend_from_slice(mesh.normals());
        uvs.extend_from_slice(mesh.uvs());
        triangles.extend(mesh.triangles().iter().map(|t| t.map(|k| k + offset)));
    }
    glb(&TriangleMesh::try_new(positions, normals, uvs, triangles)?)
}

/// The texels of a fit's image joined directly: one quad per texel, with normals from the
/// faces (what the geometry image gives without harmonic interpolation).
fn texel_glb(model: Model, setup: Setup) -> Result<Vec<u8>> {
    let result = fitted(&scan(model)?, setup, false)?;
    // Meshing the surface at its own grid puts the vertices on the texels exactly.
    let mesh = covering_mesh(&result.largest().surface, setup.layout, 1)?;
    let p = mesh.positions();
    let mut normals = vec![DVec3::ZERO; p.len()];
    for t in mesh.triangles() {
        let [a, b, c] = t.map(|k| p[k as usize]);
        let n = (b - a).cross(c - a);
        for k in t {
            normals[*k as usize] += n;
        }
    }
    let normals: Vec<DVec3> = normals
        .iter()
        .zip(mesh.normals())
        .map(|(n, smooth)| n.try_normalize().unwrap_or(*smooth))
        .collect();
    let uvs: Vec<DVec2> = mesh.uvs().to_vec();
    glb(&TriangleMesh::try_new(p.to_vec(), normals, uvs, mesh.triangles().to_vec())?)
}

/// A geometry image as a PNG: x, y, z scaled from the texels' bounding box to red, green and
/// blue; `rows` of them (all, or the first half for one side of a doubled layout), repeated
/// `tiles` times along each axis (1 for the image itself; more for its periodic extension,
/// which is what the harmonic surface through it interpolates).
fn image_png(image: &GeometryImage, rows: usize, tiles: u32) -> Result<Vec<u8>> {
    let texels = &image.texels()[..rows * image.cols()];
    let lo = texels.iter().copied().fold(DVec3::INFINITY, DVec3::min);
    let hi = texels.iter().copied().fold(DVec3::NEG_INFINITY, DVec3::max);
    let span = (hi - lo).max(DVec3::splat(1e-300));
    let k = PIXELS_PER_TEXEL;
    let (cols, rows) = (u32::try_from(image.cols())?, u32::try_from(rows)?);
    let (w, h) = (cols * k * tiles, rows * k * tiles);
    let picture = image::RgbImage::from_fn(w, h, |x, y| {
        let (x, y) = ((x / k) % cols, (y / k) % rows);
        let t = y as usize * image.cols() + x as usize;
        let c = (texels[t] - lo) / span * 255.0;
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "each channel is rounded from [0, 255]"
        )]
        image::Rgb([c.x, c.y, c.z].map(|v| v.round().clamp(0.0, 255.0) as u8))
    });
    let mut bytes = Vec::new();
    picture.write_to(&mut Cursor::new(&mut bytes), image::ImageFormat::Png)?;
    Ok(bytes)
}

/// The geometry image of a fit (before smoothing) as a PNG: its first half when `half`,
/// repeated `tiles` × `tiles` (2 shows one period and the neighbouring copies that harmonic
/// interpolation treats as its continuation).
fn fit_png(model: Model, setup: Setup, half: bool, tiles: u32) -> Result<Vec<u8>> {
    let result = fitted(&scan(model)?, setup, false)?;
    let image = result.largest().source.image();
    image_png(image, if half { image.rows() / 2 } else { image.rows() }, tiles)
}

/// Every tenth point of the scan of `model`, rendered for figure `number` (its panel (a), "Data
/// points").
fn points_view(number: (u32, u32), model: Model) -> Result<Vec<u8>> {
    let points: Vec<DVec3> = scan(model)?.points.into_iter().step_by(10).collect();
    super::renders::render_points(number, &points, 0.0022)
}

/// Whether the point `p` of a head lies on its face: in front of the ears, between the chin
/// and the brow (the close-ups of figures 5.14–5.17 frame it).
fn on_face(p: DVec3) -> bool {
    p.y > 0.35 && p.z > -0.85 && p.z < 0.45 && p.x.abs() < 0.6
}

/// The close-up of the face of the head model `glb`, for figure `number` (its panel (b)).
fn close_up(number: (u32, u32), glb: &[u8]) -> Result<Vec<u8>> {
    super::renders::render_close_up(number, glb, on_face)
}

/// The render of the harmonic surface of the head's fit, for figure `number`.
fn surface_png(number: (u32, u32), setup: Setup) -> Result<Vec<u8>> {
    // The render is WebP; this panel sits beside a PNG image in a figure of PNG files.
    let webp = super::renders::render_model(number, &harmonic_glb(Model::Head, setup)?)?;
    let mut bytes = Vec::new();
    image::load_from_memory(&webp)?
        .to_rgb8()
        .write_to(&mut Cursor::new(&mut bytes), image::ImageFormat::Png)?;
    Ok(bytes)
}

/// Figure 5.24: the coarse head, resampled on its triangles or not.
fn coarse_glb(densify: bool) -> Result<Vec<u8>> {
    let setup = Setup { densify, ..FLAT_SMOOTH };
    let result = fitted(&coarse_head()?, setup, false)?;
    glb(&covering_mesh(&result.largest().surface, setup.layout, 2)?)
}

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (5, 10),
        caption: "Surface fitting using harmonic tensor product surfaces (mannequin)",
        drawn: "The harmonic surface through a 64×64 spherical geometry image (algorithm 2) of the head's scan, \
                smoothed by a Gaussian of σ = 1 texel, meshed with 2×2 quads per texel over u ∈ [0, ½]; (a) every \
                tenth point of the scan, each drawn as a small ball.",
        data: "stand-in for the thesis's mannequin scan (not available): 60 000 points on a head made in code \
               (`head_point`: skull, jaw and neck, nose, eye sockets and eyes, brow, cheekbones, lips, chin and \
               ears), with ±0.3% noise along the rays.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "a",
            title: "(a) Data points",
            draw: |_| points_view((5, 10), Model::Head),
        }],
        panels: &[Panel {
            suffix: "b",
            title: "(b) Surface",
            draw: |_| harmonic_glb(Model::Head, SPHERE_SMOOTH),
        }],
    },
    Figure {
        number: (5, 11),
        caption: "Surface fitting using harmonic tensor product surfaces (Spock)",
        drawn: "As figure 5.10 for the head with pointed ears, (a) its data points and (b) the surface; its geometry \
                image is figure 5.13.",
        data: "stand-in for the thesis's Spock scan (not available): 60 000 points on the head of figure 5.10 with \
               Spock's ears drawn up to a point, with ±0.3% noise along the rays.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "a",
            title: "(a) Data points",
            draw: |_| points_view((5, 11), Model::Pointed),
        }],
        panels: &[Panel {
            suffix: "b",
            title: "(b) Surface",
            draw: |_| harmonic_glb(Model::Pointed, SPHERE_SMOOTH),
        }],
    },
    Figure {
        number: (5, 13),
        caption: "Geometry image (Spock)",
        drawn: "The 64×64 spherical geometry image of figure 5.11 before smoothing, x, y, z as red, green, blue \
                (scaled to the bounding box). Rows are u (pole, equator, other pole, equator), columns v; the \
                lower half repeats the upper turned by half a period, so the image is periodic both ways.",
        data: "the Spock stand-in of figure 5.11.",
        format: Format::Png,
        views: &[],
        panels: &[Panel {
            suffix: "",
            title: "",
            draw: |_| fit_png(Model::Pointed, SPHERE, false, 1),
        }],
    },
    Figure {
        number: (5, 14),
        caption: "Surface produced by spherical geometry image (mannequin)",
        drawn: "The texels of the 64×64 spherical geometry image joined directly (one quad per texel, normals from \
                the faces), no smoothing: the undulations the thesis attributes to the geometry image. (b) The same \
                model framed on the face.",
        data: "the mannequin stand-in of figure 5.10.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "b",
            title: "(b) Close-up",
            draw: |_| close_up((5, 14), &texel_glb(Model::Head, SPHERE)?),
        }],
        panels: &[Panel {
            suffix: "a",
            title: "(a) Surface",
            draw: |_| texel_glb(Model::Head, SPHERE),
        }],
    },
    Figure {
        number: (5, 15),
        caption: "Surface produced by harmonic interpolation (mannequin)",
        drawn: "The harmonic surface through the image of figure 5.14 (2×2 quads per texel): it passes through \
                every texel and keeps their undulations. (b) The same model framed on the face.",
        data: "the mannequin stand-in of figure 5.10.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "b",
            title: "(b) Close-up",
            draw: |_| close_up((5, 15), &harmonic_glb(Model::Head, SPHERE)?),
        }],
        panels: &[Panel {
            suffix: "a",
            title: "(a) Surface",
            draw: |_| harmonic_glb(Model::Head, SPHERE),
        }],
    },
    Figure {
        number: (5, 16),
        caption: "Surface produced by geometry image after smoothing (mannequin)",
        drawn: "As figure 5.14 after a periodic Gaussian of σ = 1 texel on the image (§5.4), (b) framed on the face.",
        data: "the mannequin stand-in of figure 5.10.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "b",
            title: "(b) Close-up",
            draw: |_| close_up((5, 16), &texel_glb(Model::Head, SPHERE_SMOOTH)?),
        }],
        panels: &[Panel {
            suffix: "a",
            title: "(a) Surface",
            draw: |_| texel_glb(Model::Head, SPHERE_SMOOTH),
        }],
    },
    Figure {
        number: (5, 17),
        caption: "Surface produced by harmonic interpolation after smoothing (mannequin)",
        drawn: "The harmonic surface through the smoothed image of figure 5.16 (the surface of figure 5.10); (b) the \
                same model framed on the face.",
        data: "the mannequin stand-in of figure 5.10.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "b",
            title: "(b) Close-up",
            draw: |_| close_up((5, 17), &harmonic_glb(Model::Head, SPHERE_SMOOTH)?),
        }],
        panels: &[Panel {
            suffix: "a",
            title: "(a) Surface",
            draw: |_| harmonic_glb(Model::Head, SPHERE_SMOOTH),
        }],
    },
    Figure {
        number: (5, 18),
        caption: "Octahedron geometry image",
        drawn: "The 64×64 octahedral geometry image of the head (Praun and Hoppe's square, wrapped as it is), x, y, \
                z as red, green, blue: one cover of the sphere, the upper hemisphere in the central diamond. Where \
                the square wraps, neighbouring texels are far apart on the head (figure 5.19). (b) The harmonic \
                surface through it, before smoothing, rendered (`hi-raytrace`, a mesh of 2×2 quads per texel): \
                interpolating across the jumps where the square wraps rings over the whole surface (Gibbs \
                ripples) and folds at the wrapped edges; figure 5.19 is the same after smoothing. (c) The image \
                repeated 2×2, as harmonic interpolation sees it (periodic in both directions): across each edge \
                of the square the colours jump, because the texels that meet there are far apart on the head.",
        data: "the mannequin stand-in of figure 5.10.",
        format: Format::Png,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Geometry image",
                draw: |_| fit_png(Model::Head, OCTAHEDRON_SMOOTH, false, 1),
            },
            Panel { suffix: "b", title: "(b) Render", draw: |_| surface_png((5, 18), OCTAHEDRON) },
            Panel {
                suffix: "c",
                title: "(c) Periodic image",
                draw: |_| fit_png(Model::Head, OCTAHEDRON, false, 2),
            },
        ],
    },
    Figure {
        number: (5, 19),
        caption: "Harmonic surface produced using octahedron geometry image (mannequin)",
        drawn: "(a) The texels of the 64×64 octahedral image of figure 5.18 joined directly (one quad per \
                texel). (b) The same after a periodic Gaussian of σ = 1 texel on the image. (c) The harmonic \
                surface through the smoothed image, over the whole period. (d) Panel (c) framed on the face. \
                Smoothing and interpolation across the wrapped edges of the square join far-apart texels and \
                leave seams, as in the thesis.",
        data: "the mannequin stand-in of figure 5.10.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "d",
            title: "(d) Close-up",
            draw: |_| close_up((5, 19), &harmonic_glb(Model::Head, OCTAHEDRON_SMOOTH)?),
        }],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Surface",
                draw: |_| texel_glb(Model::Head, OCTAHEDRON),
            },
            Panel {
                suffix: "b",
                title: "(b) Smooth",
                draw: |_| texel_glb(Model::Head, OCTAHEDRON_SMOOTH),
            },
            Panel {
                suffix: "c",
                title: "(c) Harmonic interpolation",
                draw: |_| harmonic_glb(Model::Head, OCTAHEDRON_SMOOTH),
            },
        ],
    },
    Figure {
        number: (5, 20),
        caption: "Flattened octahedron geometry image (one side only)",
        drawn: "The first 32 rows of the 64×64 flattened-octahedron image of the head (one cover of the sphere; the \
                other 32 rows are its half-turn), x, y, z as red, green, blue. The square is extended by its own \
                symmetry, so neighbouring texels are neighbours on the head everywhere and smoothing leaves no seam. \
                (b) The harmonic surface through the whole image (u ∈ [0, ½] drawn), rendered.",
        data: "the mannequin stand-in of figure 5.10.",
        format: Format::Png,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Geometry image",
                draw: |_| fit_png(Model::Head, FLAT, true, 1),
            },
            Panel { suffix: "b", title: "(b) Render", draw: |_| surface_png((5, 20), FLAT) },
        ],
    },
    Figure {
        number: (5, 21),
        caption: "Surface fitting using harmonic tensor product surfaces",
        drawn: "The harmonic surface fitted to Keenan Crane's Spot (a cow) by `hi fit`'s defaults: the mesh closed, \
                mapped onto the sphere without folds, sampled as a 160×160 geometry image (smaller than `hi fit` \
                picks, to keep the files small) and interpolated, with no smoothing; meshed as `hi fit` writes it (one vertex per texel, welded, closed). Horns, ears and legs \
                are reached, which the thesis's rays from a centre could not.",
        data: "`fixtures/models/spot.obj` (public domain; 2 930 vertices), the thesis's cow among its models.",
        format: Format::Glb,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |_| real_glb("spot.obj") }],
    },
    Figure {
        number: (5, 22),
        caption: "Surface fitting using harmonic tensor product surfaces",
        drawn: "As figure 5.21 for a duck, whose bill and tail are not star-shaped about any centre. The open bill's \
                halves are thinner than a texel of the 160×160 image at their rims, which come out serrated.",
        data: "`fixtures/models/duck.obj` (MIT; 10 093 vertices), the thesis's duck among its models.",
        format: Format::Glb,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |_| real_glb("duck.obj") }],
    },
    Figure {
        number: (5, 23),
        caption: "Surface fitting using harmonic tensor product surfaces",
        drawn: "As figure 5.21 for Wuson, a four-legged cartoon animal in 54 pieces: every piece of at least 0.05 % \
                of its area is fitted on its own (the body over the sphere, the pieces that are open shells as open \
                sheets), the specks below that left out, as `hi fit` reports.",
        data: "`fixtures/models/wuson.off` (BSD-3-Clause; 3 205 vertices), in place of the thesis's bunny (whose \
               licence does not allow it here).",
        format: Format::Glb,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |_| real_glb("wuson.off") }],
    },
    Figure {
        number: (5, 24),
        caption: "Surface fitting using harmonic tensor product surfaces of resampled data set",
        drawn: "(a) The head's coarse control mesh (146 vertices) fitted through a 64×64 flattened-octahedron image \
                from its vertices alone: most rays find too few points and their texels are filled from their \
                neighbours (the hole fraction is in the table below); (b) the same mesh resampled with 200 000 \
                points on its triangles first, as the thesis did for models with few points: the fit follows the \
                faceted mesh.",
        data: "the control mesh of the head of figure 4.35.",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Vertices only", draw: |_| coarse_glb(false) },
            Panel { suffix: "b", title: "(b) Resampled", draw: |_| coarse_glb(true) },
        ],
    },
];

/// The table of the fits.
pub(crate) const TABLES: &[Table] = &[Table {
    anchor: "scan-fits",
    title: "Fits of the stand-in scans (figures 5.10–5.24)",
    about: "Each scan fitted through a 64×64 geometry image as its figure says (`hi_geomimage::fit`): the fraction \
            of rays that met several shells (not star-shaped) or too few points (holes, filled from their \
            neighbours), and the distances from every scan point to the harmonic surface (mean, RMS, max) relative \
            to the diagonal of the scan's bounding box. Smoothing trades distance for fewer undulations; the \
            octahedron's seams show in its maximum.",
    make: table,
}];

/// Computes the table.
fn table() -> Result<String> {
    let rows: [(&str, Model, Setup); 10] = [
        ("5.14, 5.15", Model::Head, SPHERE),
        ("5.10, 5.16, 5.17", Model::Head, SPHERE_SMOOTH),
        ("5.19", Model::Head, OCTAHEDRON_SMOOTH),
        ("5.20", Model::Head, FLAT),
        ("", Model::Head, FLAT_SMOOTH),
        ("5.11, 5.13", Model::Pointed, SPHERE_SMOOTH),
        ("5.21", Model::Bumpy, FLAT_SMOOTH),
        ("5.22", Model::RoundedCube, FLAT_SMOOTH),
        ("5.23", Model::Peanut, FLAT_SMOOTH),
        ("5.24 (b)", Model::Head, FLAT_SMOOTH),
    ];
    let mut s = String::from(
        "| figure | scan | points | layout | smoothing | not star-shaped | holes | mean | RMS | max |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut line = |figure: &str, name: &str, scan: &Scan, setup: Setup| -> Result<()> {
        let result = fitted(scan, setup, true)?;
        let d = result.report.errors.context("the error was measured")?;
        // Sums in order, so that the page is the same on every run.
        let n = d.per_point.len() as f64;
        let mean = d.per_point.iter().sum::<f64>() / n / d.diagonal;
        let rms = (d.per_point.iter().map(|x| x * x).sum::<f64>() / n).sqrt() / d.diagonal;
        let max = d.per_point.iter().copied().fold(0.0, f64::max) / d.diagonal;
        let _ = writeln!(
            s,
            "| {figure} | {name} | {} | {:?} | {} | {:.1}% | {:.1}% | {mean:.1e} | {rms:.1e} | {max:.1e} |",
            scan.points.len(),
            setup.layout,
            if setup.smooth { "σ = 1" } else { "none" },
            100.0 * result.report.non_star_fraction,
            100.0 * result.report.hole_fraction,
        );
        Ok(())
    };
    for (figure, model, setup) in rows {
        let scan = if figure == "5.24 (b)" { coarse_head()? } else { scan(model)? };
        let name = if figure == "5.24 (b)" { "coarse head, resampled" } else { model.name() };
        line(figure, name, &scan, setup)?;
    }
    line(
        "5.24 (a)",
        "coarse head, vertices only",
        &coarse_head()?,
        Setup { densify: false, ..FLAT_SMOOTH },
    )?;
    Ok(s)
}
