// SPDX-License-Identifier: MIT
//! The stages of a fit: what a progress display shows and the stage times name.

/// A stage of a fit, as a progress display and the stage times name it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum StageKind {
    /// A large point cloud summarised on a grid ([`hi_scan::cloud`]).
    Summary,
    /// The scan's surface and its parts: a mesh's parts repaired, or the zero set of a point
    /// set's signed distance ([`hi_scan::implicit`]) and its parts.
    Parts,
    /// The geometry image (§5.3, §5.4, or the mesh's parameterisation).
    GeometryImage,
    /// Smoothing of the image.
    Smoothing,
    /// The spectral regularisation.
    Regularisation,
    /// Reduction of the image (Theorem 5.3).
    Reduction,
    /// The harmonic surface through the image or the grid.
    HarmonicSurface,
    /// The 4× rasterisation of the surface for the error.
    Rasterisation,
    /// The fit's error, measured both ways.
    FitError,
    /// Algorithm 1: the sections across the axis.
    Slicing,
    /// Algorithm 1: each section's points in contour order.
    Ordering,
    /// Algorithm 1: a harmonic curve through each contour.
    HarmonicCurves,
    /// Algorithm 1: insertion to equal counts (Theorem 5.3).
    Insertion,
    /// Algorithm 1: rotation for the least deviation (Theorem 5.1).
    Rotation,
    /// Algorithm 1: the measured problems of the sections.
    Diagnostics,
}

impl StageKind {
    /// Its name in words: "geometry image", "rasterisation (4×)", "rotation (Theorem 5.1)", ….
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            StageKind::Summary => "summary of the points",
            StageKind::Parts => "surface and parts",
            StageKind::GeometryImage => "geometry image",
            StageKind::Smoothing => "smoothing",
            StageKind::Regularisation => "regularisation",
            StageKind::Reduction => "reduction",
            StageKind::HarmonicSurface => "harmonic surface",
            StageKind::Rasterisation => "rasterisation (4×)",
            StageKind::FitError => "fit error",
            StageKind::Slicing => "slicing",
            StageKind::Ordering => "ordering",
            StageKind::HarmonicCurves => "harmonic curves",
            StageKind::Insertion => "insertion (Theorem 5.3)",
            StageKind::Rotation => "rotation (Theorem 5.1)",
            StageKind::Diagnostics => "diagnostics",
        }
    }
}

impl std::fmt::Display for StageKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The time one stage took.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stage {
    /// Which stage.
    pub kind: StageKind,
    /// Wall-clock seconds.
    pub seconds: f64,
}

/// What a fit is doing, as it tells a progress display: the stage starting, and of which part
/// (parts counted from 0; a scan fitted as one surface is part 0 of 1; the stages before the
/// parts are known, and the error measured over all of them, are given as part 0 of 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Progress {
    /// The stage starting.
    pub stage: StageKind,
    /// The part it works on.
    pub part: usize,
    /// The parts in all.
    pub parts: usize,
}

impl Progress {
    /// A stage of the whole scan.
    #[must_use]
    pub const fn whole(stage: StageKind) -> Self {
        Self { stage, part: 0, parts: 1 }
    }
}

impl std::fmt::Display for Progress {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.parts > 1 {
            write!(f, "part {} of {}: {}", self.part + 1, self.parts, self.stage)
        } else {
            write!(f, "{}", self.stage)
        }
    }
}
