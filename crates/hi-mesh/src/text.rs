// SPDX-License-Identifier: MIT
//! The tokenizer of the text mesh and point formats (OBJ, OFF, and `hi-scan`'s XYZ, PTS and
//! ASCII PLY): numbered lines, white-space separated tokens, `#` comments, numbers. It works on
//! bytes, so a file that is not UTF-8 is read as far as its records are ASCII, and it never
//! panics or allocates more than the input.
//!
//! # Examples
//!
//! ```
//! use hi_mesh::text::{lines, number, strip_comment, tokens};
//!
//! let file = b"v 1 2.5 -3 # a vertex\r\n\nf 1 2 3\n";
//! let (n, line) = lines(file).next().unwrap();
//! let fields: Vec<&[u8]> = tokens(strip_comment(line), false).collect();
//! assert_eq!((n, fields.len()), (1, 4));
//! assert_eq!(number(fields[2]), Some(2.5));
//! assert_eq!(lines(file).nth(2).map(|(n, _)| n), Some(3));
//! ```

/// The lines of `bytes` with their numbers (from 1), without the line ending (`\n`, `\r\n`).
pub fn lines(bytes: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    bytes
        .split(|&b| b == b'\n')
        .map(|l| l.strip_suffix(b"\r").unwrap_or(l))
        .enumerate()
        .map(|(i, l)| (i + 1, l))
}

/// The tokens of a line: runs of bytes between spaces, tabs, form and line feeds (and commas
/// when `commas`).
pub fn tokens(line: &[u8], commas: bool) -> impl Iterator<Item = &[u8]> {
    line.split(move |&b| {
        b == b' ' || b == b'\t' || b == b'\x0c' || b == b'\x0b' || (commas && b == b',')
    })
    .filter(|t| !t.is_empty())
}

/// `line` without a `#` comment and surrounding white space.
#[must_use]
pub fn strip_comment(line: &[u8]) -> &[u8] {
    let end = line.iter().position(|&b| b == b'#').unwrap_or(line.len());
    line[..end].trim_ascii()
}

/// A token as text, for messages (invalid UTF-8 shown with replacement characters, tokens
/// longer than 24 characters shortened with an ellipsis).
#[must_use]
pub fn show(token: &[u8]) -> String {
    let text = String::from_utf8_lossy(token);
    if text.chars().count() > 24 {
        format!("{}…", text.chars().take(24).collect::<String>())
    } else {
        text.into_owned()
    }
}

/// The number a token spells (Rust's `f64` syntax: NaN and infinities parse, so that a reader
/// can decide what to do with them), or `None`.
#[must_use]
pub fn number(token: &[u8]) -> Option<f64> {
    std::str::from_utf8(token).ok()?.parse().ok()
}

/// The non-negative whole number a token spells, if it fits `usize`, or `None`.
#[must_use]
pub fn count(token: &[u8]) -> Option<usize> {
    std::str::from_utf8(token).ok()?.parse().ok()
}
