// SPDX-License-Identifier: MIT
//! Scans as surface fitting meets them (beyond Hardy 2005, §5.3 and §5.8, which take a scan to
//! be points around a centre): reading them, repairing their meshes, measuring distances to
//! them, the local surface their points sample, summaries of clouds too large to work on point
//! by point, and their parts. `hi-geomimage` builds geometry images on it.
//!
//! | what | where |
//! |---|---|
//! | reading scans: OBJ, PLY, OFF, STL, XYZ, PTS, glTF, GLB, with located errors | [`scan`] |
//! | closing a scan mesh to one genus-0 surface (weld, clean, orient, fill holes, cut handles) | [`repair`] |
//! | closest points on triangles (BVH) and near a mesh (kd-tree) | [`closest`] |
//! | distances between point sets and meshes, summarised | [`distance`] |
//! | a point set's local surface: quadric patches, projection, signed distance, its zero set | [`implicit`] |
//! | the zero set of a function sampled on a grid (surface nets) | [`surfacenets`] |
//! | large point clouds summarised on a grid, the grid sized for the detail wanted | [`cloud`] |
//! | the noise level of a point set | [`noise`] |
//! | more points on the triangles of sparse meshes | [`sampling`] |
//!
//! # Feature flags
//!
//! | feature | default | adds |
//! |---|---|---|
//! | `parallel` | yes | every search and local fit on all cores (rayon); without it the same results on one thread |
//! | `serde` | no | `Serialize` and `Deserialize` for scans and reports (a report's per-point distances are left out, so it stays small) |

pub mod closest;
pub mod cloud;
pub mod distance;
mod error;
pub mod implicit;
pub mod noise;
#[doc(hidden)]
pub mod repair;
pub mod sampling;
pub mod scan;
#[cfg(feature = "serde")]
mod serde_impls;
pub mod surfacenets;

pub use error::{Error, NonFiniteInput};

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
