// SPDX-License-Identifier: MIT
//! The harmonic tensor-product surface p(u, v) = Σⱼ Σₖ σᵐⱼ(u)·σⁿₖ(v)·xⱼₖ (Hardy 2005, §5.1).

use hi_curve::{ControlPoint, Sigma};
use hi_interval::Interval;

use crate::Error;
use crate::spectrum::Spectrum2;

/// A harmonic tensor-product surface over an m×n grid of points: smooth, 1-periodic in u and
/// in v, and p(j/m, k/n) = xⱼₖ (Hardy 2005, §5.1; docs/math.md §3).
///
/// Row j of the grid runs along v at u = j/m; column k runs along u at v = k/n. Points may be
/// any [`ControlPoint`]; the differential geometry (normals, curvature) needs [`glam::DVec3`].
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_surface::HarmonicSurface;
///
/// let grid = vec![
///     vec![DVec3::new(0.0, 0.0, 0.0), DVec3::new(0.0, 1.0, 0.0), DVec3::new(0.0, 2.0, 1.0)],
///     vec![DVec3::new(1.0, 0.0, 0.5), DVec3::new(1.0, 1.0, 0.0), DVec3::new(1.0, 2.0, 0.0)],
/// ];
/// let s = HarmonicSurface::try_new(grid.clone()).unwrap();
/// assert_eq!((s.m(), s.n()), (2, 3));
/// assert!((s.eval(0.5, 1.0 / 3.0) - grid[1][1]).length() < 1e-15); // interpolates
/// assert!(HarmonicSurface::try_new(vec![vec![DVec3::ZERO], vec![]]).is_err()); // ragged
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HarmonicSurface<P> {
    // Invariant: m, n >= 1; grid.len() == m·n, row-major, all finite; spectrum is its spectrum.
    m: usize,
    n: usize,
    grid: Vec<P>,
    spectrum: Spectrum2<P>,
}

impl<P: ControlPoint> HarmonicSurface<P> {
    /// The surface through the rows of `grid` (row j at u = j/m, point k of a row at v = k/n).
    ///
    /// # Errors
    ///
    /// [`Error::EmptyGrid`], [`Error::RaggedGrid`] naming the first short or long row, and
    /// [`Error::NonFinitePoint`] naming the first NaN or infinite point.
    pub fn try_new(grid: Vec<Vec<P>>) -> Result<Self, Error> {
        let m = grid.len();
        let n = grid.first().map_or(0, Vec::len);
        if m == 0 || n == 0 {
            return Err(Error::EmptyGrid);
        }
        if let Some((row, r)) = grid.iter().enumerate().find(|(_, r)| r.len() != n) {
            return Err(Error::RaggedGrid { row, len: r.len(), expected: n });
        }
        Self::try_from_flat(m, n, grid.into_iter().flatten().collect())
    }

    /// The surface through an m×n grid given row-major in one vector.
    ///
    /// # Errors
    ///
    /// [`Error::EmptyGrid`] if m or n is 0, [`Error::InvalidCount`] if `points.len() != m·n`,
    /// [`Error::NonFinitePoint`].
    pub fn try_from_flat(m: usize, n: usize, points: Vec<P>) -> Result<Self, Error> {
        if m == 0 || n == 0 {
            return Err(Error::EmptyGrid);
        }
        if Some(points.len()) != m.checked_mul(n) {
            return Err(Error::InvalidCount {
                what: "number of grid points",
                value: points.len(),
                expected: "m·n",
            });
        }
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { row: i / n, col: i % n });
        }
        let spectrum = Spectrum2::from_grid(&points, m, n);
        Ok(Self { m, n, grid: points, spectrum })
    }

    /// The surface through `grid`.
    ///
    /// # Panics
    ///
    /// Panics on an empty, ragged or non-finite grid; see [`HarmonicSurface::try_new`].
    #[must_use]
    pub fn new(grid: Vec<Vec<P>>) -> Self {
        Self::try_new(grid).unwrap_or_else(|e| panic!("{e}"))
    }

    /// Number of rows m (the u direction).
    #[must_use]
    pub fn m(&self) -> usize {
        self.m
    }

    /// Number of columns n (the v direction).
    #[must_use]
    pub fn n(&self) -> usize {
        self.n
    }

    /// Grid point xⱼₖ (row j, column k).
    ///
    /// # Panics
    ///
    /// Panics if j ≥ m or k ≥ n.
    #[must_use]
    pub fn point(&self, j: usize, k: usize) -> P {
        assert!(
            j < self.m && k < self.n,
            "grid index ({j}, {k}) out of range {}×{}",
            self.m,
            self.n
        );
        self.grid[j * self.n + k]
    }

    /// The grid, row-major (m rows of n points).
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.grid
    }

    /// The grid as rows.
    #[must_use]
    pub fn rows(&self) -> Vec<Vec<P>> {
        self.grid.chunks(self.n).map(<[P]>::to_vec).collect()
    }

    /// p(u, v) = Σⱼ σᵐⱼ(u)·(Σₖ σⁿₖ(v)·xⱼₖ), the thesis's direct sum: O(mn), exact at the
    /// grid points up to rounding.
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> P {
        // σⁿ(v) on the stack for up to STACK columns, else recomputed per row: no allocation.
        const STACK: usize = 128;
        let sigma_v = Sigma::new(self.n);
        let mut sv = [0.0; STACK];
        if self.n <= STACK {
            sigma_v.for_each_value(v, |k, s| sv[k] = s);
        }
        let mut res = P::ZERO;
        Sigma::new(self.m).for_each_value(u, |j, wu| {
            let row = &self.grid[j * self.n..(j + 1) * self.n];
            let mut along_v = P::ZERO;
            if self.n <= STACK {
                for (x, wv) in row.iter().zip(&sv) {
                    along_v += *x * *wv;
                }
            } else {
                sigma_v.for_each_value(v, |k, wv| along_v += row[k] * wv);
            }
            res += along_v * wu;
        });
        res
    }

    /// The partial derivative ∂^{p+q}p/∂uᵖ∂v^q at (u, v), of any orders, from the 2-D spectrum
    /// (O(mn/4)). `eval_deriv(u, v, 0, 0)` is p(u, v) by the spectral sum.
    #[must_use]
    pub fn eval_deriv(&self, u: f64, v: f64, p: usize, q: usize) -> P {
        self.spectrum.eval_deriv(u, v, p, q)
    }

    /// (p, pᵤ, pᵥ) at (u, v) from the 2-D spectrum in one pass, without allocating: the
    /// kernel of a ray tracer's Newton steps. The same values as [`HarmonicSurface::eval_deriv`]
    /// with (0, 0), (1, 0) and (0, 1), to rounding.
    ///
    /// # Examples
    ///
    /// ```
    /// let t = hi_surface::torus(2.0, 0.5);
    /// let (p, pu, pv) = t.eval_with_partials(0.1, 0.3);
    /// assert!((p - t.eval_deriv(0.1, 0.3, 0, 0)).length() < 1e-13);
    /// assert!((pu - t.eval_deriv(0.1, 0.3, 1, 0)).length() < 1e-12);
    /// assert!((pv - t.eval_deriv(0.1, 0.3, 0, 1)).length() < 1e-12);
    /// ```
    #[must_use]
    pub fn eval_with_partials(&self, u: f64, v: f64) -> (P, P, P) {
        self.spectrum.eval_with_partials(u, v)
    }

    /// An upper bound of ‖∂^{p+q}p/∂uᵖ∂v^q‖ over the whole surface, from its 2-D spectrum in
    /// interval arithmetic (used by the Bézier conversion's guaranteed bound, §5.7).
    ///
    /// # Examples
    ///
    /// ```
    /// // The unit sphere passes through points at distance 1 from the origin.
    /// let s = hi_surface::sphere(1.0);
    /// assert!(s.deriv_bound(0, 0) >= 1.0);
    /// let d = s.eval_deriv(0.1, 0.2, 1, 0).length();
    /// assert!(s.deriv_bound(1, 0) >= d);
    /// ```
    #[must_use]
    pub fn deriv_bound(&self, p: usize, q: usize) -> f64 {
        self.spectrum.deriv_bound(p, q)
    }

    /// An enclosure of the partial derivative ∂^{p+q}p/∂uᵖ∂v^q over the parameter box `u` × `v`,
    /// one interval per coordinate: the spectral sum of [`HarmonicSurface::spectrum_coefficients`]
    /// with each factor differentiated, (cos 2πau)⁽ᵖ⁾ = (2πa)ᵖ·cos(2πau + pπ/2), evaluated in
    /// interval arithmetic with outward rounding (§5.6). Every value of the derivative over the
    /// box lies in it; the interval ray tracer bounds its cells with it.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    ///
    /// // The unit sphere: every point, over any box, lies within [-1, 1] per coordinate.
    /// let s = hi_surface::sphere(1.0);
    /// let (u, v) = (Interval::new(0.1, 0.2), Interval::new(0.3, 0.35));
    /// let e = s.enclose_deriv(u, v, 0, 0);
    /// assert_eq!(e.len(), 3);
    /// for (uu, vv) in [(0.1, 0.3), (0.15, 0.33), (0.2, 0.35)] {
    ///     let p = s.eval(uu, vv);
    ///     assert!(e[0].contains(p.x) && e[1].contains(p.y) && e[2].contains(p.z));
    /// }
    /// ```
    #[must_use]
    pub fn enclose_deriv(&self, u: Interval, v: Interval, p: usize, q: usize) -> Vec<Interval> {
        let mut out = vec![Interval::ZERO; P::DIM];
        self.spectrum.enclose_deriv(u, v, p, q, &mut out);
        out
    }

    /// A bound of the rounding error, per coordinate, of ∂^{p+q}p/∂uᵖ∂v^q evaluated in `f64` by
    /// [`HarmonicSurface::eval_deriv`] or [`HarmonicSurface::eval_with_partials`]: 16·γₖ·Σₐᵦ
    /// (2πa)ᵖ(2πβ)^q·(a + β + 2)·maxᵢ‖coefficient‖∞, where each term's trigonometric values
    /// carry O((a + β + 2)·ε) from the angle additions and the sum O(k·ε) for its k operations
    /// (γₖ = k·u/(1 − k·u), Higham §3.1). A value computed in `f64` plus or minus this bound
    /// encloses the exact derivative of the stored spectrum, which is what the interval ray
    /// tracer needs (§5.6).
    ///
    /// # Examples
    ///
    /// ```
    /// let s = hi_surface::sphere(1.0);
    /// let e = s.eval_error_bound(0, 0);
    /// assert!(e > 0.0 && e < 1e-10);
    /// // Derivatives carry the factors 2πa, so their bound is larger.
    /// assert!(s.eval_error_bound(1, 0) > e);
    /// ```
    #[must_use]
    pub fn eval_error_bound(&self, p: usize, q: usize) -> f64 {
        let order = |k: usize| i32::try_from(k).unwrap_or(i32::MAX);
        self.spectrum.eval_error_bound(order(p), order(q))
    }

    /// The real 2-D spectrum: p(u, v) = Σₐ Σᵦ [Aₐᵦ·cos 2πau·cos 2πβv + Bₐᵦ·cos 2πau·sin 2πβv +
    /// Cₐᵦ·sin 2πau·cos 2πβv + Dₐᵦ·sin 2πau·sin 2πβv] for a ≤ ⌊m/2⌋, β ≤ ⌊n/2⌋ (the tensor
    /// product of the curve spectra of eq. 5.1, even-size Nyquist terms halved, docs/math.md §7), as
    /// `[A, B, C, D]` at index a·(⌊n/2⌋ + 1) + β.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_surface::HarmonicSurface;
    ///
    /// // p = (cos 2πu, sin 2πv, 1) through a 4×4 grid.
    /// let tau = std::f64::consts::TAU;
    /// let rows = (0..4)
    ///     .map(|j| {
    ///         (0..4)
    ///             .map(|k| DVec3::new((tau * j as f64 / 4.0).cos(), (tau * k as f64 / 4.0).sin(), 1.0))
    ///             .collect()
    ///     })
    ///     .collect();
    /// let s = HarmonicSurface::try_new(rows)?;
    /// let c = s.spectrum_coefficients();
    /// assert!((c[0][0] - DVec3::Z).length() < 1e-15); // the mean (a = β = 0)
    /// assert!((c[3][0] - DVec3::X).length() < 1e-15); // A₁₀: cos 2πu (index 1·3 + 0)
    /// assert!((c[1][1] - DVec3::Y).length() < 1e-15); // B₀₁: sin 2πv
    /// # Ok::<(), hi_surface::Error>(())
    /// ```
    #[must_use]
    pub fn spectrum_coefficients(&self) -> &[[P; 4]] {
        self.spectrum.coefficients()
    }

    /// The degrees (⌊m/2⌋, ⌊n/2⌋) of the surface as a trigonometric polynomial in u and v.
    #[must_use]
    pub fn degrees(&self) -> (usize, usize) {
        self.spectrum.degrees()
    }

    /// The largest distance of a grid point from the centroid of the grid.
    #[must_use]
    pub fn radius(&self) -> f64 {
        let centroid =
            self.grid.iter().fold(P::ZERO, |a, p| a + *p) * (1.0 / self.grid.len() as f64);
        self.grid.iter().map(|p| (*p - centroid).norm()).fold(0.0, f64::max)
    }
}
