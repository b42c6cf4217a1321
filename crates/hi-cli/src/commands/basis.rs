// SPDX-License-Identifier: MIT
//! `hi basis`: σⁿₖ(t) and its derivatives.

use hi_curve::{Error, Sigma};

use crate::cli::BasisArgs;
use crate::error::{Failure, context};
use crate::output::{Json, Object};

/// `{"sigma": [...], "d1": [...], ...}` for the basis function σⁿₖ at each t.
///
/// # Errors
///
/// [`Failure::Input`] if n = 0 or k ≥ n.
pub(crate) fn run(args: &BasisArgs) -> Result<Json, Failure> {
    let sigma = Sigma::try_new(args.n).map_err(context("--n"))?;
    let k = args.k;
    if k >= args.n {
        return Err(context("--k")(Error::IndexOutOfRange { k, n: args.n }));
    }
    let ts = &args.t.0;
    let mut out = Object::new().field("sigma", Json::numbers(ts.iter().map(|&t| sigma.eval(k, t))));
    for order in 1..=args.derivatives {
        out.push(format!("d{order}"), Json::numbers(ts.iter().map(|&t| sigma.deriv(k, t, order))));
    }
    Ok(out.build())
}
