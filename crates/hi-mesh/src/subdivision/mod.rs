// SPDX-License-Identifier: MIT
//! Subdivision surfaces, the comparison schemes of Hardy 2005, §4.5 (figures 4.8–4.35,
//! Table 4.1), on polygon meshes with half-edge adjacency.
//!
//! | scheme | function | primitive | interpolating | boundary |
//! |---|---|---|---|---|
//! | Loop 1987 (β of Loop or Warren) | [`loop_step`] | triangles | no | Hoppe et al. 1994 crease rules |
//! | modified butterfly, Zorin et al. 1996 | [`butterfly_step`] | triangles | yes | error |
//! | √3, Kobbelt 2000 | [`sqrt3_step`] | triangles | no | error |
//! | interpolating √3, Labsik–Greiner 2000 | [`interpolating_sqrt3_step`] | triangles | yes | error |
//! | Catmull-Clark 1978 | [`catmull_clark_step`] | any polygons | no | crease rules |
//! | Doo-Sabin 1978 | [`doo_sabin_step`] | any polygons | no | error |
//!
//! Limit positions and normals: [`loop_limit`], [`catmull_clark_limit`]. Meshes are read and
//! written as OBJ and OFF ([`PolyMesh::load`], [`PolyMesh::save`]) and go to glTF through
//! [`PolyMesh::to_triangle_mesh`] and [`crate::export`]. Every step checks its input and
//! returns a [`Error`] naming the first face or edge it cannot handle; none panics.
//!
//! # Examples
//!
//! ```
//! use hi_mesh::subdivision::{PolyMesh, Scheme};
//!
//! let mut mesh = PolyMesh::cube();
//! for _ in 0..2 {
//!     mesh = Scheme::CatmullClark.step(&mesh)?;
//! }
//! // V − E + F = 2 after every step; Catmull-Clark: F ← Σ kᶠ = 4·6·4.
//! assert_eq!(mesh.n_faces(), 96);
//! assert_eq!(mesh.n_vertices() + mesh.n_faces(), mesh.n_edges() + 2);
//! # Ok::<(), hi_mesh::Error>(())
//! ```

mod butterfly;
mod catmull_clark;
mod doo_sabin;

mod io;
mod loop_scheme;
mod poly_mesh;
mod shapes;
mod sqrt3;

pub use crate::Error;
pub use butterfly::{butterfly_step, butterfly_step_with_tension};
pub use catmull_clark::{catmull_clark_limit, catmull_clark_step};
pub use doo_sabin::doo_sabin_step;
pub use loop_scheme::{LimitPoint, LoopWeights, loop_limit, loop_step};
pub use poly_mesh::PolyMesh;
pub use sqrt3::{interpolating_sqrt3_step, sqrt3_step};

/// The subdivision schemes of §4.5, for code that picks one at run time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Scheme {
    /// [`loop_step`] with the given β.
    Loop(LoopWeights),
    /// [`butterfly_step`].
    Butterfly,
    /// [`sqrt3_step`].
    Sqrt3,
    /// [`interpolating_sqrt3_step`].
    InterpolatingSqrt3,
    /// [`catmull_clark_step`].
    CatmullClark,
    /// [`doo_sabin_step`].
    DooSabin,
}

impl Scheme {
    /// All schemes (Loop with Loop's β).
    pub const ALL: [Scheme; 6] = [
        Scheme::Loop(LoopWeights::Loop),
        Scheme::Butterfly,
        Scheme::Sqrt3,
        Scheme::InterpolatingSqrt3,
        Scheme::CatmullClark,
        Scheme::DooSabin,
    ];

    /// One step of the scheme.
    ///
    /// # Errors
    ///
    /// Those of the scheme's function.
    pub fn step(self, mesh: &PolyMesh) -> Result<PolyMesh, Error> {
        match self {
            Scheme::Loop(w) => loop_step(mesh, w),
            Scheme::Butterfly => butterfly_step(mesh),
            Scheme::Sqrt3 => sqrt3_step(mesh),
            Scheme::InterpolatingSqrt3 => interpolating_sqrt3_step(mesh),
            Scheme::CatmullClark => catmull_clark_step(mesh),
            Scheme::DooSabin => doo_sabin_step(mesh),
        }
    }

    /// `n_steps` steps of the scheme.
    ///
    /// # Errors
    ///
    /// Those of the scheme's function.
    pub fn steps(self, mesh: &PolyMesh, n_steps: usize) -> Result<PolyMesh, Error> {
        let mut res = mesh.clone();
        for _ in 0..n_steps {
            res = self.step(&res)?;
        }
        Ok(res)
    }

    /// A short name (`loop`, `loop-warren`, `butterfly`, `sqrt3`, `isqrt3`, `catmull-clark`,
    /// `doo-sabin`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Scheme::Loop(LoopWeights::Loop) => "loop",
            Scheme::Loop(LoopWeights::Warren) => "loop-warren",
            Scheme::Butterfly => "butterfly",
            Scheme::Sqrt3 => "sqrt3",
            Scheme::InterpolatingSqrt3 => "isqrt3",
            Scheme::CatmullClark => "catmull-clark",
            Scheme::DooSabin => "doo-sabin",
        }
    }

    /// Whether the scheme keeps the old vertices (butterfly, interpolating √3).
    #[must_use]
    pub fn is_interpolating(self) -> bool {
        matches!(self, Scheme::Butterfly | Scheme::InterpolatingSqrt3)
    }
}
