// SPDX-License-Identifier: MIT
//! `hi bezier basis`: the control values of the thesis's piecewise Bézier basis (§5.7).

use hi_curve::bezier::BasisPieces;

use crate::cli::{BasisSchemeName, BezierBasisArgs};
use crate::error::{Failure, context};
use serde::Serialize;

use crate::output::{Json, json};

/// The largest n accepted: the output has pieces·n·(degree + 1) numbers.
const MAX_N: usize = 1024;

/// `{"n", "scheme", "degree", "breaks", "P": [a][k][j]}`.
///
/// # Errors
///
/// [`Failure::Input`] for n = 0, n > 1024, or n ≤ 2 with the quintic scheme.
pub(crate) fn run(args: &BezierBasisArgs) -> Result<Json, Failure> {
    if args.n > MAX_N {
        return Err(Failure::Input(format!("--n {} is too large: at most {MAX_N}", args.n)));
    }
    let (pieces, name) = match args.scheme {
        BasisSchemeName::ThesisCubic => (BasisPieces::thesis_cubic(args.n), "thesis-cubic"),
        BasisSchemeName::ThesisQuintic => (BasisPieces::thesis_quintic(args.n), "thesis-quintic"),
    };
    let pieces = pieces.map_err(context("--n"))?;
    /// `{"n", "scheme", "degree", "breaks", "P"}`: `P[a][k]` the Bernstein coefficients of σₖ
    /// on piece a.
    #[derive(Serialize)]
    struct Pieces<'a> {
        n: usize,
        scheme: &'a str,
        degree: usize,
        breaks: &'a [f64],
        #[serde(rename = "P")]
        p: Vec<Vec<&'a [f64]>>,
    }
    json(&Pieces {
        n: pieces.n(),
        scheme: name,
        degree: pieces.degree(),
        breaks: pieces.breaks(),
        p: (0..pieces.n_pieces())
            .map(|a| (0..pieces.n()).map(|k| pieces.control(a, k)).collect())
            .collect(),
    })
}
