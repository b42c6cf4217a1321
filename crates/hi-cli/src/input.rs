// SPDX-License-Identifier: MIT
//! Reading the points of a curve, or the grid of a surface, from a JSON file or stdin.
//!
//! Curves: `{"points": [...]}` or the bare array `[...]`, whose items are all points of one
//! dimension: arrays of 1, 2 or 3 numbers. A 1-D point may also be a bare number, so
//! `[1, 2, 3]` and `[[1], [2], [3]]` are the same three points.
//!
//! Surfaces: `{"grid": [[[x, y, z], ...], ...]}` or the bare array of rows, each row an array
//! of 3-D points, all rows of one length.
//!
//! Slices (`hi surface bspline-fit`): `{"slices": [[[x, y, z], ...], ...]}` or the bare array
//! of slices, each a list of 3-D points, of any lengths.

use std::io::Read;
use std::path::Path;

use glam::{DVec2, DVec3};
use hi_surface::HarmonicSurface;
use serde_json::Value;

use crate::error::Failure;

/// The name under which stdin is read (`--input -`) and shown in messages.
const STDIN_NAME: &str = "<stdin>";

/// The points of a curve, in the dimension the input gave them.
#[derive(Clone, Debug, PartialEq)]
pub enum Points {
    /// 1-D points.
    One(Vec<f64>),
    /// 2-D points.
    Two(Vec<DVec2>),
    /// 3-D points.
    Three(Vec<DVec3>),
}

/// Reads the points of the file at `path`, or of stdin when `path` is `-`.
///
/// # Errors
///
/// [`Failure::Input`] naming the file and the problem: unreadable file, malformed JSON, wrong
/// shape, mixed dimensions, no points.
pub(crate) fn read_points(path: &Path) -> Result<Points, Failure> {
    let (name, text) = read_text(path)?;
    parse_points(&text).map_err(|message| Failure::input(format!("{name}: {message}")))
}

/// Reads the grid of the file at `path` (or stdin for `-`) and builds its harmonic surface.
///
/// # Errors
///
/// [`Failure::Input`] naming the file and the problem: unreadable file, malformed JSON, wrong
/// shape, points that are not 3-D, a ragged or empty grid, a non-finite coordinate.
pub(crate) fn read_surface(path: &Path) -> Result<HarmonicSurface<DVec3>, Failure> {
    let (name, text) = read_text(path)?;
    let grid = parse_grid(&text).map_err(|message| Failure::input(format!("{name}: {message}")))?;
    HarmonicSurface::try_new(grid).map_err(|e| Failure::input(format!("{name}: {e}")))
}

/// The name of the input for messages and its text.
fn read_text(path: &Path) -> Result<(String, String), Failure> {
    if path.as_os_str() == "-" {
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| Failure::input(format!("{STDIN_NAME}: cannot read: {e}")))?;
        Ok((STDIN_NAME.to_owned(), text))
    } else {
        let name = path.display().to_string();
        match std::fs::read_to_string(path) {
            Ok(text) => Ok((name, text)),
            Err(e) => Err(Failure::input(format!("{name}: cannot read: {e}"))),
        }
    }
}

/// Parses the JSON text of a surface grid into rows of 3-D points (their lengths unchecked:
/// [`HarmonicSurface::try_new`] names a ragged row).
///
/// # Errors
///
/// A message naming the problem (without the file name).
pub fn parse_grid(text: &str) -> Result<Vec<Vec<DVec3>>, String> {
    parse_nested(text, "grid", "row")
}

/// Reads the slices of the file at `path` (or stdin for `-`): `{"slices": [[[x, y, z], ...],
/// ...]}` or the bare array of slices, each a list of 3-D points (of any lengths).
///
/// # Errors
///
/// [`Failure::Input`] naming the file and the problem: unreadable file, malformed JSON, wrong
/// shape, points that are not 3-D or not finite.
pub(crate) fn read_slices(path: &Path) -> Result<(String, Vec<Vec<DVec3>>), Failure> {
    let (name, text) = read_text(path)?;
    let slices = parse_nested(&text, "slices", "slice")
        .map_err(|message| Failure::input(format!("{name}: {message}")))?;
    Ok((name, slices))
}

/// Parses `{"KEY": [[p, ...], ...]}` or the bare array of lists of 3-D points; `row` names a
/// list in messages.
fn parse_nested(text: &str, key: &str, row: &str) -> Result<Vec<Vec<DVec3>>, String> {
    let value: Value = serde_json::from_str(text).map_err(|e| json_error(&e))?;
    let rows = match value {
        Value::Array(rows) => rows,
        Value::Object(mut map) => {
            if let Some(other) = map.keys().find(|k| *k != key) {
                return Err(format!(
                    "unknown key \"{other}\": the object must have the key \"{key}\" only"
                ));
            }
            match map.remove(key) {
                Some(Value::Array(rows)) => rows,
                Some(other) => {
                    return Err(format!(
                        "\"{key}\" must be an array of {row}s, found {}",
                        kind(&other)
                    ));
                }
                None => return Err(format!("the object has no key \"{key}\"")),
            }
        }
        other => {
            return Err(format!(
                "expected an array of {row}s of points or an object {{\"{key}\": [...]}}, found {}",
                kind(&other)
            ));
        }
    };
    rows.iter()
        .enumerate()
        .map(|(j, list)| {
            let Value::Array(points) = list else {
                return Err(format!("{row} {j} must be an array of points, found {}", kind(list)));
            };
            points
                .iter()
                .enumerate()
                .map(|(k, point)| {
                    let c = coordinates(k, point).map_err(|e| format!("{row} {j}: {e}"))?;
                    if c.len() == 3 {
                        Ok(DVec3::new(c[0], c[1], c[2]))
                    } else {
                        Err(format!(
                            "{row} {j}, point {k} has {} coordinates: surface points must have 3",
                            c.len()
                        ))
                    }
                })
                .collect()
        })
        .collect()
}

/// Parses the JSON text of a point list.
///
/// # Errors
///
/// A message naming the problem (without the file name).
pub fn parse_points(text: &str) -> Result<Points, String> {
    let value: Value = serde_json::from_str(text).map_err(|e| json_error(&e))?;
    let items = match value {
        Value::Array(items) => items,
        Value::Object(mut map) => {
            if let Some(key) = map.keys().find(|k| *k != "points") {
                return Err(format!(
                    "unknown key \"{key}\": the object must have the key \"points\" only"
                ));
            }
            match map.remove("points") {
                Some(Value::Array(items)) => items,
                Some(other) => {
                    return Err(format!("\"points\" must be an array, found {}", kind(&other)));
                }
                None => return Err("the object has no key \"points\"".to_owned()),
            }
        }
        other => {
            return Err(format!(
                "expected an array of points or an object {{\"points\": [...]}}, found {}",
                kind(&other)
            ));
        }
    };
    if items.is_empty() {
        return Err("no points given: at least one point is needed".to_owned());
    }
    let rows = items
        .iter()
        .enumerate()
        .map(|(i, item)| coordinates(i, item))
        .collect::<Result<Vec<_>, _>>()?;
    let dim = rows[0].len();
    if let Some((i, row)) = rows.iter().enumerate().find(|(_, row)| row.len() != dim) {
        return Err(format!("point {i} has {} coordinates, point 0 has {dim}", row.len()));
    }
    Ok(match dim {
        1 => Points::One(rows.iter().map(|r| r[0]).collect()),
        2 => Points::Two(rows.iter().map(|r| DVec2::new(r[0], r[1])).collect()),
        _ => Points::Three(rows.iter().map(|r| DVec3::new(r[0], r[1], r[2])).collect()),
    })
}

/// The coordinates of point `index`: 1 to 3 finite numbers.
fn coordinates(index: usize, item: &Value) -> Result<Vec<f64>, String> {
    let values: &[Value] = match item {
        Value::Number(_) => std::slice::from_ref(item),
        Value::Array(values) => values,
        other => {
            return Err(format!(
                "point {index} must be a number or an array of 1 to 3 numbers, found {}",
                kind(other)
            ));
        }
    };
    if !(1..=3).contains(&values.len()) {
        return Err(format!(
            "point {index} has {} coordinates: points must have 1, 2 or 3",
            values.len()
        ));
    }
    values
        .iter()
        .enumerate()
        .map(|(c, v)| match v.as_f64() {
            Some(x) if x.is_finite() => Ok(x),
            Some(x) => {
                Err(format!("point {index}, coordinate {c} is {x}: coordinates must be finite"))
            }
            None => {
                Err(format!("point {index}, coordinate {c} must be a number, found {}", kind(v)))
            }
        })
        .collect()
}

/// What a JSON value is, in words.
fn kind(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// A one-line message for a JSON syntax error, explaining overflowing numbers.
fn json_error(e: &serde_json::Error) -> String {
    let message = e.to_string();
    if message.starts_with("number out of range") {
        format!(
            "invalid JSON: {message} (a number too large for a double, which would be infinite: \
             coordinates must be finite)"
        )
    } else {
        format!("invalid JSON: {message}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Replays the fuzzing corpus of the JSON inputs (`fuzz/corpus/json_inputs`, from the
    /// campaign recorded in `docs/reliability.md`) as the fuzz target runs it: nothing may
    /// panic, what is read is finite, and the curve or surface the commands build from it
    /// evaluates to finite points.
    #[test]
    fn the_fuzzing_corpus_replays_without_a_failure() {
        use hi_curve::HarmonicCurve;
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus/json_inputs");
        if !dir.exists() {
            // A packaged crate leaves the fuzzing folder out (it is a package of its own).
            eprintln!("no fuzz corpus beside this crate: it is replayed in the repository");
            return;
        }
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .map(|entry| entry.expect("a corpus entry").path())
            .collect();
        files.sort();
        let (mut curves, mut surfaces) = (0, 0);
        for path in &files {
            let data = std::fs::read(path).expect("a corpus file");
            let Ok(text) = std::str::from_utf8(&data) else { continue };
            let name = path.display();
            if let Ok(points) = parse_points(text) {
                let finite = match points {
                    Points::One(p) => HarmonicCurve::try_new(p).map(|c| c.eval(0.37).is_finite()),
                    Points::Two(p) => HarmonicCurve::try_new(p).map(|c| c.eval(0.37).is_finite()),
                    Points::Three(p) => HarmonicCurve::try_new(p).map(|c| c.eval(0.37).is_finite()),
                };
                if let Ok(finite) = finite {
                    curves += 1;
                    assert!(finite, "{name}: a curve evaluates to a non-finite point");
                }
            }
            if let Ok(grid) = parse_grid(text) {
                assert!(grid.iter().flatten().all(|p| p.is_finite()), "{name}: non-finite texel");
                if let Ok(s) = HarmonicSurface::try_new(grid) {
                    surfaces += 1;
                    assert!(s.eval(0.37, 0.61).is_finite(), "{name}: non-finite surface point");
                }
            }
        }
        assert!(
            curves >= 3 && surfaces >= 2,
            "the corpus builds {curves} curves, {surfaces} surfaces"
        );
    }

    #[test]
    fn shapes() {
        assert_eq!(parse_points("[1, [2], 3.5]"), Ok(Points::One(vec![1.0, 2.0, 3.5])));
        assert_eq!(
            parse_points(r#"{"points": [[1, 2]]}"#),
            Ok(Points::Two(vec![DVec2::new(1.0, 2.0)]))
        );
        assert_eq!(parse_points("[[1, 2, 3]]"), Ok(Points::Three(vec![DVec3::new(1.0, 2.0, 3.0)])));
    }

    #[test]
    fn errors() {
        let err = |text: &str| parse_points(text).unwrap_err();
        assert_eq!(
            err("[[1,2,3],[1,2,3],[1,2,3],[1,2]]"),
            "point 3 has 2 coordinates, point 0 has 3"
        );
        assert_eq!(err("[]"), "no points given: at least one point is needed");
        assert!(err("[[1,2,3,4]]").contains("4 coordinates"), "dimension 4");
        assert!(err("[[]]").contains("0 coordinates"), "dimension 0");
        assert!(err("[1e999]").contains("number out of range"), "overflow");
        assert!(err(r#"{"pts": []}"#).contains("unknown key \"pts\""), "unknown key");
        assert!(err(r#"[["a"]]"#).contains("a string"), "string coordinate");
        assert!(err("7").contains("found a number"), "scalar");
    }

    #[test]
    fn grids() {
        let grid = parse_grid(r#"{"grid": [[[1, 2, 3], [4, 5, 6]]]}"#).unwrap();
        assert_eq!(grid, vec![vec![DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 5.0, 6.0)]]);
        assert_eq!(parse_grid("[[[0,0,0]]]").unwrap().len(), 1);
        let err = |text: &str| parse_grid(text).unwrap_err();
        assert_eq!(
            err("[[[0,0,0],[1,2]]]"),
            "row 0, point 1 has 2 coordinates: surface points must have 3"
        );
        assert!(err("[[1,2,3]]").contains("row 0, point 0"), "rows of points");
        assert!(err("[[[0,0,0]], 1]").contains("row 1 must be an array"), "a number as a row");
        assert!(err(r#"{"points": []}"#).contains("unknown key"), "wrong key");
        assert!(err("[[[0, 0, 1e999]]]").contains("number out of range"), "overflow");
    }
}
