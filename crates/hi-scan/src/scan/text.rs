// SPDX-License-Identifier: MIT
//! Shared pieces of the text readers: numbered lines, tokens and numbers (the tokenizer of
//! [`hi_mesh::text`], with this crate's errors).

use super::ScanFormat;
use crate::Error;

pub(super) use hi_mesh::text::{lines, show, strip_comment, tokens};

/// Parses a number; NaN and infinities parse (the caller drops such points and counts them).
pub(super) fn number(
    format: ScanFormat,
    line: usize,
    token: &[u8],
    what: &str,
) -> Result<f64, Error> {
    hi_mesh::text::number(token).ok_or_else(|| {
        Error::line(format, line, format!("{what}: {:?} is not a number", show(token)))
    })
}

/// Three coordinates from the next three tokens, or an error naming how many were found.
pub(super) fn point<'a>(
    format: ScanFormat,
    line: usize,
    tokens: &mut impl Iterator<Item = &'a [u8]>,
    what: &str,
) -> Result<glam::DVec3, Error> {
    let mut xyz = [0.0; 3];
    for (i, c) in xyz.iter_mut().enumerate() {
        let Some(t) = tokens.next() else {
            return Err(Error::line(
                format,
                line,
                format!("expected 3 coordinates {what}, found {i}"),
            ));
        };
        *c = number(format, line, t, "coordinate")?;
    }
    Ok(glam::DVec3::from_array(xyz))
}
