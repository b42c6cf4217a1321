// SPDX-License-Identifier: MIT
//! Triangle meshes of a harmonic surface: the surface evaluated at discrete parameter values
//! and joined into polygons, as for the scanline-rendered torus of Hardy 2005, §5.5
//! (figure 5.25), optionally coloured by curvature as in §5.9.
//!
//! [`HarmonicSurface::to_mesh`] samples p, `p_u` and `p_v` on an (`n_u` + 1)×(`n_v` + 1)
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

use hi_mesh::{ColorMap, TriangleMesh};

use crate::{CurvatureQuantity, Error, HarmonicSurface, ParamRange, ParamWindow, SurfaceDerivs};

/// Relative size below which sample points coincide (welding at poles), as a fraction of the
/// size of the surface.
const WELD: f64 = 1e-10;

/// Below this, relative to the size of the surface squared, `|p_u × p_v|` counts as zero (the
/// threshold of [`SurfaceDerivs::normal`]).
const DEGENERATE: f64 = 1e-10;

/// Windows whose width is within this of 1 are a whole period.
const PERIOD_TOLERANCE: f64 = 1e-12;

/// How a closed direction (a window one period wide) meets itself; see the module notes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
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
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CurvatureColoring {
    /// The curvature shown. Signs refer to the normals of the mesh (so H changes sign with
    /// [`MeshOptions::flip`]).
    pub quantity: CurvatureQuantity,
    /// The colour map.
    pub map: ColorMap,
}

/// How to mesh a surface: resolution, parameter window, seams, orientation, colours.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MeshOptions {
    /// Number of quads along u (at least 1; at least 3 if the u window is a whole period).
    pub n_u: usize,
    /// Number of quads along v (likewise).
    pub n_v: usize,
    /// The window [u0, u1] × [v0, v1] to mesh, u0 < u1 and v0 < v1.
    pub window: ParamWindow,
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
            window: ParamWindow::UNIT,
            seam: Seam::Welded,
            flip: false,
            color: None,
        }
    }
}

impl HarmonicSurface<DVec3> {
    /// A mesh of the surface over the window and at the resolution of `options`; see the module
    /// notes for seams, poles and normals.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidWindow`] unless the bounds are finite with u0 < u1 and v0 < v1;
    /// [`Error::InvalidCount`] if `n_u` or `n_v` is 0 (or less than 3 for a whole-period
    /// direction), if the grid is too large for the sampling paths, or if every triangle is
    /// degenerate (a surface that is one point); [`Error::Mesh`] for an invalid colour map.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_surface::{MeshOptions, ParamRange, ParamWindow, Seam, sphere, torus};
    ///
    /// // The sphere once: u ∈ [0, ½] from pole to pole, v closed.
    /// let window = ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::UNIT);
    /// let opts = MeshOptions { n_u: 16, n_v: 32, window, ..Default::default() };
    /// let mesh = sphere(1.0).to_mesh(&opts).unwrap();
    /// assert_eq!(mesh.n_vertices(), 15 * 32 + 2); // two pole vertices
    /// assert_eq!(mesh.n_triangles(), 2 * 16 * 32 - 2 * 32); // one triangle per pole quad
    /// assert!(mesh.positions().iter().all(|p| (p.length() - 1.0).abs() < 1e-14));
    ///
    /// // The torus is closed both ways: welded, no seam copies; split, one more row and column.
    /// let t = torus(2.0, 0.5);
    /// let opts = MeshOptions { n_u: 8, n_v: 16, ..Default::default() };
    /// let mesh = t.to_mesh(&opts).unwrap();
    /// assert_eq!((mesh.n_vertices(), mesh.n_triangles()), (8 * 16, 2 * 8 * 16));
    /// let split = MeshOptions { seam: Seam::Split, ..opts };
    /// assert_eq!(t.to_mesh(&split).unwrap().n_vertices(), 9 * 17);
    /// ```
    pub fn to_mesh(&self, options: &MeshOptions) -> Result<TriangleMesh, Error> {
        Builder::new(self, options)?.build()
    }
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
    fn new(range: ParamRange, n: usize, what: &'static str) -> Result<Self, Error> {
        let (lo, hi) = (range.start, range.end);
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
        let window = options.window;
        if !window.u.is_increasing() || !window.v.is_increasing() {
            return Err(Error::InvalidWindow { window });
        }
        let u = Axis::new(window.u, options.n_u, "number of quads along u")?;
        let v = Axis::new(window.v, options.n_v, "number of quads along v")?;
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

    /// The first stage of `build`: which grid points are one surface point (seam copies,
    /// collapsed rows and columns), as each grid point's class.
    fn weld(&self, samples: &Samples, rows: usize, cols: usize) -> Vec<u32> {
        let seam = self.options.seam;
        let line = |i: usize, l: usize| (i * cols + l) as u32;
        let sample_of = |g: u32| {
            let (i, l) = (g as usize / cols, g as usize % cols);
            self.u.sample(i) * samples.n_v + self.v.sample(l)
        };
        let tol = WELD * self.size;
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
        (0..(rows * cols) as u32).map(|g| same.find(g)).collect()
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

        let key = self.weld(&samples, rows, cols);
        let p = |g: u32| samples.p[sample_of(g)];
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

        let (new_index, used) = used_vertices(&triangles, rows * cols);
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
            mesh = mesh.try_with_mapping(mapping)?;
        }
        Ok(mesh)
    }
}

/// The vertices the triangles (over grid points `0..n`) use, in grid order: each grid point's
/// new index (`u32::MAX` if unused), and the grid point of each vertex.
fn used_vertices(triangles: &[[u32; 3]], n: usize) -> (Vec<u32>, Vec<u32>) {
    let mut new_index = vec![u32::MAX; n];
    for &g in triangles.iter().flatten() {
        new_index[g as usize] = 0;
    }
    let mut used: Vec<u32> = Vec::with_capacity(n);
    for (g, slot) in new_index.iter_mut().enumerate() {
        if *slot == 0 {
            *slot = used.len() as u32;
            used.push(g as u32);
        }
    }
    (new_index, used)
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
