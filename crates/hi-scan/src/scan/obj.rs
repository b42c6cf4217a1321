// SPDX-License-Identifier: MIT
//! Wavefront OBJ: `v`, `vn` and `f` lines (other records are skipped).

use super::text::{count, lines, point, show, strip_comment, tokens};
use super::{Scan, ScanFormat};
use crate::Error;

const F: ScanFormat = ScanFormat::Obj;

/// Reads an OBJ file. The k-th `vn` is the normal of the k-th `v` when there are as many of
/// one as of the other (point clouds with normals are written so); faces of any size are
/// fan-triangulated, with 1-based or negative (relative) vertex indices in any of the forms
/// `v`, `v/vt`, `v//vn`, `v/vt/vn`.
pub(super) fn parse(bytes: &[u8]) -> Result<Scan, Error> {
    let mut points = Vec::new();
    let mut normals = Vec::new();
    let mut faces: Vec<(usize, Vec<i64>)> = Vec::new();
    for (n, raw) in lines(bytes) {
        let line = strip_comment(raw);
        let mut it = tokens(line, false);
        match it.next() {
            Some(b"v") => points.push(point(F, n, &mut it, "after `v`")?),
            Some(b"vn") => normals.push(point(F, n, &mut it, "after `vn`")?),
            Some(b"f") => {
                let mut face = Vec::new();
                for t in it {
                    face.push(vertex_ref(n, t, points.len())?);
                }
                if face.len() < 3 {
                    return Err(Error::line(
                        F,
                        n,
                        format!("a face needs at least 3 vertices, found {}", face.len()),
                    ));
                }
                faces.push((n, face));
            }
            _ => {}
        }
    }
    let total = points.len();
    let mut resolved = Vec::with_capacity(faces.len());
    for (n, face) in faces {
        let mut f = Vec::with_capacity(face.len());
        for k in face {
            // Positive indices were kept 1-based; negative ones were resolved on their line.
            let k = usize::try_from(k - 1).map_err(|_| {
                Error::line(F, n, "a relative face index points before the first vertex")
            })?;
            f.push(super::text::index(F, n, k, total)?);
        }
        resolved.push(f);
    }
    let normals = (!normals.is_empty() && normals.len() == points.len()).then_some(normals);
    Ok(Scan::assemble(points, normals, &resolved))
}

/// The vertex index of one face corner (`v`, `v/vt`, `v//vn` or `v/vt/vn`), 1-based; a
/// negative index counts back from the `defined` vertices read so far.
fn vertex_ref(line: usize, token: &[u8], defined: usize) -> Result<i64, Error> {
    let first = token.split(|&b| b == b'/').next().unwrap_or(token);
    let (negative, digits) = match first.strip_prefix(b"-") {
        Some(rest) => (true, rest),
        None => (false, first),
    };
    let k = count(F, line, digits, "face vertex").map_err(|_| {
        Error::line(F, line, format!("face vertex {:?} is not a vertex index", show(token)))
    })?;
    let k = i64::try_from(k)
        .map_err(|_| Error::line(F, line, format!("face index {k} is too large")))?;
    if k == 0 {
        return Err(Error::line(F, line, "face index 0 (OBJ indices start at 1)"));
    }
    if negative {
        // -1 is the last vertex defined so far: 1-based index defined + 1 - k.
        let defined = i64::try_from(defined).unwrap_or(i64::MAX);
        Ok(defined + 1 - k)
    } else {
        Ok(k)
    }
}
