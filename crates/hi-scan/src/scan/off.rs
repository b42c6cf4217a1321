// SPDX-License-Identifier: MIT
//! Object File Format (text): `[C][N]OFF`, counts, one vertex per line, one face per line, read
//! by [`hi_mesh::PolygonSoup::parse_off`].

use super::{Scan, ScanFormat};
use crate::Error;

/// Reads a text OFF file. The header keyword may carry the prefixes `C` (colours, skipped),
/// `N` (a normal after each vertex's coordinates) and `ST` (texture coordinates, skipped); the
/// counts `vertices faces edges` may follow it on the same line. Faces are `k i₁ … iₖ` with
/// 0-based indices, followed by an optional colour.
pub(super) fn parse(bytes: &[u8]) -> Result<Scan, Error> {
    let soup = hi_mesh::PolygonSoup::parse_off(bytes)
        .map_err(|e| Error::from_parse(ScanFormat::Off, e))?;
    Ok(Scan::assemble(soup.positions, soup.normals, &soup.faces))
}
