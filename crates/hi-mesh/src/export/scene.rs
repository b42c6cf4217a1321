// SPDX-License-Identifier: MIT
//! Scenes of named meshes: several surfaces (a character's body, eyes and teeth; a teapot and
//! its lid) in one file, each a part of its own that other programs open under its name — a
//! named node with its own mesh in glTF, a named object (`o name`) in OBJ.

use std::collections::HashMap;
use std::fmt;
use std::path::{Path, PathBuf};

use super::{MeshFormat, ReadBackReport, at_path, compare, save_parts};
use crate::{Error, TriangleMesh};

/// A part of a scene: a mesh and the name it goes by in the file.
///
/// A scene is a slice of parts, written in its order by [`save_scene`], [`write_scene_glb`],
/// [`write_scene_gltf`] and [`write_scene_obj`], which check the names first
/// ([`check_part_names`]): at least one part, and every name non-empty, unique, and printable
/// on one line with no blank at either end.
///
/// [`write_scene_glb`]: super::write_scene_glb
/// [`write_scene_gltf`]: super::write_scene_gltf
/// [`write_scene_obj`]: super::write_scene_obj
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NamedMesh<'a> {
    /// The part's name: the glTF node and mesh name, the OBJ object name.
    pub name: &'a str,
    /// Its mesh.
    pub mesh: &'a TriangleMesh,
}

impl<'a> NamedMesh<'a> {
    /// The part `name` of mesh `mesh` (the name is checked when the scene is written).
    #[must_use]
    pub const fn new(name: &'a str, mesh: &'a TriangleMesh) -> Self {
        NamedMesh { name, mesh }
    }
}

/// Checks the names of a scene's parts, in order, as the scene writers do before writing: at
/// least one name; none empty; none with a control character or a line or paragraph
/// separator, or starting or ending with whitespace (an OBJ object's name is the rest of its
/// line, which readers trim); no two alike. Blanks inside a name and any other Unicode are
/// kept by every format.
///
/// A name that passes is read back unchanged by [`load_scene`], trimesh and Blender. Two
/// programs change some names all the same: three.js's glTF loader replaces whitespace with
/// `_` and drops `[ ] . : /` from node names, and Blender before 5.0 cuts names at 63 bytes.
/// Names of ASCII letters, digits, `_` and `-`, at most 63 bytes, come through everywhere.
///
/// # Errors
///
/// [`Error::InvalidCount`] when there are no names; [`Error::InvalidPart`] naming the first
/// part whose name is empty, not printable on one line, or that of an earlier part.
///
/// # Examples
///
/// ```
/// use hi_mesh::export::check_part_names;
///
/// assert!(check_part_names(["body", "left eye", "teeth"]).is_ok());
/// let err = check_part_names(["body", "eye", "eye"]).unwrap_err();
/// assert_eq!(
///     err.to_string(),
///     "scene part 2 (\"eye\"): its name is that of part 1; part names must be unique"
/// );
/// assert!(check_part_names(["body", ""]).is_err());
/// assert!(check_part_names(["two\nlines"]).is_err());
/// assert!(check_part_names([]).is_err());
/// ```
pub fn check_part_names<'n>(names: impl IntoIterator<Item = &'n str>) -> Result<(), Error> {
    let mut seen: HashMap<&str, usize> = HashMap::new();
    for (part, name) in names.into_iter().enumerate() {
        let invalid = |problem: String| Error::InvalidPart { part, name: name.to_owned(), problem };
        if name.is_empty() {
            return Err(invalid("its name is empty; every part needs a name".to_owned()));
        }
        if let Some((at, c)) = name
            .char_indices()
            .find(|&(_, c)| c.is_control() || matches!(c, '\u{2028}' | '\u{2029}'))
        {
            return Err(invalid(format!(
                "its name has the control character or line break U+{:04X} at byte {at}; a name \
                 is printed on one line",
                u32::from(c)
            )));
        }
        if name.trim() != name {
            return Err(invalid(
                "its name starts or ends with whitespace, which OBJ readers drop".to_owned(),
            ));
        }
        if let Some(&first) = seen.get(name) {
            return Err(invalid(format!(
                "its name is that of part {first}; part names must be unique"
            )));
        }
        seen.insert(name, part);
    }
    if seen.is_empty() {
        return Err(Error::InvalidCount {
            what: "number of scene parts",
            value: 0,
            expected: "at least 1",
        });
    }
    Ok(())
}

/// [`check_part_names`] on the names of `parts`.
pub(super) fn check_scene(parts: &[NamedMesh<'_>]) -> Result<(), Error> {
    check_part_names(parts.iter().map(|p| p.name))
}

/// Writes the parts of a scene to `path`, one file in the format its extension names (and for
/// `.gltf` its buffer beside it, as [`save`](super::save) writes it), and returns the files
/// written.
///
/// glTF (`.gltf`, `.glb`): one buffer; one mesh per part with its own accessors (positions
/// with their min and max, normals, UVs, colours when the part has them, indices as `u16` or
/// `u32` by the part's own vertex count) and the one double-sided material; one node per part,
/// named as its mesh; one scene of all the nodes, in order. OBJ: one object per part
/// (`o name`), its lines as [`write_obj`](super::write_obj) writes a mesh, indices counted
/// across the file. Each part is written as [`save`](super::save) writes a mesh alone, so a
/// scene of one part is, but for the name, the file of its mesh.
///
/// # Errors
///
/// [`Error::UnknownExtension`](crate::Error::UnknownExtension); those of
/// [`check_part_names`]; for OBJ, [`Error::InvalidPart`] when some parts have vertex colours
/// and others not (OBJ gives colours to every vertex or to none); as [`save`](super::save) for
/// files that cannot be written.
///
/// # Examples
///
/// ```
/// use hi_mesh::export::{self, NamedMesh};
/// use hi_mesh::PolyMesh;
///
/// let pot = PolyMesh::cube().to_triangle_mesh()?;
/// let lid = PolyMesh::octahedron().to_triangle_mesh()?;
/// let dir = std::env::temp_dir().join(format!("hi-mesh-doc-scene-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let parts = [NamedMesh::new("pot", &pot), NamedMesh::new("lid", &lid)];
/// for file in ["teapot.glb", "teapot.gltf", "teapot.obj"] {
///     let written = export::save_scene(&parts, dir.join(file))?;
///     let scene = export::load_scene(&written[0])?;
///     let names: Vec<&str> = scene.iter().map(|(name, _)| name.as_str()).collect();
///     assert_eq!(names, ["pot", "lid"]);
///     assert_eq!(scene[1].1.n_triangles(), lid.n_triangles());
///     assert!(export::read_back_scene(&parts, &written[0])?.agrees_within(0.0, 1e-7));
/// }
/// std::fs::remove_dir_all(&dir).unwrap();
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn save_scene(parts: &[NamedMesh<'_>], path: impl AsRef<Path>) -> Result<Vec<PathBuf>, Error> {
    let path = path.as_ref();
    MeshFormat::try_from_path(path)?;
    check_scene(parts)?;
    save_parts(parts, path)
}

/// Reads the parts of a scene from an OBJ, `.gltf` or `.glb` file, each with its name, in the
/// order of the file; [`load`](super::load) reads the same file as one mesh, and each part
/// here is read as it reads a mesh (OBJ's t flipped back and its colours made linear; glTF's
/// node transforms applied, flat normals where a primitive has none).
///
/// glTF: one part per node that places a mesh with triangles (every triangle primitive of the
/// mesh), in the order [`placed_meshes`](super::placed_meshes) lists them, named by the node,
/// or by the mesh when the node has no name, or `mesh_k` for the file's k-th mesh when neither
/// has one; a document without scenes gives one part per mesh. OBJ: one part per object (`o`
/// or `g` line) with triangles, named by it (`tobj` calls faces before any such line
/// `unnamed_object`). Names read from other programs' files need not be unique.
///
/// # Errors
///
/// Those of [`load`](super::load).
pub fn load_scene(path: impl AsRef<Path>) -> Result<Vec<(String, TriangleMesh)>, Error> {
    let path = path.as_ref();
    let parts = match MeshFormat::try_from_path(path)? {
        #[cfg(feature = "obj")]
        MeshFormat::Obj => super::obj::read_obj_scene(path),
        #[cfg(feature = "gltf")]
        MeshFormat::Gltf | MeshFormat::Glb => super::gltf::read_gltf_scene(path),
        #[cfg(not(feature = "obj"))]
        MeshFormat::Obj => Err(super::feature_disabled(path, "obj")),
        #[cfg(not(feature = "gltf"))]
        MeshFormat::Gltf | MeshFormat::Glb => Err(super::feature_disabled(path, "gltf")),
    };
    parts.map_err(|e| at_path(e, path))
}

/// How a scene read from a file compares with the parts it was written from: the names, and
/// each part written against the part read in the same place ([`ReadBackReport`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SceneReadBackReport {
    /// The names of the parts written, in order.
    pub expected_names: Vec<String>,
    /// The names of the parts read, in order.
    pub found_names: Vec<String>,
    /// The k-th part written against the k-th part read, for every k both scenes have.
    pub parts: Vec<ReadBackReport>,
}

impl SceneReadBackReport {
    /// The same names in the same order (so the same number of parts).
    #[must_use]
    pub fn names_agree(&self) -> bool {
        self.expected_names == self.found_names
    }

    /// Names agree and every part agrees exactly at f32 ([`ReadBackReport::is_exact`]).
    #[must_use]
    pub fn is_exact(&self) -> bool {
        self.agrees_within(0.0, 0.0)
    }

    /// Names agree and every part agrees within the tolerances of
    /// [`ReadBackReport::agrees_within`].
    #[must_use]
    pub fn agrees_within(&self, tolerance: f64, display_tolerance: f64) -> bool {
        self.names_agree()
            && self.parts.len() == self.expected_names.len()
            && self.parts.iter().all(|p| p.agrees_within(tolerance, display_tolerance))
    }
}

impl fmt::Display for SceneReadBackReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "parts {}/{}", self.found_names.len(), self.expected_names.len())?;
        if self.names_agree() {
            write!(f, ", names agree")?;
        } else {
            write!(f, ", names {:?} expected {:?}", self.found_names, self.expected_names)?;
        }
        for (name, part) in self.expected_names.iter().zip(&self.parts) {
            write!(f, "; {name:?}: {part}")?;
        }
        Ok(())
    }
}

/// Compares a scene read from a file (`found`, as [`load_scene`] returns it) with the parts
/// written (`expected`): the names, and each part against the part read in the same place
/// ([`compare`](super::compare)).
#[must_use]
pub fn compare_scene(
    expected: &[NamedMesh<'_>],
    found: &[(String, TriangleMesh)],
) -> SceneReadBackReport {
    SceneReadBackReport {
        expected_names: expected.iter().map(|p| p.name.to_owned()).collect(),
        found_names: found.iter().map(|(name, _)| name.clone()).collect(),
        parts: expected.iter().zip(found).map(|(e, (_, f))| compare(e.mesh, f)).collect(),
    }
}

/// Reads the scene at `path` with [`load_scene`] and compares it with `parts`
/// ([`compare_scene`]).
///
/// # Errors
///
/// Those of [`load_scene`].
pub fn read_back_scene(
    parts: &[NamedMesh<'_>],
    path: impl AsRef<Path>,
) -> Result<SceneReadBackReport, Error> {
    Ok(compare_scene(parts, &load_scene(path)?))
}
