// SPDX-License-Identifier: MIT
//! The error type of the polygon meshes and subdivision schemes of [`crate::subdivision`].

use std::fmt;

/// Everything that can be wrong with a polygon mesh, a mesh file, or the input of a
/// subdivision scheme; `Display` gives one line naming the offending face, edge, vertex or
/// file line.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum MeshError {
    /// A face names a vertex that does not exist.
    IndexOutOfRange {
        /// Index of the face.
        face: usize,
        /// The vertex index it names.
        index: usize,
        /// The number of vertices of the mesh.
        n_vertices: usize,
    },
    /// A face has fewer than three corners or names a vertex twice.
    DegenerateFace {
        /// Index of the face.
        face: usize,
        /// What is wrong, in words.
        reason: String,
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
        /// The 1-based line number.
        line: usize,
        /// What is wrong, in words.
        message: String,
    },
    /// Reading or writing a file failed.
    Io {
        /// The file, as given.
        path: String,
        /// The message of the operating system.
        message: String,
    },
    /// A mesh could not be converted to a [`crate::TriangleMesh`] (e.g. it has no faces).
    Conversion(crate::Error),
}

impl fmt::Display for MeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshError::IndexOutOfRange { face, index, n_vertices } => write!(
                f,
                "face {face} names vertex {index}, but the mesh has {n_vertices} vertices"
            ),
            MeshError::DegenerateFace { face, reason } => {
                write!(f, "face {face} is degenerate: {reason}")
            }
            MeshError::NonFinitePosition { vertex } => {
                write!(f, "vertex {vertex} has a non-finite coordinate (NaN or infinity)")
            }
            MeshError::NonManifoldEdge { edge, faces } => write!(
                f,
                "edge ({}, {}) is non-manifold: it is shared by faces {faces:?}",
                edge[0], edge[1]
            ),
            MeshError::InconsistentOrientation { edge, faces } => write!(
                f,
                "faces {} and {} both traverse edge {} → {}: their orientations disagree",
                faces[0], faces[1], edge[0], edge[1]
            ),
            MeshError::NonManifoldVertex { vertex } => {
                write!(f, "vertex {vertex} is non-manifold: its faces form more than one fan")
            }
            MeshError::TooLarge { what, count } => {
                write!(f, "{count} {what} is too many for 32-bit indices")
            }
            MeshError::WrongPrimitive { scheme, face, n_sides, expected } => {
                write!(f, "{scheme} needs {expected}, but face {face} has {n_sides} sides")
            }
            MeshError::OpenMesh { scheme, edge } => write!(
                f,
                "{scheme} has no boundary rule here, and the mesh is open (boundary edge {} → {})",
                edge[0], edge[1]
            ),
            MeshError::UnsupportedVertex { vertex, reason } => {
                write!(f, "vertex {vertex}: {reason}")
            }
            MeshError::Parse { format, line, message } => {
                write!(f, "{format} line {line}: {message}")
            }
            MeshError::Io { path, message } => write!(f, "{path}: {message}"),
            MeshError::Conversion(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for MeshError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            MeshError::Conversion(e) => Some(e),
            _ => None,
        }
    }
}
