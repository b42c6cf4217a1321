// SPDX-License-Identifier: MIT
//! Wavefront OBJ: `v`, `vt`, `vn` and `f a/a/a b/b/b c/c/c` lines (Hardy 2005, §5.5: the
//! surface as polygons), read back with `tobj`.

use std::io::{BufWriter, Write};

use super::{GENERATOR, io_error};
use crate::colormap::linear_to_srgb_rgb;
use crate::{Error, TriangleMesh};

/// Writes `mesh` as OBJ: positions (with sRGB vertex colours as `v x y z r g b` when the mesh
/// has colours), UVs as `vt s 1−t`, normals, and one `f` line per triangle. Numbers are the f32
/// values, printed so that they parse back to the same f32.
///
/// # Errors
///
/// [`super::FileError::Io`] when writing fails.
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
    write(mesh, &mut BufWriter::new(writer)).map_err(|e| io_error(&e, None))
}

fn write<W: Write>(mesh: &TriangleMesh, w: &mut BufWriter<W>) -> std::io::Result<()> {
    writeln!(w, "# {GENERATOR}")?;
    writeln!(w, "# {} vertices, {} triangles", mesh.n_vertices(), mesh.n_triangles())?;
    writeln!(w, "# vt = (s, 1 - t) of the glTF texture coordinates; vertex colours are sRGB")?;
    writeln!(w, "o harmonic_surface")?;
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
        let [a, b, c] = t.map(|k| u64::from(k) + 1);
        writeln!(w, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}")?;
    }
    w.flush()
}

#[cfg(feature = "obj")]
pub(super) use read::read_obj;

/// Reading OBJ back, with `tobj` (the `obj` feature).
#[cfg(feature = "obj")]
mod read {
    use std::fs::File;
    use std::io::BufReader;
    use std::path::Path;

    use glam::{DVec2, DVec3};

    use super::super::{format_error, io_error};
    use crate::colormap::srgb_to_linear_rgb;
    use crate::{Error, TriangleMesh};

    /// Reads an OBJ file with `tobj` (one index per vertex, triangulated), all objects
    /// concatenated; flips t back and makes colours linear.
    pub(in crate::export) fn read_obj(path: &Path) -> Result<TriangleMesh, Error> {
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
        let (mut positions, mut normals, mut uvs, mut colors, mut triangles) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut all_colored = true;
        for model in &models {
            let m = &model.mesh;
            let n = m.positions.len() / 3;
            if m.normals.len() != 3 * n || m.texcoords.len() != 2 * n {
                return Err(format_error(
                    format!("OBJ object {:?} lacks normals or texture coordinates", model.name),
                    None,
                ));
            }
            let base = u32::try_from(positions.len())
                .map_err(|_| format_error("too many vertices", None))?;
            positions.extend(
                m.positions
                    .chunks_exact(3)
                    .map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into())),
            );
            normals.extend(
                m.normals
                    .chunks_exact(3)
                    .map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into())),
            );
            uvs.extend(
                m.texcoords.chunks_exact(2).map(|t| DVec2::new(t[0].into(), f64::from(1.0 - t[1]))),
            );
            if m.vertex_color.len() == 3 * n {
                colors.extend(
                    m.vertex_color.chunks_exact(3).map(|c| srgb_to_linear_rgb([c[0], c[1], c[2]])),
                );
            } else {
                all_colored = false;
            }
            triangles.extend(
                m.indices
                    .chunks_exact(3)
                    .map(|t| [t[0], t[1], t[2]].map(|k| k.saturating_add(base))),
            );
        }
        if triangles.is_empty() {
            return Err(format_error("OBJ file has no triangles", None));
        }
        let mesh = TriangleMesh::try_new(positions, normals, uvs, triangles)?;
        if all_colored && !colors.is_empty() { mesh.try_with_colors(colors) } else { Ok(mesh) }
    }
}
