// SPDX-License-Identifier: MIT
//! Binary glTF (`.glb`) figure files: written with `hi_mesh::export::write_glb` and read
//! back at once with the `gltf` crate, so that a model that does not read back as the mesh in
//! memory is an error of `cargo xtask figures`, not a file in `docs/figures/`.
//!
//! The read-back ([`check_read_back`]) parses the bytes, expects one mesh with one triangle
//! primitive, and compares its vertex count, positions, normals, UVs, colours and indices with
//! the mesh, each value to the f32 the file holds (bit for bit).
//!
//! The test `khronos_validator_accepts_every_figure` runs the Khronos glTF-Validator
//! (`xtask/peers/gltf-validator`, installed with `npm ci` there) on every `.glb` figure: 0 errors
//! and 0 warnings. Without node or the validator it says so and passes, unless
//! `HI_REQUIRE_PEERS=1`, when it fails.

use std::path::PathBuf;

use anyhow::{Context, Result, bail, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::TriangleMesh;

/// The `.glb` file of `mesh`, checked by reading it back.
///
/// # Errors
///
/// If writing fails or the file does not read back as `mesh` ([`check_read_back`]).
pub(crate) fn glb(mesh: &TriangleMesh) -> Result<Vec<u8>> {
    glb_with_edges(mesh, &[])
}

/// The `.glb` file of `mesh` with `edges` as a second primitive of lines
/// (`hi_mesh::export::write_glb_with_edges`), checked by reading it back.
///
/// # Errors
///
/// As [`glb`].
pub(crate) fn glb_with_edges(mesh: &TriangleMesh, edges: &[[u32; 2]]) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    hi_mesh::export::write_glb_with_edges(mesh, edges, &mut bytes).context("writing the GLB")?;
    check_read_back(mesh, edges, &bytes).context("reading the GLB back")?;
    Ok(bytes)
}

/// A polygon mesh drawn flat, with its polygons' outlines: each polygon keeps its own corners
/// with its Newell normal (the one plane that fits a non-planar polygon best) and is fanned into
/// triangles; the edges are each polygon's sides, by those corners (a side between two
/// polygons is listed by both), so a quad's diagonal is not among them. Polygons with no area
/// are left out.
///
/// # Errors
///
/// If no polygon is left or there are more than 2³² corners.
pub(crate) fn flat_with_edges(polygons: &[Vec<DVec3>]) -> Result<(TriangleMesh, Vec<[u32; 2]>)> {
    let (mut positions, mut normals, mut triangles, mut edges) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for polygon in polygons {
        let k = polygon.len();
        let newell: DVec3 = (0..k).map(|i| polygon[i].cross(polygon[(i + 1) % k])).sum();
        let Some(normal) = newell.try_normalize() else { continue };
        let base = u32::try_from(positions.len())?;
        let last = u32::try_from(k)? - 1;
        positions.extend(polygon);
        normals.extend(std::iter::repeat_n(normal, k));
        triangles.extend((1..last).map(|i| [base, base + i, base + i + 1]));
        edges.extend((0..=last).map(|i| [base + i, base + (i + 1) % (last + 1)]));
    }
    ensure!(!triangles.is_empty(), "no polygon with an area");
    let uvs = vec![DVec2::ZERO; positions.len()];
    Ok((TriangleMesh::try_new(positions, normals, uvs, triangles)?, edges))
}

/// Compares `values` read from the file with `expected` (f64 rounded to f32), bit for bit.
fn same<const N: usize>(
    what: &str,
    found: impl IntoIterator<Item = [f32; N]>,
    expected: impl IntoIterator<Item = [f32; N]>,
) -> Result<()> {
    let found: Vec<[f32; N]> = found.into_iter().collect();
    let expected: Vec<[f32; N]> = expected.into_iter().collect();
    ensure!(
        found.len() == expected.len(),
        "{what}: {} values in the file, {} in memory",
        found.len(),
        expected.len()
    );
    if let Some(i) =
        found.iter().zip(&expected).position(|(a, b)| a.map(f32::to_bits) != b.map(f32::to_bits))
    {
        bail!("{what} {i}: {:?} in the file, {:?} in memory", found[i], expected[i]);
    }
    Ok(())
}

/// Parses `bytes` with the `gltf` crate and checks that they hold `mesh`: one mesh with one
/// triangle primitive, the same number of vertices, and the same positions, normals, UVs,
/// colours (present exactly when the mesh has them) and indices, to f32; and, when `edges`
/// are given, a second primitive of lines with exactly those vertex pairs.
///
/// # Errors
///
/// If the bytes do not parse or differ from `mesh`; the message says where.
pub(crate) fn check_read_back(mesh: &TriangleMesh, edges: &[[u32; 2]], bytes: &[u8]) -> Result<()> {
    let (document, buffers, _images) = gltf::import_slice(bytes).context("parsing")?;
    let meshes: Vec<gltf::Mesh<'_>> = document.meshes().collect();
    ensure!(meshes.len() == 1, "{} meshes, expected 1", meshes.len());
    let primitives: Vec<gltf::Primitive<'_>> = meshes[0].primitives().collect();
    let expected = if edges.is_empty() { 1 } else { 2 };
    ensure!(primitives.len() == expected, "{} primitives, expected {expected}", primitives.len());
    if let Some(lines) = primitives.get(1) {
        ensure!(lines.mode() == gltf::mesh::Mode::Lines, "edge primitive mode {:?}", lines.mode());
        let reader = lines.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
        let found: Vec<u32> =
            reader.read_indices().context("no edge indices")?.into_u32().collect();
        let expected: Vec<u32> = edges.iter().flatten().copied().collect();
        ensure!(
            found == expected,
            "edges differ ({} indices in the file, {} in memory)",
            found.len(),
            expected.len()
        );
    }
    let primitive = &primitives[0];
    ensure!(
        primitive.mode() == gltf::mesh::Mode::Triangles,
        "primitive mode {:?}",
        primitive.mode()
    );
    let reader = primitive.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
    let positions: Vec<[f32; 3]> = reader.read_positions().context("no POSITION")?.collect();
    ensure!(
        positions.len() == mesh.n_vertices(),
        "{} vertices in the file, {} in memory",
        positions.len(),
        mesh.n_vertices()
    );
    same("position", positions, mesh.positions().iter().map(|p| p.as_vec3().to_array()))?;
    same(
        "normal",
        reader.read_normals().context("no NORMAL")?,
        mesh.normals().iter().map(|n| n.as_vec3().to_array()),
    )?;
    // A mesh with every UV at the origin is written without them.
    match reader.read_tex_coords(0) {
        Some(found) => {
            same("UV", found.into_f32(), mesh.uvs().iter().map(|t| t.as_vec2().to_array()))?
        }
        None => {
            ensure!(mesh.uvs().iter().all(|t| *t == DVec2::ZERO), "the mesh has UVs, the file none")
        }
    }
    match (reader.read_colors(0), mesh.colors()) {
        (Some(found), Some(expected)) => same("colour", found.into_rgb_f32(), expected.to_vec())?,
        (None, None) => {}
        (Some(_), None) => bail!("the file has colours, the mesh none"),
        (None, Some(_)) => bail!("the mesh has colours, the file none"),
    }
    let indices: Vec<u32> = reader.read_indices().context("no indices")?.into_u32().collect();
    let expected: Vec<u32> = mesh.triangles().iter().flatten().copied().collect();
    ensure!(
        indices == expected,
        "indices differ ({} in the file, {} in memory)",
        indices.len(),
        expected.len()
    );
    Ok(())
}

/// The validator's directory, or why it cannot run.
pub(crate) fn validator() -> Result<PathBuf, String> {
    let dir = crate::project_root().join("xtask/peers/gltf-validator");
    if !dir.join("node_modules/gltf-validator").is_dir() {
        return Err(
            "gltf-validator is not installed (run `npm ci` in xtask/peers/gltf-validator)".into()
        );
    }
    match std::process::Command::new("node").arg("--version").output() {
        Ok(o) if o.status.success() => Ok(dir),
        Ok(o) => {
            Err(format!("node --version failed: {}", String::from_utf8_lossy(&o.stderr).trim()))
        }
        Err(e) => Err(format!("node is not usable: {e}")),
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;
    use std::process::Command;

    use super::super::{Format, registry};
    use super::*;

    #[test]
    fn flat_polygons_keep_their_sides_and_not_their_diagonals() {
        // A unit square (in z = 0) and a triangle standing on its side y = 0.
        let square = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        let triangle = vec![DVec3::ZERO, DVec3::new(0.5, 0.0, 1.0), DVec3::X];
        let (mesh, edges) = flat_with_edges(&[square, triangle]).expect("flat");
        assert_eq!(mesh.n_vertices(), 7, "each polygon its own corners");
        assert_eq!(mesh.n_triangles(), 3);
        assert_eq!(edges, [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 4]]);
        assert!(mesh.normals()[..4].iter().all(|n| *n == DVec3::Z), "the square faces +z");
        // (b − a) × (c − a) = (0.5, 0, 1) × (1, 0, 0) = (0, 1, 0).
        assert!(mesh.normals()[4..].iter().all(|n| *n == DVec3::Y), "the triangle faces +y");
        let bytes = glb_with_edges(&mesh, &edges).expect("reads back with its lines");
        let error = check_read_back(&mesh, &edges[..6], &bytes).expect_err("an edge short");
        assert!(error.to_string().contains("edges differ"), "{error}");
        assert!(flat_with_edges(&[vec![DVec3::ZERO, DVec3::X, DVec3::X]]).is_err(), "no area");
    }

    #[test]
    fn a_changed_file_does_not_read_back() {
        let mesh = hi_surface::torus(2.0, 1.0)
            .to_mesh(&hi_surface::MeshOptions { n_u: 4, n_v: 6, ..Default::default() })
            .expect("meshes");
        let bytes = glb(&mesh).expect("reads back");
        let other = hi_surface::torus(2.0, 0.9)
            .to_mesh(&hi_surface::MeshOptions { n_u: 4, n_v: 6, ..Default::default() })
            .expect("meshes");
        let error = check_read_back(&other, &[], &bytes).expect_err("another mesh");
        assert!(error.to_string().contains("position"), "{error}");
        let error = check_read_back(&mesh, &[], &bytes[..bytes.len() - 8]).expect_err("truncated");
        assert!(error.to_string().contains("parsing"), "{error}");
    }

    #[test]
    fn khronos_validator_accepts_every_figure() {
        let required = std::env::var("HI_REQUIRE_PEERS").is_ok_and(|v| v == "1");
        let dir = match validator() {
            Ok(dir) => dir,
            Err(why) => {
                assert!(
                    !required,
                    "HI_REQUIRE_PEERS=1 but the glTF validator is not usable: {why}"
                );
                eprintln!("glTF validator check of the figures skipped: {why}");
                return;
            }
        };
        let out = std::env::temp_dir().join(format!("harmonic-figures-{}", std::process::id()));
        std::fs::create_dir_all(&out).expect("a temporary directory");
        let mut files = Vec::new();
        for figure in registry().into_iter().filter(|f| f.format == Format::Glb) {
            for panel in figure.panels {
                let bytes = (panel.draw)(&figure.title(panel)).expect("the figure draws");
                let path = out.join(figure.file(panel));
                std::fs::write(&path, bytes).expect("the file is written");
                files.push(path);
            }
        }
        assert!(!files.is_empty(), "no .glb figures");
        let output = Command::new("node")
            .arg(Path::new(&dir).join("validate.js"))
            .args(&files)
            .output()
            .expect("node runs");
        let _ = std::fs::remove_dir_all(&out);
        let stdout = String::from_utf8_lossy(&output.stdout);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            output.status.success(),
            "the validator found errors or warnings:\n{stdout}{stderr}"
        );
        let summaries: Vec<&str> = stdout.lines().filter(|l| l.contains(": validator ")).collect();
        assert_eq!(summaries.len(), files.len(), "one report per file:\n{stdout}");
        for line in &summaries {
            assert!(line.contains(" errors=0 warnings=0 "), "{line}");
        }
        // The one note expected: UVs that no texture uses.
        for line in stdout.lines().filter(|l| l.starts_with("  [")) {
            assert!(
                line.contains("[INFO] UNUSED_OBJECT /meshes/0/primitives/0/attributes/TEXCOORD_0"),
                "{line}"
            );
        }
        eprintln!("glTF validator: {} figure files, 0 errors, 0 warnings", files.len());
    }
}
