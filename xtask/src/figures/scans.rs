// SPDX-License-Identifier: MIT
//! Figures 5.10, 5.11 and 5.13–5.24: scans fitted through geometry images (§5.3, §5.4) — the
//! images themselves as PNG, the surfaces they make (texels joined directly, and harmonic
//! interpolation of them) as glTF models, before and after smoothing, in the spherical,
//! octahedral and flattened-octahedral layouts — and a table of how well each fits its scan.
//!
//! The thesis's scans (Hoppe's mannequin head, Spock, and the public models of figures
//! 5.21–5.24) are not available. Lee Perry-Smith's head scan (`fixtures/models`, CC BY 3.0)
//! stands in for the mannequin ([`head_point`]: the scan's farthest point along each direction
//! from the head's centre, the neck closed by a plane) and, with Spock's pointed ears added, for
//! Spock, each sampled with 60 000 points along a Fibonacci lattice of directions and given a
//! deterministic noise of ±0.3% of its size along the direction from its centre, as a scanner
//! would. Figures 5.21–5.23 pair the vertices of real models of `fixtures/models` (Spot, a duck,
//! Wuson) with their surfaces as `hi fit` makes them; figure 5.24 fits Spot by the thesis's rays
//! from its vertices alone, too few for them, and resampled on its triangles as the thesis did.
//! `cargo xtask bench fit` fits more real models (Table 5.1).

use std::f64::consts::{PI, TAU};
use std::fmt::Write as _;
use std::io::Cursor;
use std::sync::OnceLock;

use anyhow::{Context, Result, ensure};
use glam::{DMat3, DVec2, DVec3};
use hi_geomimage::{ErrorMeasure, Fit, FitOptions, GeometryImage, Layout, Smoothing, fit};
use hi_mesh::TriangleMesh;
use hi_scan::scan::Scan;
use hi_surface::{HarmonicSurface, MeshOptions};
use rayon::prelude::*;

use super::glb::glb;
use super::{Figure, Format, Panel, Table};
use hi_surface::{ParamRange, ParamWindow};

/// Rows and columns of every geometry image here.
const IMAGE: usize = 64;
/// Points of each scan.
const SCAN_POINTS: usize = 60_000;
/// The scanner noise: ± this fraction of the scan's mean radius, along the ray from its centre.
const NOISE: f64 = 0.003;
/// σ of the Gaussian smoothing (in texels) of the "after smoothing" figures.
const SIGMA: f64 = 1.0;
/// Each texel of a PNG geometry image is a square of this many pixels.
const PIXELS_PER_TEXEL: u32 = 4;

/// The scans of this module.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Model {
    /// The head scan (standing in for the mannequin), [`head_point`].
    Head,
    /// The head with pointed ears (Spock).
    Pointed,
}

impl Model {
    const fn name(self) -> &'static str {
        match self {
            Self::Head => "head scan (mannequin stand-in)",
            Self::Pointed => "head scan with pointed ears (Spock stand-in)",
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

/// `n` directions spread evenly over the unit sphere ([`hi_testkit::fibonacci_sphere`]).
fn directions(n: usize) -> impl Iterator<Item = DVec3> {
    hi_testkit::fibonacci_sphere(n).map(DVec3::from)
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

/// The scan of a model.
fn scan(model: Model) -> Result<Scan> {
    let (head, pointed) = (radial_head()?, model == Model::Pointed);
    let points = directions(SCAN_POINTS).map(|d| head_point(head, d, pointed)).collect();
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

/// Lee Perry-Smith's head scan in `fixtures/models` (Infinite Realities, CC BY 3.0; see its
/// `SOURCES.md`): a closed bust, +y up, facing +z.
const HEAD_FILE: &str = "lee-perry-smith-head.obj";

/// The scan's centre inside the head (in the file's coordinates), from which its radius is
/// taken, and the scale to the figures' size (about 1.7 wide, 2.2 deep, 2.2 high).
const HEAD_CENTRE: DVec3 = DVec3::new(0.0, 0.0, -0.07);
const HEAD_SCALE: f64 = 9.0;

/// The height (the file's y) below which the bust is left out: the neck under the chin, where
/// the shoulders begin; the head is closed there by the plane.
const NECK: f64 = -0.13;

/// Rows (θ from the crown, 0..=π) and columns (φ, a full turn) of the head's radius table.
const HEAD_ROWS: usize = 360;
const HEAD_COLS: usize = 720;

/// The head's radius from [`HEAD_CENTRE`] (in the figures' units) at the nodes of a
/// (θ, φ) grid of [`HEAD_ROWS`] + 1 rows and [`HEAD_COLS`] columns, θ from +z and φ from +x
/// towards +y in the figures' frame (+z up, facing +y).
struct RadialHead(Vec<f64>);

/// The figures' frame (x right, y the way the face looks, z up) to the file's (y up, facing
/// +z): a rotation.
fn to_file(d: DVec3) -> DVec3 {
    DVec3::new(-d.x, d.z, d.y)
}

impl RadialHead {
    /// The table, ray cast once: along each direction the farthest point of the scan above
    /// [`NECK`] (a ray from outside towards the centre, its first hit), or the plane at the
    /// neck where the ray leaves through it.
    fn load() -> Result<Self> {
        let path = crate::project_root().join("fixtures/models").join(HEAD_FILE);
        let scan =
            hi_scan::scan::read_scan(&path).with_context(|| format!("reading {HEAD_FILE}"))?;
        let above = |k: u32| scan.points[k as usize].y >= NECK;
        let triangles: Vec<[u32; 3]> =
            scan.triangles.iter().copied().filter(|t| t.iter().all(|&k| above(k))).collect();
        ensure!(triangles.len() > 1000, "{HEAD_FILE}: too few triangles above the neck");
        let mesh = hi_raytrace::MeshObject::new(TriangleMesh::from_triangles(
            scan.points.clone(),
            triangles,
        )?);
        let far = 1.0;
        let table = (0..=HEAD_ROWS)
            .into_par_iter()
            .flat_map_iter(|i| (0..HEAD_COLS).map(move |j| (i, j)))
            .map(|(i, j)| {
                let (theta, phi) =
                    (PI * i as f64 / HEAD_ROWS as f64, TAU * j as f64 / HEAD_COLS as f64);
                let d = to_file(DVec3::new(
                    theta.sin() * phi.cos(),
                    theta.sin() * phi.sin(),
                    theta.cos(),
                ));
                let ray = hi_raytrace::Ray {
                    t_max: far,
                    ..hi_raytrace::Ray::new(HEAD_CENTRE + d * far, -d)
                };
                match mesh.intersect(&ray) {
                    Some((_, hit)) => Ok((far - hit.t) * HEAD_SCALE),
                    None if d.y < 0.0 => Ok((HEAD_CENTRE.y - NECK) / -d.y * HEAD_SCALE),
                    None => Err(anyhow::anyhow!(
                        "{HEAD_FILE}: a ray from the head's centre up meets no triangle"
                    )),
                }
            })
            .collect::<Result<Vec<f64>>>()?;
        Ok(Self(table))
    }

    /// The radius in the unit direction `dir` (figures' frame), bilinear in (θ, φ).
    fn radius(&self, dir: DVec3) -> f64 {
        let theta = dir.z.clamp(-1.0, 1.0).acos() / PI * HEAD_ROWS as f64;
        let phi = dir.y.atan2(dir.x).rem_euclid(TAU) / TAU * HEAD_COLS as f64;
        #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "in the table")]
        let (i, j) =
            ((theta.floor() as usize).min(HEAD_ROWS - 1), phi.floor() as usize % HEAD_COLS);
        let (a, b) = (theta - i as f64, phi - phi.floor());
        let at = |i: usize, j: usize| self.0[i * HEAD_COLS + j % HEAD_COLS];
        (1.0 - a) * ((1.0 - b) * at(i, j) + b * at(i, j + 1))
            + a * ((1.0 - b) * at(i + 1, j) + b * at(i + 1, j + 1))
    }
}

/// The head, tabulated once per run ([`RadialHead::load`]).
fn radial_head() -> Result<&'static RadialHead> {
    static HEAD: OnceLock<std::result::Result<RadialHead, String>> = OnceLock::new();
    HEAD.get_or_init(|| RadialHead::load().map_err(|e| format!("{e:#}")))
        .as_ref()
        .map_err(|e| anyhow::anyhow!("{e}"))
}

/// The head: the point of its surface in the unit direction `dir` (star-shaped about its
/// centre, as the thesis's algorithm 2 needs, since each direction keeps the scan's farthest
/// point), facing +y with +z up: Lee Perry-Smith's head scan ([`RadialHead`]). With `pointed`,
/// Spock's ears: each ear's rim drawn up and back to a point well above it (two bumps of the
/// radius, [`bump`], over the ear, whose middle lies in the direction (±0.97, −0.2, −0.19),
/// measured on the scan).
fn head_point(head: &RadialHead, dir: DVec3, pointed: bool) -> DVec3 {
    let v = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
    let mut r = head.radius(dir);
    if pointed {
        for side in [-1.0, 1.0] {
            r += bump(dir, v(side, -0.3, 0.12), (0.11, 0.2), 0.3, 1);
            r += bump(dir, v(side, -0.38, 0.36), (0.08, 0.13), 0.38, 1);
        }
    }
    dir * r
}

/// The control mesh of the head (figures 1.1 and 4.35): the geodesic sphere of
/// [`CONTROL_LEVELS`] cuts of the octahedron (512 triangles, 258 vertices), its directions drawn
/// towards the face by a conformal zoom ([`FACE_ZOOM`]), each vertex on the head's surface along
/// its direction ([`head_point`]): a coarse closed triangle mesh of Lee Perry-Smith's head, as
/// the thesis's control mesh of the mannequin was coarse.
pub(crate) fn head_control() -> Result<(Vec<DVec3>, Vec<[u32; 3]>)> {
    let head = radial_head()?;
    let (directions, faces) = super::surfaces::geodesic(CONTROL_LEVELS);
    let points = directions.into_iter().map(|d| head_point(head, toward_face(d), false)).collect();
    Ok((points, faces))
}

/// Cuts of the octahedron in the head's control mesh ([`head_control`]).
const CONTROL_LEVELS: u32 = 3;

/// The scale of the stereographic plane from the back of the head (−y) in [`toward_face`]: the
/// face's vertices 1/0.6² = 2.8 times as dense as on the sphere, the back's as much sparser,
/// every triangle's shape kept (the map is conformal).
const FACE_ZOOM: f64 = 0.6;

/// The unit direction `d` moved towards the face (+y): projected stereographically from −y onto
/// the plane y = 0, scaled by [`FACE_ZOOM`] and projected back; −y itself stays.
fn toward_face(d: DVec3) -> DVec3 {
    let lift = 1.0 + d.y;
    if lift <= 1e-12 {
        return d;
    }
    let (a, b) = (FACE_ZOOM * d.x / lift, FACE_ZOOM * d.z / lift);
    let r2 = a * a + b * b;
    DVec3::new(2.0 * a, 1.0 - r2, 2.0 * b) / (1.0 + r2)
}

/// The scan of the head (standing in for the mannequin), or of the head with pointed ears (Spock).
pub(crate) fn head_scan(pointed: bool) -> Result<Scan> {
    scan(if pointed { Model::Pointed } else { Model::Head })
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

/// [`fitted`] on a head's `scan`. For the octahedral layouts the head is fitted turned to
/// look up (+z, [`FACE_UP`]): the face then lies about the layout's centre, and the seams of the
/// octahedron's lower half, where its unfolding folds, run over the back of the head rather than
/// down the nose and mouth; the fitted surfaces are turned back (a harmonic surface turns with its
/// grid), the images stay as fitted.
fn fitted_head(scan: Scan, setup: Setup, measure: bool) -> Result<Fit> {
    if !matches!(setup.layout, Layout::Octahedron | Layout::FlatOctahedron) {
        return fitted(&scan, setup, measure);
    }
    let mut result = fitted(&face_up(scan), setup, measure)?;
    for part in &mut result.parts {
        part.surface = turned_back(&part.surface)?;
    }
    Ok(result)
}

/// The scan of a head turned to look up ([`FACE_UP`]).
pub(crate) fn face_up(scan: Scan) -> Scan {
    Scan { points: scan.points.iter().map(|p| FACE_UP * *p).collect(), ..scan }
}

/// A surface fitted to [`face_up`]'s scan turned back to the head's frame: a harmonic surface
/// turns with its grid.
pub(crate) fn turned_back(surface: &HarmonicSurface<DVec3>) -> Result<HarmonicSurface<DVec3>> {
    let back = surface.points().iter().map(|p| FACE_UP.transpose() * *p).collect();
    Ok(HarmonicSurface::try_from_flat(surface.m(), surface.n(), back)?)
}

/// The quarter turn about x that takes the head's face (+y) to +z ([`fitted_head`]).
const FACE_UP: DMat3 = DMat3::from_cols(DVec3::X, DVec3::Z, DVec3::NEG_Y);

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
    let result = fitted_head(scan(model)?, setup, false)?;
    glb(&covering_mesh(&result.largest().surface, setup.layout, 2)?)
}

/// The image size of the real models' fits: below what `hi fit` picks for them, so that each
/// figure file stays under a megabyte (the scans themselves live in
/// `fixtures/models`).
const REAL_IMAGE: (usize, usize) = (160, 160);

/// The real model `file` of `fixtures/models`, stood up and turned to the viewer: its files
/// have +y up and face −z, the figures have +z up and are seen from −y.
fn real_scan(file: &str) -> Result<Scan> {
    let path = crate::project_root().join("fixtures/models").join(file);
    let scan = hi_scan::scan::read_scan(&path).with_context(|| format!("reading {file}"))?;
    let points = scan.points.iter().map(|p| DVec3::new(-p.x, p.z, p.y)).collect();
    Ok(Scan { points, ..scan })
}

/// The data set of figure `number`: the points of the real model `file` (the vertices its
/// triangles use), each a small ball, seen as its surface is ([`real_glb`]).
fn real_points(number: (u32, u32), file: &str) -> Result<Vec<u8>> {
    super::renders::render_points(number, &used_points(&real_scan(file)?), 0.0035)
}

/// The points of `scan` its triangles use (all of them for a point set).
pub(crate) fn used_points(scan: &Scan) -> Vec<DVec3> {
    let mut used = vec![scan.triangles.is_empty(); scan.points.len()];
    for &k in scan.triangles.iter().flatten() {
        used[k as usize] = true;
    }
    scan.points.iter().zip(&used).filter(|(_, u)| **u).map(|(p, _)| *p).collect()
}

/// The fit of the real model `file` of `fixtures/models` ([`real_scan`]) by
/// `hi fit`'s defaults (the parameterisation of each part of its mesh, no smoothing) at
/// [`REAL_IMAGE`] (shared by the parts by area), meshed as `hi fit` writes them: one vertex per
/// texel, welded into closed surfaces checked to enclose a positive volume (wound outwards), or
/// open sheets; the parts in one mesh, without texture coordinates (each part's would be of its
/// own domain, meaningless in one mesh, and the wuson's 42 parts would take the file past a
/// megabyte).
fn real_glb(file: &str) -> Result<Vec<u8>> {
    let result = real_fit(&real_scan(file)?, file, false)?;
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
        uvs.extend(std::iter::repeat_n(DVec2::ZERO, mesh.positions().len()));
        triangles.extend(mesh.triangles().iter().map(|t| t.map(|k| k + offset)));
    }
    glb(&TriangleMesh::try_new(positions, normals, uvs, triangles)?)
}

/// The fit of [`real_glb`] of the scan of `file`, its error measured when `measure`.
fn real_fit(scan: &Scan, file: &str, measure: bool) -> Result<Fit> {
    let options = FitOptions {
        resolution: Some(REAL_IMAGE),
        error: if measure { ErrorMeasure::Sampled(4) } else { ErrorMeasure::Off },
        ..FitOptions::default()
    };
    let result = fit(scan, &options, &mut |_| {})?;
    ensure!(
        result.report.method == hi_geomimage::Method::Mesh,
        "{file}: fitted by {}, not by its mesh ({})",
        result.report.method.name(),
        result.report.method_reason
    );
    Ok(result)
}

/// The texels of a fit's image joined directly: one quad per texel, with normals from the
/// faces (what the geometry image gives without harmonic interpolation).
fn texel_glb(model: Model, setup: Setup) -> Result<Vec<u8>> {
    let result = fitted_head(scan(model)?, setup, false)?;
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
    let result = fitted_head(scan(model)?, setup, false)?;
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
    p.y > 0.4 && p.z > -1.0 && p.z < 0.45 && p.x.abs() < 0.55
}

/// The close-up of the face of the head model `glb` (a figure's panel (b)).
fn close_up(glb: &[u8]) -> Result<Vec<u8>> {
    super::renders::render_close_up(glb, on_face)
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

/// The model of figure 5.24, whose vertices are too few for the rays of a 64×64 image: Spot
/// (2 930 vertices), the thesis's cow.
const RESAMPLED: &str = "spot.obj";

/// Figure 5.24: [`RESAMPLED`] fitted by the thesis's rays from its vertices alone, or resampled
/// on its triangles first (`densify`).
fn resampled_glb(densify: bool) -> Result<Vec<u8>> {
    let setup = Setup { densify, ..FLAT_SMOOTH };
    let result = fitted(&real_scan(RESAMPLED)?, setup, false)?;
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
        data: "stand-in for the thesis's mannequin scan (not available): 60 000 points on Lee Perry-Smith's head \
               scan (Infinite Realities, CC BY 3.0; `fixtures/models/lee-perry-smith-head.obj`), the farthest point \
               of the scan along each direction from the head's centre, the neck closed by a plane, with ±0.3% \
               noise along the rays.",
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
        data: "stand-in for the thesis's Spock scan (not available): 60 000 points on the head scan of figure 5.10 \
               with Spock's ears drawn up to a point above each ear, with ±0.3% noise along the rays.",
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
        data: "the head scan with pointed ears of figure 5.11 (Spock stand-in).",
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
        data: "the head scan of figure 5.10 (mannequin stand-in).",
        format: Format::Glb,
        views: &[Panel {
            suffix: "b",
            title: "(b) Close-up",
            draw: |_| close_up(&texel_glb(Model::Head, SPHERE)?),
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
        data: "the head scan of figure 5.10 (mannequin stand-in).",
        format: Format::Glb,
        views: &[Panel {
            suffix: "b",
            title: "(b) Close-up",
            draw: |_| close_up(&harmonic_glb(Model::Head, SPHERE)?),
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
        data: "the head scan of figure 5.10 (mannequin stand-in).",
        format: Format::Glb,
        views: &[Panel {
            suffix: "b",
            title: "(b) Close-up",
            draw: |_| close_up(&texel_glb(Model::Head, SPHERE_SMOOTH)?),
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
        data: "the head scan of figure 5.10 (mannequin stand-in).",
        format: Format::Glb,
        views: &[Panel {
            suffix: "b",
            title: "(b) Close-up",
            draw: |_| close_up(&harmonic_glb(Model::Head, SPHERE_SMOOTH)?),
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
        data: "the head scan of figure 5.10 (mannequin stand-in).",
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
                leave seams, as in the thesis; the head is fitted turned to look up, so that the face lies about \
                the layout's centre and the seams of the octahedron's lower half run over the back of the head.",
        data: "the head scan of figure 5.10 (mannequin stand-in).",
        format: Format::Glb,
        views: &[Panel {
            suffix: "d",
            title: "(d) Close-up",
            draw: |_| close_up(&harmonic_glb(Model::Head, OCTAHEDRON_SMOOTH)?),
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
        data: "the head scan of figure 5.10 (mannequin stand-in).",
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
        drawn: "(a) The data set: the model's vertices, each a small ball. (b) The harmonic surface fitted to Keenan \
                Crane's Spot (a cow) by `hi fit`'s defaults: the mesh closed, \
                mapped onto the sphere without folds, sampled as a 160×160 geometry image (smaller than `hi fit` \
                picks, to keep the files small) and interpolated, with no smoothing; meshed as `hi fit` writes it (one vertex per texel, welded, closed). Horns, ears and legs \
                are reached, which the thesis's rays from a centre could not.",
        data: "`fixtures/models/spot.obj` (public domain; 2 930 vertices), the thesis's cow among its models.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "a",
            title: "(a) Data set",
            draw: |_| real_points((5, 21), "spot.obj"),
        }],
        panels: &[Panel { suffix: "b", title: "(b) Surface", draw: |_| real_glb("spot.obj") }],
    },
    Figure {
        number: (5, 22),
        caption: "Surface fitting using harmonic tensor product surfaces",
        drawn: "As figure 5.21 for a duck, (a) its vertices and (b) its surface, whose bill and tail are not star-shaped about any centre. The open bill's \
                halves are thinner than a texel of the 160×160 image at their rims, which come out serrated.",
        data: "`fixtures/models/duck.obj` (MIT; 10 093 vertices), the thesis's duck among its models.",
        format: Format::Glb,
        views: &[Panel {
            suffix: "a",
            title: "(a) Data set",
            draw: |_| real_points((5, 22), "duck.obj"),
        }],
        panels: &[Panel { suffix: "b", title: "(b) Surface", draw: |_| real_glb("duck.obj") }],
    },
    Figure {
        number: (5, 23),
        caption: "Surface fitting using harmonic tensor product surfaces",
        drawn: "As figure 5.21 for Wuson, a four-legged cartoon animal in 54 pieces, (a) its vertices and (b) its \
                surface: every piece of at least 0.05 % \
                of its area is fitted on its own (the body over the sphere, the pieces that are open shells as open \
                sheets), the specks below that left out, as `hi fit` reports.",
        data: "`fixtures/models/wuson.off` (BSD-3-Clause; 3 205 vertices), in place of the thesis's bunny (whose \
               licence does not allow it here).",
        format: Format::Glb,
        views: &[Panel {
            suffix: "a",
            title: "(a) Data set",
            draw: |_| real_points((5, 23), "wuson.off"),
        }],
        panels: &[Panel { suffix: "b", title: "(b) Surface", draw: |_| real_glb("wuson.off") }],
    },
    Figure {
        number: (5, 24),
        caption: "Surface fitting using harmonic tensor product surfaces of resampled data set",
        drawn: "(a) Spot's mesh (2 930 vertices) fitted by the thesis's rays from its centre (algorithm 2) through a \
                64×64 flattened-octahedron image from its vertices alone, smoothed by a Gaussian of σ = 1 texel: \
                some rays find too few points and their texels are filled from their neighbours; (b) the same mesh \
                resampled with 200 000 points on its triangles first, as the thesis did for models with few points \
                (the table below gives both fractions of rays). The legs, horns and ears are not star-shaped about \
                the centre: the rays meet them more than once, and the surface through one shell per ray rounds \
                them off, as the thesis's did.",
        data: "`fixtures/models/spot.obj` (public domain; 2 930 vertices), the thesis's cow among its resampled \
               models.",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Vertices only", draw: |_| resampled_glb(false) },
            Panel { suffix: "b", title: "(b) Resampled", draw: |_| resampled_glb(true) },
        ],
    },
];

/// The table of the fits.
pub(crate) const TABLES: &[Table] = &[Table {
    anchor: "scan-fits",
    title: "Fits of the scans of figures 5.10–5.24",
    about: "Each scan fitted as its figure says (`hi_geomimage::fit`): the heads and Spot in 5.24 through a 64×64 \
            geometry image by the thesis's rays, 5.21–5.23 by their meshes' own parameterisation (`hi fit`'s \
            defaults at 160×160); the fraction of rays that met several shells (not star-shaped) or too few points \
            (holes, filled from their neighbours), and the distances from every scan point to the harmonic surface \
            (mean, RMS, max) relative to the diagonal of the scan's bounding box. Smoothing trades distance for fewer undulations; the \
            octahedron's seams show in its maximum.",
    make: table,
}];

/// Computes the table.
fn table() -> Result<String> {
    let rows: [(&str, Model, Setup); 6] = [
        ("5.14, 5.15", Model::Head, SPHERE),
        ("5.10, 5.16, 5.17", Model::Head, SPHERE_SMOOTH),
        ("5.19", Model::Head, OCTAHEDRON_SMOOTH),
        ("5.20", Model::Head, FLAT),
        ("", Model::Head, FLAT_SMOOTH),
        ("5.11, 5.13", Model::Pointed, SPHERE_SMOOTH),
    ];
    let mut s = String::from(
        "| figure | scan | points | layout | smoothing | not star-shaped | holes | mean | RMS | max |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut line = |figure: &str,
                    name: &str,
                    points: usize,
                    result: &Fit,
                    layout: &str,
                    smooth: bool|
     -> Result<()> {
        let d = result.report.errors.as_ref().context("the error was measured")?;
        // Sums in order, so that the page is the same on every run.
        let n = d.per_point.len() as f64;
        let mean = d.per_point.iter().sum::<f64>() / n / d.diagonal;
        let rms = (d.per_point.iter().map(|x| x * x).sum::<f64>() / n).sqrt() / d.diagonal;
        let max = d.per_point.iter().copied().fold(0.0, f64::max) / d.diagonal;
        let _ = writeln!(
            s,
            "| {figure} | {name} | {points} | {layout} | {} | {:.1}% | {:.1}% | {mean:.1e} | {rms:.1e} | {max:.1e} |",
            if smooth { "σ = 1" } else { "none" },
            100.0 * result.report.non_star_fraction,
            100.0 * result.report.hole_fraction,
        );
        Ok(())
    };
    for (figure, model, setup) in rows {
        let scan = scan(model)?;
        let points = scan.points.len();
        let result = fitted_head(scan, setup, true)?;
        line(figure, model.name(), points, &result, &format!("{:?}", setup.layout), setup.smooth)?;
    }
    for (figure, file) in [("5.21", "spot.obj"), ("5.22", "duck.obj"), ("5.23", "wuson.off")] {
        let scan = real_scan(file)?;
        let result = real_fit(&scan, file, true)?;
        let name = format!(
            "{file}, its mesh parameterised (`hi fit`'s defaults, {}×{})",
            REAL_IMAGE.0, REAL_IMAGE.1
        );
        line(figure, &name, scan.points.len(), &result, "mesh's own", false)?;
    }
    let spot = real_scan(RESAMPLED)?;
    for (figure, densify, what) in
        [("5.24 (a)", false, "vertices only"), ("5.24 (b)", true, "resampled")]
    {
        let setup = Setup { densify, ..FLAT_SMOOTH };
        let result = fitted(&spot, setup, true)?;
        let name = format!("{RESAMPLED}, {what}");
        line(
            figure,
            &name,
            spot.points.len(),
            &result,
            &format!("{:?}", setup.layout),
            setup.smooth,
        )?;
    }
    Ok(s)
}
