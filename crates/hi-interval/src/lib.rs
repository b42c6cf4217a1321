// SPDX-License-Identifier: MIT
//! Rigorous interval arithmetic for the `harmonic` workspace (Hardy 2005, §5.6).
//!
//! [`Interval`] is a closed interval of `f64` whose every operation rounds outward, so the
//! inclusion property holds: the result of an operation on intervals contains the exact result for
//! every choice of reals in the operands. On top of it:
//!
//! - enclosures of sin, cos (the case analysis of §5.6), exp, ln, atan and integer powers;
//! - interval vectors (slices) and [`IntervalMatrix`] with the norms of §5.6, and the
//!   [`mean_value_form`];
//! - root finding: interval bisection ([`bisect`], [`bisect_1d`]), the [`krawczyk`] operator and
//!   [`interval_newton`] iteration with the thesis's preconditioner update, and the combined
//!   searches [`find_roots`] and [`find_roots_1d`] that return every zero with a [`Verdict`];
//! - [`Scalar`], implemented by `f64` and [`Interval`], so formulas are written once and give both
//!   values and their interval extensions.
//!
//! Rust has no rounding-mode control. Outward rounding uses error-free transformations (`TwoSum`,
//! and the fused multiply-add for products, quotients and square roots) to find the side of the
//! rounded result on which the exact one lies, and steps one ulp only then: `+ − × ÷ √` have the
//! tightest double bounds. The transcendental functions widen libm's values by [`LIBM_ULPS`];
//! see the `elementary` module docs for the bound relied on.
//!
//! It is a foundation crate: it depends on no other `hi-*` crate.
//!
//! # Examples
//!
//! ```
//! use hi_interval::{Interval, RootOptions, Verdict, find_roots_1d};
//! // The zeros of sin(3x) on [0.5, 3]: π/3 and 2π/3, each proven unique.
//! let f = |x: Interval| (x * 3.0).sin();
//! let df = |x: Interval| (x * 3.0).cos() * 3.0;
//! let res = find_roots_1d(f, df, Interval::new(0.5, 3.0), &RootOptions::default());
//! assert_eq!(res.roots.len(), 2);
//! for (root, k) in res.roots.iter().zip([1.0, 2.0]) {
//!     assert_eq!(root.verdict, Verdict::Unique);
//!     assert!((Interval::PI * k / 3.0).overlaps(root.enclosure));
//! }
//! ```
//!
//! # Feature flags
//!
//! - `serde`: `Serialize` and `Deserialize` for [`Interval`] (the pair `[lo, hi]`, `null` for an
//!   unbounded side, `[]` when empty), [`IntervalMatrix`] (its rows) and the root-finding
//!   options and results. Reading checks the invariants: reversed bounds are an error.

mod elementary;
mod interval;
mod linalg;
mod roots;
mod round;
mod scalar;
#[cfg(feature = "serde")]
mod serde_impls;

pub use crate::elementary::LIBM_ULPS;
pub use crate::interval::Interval;
pub use crate::linalg::{
    IntervalMatrix, distance, hull, intersection, max_width, mean_value_form, midpoint, norm,
    real_inverse,
};
pub use crate::roots::{
    NewtonOutcome, Root, Root1, RootOptions, Roots, Roots1, Verdict, bisect, bisect_1d, find_roots,
    find_roots_1d, interval_newton, krawczyk,
};
pub use crate::scalar::Scalar;

/// Errors of this crate.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// The bounds do not describe a non-empty interval (`lo > hi`, NaN, `lo = +∞` or `hi = −∞`).
    InvalidBounds {
        /// The lower bound given.
        lo: f64,
        /// The upper bound given.
        hi: f64,
    },
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::InvalidBounds { lo, hi } => write!(f, "[{lo}, {hi}] is not an interval"),
        }
    }
}

impl std::error::Error for Error {}

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
