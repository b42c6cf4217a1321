// SPDX-License-Identifier: MIT
//! Shared pieces of the text readers: numbered lines, tokens and numbers.

use super::ScanFormat;
use crate::Error;

/// The lines of `bytes` with their numbers (from 1), without the line ending (`\n`, `\r\n`).
pub(super) fn lines(bytes: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    bytes
        .split(|&b| b == b'\n')
        .map(|l| l.strip_suffix(b"\r").unwrap_or(l))
        .enumerate()
        .map(|(i, l)| (i + 1, l))
}

/// The tokens of a line: runs of bytes between spaces, tabs (and commas when `commas`).
pub(super) fn tokens(line: &[u8], commas: bool) -> impl Iterator<Item = &[u8]> {
    line.split(move |&b| {
        b == b' ' || b == b'\t' || b == b'\x0c' || b == b'\x0b' || (commas && b == b',')
    })
    .filter(|t| !t.is_empty())
}

/// `line` without a `#` comment and surrounding white space.
pub(super) fn strip_comment(line: &[u8]) -> &[u8] {
    let end = line.iter().position(|&b| b == b'#').unwrap_or(line.len());
    line[..end].trim_ascii()
}

/// A token as text, for messages (invalid UTF-8 shown with replacement characters, long
/// tokens shortened).
pub(super) fn show(token: &[u8]) -> String {
    let text = String::from_utf8_lossy(token);
    if text.chars().count() > 24 {
        format!("{}…", text.chars().take(24).collect::<String>())
    } else {
        text.into_owned()
    }
}

/// Parses a number; NaN and infinities parse (the caller drops such points and counts them).
pub(super) fn number(
    format: ScanFormat,
    line: usize,
    token: &[u8],
    what: &str,
) -> Result<f64, Error> {
    std::str::from_utf8(token).ok().and_then(|s| s.parse::<f64>().ok()).ok_or_else(|| {
        Error::line(format, line, format!("{what}: {:?} is not a number", show(token)))
    })
}

/// Parses a non-negative integer that fits `usize`.
pub(super) fn count(
    format: ScanFormat,
    line: usize,
    token: &[u8],
    what: &str,
) -> Result<usize, Error> {
    std::str::from_utf8(token).ok().and_then(|s| s.parse::<usize>().ok()).ok_or_else(|| {
        Error::line(format, line, format!("{what}: {:?} is not a whole number", show(token)))
    })
}

/// Checks that face index `k` is below `n`, as `u32`.
pub(super) fn index(format: ScanFormat, line: usize, k: usize, n: usize) -> Result<u32, Error> {
    if k >= n {
        return Err(Error::line(
            format,
            line,
            format!("face index {k} is out of range (the file has {n} points)"),
        ));
    }
    u32::try_from(k).map_err(|_| Error::line(format, line, "face index does not fit 32 bits"))
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
