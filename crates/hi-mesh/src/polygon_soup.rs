// SPDX-License-Identifier: MIT
//! The geometry of OBJ and OFF text files as a polygon soup ([`PolygonSoup`]).

use glam::DVec3;

use crate::Error;
use crate::text::{count, lines, number, show, strip_comment, tokens};

/// The vertices and faces of an OBJ or OFF file: positions, per-vertex normals when the file
/// gives one per vertex, and polygons of any size. It is the one parser of these two formats'
/// geometry: [`PolyMesh`](crate::PolyMesh) builds its half-edge mesh from it, and `hi-scan` its
/// scans. (Meshes with texture coordinates and several objects, as the exporters write them,
/// are read by [`crate::export::load`] through `tobj`; `tobj` reads no bare `v` lines, the usual
/// point-cloud OBJ, and splits a vertex shared by two groups in two, so it cannot give a mesh's
/// topology.)
///
/// Malformed input gives [`Error::Parse`] with the line and what is wrong; no input panics or
/// makes the parser reserve more memory than its size justifies. Coordinates are read as
/// written, NaN and infinities included: a [`PolyMesh`](crate::PolyMesh) refuses them, a scan
/// drops their points.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_mesh::PolygonSoup;
///
/// let soup = PolygonSoup::parse_obj(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")?;
/// assert_eq!(soup.positions[2], DVec3::new(1.0, 1.0, 0.0));
/// assert_eq!(soup.faces, [vec![0, 1, 2, 3]]);
/// let soup = PolygonSoup::parse_off(b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")?;
/// assert_eq!(soup.faces, [vec![0, 1, 2]]);
/// let bad = PolygonSoup::parse_obj(b"v 0 0 0\nf 1 2 x\n").unwrap_err();
/// assert_eq!(bad.to_string(), "OBJ, line 2: face vertex \"x\" is not a vertex index");
/// # Ok::<(), hi_mesh::Error>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonSoup {
    /// The vertices, in the order of the file.
    pub positions: Vec<DVec3>,
    /// One normal per vertex: OBJ's `vn` records when there are as many as `v` records (point
    /// clouds with normals are written so), or the normals of an `NOFF` file.
    pub normals: Option<Vec<DVec3>>,
    /// The faces, each at least three 0-based indices below `positions.len()`.
    pub faces: Vec<Vec<u32>>,
}

/// The format name of OBJ errors.
const OBJ: &str = "OBJ";
/// The format name of OFF errors.
const OFF: &str = "OFF";

/// An error at line `line` of a `format` file.
fn at(format: &'static str, line: usize, message: impl Into<String>) -> Error {
    Error::Parse { format, line: Some(line), message: message.into() }
}

/// An error about a `format` file as a whole (it ends too soon, or is empty).
fn whole(format: &'static str, message: impl Into<String>) -> Error {
    Error::Parse { format, line: None, message: message.into() }
}

/// A whole number, or an error naming `what` it should have been.
fn whole_number(
    format: &'static str,
    line: usize,
    token: &[u8],
    what: &str,
) -> Result<usize, Error> {
    count(token)
        .ok_or_else(|| at(format, line, format!("{what}: {:?} is not a whole number", show(token))))
}

/// Three coordinates from the next three tokens, or an error naming how many were found.
fn point<'a>(
    format: &'static str,
    line: usize,
    tokens: &mut impl Iterator<Item = &'a [u8]>,
    what: &str,
) -> Result<DVec3, Error> {
    let mut xyz = [0.0; 3];
    for (i, c) in xyz.iter_mut().enumerate() {
        let Some(t) = tokens.next() else {
            return Err(at(format, line, format!("expected 3 coordinates {what}, found {i}")));
        };
        *c = number(t).ok_or_else(|| {
            at(format, line, format!("coordinate: {:?} is not a number", show(t)))
        })?;
    }
    Ok(DVec3::from_array(xyz))
}

/// Checks that face index `k` (0-based) is below `n`, as `u32`; an error names the index as the
/// file writes it, `written`.
fn index(
    format: &'static str,
    line: usize,
    k: usize,
    n: usize,
    written: i64,
) -> Result<u32, Error> {
    if k >= n {
        return Err(at(
            format,
            line,
            format!("face index {written} is out of range (the file has {n} vertices)"),
        ));
    }
    u32::try_from(k).map_err(|_| at(format, line, "face index does not fit 32 bits"))
}

impl PolygonSoup {
    /// Reads the `v`, `vn` and `f` records of an OBJ file (other records are skipped). The
    /// k-th `vn` is the normal of the k-th `v` when there are as many of one as of the other;
    /// faces have 1-based or negative (relative) vertex indices in any of the forms `v`,
    /// `v/vt`, `v//vn`, `v/vt/vn`, and may name vertices defined later in the file.
    ///
    /// # Errors
    ///
    /// [`Error::Parse`] with the line of a malformed `v`, `vn` or `f` record: a coordinate
    /// missing or not a number, a face of fewer than three vertices, an index that is 0, not a
    /// number, or out of range.
    pub fn parse_obj(bytes: &[u8]) -> Result<Self, Error> {
        let mut positions = Vec::new();
        let mut normals = Vec::new();
        let mut faces: Vec<(usize, Vec<i64>)> = Vec::new();
        for (n, raw) in lines(bytes) {
            let mut it = tokens(strip_comment(raw), false);
            match it.next() {
                Some(b"v") => positions.push(point(OBJ, n, &mut it, "after `v`")?),
                Some(b"vn") => normals.push(point(OBJ, n, &mut it, "after `vn`")?),
                Some(b"f") => {
                    let face = it
                        .map(|t| vertex_ref(n, t, positions.len()))
                        .collect::<Result<Vec<_>, _>>()?;
                    if face.len() < 3 {
                        return Err(at(
                            OBJ,
                            n,
                            format!("a face needs at least 3 vertices, found {}", face.len()),
                        ));
                    }
                    faces.push((n, face));
                }
                _ => {}
            }
        }
        let total = positions.len();
        let mut resolved = Vec::with_capacity(faces.len());
        for (n, face) in faces {
            let mut f = Vec::with_capacity(face.len());
            for k in face {
                // Positive indices were kept 1-based; negative ones were resolved on their line.
                let written = k;
                let k = usize::try_from(k - 1).map_err(|_| {
                    at(OBJ, n, "a relative face index points before the first vertex")
                })?;
                f.push(index(OBJ, n, k, total, written)?);
            }
            resolved.push(f);
        }
        let normals = (!normals.is_empty() && normals.len() == positions.len()).then_some(normals);
        Ok(Self { positions, normals, faces: resolved })
    }

    /// Reads a text OFF file. The header keyword may carry the prefixes `C` (colours, skipped),
    /// `N` (a normal after each vertex's coordinates) and `ST` (texture coordinates, skipped);
    /// the counts `vertices faces [edges]` may follow it on the same line; `#` starts a
    /// comment. Faces are `k i₁ … iₖ` with 0-based indices, followed by an optional colour.
    ///
    /// # Errors
    ///
    /// [`Error::Parse`] with the line of a bad header, count, coordinate or face, or naming
    /// the file as a whole when it ends before the vertices and faces its counts announce.
    /// Binary OFF is refused.
    pub fn parse_off(bytes: &[u8]) -> Result<Self, Error> {
        let mut content =
            lines(bytes).map(|(n, l)| (n, strip_comment(l))).filter(|(_, l)| !l.is_empty());
        let Some((n, header)) = content.next() else {
            return Err(whole(OFF, "the file is empty"));
        };
        let mut head = tokens(header, false);
        let keyword = head.next().unwrap_or_default();
        let Some(prefix) = keyword.strip_suffix(b"OFF") else {
            return Err(at(OFF, n, format!("expected the keyword OFF, found {:?}", show(keyword))));
        };
        if prefix.iter().any(|b| !matches!(b, b'S' | b'T' | b'C' | b'N')) {
            return Err(at(
                OFF,
                n,
                format!(
                    "unsupported OFF variant {:?} (4-D and n-D OFF are not meshes)",
                    show(keyword)
                ),
            ));
        }
        let with_normals = prefix.contains(&b'N');
        let mut counts: Vec<(usize, &[u8])> = head.map(|t| (n, t)).collect();
        if counts.first().is_some_and(|(_, t)| t.eq_ignore_ascii_case(b"BINARY")) {
            return Err(at(OFF, n, "binary OFF is not supported; write it as text"));
        }
        if counts.is_empty() {
            let Some((m, line)) = content.next() else {
                return Err(whole(OFF, "the file ends before the vertex and face counts"));
            };
            counts = tokens(line, false).map(|t| (m, t)).collect();
        }
        if counts.len() < 2 {
            let line = counts.first().map_or(n, |c| c.0);
            return Err(at(OFF, line, "expected the counts: vertices faces [edges]"));
        }
        let vertices = whole_number(OFF, counts[0].0, counts[0].1, "vertex count")?;
        let n_faces = whole_number(OFF, counts[1].0, counts[1].1, "face count")?;
        // Each vertex takes at least 6 bytes ("0 0 0\n"): do not reserve what the file cannot hold.
        let mut positions = Vec::with_capacity(vertices.min(bytes.len() / 6));
        let mut normals = Vec::with_capacity(if with_normals { positions.capacity() } else { 0 });
        for i in 0..vertices {
            let Some((m, line)) = content.next() else {
                return Err(whole(OFF, format!("the file ends after {i} of {vertices} vertices")));
            };
            let mut it = tokens(line, false);
            positions.push(point(OFF, m, &mut it, "for a vertex")?);
            if with_normals {
                normals.push(point(OFF, m, &mut it, "of the vertex normal (NOFF)")?);
            }
        }
        let mut faces = Vec::with_capacity(n_faces.min(bytes.len() / 8));
        for i in 0..n_faces {
            let Some((m, line)) = content.next() else {
                return Err(whole(OFF, format!("the file ends after {i} of {n_faces} faces")));
            };
            let mut it = tokens(line, false);
            let k = whole_number(OFF, m, it.next().unwrap_or_default(), "face size")?;
            if k < 3 {
                return Err(at(OFF, m, format!("a face needs at least 3 vertices, found {k}")));
            }
            let mut face = Vec::with_capacity(k.min(line.len()));
            for j in 0..k {
                let Some(t) = it.next() else {
                    return Err(at(OFF, m, format!("the face lists {j} of its {k} vertices")));
                };
                let k = whole_number(OFF, m, t, "face vertex")?;
                face.push(index(OFF, m, k, vertices, i64::try_from(k).unwrap_or(i64::MAX))?);
            }
            faces.push(face);
        }
        Ok(Self { positions, normals: with_normals.then_some(normals), faces })
    }
}

/// The vertex index of one OBJ face corner (`v`, `v/vt`, `v//vn` or `v/vt/vn`), 1-based; a
/// negative index counts back from the `defined` vertices read so far.
fn vertex_ref(line: usize, token: &[u8], defined: usize) -> Result<i64, Error> {
    let first = token.split(|&b| b == b'/').next().unwrap_or(token);
    let (negative, digits) = match first.strip_prefix(b"-") {
        Some(rest) => (true, rest),
        None => (false, first),
    };
    let k = count(digits).ok_or_else(|| {
        at(OBJ, line, format!("face vertex {:?} is not a vertex index", show(token)))
    })?;
    let k = i64::try_from(k).map_err(|_| at(OBJ, line, format!("face index {k} is too large")))?;
    if k == 0 {
        return Err(at(OBJ, line, "face index 0 (OBJ indices start at 1)"));
    }
    if negative {
        // -1 is the last vertex defined so far: 1-based index defined + 1 - k.
        let defined = i64::try_from(defined).unwrap_or(i64::MAX);
        Ok(defined + 1 - k)
    } else {
        Ok(k)
    }
}
