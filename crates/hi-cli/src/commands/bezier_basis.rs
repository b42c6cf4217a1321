// SPDX-License-Identifier: MIT
//! `hi bezier basis`: the control values of the thesis's piecewise Bézier basis (§5.7).

use hi_curve::bezier::BasisPieces;

use crate::cli::{BasisSchemeName, BezierBasisArgs};
use crate::error::{Failure, context};
use crate::output::{Json, Object};

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
    let p = (0..pieces.n_pieces())
        .map(|a| {
            Json::Array(
                (0..pieces.n())
                    .map(|k| Json::numbers(pieces.control(a, k).iter().copied()))
                    .collect(),
            )
        })
        .collect();
    Ok(Object::new()
        .field("n", Json::Count(pieces.n()))
        .field("scheme", Json::String(name.to_owned()))
        .field("degree", Json::Count(pieces.degree()))
        .field("breaks", Json::numbers(pieces.breaks().iter().copied()))
        .field("P", Json::Array(p))
        .build())
}
