// SPDX-License-Identifier: MIT
//! Reference computations, for tests and benchmarks: the thesis's direct sum beside the fast
//! grid paths of [`HarmonicSurface`]. Each gives the same result as a faster method, named in
//! its documentation; none is the way to compute anything.
//!
//! Compiled only with the crate's `testing` feature.

use hi_par::*;

use crate::grid::{check_params, check_sizes};
use hi_curve::ControlPoint;

use crate::{Error, GridSamples, HarmonicSurface};

/// p at every (uᵢ, vₗ) by the direct sum of [`HarmonicSurface::eval`] (§5.1), O(U·V·m·n):
/// the same values as [`HarmonicSurface::sample_params`] with p = q = 0 (separable basis
/// matrices), to rounding.
///
/// # Errors
///
/// As [`HarmonicSurface::sample_params`].
///
/// # Examples
///
/// ```
/// use hi_surface::{testing, torus};
///
/// let t = torus(2.0, 0.5);
/// let (us, vs) = ([0.1, 0.7], [0.0, 0.3, 0.9]);
/// let fast = t.sample_params(&us, &vs, 0, 0)?;
/// let direct = testing::sample_params_direct(&t, &us, &vs)?;
/// assert!(fast.values.iter().zip(&direct.values).all(|(a, b)| (*a - *b).length() < 1e-13));
/// # Ok::<(), hi_surface::Error>(())
/// ```
pub fn sample_params_direct<P: ControlPoint>(
    surface: &HarmonicSurface<P>,
    us: &[f64],
    vs: &[f64],
) -> Result<GridSamples<P>, Error> {
    check_sizes(us.len(), vs.len())?;
    check_params("u", us)?;
    check_params("v", vs)?;
    let values =
        us.par_iter().flat_map_iter(|&u| vs.iter().map(move |&v| surface.eval(u, v))).collect();
    Ok(GridSamples { n_u: us.len(), n_v: vs.len(), values })
}
