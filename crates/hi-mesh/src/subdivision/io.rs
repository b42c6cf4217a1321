// SPDX-License-Identifier: MIT
//! Reading and writing [`PolyMesh`]es as ASCII OBJ (`v` and `f` records) and OFF.
//!
//! Readers never panic: a malformed file gives [`Error::Parse`] with its 1-based line
//! number, and the faces then go through the checks of [`PolyMesh::try_new`]. OBJ texture
//! and normal indices (`f 1/2/3`), negative (relative) indices, and records other than `v`
//! and `f` (`vt`, `vn`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, …) are accepted; the latter are
//! ignored. Writers print every coordinate with Rust's shortest round-trip formatting, so
//! reading a written file gives back the same f64 positions.

use std::io::Write;
use std::path::Path;

use glam::DVec3;

use super::PolyMesh;
use crate::Error;
use crate::export::{FileError, io_error};

fn parse_err(format: &'static str, line: usize, message: impl Into<String>) -> Error {
    Error::Parse { format, line, message: message.into() }
}

fn io_err(path: &Path, e: &std::io::Error) -> Error {
    io_error(e, Some(path))
}

fn parse_coord(format: &'static str, line: usize, tok: Option<&str>) -> Result<f64, Error> {
    let tok = tok.ok_or_else(|| parse_err(format, line, "a vertex needs three coordinates"))?;
    let x: f64 =
        tok.parse().map_err(|_| parse_err(format, line, format!("`{tok}` is not a number")))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(parse_err(format, line, format!("coordinate `{tok}` is not finite")))
    }
}

impl PolyMesh {
    /// Parses an OBJ file's text.
    ///
    /// # Errors
    ///
    /// [`Error::Parse`] with the line number for a malformed `v` or `f` record or an index
    /// out of range; then the errors of [`PolyMesh::try_new`].
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_mesh::subdivision::PolyMesh;
    ///
    /// let m = PolyMesh::try_from_obj_str("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")?;
    /// assert_eq!((m.n_vertices(), m.n_faces()), (3, 1));
    /// let bad = PolyMesh::try_from_obj_str("v 0 0 0\nf 1 2 x\n").unwrap_err();
    /// assert!(bad.to_string().starts_with("OBJ line 2"));
    /// # Ok::<(), hi_mesh::Error>(())
    /// ```
    pub fn try_from_obj_str(text: &str) -> Result<Self, Error> {
        const F: &str = "OBJ";
        let mut positions = Vec::new();
        let mut faces: Vec<Vec<u32>> = Vec::new();
        for (i, line) in text.lines().enumerate() {
            let line_no = i + 1;
            let line = line.split('#').next().unwrap_or("");
            let mut toks = line.split_whitespace();
            match toks.next() {
                Some("v") => {
                    let x = parse_coord(F, line_no, toks.next())?;
                    let y = parse_coord(F, line_no, toks.next())?;
                    let z = parse_coord(F, line_no, toks.next())?;
                    positions.push(DVec3::new(x, y, z));
                }
                Some("f") => {
                    let mut face = Vec::new();
                    for tok in toks {
                        let idx = tok.split('/').next().unwrap_or("");
                        let k: i64 = idx.parse().map_err(|_| {
                            parse_err(F, line_no, format!("`{tok}` is not a vertex index"))
                        })?;
                        let n = positions.len() as i64;
                        let k0 = match k {
                            k if k > 0 && k <= n => k - 1,
                            k if k < 0 && -k <= n => n + k,
                            _ => {
                                return Err(parse_err(
                                    F,
                                    line_no,
                                    format!("index {k} is out of range: {n} vertices so far"),
                                ));
                            }
                        };
                        face.push(
                            u32::try_from(k0).map_err(|_| {
                                parse_err(F, line_no, "index too large for 32 bits")
                            })?,
                        );
                    }
                    if face.len() < 3 {
                        return Err(parse_err(F, line_no, "a face needs at least three vertices"));
                    }
                    faces.push(face);
                }
                _ => {}
            }
        }
        PolyMesh::try_new(positions, &faces)
    }

    /// Parses an ASCII OFF file's text (`OFF`, then `n_vertices n_faces n_edges`, the vertices,
    /// and the faces as `k i₁ … iₖ`; `#` comments; extra values after a face, such as
    /// colours, are ignored).
    ///
    /// # Errors
    ///
    /// [`Error::Parse`] with the line number for a missing header, binary OFF, a bad
    /// count or value, or a truncated file; then the errors of [`PolyMesh::try_new`].
    pub fn try_from_off_str(text: &str) -> Result<Self, Error> {
        const F: &str = "OFF";
        // Tokens with their line numbers, comments removed.
        let mut toks = text.lines().enumerate().flat_map(|(i, line)| {
            line.split('#').next().unwrap_or("").split_whitespace().map(move |t| (i + 1, t))
        });
        let last_line = text.lines().count().max(1);
        let mut next = |what: &str| {
            toks.next().ok_or_else(|| parse_err(F, last_line, format!("file ends before {what}")))
        };
        let (line, head) = next("the header")?;
        match head {
            "OFF" => {}
            "BINARY" | "OFF BINARY" => {
                return Err(parse_err(F, line, "binary OFF is not supported"));
            }
            h => return Err(parse_err(F, line, format!("expected the header `OFF`, found `{h}`"))),
        }
        let mut count = |what: &str| -> Result<usize, Error> {
            let (line, t) = next(what)?;
            if t == "BINARY" {
                return Err(parse_err(F, line, "binary OFF is not supported"));
            }
            t.parse().map_err(|_| parse_err(F, line, format!("{what}: `{t}` is not a count")))
        };
        let n_vertices = count("the vertex count")?;
        let n_faces = count("the face count")?;
        let _n_edges = count("the edge count")?;
        let mut next = |what: &str| {
            toks.next().ok_or_else(|| parse_err(F, last_line, format!("file ends before {what}")))
        };
        // Reserve no more than the text can hold (a vertex takes at least 6 bytes, a face 8, a
        // corner 2): the counts come from the file, which may lie.
        let mut positions = Vec::with_capacity(n_vertices.min(text.len() / 6));
        for _ in 0..n_vertices {
            let mut c = [0.0; 3];
            for x in &mut c {
                let (line, t) = next("all vertices are read")?;
                *x = parse_coord(F, line, Some(t))?;
            }
            positions.push(DVec3::from_array(c));
        }
        let mut faces = Vec::with_capacity(n_faces.min(text.len() / 8));
        let mut last_face_line = 0;
        for _ in 0..n_faces {
            let (line, t) = next("all faces are read")?;
            if line == last_face_line {
                return Err(parse_err(F, line, "two faces on one line (or a wrong corner count)"));
            }
            last_face_line = line;
            let k: usize = t
                .parse()
                .map_err(|_| parse_err(F, line, format!("`{t}` is not a corner count")))?;
            if k < 3 {
                return Err(parse_err(
                    F,
                    line,
                    format!("a face needs at least 3 corners, not {k}"),
                ));
            }
            let mut face = Vec::with_capacity(k.min(text.len() / 2));
            for _ in 0..k {
                let (l, t) = next("all faces are read")?;
                if l != line {
                    return Err(parse_err(F, line, format!("the face has fewer than {k} corners")));
                }
                let idx: u32 = t
                    .parse()
                    .map_err(|_| parse_err(F, line, format!("`{t}` is not a vertex index")))?;
                if idx as usize >= n_vertices {
                    return Err(parse_err(
                        F,
                        line,
                        format!("index {idx} is out of range: {n_vertices} vertices"),
                    ));
                }
                face.push(idx);
            }
            faces.push(face);
        }
        PolyMesh::try_new(positions, &faces)
    }

    /// Writes the mesh as OBJ (`v` records, then 1-based `f` records).
    ///
    /// # Errors
    ///
    /// [`Error::File`] if writing fails.
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
    /// [`Error::File`] if writing fails.
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
    /// [`Error::File`] if the file cannot be read or its extension is neither; then the
    /// errors of [`PolyMesh::try_from_obj_str`] or [`PolyMesh::try_from_off_str`].
    pub fn load(path: impl AsRef<Path>) -> Result<Self, Error> {
        let path = path.as_ref();
        let ext = extension(path)?;
        let bytes = std::fs::read(path).map_err(|e| io_err(path, &e))?;
        let text = String::from_utf8_lossy(&bytes);
        if ext == "obj" { Self::try_from_obj_str(&text) } else { Self::try_from_off_str(&text) }
    }

    /// Writes an `.obj` or `.off` file (by extension, case-insensitive).
    ///
    /// # Errors
    ///
    /// [`Error::File`] if the extension is neither or writing fails.
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
        Err(FileError::UnknownExtension { path: path.to_path_buf(), expected: ".obj or .off" }
            .into())
    }
}
