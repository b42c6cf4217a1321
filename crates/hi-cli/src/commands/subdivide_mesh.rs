// SPDX-License-Identifier: MIT
//! `hi subdivide`: a polygon mesh refined by one of the subdivision schemes of §4.5.

use std::path::PathBuf;

use hi_mesh::export;
use hi_mesh::subdivision::{LoopWeights, PolyMesh, Scheme};

use crate::cli::{LoopBeta, SchemeName, SubdivideMeshArgs};
use crate::error::{Failure, about_file};
use serde::Serialize;

use crate::output::{Json, check_writable, file_names, json};

/// The most steps allowed: each multiplies the faces by 3 or 4, so 8 steps make a cube's 6
/// faces about 400 000.
const MAX_STEPS: usize = 8;

/// Subdivides the mesh and writes it; returns `{"files", "vertices", "edges", "faces"}`.
///
/// # Errors
///
/// [`Failure::Input`] for an unknown extension, a mesh file that cannot be read or is not a
/// valid manifold mesh, a scheme that does not take this mesh (wrong primitive, boundary),
/// too many steps, or an output file that cannot be written.
pub(crate) fn run(args: &SubdivideMeshArgs) -> Result<Json, Failure> {
    if args.steps > MAX_STEPS {
        return Err(Failure::input(format!(
            "--steps: {} is too many (at most {MAX_STEPS})",
            args.steps
        )));
    }
    let ext = args
        .output
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    if !matches!(ext.as_str(), "obj" | "off" | "gltf" | "glb") {
        return Err(Failure::input(format!(
            "-o: {}: unknown extension (expected .obj, .off, .gltf or .glb)",
            args.output.display()
        )));
    }
    check_writable(&args.output, "-o")?;
    let mesh = PolyMesh::load(&args.input)
        .map_err(|e| Failure::input(about_file(&args.input, &e.to_string())))?;
    let scheme = match args.scheme {
        SchemeName::Loop => Scheme::Loop(match args.loop_weights {
            LoopBeta::Loop => LoopWeights::Loop,
            LoopBeta::Warren => LoopWeights::Warren,
        }),
        SchemeName::Butterfly => Scheme::Butterfly,
        SchemeName::Sqrt3 => Scheme::Sqrt3,
        SchemeName::Isqrt3 => Scheme::InterpolatingSqrt3,
        SchemeName::CatmullClark => Scheme::CatmullClark,
        SchemeName::DooSabin => Scheme::DooSabin,
    };
    let refined = scheme
        .steps(&mesh, args.steps)
        .map_err(|e| Failure::input(format!("{}: {e}", scheme.name())))?;
    let files: Vec<PathBuf> = match ext.as_str() {
        "obj" | "off" => {
            refined.save(&args.output).map_err(|e| Failure::input(format!("-o: {e}")))?;
            vec![args.output.clone()]
        }
        _ => {
            let triangles =
                refined.to_triangle_mesh().map_err(|e| Failure::input(format!("-o: {e}")))?;
            export::save(&triangles, &args.output)?
        }
    };
    /// `{"files", "vertices", "edges", "faces"}`.
    #[derive(Serialize)]
    struct Written {
        files: Vec<String>,
        vertices: usize,
        edges: usize,
        faces: usize,
    }
    json(&Written {
        files: file_names(&files),
        vertices: refined.n_vertices(),
        edges: refined.n_edges(),
        faces: refined.n_faces(),
    })
}
