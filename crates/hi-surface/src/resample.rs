// SPDX-License-Identifier: MIT
//! The theorems of chapter 5 along each axis of a surface: rotation (Thm 5.1 and an exact
//! rotation), insertion and reduction (Thm 5.3, §5.4), and harmonic surface subdivision
//! (§5.2, figures 5.3–5.5). docs/math.md §2: inserting along both axes keeps the surface exactly.
//!
//! Each operation applies the curve operation of `hi-curve` to every column (along u) or every
//! row (along v) of the grid; since the surface is a tensor product, that is the operation on
//! the surface.

use std::f64::consts::PI;

use hi_curve::{ControlPoint, HarmonicCurve, ReductionDeviation};

use crate::{Error, HarmonicSurface};

/// A parameter direction of a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Axis {
    /// The first parameter (grid rows, m of them).
    U,
    /// The second parameter (grid columns, n of them).
    V,
}

impl<P: ControlPoint> HarmonicSurface<P> {
    /// Applies a curve operation to every line of the grid along `axis`.
    fn map_lines(
        &self,
        axis: Axis,
        op: impl Fn(HarmonicCurve<P>) -> Result<HarmonicCurve<P>, hi_curve::Error>,
    ) -> Result<Self, Error> {
        let (m, n) = (self.m(), self.n());
        match axis {
            Axis::V => {
                let rows = self
                    .points()
                    .chunks(n)
                    .map(|row| Ok(op(HarmonicCurve::try_new(row.to_vec())?)?.points().to_vec()))
                    .collect::<Result<Vec<_>, Error>>()?;
                Self::try_new(rows)
            }
            Axis::U => {
                let cols = (0..n)
                    .map(|k| {
                        let col = (0..m).map(|j| self.point(j, k)).collect();
                        Ok(op(HarmonicCurve::try_new(col)?)?.points().to_vec())
                    })
                    .collect::<Result<Vec<Vec<P>>, Error>>()?;
                let new_m = cols[0].len();
                Self::try_new((0..new_m).map(|j| cols.iter().map(|c| c[j]).collect()).collect())
            }
        }
    }

    /// Theorem 5.3 along `axis`: the surface through N samples per line of that axis. For N at
    /// least the current size this is the same surface (exact insertion); for fewer it is a
    /// reduction, whose error is returned (see [`ReductionDeviation`], here measured over the whole
    /// surface on a grid of at least 32 samples per unit of degree in each direction).
    ///
    /// # Errors
    ///
    /// [`Error::Curve`] with `InvalidCount` unless 1 ≤ N ≤ 2²⁸.
    #[doc(alias = "theorem 5.3")]
    pub fn resample(&self, axis: Axis, n_new: usize) -> Result<(Self, ReductionDeviation), Error> {
        let res = self.map_lines(axis, |c| Ok(c.resample(n_new)?.0))?;
        let old = match axis {
            Axis::U => self.m(),
            Axis::V => self.n(),
        };
        if n_new >= old {
            return Ok((res, ReductionDeviation::default()));
        }
        let err = self.deviation_from(&res)?;
        Ok((res, err))
    }

    /// max |p − q| over the surfaces' common period, measured on a fine uniform grid, with a
    /// guaranteed bound from Bernstein's inequality in each direction.
    fn deviation_from(&self, other: &Self) -> Result<ReductionDeviation, Error> {
        let deg_u = self.degrees().0.max(other.degrees().0).max(1);
        let deg_v = self.degrees().1.max(other.degrees().1).max(1);
        let (l_u, l_v) = (32 * deg_u, 32 * deg_v);
        let a = self.sample_uniform(l_u, l_v, 0, 0)?;
        let b = other.sample_uniform(l_u, l_v, 0, 0)?;
        let max_deviation =
            a.values.iter().zip(&b.values).map(|(x, y)| (*x - *y).norm()).fold(0.0, f64::max);
        // |D| ≤ grid max + (h_u/2)|D_u| + (h_v/2)|D_v| ≤ grid max + π(M_u/L_u + M_v/L_v)·max|D|.
        let slack = PI * (deg_u as f64 / l_u as f64 + deg_v as f64 / l_v as f64);
        Ok(ReductionDeviation { max_deviation, upper_bound: max_deviation / (1.0 - slack) })
    }

    /// Theorem 5.3 on both axes: the same surface through an M×N grid (M ≥ m, N ≥ n).
    ///
    /// # Errors
    ///
    /// As [`HarmonicSurface::resample`].
    pub fn insert(&self, m_new: usize, n_new: usize) -> Result<Self, Error> {
        Ok(self.resample(Axis::U, m_new.max(self.m()))?.0.resample(Axis::V, n_new.max(self.n()))?.0)
    }

    /// Theorem 5.1 as the thesis states it along `axis`: samples shifted by `offset` — exact
    /// only for an odd number of points along that axis (docs/math.md §2).
    ///
    /// # Errors
    ///
    /// [`Error::Curve`] with `NonFiniteParameter` if `offset` is not finite.
    #[doc(alias = "theorem 5.1")]
    pub fn rotate_theorem_5_1(&self, axis: Axis, offset: f64) -> Result<Self, Error> {
        self.map_lines(axis, |c| c.rotate_theorem_5_1(offset))
    }

    /// Exact rotation along `axis`: q(u, v) = p(u + o, v) (or p(u, v + o)) for every grid size;
    /// an even size grows by one (the lift of Theorem 5.3).
    ///
    /// # Errors
    ///
    /// [`Error::Curve`] with `NonFiniteParameter` if `offset` is not finite.
    pub fn rotate(&self, axis: Axis, offset: f64) -> Result<Self, Error> {
        self.map_lines(axis, |c| c.rotate(offset))
    }

    /// Harmonic surface subdivision (§5.2), `levels` times on both axes: the (m·2ᴸ)×(n·2ᴸ) grid
    /// of the same surface, with the original points kept exactly.
    ///
    /// # Errors
    ///
    /// [`Error::Curve`] with `InvalidCount` if a size exceeds 2²⁸.
    pub fn subdivide(&self, levels: u32) -> Result<Self, Error> {
        self.map_lines(Axis::U, |c| c.subdivide(levels))?
            .map_lines(Axis::V, |c| c.subdivide(levels))
    }
}
