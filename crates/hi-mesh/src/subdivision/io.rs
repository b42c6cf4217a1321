// SPDX-License-Identifier: MIT
//! Reading and writing [`PolyMesh`]es as ASCII OBJ (`v` and `f` records) and OFF.
//!
//! The files are read by [`PolygonSoup`], the one parser of OBJ and OFF geometry (it never
//! panics: a malformed file gives [`Error::Parse`] with its 1-based line number), and the faces
//! then go through the checks of [`PolyMesh::try_new`]. OBJ texture and normal indices
//! (`f 1/2/3`), negative (relative) indices, and records other than `v` and `f` (`vt`, `vn`,
//! `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, …) are accepted; the latter are ignored. Writers print every coordinate with Rust's shortest round-trip formatting, so
//! reading a written file gives back the same f64 positions.

use std::io::Write;
use std::path::Path;

use super::PolyMesh;
use crate::export::io_error;
use crate::{Error, PolygonSoup};

fn io_err(path: &Path, e: &std::io::Error) -> Error {
    io_error(e, Some(path))
}

impl PolyMesh {
    /// Parses an OBJ file's text ([`PolygonSoup::parse_obj`]).
    ///
    /// # Errors
    ///
    /// [`Error::Parse`] with the line number for a malformed `v` or `f` record or an index
    /// out of range; then the errors of [`PolyMesh::try_new`] (a non-finite coordinate is
    /// [`Error::NonFinitePosition`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_mesh::subdivision::PolyMesh;
    ///
    /// let m = PolyMesh::try_from_obj_str("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")?;
    /// assert_eq!((m.n_vertices(), m.n_faces()), (3, 1));
    /// let bad = PolyMesh::try_from_obj_str("v 0 0 0\nf 1 2 x\n").unwrap_err();
    /// assert!(bad.to_string().starts_with("OBJ, line 2"));
    /// # Ok::<(), hi_mesh::Error>(())
    /// ```
    pub fn try_from_obj_str(text: &str) -> Result<Self, Error> {
        Self::try_from_soup(PolygonSoup::parse_obj(text.as_bytes())?)
    }

    /// Parses an ASCII OFF file's text ([`PolygonSoup::parse_off`]: `OFF`, then `n_vertices
    /// n_faces n_edges`, the vertices, and the faces as `k i₁ … iₖ`; `#` comments; extra values
    /// after a face, such as colours, are ignored).
    ///
    /// # Errors
    ///
    /// [`Error::Parse`] with the line number for a missing header, binary OFF, a bad
    /// count or value, or a truncated file; then the errors of [`PolyMesh::try_new`].
    pub fn try_from_off_str(text: &str) -> Result<Self, Error> {
        Self::try_from_soup(PolygonSoup::parse_off(text.as_bytes())?)
    }

    /// The mesh of a polygon soup's positions and faces (its normals are not kept).
    fn try_from_soup(soup: PolygonSoup) -> Result<Self, Error> {
        PolyMesh::try_new(soup.positions, &soup.faces)
    }

    /// Writes the mesh as OBJ (`v` records, then 1-based `f` records).
    ///
    /// # Errors
    ///
    /// [`Error::Io`] if writing fails.
    pub fn write_obj<W: Write>(&self, mut writer: W) -> Result<(), Error> {
        let e = |e: std::io::Error| io_error(&e, None);
        writeln!(writer, "# {} vertices, {} faces", self.n_vertices(), self.n_faces())
            .map_err(e)?;
        for p in self.positions() {
            writeln!(writer, "v {} {} {}", p.x, p.y, p.z).map_err(e)?;
        }
        for face in self.faces() {
            write!(writer, "f").map_err(e)?;
            for &k in face {
                write!(writer, " {}", k + 1).map_err(e)?;
            }
            writeln!(writer).map_err(e)?;
        }
        writer.flush().map_err(e)
    }

    /// Writes the mesh as ASCII OFF.
    ///
    /// # Errors
    ///
    /// [`Error::Io`] if writing fails.
    pub fn write_off<W: Write>(&self, mut writer: W) -> Result<(), Error> {
        let e = |e: std::io::Error| io_error(&e, None);
        writeln!(writer, "OFF\n{} {} {}", self.n_vertices(), self.n_faces(), self.n_edges())
            .map_err(e)?;
        for p in self.positions() {
            writeln!(writer, "{} {} {}", p.x, p.y, p.z).map_err(e)?;
        }
        for face in self.faces() {
            write!(writer, "{}", face.len()).map_err(e)?;
            for &k in face {
                write!(writer, " {k}").map_err(e)?;
            }
            writeln!(writer).map_err(e)?;
        }
        writer.flush().map_err(e)
    }

    /// Reads an `.obj` or `.off` file (by extension, case-insensitive).
    ///
    /// # Errors
    ///
    /// [`Error::Io`] if the file cannot be read, [`Error::UnknownExtension`] if its extension is neither; then the
    /// errors of [`PolyMesh::try_from_obj_str`] or [`PolyMesh::try_from_off_str`].
    pub fn load(path: impl AsRef<Path>) -> Result<Self, Error> {
        let path = path.as_ref();
        let ext = extension(path)?;
        let bytes = std::fs::read(path).map_err(|e| io_err(path, &e))?;
        let soup = if ext == "obj" {
            PolygonSoup::parse_obj(&bytes)?
        } else {
            PolygonSoup::parse_off(&bytes)?
        };
        Self::try_from_soup(soup)
    }

    /// Writes an `.obj` or `.off` file (by extension, case-insensitive).
    ///
    /// # Errors
    ///
    /// [`Error::UnknownExtension`] if the extension is neither, [`Error::Io`] if writing fails.
    pub fn save(&self, path: impl AsRef<Path>) -> Result<(), Error> {
        let path = path.as_ref();
        let ext = extension(path)?;
        let file = std::fs::File::create(path).map_err(|e| io_err(path, &e))?;
        let w = std::io::BufWriter::new(file);
        let res = if ext == "obj" { self.write_obj(w) } else { self.write_off(w) };
        res.map_err(|e| crate::export::at_path(e, path))
    }
}

fn extension(path: &Path) -> Result<String, Error> {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
    if ext == "obj" || ext == "off" {
        Ok(ext)
    } else {
        Err(Error::UnknownExtension { path: path.to_path_buf(), expected: ".obj or .off" })
    }
}
