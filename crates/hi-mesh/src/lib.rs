// SPDX-License-Identifier: MIT
//! Triangle and polygon meshes for the `harmonic` workspace: the polygonal form of a surface
//! (A. Hardy, *Harmonic interpolation for smooth curves and surfaces*, 2005, §5.5), the
//! subdivision surfaces the thesis compares against (§4.5), colour maps for curvature
//! pictures (§5.9), and the OBJ and glTF 2.0 files that carry meshes to other programs.
//!
//! The crate knows nothing of harmonic surfaces: `hi-surface` builds a [`TriangleMesh`] from
//! one (`HarmonicSurface::to_mesh`), and `hi-raytrace` draws it.
//!
//! | what | where |
//! |---|---|
//! | indexed triangle meshes with normals, UVs and optional vertex colours | [`TriangleMesh`] |
//! | a coarse mesh of a smooth surface drawn smooth: curved PN triangles (Vlachos et al. 2001) | [`TriangleMesh::curved`] |
//! | values → colours: the thesis's blue → purple ramp, viridis, cool–warm, with a legend | [`ColorMap`], [`ColorLegend`], [`Palette`] |
//! | OBJ and glTF 2.0 (`.gltf`, `.glb`) files of a mesh or of a scene of named meshes, read-back checks | [`export`] |
//! | polygon meshes with half-edge adjacency; subdivision surfaces of §4.5 (Loop, butterfly, √3, Catmull-Clark, Doo-Sabin) | [`PolyMesh`], [`subdivision`] |
//!
//! # Examples
//!
//! ```
//! use hi_mesh::subdivision::Scheme;
//! use hi_mesh::{PolyMesh, export};
//!
//! // A cube, refined twice by Catmull-Clark, triangulated and written as OBJ.
//! let mesh = Scheme::CatmullClark.steps(&PolyMesh::cube(), 2)?;
//! let triangles = mesh.to_triangle_mesh()?;
//! assert_eq!(triangles.n_triangles(), 2 * mesh.n_faces());
//! let mut obj = Vec::new();
//! export::write_obj(&triangles, &mut obj)?;
//! let text = String::from_utf8(obj).unwrap();
//! assert_eq!(text.lines().filter(|l| l.starts_with("f ")).count(), 2 * 96);
//! # Ok::<(), hi_mesh::Error>(())
//! ```
//!
//! # Feature flags
//!
//! | feature | default | adds |
//! |---|---|---|
//! | `gltf` | yes | glTF 2.0 and GLB: [`export::write_gltf`], [`export::write_glb`], [`export::write_scene_gltf`], [`export::write_scene_glb`], reading them back (the `gltf` crate) |
//! | `obj` | yes | reading OBJ files back (the `tobj` crate); writing OBJ needs no feature |
//! | `serde` | no | `Serialize` and `Deserialize` for the meshes, colour maps and reports; a [`TriangleMesh`] is `{"positions", "normals", "uvs", "triangles"}` (plus `"colors"` and `"legend"` when it has them), a [`PolyMesh`] `{"positions", "faces"}`, both read back through their checked constructors |
//!
//! Without them [`export::save`], [`export::load`], [`export::save_scene`] and
//! [`export::load_scene`] still know every extension and answer a
//! format left out with [`Error::FeatureDisabled`], naming the feature.

mod colormap;
mod curved;
mod error;
pub mod export;
mod polygon_soup;
#[cfg(feature = "serde")]
mod serde_impls;
pub mod subdivision;
pub mod text;
mod triangle_mesh;

pub use colormap::{
    ColorLegend, ColorMap, ColorMapping, ColorScale, HIGH_SRGB, LOW_SRGB, NEGATIVE_SRGB,
    NEUTRAL_SRGB, Palette, linear_to_srgb, linear_to_srgb_rgb, srgb_to_linear, srgb_to_linear_rgb,
};
pub use error::Error;
pub use polygon_soup::PolygonSoup;
pub use subdivision::PolyMesh;
pub use triangle_mesh::TriangleMesh;

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
