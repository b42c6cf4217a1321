// SPDX-License-Identifier: MIT
//! The error type of `hi-mesh`: triangle and polygon meshes, colour maps, subdivision schemes
//! and mesh files.

use std::fmt;
use std::io;
use std::path::PathBuf;

/// Everything that can be wrong with a mesh, a colour map, a mesh file, or the input of a
/// subdivision scheme; `Display` gives one line naming the offending face, edge, vertex, value
/// or file line.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A face names a vertex that does not exist.
    IndexOutOfRange {
        /// Index of the face.
        face: usize,
        /// The vertex index it names.
        index: usize,
        /// The number of vertices of the mesh.
        n_vertices: usize,
    },
    /// A face has fewer than three corners.
    TooFewCorners {
        /// Index of the face.
        face: usize,
        /// Its number of corners.
        corners: usize,
    },
    /// A face names a vertex twice.
    RepeatedVertex {
        /// Index of the face.
        face: usize,
        /// The vertex it names twice.
        vertex: u32,
    },
    /// A vertex position has a NaN or infinite coordinate.
    NonFinitePosition {
        /// Index of the vertex.
        vertex: usize,
    },
    /// More than two faces share an edge.
    NonManifoldEdge {
        /// The edge, as its two vertex indices (smaller first).
        edge: [u32; 2],
        /// The faces that share it (at least three).
        faces: Vec<usize>,
    },
    /// Two faces traverse a shared edge in the same direction, so their orientations disagree.
    InconsistentOrientation {
        /// The edge as both faces traverse it (from, to).
        edge: [u32; 2],
        /// The two faces.
        faces: [usize; 2],
    },
    /// The faces around a vertex form more than one fan (two cones touching at a point).
    NonManifoldVertex {
        /// Index of the vertex.
        vertex: usize,
    },
    /// The mesh is too large for 32-bit indices.
    TooLarge {
        /// What overflowed.
        what: &'static str,
        /// Its count.
        count: usize,
    },
    /// A scheme was given a face it is not defined on (e.g. Loop on a quad).
    WrongPrimitive {
        /// The scheme.
        scheme: &'static str,
        /// Index of the first offending face.
        face: usize,
        /// Its number of sides.
        n_sides: usize,
        /// What the scheme accepts, in words.
        expected: &'static str,
    },
    /// A scheme without a boundary rule was given an open mesh.
    OpenMesh {
        /// The scheme.
        scheme: &'static str,
        /// A boundary edge (from, to) of the mesh.
        edge: [u32; 2],
    },
    /// A vertex query (limit position or normal) needs something the vertex lacks.
    UnsupportedVertex {
        /// Index of the vertex.
        vertex: usize,
        /// What is wrong, in words.
        reason: &'static str,
    },
    /// A mesh file is malformed.
    Parse {
        /// The file format (`"OBJ"`, `"OFF"`).
        format: &'static str,
        /// The 1-based line number, or `None` for the file as a whole (empty, or ending before
        /// what its header announces).
        line: Option<usize>,
        /// What is wrong, in words.
        message: String,
    },
    /// A count (of triangles, normals, UVs, colours) is out of range, or an index names an
    /// element that does not exist.
    InvalidCount {
        /// Which count.
        what: &'static str,
        /// Its value.
        value: usize,
        /// The accepted range, in words.
        expected: &'static str,
    },
    /// A value is out of its range: a normal not of unit length, a non-finite UV, a colour
    /// component outside [0, 1], a colour-map bound.
    InvalidValue {
        /// What the value is.
        what: &'static str,
        /// Its index, for an element of a list (a vertex).
        index: Option<usize>,
        /// The value.
        value: f64,
        /// The accepted range, in words.
        expected: &'static str,
    },
    /// A part of a scene of named meshes ([`crate::export::NamedMesh`]) cannot be written: its
    /// name is empty, repeated, or holds what a mesh file cannot carry, or (OBJ) it lacks the
    /// vertex colours another part has.
    InvalidPart {
        /// Index of the part in the scene.
        part: usize,
        /// Its name.
        name: String,
        /// What is wrong, in words.
        problem: String,
    },
    /// The extension of a mesh file's path is not one the reader or writer knows
    /// ([`crate::export`], [`crate::PolyMesh::load`]).
    UnknownExtension {
        /// The path.
        path: PathBuf,
        /// The extensions it knows, in words (`".obj, .gltf or .glb"`).
        expected: &'static str,
    },
    /// Creating, writing or reading a mesh file failed.
    Io {
        /// The file, when known (writers given a bare `Write` do not know it).
        path: Option<PathBuf>,
        /// The kind of the underlying `std::io::Error`.
        kind: io::ErrorKind,
        /// Its message.
        message: String,
    },
    /// The format is known, but this build leaves it out: `hi-mesh` was built without the
    /// feature that reads or writes it.
    FeatureDisabled {
        /// The path.
        path: PathBuf,
        /// The Cargo feature of `hi-mesh` that adds the format (`"gltf"`, `"obj"`).
        feature: &'static str,
    },
    /// A glTF or OBJ file could not be parsed (by `gltf` or `tobj`), or holds no triangle mesh.
    Format {
        /// The file, when known.
        path: Option<PathBuf>,
        /// What is wrong.
        message: String,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::IndexOutOfRange { face, index, n_vertices } => write!(
                f,
                "face {face} names vertex {index}, but the mesh has {n_vertices} vertices"
            ),
            Error::TooFewCorners { face, corners } => write!(
                f,
                "face {face} is degenerate: it has {corners} corners, at least 3 are needed"
            ),
            Error::RepeatedVertex { face, vertex } => {
                write!(f, "face {face} is degenerate: it names vertex {vertex} twice")
            }
            Error::NonFinitePosition { vertex } => {
                write!(f, "vertex {vertex} has a non-finite coordinate (NaN or infinity)")
            }
            Error::NonManifoldEdge { edge, faces } => write!(
                f,
                "edge ({}, {}) is non-manifold: it is shared by faces {faces:?}",
                edge[0], edge[1]
            ),
            Error::InconsistentOrientation { edge, faces } => write!(
                f,
                "faces {} and {} both traverse edge {} → {}: their orientations disagree",
                faces[0], faces[1], edge[0], edge[1]
            ),
            Error::NonManifoldVertex { vertex } => {
                write!(f, "vertex {vertex} is non-manifold: its faces form more than one fan")
            }
            Error::TooLarge { what, count } => {
                write!(f, "{count} {what} is too many for 32-bit indices")
            }
            Error::WrongPrimitive { scheme, face, n_sides, expected } => {
                write!(f, "{scheme} needs {expected}, but face {face} has {n_sides} sides")
            }
            Error::OpenMesh { scheme, edge } => write!(
                f,
                "{scheme} has no boundary rule here, and the mesh is open (boundary edge {} → {})",
                edge[0], edge[1]
            ),
            Error::UnsupportedVertex { vertex, reason } => {
                write!(f, "vertex {vertex}: {reason}")
            }
            Error::Parse { format, line: Some(line), message } => {
                write!(f, "{format}, line {line}: {message}")
            }
            Error::Parse { format, line: None, message } => write!(f, "{format}: {message}"),
            Error::InvalidCount { what, value, expected } => {
                write!(f, "{what} = {value} is invalid: expected {expected}")
            }
            Error::InvalidValue { what, index: Some(i), value, expected } => {
                write!(f, "{what} {i} = {value} is invalid: expected {expected}")
            }
            Error::InvalidValue { what, index: None, value, expected } => {
                write!(f, "{what} = {value} is invalid: expected {expected}")
            }
            Error::InvalidPart { part, name, problem } => {
                write!(f, "scene part {part} ({name:?}): {problem}")
            }
            Error::UnknownExtension { path, expected } => {
                write!(f, "{}: unknown mesh file extension: expected {expected}", path.display())
            }
            Error::FeatureDisabled { path, feature } => write!(
                f,
                "{}: this build of hi-mesh has no `{feature}` feature, which this format needs",
                path.display()
            ),
            Error::Io { path: Some(path), message, .. } => {
                write!(f, "{}: {message}", path.display())
            }
            Error::Io { path: None, message, .. } => write!(f, "mesh file I/O failed: {message}"),
            Error::Format { path: Some(path), message } => {
                write!(f, "{}: not a readable mesh file: {message}", path.display())
            }
            Error::Format { path: None, message } => {
                write!(f, "not a readable mesh file: {message}")
            }
        }
    }
}

impl std::error::Error for Error {}
