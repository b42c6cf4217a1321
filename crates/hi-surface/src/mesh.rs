// SPDX-License-Identifier: MIT
//! Triangle meshes of a harmonic surface: the surface evaluated at discrete parameter values
//! and joined into polygons, as for the scanline-rendered torus of Hardy 2005, §5.5
//! (figure 5.25), optionally coloured by curvature as in §5.9.
//!
//! [`TriangleMesh::try_from_surface`] samples p, `p_u` and `p_v` on an (`n_u` + 1)×(`n_v` + 1)
//! grid of a parameter window [u0, u1]×[v0, v1] with the fast grid paths of
//! [`crate::HarmonicSurface`]: the 2-D FFT when the window is exactly [0, 1]², separable basis
//! matrices otherwise. Each grid quad (i, l) becomes the triangles (i, l), (i + 1, l),
//! (i + 1, l + 1) and (i, l), (i + 1, l + 1), (i, l + 1).
//!
//! **Precision.** Positions, normals and UVs are kept in f64 ([`DVec3`], [`DVec2`]), as the
//! surface is evaluated; the exporters round each value once to the f32 of the file formats.
//! Colours are display data and are kept as f32 linear RGB.
//!
//! **Orientation.** Triangles wind counter-clockwise about `p_u × p_v`, and the vertex normals
//! are `p_u × p_v / |p_u × p_v|`; [`MeshOptions::flip`] reverses both. (For [`crate::sphere`]
//! and [`crate::torus`], `p_u × p_v` points outward.)
//!
//! **Seams.** A direction whose window is a whole period (u1 − u0 = 1) is closed: with
//! [`Seam::Welded`] (the default) its last row of samples is the first one and is not repeated,
//! so the mesh is closed there with no vertex repeated; the UVs of the quads closing the seam
//! then run from (n − 1)/n back to 0. glTF stores one UV per vertex, so a correct texture
//! across the seam needs [`Seam::Split`], which repeats the first row as a last one with the
//! same positions and normals (copied, so bit-identical) but UV 1.
//!
//! **Poles.** A row or column of samples whose points all coincide (the poles of the sphere
//! grid; to 10⁻¹⁰ of the larger of the size of the surface and its distance from the origin)
//! is one point of the surface. With [`Seam::Welded`] it becomes one vertex (with the UV of its
//! first sample); with [`Seam::Split`] its samples stay separate vertices so that each keeps
//! its own UV. Either way a triangle with two corners at the same point is dropped, so each
//! quad at a pole gives one triangle, and vertices no triangle uses are removed. Other
//! coincident points (the sphere grid over u ∈ [0, 1] covers the sphere twice) are not merged.
//!
//! **Normals where `p_u × p_v` vanishes** (poles, creases): the sum of the normals of the
//! triangles around the point, weighted by area, normalised (at a pole: the axis); failing
//! that (all those triangles have zero area), the mean of the regular normals of their
//! corners; failing that, +z. Normals are never NaN.
//!
//! **Colours** ([`MeshOptions::color`]) map the curvature at each vertex, from the second
//! derivatives sampled on the same grid; where it is undefined (a pole) the vertex gets the
//! neutral grey of [`crate::ColorMap`], counted in the legend.

use glam::{DVec2, DVec3};

use crate::colormap::{ColorLegend, ColorMap, CurvatureQuantity};
use crate::{Error, HarmonicSurface, SurfaceDerivs};

/// Relative size below which sample points coincide (welding at poles), as a fraction of the
/// size of the surface.
const WELD: f64 = 1e-10;

/// Below this, relative to the size of the surface squared, `|p_u × p_v|` counts as zero (the
/// threshold of [`SurfaceDerivs::normal`]).
const DEGENERATE: f64 = 1e-10;

/// Tolerance on the length of a normal given to [`TriangleMesh::try_new`].
const UNIT_TOLERANCE: f64 = 1e-6;

/// Windows whose width is within this of 1 are a whole period.
const PERIOD_TOLERANCE: f64 = 1e-12;

/// How a closed direction (a window one period wide) meets itself; see the module notes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Seam {
    /// One vertex per surface point: the mesh is closed, UVs wrap back to 0 in the last quads,
    /// and a pole is one vertex.
    #[default]
    Welded,
    /// The first row (column) is repeated with UV 1, and pole samples stay separate, so every
    /// vertex has a UV that is right for all its triangles; positions are still shared exactly.
    Split,
}

/// Colouring a mesh by curvature: which curvature and which colour map.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CurvatureColoring {
    /// The curvature shown. Signs refer to the normals of the mesh (so H changes sign with
    /// [`MeshOptions::flip`]).
    pub quantity: CurvatureQuantity,
    /// The colour map.
    pub map: ColorMap,
}

/// How to mesh a surface: resolution, parameter window, seams, orientation, colours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshOptions {
    /// Number of quads along u (at least 1; at least 3 if the u window is a whole period).
    pub n_u: usize,
    /// Number of quads along v (likewise).
    pub n_v: usize,
    /// The u window [u0, u1], u0 < u1.
    pub u_range: [f64; 2],
    /// The v window [v0, v1], v0 < v1.
    pub v_range: [f64; 2],
    /// How a closed direction meets itself.
    pub seam: Seam,
    /// Reverse the triangles and normals (so they follow `p_v × p_u`).
    pub flip: bool,
    /// Vertex colours from curvature, or none.
    pub color: Option<CurvatureColoring>,
}

impl Default for MeshOptions {
    /// 64×64 quads over the whole period [0, 1]², welded, no colours.
    fn default() -> Self {
        MeshOptions {
            n_u: 64,
            n_v: 64,
            u_range: [0.0, 1.0],
            v_range: [0.0, 1.0],
            seam: Seam::Welded,
            flip: false,
            color: None,
        }
    }
}

/// An indexed triangle mesh with one normal and one UV per vertex and optional vertex colours.
///
/// Invariants (checked by [`TriangleMesh::try_new`]): at least one triangle; every index less
/// than the number of vertices, which is less than 2³² − 1; finite positions and UVs; normals
/// of unit length (to 10⁻⁶); colours, if any, one per vertex with components in [0, 1].
///
/// UVs are (s, t) = ((u − u0)/(u1 − u0), (v − v0)/(v1 − v0)) for a mesh of a surface, in
/// glTF's convention (t down the texture image); the OBJ writer stores (s, 1 − t).
///
/// # Examples
///
/// ```
/// use hi_surface::{MeshOptions, Seam, TriangleMesh, torus};
///
/// let t = torus(2.0, 0.5);
/// let opts = MeshOptions { n_u: 8, n_v: 16, ..Default::default() };
/// let mesh = TriangleMesh::try_from_surface(&t, &opts).unwrap();
/// assert_eq!(mesh.n_vertices(), 8 * 16); // closed both ways: no seam copies
/// assert_eq!(mesh.n_triangles(), 2 * 8 * 16);
/// let split = MeshOptions { n_u: 8, n_v: 16, seam: Seam::Split, ..Default::default() };
/// assert_eq!(TriangleMesh::try_from_surface(&t, &split).unwrap().n_vertices(), 9 * 17);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleMesh {
    positions: Vec<DVec3>,
    normals: Vec<DVec3>,
    uvs: Vec<DVec2>,
    colors: Option<Vec<[f32; 3]>>,
    triangles: Vec<[u32; 3]>,
    legend: Option<ColorLegend>,
}

impl TriangleMesh {
    /// A mesh from its parts, checked against the invariants of [`TriangleMesh`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] for no triangles, too many vertices, a normal or UV count
    /// different from the number of positions, or an index out of range;
    /// [`Error::InvalidValue`] for a non-finite position or UV coordinate or a normal whose
    /// length is not 1.
    pub fn try_new(
        positions: Vec<DVec3>,
        normals: Vec<DVec3>,
        uvs: Vec<DVec2>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Self, Error> {
        let n = positions.len();
        if n >= u32::MAX as usize {
            return Err(Error::InvalidCount {
                what: "number of mesh vertices",
                value: n,
                expected: "less than 2^32 - 1",
            });
        }
        if triangles.is_empty() {
            return Err(Error::InvalidCount {
                what: "number of triangles",
                value: 0,
                expected: "at least 1",
            });
        }
        for (what, len) in [("number of normals", normals.len()), ("number of UVs", uvs.len())] {
            if len != n {
                return Err(Error::InvalidCount { what, value: len, expected: "one per position" });
            }
        }
        if let Some(i) = positions.iter().position(|p| !p.is_finite()) {
            let value =
                positions[i].to_array().into_iter().find(|c| !c.is_finite()).unwrap_or(f64::NAN);
            return Err(Error::InvalidValue {
                what: "coordinate of position",
                index: Some(i),
                value,
                expected: "a finite number",
            });
        }
        if let Some(i) = uvs.iter().position(|t| !t.is_finite()) {
            let value = uvs[i].to_array().into_iter().find(|c| !c.is_finite()).unwrap_or(f64::NAN);
            return Err(Error::InvalidValue {
                what: "coordinate of UV",
                index: Some(i),
                value,
                expected: "a finite number",
            });
        }
        if let Some(i) = normals.iter().position(|v| !is_unit(*v)) {
            return Err(Error::InvalidValue {
                what: "length of normal",
                index: Some(i),
                value: normals[i].length(),
                expected: "1 (within 1e-6)",
            });
        }
        if let Some(&bad) = triangles.iter().flatten().find(|&&k| k as usize >= n) {
            return Err(Error::InvalidCount {
                what: "triangle vertex index",
                value: bad as usize,
                expected: "less than the number of vertices",
            });
        }
        Ok(TriangleMesh { positions, normals, uvs, colors: None, triangles, legend: None })
    }

    /// The mesh with vertex colours (linear RGB, one per vertex), replacing any it had, and
    /// no legend.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] if there is not one colour per vertex, [`Error::InvalidValue`]
    /// for a component outside [0, 1] (or NaN).
    pub fn try_with_colors(mut self, colors: Vec<[f32; 3]>) -> Result<Self, Error> {
        if colors.len() != self.positions.len() {
            return Err(Error::InvalidCount {
                what: "number of colours",
                value: colors.len(),
                expected: "one per vertex",
            });
        }
        if let Some(i) = colors.iter().position(|c| !c.iter().all(|x| (0.0..=1.0).contains(x))) {
            let value = colors[i]
                .into_iter()
                .find(|x| !(0.0..=1.0).contains(x))
                .map_or(f64::NAN, f64::from);
            return Err(Error::InvalidValue {
                what: "component of colour",
                index: Some(i),
                value,
                expected: "in [0, 1]",
            });
        }
        self.colors = Some(colors);
        self.legend = None;
        Ok(self)
    }

    /// The mesh without vertex colours.
    #[must_use]
    pub fn without_colors(mut self) -> Self {
        self.colors = None;
        self.legend = None;
        self
    }

    /// A mesh of `surface` over the window and at the resolution of `options`; see the module
    /// notes for seams, poles and normals.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidWindow`] unless the bounds are finite with u0 < u1 and v0 < v1;
    /// [`Error::InvalidCount`] if `n_u` or `n_v` is 0 (or less than 3 for a whole-period
    /// direction), if the grid is too large for the sampling paths, or if every triangle is
    /// degenerate (a surface that is one point); [`Error::InvalidValue`] for an invalid colour
    /// map.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_surface::{MeshOptions, TriangleMesh, sphere};
    ///
    /// // The sphere once: u ∈ [0, ½] from pole to pole, v closed.
    /// let opts = MeshOptions { n_u: 16, n_v: 32, u_range: [0.0, 0.5], ..Default::default() };
    /// let mesh = TriangleMesh::try_from_surface(&sphere(1.0), &opts).unwrap();
    /// assert_eq!(mesh.n_vertices(), 15 * 32 + 2); // two pole vertices
    /// assert_eq!(mesh.n_triangles(), 2 * 16 * 32 - 2 * 32); // one triangle per pole quad
    /// assert!(mesh.positions().iter().all(|p| (p.length() - 1.0).abs() < 1e-14));
    /// ```
    pub fn try_from_surface(
        surface: &HarmonicSurface<DVec3>,
        options: &MeshOptions,
    ) -> Result<Self, Error> {
        Builder::new(surface, options)?.build()
    }

    /// Number of vertices.
    #[must_use]
    pub fn n_vertices(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    #[must_use]
    pub fn n_triangles(&self) -> usize {
        self.triangles.len()
    }

    /// Vertex positions.
    #[must_use]
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// Unit vertex normals.
    #[must_use]
    pub fn normals(&self) -> &[DVec3] {
        &self.normals
    }

    /// Vertex UVs (s, t), glTF convention (see [`TriangleMesh`]).
    #[must_use]
    pub fn uvs(&self) -> &[DVec2] {
        &self.uvs
    }

    /// Vertex colours, linear RGB in [0, 1], if any.
    #[must_use]
    pub fn colors(&self) -> Option<&[[f32; 3]]> {
        self.colors.as_deref()
    }

    /// The triangles: vertex indices, counter-clockwise about the normal.
    #[must_use]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The legend of the curvature colour map the colours came from, if they did.
    #[must_use]
    pub fn legend(&self) -> Option<&ColorLegend> {
        self.legend.as_ref()
    }

    /// The smallest and largest coordinates of the positions (f64).
    #[must_use]
    pub fn bounds(&self) -> (DVec3, DVec3) {
        self.positions
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)))
    }

    /// The volume the triangles enclose, Σ a·(b × c)/6 over the triangles (divergence
    /// theorem): positive when a closed mesh is wound counter-clockwise seen from outside,
    /// negative when it is wound inwards; for an open mesh, the signed volume of the cone
    /// from the origin.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::{DVec2, DVec3};
    /// use hi_surface::TriangleMesh;
    ///
    /// // The tetrahedron on the unit axes, wound outwards: volume 1/6.
    /// let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    /// let t = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 4], vec![DVec2::ZERO; 4], t)?;
    /// assert!((mesh.signed_volume() - 1.0 / 6.0).abs() < 1e-15);
    /// # Ok::<(), hi_surface::Error>(())
    /// ```
    #[must_use]
    pub fn signed_volume(&self) -> f64 {
        let p = &self.positions;
        self.triangles
            .iter()
            .map(|t| p[t[0] as usize].dot(p[t[1] as usize].cross(p[t[2] as usize])) / 6.0)
            .sum()
    }
}

/// Whether `v` has length 1 to [`UNIT_TOLERANCE`] (false for NaN).
fn is_unit(v: DVec3) -> bool {
    (v.length() - 1.0).abs() <= UNIT_TOLERANCE
}

/// One direction of the window: its parameters and how its logical grid maps to samples.
#[derive(Clone, Copy, Debug)]
struct Axis {
    lo: f64,
    hi: f64,
    /// Number of quads.
    n: usize,
    /// The window is a whole period.
    closed: bool,
}

impl Axis {
    fn new(range: [f64; 2], n: usize, what: &'static str) -> Result<Self, Error> {
        let [lo, hi] = range;
        let closed = ((hi - lo) - 1.0).abs() <= PERIOD_TOLERANCE;
        let min = if closed { 3 } else { 1 };
        if n < min {
            let expected =
                if closed { "at least 3 for a whole-period window" } else { "at least 1" };
            return Err(Error::InvalidCount { what, value: n, expected });
        }
        Ok(Axis { lo, hi, n, closed })
    }

    /// Number of distinct samples: n for a closed direction, n + 1 otherwise.
    fn n_samples(self) -> usize {
        if self.closed { self.n } else { self.n + 1 }
    }

    /// Number of grid lines (logical vertices): the samples, plus the seam copy when split.
    fn n_lines(self, seam: Seam) -> usize {
        if self.closed && seam == Seam::Welded { self.n } else { self.n + 1 }
    }

    fn params(self) -> Vec<f64> {
        let step = (self.hi - self.lo) / self.n as f64;
        (0..self.n_samples()).map(|i| self.lo + step * i as f64).collect()
    }

    /// The sample of grid line i.
    fn sample(self, i: usize) -> usize {
        i % self.n_samples()
    }

    /// The next grid line after i (wrapping for a welded closed direction).
    fn next(self, i: usize, n_lines: usize) -> usize {
        (i + 1) % n_lines
    }
}

/// The sampled derivatives on the grid of distinct samples, row-major (u rows, v columns).
struct Samples {
    n_v: usize,
    p: Vec<DVec3>,
    pu: Vec<DVec3>,
    pv: Vec<DVec3>,
    /// `p_uu`, `p_uv`, `p_vv` when colours are wanted.
    second: Option<[Vec<DVec3>; 3]>,
}

impl Samples {
    fn derivs(&self, k: usize) -> SurfaceDerivs {
        let [puu, puv, pvv] = match &self.second {
            Some([a, b, c]) => [a[k], b[k], c[k]],
            None => [DVec3::ZERO; 3],
        };
        SurfaceDerivs { p: self.p[k], pu: self.pu[k], pv: self.pv[k], puu, puv, pvv }
    }
}

/// Union-find over the logical grid, joining the grid points that are one surface point.
struct Classes(Vec<u32>);

impl Classes {
    fn find(&mut self, mut x: u32) -> u32 {
        while self.0[x as usize] != x {
            let parent = self.0[x as usize];
            self.0[x as usize] = self.0[parent as usize];
            x = parent;
        }
        x
    }

    /// Joins the classes of a and b; the smaller index is the root.
    fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
            self.0[hi as usize] = lo;
        }
    }
}

struct Builder<'a> {
    surface: &'a HarmonicSurface<DVec3>,
    options: MeshOptions,
    u: Axis,
    v: Axis,
    /// The scale of [`HarmonicSurface::curvature`].
    radius: f64,
    /// The size rounding errors of samples are relative to: the largest of the radius and the
    /// distances of the grid points from the origin.
    size: f64,
}

impl<'a> Builder<'a> {
    fn new(surface: &'a HarmonicSurface<DVec3>, options: &MeshOptions) -> Result<Self, Error> {
        let [u0, u1] = options.u_range;
        let [v0, v1] = options.v_range;
        let window = [u0, u1, v0, v1];
        if !window.iter().all(|x| x.is_finite()) || u0 >= u1 || v0 >= v1 {
            return Err(Error::InvalidWindow { window });
        }
        let u = Axis::new(options.u_range, options.n_u, "number of quads along u")?;
        let v = Axis::new(options.v_range, options.n_v, "number of quads along v")?;
        for n in [options.n_u, options.n_v] {
            if n >= 1 << 24 {
                return Err(Error::InvalidCount {
                    what: "number of quads",
                    value: n,
                    expected: "less than 2^24",
                });
            }
        }
        let lines = u.n_lines(options.seam).saturating_mul(v.n_lines(options.seam));
        if lines > 1 << 28 {
            return Err(Error::InvalidCount {
                what: "number of mesh vertices",
                value: lines,
                expected: "at most 2^28",
            });
        }
        let radius = surface.radius();
        let size = surface.points().iter().map(|p| p.length()).fold(radius, f64::max);
        Ok(Builder { surface, options: *options, u, v, radius, size })
    }

    fn sample(&self) -> Result<Samples, Error> {
        let fft = self.u.closed && self.v.closed && self.u.lo == 0.0 && self.v.lo == 0.0;
        let (us, vs) = (self.u.params(), self.v.params());
        let grid = |p: usize, q: usize| -> Result<Vec<DVec3>, Error> {
            let g = if fft {
                self.surface.sample_uniform(us.len(), vs.len(), p, q)?
            } else {
                self.surface.sample_params(&us, &vs, p, q)?
            };
            Ok(g.values)
        };
        let second = match self.options.color {
            Some(_) => Some([grid(2, 0)?, grid(1, 1)?, grid(0, 2)?]),
            None => None,
        };
        Ok(Samples { n_v: vs.len(), p: grid(0, 0)?, pu: grid(1, 0)?, pv: grid(0, 1)?, second })
    }

    fn build(self) -> Result<TriangleMesh, Error> {
        let samples = self.sample()?;
        let seam = self.options.seam;
        let (rows, cols) = (self.u.n_lines(seam), self.v.n_lines(seam));
        let line = |i: usize, l: usize| (i * cols + l) as u32;
        let sample_of = |g: u32| {
            let (i, l) = (g as usize / cols, g as usize % cols);
            self.u.sample(i) * samples.n_v + self.v.sample(l)
        };
        let tol = WELD * self.size;

        // Which grid points are one surface point: seam copies, collapsed rows and columns.
        let mut same = Classes((0..(rows * cols) as u32).collect());
        if seam == Seam::Split {
            if self.u.closed {
                for l in 0..cols {
                    same.union(line(0, l), line(rows - 1, l));
                }
            }
            if self.v.closed {
                for i in 0..rows {
                    same.union(line(i, 0), line(i, cols - 1));
                }
            }
        }
        let p = |g: u32| samples.p[sample_of(g)];
        for i in 0..rows {
            let first = p(line(i, 0));
            if (1..cols).all(|l| p(line(i, l)).distance(first) <= tol) {
                for l in 1..cols {
                    same.union(line(i, 0), line(i, l));
                }
            }
        }
        for l in 0..cols {
            let first = p(line(0, l));
            if (1..rows).all(|i| p(line(i, l)).distance(first) <= tol) {
                for i in 1..rows {
                    same.union(line(0, l), line(i, l));
                }
            }
        }
        let key: Vec<u32> = (0..(rows * cols) as u32).map(|g| same.find(g)).collect();
        // A vertex is a class when welded, a grid point when split.
        let vertex_of = |g: u32| if seam == Seam::Welded { key[g as usize] } else { g };

        // Triangles, over grid vertex ids, dropping those with two corners at one point.
        let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(2 * self.u.n * self.v.n);
        for i in 0..self.u.n {
            let i1 = self.u.next(i, rows);
            for l in 0..self.v.n {
                let l1 = self.v.next(l, cols);
                let (a, b, c, d) = (line(i, l), line(i1, l), line(i1, l1), line(i, l1));
                for t in [[a, b, c], [a, c, d]] {
                    let [ka, kb, kc] = t.map(|g| key[g as usize]);
                    if ka != kb && kb != kc && ka != kc {
                        triangles.push(t.map(vertex_of));
                    }
                }
            }
        }
        if triangles.is_empty() {
            return Err(Error::InvalidCount {
                what: "number of non-degenerate triangles",
                value: 0,
                expected: "at least 1 (the surface is a single point over the window)",
            });
        }

        // Keep the vertices that triangles use, in grid order.
        let mut new_index = vec![u32::MAX; rows * cols];
        for &g in triangles.iter().flatten() {
            new_index[g as usize] = 0;
        }
        let mut used: Vec<u32> = Vec::with_capacity(rows * cols);
        for (g, slot) in new_index.iter_mut().enumerate() {
            if *slot == 0 {
                *slot = used.len() as u32;
                used.push(g as u32);
            }
        }
        let positions: Vec<DVec3> = used.iter().map(|&g| p(g)).collect();

        // Normals: `p_u × p_v`, or the fallbacks of the module notes where it vanishes.
        let floor = DEGENERATE * self.size * self.size;
        let regular = |g: u32| {
            let k = sample_of(g);
            let c = samples.pu[k].cross(samples.pv[k]);
            let len = c.length();
            (len > floor && len.is_finite()).then(|| c / len)
        };
        let mut normals: Vec<Option<DVec3>> = used.iter().map(|&g| regular(g)).collect();
        if normals.iter().any(Option::is_none) {
            fill_degenerate_normals(
                &mut normals,
                &used,
                &key,
                &triangles,
                &new_index,
                &|g| p(g),
                &regular,
            );
        }
        let sign = if self.options.flip { -1.0 } else { 1.0 };
        let normals: Vec<DVec3> =
            normals.into_iter().map(|n| sign * n.unwrap_or(DVec3::Z)).collect();

        let uvs: Vec<DVec2> = used
            .iter()
            .map(|&g| {
                let (i, l) = (g as usize / cols, g as usize % cols);
                DVec2::new(i as f64 / self.u.n as f64, l as f64 / self.v.n as f64)
            })
            .collect();

        let triangles: Vec<[u32; 3]> = triangles
            .into_iter()
            .map(|t| {
                let [a, b, c] = t.map(|g| new_index[g as usize]);
                if self.options.flip { [a, c, b] } else { [a, b, c] }
            })
            .collect();

        let mut mesh = TriangleMesh::try_new(positions, normals, uvs, triangles)?;
        if let Some(coloring) = self.options.color {
            let odd = coloring.quantity.is_odd_in_normal() && self.options.flip;
            let values: Vec<f64> = used
                .iter()
                .map(|&g| {
                    samples.derivs(sample_of(g)).curvature(self.radius).map_or(f64::NAN, |c| {
                        if odd { -coloring.quantity.of(&c) } else { coloring.quantity.of(&c) }
                    })
                })
                .collect();
            let mapping = coloring.map.try_apply(&values)?;
            mesh = mesh.try_with_colors(mapping.colors)?;
            mesh.legend = Some(mapping.legend);
        }
        Ok(mesh)
    }
}

/// Normals where `p_u × p_v` vanishes: the area-weighted sum of the normals of the triangles
/// around the surface point (all grid points of its class), else the mean of the regular
/// normals of those triangles' corners; `None` is left where both fail.
fn fill_degenerate_normals(
    normals: &mut [Option<DVec3>],
    used: &[u32],
    key: &[u32],
    triangles: &[[u32; 3]],
    new_index: &[u32],
    position: &dyn Fn(u32) -> DVec3,
    regular: &dyn Fn(u32) -> Option<DVec3>,
) {
    // Accumulators per class of the vertices that need one.
    let mut slot = std::collections::HashMap::new();
    for (k, &g) in used.iter().enumerate() {
        if normals[k].is_none() {
            let next = slot.len();
            slot.entry(key[g as usize]).or_insert(next);
        }
    }
    let mut area_sum = vec![DVec3::ZERO; slot.len()];
    let mut corner_sum = vec![DVec3::ZERO; slot.len()];
    for t in triangles {
        let [a, b, c] = t.map(position);
        let face = (b - a).cross(c - a);
        for &g in t {
            if let Some(&s) = slot.get(&key[g as usize]) {
                area_sum[s] += face;
                for &h in t {
                    let n = normals[new_index[h as usize] as usize].or_else(|| regular(h));
                    corner_sum[s] += n.unwrap_or(DVec3::ZERO);
                }
            }
        }
    }
    for (k, &g) in used.iter().enumerate() {
        if normals[k].is_none() {
            let s = slot[&key[g as usize]];
            normals[k] = area_sum[s].try_normalize().or_else(|| corner_sum[s].try_normalize());
        }
    }
}
