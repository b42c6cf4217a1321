// SPDX-License-Identifier: MIT
//! Wavefront OBJ: `v`, `vn` and `f` lines (other records are skipped), read by
//! [`hi_mesh::PolygonSoup::parse_obj`].

use super::{Scan, ScanFormat};
use crate::Error;

/// Reads an OBJ file. The k-th `vn` is the normal of the k-th `v` when there are as many of
/// one as of the other (point clouds with normals are written so); faces of any size are
/// fan-triangulated, with 1-based or negative (relative) vertex indices in any of the forms
/// `v`, `v/vt`, `v//vn`, `v/vt/vn`.
pub(super) fn parse(bytes: &[u8]) -> Result<Scan, Error> {
    let soup = hi_mesh::PolygonSoup::parse_obj(bytes)
        .map_err(|e| Error::from_parse(ScanFormat::Obj, e))?;
    Ok(Scan::assemble(soup.positions, soup.normals, &soup.faces))
}
