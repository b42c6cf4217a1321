// SPDX-License-Identifier: MIT
//! XYZ point files (`x y z [nx ny nz]` per line) and Hoppe's PTS files (`p x y z` lines).

use glam::DVec3;

use super::text::{lines, number, point, strip_comment, tokens};
use super::{Scan, ScanFormat};
use crate::Error;

/// Reads an XYZ file: every non-blank line (after removing a `#` comment) holds 3 numbers, or
/// 6 (a point and its normal); all lines must have the same count.
pub(super) fn parse_xyz(bytes: &[u8]) -> Result<Scan, Error> {
    const F: ScanFormat = ScanFormat::Xyz;
    let mut points = Vec::new();
    let mut normals = Vec::new();
    let mut width: Option<(usize, usize)> = None; // (numbers per line, first line)
    for (n, raw) in lines(bytes) {
        let line = strip_comment(raw);
        if line.is_empty() {
            continue;
        }
        let values: Vec<&[u8]> = tokens(line, true).collect();
        if values.len() != 3 && values.len() != 6 {
            return Err(Error::line(
                F,
                n,
                format!("expected 3 numbers (x y z) or 6 (x y z nx ny nz), found {}", values.len()),
            ));
        }
        match width {
            None => width = Some((values.len(), n)),
            Some((w, first)) if w != values.len() => {
                return Err(Error::line(
                    F,
                    n,
                    format!("{} numbers, but line {first} has {w}", values.len()),
                ));
            }
            Some(_) => {}
        }
        let mut it = values.into_iter();
        points.push(point(F, n, &mut it, "")?);
        if it.len() == 3 {
            normals.push(point(F, n, &mut it, "of the normal")?);
        }
    }
    let normals = (!normals.is_empty()).then_some(normals);
    Ok(Scan::assemble(points, normals, &[]))
}

/// Reads a PTS file: `p x y z` lines are points; every other line is skipped.
pub(super) fn parse_pts(bytes: &[u8]) -> Result<Scan, Error> {
    const F: ScanFormat = ScanFormat::Pts;
    let mut points = Vec::new();
    for (n, raw) in lines(bytes) {
        let mut it = tokens(raw, false);
        if it.next() != Some(b"p".as_slice()) {
            continue;
        }
        let rest: Vec<&[u8]> = it.collect();
        if rest.len() != 3 {
            return Err(Error::line(
                F,
                n,
                format!("expected 3 coordinates after `p`, found {}", rest.len()),
            ));
        }
        let xyz: Result<Vec<f64>, _> = rest.iter().map(|t| number(F, n, t, "coordinate")).collect();
        let xyz = xyz?;
        points.push(DVec3::new(xyz[0], xyz[1], xyz[2]));
    }
    Ok(Scan::assemble(points, None, &[]))
}
