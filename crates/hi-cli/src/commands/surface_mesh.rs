// SPDX-License-Identifier: MIT
//! `hi surface mesh`: a triangle mesh of a harmonic surface written as OBJ, glTF or GLB
//! (Hardy 2005, §5.5, with the curvature colours of §5.9).

use hi_mesh::export::{self, MeshFormat};
use hi_surface::{CurvatureColoring, CurvatureQuantity, MeshOptions};

use crate::cli::{ColorBy, SurfaceMeshArgs};
use crate::error::Failure;
use crate::input::read_surface;
use serde::Serialize;

use crate::output::{Json, check_writable, file_names, json};
use hi_surface::{ParamRange, ParamWindow};

/// Writes the mesh and returns `{"files": [...], "vertices": V, "triangles": T}`, with
/// `"legend"` when coloured.
///
/// # Errors
///
/// [`Failure::Input`] for a bad grid file, an unknown extension, a resolution or window the
/// mesher rejects, or an output file that cannot be written.
pub(crate) fn run(args: &SurfaceMeshArgs) -> Result<Json, Failure> {
    // Check the extension before reading and meshing: a typo should fail at once.
    MeshFormat::try_from_path(&args.output).map_err(|e| Failure::input(format!("-o: {e}")))?;
    check_writable(&args.output, "-o")?;
    let surface = read_surface(&args.input.input)?;
    let [u0, u1, v0, v1] = args.window.0;
    let quantity = args.color.map(|c| match c {
        ColorBy::Gaussian => CurvatureQuantity::Gaussian,
        ColorBy::Mean => CurvatureQuantity::Mean,
    });
    let options = MeshOptions {
        n_u: args.resolution.0,
        n_v: args.resolution.1,
        window: ParamWindow::new(ParamRange::new(u0, u1), ParamRange::new(v0, v1)),
        color: quantity
            .map(|quantity| CurvatureColoring { quantity, map: args.palette.color_map() }),
        ..Default::default()
    };
    let mesh = surface
        .to_mesh(&options)
        .map_err(|e| Failure::input(format!("--resolution/--window: {e}")))?;
    let files = export::save(&mesh, &args.output)?;
    /// The colour scale of a curvature-coloured mesh.
    #[derive(Serialize)]
    struct Legend {
        quantity: &'static str,
        min: f64,
        max: f64,
    }
    /// `{"files", "vertices", "triangles"}`, and `"legend"` when coloured.
    #[derive(Serialize)]
    struct Written {
        files: Vec<String>,
        vertices: usize,
        triangles: usize,
        #[serde(skip_serializing_if = "Option::is_none")]
        legend: Option<Legend>,
    }
    json(&Written {
        files: file_names(&files),
        vertices: mesh.n_vertices(),
        triangles: mesh.n_triangles(),
        legend: quantity.zip(mesh.legend()).map(|(quantity, legend)| Legend {
            quantity: quantity.symbol(),
            min: legend.min,
            max: legend.max,
        }),
    })
}
