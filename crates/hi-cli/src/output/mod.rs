// SPDX-License-Identifier: MIT
//! The JSON that `hi` prints: objects with keys in a fixed order, numbers in shortest
//! round-trip form, and non-finite numbers spelled out instead of silently becoming `null`.
//!
//! * A finite number is printed by `serde_json`'s float formatter: the shortest decimal that
//!   reads back to the same double, so parsing the output recovers every bit (including −0.0).
//! * A non-finite number (a derivative of very high order overflows, for instance) is printed
//!   as one of the strings `"Infinity"`, `"-Infinity"` or `"NaN"`, which JavaScript's `Number()`,
//!   Python's `float()` and `numpy.array(..., dtype=float)` all read back.
//! * `null` means "undefined here": the curvature or torsion at a singular point.
//!
//! Every output is a value whose type derives `Serialize`: each command's own output struct,
//! embedding the libraries' report types (their `serde` feature), so a field's name is the
//! name of the field it prints. [`json()`] writes it by `serde_json` (keys in the order of the
//! fields) through [`Spelled`](finite::Spelled), which spells out the non-finite numbers, into
//! a [`Json`], which [`write_json`] prints, compact or indented.

use std::io::{self, Write};

use hi_curve::ControlPoint;
use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::value::RawValue;

mod finite;

use finite::Spelled;

/// A JSON value as `hi` prints it: its compact text, written by the rules above (it may be
/// embedded in another output, and is written as it is).
#[derive(Clone, Debug)]
pub(crate) struct Json(Box<RawValue>);

/// A point as the array of its coordinates (a 1-D point is `[x]`), for output structs.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Coords<'a, P>(pub(crate) &'a P);

impl<P: ControlPoint> Serialize for Coords<'_, P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq((0..P::DIM).map(|i| self.0.coord(i)))
    }
}

/// Points as an array of coordinate arrays, for output structs.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PointList<'a, P>(pub(crate) &'a [P]);

impl<P: ControlPoint> Serialize for PointList<'_, P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0.iter().map(Coords))
    }
}

/// The coordinates of a point (`[x]` in 1-D).
pub(crate) fn coords<P: ControlPoint>(p: &P) -> Vec<f64> {
    (0..P::DIM).map(|i| p.coord(i)).collect()
}

/// `{"points": [...]}`: the output of the commands that return a new polygon.
#[derive(Debug, serde::Serialize)]
#[serde(bound = "P: ControlPoint")]
pub(crate) struct PointsOutput<'a, P: ControlPoint> {
    /// The points.
    pub(crate) points: PointList<'a, P>,
}

/// Checks, before any work, that `path` (given as `flag`) can be written: its folder exists and
/// the file can be opened for writing. A file made only by the check is removed again; an
/// existing file is left untouched.
///
/// # Errors
///
/// [`Failure::Input`](crate::error::Failure::Input) naming the flag, the path and the reason
/// (no such folder, permission denied, a folder in the way).
pub(crate) fn check_writable(
    path: &std::path::Path,
    flag: &str,
) -> Result<(), crate::error::Failure> {
    let fail = |why: String| {
        crate::error::Failure::input(format!("{flag} {}: cannot write: {why}", path.display()))
    };
    if path.is_dir() {
        return Err(fail("it is a folder".to_owned()));
    }
    let existed = path.exists();
    std::fs::OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(false)
        .open(path)
        .map_err(|e| fail(e.to_string()))?;
    if !existed {
        std::fs::remove_file(path).map_err(|e| fail(e.to_string()))?;
    }
    Ok(())
}

/// The names of the files a command wrote, as printed in its `"files"` array.
pub(crate) fn file_names(files: &[std::path::PathBuf]) -> Vec<String> {
    files.iter().map(|f| f.display().to_string()).collect()
}

/// Values keyed `d1`, `d2`, … in order (the derivatives of a command's output); flattened
/// into the output struct with `#[serde(flatten)]`.
#[derive(Clone, Debug)]
pub(crate) struct Derivatives<T>(pub(crate) Vec<T>);

impl<T: Serialize> Serialize for Derivatives<T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (i, value) in self.0.iter().enumerate() {
            map.serialize_entry(&format!("d{}", i + 1), value)?;
        }
        map.end()
    }
}

/// The [`Json`] of a command's output struct.
///
/// # Errors
///
/// [`Failure::Output`](crate::error::Failure::Output) if the value has no JSON form (a map
/// keyed by something other than a string or number): a bug in the output struct, reported
/// rather than panicking.
pub(crate) fn json<T: Serialize + ?Sized>(value: &T) -> Result<Json, crate::error::Failure> {
    serde_json::value::to_raw_value(&Spelled(value))
        .map(Json)
        .map_err(|e| crate::error::Failure::Output(io::Error::other(e.to_string())))
}

impl Json {
    /// The JSON text, to embed in another output.
    pub(crate) fn into_raw(self) -> Box<RawValue> {
        self.0
    }
}

impl Serialize for Json {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.0.serialize(serializer)
    }
}

/// Writes `json` and a newline to `out`, indented if `pretty`.
///
/// # Errors
///
/// Any I/O error of `out`.
pub(crate) fn write_json(out: &mut impl Write, json: &Json, pretty: bool) -> io::Result<()> {
    if pretty {
        // Read back and written indented, in the same order; every number reads back to the
        // double it was written from, and is written again the same.
        let mut from = serde_json::Deserializer::from_str(json.0.get());
        let mut to = serde_json::Serializer::pretty(&mut *out);
        serde_transcode::transcode(&mut from, &mut to)?;
    } else {
        out.write_all(json.0.get().as_bytes())?;
    }
    out.write_all(b"\n")?;
    out.flush()
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use super::*;

    fn text(json: &Json, pretty: bool) -> String {
        let mut out = Vec::new();
        write_json(&mut out, json, pretty).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn numbers_round_trip_and_non_finite_are_strings() {
        /// Fields out of alphabetical order, to show that the order is kept.
        #[derive(serde::Serialize)]
        struct Values {
            b: Vec<f64>,
            a: Vec<Option<f64>>,
            n: Vec<i64>,
            f: [f32; 2],
        }
        let values = Values {
            b: vec![0.1, -0.0, 1e300, f64::INFINITY, f64::NEG_INFINITY, f64::NAN],
            a: vec![None, Some(1.0)],
            n: vec![-3, 0, i64::MAX],
            f: [0.1, f32::NAN],
        };
        let compact = "{\"b\":[0.1,-0.0,1e+300,\"Infinity\",\"-Infinity\",\"NaN\"],\"a\":[null,1.0],\"n\":[-3,0,9223372036854775807],\"f\":[0.1,\"NaN\"]}";
        assert_eq!(text(&json(&values).unwrap(), false), format!("{compact}\n"));
        // Indented: the same values (serde_json's own pretty form of the same text).
        let pretty = text(&json(&values).unwrap(), true);
        let reread: serde_json::Value = serde_json::from_str(&pretty).unwrap();
        assert_eq!(reread, serde_json::from_str::<serde_json::Value>(compact).unwrap());
        assert!(pretty.starts_with("{\n  \"b\": [\n    0.1,\n    -0.0,"), "{pretty}");
        let points = [1.5, -2.0];
        assert_eq!(
            text(&json(&PointsOutput { points: PointList(&points) }).unwrap(), false),
            "{\"points\":[[1.5],[-2.0]]}\n"
        );
    }

    #[derive(serde::Serialize)]
    #[serde(rename_all = "snake_case")]
    enum Shape {
        Unit,
        Newtype(f64),
        Tuple(u8, i32),
        Struct { side: f32 },
    }

    #[derive(serde::Serialize)]
    struct Report {
        b: Vec<Shape>,
        a: Option<f64>,
        counts: (usize, i64),
        keys: BTreeMap<u32, bool>,
        infinite: f64,
        inner: Option<Json>,
    }

    #[test]
    fn the_output_is_serde_jsons_with_non_finite_numbers_spelled() {
        let report = Report {
            b: vec![
                Shape::Unit,
                Shape::Newtype(f64::NAN),
                Shape::Tuple(1, -2),
                Shape::Struct { side: 0.25 },
            ],
            a: None,
            counts: (3, -4),
            keys: BTreeMap::from([(7, true)]),
            infinite: f64::NEG_INFINITY,
            inner: Some(json(&[f64::INFINITY]).unwrap()),
        };
        let ours = text(&json(&report).unwrap(), false);
        assert_eq!(
            ours,
            "{\"b\":[\"unit\",{\"newtype\":\"NaN\"},{\"tuple\":[1,-2]},{\"struct\":{\"side\":0.25}}],\"a\":null,\"counts\":[3,-4],\"keys\":{\"7\":true},\"infinite\":\"-Infinity\",\"inner\":[\"Infinity\"]}\n"
        );
        // serde_json writes the same text, except that it turns NaN and ±∞ into null.
        let theirs = serde_json::to_string(&report).unwrap();
        let nulled = ours.trim_end().replace("\"-Infinity\"", "null").replace("\"NaN\"", "null");
        assert_eq!(nulled, theirs);
        let map = BTreeMap::from([(vec![1u8], 1.0)]);
        assert!(json(&map).is_err(), "a map keyed by a sequence has no JSON form");
    }
}
