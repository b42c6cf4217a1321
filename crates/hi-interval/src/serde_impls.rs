// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`): an [`Interval`] is the pair `[lo, hi]`.
//!
//! JSON has no infinity, so an unbounded side is written `null` (`[null, 1.0]` is `[−∞, 1]`);
//! the empty interval is `[]`. Reading checks what [`Interval::try_new`] checks: `[2.0, 1.0]`
//! is an error, not an empty interval read silently. An [`IntervalMatrix`] is its rows; ragged
//! rows are an error.

use serde::de::{Deserialize, Deserializer, Error as _};
use serde::ser::{Serialize, SerializeSeq, Serializer};

use crate::{Interval, IntervalMatrix};

impl Serialize for Interval {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        if self.is_empty() {
            return serializer.serialize_seq(Some(0))?.end();
        }
        let bound = |x: f64| if x.is_finite() { Some(x) } else { None };
        let mut seq = serializer.serialize_seq(Some(2))?;
        seq.serialize_element(&bound(self.lo()))?;
        seq.serialize_element(&bound(self.hi()))?;
        seq.end()
    }
}

impl<'de> Deserialize<'de> for Interval {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let bounds = Vec::<Option<f64>>::deserialize(deserializer)?;
        match bounds[..] {
            [] => Ok(Interval::EMPTY),
            [lo, hi] => {
                Interval::try_new(lo.unwrap_or(f64::NEG_INFINITY), hi.unwrap_or(f64::INFINITY))
                    .map_err(D::Error::custom)
            }
            _ => Err(D::Error::invalid_length(
                bounds.len(),
                &"an interval [lo, hi], or [] when empty",
            )),
        }
    }
}

impl Serialize for IntervalMatrix {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.n_rows()))?;
        for i in 0..self.n_rows() {
            let row: Vec<Interval> = (0..self.n_cols()).map(|j| self.get(i, j)).collect();
            seq.serialize_element(&row)?;
        }
        seq.end()
    }
}

impl<'de> Deserialize<'de> for IntervalMatrix {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let rows = Vec::<Vec<Interval>>::deserialize(deserializer)?;
        let n_cols = rows.first().map_or(0, Vec::len);
        if let Some(i) = rows.iter().position(|row| row.len() != n_cols) {
            return Err(D::Error::custom(format!(
                "row {i} of the interval matrix has {} entries, row 0 has {n_cols}",
                rows[i].len()
            )));
        }
        Ok(IntervalMatrix::from_rows(rows))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trip(x: Interval) -> Interval {
        serde_json::from_str(&serde_json::to_string(&x).unwrap()).unwrap()
    }

    #[test]
    fn intervals_read_back_bit_for_bit() {
        for x in [
            Interval::new(0.1, 0.3),
            Interval::point(-0.0),
            Interval::new(f64::NEG_INFINITY, 2.0),
            Interval::ENTIRE,
            Interval::EMPTY,
            Interval::PI,
        ] {
            let back = round_trip(x);
            assert_eq!(back.is_empty(), x.is_empty(), "{x:?}");
            if !x.is_empty() {
                assert_eq!(back.lo().to_bits(), x.lo().to_bits(), "{x:?}");
                assert_eq!(back.hi().to_bits(), x.hi().to_bits(), "{x:?}");
            }
        }
        assert_eq!(serde_json::to_string(&Interval::new(1.0, 2.0)).unwrap(), "[1.0,2.0]");
        assert_eq!(serde_json::to_string(&Interval::ENTIRE).unwrap(), "[null,null]");
        assert_eq!(serde_json::to_string(&Interval::EMPTY).unwrap(), "[]");
    }

    #[test]
    fn matrices_are_their_rows() {
        let m = IntervalMatrix::from_rows(vec![
            vec![Interval::new(0.0, 1.0), Interval::ONE],
            vec![Interval::ZERO, Interval::new(-2.0, f64::INFINITY)],
        ]);
        let text = serde_json::to_string(&m).unwrap();
        // A zero lower bound is −0 (the invariant of `Interval`).
        assert_eq!(text, "[[[-0.0,1.0],[1.0,1.0]],[[-0.0,0.0],[-2.0,null]]]");
        assert_eq!(serde_json::from_str::<IntervalMatrix>(&text).unwrap(), m);
        assert!(serde_json::from_str::<IntervalMatrix>("[[[0.0,1.0]],[]]").is_err());
    }

    #[test]
    fn reversed_or_malformed_bounds_are_errors() {
        for bad in ["[2.0, 1.0]", "[1.0]", "[1.0, 2.0, 3.0]", "\"x\""] {
            assert!(serde_json::from_str::<Interval>(bad).is_err(), "{bad}");
        }
    }
}
