// SPDX-License-Identifier: MIT
//! Object File Format (text): `[C][N]OFF`, counts, one vertex per line, one face per line.

use super::text::{count, index, lines, point, show, strip_comment, tokens};
use super::{Scan, ScanFormat};
use crate::Error;

const F: ScanFormat = ScanFormat::Off;

/// Reads a text OFF file. The header keyword may carry the prefixes `C` (colours, skipped),
/// `N` (a normal after each vertex's coordinates) and `ST` (texture coordinates, skipped); the
/// counts `vertices faces edges` may follow it on the same line. Faces are `k i₁ … iₖ` with
/// 0-based indices, followed by an optional colour.
pub(super) fn parse(bytes: &[u8]) -> Result<Scan, Error> {
    let mut content =
        lines(bytes).map(|(n, l)| (n, strip_comment(l))).filter(|(_, l)| !l.is_empty());
    let Some((n, header)) = content.next() else {
        return Err(Error::file(F, "the file is empty"));
    };
    let mut head = tokens(header, false);
    let keyword = head.next().unwrap_or_default();
    let Some(prefix) = keyword.strip_suffix(b"OFF") else {
        return Err(Error::line(
            F,
            n,
            format!("expected the keyword OFF, found {:?}", show(keyword)),
        ));
    };
    if prefix.iter().any(|b| !matches!(b, b'S' | b'T' | b'C' | b'N')) {
        return Err(Error::line(
            F,
            n,
            format!("unsupported OFF variant {:?} (4-D and n-D OFF are not scans)", show(keyword)),
        ));
    }
    let with_normals = prefix.contains(&b'N');
    let mut counts: Vec<(usize, &[u8])> = head.map(|t| (n, t)).collect();
    if counts.first().is_some_and(|(_, t)| t.eq_ignore_ascii_case(b"BINARY")) {
        return Err(Error::line(F, n, "binary OFF is not supported; write it as text"));
    }
    if counts.is_empty() {
        let Some((m, line)) = content.next() else {
            return Err(Error::file(F, "the file ends before the vertex and face counts"));
        };
        counts = tokens(line, false).map(|t| (m, t)).collect();
    }
    if counts.len() < 2 {
        let line = counts.first().map_or(n, |c| c.0);
        return Err(Error::line(F, line, "expected the counts: vertices faces [edges]"));
    }
    let vertices = count(F, counts[0].0, counts[0].1, "vertex count")?;
    let faces = count(F, counts[1].0, counts[1].1, "face count")?;
    // Each vertex takes at least 6 bytes ("0 0 0\n"): do not reserve what the file cannot hold.
    let mut points = Vec::with_capacity(vertices.min(bytes.len() / 6));
    let mut normals = Vec::with_capacity(if with_normals { points.capacity() } else { 0 });
    for i in 0..vertices {
        let Some((m, line)) = content.next() else {
            return Err(Error::file(F, format!("the file ends after {i} of {vertices} vertices")));
        };
        let mut it = tokens(line, false);
        points.push(point(F, m, &mut it, "for a vertex")?);
        if with_normals {
            normals.push(point(F, m, &mut it, "of the vertex normal (NOFF)")?);
        }
    }
    let mut polygons = Vec::with_capacity(faces.min(bytes.len() / 8));
    for i in 0..faces {
        let Some((m, line)) = content.next() else {
            return Err(Error::file(F, format!("the file ends after {i} of {faces} faces")));
        };
        let mut it = tokens(line, false);
        let k = count(F, m, it.next().unwrap_or_default(), "face size")?;
        if k < 3 {
            return Err(Error::line(F, m, format!("a face needs at least 3 vertices, found {k}")));
        }
        let mut face = Vec::with_capacity(k.min(line.len()));
        for j in 0..k {
            let Some(t) = it.next() else {
                return Err(Error::line(F, m, format!("the face lists {j} of its {k} vertices")));
            };
            face.push(index(F, m, count(F, m, t, "face vertex")?, vertices)?);
        }
        polygons.push(face);
    }
    let normals = with_normals.then_some(normals);
    Ok(Scan::assemble(points, normals, &polygons))
}
