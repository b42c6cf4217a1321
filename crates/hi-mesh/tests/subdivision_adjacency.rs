// SPDX-License-Identifier: MIT
//! The meshes the subdivision steps build, with their half-edge adjacency derived from the
//! old mesh's by index arithmetic, are the meshes the general builder makes from the same
//! faces: the same twins, the same edge numbering (which names the next step's edge
//! vertices) and the same outgoing half-edge per vertex.

use glam::DVec3;
use hi_mesh::subdivision::{LoopWeights, PolyMesh, Scheme};

/// The mesh rebuilt from its positions and faces by [`PolyMesh::try_new`], which pairs
/// half-edges by sorting and checks every manifold condition.
fn rebuilt(mesh: &PolyMesh) -> PolyMesh {
    let faces: Vec<Vec<u32>> = mesh.faces().map(<[u32]>::to_vec).collect();
    PolyMesh::try_new(mesh.positions().to_vec(), &faces).expect("a valid mesh")
}

/// A 3×2 grid of quads in the plane z = 0 with one corner quad missing: open, with a concave
/// boundary corner.
fn open_quads() -> PolyMesh {
    let positions = (0..12).map(|k| DVec3::new(f64::from(k % 4), f64::from(k / 4), 0.0)).collect();
    let faces = [[0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [4, 5, 9, 8], [5, 6, 10, 9]];
    PolyMesh::try_new(positions, &faces).expect("grid")
}

/// A square pyramid without its base, and a fan with a vertex of valence 2 on the boundary.
fn open_triangles() -> [PolyMesh; 2] {
    let pyramid = PolyMesh::try_new(
        vec![DVec3::Z, DVec3::X, DVec3::Y, -DVec3::X, -DVec3::Y],
        &[[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]],
    )
    .expect("pyramid");
    let strip = PolyMesh::try_new(
        vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.3), DVec3::Y, DVec3::new(2.0, 0.5, 0.0)],
        &[[0, 1, 2], [0, 2, 3], [1, 4, 2]],
    )
    .expect("strip");
    [pyramid, strip]
}

#[test]
fn every_step_builds_the_mesh_the_general_builder_builds() {
    let closed_triangles =
        [PolyMesh::octahedron(), PolyMesh::star(), PolyMesh::triangulated_cube()];
    let closed_polygons = [PolyMesh::cube(), PolyMesh::quad_star(), PolyMesh::sharp_star()];
    let mut checked = 0;
    for scheme in Scheme::ALL.into_iter().chain([Scheme::Loop(LoopWeights::Warren)]) {
        let mut inputs: Vec<PolyMesh> = closed_triangles.to_vec();
        match scheme {
            Scheme::Loop(_) => inputs.extend(open_triangles()),
            Scheme::CatmullClark => {
                inputs.extend(closed_polygons.clone());
                inputs.extend(open_triangles());
                inputs.push(open_quads());
            }
            Scheme::DooSabin => inputs.extend(closed_polygons.clone()),
            _ => {}
        }
        for (k, input) in inputs.iter().enumerate() {
            // Two steps: the second reads the first's edge numbering and twins.
            let mut mesh = input.clone();
            for step in 0..2 {
                mesh = scheme.step(&mesh).expect("a step");
                assert_eq!(mesh, rebuilt(&mesh), "{} step {step} of input {k}", scheme.name());
                checked += 1;
            }
        }
    }
    // Seven schemes on three closed triangle meshes; Loop's two on two open ones;
    // Catmull-Clark on six more, Doo-Sabin on three.
    assert_eq!(checked, 2 * (7 * 3 + 2 * 2 + 6 + 3));
}
