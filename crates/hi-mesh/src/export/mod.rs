// SPDX-License-Identifier: MIT
//! Mesh files: writing a [`TriangleMesh`], or a scene of several named meshes, as Wavefront
//! OBJ or glTF 2.0 (`.gltf` + `.bin`, or `.glb`) and reading such files back, so that "most
//! computer graphics software will be able to import the surface" (Hardy 2005, §1.4) in
//! polygonal form (§5.5).
//!
//! | what | where |
//! |---|---|
//! | by file extension: `.obj`, `.gltf` (+ `.bin` beside it), `.glb` | [`save`], [`load`] |
//! | to any writer | [`write_obj`], [`write_gltf`], [`write_glb`], [`write_glb_with_edges`] |
//! | read back, compare with the mesh in memory | [`read_back`], [`compare`], [`ReadBackReport`] |
//! | a scene of named parts (one glTF node, one OBJ object each), by file extension | [`NamedMesh`], [`save_scene`], [`load_scene`], [`check_part_names`] |
//! | a scene to any writer | [`write_scene_obj`], [`write_scene_gltf`], [`write_scene_glb`] |
//! | read a scene back, compare part by part | [`read_back_scene`], [`compare_scene`], [`SceneReadBackReport`] |
//!
//! **What is written.** Every value is rounded once from the mesh's f64 to f32. glTF: one
//! buffer with tightly packed, 4-byte aligned views of `POSITION` (with the min and max of the
//! f32 values written), `NORMAL`, `TEXCOORD_0` (when the mesh has texture coordinates: not
//! every UV at the origin; a reader gives a primitive without them UV (0, 0)), `COLOR_0`
//! (linear RGB, when the mesh has colours) and the indices (`u16` up to 65 535 vertices, `u32` above); one double-sided
//! material (a window of a surface is seen from both sides), one node, one
//! scene, and `asset.generator` naming this crate. OBJ: `v x y z` (`v x y z r g b` with sRGB
//! colours, the convention of `MeshLab` and Blender), `vt s (1 − t)` (OBJ's t runs up the
//! image), `vn`, and `f a/a/a b/b/b c/c/c`.
//!
//! **Scenes.** A scene is a slice of [`NamedMesh`] parts, each written as a mesh alone is, in
//! one file: glTF has one buffer, then per part its own accessors, a mesh and a node of the
//! part's name, all in one scene; OBJ has an object (`o name`) per part. A single mesh is
//! written by the same code, as a scene of one part. Parts may be closed or open; nothing
//! is assumed of their shape. [`load_scene`] reads one named mesh per glTF node or OBJ object.
//!
//! **Reading back** uses the `gltf` and `tobj` crates. glTF returns the mesh exactly (to the f32
//! written); OBJ returns the same triangles with the vertices renumbered (`tobj` orders them by
//! first use), UVs to 6·10⁻⁸ (one rounding of 1 − t) and colours to about 10⁻⁷ (the sRGB
//! conversion).

#[cfg(feature = "gltf")]
mod gltf;
mod obj;
mod scene;

use std::fmt;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

#[cfg(feature = "gltf")]
pub use self::gltf::{
    accessor_problem, parse_gltf, placed_meshes, primitive_triangles, write_glb,
    write_glb_with_edges, write_gltf, write_scene_glb, write_scene_gltf,
};
pub use self::obj::{write_obj, write_scene_obj};
use self::scene::check_scene;
pub use self::scene::{
    NamedMesh, SceneReadBackReport, check_part_names, compare_scene, load_scene, read_back_scene,
    save_scene,
};
use crate::{Error, TriangleMesh};

/// The `asset.generator` of glTF files and the first comment of OBJ files.
pub const GENERATOR: &str = concat!("harmonic (hi-mesh ", env!("CARGO_PKG_VERSION"), ")");

/// The extensions [`save`] and [`load`] know, in words.
const MESH_EXTENSIONS: &str = ".obj, .gltf or .glb";

/// A mesh file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum MeshFormat {
    /// Wavefront OBJ (`.obj`).
    Obj,
    /// glTF 2.0 JSON with an external binary buffer (`.gltf` + `.bin`).
    Gltf,
    /// Binary glTF 2.0 (`.glb`).
    Glb,
}

impl MeshFormat {
    /// The format named by the extension of `path` (`obj`, `gltf`, `glb`, any case).
    ///
    /// # Errors
    ///
    /// [`Error::UnknownExtension`] for any other extension or none.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_mesh::export::MeshFormat;
    ///
    /// assert_eq!(MeshFormat::try_from_path("surface.GLB".as_ref()).unwrap(), MeshFormat::Glb);
    /// assert!(MeshFormat::try_from_path("surface.stl".as_ref()).is_err());
    /// ```
    pub fn try_from_path(path: &Path) -> Result<Self, Error> {
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("obj") => Ok(MeshFormat::Obj),
            Some("gltf") => Ok(MeshFormat::Gltf),
            Some("glb") => Ok(MeshFormat::Glb),
            _ => {
                Err(Error::UnknownExtension { path: path.to_path_buf(), expected: MESH_EXTENSIONS })
            }
        }
    }

    /// The usual extension, without the dot.
    #[must_use]
    pub fn extension(self) -> &'static str {
        match self {
            MeshFormat::Obj => "obj",
            MeshFormat::Gltf => "gltf",
            MeshFormat::Glb => "glb",
        }
    }
}

/// An [`io::Error`] as an [`Error`], with the file when known.
pub(crate) fn io_error(e: &io::Error, path: Option<&Path>) -> Error {
    Error::Io { path: path.map(Path::to_path_buf), kind: e.kind(), message: e.to_string() }
}

#[cfg(any(feature = "gltf", feature = "obj"))]
fn format_error(message: impl Into<String>, path: Option<&Path>) -> Error {
    Error::Format { path: path.map(Path::to_path_buf), message: message.into() }
}

/// Fills in the path of a file error that lacks one.
pub(crate) fn at_path(e: Error, at: &Path) -> Error {
    match e {
        Error::Io { path: None, kind, message } => {
            Error::Io { path: Some(at.to_path_buf()), kind, message }
        }
        Error::Format { path: None, message } => {
            Error::Format { path: Some(at.to_path_buf()), message }
        }
        other => other,
    }
}

fn create(path: &Path) -> Result<BufWriter<File>, Error> {
    File::create(path).map(BufWriter::new).map_err(|e| io_error(&e, Some(path)))
}

/// Writes `mesh` to `path` in the format its extension names, and returns the files written:
/// for `.gltf` the JSON file and its buffer, the same path with extension `.bin` (replacing
/// any file there). The file is that of a scene ([`save_scene`]) of one part, named
/// `harmonic surface` in glTF and `harmonic_surface` in OBJ.
///
/// # Errors
///
/// [`Error::UnknownExtension`]; [`Error::Io`] naming the file when it cannot be
/// created or written (no such directory, no permission); the errors of the writers.
///
/// # Examples
///
/// ```
/// use hi_mesh::{PolyMesh, export};
///
/// let mesh = PolyMesh::cube().to_triangle_mesh()?;
/// let dir = std::env::temp_dir();
/// let files = export::save(&mesh, dir.join("hi-mesh-doc-cube.gltf"))?;
/// assert_eq!(files[1], dir.join("hi-mesh-doc-cube.bin"));
/// assert!(export::read_back(&mesh, &files[0])?.is_exact());
/// assert!(export::save(&mesh, dir.join("cube.stl")).is_err()); // unknown extension
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn save(mesh: &TriangleMesh, path: impl AsRef<Path>) -> Result<Vec<PathBuf>, Error> {
    let path = path.as_ref();
    let name = match MeshFormat::try_from_path(path)? {
        MeshFormat::Obj => obj::SINGLE_NAME,
        MeshFormat::Gltf | MeshFormat::Glb => SINGLE_GLTF_NAME,
    };
    save_parts(&[NamedMesh::new(name, mesh)], path)
}

/// The mesh and node name of a single mesh written as glTF.
const SINGLE_GLTF_NAME: &str = "harmonic surface";

/// Writes `parts` (names not checked) to `path` in the format its extension names: the one
/// writer of files behind [`save`] and [`save_scene`].
fn save_parts(parts: &[NamedMesh<'_>], path: &Path) -> Result<Vec<PathBuf>, Error> {
    let finish = |mut w: BufWriter<File>, p: &Path| w.flush().map_err(|e| io_error(&e, Some(p)));
    match MeshFormat::try_from_path(path)? {
        MeshFormat::Obj => {
            obj::check_colors(parts)?; // before the file is created
            let mut w = create(path)?;
            obj::write_parts(parts, &mut w).map_err(|e| at_path(e, path))?;
            finish(w, path)?;
            Ok(vec![path.to_path_buf()])
        }
        #[cfg(feature = "gltf")]
        MeshFormat::Glb => {
            let mut w = create(path)?;
            gltf::write_glb_parts(&gltf::unedged(parts), &mut w).map_err(|e| at_path(e, path))?;
            finish(w, path)?;
            Ok(vec![path.to_path_buf()])
        }
        #[cfg(feature = "gltf")]
        MeshFormat::Gltf => {
            let bin_path = path.with_extension("bin");
            let bin_name = bin_path.file_name().and_then(|n| n.to_str()).ok_or_else(|| {
                io_error(
                    &io::Error::new(io::ErrorKind::InvalidInput, "file name is not valid UTF-8"),
                    Some(path),
                )
            })?;
            let uri = percent_encode(bin_name);
            let mut w = create(path)?;
            let mut b = create(&bin_path)?;
            gltf::write_gltf_parts(&gltf::unedged(parts), &mut w, &mut b, &uri)
                .map_err(|e| at_path(e, path))?;
            finish(w, path)?;
            finish(b, &bin_path)?;
            Ok(vec![path.to_path_buf(), bin_path])
        }
        #[cfg(not(feature = "gltf"))]
        MeshFormat::Gltf | MeshFormat::Glb => Err(feature_disabled(path, "gltf")),
    }
}

/// [`Error::FeatureDisabled`] for `path`.
#[cfg(not(all(feature = "gltf", feature = "obj")))]
fn feature_disabled(path: &Path, feature: &'static str) -> Error {
    Error::FeatureDisabled { path: path.to_path_buf(), feature }
}

/// A file name as a relative URI: every byte but ASCII letters, digits and `-._~` as `%XX`.
#[cfg(feature = "gltf")]
fn percent_encode(name: &str) -> String {
    let mut out = String::with_capacity(name.len());
    for b in name.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~".contains(&b) {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// Reads the triangle mesh in an OBJ, `.gltf` or `.glb` file (all objects; or the triangle
/// primitives of every mesh the glTF scene places, node transforms applied, flat normals where a
/// primitive has none, as the glTF specification asks), undoing what the writers do: OBJ's t is
/// flipped back and its sRGB colours made linear again. An OBJ object without normals (any
/// OBJ not written here) gets area-weighted vertex normals from its triangles, and one without
/// texture coordinates gets (0, 0) at every vertex.
///
/// # Errors
///
/// [`Error::UnknownExtension`], [`Error::Io`] (a missing file), [`Error::Format`]
/// (not parseable, no triangles), and the errors of
/// [`TriangleMesh::try_new`] for what the file holds (normals not of unit length, indices out
/// of range).
pub fn load(path: impl AsRef<Path>) -> Result<TriangleMesh, Error> {
    let path = path.as_ref();
    let mesh = match MeshFormat::try_from_path(path)? {
        #[cfg(feature = "obj")]
        MeshFormat::Obj => obj::read_obj(path),
        #[cfg(feature = "gltf")]
        MeshFormat::Gltf | MeshFormat::Glb => gltf::read_gltf(path),
        #[cfg(not(feature = "obj"))]
        MeshFormat::Obj => Err(feature_disabled(path, "obj")),
        #[cfg(not(feature = "gltf"))]
        MeshFormat::Gltf | MeshFormat::Glb => Err(feature_disabled(path, "gltf")),
    };
    mesh.map_err(|e| at_path(e, path))
}

/// A triangle mesh gathered from a file, one object or primitive after another, checked by
/// [`TriangleMesh::try_new`] at the end.
#[cfg(any(feature = "gltf", feature = "obj"))]
#[derive(Debug, Default)]
struct MeshBuilder {
    positions: Vec<glam::DVec3>,
    normals: Vec<glam::DVec3>,
    uvs: Vec<glam::DVec2>,
    colors: Vec<[f32; 3]>,
    triangles: Vec<[u32; 3]>,
    /// Some object or primitive had no colours: the mesh gets none.
    uncolored: bool,
}

#[cfg(any(feature = "gltf", feature = "obj"))]
impl MeshBuilder {
    /// The index the next vertex gets.
    fn next_vertex(&self) -> Result<u32, Error> {
        u32::try_from(self.positions.len()).map_err(|_| format_error("too many vertices", None))
    }

    /// No triangle yet.
    fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// The mesh, with its colours when every part gathered had them.
    fn finish(self) -> Result<TriangleMesh, Error> {
        let mesh = TriangleMesh::try_new(self.positions, self.normals, self.uvs, self.triangles)?;
        if !self.uncolored && !self.colors.is_empty() && self.colors.len() == mesh.n_vertices() {
            mesh.try_with_colors(self.colors)
        } else {
            Ok(mesh)
        }
    }
}

/// Whether two meshes have the same triangles over the same vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Connectivity {
    /// The same index lists.
    Identical,
    /// The same triangles, in the same order, over vertices numbered differently (one-to-one).
    Renumbered,
    /// Different numbers of triangles or vertices, or no one-to-one renumbering.
    Different,
}

/// How a mesh read from a file compares with the mesh it was written from. Attribute errors
/// are the largest absolute difference of a component between the two, both rounded to f32,
/// over the corners of corresponding triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ReadBackReport {
    /// Number of vertices of the mesh in memory.
    pub expected_vertices: usize,
    /// Number of vertices in the file.
    pub found_vertices: usize,
    /// Number of triangles of the mesh in memory.
    pub expected_triangles: usize,
    /// Number of triangles in the file.
    pub found_triangles: usize,
    /// Index agreement.
    pub connectivity: Connectivity,
    /// Largest position difference.
    pub position_error: f64,
    /// Largest normal difference.
    pub normal_error: f64,
    /// Largest UV difference.
    pub uv_error: f64,
    /// Largest colour difference; `None` when neither mesh has colours, ∞ when only one has.
    pub color_error: Option<f64>,
}

impl ReadBackReport {
    /// Everything agrees exactly at f32: counts, triangles (up to renumbering) and attributes.
    #[must_use]
    pub fn is_exact(&self) -> bool {
        self.agrees_within(0.0, 0.0)
    }

    /// Counts and triangles agree (up to renumbering), positions and normals to `tolerance`
    /// and UVs and colours to `display_tolerance`.
    #[must_use]
    pub fn agrees_within(&self, tolerance: f64, display_tolerance: f64) -> bool {
        self.expected_vertices == self.found_vertices
            && self.expected_triangles == self.found_triangles
            && self.connectivity != Connectivity::Different
            && self.position_error <= tolerance
            && self.normal_error <= tolerance
            && self.uv_error <= display_tolerance
            && self.color_error.is_none_or(|e| e <= display_tolerance)
    }
}

impl fmt::Display for ReadBackReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "vertices {}/{}, triangles {}/{}, {:?}, errors: position {:.1e}, normal {:.1e}, \
             uv {:.1e}",
            self.found_vertices,
            self.expected_vertices,
            self.found_triangles,
            self.expected_triangles,
            self.connectivity,
            self.position_error,
            self.normal_error,
            self.uv_error
        )?;
        match self.color_error {
            Some(e) => write!(f, ", colour {e:.1e}"),
            None => write!(f, ", no colours"),
        }
    }
}

/// Compares `found` (read from a file) with `expected` (the mesh written), corner by corner of
/// corresponding triangles; see [`ReadBackReport`].
#[must_use]
pub fn compare(expected: &TriangleMesh, found: &TriangleMesh) -> ReadBackReport {
    let mut report = ReadBackReport {
        expected_vertices: expected.n_vertices(),
        found_vertices: found.n_vertices(),
        expected_triangles: expected.n_triangles(),
        found_triangles: found.n_triangles(),
        connectivity: Connectivity::Identical,
        position_error: 0.0,
        normal_error: 0.0,
        uv_error: 0.0,
        color_error: match (expected.colors(), found.colors()) {
            (None, None) => None,
            (Some(_), Some(_)) => Some(0.0),
            _ => Some(f64::INFINITY),
        },
    };
    if report.expected_vertices != report.found_vertices
        || report.expected_triangles != report.found_triangles
    {
        report.connectivity = Connectivity::Different;
    }
    // found vertex → expected vertex, and back: a one-to-one renumbering or not.
    let mut to_expected = vec![u32::MAX; found.n_vertices()];
    let mut to_found = vec![u32::MAX; expected.n_vertices()];
    let colors = expected.colors().zip(found.colors());
    for (te, tf) in expected.triangles().iter().zip(found.triangles()) {
        for (&e, &f) in te.iter().zip(tf) {
            let (ei, fi) = (e as usize, f as usize);
            if to_expected[fi] == u32::MAX && to_found[ei] == u32::MAX {
                to_expected[fi] = e;
                to_found[ei] = f;
            } else if to_expected[fi] != e || to_found[ei] != f {
                report.connectivity = Connectivity::Different;
            }
            if e != f && report.connectivity == Connectivity::Identical {
                report.connectivity = Connectivity::Renumbered;
            }
            let pe = expected.positions()[ei].as_vec3() - found.positions()[fi].as_vec3();
            report.position_error = report.position_error.max(f64::from(pe.abs().max_element()));
            let ne = expected.normals()[ei].as_vec3() - found.normals()[fi].as_vec3();
            report.normal_error = report.normal_error.max(f64::from(ne.abs().max_element()));
            let ue = expected.uvs()[ei].as_vec2() - found.uvs()[fi].as_vec2();
            report.uv_error = report.uv_error.max(f64::from(ue.abs().max_element()));
            if let (Some((ce, cf)), Some(err)) = (colors, report.color_error.as_mut()) {
                let d =
                    ce[ei].iter().zip(&cf[fi]).map(|(a, b)| (a - b).abs()).fold(0.0f32, f32::max);
                *err = err.max(f64::from(d));
            }
        }
    }
    report
}

/// Reads the file at `path` with [`load`] and compares it with `mesh` ([`compare`]).
///
/// # Errors
///
/// Those of [`load`].
pub fn read_back(mesh: &TriangleMesh, path: impl AsRef<Path>) -> Result<ReadBackReport, Error> {
    Ok(compare(mesh, &load(path)?))
}

#[cfg(all(test, feature = "gltf"))]
mod tests {
    use super::*;

    #[test]
    fn percent_encoding_keeps_unreserved_bytes() {
        assert_eq!(percent_encode("a-b_c.d~e.bin"), "a-b_c.d~e.bin", "unreserved");
        assert_eq!(percent_encode("my mesh#1.bin"), "my%20mesh%231.bin", "space and hash");
        assert_eq!(percent_encode("é.bin"), "%C3%A9.bin", "UTF-8 bytes");
    }
}
