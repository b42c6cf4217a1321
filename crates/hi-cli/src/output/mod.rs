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
//! name of the field it prints. [`to_json()`] turns it into a [`Json`] tree, which
//! [`write_json`] prints by the rules above.

use std::io::{self, Write};

use hi_curve::ControlPoint;
use serde::ser::{Serialize, SerializeMap, SerializeSeq, Serializer};

mod to_json;

pub(crate) use to_json::to_json;

/// A JSON value as `hi` prints it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Json {
    /// `null`: a value that is undefined (a singular point).
    Null,
    /// A number; non-finite ones are printed as strings (see the module documentation).
    Number(f64),
    /// A whole number, printed without a decimal point.
    Integer(i128),
    /// `true` or `false`.
    Bool(bool),
    /// A string.
    String(String),
    /// An array.
    Array(Vec<Json>),
    /// An object, with its keys in the order given.
    Object(Vec<(String, Json)>),
}

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
    to_json(value).map_err(|e| crate::error::Failure::Output(io::Error::other(e.to_string())))
}

impl Serialize for Json {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Json::Null => serializer.serialize_unit(),
            Json::Number(x) if x.is_finite() => serializer.serialize_f64(*x),
            Json::Number(x) if x.is_nan() => serializer.serialize_str("NaN"),
            Json::Number(x) if *x > 0.0 => serializer.serialize_str("Infinity"),
            Json::Number(_) => serializer.serialize_str("-Infinity"),
            Json::Integer(n) => match (u64::try_from(*n), i64::try_from(*n)) {
                (Ok(n), _) => serializer.serialize_u64(n),
                (_, Ok(n)) => serializer.serialize_i64(n),
                _ => serializer.serialize_i128(*n),
            },
            Json::String(text) => serializer.serialize_str(text),
            Json::Bool(b) => serializer.serialize_bool(*b),
            Json::Array(items) => {
                let mut seq = serializer.serialize_seq(Some(items.len()))?;
                for item in items {
                    seq.serialize_element(item)?;
                }
                seq.end()
            }
            Json::Object(fields) => {
                let mut map = serializer.serialize_map(Some(fields.len()))?;
                for (key, value) in fields {
                    map.serialize_entry(key, value)?;
                }
                map.end()
            }
        }
    }
}

/// Writes `json` and a newline to `out`, indented if `pretty`.
///
/// # Errors
///
/// Any I/O error of `out`.
pub(crate) fn write_json(out: &mut impl Write, json: &Json, pretty: bool) -> io::Result<()> {
    if pretty {
        serde_json::to_writer_pretty(&mut *out, json)?;
    } else {
        serde_json::to_writer(&mut *out, json)?;
    }
    out.write_all(b"\n")?;
    out.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(json: &Json) -> String {
        let mut out = Vec::new();
        write_json(&mut out, json, false).unwrap();
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
        }
        let values = Values {
            b: vec![0.1, -0.0, 1e300, f64::INFINITY, f64::NEG_INFINITY, f64::NAN],
            a: vec![None, Some(1.0)],
            n: vec![-3, 0, i64::MAX],
        };
        assert_eq!(
            text(&to_json(&values).unwrap()),
            "{\"b\":[0.1,-0.0,1e+300,\"Infinity\",\"-Infinity\",\"NaN\"],\"a\":[null,1.0],\"n\":[-3,0,9223372036854775807]}\n"
        );
        let points = [1.5, -2.0];
        assert_eq!(
            text(&to_json(&PointsOutput { points: PointList(&points) }).unwrap()),
            "{\"points\":[[1.5],[-2.0]]}\n"
        );
    }
}
