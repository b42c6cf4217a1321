// SPDX-License-Identifier: MIT
//! `hi surface mesh`: a triangle mesh of a harmonic surface written as OBJ, glTF or GLB
//! (Hardy 2005, §5.5, with the curvature colours of §5.9).

use hi_mesh::export::{self, MeshFormat};
use hi_surface::{CurvatureColoring, CurvatureQuantity, MeshOptions};

use crate::cli::{ColorBy, SurfaceMeshArgs};
use crate::error::Failure;
use crate::input::read_surface;
use crate::output::{Json, Object};

/// Writes the mesh and returns `{"files": [...], "vertices": V, "triangles": T}`, with
/// `"legend"` when coloured.
///
/// # Errors
///
/// [`Failure::Input`] for a bad grid file, an unknown extension, a resolution or window the
/// mesher rejects, or an output file that cannot be written.
pub(crate) fn run(args: &SurfaceMeshArgs) -> Result<Json, Failure> {
    // Check the extension before reading and meshing: a typo should fail at once.
    MeshFormat::from_path(&args.output).map_err(|e| Failure::input(format!("-o: {e}")))?;
    let surface = read_surface(&args.input.input)?;
    let [u0, u1, v0, v1] = args.window.0;
    let quantity = args.color.map(|c| match c {
        ColorBy::Gaussian => CurvatureQuantity::Gaussian,
        ColorBy::Mean => CurvatureQuantity::Mean,
    });
    let options = MeshOptions {
        n_u: args.resolution.0,
        n_v: args.resolution.1,
        u_range: [u0, u1],
        v_range: [v0, v1],
        color: quantity
            .map(|quantity| CurvatureColoring { quantity, map: args.palette.color_map() }),
        ..Default::default()
    };
    let mesh = surface
        .to_mesh(&options)
        .map_err(|e| Failure::input(format!("--resolution/--window: {e}")))?;
    let files = export::save(&mesh, &args.output)?;
    let mut out = Object::new()
        .field(
            "files",
            Json::Array(files.iter().map(|f| Json::String(f.display().to_string())).collect()),
        )
        .field("vertices", Json::Count(mesh.n_vertices()))
        .field("triangles", Json::Count(mesh.n_triangles()));
    if let (Some(quantity), Some(legend)) = (quantity, mesh.legend()) {
        out.push(
            "legend",
            Object::new()
                .field("quantity", Json::String(quantity.symbol().to_owned()))
                .field("min", Json::Number(legend.min))
                .field("max", Json::Number(legend.max))
                .build(),
        );
    }
    Ok(out.build())
}
