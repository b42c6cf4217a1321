// SPDX-License-Identifier: MIT
//! Wavefront OBJ: `v`, `vt`, `vn` and `f a/a/a b/b/b c/c/c` lines (Hardy 2005, §5.5: the
//! surface as polygons), read back with `tobj`.

use std::io::{BufWriter, Write};

use super::{GENERATOR, NamedMesh, check_scene, io_error};
use crate::colormap::linear_to_srgb_rgb;
use crate::{Error, TriangleMesh};

/// Writes `mesh` as OBJ: positions (with sRGB vertex colours as `v x y z r g b` when the mesh
/// has colours), UVs as `vt s 1−t`, normals, and one `f` line per triangle. Numbers are the f32
/// values, printed so that they parse back to the same f32.
///
/// # Errors
///
/// [`Error::Io`](crate::Error::Io) when writing fails.
///
/// # Examples
///
/// ```
/// use glam::{DVec2, DVec3};
/// use hi_mesh::{TriangleMesh, export};
///
/// // One unit square of two triangles, facing +z.
/// let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
/// let uv = p.iter().map(|q| q.truncate()).collect::<Vec<DVec2>>();
/// let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 4], uv, vec![[0, 1, 2], [0, 2, 3]])?;
/// let mut out = Vec::new();
/// export::write_obj(&mesh, &mut out)?;
/// let text = String::from_utf8(out).unwrap();
/// assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 4);
/// assert!(text.contains("\nf 1/1/1 2/2/2 3/3/3\nf 1/1/1 3/3/3 4/4/4\n"));
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn write_obj<W: Write>(mesh: &TriangleMesh, writer: W) -> Result<(), Error> {
    write_parts(&[NamedMesh::new(SINGLE_NAME, mesh)], writer)
}

/// Writes the parts of a scene as one OBJ file, each an object (`o name`) of its own with its
/// vertices, UVs, normals and faces as [`write_obj`] writes them; the faces' indices count
/// from the first vertex of the file.
///
/// # Errors
///
/// Those of [`check_part_names`](super::check_part_names) (no parts, a name empty, repeated
/// or not printable on one line); [`Error::InvalidPart`] when some parts have vertex colours
/// and others do not (OBJ gives colours to every vertex or to none; glTF keeps them per part);
/// [`Error::Io`](crate::Error::Io) when writing fails.
///
/// # Examples
///
/// ```
/// use glam::{DVec2, DVec3};
/// use hi_mesh::export::{self, NamedMesh};
/// use hi_mesh::TriangleMesh;
///
/// // One triangle, and the same one a unit higher.
/// let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
/// let (n, uv) = (vec![DVec3::Z; 3], vec![DVec2::ZERO, DVec2::X, DVec2::Y]);
/// let low = TriangleMesh::try_new(p.clone(), n.clone(), uv.clone(), vec![[0, 1, 2]])?;
/// let p = p.iter().map(|q| *q + DVec3::Z).collect();
/// let high = TriangleMesh::try_new(p, n, uv, vec![[0, 1, 2]])?;
/// let mut out = Vec::new();
/// let parts = [NamedMesh::new("low", &low), NamedMesh::new("high", &high)];
/// export::write_scene_obj(&parts, &mut out)?;
/// let text = String::from_utf8(out).unwrap();
/// assert!(text.contains("o low\n") && text.contains("o high\n"));
/// // The second object's vertices are numbered after the first's.
/// assert!(text.ends_with("f 4/4/4 5/5/5 6/6/6\n"));
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn write_scene_obj<W: Write>(parts: &[NamedMesh<'_>], writer: W) -> Result<(), Error> {
    check_scene(parts)?;
    write_parts(parts, writer)
}

/// The object name of a single mesh written as OBJ.
pub(super) const SINGLE_NAME: &str = "harmonic_surface";

/// Writes `parts` (names not checked) as OBJ objects: the one writer behind [`write_obj`],
/// [`write_scene_obj`] and [`super::save`].
pub(super) fn write_parts<W: Write>(parts: &[NamedMesh<'_>], writer: W) -> Result<(), Error> {
    check_colors(parts)?;
    write(parts, &mut BufWriter::new(writer)).map_err(|e| io_error(&e, None))
}

/// An error naming a part without vertex colours when another part has them: tobj, like other
/// readers, numbers colours with the positions, so a file's `v` lines must all have colours or
/// none have.
pub(super) fn check_colors(parts: &[NamedMesh<'_>]) -> Result<(), Error> {
    if let Some(colored) = parts.iter().position(|p| p.mesh.colors().is_some())
        && let Some(plain) = parts.iter().position(|p| p.mesh.colors().is_none())
    {
        return Err(Error::InvalidPart {
            part: plain,
            name: parts[plain].name.to_owned(),
            problem: format!(
                "it has no vertex colours but part {colored} ({:?}) has; an OBJ file gives \
                 colours to every vertex or to none (colour every part, or write glTF)",
                parts[colored].name
            ),
        });
    }
    Ok(())
}

fn write<W: Write>(parts: &[NamedMesh<'_>], w: &mut BufWriter<W>) -> std::io::Result<()> {
    let n_vertices: usize = parts.iter().map(|p| p.mesh.n_vertices()).sum();
    let n_triangles: usize = parts.iter().map(|p| p.mesh.n_triangles()).sum();
    writeln!(w, "# {GENERATOR}")?;
    writeln!(w, "# {n_vertices} vertices, {n_triangles} triangles")?;
    writeln!(w, "# vt = (s, 1 - t) of the glTF texture coordinates; vertex colours are sRGB")?;
    // OBJ numbers vertices from 1 across the whole file.
    let mut first = 1;
    for &NamedMesh { name, mesh } in parts {
        writeln!(w, "o {name}")?;
        let colors = mesh.colors();
        for (k, p) in mesh.positions().iter().enumerate() {
            let [x, y, z] = p.as_vec3().to_array();
            match colors {
                Some(c) => {
                    let [r, g, b] = linear_to_srgb_rgb(c[k]);
                    writeln!(w, "v {x} {y} {z} {r} {g} {b}")?;
                }
                None => writeln!(w, "v {x} {y} {z}")?,
            }
        }
        for uv in mesh.uvs() {
            let [s, t] = uv.as_vec2().to_array();
            writeln!(w, "vt {s} {}", 1.0 - t)?;
        }
        for n in mesh.normals() {
            let [x, y, z] = n.as_vec3().to_array();
            writeln!(w, "vn {x} {y} {z}")?;
        }
        for t in mesh.triangles() {
            let [a, b, c] = t.map(|k| u64::from(k) + first);
            writeln!(w, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}")?;
        }
        first += mesh.n_vertices() as u64;
    }
    w.flush()
}

#[cfg(feature = "obj")]
pub(super) use read::{read_obj, read_obj_scene};

/// Reading OBJ back, with `tobj` (the `obj` feature).
#[cfg(feature = "obj")]
mod read {
    use std::fs::File;
    use std::io::BufReader;
    use std::path::Path;

    use glam::{DVec2, DVec3};

    use super::super::{MeshBuilder, format_error, io_error};
    use crate::colormap::srgb_to_linear_rgb;
    use crate::{Error, TriangleMesh};

    /// Reads an OBJ file with `tobj` (one index per vertex, triangulated), all objects
    /// concatenated; flips t back and makes colours linear.
    pub(in crate::export) fn read_obj(path: &Path) -> Result<TriangleMesh, Error> {
        let mut all = MeshBuilder::default();
        for model in &models(path)? {
            append(model, &mut all)?;
        }
        if all.is_empty() {
            return Err(format_error("OBJ file has no triangles", None));
        }
        all.finish()
    }

    /// Reads an OBJ file as [`read_obj`] does, one mesh per object (`o` or `g` line, as `tobj`
    /// splits them) with its name, in the order of the file; objects without triangles are
    /// left out.
    pub(in crate::export) fn read_obj_scene(
        path: &Path,
    ) -> Result<Vec<(String, TriangleMesh)>, Error> {
        let mut parts = Vec::new();
        for model in models(path)? {
            let mut part = MeshBuilder::default();
            append(&model, &mut part)?;
            if !part.is_empty() {
                parts.push((model.name, part.finish()?));
            }
        }
        if parts.is_empty() {
            return Err(format_error("OBJ file has no triangles", None));
        }
        Ok(parts)
    }

    /// The objects of an OBJ file, read by `tobj` with one index per vertex (each object's
    /// vertices numbered by first use), polygons triangulated, points and lines left out and
    /// material libraries not opened.
    fn models(path: &Path) -> Result<Vec<tobj::Model>, Error> {
        let file = File::open(path).map_err(|e| io_error(&e, Some(path)))?;
        let options = tobj::LoadOptions {
            single_index: true,
            triangulate: true,
            ignore_points: true,
            ignore_lines: true,
        };
        let (models, _materials) = tobj::load_obj_buf(&mut BufReader::new(file), &options, |_| {
            Err(tobj::LoadError::OpenFileFailed)
        })
        .map_err(|e| format_error(format!("OBJ: {e}"), Some(path)))?;
        Ok(models)
    }

    /// Appends an object to `out`: t flipped back, colours made linear. An object without
    /// normals gets area-weighted vertex normals from its triangles (+z where they cancel), one
    /// without texture coordinates gets (0, 0) at every vertex.
    fn append(model: &tobj::Model, out: &mut MeshBuilder) -> Result<(), Error> {
        let m = &model.mesh;
        let n = m.positions.len() / 3;
        let with_normals = m.normals.len() == 3 * n;
        let with_uvs = m.texcoords.len() == 2 * n;
        if (!m.normals.is_empty() && !with_normals) || (!m.texcoords.is_empty() && !with_uvs) {
            return Err(format_error(
                format!(
                    "OBJ object {:?} has normals or texture coordinates for only some vertices",
                    model.name
                ),
                None,
            ));
        }
        let base = out.next_vertex()?;
        let positions: Vec<DVec3> = m
            .positions
            .chunks_exact(3)
            .map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into()))
            .collect();
        if with_normals {
            out.normals.extend(
                m.normals
                    .chunks_exact(3)
                    .map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into())),
            );
        } else {
            out.normals.extend(crate::triangle_mesh::area_weighted_normals(
                &positions,
                m.indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]),
            ));
        }
        out.positions.extend(positions);
        if with_uvs {
            out.uvs.extend(
                m.texcoords.chunks_exact(2).map(|t| DVec2::new(t[0].into(), f64::from(1.0 - t[1]))),
            );
        } else {
            out.uvs.extend(std::iter::repeat_n(DVec2::ZERO, n));
        }
        if m.vertex_color.len() == 3 * n {
            out.colors.extend(
                m.vertex_color.chunks_exact(3).map(|c| srgb_to_linear_rgb([c[0], c[1], c[2]])),
            );
        } else {
            out.uncolored = true;
        }
        out.triangles.extend(
            m.indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]].map(|k| k.saturating_add(base))),
        );
        Ok(())
    }
}
