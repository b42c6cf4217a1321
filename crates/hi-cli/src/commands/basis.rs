// SPDX-License-Identifier: MIT
//! `hi basis`: σⁿₖ(t) and its derivatives.

use hi_curve::{Error, Sigma};
use hi_interval::{Interval, RootOptions, Verdict};

use crate::cli::{BasisArgs, BasisCommand, RootsArgs};
use crate::error::{Failure, context};
use serde::Serialize;

use crate::output::{Derivatives, Json, json};

/// `{"sigma": [...], "d1": [...], ...}` for the basis function σⁿₖ at each t.
///
/// # Errors
///
/// [`Failure::Input`] if n = 0 or k ≥ n.
pub(crate) fn run(args: &BasisArgs) -> Result<Json, Failure> {
    if let Some(BasisCommand::Roots(roots)) = &args.command {
        return run_roots(roots);
    }
    // clap makes --n, --k and --t required unless a subcommand is given.
    let (Some(n), Some(k), Some(t)) = (args.n, args.k, args.t.as_ref()) else {
        return Err(Failure::Input("hi basis needs --n, --k and --t (or a subcommand)".into()));
    };
    let sigma = Sigma::try_new(n).map_err(context("--n"))?;
    if k >= n {
        return Err(context("--k")(Error::IndexOutOfRange { k, n }));
    }
    let ts = &t.0;
    /// `{"sigma": [...], "d1": [...], ...}`.
    #[derive(Serialize)]
    struct Values {
        sigma: Vec<f64>,
        #[serde(flatten)]
        derivatives: Derivatives<Vec<f64>>,
    }
    json(&Values {
        sigma: ts.iter().map(|&t| sigma.eval(k, t)).collect(),
        derivatives: Derivatives(
            (1..=args.derivatives)
                .map(|order| ts.iter().map(|&t| sigma.deriv(k, t, order)).collect())
                .collect(),
        ),
    })
}

/// `{"roots": [[lo, hi], ...], "unique": [...], "verdicts": [...], "complete": c}`: the zeros
/// of the D-th derivative of σⁿ on [0, 1] (§5.6).
///
/// # Errors
///
/// [`Failure::Input`] unless 1 ≤ n ≤ 4096 and D ≤ 16.
fn run_roots(args: &RootsArgs) -> Result<Json, Failure> {
    let sigma = Sigma::try_new(args.n).map_err(context("--n"))?;
    if args.n > 4096 {
        return Err(Failure::Input(format!(
            "--n: {} is too large for the root search (at most 4096)",
            args.n
        )));
    }
    if args.derivative > 16 {
        return Err(Failure::Input(format!(
            "--derivative: {} is too large (at most 16)",
            args.derivative
        )));
    }
    let found =
        sigma.deriv_roots(args.derivative, Interval::new(0.0, 1.0), &RootOptions::default());
    /// `{"roots": [[lo, hi], ...], "unique": [...], "verdicts": [...], "complete": bool}`.
    #[derive(Serialize)]
    struct Found {
        roots: Vec<Interval>,
        unique: Vec<bool>,
        verdicts: Vec<Verdict>,
        complete: bool,
    }
    json(&Found {
        roots: found.roots.iter().map(|r| r.enclosure).collect(),
        unique: found.roots.iter().map(|r| r.verdict == Verdict::Unique).collect(),
        verdicts: found.roots.iter().map(|r| r.verdict).collect(),
        complete: found.complete,
    })
}
