// SPDX-License-Identifier: MIT
//! B-spline surface interpolation through slices of data (Hardy 2005, §4.4, "B-Spline Surface
//! Interpolation", the algorithm of Watt & Watt, figure 4.5): the curve network and the
//! tensor-product surface it defines, and its conversion to bicubic Bézier patches.
//!
//! # The algorithm
//!
//! The data points come in groups, the *slices* (one list of 3-D points each, of any lengths).
//!
//! 1. **U-curves** (figure 4.5(a)). Through each slice s, the interpolating cubic B-spline
//!    Cₛ(u) of §2.11 (`hi_curve`'s `InterpolatingSpline`), with chord-length parameters
//!    (or uniform, or given ones) on [0, 1]: open with an [`EndCondition`], or periodic when
//!    the slices are closed curves (`closed_u`).
//! 2. **The U-knot vector**: the union of the distinct knots of all U-curves.
//! 3. **U-curves on it** (figure 4.5(b)): each U-curve's missing knots are inserted
//!    ([`insert_knots`], Boehm's knot insertion). This is exact: every U-curve is unchanged and
//!    all of them now have the same knots, so the same number M of control points Pₛ,ᵢ.
//! 4. **V-curves** (figure 4.5(c)). For each i = 0, …, M − 1, the interpolating cubic through
//!    the control points P₀,ᵢ, …, P_{S−1},ᵢ at common parameters v₀ < … < v_{S−1}. By default
//!    these are chord-length parameters averaged over the knot lines: for every distinct
//!    U-knot ū, the chord-length parameters of the points C₀(ū), …, C_{S−1}(ū), averaged
//!    (Piegl & Tiller's averaging, *The NURBS Book* §9.2.5).
//! 5. **The V-knot vector** (figure 4.5(d)): all V-curves have the same parameters, hence the
//!    same knots; there is nothing left to merge. The result (figure 4.5(e)) is the bicubic
//!    tensor-product B-spline [`BSplineSurface`] whose control point xᵢₗ is control point l of
//!    V-curve i.
//!
//! # What is exact, and what is the thesis's heuristic
//!
//! * The surface passes through every data point: at v = vₛ the tensor product reduces to
//!   Σᵢ Nᵢ(u)·Pₛ,ᵢ = Cₛ(u), the U-curve of slice s, which interpolates the slice. The tests
//!   check this to 1e-12 relative.
//! * Interpolating the *control points* Pₛ,ᵢ column by column is what makes the surface a
//!   true tensor product. Interpolation with fixed parameters and end conditions is linear, so
//!   the iso-curve u = ū of the surface is the cubic through the *curve points* Cₛ(ū): the
//!   thesis's V-curves through the U-curves at the U-knots are exactly the surface's knot
//!   lines ([`BSplineFit::v_curves`]), and the curve network of figure 4.5(e) lies on it.
//! * The thesis gives every V-curve its own chord-length parameters and merges their knot
//!   vectors by knot insertion (its step 5). Knot insertion keeps each V-curve, but curves that
//!   pass through the data at *different* parameters cannot be the iso-curves of one tensor
//!   product through the data: at any fixed v they hit different slices. Here the V-curves
//!   share averaged parameters instead, so step 5 becomes trivial and interpolation is exact;
//!   the per-curve parameters survive only as the average.
//! * The U direction follows the thesis as written: each slice keeps its own chord-length
//!   parameters, so slices may have different numbers of points. The price is a U-knot vector
//!   with the knots of every slice (nearly equal parameters of different slices give short
//!   knot intervals; they are kept, since removing them would change the U-curves).
//!
//! The conversion to Bézier patches is available exactly
//! ([`BSplineSurface::to_bezier_patches`]: multiple knot insertion in both directions) and as
//! Watt & Watt describe it ([`BSplineSurface::to_adini_patches`]: the network's Bézier
//! segments as boundaries, the interior points from Adini's twist estimate).
//!
//! # Requirements
//!
//! At least 2 slices (3 when `closed_v`, 4 with [`EndCondition::NotAKnot`] along v); each
//! slice at least 2 points (3 when `closed_u`, 4 with not-a-knot along u); finite coordinates;
//! no two consecutive points of a slice equal (nor the last and first of a closed slice) with
//! chord-length parameters; no two consecutive slices equal. Slices may have different
//! lengths, except with [`Parameters::Given`] along u (one parameter list for every slice).

mod axis;
mod patches;
mod surface;

use crate::bspline::BSplineCurve;
use crate::bspline_interp::InterpolatingSpline;
pub use crate::bspline_interp::{EndCondition, Parameters};
use glam::DVec3;

use self::axis::Axis;
pub use self::patches::BezierPatchGrid;
pub use self::surface::{BSplineSurface, insert_knots};
use crate::Error;

/// The choices of [`BSplineFit::try_new`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BSplineFitOptions {
    /// The slices are closed curves: periodic U-curves (do not repeat the first point).
    pub closed_u: bool,
    /// The surface closes across the slices: the last slice is followed by the first.
    pub closed_v: bool,
    /// How the U-curves end when open.
    pub end_u: EndCondition,
    /// How the V-curves end when open.
    pub end_v: EndCondition,
    /// The parameters of the points of each slice: chord length per slice (the thesis's
    /// choice), uniform per slice, or one given list for every slice (equal slice lengths;
    /// strictly increasing, mapped affinely onto [0, 1] when open, in [0, 1) when closed).
    pub u_params: Parameters,
    /// The parameters v₀ < … < v_{S−1} of the slices: chord length averaged over the knot
    /// lines (see the [module documentation](self)), uniform, or given (as for `u_params`).
    pub v_params: Parameters,
}

impl Default for BSplineFitOptions {
    /// Open both ways, natural ends (zero second derivatives, scipy's `bc_type='natural'`),
    /// chord-length parameters.
    fn default() -> Self {
        Self {
            closed_u: false,
            closed_v: false,
            end_u: EndCondition::Natural,
            end_v: EndCondition::Natural,
            u_params: Parameters::ChordLength,
            v_params: Parameters::ChordLength,
        }
    }
}

/// A bicubic B-spline surface through slices of data, with the stages of its curve network
/// (§4.4, figure 4.5); see the [module documentation](self).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_compare::bspline_fit::{BSplineFit, BSplineFitOptions};
///
/// // Three slices of different lengths across a bump.
/// let slices = vec![
///     vec![DVec3::new(0.0, 0.0, 0.0), DVec3::new(1.0, 0.0, 0.5), DVec3::new(2.0, 0.0, 0.0)],
///     vec![DVec3::new(0.0, 1.0, 0.2), DVec3::new(0.7, 1.0, 1.0), DVec3::new(1.4, 1.0, 0.9),
///          DVec3::new(2.0, 1.0, 0.1)],
///     vec![DVec3::new(0.0, 2.0, 0.0), DVec3::new(1.0, 2.1, 0.4), DVec3::new(2.0, 2.0, 0.0)],
/// ];
/// let fit = BSplineFit::try_new(slices.clone(), &BSplineFitOptions::default()).unwrap();
/// // Every data point is on the surface, at its slice's parameters.
/// for (s, slice) in slices.iter().enumerate() {
///     for (k, x) in slice.iter().enumerate() {
///         let p = fit.surface().eval(fit.u_params()[s][k], fit.v_params()[s]);
///         assert!((p - *x).length() < 1e-12);
///     }
/// }
/// // The merged U-knots are the union of the slices' knots: 0, ½ (slices 0 and 2), the
/// // two of slice 1, and 1.
/// assert_eq!(fit.surface().u_breakpoints().len(), 5);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineFit {
    slices: Vec<Vec<DVec3>>,
    u_params: Vec<Vec<f64>>,
    v_params: Vec<f64>,
    u_curves: Vec<BSplineCurve<DVec3>>,
    merged_u_curves: Vec<BSplineCurve<DVec3>>,
    surface: BSplineSurface,
}

impl BSplineFit {
    /// Fits the surface to `slices` (§4.4, steps 1–5).
    ///
    /// # Errors
    ///
    /// [`Error::TooFewSlices`] and [`Error::TooFewSlicePoints`] for too little data,
    /// [`Error::NonFiniteSlicePoint`] naming a slice and point with a NaN or infinite
    /// coordinate, [`Error::SliceLengthMismatch`] for slices of different lengths with given
    /// u parameters, [`Error::CoincidentSlicePoints`] for equal consecutive points of a slice
    /// (zero chord length), [`Error::CoincidentSlices`] for consecutive slices whose averaged
    /// chord length is zero, and the errors of the B-spline interpolation for given
    /// parameters that are invalid or a solve that overflows.
    pub fn try_new(slices: Vec<Vec<DVec3>>, options: &BSplineFitOptions) -> Result<Self, Error> {
        check_slices(&slices, options)?;
        // Step 1: the U-curves.
        let mut u_curves = Vec::with_capacity(slices.len());
        let mut u_params = Vec::with_capacity(slices.len());
        for slice in &slices {
            let spline = if options.closed_u {
                InterpolatingSpline::try_periodic(slice.clone(), options.u_params.clone())?
            } else {
                InterpolatingSpline::try_open(
                    slice.clone(),
                    options.u_params.clone(),
                    options.end_u,
                )?
            };
            u_params.push(spline.params().to_vec());
            u_curves.push(spline.spline().clone());
        }
        // Steps 2 and 3: the merged U-knot vector, every U-curve refined onto it.
        let u_axis = merged_axis(&u_curves, options.closed_u)?;
        let mut rows = Vec::with_capacity(slices.len());
        let mut merged_u_curves = Vec::with_capacity(slices.len());
        for curve in &u_curves {
            let own = Axis::try_new(
                curve.knots().to_vec(),
                curve.control_points().len(),
                options.closed_u,
                "u knot",
            )?;
            let control = own.refine(curve.control_points(), &u_axis);
            merged_u_curves.push(curve_on(&u_axis, control.clone())?);
            rows.push(control);
        }
        // Step 4: the common V parameters, then the V-curves through the control columns.
        let v_params = slice_params(&merged_u_curves, &u_axis, options)?;
        let given = Parameters::Given(v_params.clone());
        let n_u = u_axis.n_control;
        let mut columns = Vec::with_capacity(n_u);
        let mut v_knots = Vec::new();
        for i in 0..n_u {
            let column: Vec<DVec3> = rows.iter().map(|r| r[i]).collect();
            let spline = if options.closed_v {
                InterpolatingSpline::try_periodic(column, given.clone())?
            } else {
                InterpolatingSpline::try_open(column, given.clone(), options.end_v)?
            };
            v_knots = spline.spline().knots().to_vec();
            columns.push(spline.spline().control_points().to_vec());
        }
        // Step 5: one V-knot vector (the parameters are common), and the tensor product.
        let n_v = columns[0].len();
        let v_axis = Axis::try_new(v_knots, n_v, options.closed_v, "v knot")?;
        let surface = BSplineSurface::from_parts(u_axis, v_axis, columns.concat());
        Ok(Self { slices, u_params, v_params, u_curves, merged_u_curves, surface })
    }

    /// The data, one list of points per slice.
    #[must_use]
    pub fn slices(&self) -> &[Vec<DVec3>] {
        &self.slices
    }

    /// The tensor-product surface; slice s's point k is p(`u_params()[s][k]`, `v_params()[s]`).
    #[must_use]
    pub fn surface(&self) -> &BSplineSurface {
        &self.surface
    }

    /// The parameters of the points of each slice along u, in [0, 1].
    #[must_use]
    pub fn u_params(&self) -> &[Vec<f64>] {
        &self.u_params
    }

    /// The parameter vₛ of each slice along v, in [0, 1].
    #[must_use]
    pub fn v_params(&self) -> &[f64] {
        &self.v_params
    }

    /// The U-curves on their own knots (step 1, figure 4.5(a)).
    #[must_use]
    pub fn u_curves(&self) -> &[BSplineCurve<DVec3>] {
        &self.u_curves
    }

    /// The U-curves on the merged U-knot vector (step 3, figure 4.5(b)): the same curves as
    /// [`BSplineFit::u_curves`], and the iso-curves v = vₛ of the surface.
    #[must_use]
    pub fn merged_u_curves(&self) -> &[BSplineCurve<DVec3>] {
        &self.merged_u_curves
    }

    /// The merged U-knots: the distinct knots of all U-curves, increasing, from 0 to 1.
    #[must_use]
    pub fn u_knots(&self) -> Vec<f64> {
        self.surface.u_breakpoints()
    }

    /// The V-curves at the U-knots (steps 4–5, figure 4.5(c)–(e)): the iso-curves u = ū of
    /// the surface at every distinct U-knot ū (the last, 1, left out when closed), each
    /// through the points Cₛ(ū) of the U-curves at vₛ, on the V-knot vector.
    #[must_use]
    pub fn v_curves(&self) -> Vec<BSplineCurve<DVec3>> {
        let mut knots = self.u_knots();
        if self.surface.is_closed_u() {
            knots.pop();
        }
        knots.into_iter().map(|u| self.surface.iso_u(u)).collect()
    }
}

/// Checks the slices against the requirements of the module documentation (the parameters
/// themselves are checked by `hi_curve`).
fn check_slices(slices: &[Vec<DVec3>], options: &BSplineFitOptions) -> Result<(), Error> {
    let needed_slices = if options.closed_v {
        3
    } else if options.end_v == EndCondition::NotAKnot {
        4
    } else {
        2
    };
    if slices.len() < needed_slices {
        return Err(Error::TooFewSlices { needed: needed_slices, got: slices.len() });
    }
    let needed_points = if options.closed_u {
        3
    } else if options.end_u == EndCondition::NotAKnot {
        4
    } else {
        2
    };
    for (slice, points) in slices.iter().enumerate() {
        if points.len() < needed_points {
            return Err(Error::TooFewSlicePoints {
                slice,
                needed: needed_points,
                got: points.len(),
            });
        }
        if let Some(point) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFiniteSlicePoint { slice, point });
        }
    }
    if let Parameters::Given(given) = &options.u_params
        && let Some((slice, points)) =
            slices.iter().enumerate().find(|(_, s)| s.len() != given.len())
    {
        return Err(Error::SliceLengthMismatch { slice, len: points.len(), expected: given.len() });
    }
    if options.u_params == Parameters::ChordLength {
        for (slice, points) in slices.iter().enumerate() {
            let n = points.len();
            let pairs =
                (0..n - 1).map(|k| (k, k + 1)).chain(options.closed_u.then_some((n - 1, 0)));
            for (first, second) in pairs {
                if points[first] == points[second] {
                    return Err(Error::CoincidentSlicePoints { slice, first, second });
                }
            }
        }
    }
    Ok(())
}

/// The direction whose knots are the union of the distinct knots of `curves` (all on [0, 1]).
fn merged_axis(curves: &[BSplineCurve<DVec3>], closed: bool) -> Result<Axis, Error> {
    let mut all: Vec<f64> = curves.iter().flat_map(|c| c.knots().iter().copied()).collect();
    all.sort_by(f64::total_cmp);
    all.dedup();
    if closed {
        // Breakpoints: the distinct values, τₙ = τ₀ + 1 last.
        let n = all.len() - 1;
        Axis::try_new(all, n, true, "u knot")
    } else {
        // Clamped: 0 and 1 four times, the distinct interior knots once.
        let (a, b) = (all[0], all[all.len() - 1]);
        let mut knots = vec![a; 3];
        knots.extend_from_slice(&all);
        knots.extend([b; 3]);
        let n = knots.len() - 4;
        Axis::try_new(knots, n, false, "u knot")
    }
}

/// The cubic B-spline along `axis` with these control points.
fn curve_on(axis: &Axis, control: Vec<DVec3>) -> Result<BSplineCurve<DVec3>, Error> {
    Ok(if axis.closed {
        BSplineCurve::try_new_periodic(3, axis.knots.clone(), control)?
    } else {
        BSplineCurve::try_new(3, axis.knots.clone(), control)?
    })
}

/// The parameters of the slices along v (step 4).
fn slice_params(
    curves: &[BSplineCurve<DVec3>],
    u_axis: &Axis,
    options: &BSplineFitOptions,
) -> Result<Vec<f64>, Error> {
    let n = curves.len();
    match &options.v_params {
        Parameters::Uniform => {
            let d = if options.closed_v { n } else { n - 1 } as f64;
            Ok((0..n).map(|s| s as f64 / d).collect())
        }
        // Open: mapped onto [0, 1] as the V-curves will map them (bad lists are left for
        // `hi_curve` to name).
        Parameters::Given(given) if !options.closed_v && given.len() == n && n >= 2 => {
            let (a, b) = (given[0], given[n - 1]);
            let mut res: Vec<f64> = given.iter().map(|&v| (v - a) / (b - a)).collect();
            res[n - 1] = 1.0;
            Ok(res)
        }
        Parameters::Given(given) => Ok(given.clone()),
        Parameters::ChordLength => {
            let mut lines = u_axis.breakpoints();
            if u_axis.closed {
                lines.pop();
            }
            let n_chords = if options.closed_v { n } else { n - 1 };
            let mut sum = vec![0.0; n_chords];
            let mut n_lines = 0usize;
            for &u in &lines {
                let points: Vec<DVec3> = curves.iter().map(|c| c.eval(u)).collect();
                let chords: Vec<f64> =
                    (0..n_chords).map(|s| points[s].distance(points[(s + 1) % n])).collect();
                let total: f64 = chords.iter().sum();
                // A knot line that is one point (a pole) says nothing about the spacing.
                if total > 0.0 && total.is_finite() {
                    for (acc, c) in sum.iter_mut().zip(&chords) {
                        *acc += c / total;
                    }
                    n_lines += 1;
                }
            }
            if let Some(first) = sum.iter().position(|&c| c == 0.0) {
                return Err(Error::CoincidentSlices { first, second: (first + 1) % n });
            }
            let mut res = Vec::with_capacity(n);
            let mut acc = 0.0;
            res.push(0.0);
            for c in &sum[..n - 1] {
                acc += c / n_lines as f64;
                res.push(acc);
            }
            if !options.closed_v {
                res[n - 1] = 1.0;
            }
            Ok(res)
        }
    }
}
