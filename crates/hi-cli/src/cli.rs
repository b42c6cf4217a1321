// SPDX-License-Identifier: MIT
//! The command line of `hi`: subcommands and options (their help texts are in `help`).

use std::path::PathBuf;

use clap::{Args, CommandFactory, Parser, Subcommand, ValueEnum};
use hi_compare::CurveKind;
use hi_curve::bezier::BezierScheme;

use crate::args::{
    FloatList, Size, Window, parse_count, parse_derivatives, parse_finite, parse_float_list,
    parse_kind, parse_levels, parse_regularisation, parse_size, parse_whole, parse_window,
};
use hi_geomimage::regularise::Regularisation;

use crate::help::*;

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
    /// The harmonic surface through a grid of points: evaluation, meshes, examples.
    #[command(subcommand, after_help = SURFACE_HELP, arg_required_else_help = false)]
    Surface(SurfaceCommand),
    /// Subdivision surfaces of §4.5: refine a polygon mesh by a classic scheme.
    #[command(after_help = SUBDIVIDE_MESH_HELP)]
    Subdivide(SubdivideMeshArgs),
    /// Fit a harmonic surface to a scan through a geometry image, or by cross-sections (§5.3, §5.4, §5.8).
    #[command(after_help = FIT_HELP)]
    Fit(FitArgs),
    /// Bézier forms of the harmonic basis (§5.7).
    #[command(subcommand)]
    Bezier(BezierCommand),
    /// Ray-trace a scene, or one surface or mesh file, to a PNG image (§5.5, §5.6).
    #[command(after_help = RENDER_HELP)]
    Render(RenderArgs),
}

/// How `hi render` draws a harmonic grid (`--method` and a scene file's `"method"`).
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, ValueEnum, serde::Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub(crate) enum RenderMethod {
    /// C1 Hermite Bézier patches within 1e-4 of the grid's size, Newton on the patches.
    Bezier,
    /// The surface itself by interval Newton (the Krawczyk operator); `interval` is a
    /// deprecated alias.
    #[value(alias = "interval")]
    #[serde(alias = "interval")]
    Krawczyk,
    /// The surface itself by interval bisection.
    Bisection,
    /// A 256×256 triangle mesh of the surface.
    Mesh,
}

/// Options of `hi render`.
#[derive(Debug, Args)]
pub(crate) struct RenderArgs {
    /// The scene file (JSON; see below).
    #[arg(value_name = "SCENE", required_unless_present = "quick", conflicts_with = "quick")]
    pub(crate) scene: Option<PathBuf>,
    /// Render this grid, patches or mesh file alone, framed automatically.
    #[arg(long, value_name = "FILE")]
    pub(crate) quick: Option<PathBuf>,
    /// With --quick: how a harmonic grid is drawn.
    #[arg(long, value_enum, default_value = "bezier")]
    pub(crate) method: RenderMethod,
    /// With --quick: colour a harmonic grid (krawczyk, bisection, mesh) by this curvature.
    #[arg(long, value_enum, value_name = "CURVATURE")]
    pub(crate) curvature: Option<ColorBy>,
    /// With --curvature: the colours (coolwarm keeps the sign).
    #[arg(long, value_enum, default_value = "thesis", requires = "curvature")]
    pub(crate) palette: PaletteName,
    /// Image width in pixels [default: the scene's, else 512].
    #[arg(long, value_name = "W", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) width: Option<usize>,
    /// Image height in pixels [default: the scene's, else 512].
    #[arg(long, value_name = "H", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) height: Option<usize>,
    /// Samples per pixel [default: the scene's, else 4].
    #[arg(long, value_name = "S", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) spp: Option<usize>,
    /// The PNG file to write.
    #[arg(short = 'o', long = "output", value_name = "OUT.png")]
    pub(crate) output: PathBuf,
}

/// The subcommands of `hi bezier`.
#[derive(Debug, Subcommand)]
pub(crate) enum BezierCommand {
    /// The control values `P[a][k][j]` of σₖ on piece a of a thesis scheme (§5.7).
    #[command(after_help = BEZIER_BASIS_HELP)]
    Basis(BezierBasisArgs),
}

/// The thesis schemes of `hi bezier basis`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum BasisSchemeName {
    /// One cubic per interval [a/n, (a+1)/n] through 4 equally spaced samples (C0).
    ThesisCubic,
    /// Two quintic Hermite pieces between consecutive zeros of σ′.
    ThesisQuintic,
}

/// Options of `hi bezier basis`.
#[derive(Debug, Args)]
pub(crate) struct BezierBasisArgs {
    /// Number of basis functions n (1 to 1024; the quintic scheme needs n ≥ 3).
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) n: usize,
    /// The scheme.
    #[arg(long, value_enum, default_value = "thesis-cubic")]
    pub(crate) scheme: BasisSchemeName,
}

/// The geometry-image layouts of `hi fit`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum ParamName {
    /// Latitude–longitude rays over a doubled meridian (algorithm 2).
    Sphere,
    /// The octahedral square, wrapped as it is (seams at its edges, as in figure 5.19).
    Octahedron,
    /// The octahedral square extended by its symmetry (seamless).
    FlatOctahedron,
    /// No geometry image: algorithm 1's cross-sections (§5.3).
    Sections,
}

/// How `hi fit` makes its geometry image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum MethodName {
    /// The mesh's spherical parameterisation when the scan is a mesh that closes to genus 0,
    /// the points shrink-wrapped otherwise.
    Auto,
    /// A spherical parameterisation of the scan's mesh (any shape; handles are cut).
    Mesh,
    /// A surface wrapped onto the points: the zero set of their signed distance, parameterised
    /// over the sphere, projected onto them and pulled into the creases it bridged (for point
    /// sets).
    ShrinkWrap,
    /// Rays from the centre, the distance along each averaged over the points about it
    /// (algorithm 2).
    Radial,
    /// Rays from the centre, each keeping the scan point it located; rows made contours by
    /// Theorem 5.3 (§5.8 "combined results").
    Contours,
}

/// The slicing axes of `hi fit --param sections`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum AxisName {
    /// Sections perpendicular to x.
    X,
    /// Sections perpendicular to y.
    Y,
    /// Sections perpendicular to z.
    Z,
    /// Sections perpendicular to the direction of largest variance.
    Principal,
}

/// The contour orders of `hi fit --param sections`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum OrderName {
    /// By polar angle about the section's centroid.
    Angular,
    /// Greedy nearest-neighbour chaining.
    Nearest,
}

/// The output formats of `hi fit --out-dir`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum FormatName {
    /// Binary glTF.
    Glb,
    /// glTF with its .bin.
    Gltf,
    /// Wavefront OBJ.
    Obj,
    /// The surfaces' grids, for 'hi surface'.
    Json,
}

/// Options of `hi fit`.
#[derive(Debug, Args)]
pub(crate) struct FitArgs {
    /// The scan: .obj, .ply, .off, .stl, .xyz (.pwn), .pts, .gltf or .glb (every mesh the scene places,
    /// in world space); with --out-dir, any number of scans, folders of scans and quoted globs.
    #[arg(value_name = "SCAN", required = true, num_args = 1..)]
    pub(crate) scans: Vec<PathBuf>,
    /// The output: a mesh of each part's surface (.glb, .gltf, .obj; several parts as one scene
    /// of named meshes) or the surfaces' grids (.json, for 'hi surface').
    #[arg(short = 'o', long = "output", value_name = "OUT", required_unless_present = "out_dir")]
    pub(crate) output: Option<PathBuf>,
    /// Fit every scan into DIR/NAME.FORMAT, in parallel, and append one JSON line per scan to
    /// DIR/summary.jsonl; scans already done there are skipped.
    #[arg(long, value_name = "DIR", conflicts_with_all = ["output", "report", "bezier"])]
    pub(crate) out_dir: Option<PathBuf>,
    /// With --out-dir: the format of the outputs [default: glb].
    #[arg(long, value_enum)]
    pub(crate) format: Option<FormatName>,
    /// With --out-dir: fit again the scans already done.
    #[arg(long)]
    pub(crate) force: bool,
    /// With --out-dir: scans fitted at once [default: the number of cores].
    #[arg(long, value_name = "N", value_parser = parse_whole)]
    pub(crate) jobs: Option<usize>,
    /// The geometry image's layout (or algorithm 1's cross-sections).
    #[arg(long, value_enum, default_value = "flat-octahedron")]
    pub(crate) param: ParamName,
    /// How the geometry image is made.
    #[arg(long, value_enum, default_value = "auto")]
    pub(crate) method: MethodName,
    /// Geometry image size, rows×columns (rows even) [default: from the number of points,
    /// up to 512×512: about eight distinct texels per vertex of a mesh, at least 256×256; for a
    /// point set, from 64×64, twelve per point up to 320×320, and two per point beyond].
    #[arg(long, value_name = "RxC", value_parser = parse_size)]
    pub(crate) resolution: Option<Size>,
    /// Smooth the geometry image with a periodic Gaussian of σ = K texels (§5.4); 0 turns all
    /// smoothing and regularisation off, so that the surface interpolates the image (the thesis).
    #[arg(long, value_name = "K", value_parser = parse_finite)]
    pub(crate) smooth: Option<f64>,
    /// The thin-plate regularisation of the surface: auto (for images made from points, to the
    /// noise left in the texels, √(6/16) of the scan's estimated noise, all of it for noise as
    /// large as the points' spacing; none for a mesh's), off,
    /// gcv (weight by generalised cross-validation), noise=S (to the noise level S), or a
    /// weight W.
    #[arg(long, value_name = "auto|off|gcv|noise=S|W", value_parser = parse_regularisation)]
    pub(crate) regularise: Option<Regularisation>,
    /// Measure the error exactly, by projecting onto the harmonic surface, rather than onto its
    /// mesh at the image's resolution.
    #[arg(long, conflicts_with = "no_error")]
    pub(crate) exact_error: bool,
    /// Do not measure the error.
    #[arg(long)]
    pub(crate) no_error: bool,
    /// Keep about this fraction of the texels by Theorem 5.3 (§5.8 keeps 0.25).
    #[arg(long, value_name = "F", value_parser = parse_finite)]
    pub(crate) reduce: Option<f64>,
    /// The centre of the rays, x,y,z (default: the mean of the points).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = parse_float_list)]
    pub(crate) centre: Option<FloatList>,
    /// Write the surface as Bézier patches (§5.7): .json patches, .obj free-form surfaces, or a
    /// .glb/.gltf mesh with one colour per patch (geometry-image layouts only).
    #[arg(long)]
    pub(crate) bezier: bool,
    /// With --bezier: thesis-cubic, thesis-quintic, hermite (C1, the default) or hermite-quintic.
    #[arg(long, value_name = "SCHEME", value_parser = parse_bezier_scheme)]
    pub(crate) bezier_scheme: Option<BezierScheme>,
    /// With --bezier and a Hermite scheme: the largest deviation of the patches from the surface
    /// (default 1e-4 of the diagonal of the image's bounding box).
    #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = parse_finite)]
    pub(crate) tolerance: Option<f64>,
    /// Fit every part that has holes as a closed surface, its holes capped [default: a part is
    /// an open sheet when it has no handle and the cap of its widest hole would span a quarter
    /// of its area].
    #[arg(long, conflicts_with = "open")]
    pub(crate) closed: bool,
    /// Fit every part that has a boundary as an open sheet (a disc over the mirrored square,
    /// its handles cut).
    #[arg(long)]
    pub(crate) open: bool,
    /// Also write the summary as JSON to this file.
    #[arg(long, value_name = "R.json")]
    pub(crate) report: Option<PathBuf>,
    /// --param sections: K sections of equal thickness (default: the thesis's recursive subdivision).
    #[arg(long, value_name = "K", value_parser = parse_whole)]
    pub(crate) slices: Option<usize>,
    /// --param sections: the axis the sections are cut across.
    #[arg(long, value_enum, default_value = "z")]
    pub(crate) axis: AxisName,
    /// --param sections: how each section's points are ordered along its contour.
    #[arg(long, value_enum, default_value = "angular")]
    pub(crate) order: OrderName,
}

/// The subdivision schemes of `hi subdivide`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum SchemeName {
    /// Loop (triangles; closed or with boundary).
    Loop,
    /// Modified butterfly, Zorin et al. (closed triangle meshes; interpolating).
    Butterfly,
    /// Kobbelt's √3 (closed triangle meshes).
    Sqrt3,
    /// Interpolating √3, Labsik and Greiner (closed triangle meshes).
    Isqrt3,
    /// Catmull-Clark (any polygons; closed or with boundary).
    CatmullClark,
    /// Doo-Sabin (any closed polygon mesh).
    DooSabin,
}

/// The weights of Loop's scheme.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum LoopBeta {
    /// Loop's original β.
    Loop,
    /// Warren's simpler β.
    Warren,
}

/// Options of `hi subdivide`.
#[derive(Debug, Args)]
pub(crate) struct SubdivideMeshArgs {
    /// The scheme.
    #[arg(long, value_enum)]
    pub(crate) scheme: SchemeName,
    /// Number of steps (0 to 8).
    #[arg(long, value_name = "K", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) steps: usize,
    /// β of Loop's scheme.
    #[arg(long, value_enum, default_value = "loop")]
    pub(crate) loop_weights: LoopBeta,
    /// The input mesh, `.obj` or `.off`.
    #[arg(value_name = "IN")]
    pub(crate) input: PathBuf,
    /// The output file: `.obj`, `.off`, `.gltf` (with a `.bin`) or `.glb`.
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub(crate) output: PathBuf,
}

/// The subcommands of `hi curve`.
#[derive(Debug, Subcommand)]
pub(crate) enum CurveCommand {
    /// The curve, its derivatives, curvature and torsion at parameters t.
    #[command(after_help = EVAL_HELP)]
    Eval(EvalArgs),
    /// N uniform samples of the curve of a kind (harmonic by default, X(l/N) by FFT).
    #[command(after_help = SAMPLE_HELP)]
    Sample(SampleArgs),
    /// Fairness of a plane curve: max |κ|, monotone pieces of κ, ∫κ² ds, confinement.
    #[command(after_help = FAIRNESS_HELP)]
    Fairness(FairnessArgs),
    /// The piecewise Bézier form of a piecewise polynomial curve.
    #[command(name = "to-bezier", after_help = TO_BEZIER_HELP)]
    ToBezier(ToBezierArgs),
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
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub(crate) struct BasisArgs {
    /// Other questions about the basis.
    #[command(subcommand)]
    pub(crate) command: Option<BasisCommand>,
    /// Number of basis functions n (at least 1).
    #[arg(long, value_name = "N", required = true, allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) n: Option<usize>,
    /// Index k of the basis function (0 ≤ k < n).
    #[arg(long, value_name = "K", required = true, allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) k: Option<usize>,
    /// Parameters t, comma-separated (e.g. 0,0.25,-1.5).
    #[arg(long, value_name = "T1,T2,...", required = true, allow_hyphen_values = true, value_parser = parse_float_list)]
    pub(crate) t: Option<FloatList>,
    /// Also print the derivatives of orders 1 to D (D ≤ 1024).
    #[arg(long, value_name = "D", default_value = "0", allow_negative_numbers = true, value_parser = parse_derivatives)]
    pub(crate) derivatives: usize,
}

/// The subcommands of `hi basis`.
#[derive(Debug, Subcommand)]
pub(crate) enum BasisCommand {
    /// Every zero of a derivative of σⁿ on [0, 1], enclosed by interval arithmetic (§5.6).
    #[command(after_help = ROOTS_HELP)]
    Roots(RootsArgs),
}

/// Options of `hi basis roots`.
#[derive(Debug, Args)]
pub(crate) struct RootsArgs {
    /// Number of basis functions n (1 to 4096).
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) n: usize,
    /// The order D of the derivative whose zeros are wanted (0 for σ itself, up to 16).
    #[arg(long, value_name = "D", default_value = "1", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) derivative: usize,
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
    /// Which curve through the points (see below).
    #[arg(long, value_name = "KIND", default_value = "harmonic", value_parser = parse_kind)]
    pub(crate) kind: CurveKind,
}

/// Options of `hi curve fairness`.
#[derive(Debug, Args)]
pub(crate) struct FairnessArgs {
    /// Where the points come from.
    #[command(flatten)]
    pub(crate) input: InputArg,
    /// Which curve through the points (see 'hi curve sample --help').
    #[arg(long, value_name = "KIND", default_value = "harmonic", value_parser = parse_kind)]
    pub(crate) kind: CurveKind,
    /// Number of parameters the measures are computed from (3 ≤ N ≤ 2^28).
    #[arg(long, value_name = "N", default_value = "4096", allow_negative_numbers = true, value_parser = parse_count)]
    pub(crate) samples: usize,
}

/// Options of `hi curve to-bezier`.
#[derive(Debug, Args)]
pub(crate) struct ToBezierArgs {
    /// Where the points come from.
    #[command(flatten)]
    pub(crate) input: InputArg,
    /// Which curve through the points (see 'hi curve sample --help').
    #[arg(long, value_name = "KIND", value_parser = parse_kind)]
    pub(crate) kind: CurveKind,
    /// For --kind harmonic: thesis-cubic, thesis-quintic, hermite (C1, default) or
    /// hermite-quintic (C2) (§5.7).
    #[arg(long, value_name = "SCHEME", value_parser = parse_bezier_scheme)]
    pub(crate) scheme: Option<BezierScheme>,
    /// For the Hermite schemes: the largest deviation from the curve (default 1e-4 of the
    /// diagonal of the points' bounding box).
    #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = parse_finite)]
    pub(crate) tolerance: Option<f64>,
}

/// A Bézier scheme name of `hi curve to-bezier --scheme`.
fn parse_bezier_scheme(s: &str) -> Result<BezierScheme, String> {
    BezierScheme::from_name(s.trim()).ok_or_else(|| {
        format!(
            "unknown scheme '{}': expected thesis-cubic, thesis-quintic, hermite or hermite-quintic",
            s.trim()
        )
    })
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

/// The subcommands of `hi surface`.
#[derive(Debug, Subcommand)]
pub(crate) enum SurfaceCommand {
    /// The surface, its partial derivatives, normal, K and H at (u, v) pairs.
    #[command(after_help = SURFACE_EVAL_HELP)]
    Eval(SurfaceEvalArgs),
    /// A triangle mesh of the surface in an OBJ, glTF or GLB file.
    #[command(after_help = SURFACE_MESH_HELP)]
    Mesh(SurfaceMeshArgs),
    /// The grid file of an example surface: sphere, torus or a surface of §5.9.
    #[command(after_help = SURFACE_EXAMPLE_HELP)]
    Example(SurfaceExampleArgs),
    /// The surface as Bézier patches (§5.7): JSON, OBJ free-form, or a coloured mesh.
    #[command(after_help = SURFACE_BEZIER_HELP)]
    Bezier(SurfaceBezierArgs),
    /// A bicubic B-spline surface through slices of points (§4.4): JSON or a mesh.
    #[command(name = "bspline-fit", after_help = SURFACE_BSPLINE_HELP)]
    BsplineFit(SurfaceBsplineArgs),
}

/// Options of `hi surface bspline-fit`.
#[derive(Debug, Args)]
pub(crate) struct SurfaceBsplineArgs {
    /// JSON file with the slices ("-" reads stdin).
    #[arg(long, value_name = "FILE")]
    pub(crate) input: PathBuf,
    /// The slices are closed curves (periodic U-curves; do not repeat the first point).
    #[arg(long)]
    pub(crate) closed_u: bool,
    /// The surface closes across the slices (the last slice is followed by the first).
    #[arg(long)]
    pub(crate) closed_v: bool,
    /// End condition of the open directions.
    #[arg(long, value_enum, default_value = "natural")]
    pub(crate) end: BsplineEnd,
    /// Parameters of the points along the slices and of the slices.
    #[arg(long, value_enum, default_value = "chord-length")]
    pub(crate) params: BsplineParams,
    /// Mesh quads along u and v, as U×V (at least 3 along a closed direction).
    #[arg(long, value_name = "UxV", default_value = "64x64", value_parser = parse_size)]
    pub(crate) resolution: Size,
    /// Write to OUT: .json (the surface) or a mesh (.obj, .gltf + .bin, .glb).
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub(crate) output: Option<PathBuf>,
}

/// End conditions of `hi surface bspline-fit`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum BsplineEnd {
    /// Zero second derivatives at the ends.
    Natural,
    /// Continuous third derivatives at the second and second-last points.
    NotAKnot,
    /// Coincident end control points (§2.11): zero end derivatives.
    Clamped,
}

/// Parameters of `hi surface bspline-fit`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum BsplineParams {
    /// Chord length (per slice; averaged across the slices).
    ChordLength,
    /// Uniform.
    Uniform,
}

/// Options of `hi surface bezier`.
#[derive(Debug, Args)]
pub(crate) struct SurfaceBezierArgs {
    /// Where the grid comes from.
    #[command(flatten)]
    pub(crate) input: GridArg,
    /// thesis-cubic, thesis-quintic, hermite (C1, default) or hermite-quintic (C2).
    #[arg(long, value_name = "SCHEME", default_value = "hermite", value_parser = parse_bezier_scheme)]
    pub(crate) scheme: BezierScheme,
    /// For the Hermite schemes: the largest deviation from the surface (default 1e-4 of the
    /// diagonal of the grid's bounding box).
    #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = parse_finite)]
    pub(crate) tolerance: Option<f64>,
    /// Samples per patch side in a mesh output (1 to 64).
    #[arg(long, value_name = "K", default_value = "8", allow_negative_numbers = true, value_parser = parse_whole)]
    pub(crate) samples: usize,
    /// The output: .json (patches), .obj (free-form Bézier surfaces), .gltf or .glb (a mesh with
    /// one colour per patch).
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub(crate) output: PathBuf,
}

/// The grid file option shared by the surface subcommands.
#[derive(Debug, Args)]
pub(crate) struct GridArg {
    /// JSON file with the grid ("-" reads stdin); see 'hi surface --help' for its shape.
    #[arg(long, value_name = "FILE")]
    pub(crate) input: PathBuf,
}

/// Options of `hi surface eval`.
#[derive(Debug, Args)]
pub(crate) struct SurfaceEvalArgs {
    /// Where the grid comes from.
    #[command(flatten)]
    pub(crate) input: GridArg,
    /// Parameters u, comma-separated, one per v.
    #[arg(long, value_name = "U1,U2,...", allow_hyphen_values = true, value_parser = parse_float_list)]
    pub(crate) u: FloatList,
    /// Parameters v, comma-separated, one per u.
    #[arg(long, value_name = "V1,V2,...", allow_hyphen_values = true, value_parser = parse_float_list)]
    pub(crate) v: FloatList,
}

/// Options of `hi surface mesh`.
#[derive(Debug, Args)]
pub(crate) struct SurfaceMeshArgs {
    /// Where the grid comes from.
    #[command(flatten)]
    pub(crate) input: GridArg,
    /// Quads along u and v, as U×V such as 128x128 (at least 3 along a direction whose window is a period).
    #[arg(long, value_name = "UxV", default_value = "64x64", value_parser = parse_size)]
    pub(crate) resolution: Size,
    /// The parameter window u0,u1,v0,v1 (u0 < u1, v0 < v1).
    #[arg(long, value_name = "U0,U1,V0,V1", default_value = "0,1,0,1", allow_hyphen_values = true, value_parser = parse_window)]
    pub(crate) window: Window,
    /// Colour the vertices by this curvature.
    #[arg(long, value_enum, value_name = "CURVATURE")]
    pub(crate) color: Option<ColorBy>,
    /// With --color: the colours (coolwarm keeps the sign).
    #[arg(long, value_enum, default_value = "thesis", requires = "color")]
    pub(crate) palette: PaletteName,
    /// The mesh file to write: .obj, .gltf (+ .bin) or .glb.
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub(crate) output: PathBuf,
}

/// Options of `hi surface example`.
#[derive(Debug, Args)]
pub(crate) struct SurfaceExampleArgs {
    /// sphere, torus, or a surface of §5.9 by name or figure number (see below).
    #[arg(value_name = "NAME")]
    pub(crate) name: String,
    /// Sample the surface at M×N points instead, such as 24x4 (see below).
    #[arg(long, value_name = "MxN", value_parser = parse_size)]
    pub(crate) samples: Option<Size>,
    /// Write the grid to FILE instead of stdout.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) output: Option<PathBuf>,
}

/// The curvature that colours a mesh.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, ValueEnum, serde::Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub(crate) enum ColorBy {
    /// Gaussian curvature K.
    Gaussian,
    /// Mean curvature H.
    Mean,
}

/// The colours of a curvature map.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum, serde::Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub(crate) enum PaletteName {
    /// The thesis's (§5.9): |value| from blue (0) to purple (the largest).
    #[default]
    Thesis,
    /// Viridis: |value| from dark purple (0) to yellow (the largest), perceptually even.
    Viridis,
    /// Cool–warm: the value with its sign, blue (negative) through grey (0) to red (positive).
    Coolwarm,
}

impl PaletteName {
    /// The colour map: the magnitude from 0 for the sequential palettes, the signed value
    /// about 0 for the diverging one; over every value.
    pub(crate) fn color_map(self) -> hi_mesh::ColorMap {
        use hi_mesh::{ColorMap, ColorScale, Palette};
        let (scale, palette) = match self {
            PaletteName::Thesis => (ColorScale::Magnitude, Palette::Thesis),
            PaletteName::Viridis => (ColorScale::Magnitude, Palette::Viridis),
            PaletteName::Coolwarm => (ColorScale::Symmetric, Palette::CoolWarm),
        };
        ColorMap { scale, coverage: 1.0, palette }
    }
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
