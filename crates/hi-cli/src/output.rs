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

use std::io::{self, Write};

use hi_curve::ControlPoint;
use serde::ser::{Serialize, SerializeMap, SerializeSeq, Serializer};

/// A JSON value as `hi` prints it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Json {
    /// `null`: a value that is undefined (a singular point).
    Null,
    /// A number; non-finite ones are printed as strings (see the module documentation).
    Number(f64),
    /// A whole number (a count), printed without a decimal point.
    Count(usize),
    /// `true` or `false`.
    Bool(bool),
    /// A string.
    String(String),
    /// An array.
    Array(Vec<Json>),
    /// An object, with its keys in the order given.
    Object(Vec<(String, Json)>),
}

impl Json {
    /// An array of numbers.
    pub(crate) fn numbers(values: impl IntoIterator<Item = f64>) -> Self {
        Json::Array(values.into_iter().map(Json::Number).collect())
    }

    /// An array of numbers that may be undefined (`None` is `null`).
    pub(crate) fn optional_numbers(values: impl IntoIterator<Item = Option<f64>>) -> Self {
        Json::Array(values.into_iter().map(|v| v.map_or(Json::Null, Json::Number)).collect())
    }

    /// A point as the array of its coordinates (a 1-D point is `[x]`).
    pub(crate) fn point<P: ControlPoint>(p: &P) -> Self {
        Json::numbers((0..P::DIM).map(|i| p.coord(i)))
    }

    /// An array of points.
    pub(crate) fn points<P: ControlPoint>(points: &[P]) -> Self {
        Json::Array(points.iter().map(Json::point).collect())
    }
}

/// Builds a [`Json::Object`] field by field, keeping the order.
#[derive(Debug, Default)]
pub(crate) struct Object(Vec<(String, Json)>);

impl Object {
    /// An empty object.
    pub(crate) fn new() -> Self {
        Self::default()
    }

    /// Adds the field `key: value`.
    #[must_use]
    pub(crate) fn field(mut self, key: impl Into<String>, value: Json) -> Self {
        self.push(key, value);
        self
    }

    /// Adds the field `key: value` in place.
    pub(crate) fn push(&mut self, key: impl Into<String>, value: Json) {
        self.0.push((key.into(), value));
    }

    /// The finished object.
    pub(crate) fn build(self) -> Json {
        Json::Object(self.0)
    }
}

impl Serialize for Json {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Json::Null => serializer.serialize_unit(),
            Json::Number(x) if x.is_finite() => serializer.serialize_f64(*x),
            Json::Number(x) if x.is_nan() => serializer.serialize_str("NaN"),
            Json::Number(x) if *x > 0.0 => serializer.serialize_str("Infinity"),
            Json::Number(_) => serializer.serialize_str("-Infinity"),
            Json::Count(n) => serializer.serialize_u64(*n as u64),
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
        let json = Object::new()
            .field(
                "b",
                Json::numbers([0.1, -0.0, 1e300, f64::INFINITY, f64::NEG_INFINITY, f64::NAN]),
            )
            .field("a", Json::optional_numbers([None, Some(1.0)]))
            .build();
        assert_eq!(
            text(&json),
            "{\"b\":[0.1,-0.0,1e+300,\"Infinity\",\"-Infinity\",\"NaN\"],\"a\":[null,1.0]}\n"
        );
    }
}
