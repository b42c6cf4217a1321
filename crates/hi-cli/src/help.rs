// SPDX-License-Identifier: MIT
//! The help texts of `hi`'s commands, shown after their options (`hi <command> --help`):
//! what each reads and writes, with an example.

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

/// Prefixes a surface subcommand's help text with the input shape.
macro_rules! surface_help {
    ($text:literal) => {
        concat!(
            "Input: {\"grid\": [[[x, y, z], ...], ...]} or the bare array of rows: an m×n grid of\n",
            "  3-D points, row j at u = j/m; --input - reads stdin. See 'hi surface --help'.\n",
            $text
        )
    };
}

/// The input and output conventions, shown by `hi --help`.
pub(crate) const MAIN_HELP: &str = "\
Basis: hi basis --n N --k K --t T1,... (values, derivatives); hi basis roots --n N --derivative D.
Curve commands: hi curve eval|sample|fairness|to-bezier|rotate|resample|subdivide|nonuniform
  --input FILE ... (see 'hi curve --help' and 'hi curve eval --help', for instance).
Surface commands: hi surface eval|mesh|example|bspline-fit|bezier (see 'hi surface --help').
Subdivision: hi subdivide --scheme SCHEME --steps K IN.(obj|off) -o OUT.(obj|off|gltf|glb).
Fitting: hi fit SCAN -o OUT.(glb|gltf|obj|json) [--param sphere|octahedron|flat-octahedron|sections] ...
         hi fit SCAN... --out-dir DIR [--format glb|gltf|obj|json] [--jobs N] [--force]
Rendering (§5.6): hi render SCENE.json -o OUT.png, or hi render --quick FILE -o OUT.png.
Bézier forms (§5.7): hi bezier basis --n N --scheme thesis-cubic|thesis-quintic;
  hi curve to-bezier --kind harmonic --scheme thesis-cubic|thesis-quintic|hermite|hermite-quintic.

Input (--input FILE, or --input - for stdin):
  {\"points\": [[x, y], ...]}   or the bare array   [[x, y], ...]
  Points are arrays of 1, 2 or 3 numbers, all of one dimension; a 1-D point may also be a
  bare number, so [0, 1, 0.5] is three 1-D points. With n points, the harmonic curve X(t)
  passes through point k at t = k/n and is smooth and 1-periodic. 'hi curve sample',
  'fairness' and 'to-bezier' take --kind KIND to draw another curve through the points:
  harmonic (the default), trig, lagrange, catmull-rom, bessel-overhauser, tcb,
  bspline-periodic, bspline-open, hobby-closed, hobby-open, chaikin, four-point.
  Surfaces: {\"grid\": [[[x, y, z], ...], ...]} or the bare array of rows: an m×n grid of
  3-D points, row j at u = j/m, point k of a row at v = k/n.

Output (stdout): one JSON object on one line, e.g. {\"X\": [[x, y], ...]}
  Points are arrays of coordinates ([x] for 1-D). Numbers are the shortest decimals that read
  back to the same double. A non-finite result (an overflowing high derivative) is printed as
  the string \"Infinity\", \"-Infinity\" or \"NaN\"; null means undefined (the curvature or
  torsion at a singular point, the normal at a pole). --pretty indents the output.

Exit status: 0 on success; 2 on bad input, a bad command line or an output file that cannot
be written (-o), with one line \"hi: ...\" on stderr; 1 if stdout could not be written
(silently if the reader closed the pipe).";

/// The output of `hi basis`.
pub(crate) const BASIS_HELP: &str = "\
Output: {\"sigma\": [σ(t1), σ(t2), ...], \"d1\": [...], ..., \"dD\": [...]}
  dp holds the p-th derivative of σⁿₖ at each t (from its cosine sum).
Example: hi basis --n 3 --k 0 --t 0,0.5   prints   {\"sigma\":[1.0,-0.3333333333333333]}";

/// The output of `hi basis roots`.
pub(crate) const ROOTS_HELP: &str = "\
Output: {\"roots\": [[lo, hi], ...], \"unique\": [true, ...], \"verdicts\": [\"unique\", ...],
         \"complete\": true}
  Every zero of dᴰσⁿ/dtᴰ (σⁿ = σⁿ₀; the zeros of σⁿₖ are these shifted by k/n) in [0, 1] lies in
  one of the intervals [lo, hi], found by interval bisection and Krawczyk's method on the
  cosine-sum extension (eq. 5.4) with outward rounding. unique: the interval holds exactly one
  zero (proven). verdicts: unique, exists (at least one), at_most_one (a zero at an end of
  [0, 1] may lie just outside), unknown. complete: false if a cap stopped the search.
Example: hi basis roots --n 3 --derivative 1   (zeros at 0, 1/2 and 1)";

/// The output of `hi subdivide`.
pub(crate) const SUBDIVIDE_MESH_HELP: &str = "\
Output: {\"files\": [...], \"vertices\": V, \"edges\": E, \"faces\": F} after writing the mesh.
  Loop, butterfly, sqrt3 and isqrt3 take triangle meshes; catmull-clark and doo-sabin any
  polygons. Loop and catmull-clark have boundary rules; the others need a closed mesh.
  glTF output is the mesh triangulated (fans), with smooth normals.
Example: hi subdivide --scheme catmull-clark --steps 2 cube.obj -o cube2.glb";

/// The output of `hi fit`.
pub(crate) const FIT_HELP: &str = "\
Output (stdout, and --report): {\"scan\": …, \"method\": \"mesh\" | \"shrink-wrap\" | \"radial\" | \"contours\",
  \"method_reason\": …, \"points\": P, \"unused_points\": U, \"image_points\": Q, \"dropped_points\": D,
  \"image\": [R, C], \"surface\": [M, N], \"non_star_fraction\": s, \"hole_fraction\": h,
  \"mesh\": {\"holes_filled\", \"hole_edges\", \"parts\", \"area_kept\", \"welded_points\",
  \"dropped_triangles\", \"reoriented_triangles\", \"split_vertices\", \"handles_cut\",
  \"stretch_efficiency\", \"area_ratio\"} | null, \"regularisation\": {\"lambda\", \"kept\", \"rms_change\", \"max_change\"},
  \"stages\": [{\"kind\": …, \"seconds\": t}, …], \"reduction\": {\"max_deviation\", \"upper_bound\"} | null,
  \"errors\": {\"mean\", \"rms\", \"max\", \"diagonal\", \"relative\": [mean, rms, max]},
  \"both_ways\": {\"scan_to_surface\", \"surface_to_scan\": {\"mean\", \"rms\", \"max\", \"relative\"},
  \"filled_to_scan_max\", \"filled_to_scan_max_relative\", \"unreached_fraction\", \"diagonal\"},
  \"hausdorff\": {\"distance\", \"relative\"} | null,
  \"topology\": {\"parts\", \"parts_dropped\", \"part_floor\", \"genus\": [...], \"boundary_loops\": [...],
  \"domains\": [\"sphere\" | \"torus\" | \"sheet\", ...]},
  \"parts\": [{\"name\", \"domain\", \"why\", \"area_fraction\", \"genus\", \"boundary_loops\",
  \"holes_filled\", \"handles_cut\", \"image\", \"surface\", \"hole_fraction\", \"both_ways\"}, …],
  \"dropped_parts\": [{\"name\", \"vertices\", \"area_fraction\", \"point_fraction\", \"reason\"}, …], \"files\": [...]}
  Image, surface, mesh, regularisation and reduction are the largest part's.
  Every part of the scan of at least 0.05% of its area is fitted on its own (part 1 the
  largest): a mesh's connected parts, or the parts of the zero set of a point set's signed
  distance. --method auto (the default) parameterises a mesh's parts (mesh) when those hold at
  least half its area, and otherwise wraps a surface onto the points (shrink-wrap: the zero set
  of their signed distance, parameterised, projected onto them and pulled into the creases it
  bridged; a cloud larger than its images can hold is first summarised on a grid); method_reason
  says why. Each part goes over the domain its topology asks for: a closed surface of genus 0
  over the sphere (holes capped by a thin plate that continues the surface), genus 1 over the
  torus (no cut, no seam), higher genus over the sphere with its handles cut, an open sheet (no
  handle, and its widest rim would need a cap of a quarter of its area) over the mirrored square
  as an open surface; --closed caps every part, --open leaves every part with a rim open (its
  handles cut). radial is the
  thesis's algorithm 2 (rays from the centre, the whole scan as one surface). non_star_fraction
  counts the rays from the centre that met the scan more than once; above 5% a warning, when the
  surface follows the outermost shell the rays met. The image size follows the point count
  unless --resolution is given (several parts share its texels by area). A surface through
  points is regularised to the scan's own noise (--regularise); --smooth 0 interpolates.
  Several parts are written as one scene of meshes named part 1, part 2, … (glTF nodes, OBJ
  objects); closed parts are welded at every seam and face outwards. errors: the scan's points
  to the nearest output mesh (kd-tree, or with --exact-error Gauss-Newton onto the surface);
  both_ways adds the surfaces to the scan, the largest distance from filled texels (holes)
  apart, and the fraction of the scan's points farther than 2% of the diagonal from the surface
  (unreached; above 1% a warning with its cause). Notes on stderr say what was done about each
  part's topology; warnings name the parts left out and points dropped for non-finite
  coordinates. A part whose image is more than half holes is left out; if every part's is, the
  fit is refused.
--param sections is algorithm 1 (§5.3) instead: sections across --axis (K equal slabs with
  --slices K, else the thesis's recursive subdivision), a harmonic curve through each (points in
  --order), insertion to equal counts, rotation alignment, the reversed traversal. Its output
  replaces image, non_star_fraction and hole_fraction by \"sections\": [{\"range\", \"height\",
  \"points\", \"radius\", \"polygon_crossings\", \"misordered\", \"curve_crossings\",
  \"overshoot\", \"rotation\", \"deviation\", \"deviation_unaligned\"}, …], \"axis\",
  \"contour_points\", \"deviation\", \"deviation_unaligned\", \"sampling_scale\",
  \"surface_to_points\" and \"problems\": [\"section 3: …\", …] (each also printed as a warning).
--out-dir DIR fits every SCAN (files, folders of scans, quoted globs) into DIR/NAME.FORMAT,
  --jobs at a time (default: the number of cores), with one progress bar, and appends one line
  per scan to DIR/summary.jsonl: {\"input\", \"output\", \"status\": \"ok\" | \"failed\", \"method\",
  \"parts\", \"points\", \"both_ways\", \"files\", \"seconds\": {\"read\", \"fit\", \"write\", \"total\"},
  \"warnings\": [...], \"error\"}. A scan that fails is recorded and the others go on; the exit
  status is 2 if any failed. A scan already done (an \"ok\" line for the same input and output,
  and the output there) is skipped; --force fits it again. Output: {\"out_dir\", \"summary\",
  \"fitted\", \"skipped\", \"failed\", \"failures\": [...]}.
--bezier writes the surface as Bézier patches (§5.7, see 'hi surface bezier --help'): .json
  patches, .obj free-form surfaces or a .glb/.gltf mesh with one colour per patch (the patches
  of one cover of the object), and adds \"bezier\": {\"scheme\", \"patches\", \"patches_once\",
  \"degree\", \"max_deviation\", \"rms_deviation\", \"bound\", \"max_normal_jump\", \"seconds\"}.
Example: hi fit bunny.obj -o bunny.glb
         hi fit bunny.obj -o bunny.glb --method radial --param sphere --resolution 128x128 --smooth 0
         hi fit scan.xyz -o fit.glb --param sections --slices 24 --axis y
         hi fit scans/ 'more/*.ply' --out-dir fitted";

/// The output of `hi curve eval`.
pub(crate) const EVAL_HELP: &str = curve_help!(
    "\
Output: {\"X\": [[x, y], ...], \"d1\": [[...], ...], ..., \"curvature\": [...], \"torsion\": [...]}
  X holds X(t) at each t, dp the p-th derivative X⁽ᵖ⁾(t) (only with --derivatives).
  1-D: no curvature. 2-D: \"curvature\" is the signed curvature (positive turning left).
  3-D: \"curvature\" is the unsigned curvature, and \"torsion\" is added.
  Curvature or torsion is null where it is undefined (X′ = 0, or X′ × X″ = 0 for torsion).
Example: echo '[[1,0],[0,1],[-1,0],[0,-1]]' | hi curve eval --input - --t 0.125"
);

/// The output of `hi curve sample`.
pub(crate) const SAMPLE_HELP: &str = curve_help!(
    "\
Output: {\"X\": [[x, y], ...]} with the N points X(0), X(1/N), ..., X((N-1)/N) of a closed
  curve (the harmonic one by FFT), or X(0), X(1/(N-1)), ..., X(1) of an open one (lagrange,
  bspline-open, hobby-open).
Kinds (--kind): every kind takes nothing but the points. Closed, point k at t = k/n: harmonic,
  trig, catmull-rom, tcb (tension = continuity = bias = 0, so the Catmull-Rom spline),
  bspline-periodic (uniform), hobby-closed (tension 1), four-point (w = 1/16); closed with
  chord-length parameters: bessel-overhauser; closed, approximating: chaikin (the exact limit,
  a quadratic B-spline; (x0 + x1)/2 at t = 0). Open, point k at t = k/(n-1): lagrange,
  bspline-open (natural ends, X'' = 0, rather than the thesis's coincident end control points,
  with which the curve stops at its ends and its bending energy is infinite), hobby-open
  (curl 1 at both ends). Hobby curves need 2-D points. four-point is the polygon after
  four steps of the scheme (16 points per point, all on the limit), joined by the periodic
  cubic spline through them.
Example: hi curve sample --input square.json --count 8 --kind hobby-closed"
);

/// The output of `hi curve fairness`.
pub(crate) const FAIRNESS_HELP: &str = curve_help!(
    "\
  Fairness needs 2-D points (the curvature is signed).
Output: {\"max_curvature\": k, \"max_curvature_at\": t, \"monotone_pieces\": p,
  \"bending_energy\": e, \"bending_energy_error\": d, \"length\": l, \"confinement\": c}
  max_curvature: the largest |κ| and a parameter t where it is reached. monotone_pieces: the
  number of pieces on which κ is monotone (1 for a circle; for a closed curve, the number of
  extrema of κ). bending_energy: ∫ κ² ds over the curve; bending_energy_error: the
  quadrature's estimated error (large near a cusp). length: ∫ ds. confinement: the area
  of the convex hull of the curve over that of the points (null for collinear points): above 1
  where the curve bulges out of its polygon (§2.4, §3.8).
  The measures come from --samples parameters (closed: t = j/N; open: t = j/(N-1)).
Kinds: see 'hi curve sample --help'.
Example: hi curve fairness --input pentagon.json --kind bspline-periodic"
);

/// The output of `hi curve to-bezier`.
pub(crate) const TO_BEZIER_HELP: &str = curve_help!(
    "\
Output: {\"segments\": [[p0, p1, p2, p3], ...]}: the curve as Bézier segments, segment i for
  t in [i/s, (i+1)/s] of s segments. Cubic for catmull-rom, tcb, bessel-overhauser,
  bspline-periodic, bspline-open, hobby-closed and hobby-open (for Hobby: knot, postcontrol,
  precontrol, next knot, the numbers METAPOST reports); quadratic ([p0, p1, p2]) for chaikin;
  one segment of degree n-1 (n control points) for lagrange. bessel-overhauser's segments are
  its chord-length pieces, each on its own parameter. harmonic, trig and four-point are not
  piecewise polynomial and have no Bézier form.
Example: hi curve to-bezier --input pentagon.json --kind hobby-closed"
);

/// The output of `hi curve rotate`.
pub(crate) const ROTATE_HELP: &str = curve_help!(
    "\
Output: {\"points\": [[x, y], ...]}
  Without --exact: the n points X(j/n + O) of Theorem 5.1. For odd n their curve is X(t + O);
  for even n it is not (the theorem fails there), unless n·O is a whole number or the
  alternating sum of the points is zero (a regular polygon, for instance).
  With --exact: points whose harmonic curve is exactly X(t + O); for even n there are n + 1.
Example: hi curve rotate --input square.json --offset 0.1 --exact"
);

/// The output of `hi curve resample`.
pub(crate) const RESAMPLE_HELP: &str = curve_help!(
    "\
Output: {\"points\": [[x, y], ...], \"max_error\": e, \"error_bound\": b}
  The N points X(j/N) (Theorem 5.3). For N ≥ n their curve is X itself and e = b = 0. For
  N < n (reduction) e is max |X(t) − Y(t)| measured on a fine grid and b a guaranteed bound,
  where Y is the curve through the N new points.
Example: hi curve resample --input square.json --count 3"
);

/// The output of `hi curve subdivide`.
pub(crate) const SUBDIVIDE_HELP: &str = curve_help!(
    "\
Output: {\"points\": [[x, y], ...]}: the n·2^L points X(i/(n·2^L)) of harmonic subdivision
  (§5.2) after L levels; the original point k is copied exactly to index k·2^L.
Example: hi curve subdivide --input square.json --levels 1"
);

/// The output of `hi curve nonuniform`.
pub(crate) const NONUNIFORM_HELP: &str = curve_help!(
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

/// The scene format and output of `hi render`.
pub(crate) const RENDER_HELP: &str = "\
Scene (JSON; file names relative to the scene file; schema: docs/schemas/scene.schema.json):
  {\"camera\": {\"eye\": [x, y, z], \"target\": [x, y, z], \"up\": [0, 0, 1], \"fov\": 40},
   \"image\": {\"width\": 512, \"height\": 512, \"spp\": 4},
   \"background\": [r, g, b], \"ambient\": [r, g, b],
   \"lights\": [{\"type\": \"directional\", \"direction\": [x, y, z], \"intensity\": 1},
              {\"type\": \"point\", \"position\": [x, y, z], \"intensity\": [r, g, b]}],
   \"objects\": [{\"type\": \"harmonic\", \"file\": \"torus.json\", \"method\": \"krawczyk\"},
               {\"type\": \"mesh\", \"file\": \"head.glb\", \"material\": {\"color\": [r, g, b]}},
               {\"type\": \"bezier\", \"file\": \"patches.json\"}]}
  camera, lights, material: the serde forms of hi-raytrace's Camera, Light and Material.
  camera: fov is the vertical field of view in degrees (default 40); up defaults to [0, 0, 1];
    without a camera the scene is framed from the front, above and to the side.
  Colours are sRGB in [0, 1]; intensities linear (a number or [r, g, b], default 1); the
    direction of a directional light points towards the light; a \"fill\" light is a
    directional light that casts no shadow; point lights fall off with the squared distance.
    Without \"lights\", a key and a fill light; [] for none.
  harmonic: a grid file (as 'hi surface example' writes) drawn by \"method\": krawczyk (interval
    Newton, the default; 'interval' is a deprecated alias), bisection (interval bisection),
    bezier (C1 Hermite patches) or mesh (256x256 quads); \"curvature\": \"gaussian\" or \"mean\"
    colours it by K or H, and \"palette\": \"thesis\" (|value|, blue to purple, the default),
    \"viridis\" (|value|) or \"coolwarm\" (the signed value, blue through grey at 0 to red).
  mesh: .obj, .gltf or .glb (vertex colours are used if the file has them).
  bezier: the patches file of 'hi surface bezier -o patches.json', one colour per patch.
  Every object may have a \"material\": {\"color\" (sRGB), \"diffuse\", \"specular\",
    \"shininess\"}; its colour, when given, also paints a Bezier or uncoloured harmonic object.
  A bad field is named by its path: scene.json: objects[1].material.color: ...
--quick FILE frames one grid, patches or mesh file by itself (--method picks how a grid file
  is drawn: bezier, the default, krawczyk, bisection or mesh).
Output: the PNG in OUT (sRGB, anti-aliased by SPP samples per pixel in a fixed pattern: the same
  bytes on every run); stdout gets {\"files\": [OUT], \"width\": W, \"height\": H, \"spp\": S,
  \"rays\": {\"camera\", \"shadow\", \"hits\"}, \"seconds\": T}. A progress bar is shown on a terminal.
Example: hi surface example torus -o torus.json && hi render --quick torus.json --method krawczyk -o torus.png";

/// The output of `hi bezier basis`.
pub(crate) const BEZIER_BASIS_HELP: &str =
    "Output: {\"n\": n, \"scheme\": s, \"degree\": d, \"breaks\": [t0 = 0, ..., 1],
  \"P\": [a][k][j]}: on piece a (t from breaks[a] to breaks[a+1]) the approximation of σₖ is the
  Bézier polynomial with control values P[a][k][0..=d]. The patches of a harmonic surface are
  Σₖ Σₗ P[a][k][j]·P[b][l][i]·x_kl (§5.7). thesis-cubic: n pieces, P[a][k][0] = δ(a,k).
Example: hi bezier basis --n 4 --scheme thesis-cubic";

/// The input shape of the surface commands, shown by `hi surface --help`.
pub(crate) const SURFACE_HELP: &str = "\
Input (--input FILE, or --input - for stdin): {\"grid\": [[[x, y, z], ...], ...]} or the bare
  array of rows: an m×n grid of 3-D points (m, n ≥ 1, every row of the same length), row j at
  u = j/m, point k of a row at v = k/n. The harmonic surface p(u, v) through it is smooth and
  1-periodic in u and v (§5.1). 'hi surface example' writes such files.
  'hi surface bspline-fit' takes slices of points instead (see its --help).";

/// The output of `hi surface eval`.
pub(crate) const SURFACE_EVAL_HELP: &str = surface_help!(
    "\
Output: {\"p\": [[x, y, z], ...], \"pu\": [...], \"pv\": [...], \"puu\": [...], \"puv\": [...],
  \"pvv\": [...], \"normal\": [...], \"gaussian\": [...], \"mean\": [...]}, one entry per (u, v)
  pair: the point, its first and second partial derivatives, the unit normal pu × pv/|pu × pv|,
  the Gaussian curvature K and the mean curvature H = (κ1 + κ2)/2 (the thesis calls κ1 + κ2 = 2H
  the mean curvature). Signs follow that normal: on the sphere of 'hi surface example sphere'
  it points outward and H = -1/r. normal, gaussian and mean are null where pu × pv = 0 (a pole).
Example: hi surface example sphere | hi surface eval --input - --u 0.1,0.2 --v 0,0.5"
);

/// The output of `hi surface mesh`.
pub(crate) const SURFACE_MESH_HELP: &str = surface_help!(
    "\
Writes a triangle mesh of the surface over the window to OUT, in the format its extension
  names: .obj (Wavefront OBJ), .gltf (glTF 2.0 JSON, with its buffer in OUT.bin beside it) or
  .glb (binary glTF 2.0); with positions, normals, UVs and, with --color, vertex colours of K
  or H (blue: none, purple: high |K| or |H|). The grid of samples is (U+1)×(V+1) for
  --resolution UxV; a direction whose window is a whole period is closed (its last row is its
  first, not repeated), and the points of a pole are welded into one vertex.
Output: {\"files\": [...], \"vertices\": V, \"triangles\": T} and, with --color,
  \"legend\": {\"quantity\": \"K\" or \"H\", \"min\": a, \"max\": b}, the values at the two ends of
  the colour ramp.
Example: hi surface mesh --input torus.json --resolution 64x32 --color gaussian -o torus.glb"
);

/// The output of `hi surface example`.
pub(crate) const SURFACE_EXAMPLE_HELP: &str = "\
Output: the grid file {\"grid\": [[[x, y, z], ...], ...]} of a surface, on stdout or in FILE.
  sphere: the exact unit sphere from a 4×4 grid (docs/math.md §3); u ∈ [0, 1/2] covers it once, the
    poles are at u = 0 and 1/2, and pu × pv points outward.
  torus: the exact torus with radii R = 2 and r = 1 from a 4×4 grid.
  With --samples MxN they are sampled at (j/M, k/N) instead: the same surface when M, N ≥ 4.
  The surfaces of §5.9, sampled f(j/M, k/N) at the thesis's 24×4 (48×4 for solomon-fine)
  unless --samples is given: plane, partial-sphere, mobius, revolution, shell, shell2, klein,
  overhand, solomon, solomon-fine, revolution-periodic, and by their figure numbers 5.31 to
  5.43 (5.33 and 5.34 are §5.9's own torus and sphere definitions).
  With -o FILE, stdout gets {\"files\": [FILE], \"m\": M, \"n\": N}.
Example: hi surface example torus --samples 8x8 -o torus.json";

/// The input and output of `hi surface bspline-fit`.
pub(crate) const SURFACE_BSPLINE_HELP: &str = "\
Input: {\"slices\": [[[x, y, z], ...], ...]} or the bare array of slices: lists of 3-D points,
  of any lengths (at least 2 slices of at least 2 points; 3 when closed; 4 with not-a-knot).
  Through each slice a cubic U-curve (chord-length parameters); the U-curves' knots merged by
  knot insertion; V-curves across the slices at common averaged chord-length parameters; the
  bicubic tensor-product B-spline through every point (Watt & Watt's curve network, §4.4).
Output: without -o, {\"degree\": [3, 3], \"closed\": [cu, cv], \"u_knots\": [...],
  \"v_knots\": [...], \"control\": [[[x, y, z], ...], ...] (row i along u), \"u_params\": [[...]],
  \"v_params\": [...], \"patches\": {\"u_breaks\", \"v_breaks\", \"control\": [4×4 nets]},
  \"adini_patches\": {...}}: point k of slice s is p(u_params[s][k], v_params[s]); closed knots
  are breakpoints. patches: the exact bicubic Bézier patches; adini_patches: Watt & Watt's,
  interior points from Adini's twists. With -o OUT.json that object goes to OUT; with
  -o OUT.(obj|gltf|glb) a mesh of the surface does. stdout then gets {\"files\": [...],
  \"control\": [M, N]} (and \"vertices\", \"triangles\" for a mesh).
Example: hi surface bspline-fit --input slices.json --closed-u -o tube.glb";

/// The output of `hi surface bezier`.
pub(crate) const SURFACE_BEZIER_HELP: &str = surface_help!(
    "\
Converts the harmonic surface to Bézier patches (§5.7) and writes them to OUT: .json
  {\"scheme\", \"u_breaks\", \"v_breaks\", \"patches\": [{\"u\": [u0, u1], \"v\": [v0, v1],
  \"degree\": [du, dv], \"control\": [[point, ...] per u index]}], \"report\"}; .obj: OBJ free-form
  surfaces (cstype bezier, surf); .gltf/.glb: the patches sampled K×K, one colour per patch.
  thesis-cubic: the thesis's m×n bicubic patches (C0, through the points); thesis-quintic: its
  degree-5 scheme; hermite: C1 bicubic patches from the surface's derivatives, refined until
  a guaranteed bound is below the tolerance.
Output: {\"files\": [...], \"report\": {\"scheme\", \"patches\", \"degree\": [du, dv],
  \"max_deviation\", \"rms_deviation\", \"bound\", \"max_normal_jump\" (radians)}}.
Example: hi surface example torus | hi surface bezier --input - --scheme thesis-cubic -o torus.glb"
);
