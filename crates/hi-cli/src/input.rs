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
//!
//! Patches (`hi render`): the file of `hi surface bezier`, `{"patches": [{"control": [[[x, y,
//! z], ...], ...], ...}, ...], ...}`, each patch's control rows handed to
//! [`BezierPatch::try_new`].
//!
//! Each is read by `serde` (the shapes below, whose JSON schemas are in `docs/schemas/`) and
//! handed to the libraries' checked constructors; an error names where it is (`point 3,
//! coordinate 1: …`, `row 2, point 0 has 2 coordinates …`).

use std::io::Read;
use std::path::Path;

use std::fmt;
use std::marker::PhantomData;

use glam::{DVec2, DVec3};
use hi_bezier::BezierPatch;
use hi_surface::HarmonicSurface;
use serde::Deserialize;
use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
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

/// The coordinates of a point as given: a number (a 1-D point) or an array of numbers (their
/// count is checked by the caller, who knows which point it is).
#[derive(Debug)]
struct Coords(Vec<f64>);

impl<'de> Deserialize<'de> for Coords {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct CoordsVisitor;
        impl<'de> Visitor<'de> for CoordsVisitor {
            type Value = Coords;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number or an array of 1 to 3 numbers")
            }
            fn visit_f64<E: de::Error>(self, x: f64) -> Result<Coords, E> {
                Ok(Coords(vec![x]))
            }
            fn visit_i64<E: de::Error>(self, x: i64) -> Result<Coords, E> {
                Ok(Coords(vec![x as f64]))
            }
            fn visit_u64<E: de::Error>(self, x: u64) -> Result<Coords, E> {
                Ok(Coords(vec![x as f64]))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Coords, A::Error> {
                let mut c = Vec::with_capacity(3);
                while let Some(Number(x)) = seq.next_element()? {
                    if !x.is_finite() {
                        return Err(de::Error::custom(format!("{x}: coordinates must be finite")));
                    }
                    c.push(x);
                }
                Ok(Coords(c))
            }
        }
        deserializer.deserialize_any(CoordsVisitor)
    }
}

/// A coordinate: a JSON number.
struct Number(f64);

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct NumberVisitor;
        impl Visitor<'_> for NumberVisitor {
            type Value = Number;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number")
            }
            fn visit_f64<E: de::Error>(self, x: f64) -> Result<Number, E> {
                Ok(Number(x))
            }
            fn visit_i64<E: de::Error>(self, x: i64) -> Result<Number, E> {
                Ok(Number(x as f64))
            }
            fn visit_u64<E: de::Error>(self, x: u64) -> Result<Number, E> {
                Ok(Number(x as f64))
            }
        }
        deserializer.deserialize_f64(NumberVisitor)
    }
}

/// A list of items given bare (`[...]`) or as the object `{"KEY": [...]}` with that key only.
struct Listed<T> {
    key: &'static str,
    item: &'static str,
    marker: PhantomData<T>,
}

impl<'de, T: Deserialize<'de>> DeserializeSeed<'de> for Listed<T> {
    type Value = Vec<T>;
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<Vec<T>, D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de, T: Deserialize<'de>> Visitor<'de> for Listed<T> {
    type Value = Vec<T>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "an array of {}s or an object {{\"{}\": [...]}}", self.item, self.key)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<T>, A::Error> {
        let mut items = Vec::new();
        while let Some(item) = seq.next_element()? {
            items.push(item);
        }
        Ok(items)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Vec<T>, A::Error> {
        let mut items = None;
        while let Some(key) = map.next_key::<String>()? {
            if key != self.key || items.is_some() {
                return Err(de::Error::custom(format!(
                    "unknown key \"{key}\": the object must have the key \"{}\" only",
                    self.key
                )));
            }
            items = Some(map.next_value::<Vec<T>>()?);
        }
        items.ok_or_else(|| de::Error::custom(format!("the object has no key \"{}\"", self.key)))
    }
}

/// Reads `text` by `seed`; an error names where it is, each array index by the word in
/// `names` for its depth (`row 2, point 0, coordinate 1: …`).
fn read_json<'de, S: DeserializeSeed<'de>>(
    text: &'de str,
    seed: S,
    names: &[&str],
) -> Result<S::Value, String> {
    let mut json = serde_json::Deserializer::from_str(text);
    let mut track = serde_path_to_error::Track::new();
    let value = seed
        .deserialize(serde_path_to_error::Deserializer::new(&mut json, &mut track))
        .and_then(|value| json.end().map(|()| value));
    value.map_err(|e| {
        let path = track.path();
        let at = place(&path, names);
        let message = json_error(&e);
        if at.is_empty() { message } else { format!("{at}: {message}") }
    })
}

/// The path of a value in words: array indices named by depth, object keys quoted.
fn place(path: &serde_path_to_error::Path, names: &[&str]) -> String {
    use serde_path_to_error::Segment;
    let segments: Vec<&Segment> = path.iter().collect();
    let mut depth = 0;
    let mut words = Vec::new();
    for (i, segment) in segments.iter().enumerate() {
        match segment {
            Segment::Seq { index } => {
                let name = names.get(depth).copied().unwrap_or("item");
                words.push(format!("{name} {index}"));
                depth += 1;
            }
            Segment::Map { key } if depth > 0 || i + 1 == segments.len() => {
                words.push(format!("\"{key}\""));
            }
            Segment::Map { .. } => {}
            Segment::Enum { variant } => words.push(variant.clone()),
            Segment::Unknown => words.push("?".to_owned()),
        }
    }
    words.join(", ")
}

/// Parses `{"KEY": [[p, ...], ...]}` or the bare array of lists of 3-D points; `row` names a
/// list in messages.
fn parse_nested(
    text: &str,
    key: &'static str,
    row: &'static str,
) -> Result<Vec<Vec<DVec3>>, String> {
    let seed = Listed::<Vec<Coords>> { key, item: row, marker: PhantomData };
    let rows = read_json(text, seed, &[row, "point", "coordinate"])?;
    rows.into_iter()
        .enumerate()
        .map(|(j, points)| {
            points
                .into_iter()
                .enumerate()
                .map(|(k, Coords(c))| match c[..] {
                    [x, y, z] => Ok(DVec3::new(x, y, z)),
                    _ => Err(format!(
                        "{row} {j}, point {k} has {} coordinates: surface points must have 3",
                        c.len()
                    )),
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
    let seed = Listed::<Coords> { key: "points", item: "point", marker: PhantomData };
    let rows = read_json(text, seed, &["point", "coordinate"])?;
    let Some(first) = rows.first() else {
        return Err("no points given: at least one point is needed".to_owned());
    };
    if let Some((i, Coords(c))) =
        rows.iter().enumerate().find(|(_, c)| !(1..=3).contains(&c.0.len()))
    {
        return Err(format!("point {i} has {} coordinates: points must have 1, 2 or 3", c.len()));
    }
    let dim = first.0.len();
    if let Some((i, row)) = rows.iter().enumerate().find(|(_, row)| row.0.len() != dim) {
        return Err(format!("point {i} has {} coordinates, point 0 has {dim}", row.0.len()));
    }
    Ok(match dim {
        1 => Points::One(rows.iter().map(|r| r.0[0]).collect()),
        2 => Points::Two(rows.iter().map(|r| DVec2::new(r.0[0], r.0[1])).collect()),
        _ => Points::Three(rows.iter().map(|r| DVec3::new(r.0[0], r.0[1], r.0[2])).collect()),
    })
}

/// The patches file of `hi surface bezier` (its other keys, the breaks and the report, are
/// not needed to draw the patches).
#[derive(Deserialize, schemars::JsonSchema)]
pub(crate) struct PatchesFile {
    /// The patches.
    patches: Vec<PatchIn>,
}

/// One patch: its control points, rows along u (its other keys, the window and degrees, are
/// not needed).
#[derive(Deserialize, schemars::JsonSchema)]
struct PatchIn {
    /// The control points [x, y, z], rows along u, all rows of one length.
    control: Vec<Vec<[f64; 3]>>,
}

/// The Bézier patches of a `hi surface bezier` patches file, each through
/// [`BezierPatch::try_new`].
///
/// # Errors
///
/// A message naming the patch (`patches[2].control[0][1]: …`) and the problem.
pub(crate) fn parse_patches(value: Value) -> Result<Vec<BezierPatch<DVec3>>, String> {
    let file: PatchesFile = serde_path_to_error::deserialize(value)
        .map_err(|e| format!("{}: {}", e.path(), e.inner()))?;
    file.patches
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let rows = p.control.into_iter().map(|r| r.into_iter().map(DVec3::from).collect());
            BezierPatch::try_new(rows.collect()).map_err(|e| format!("patches[{i}]: {e}"))
        })
        .collect()
}

/// A one-line message for a JSON error, explaining overflowing numbers.
fn json_error(e: &serde_json::Error) -> String {
    let message = e.to_string();
    let syntax = e.is_syntax() || e.is_eof();
    if message.starts_with("number out of range") {
        format!(
            "invalid JSON: {message} (a number too large for a double, which would be infinite: \
             coordinates must be finite)"
        )
    } else if syntax {
        format!("invalid JSON: {message}")
    } else {
        message
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
        assert_eq!(
            err(r#"[[1], ["a"]]"#),
            "point 1, coordinate 0: invalid type: string \"a\", expected a number at line 1 column 10"
        );
        assert!(err("7").starts_with("invalid type: integer `7`, expected an array"), "scalar");
        assert!(err(r#"{"points": 7}"#).starts_with("\"points\": invalid type"), "not a list");
        assert!(err("[1, 2] x").starts_with("invalid JSON: trailing characters"), "trailing");
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
        assert!(
            err("[[[0,0,0]], 1]").starts_with("row 1: invalid type: integer"),
            "a number as a row"
        );
        assert!(err(r#"{"points": []}"#).contains("unknown key"), "wrong key");
        assert!(err("[[[0, 0, 1e999]]]").contains("number out of range"), "overflow");
    }
}
