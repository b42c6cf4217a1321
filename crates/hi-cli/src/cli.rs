// SPDX-License-Identifier: MIT
//! The command line of `hi`: subcommands, options and their help texts.

use std::path::PathBuf;

use clap::{Args, CommandFactory, Parser, Subcommand, ValueEnum};

use crate::args::{
    FloatList, parse_count, parse_derivatives, parse_finite, parse_float_list, parse_levels,
    parse_whole,
};

/// The input and output conventions, shown by `hi --help`.
const MAIN_HELP: &str = "\
Curve commands: hi curve eval|sample|rotate|resample|subdivide|nonuniform --input FILE ...
  (see 'hi curve --help' and 'hi curve eval --help', for instance).

Input (--input FILE, or --input - for stdin):
  {\"points\": [[x, y], ...]}   or the bare array   [[x, y], ...]
  Points are arrays of 1, 2 or 3 numbers, all of one dimension; a 1-D point may also be a
  bare number, so [0, 1, 0.5] is three 1-D points. With n points, the harmonic curve X(t)
  passes through point k at t = k/n and is smooth and 1-periodic.

Output (stdout): one JSON object on one line, e.g. {\"X\": [[x, y], ...]}
  Points are arrays of coordinates ([x] for 1-D). Numbers are the shortest decimals that read
  back to the same double. A non-finite result (an overflowing high derivative) is printed as
  the string \"Infinity\", \"-Infinity\" or \"NaN\"; null means undefined (the curvature or
  torsion at a singular point). --pretty indents the output.

Exit status: 0 on success; 2 on bad input or a bad command line, with one line \"hi: ...\" on
stderr; 1 if the output could not be written (silently if the reader closed the pipe).";

/// The output of `hi basis`.
const BASIS_HELP: &str = "\
Output: {\"sigma\": [σ(t1), σ(t2), ...], \"d1\": [...], ..., \"dD\": [...]}
  dp holds the p-th derivative of σⁿₖ at each t (from its cosine sum).
Example: hi basis --n 3 --k 0 --t 0,0.5   prints   {\"sigma\":[1.0,-0.3333333333333333]}";

/// Prefixes a curve subcommand's help text with the input shape.
macro_rules! curve_help {
    ($text:literal) => {
        concat!(
            "Input: {\"points\": [[x, y], ...]} or [[x, y], ...]: n points of 1, 2 or 3 coordinates\n",
            "  (a 1-D point may be a bare number); --input - reads stdin. See 'hi --help'.\n",
            $text
        )
    };
}

/// The output of `hi curve eval`.
const EVAL_HELP: &str = curve_help!(
    "\
Output: {\"X\": [[x, y], ...], \"d1\": [[...], ...], ..., \"curvature\": [...], \"torsion\": [...]}
  X holds X(t) at each t, dp the p-th derivative X⁽ᵖ⁾(t) (only with --derivatives).
  1-D: no curvature. 2-D: \"curvature\" is the signed curvature (positive turning left).
  3-D: \"curvature\" is the unsigned curvature, and \"torsion\" is added.
  Curvature or torsion is null where it is undefined (X′ = 0, or X′ × X″ = 0 for torsion).
Example: echo '[[1,0],[0,1],[-1,0],[0,-1]]' | hi curve eval --input - --t 0.125"
);

/// The output of `hi curve sample`.
const SAMPLE_HELP: &str = curve_help!(
    "\
Output: {\"X\": [[x, y], ...]} with the N points X(0), X(1/N), ..., X((N-1)/N).
Example: hi curve sample --input square.json --count 8"
);

/// The output of `hi curve rotate`.
const ROTATE_HELP: &str = curve_help!(
    "\
Output: {\"points\": [[x, y], ...]}
  Without --exact: the n points X(j/n + O) of Theorem 5.1. For odd n their curve is X(t + O);
  for even n it is not (the theorem fails there), unless n·O is a whole number or the
  alternating sum of the points is zero (a regular polygon, for instance).
  With --exact: points whose harmonic curve is exactly X(t + O); for even n there are n + 1.
Example: hi curve rotate --input square.json --offset 0.1 --exact"
);

/// The output of `hi curve resample`.
const RESAMPLE_HELP: &str = curve_help!(
    "\
Output: {\"points\": [[x, y], ...], \"max_error\": e, \"error_bound\": b}
  The N points X(j/N) (Theorem 5.3). For N ≥ n their curve is X itself and e = b = 0. For
  N < n (reduction) e is max |X(t) − Y(t)| measured on a fine grid and b a guaranteed bound,
  where Y is the curve through the N new points.
Example: hi curve resample --input square.json --count 3"
);

/// The output of `hi curve subdivide`.
const SUBDIVIDE_HELP: &str = curve_help!(
    "\
Output: {\"points\": [[x, y], ...]}: the n·2^L points X(i/(n·2^L)) of harmonic subdivision
  (§5.2) after L levels; the original point k is copied exactly to index k·2^L.
Example: hi curve subdivide --input square.json --levels 1"
);

/// The output of `hi curve nonuniform`.
const NONUNIFORM_HELP: &str = curve_help!(
    "\
Output: {\"params\": [...], \"X\": [[x, y], ...], \"condition\": c, \"matrix_condition\": m}
  params: the parameter of each point (closed chord-length unless --params is given).
  X: the curve at each t. condition: the Lebesgue constant of the interpolation (moving the
  points by δ moves the curve by at most c·δ). matrix_condition (thesis variant only): the
  1-norm condition number of the thesis's Vandermonde matrix.
Variants: nodes passes through point k at t = params[k] (1-periodic); thesis is §3.10's
  formula as printed, which passes through point k at t = k/(n−1) instead.
Example: hi curve nonuniform --input pts.json --t 0,0.5 --variant nodes --params 0,0.1,0.5,0.7"
);

/// Harmonic interpolation for smooth curves (A. Hardy, 2005), with JSON in and out.
#[derive(Debug, Parser)]
#[command(name = "hi", version, after_help = MAIN_HELP, arg_required_else_help = false)]
pub(crate) struct Cli {
    /// Indent the JSON output.
    #[arg(long, global = true)]
    pub(crate) pretty: bool,
    /// What to compute.
    #[command(subcommand)]
    pub(crate) command: Command,
}

/// The top-level subcommands.
#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Values and derivatives of the harmonic basis function σⁿₖ.
    #[command(after_help = BASIS_HELP)]
    Basis(BasisArgs),
    /// The harmonic curve through points read from a JSON file.
    #[command(subcommand, after_help = MAIN_HELP, arg_required_else_help = false)]
    Curve(CurveCommand),
}

/// The subcommands of `hi curve`.
#[derive(Debug, Subcommand)]
pub(crate) enum CurveCommand {
    /// The curve, its derivatives, curvature and torsion at parameters t.
    #[command(after_help = EVAL_HELP)]
    Eval(EvalArgs),
    /// N uniform samples X(l/N), by FFT.
    #[command(after_help = SAMPLE_HELP)]
    Sample(SampleArgs),
    /// Points of the curve rotated by an offset in t (Theorem 5.1, or exact).
    #[command(after_help = ROTATE_HELP)]
    Rotate(RotateArgs),
    /// N points on the curve: insertion (N ≥ n, exact) or reduction (N < n) (Theorem 5.3).
    #[command(after_help = RESAMPLE_HELP)]
    Resample(ResampleArgs),
    /// Harmonic subdivision: each level doubles the points (§5.2).
    #[command(after_help = SUBDIVIDE_HELP)]
    Subdivide(SubdivideArgs),
    /// A curve through the points at non-uniform parameters (§3.10).
    #[command(after_help = NONUNIFORM_HELP)]
    Nonuniform(NonUniformArgs),
}

/// Options of `hi basis`.
#[derive(Debug, Args)]
pub(crate) struct BasisArgs {
    /// Number of basis functions n (at least 1).
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) n: usize,
    /// Index k of the basis function (0 ≤ k < n).
    #[arg(long, value_name = "K", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) k: usize,
    /// Parameters t, comma-separated (e.g. 0,0.25,-1.5).
    #[arg(long, value_name = "T1,T2,...", allow_hyphen_values = true, value_parser = parse_float_list)]
    pub(crate) t: FloatList,
    /// Also print the derivatives of orders 1 to D (D ≤ 1024).
    #[arg(long, value_name = "D", default_value = "0", allow_negative_numbers = true, value_parser = parse_derivatives)]
    pub(crate) derivatives: usize,
}

/// The input file option shared by the curve subcommands.
#[derive(Debug, Args)]
pub(crate) struct InputArg {
    /// JSON file with the points ("-" reads stdin); see 'hi --help' for its shape.
    #[arg(long, value_name = "FILE")]
    pub(crate) input: PathBuf,
}

/// Options of `hi curve eval`.
#[derive(Debug, Args)]
pub(crate) struct EvalArgs {
    /// Where the points come from.
    #[command(flatten)]
    pub(crate) input: InputArg,
    /// Parameters t, comma-separated (e.g. 0,0.25,-1.5).
    #[arg(long, value_name = "T1,T2,...", allow_hyphen_values = true, value_parser = parse_float_list)]
    pub(crate) t: FloatList,
    /// Also print the derivatives of orders 1 to D (D ≤ 1024).
    #[arg(long, value_name = "D", default_value = "0", allow_negative_numbers = true, value_parser = parse_derivatives)]
    pub(crate) derivatives: usize,
}

/// Options of `hi curve sample`.
#[derive(Debug, Args)]
pub(crate) struct SampleArgs {
    /// Where the points come from.
    #[command(flatten)]
    pub(crate) input: InputArg,
    /// Number of samples N (1 ≤ N ≤ 2^28).
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = parse_count)]
    pub(crate) count: usize,
}

/// Options of `hi curve rotate`.
#[derive(Debug, Args)]
pub(crate) struct RotateArgs {
    /// Where the points come from.
    #[command(flatten)]
    pub(crate) input: InputArg,
    /// The offset O in t: the new curve is X(t + O).
    #[arg(long, value_name = "O", allow_negative_numbers = true, value_parser = parse_finite)]
    pub(crate) offset: f64,
    /// Exact rotation for every n (n + 1 points for even n) instead of Theorem 5.1 as stated.
    #[arg(long)]
    pub(crate) exact: bool,
}

/// Options of `hi curve resample`.
#[derive(Debug, Args)]
pub(crate) struct ResampleArgs {
    /// Where the points come from.
    #[command(flatten)]
    pub(crate) input: InputArg,
    /// Number of new points N (1 ≤ N ≤ 2^28).
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = parse_count)]
    pub(crate) count: usize,
}

/// Options of `hi curve subdivide`.
#[derive(Debug, Args)]
pub(crate) struct SubdivideArgs {
    /// Where the points come from.
    #[command(flatten)]
    pub(crate) input: InputArg,
    /// Number of levels L; the result has n·2^L ≤ 2^28 points.
    #[arg(long, value_name = "L", allow_negative_numbers = true, value_parser = parse_levels)]
    pub(crate) levels: u32,
}

/// Options of `hi curve nonuniform`.
#[derive(Debug, Args)]
pub(crate) struct NonUniformArgs {
    /// Where the points come from.
    #[command(flatten)]
    pub(crate) input: InputArg,
    /// Parameters t at which to evaluate, comma-separated.
    #[arg(long, value_name = "T1,T2,...", allow_hyphen_values = true, value_parser = parse_float_list)]
    pub(crate) t: FloatList,
    /// Which reading of §3.10.
    #[arg(long, value_enum)]
    pub(crate) variant: Variant,
    /// The parameter of each point, distinct, in [0, 1), comma-separated [default: closed chord length].
    #[arg(long, value_name = "P0,P1,...", allow_hyphen_values = true, value_parser = parse_float_list)]
    pub(crate) params: Option<FloatList>,
}

/// The subcommand path that a command line names, such as `hi curve eval`: where to point
/// for help when the command line is wrong. Options and their values are skipped.
pub(crate) fn command_path(args: impl IntoIterator<Item = String>) -> String {
    let mut command = Cli::command();
    let mut path = vec![command.get_name().to_owned()];
    for arg in args.into_iter().skip(1) {
        let Some(sub) = command.find_subcommand(&arg).cloned() else {
            if arg.starts_with('-') {
                continue;
            }
            break;
        };
        path.push(sub.get_name().to_owned());
        command = sub;
    }
    path.join(" ")
}

/// The two readings of §3.10.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum Variant {
    /// The thesis's final formula as printed (interpolates at t = k/(n−1)).
    Thesis,
    /// True interpolation at the parameters (barycentric trigonometric interpolation).
    Nodes,
}

impl From<Variant> for hi_curve::NonUniformVariant {
    fn from(v: Variant) -> Self {
        match v {
            Variant::Thesis => hi_curve::NonUniformVariant::Thesis,
            Variant::Nodes => hi_curve::NonUniformVariant::Nodes,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn command_line_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn command_paths() {
        let path = |line: &str| command_path(line.split(' ').map(str::to_owned));
        assert_eq!(path("hi --pretty curve eval --input x"), "hi curve eval");
        assert_eq!(path("hi curve eval --input curve"), "hi curve eval");
        assert_eq!(path("hi basis --n 3"), "hi basis");
        assert_eq!(path("hi frob curve"), "hi");
    }
}
