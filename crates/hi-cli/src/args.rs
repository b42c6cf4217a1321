// SPDX-License-Identifier: MIT
//! Parsers for the values of command-line options: finite numbers, comma-separated lists,
//! counts, derivative orders, curve kinds, grid sizes and parameter windows.

use hi_compare::CurveKind;
use hi_geomimage::regularise::Regularisation;

/// Highest derivative order `--derivatives` accepts. Above it every derivative of a
/// non-constant basis function or curve has overflowed: its size grows like (2π)ᵖ ≥ 10⁸¹⁷.
pub(crate) const MAX_DERIVATIVES: usize = 1024;

/// A comma-separated list of finite numbers, such as `0,0.25,-1.5`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct FloatList(pub(crate) Vec<f64>);

/// Parses one finite number.
///
/// # Errors
///
/// A message if `s` is not a number or is NaN or infinite (also `1e999`, which overflows).
pub(crate) fn parse_finite(s: &str) -> Result<f64, String> {
    let trimmed = s.trim();
    match trimmed.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(format!("'{trimmed}' is not a finite number")),
        Err(_) if trimmed.is_empty() => Err("a number is missing".to_owned()),
        Err(_) => Err(format!("'{trimmed}' is not a number")),
    }
}

/// Parses a comma-separated list of finite numbers (at least one).
///
/// # Errors
///
/// A message naming the first bad item (counted from 0).
pub(crate) fn parse_float_list(s: &str) -> Result<FloatList, String> {
    if s.trim().is_empty() {
        return Err("the list is empty: give at least one number".to_owned());
    }
    s.split(',')
        .enumerate()
        .map(|(i, item)| parse_finite(item).map_err(|e| format!("item {i}: {e}")))
        .collect::<Result<Vec<_>, _>>()
        .map(FloatList)
}

/// Parses a whole number ≥ 0 (`--n`, `--k`).
///
/// # Errors
///
/// A message if `s` is not a whole number (negative numbers included).
pub(crate) fn parse_whole(s: &str) -> Result<usize, String> {
    s.trim().parse::<usize>().map_err(|_| format!("'{}' is not a whole number ≥ 0", s.trim()))
}

/// Parses a number of subdivision levels (`--levels`).
///
/// # Errors
///
/// A message if `s` is not a whole number ≥ 0 that fits in 32 bits.
pub(crate) fn parse_levels(s: &str) -> Result<u32, String> {
    s.trim().parse::<u32>().map_err(|_| format!("'{}' is not a whole number ≥ 0", s.trim()))
}

/// Parses a count that must be at least 1 (`--count`).
///
/// # Errors
///
/// A message if `s` is not a whole number or is 0.
pub(crate) fn parse_count(s: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(0) => Err("must be at least 1".to_owned()),
        Ok(n) => Ok(n),
        Err(_) => Err(format!("'{}' is not a whole number ≥ 1", s.trim())),
    }
}

/// Parses a derivative order, 0 ≤ D ≤ [`MAX_DERIVATIVES`] (`--derivatives`).
///
/// # Errors
///
/// A message if `s` is not a whole number or is too large.
pub(crate) fn parse_derivatives(s: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(d) if d <= MAX_DERIVATIVES => Ok(d),
        Ok(_) => Err(format!(
            "at most {MAX_DERIVATIVES} (beyond that every derivative of a non-constant curve overflows)"
        )),
        Err(_) => Err(format!("'{}' is not a whole number ≥ 0", s.trim())),
    }
}

/// Parses a curve kind (`--kind`), such as `bspline-periodic`.
///
/// # Errors
///
/// A message listing the valid names.
pub(crate) fn parse_kind(s: &str) -> Result<CurveKind, String> {
    s.trim().parse::<CurveKind>().map_err(|e| e.to_string())
}

/// A grid size or resolution `AxB`, such as `128x128`: two whole numbers ≥ 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Size(pub(crate) usize, pub(crate) usize);

/// Parses a size `AxB` (`--resolution`, `--samples`); `×` and `X` may stand for `x`.
///
/// # Errors
///
/// A message if `s` is not two whole numbers ≥ 1 joined by `x`.
pub(crate) fn parse_size(s: &str) -> Result<Size, String> {
    let trimmed = s.trim();
    let parts: Vec<&str> = trimmed.split(['x', 'X', '×']).collect();
    let [a, b] = parts[..] else {
        return Err(format!("'{trimmed}' is not a size like 128x128"));
    };
    let count = |part: &str| {
        parse_count(part).map_err(|e| format!("'{trimmed}' is not a size like 128x128: {e}"))
    };
    Ok(Size(count(a)?, count(b)?))
}

/// Parses `hi fit --regularise`: `auto`, `off`, `gcv`, `noise=S` or a weight W, S and W
/// finite and ≥ 0.
///
/// # Errors
///
/// A message naming the problem.
pub(crate) fn parse_regularisation(s: &str) -> Result<Regularisation, String> {
    let number = |x: &str| match x.parse::<f64>() {
        Ok(w) if w >= 0.0 && w.is_finite() => Ok(w),
        _ => Err(format!("'{}' is not auto, off, gcv, noise=S or a weight W (S, W ≥ 0)", s.trim())),
    };
    match s.trim() {
        "auto" => Ok(Regularisation::Auto),
        "off" => Ok(Regularisation::Off),
        "gcv" => Ok(Regularisation::Gcv),
        other => match other.strip_prefix("noise=") {
            Some(level) => Ok(Regularisation::Noise(number(level)?)),
            None => Ok(Regularisation::Weight(number(other)?)),
        },
    }
}

/// A parameter window u0 < u1, v0 < v1 (`--window`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Window(pub(crate) [f64; 4]);

/// Parses a window `u0,u1,v0,v1` of finite numbers with u0 < u1 and v0 < v1.
///
/// # Errors
///
/// A message naming the problem.
pub(crate) fn parse_window(s: &str) -> Result<Window, String> {
    let FloatList(values) = parse_float_list(s)?;
    let [u0, u1, v0, v1] = values[..] else {
        return Err(format!("expected 4 numbers u0,u1,v0,v1, got {}", values.len()));
    };
    if u0 >= u1 || v0 >= v1 {
        return Err(format!("need u0 < u1 and v0 < v1, got u in [{u0}, {u1}], v in [{v0}, {v1}]"));
    }
    Ok(Window([u0, u1, v0, v1]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists() {
        assert_eq!(parse_float_list("0, 0.25,-1.5"), Ok(FloatList(vec![0.0, 0.25, -1.5])));
        assert_eq!(parse_float_list("0,nan").unwrap_err(), "item 1: 'nan' is not a finite number");
        assert_eq!(
            parse_float_list("1e999").unwrap_err(),
            "item 0: '1e999' is not a finite number"
        );
        assert_eq!(parse_float_list("1,,2").unwrap_err(), "item 1: a number is missing");
        assert!(parse_float_list(" ").is_err(), "empty list");
        assert!(parse_float_list("x").is_err(), "not a number");
    }

    #[test]
    fn counts() {
        assert_eq!(parse_count("3"), Ok(3));
        assert!(parse_count("0").is_err(), "zero");
        assert!(parse_count("-1").is_err(), "negative");
        assert_eq!(parse_derivatives("0"), Ok(0));
        assert!(parse_derivatives("1025").is_err(), "too many");
    }

    #[test]
    fn kinds_sizes_and_windows() {
        assert_eq!(parse_kind("tcb"), Ok(CurveKind::Tcb));
        assert!(parse_kind("spline").unwrap_err().contains("bspline-open"), "lists the names");
        assert_eq!(parse_size("128x64"), Ok(Size(128, 64)));
        assert_eq!(parse_size("24×4"), Ok(Size(24, 4)));
        assert!(parse_size("0x4").is_err(), "zero");
        assert!(parse_size("12").is_err(), "one number");
        assert!(parse_size("1x2x3").is_err(), "three numbers");
        assert_eq!(parse_window("0,0.5,-1,1"), Ok(Window([0.0, 0.5, -1.0, 1.0])));
        assert!(parse_window("0,1,0").is_err(), "three numbers");
        assert!(parse_window("1,0,0,1").is_err(), "empty u window");
    }
}
