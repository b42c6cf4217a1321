// SPDX-License-Identifier: MIT
//! Small closed control meshes for the subdivision figures of Hardy 2005, §4.5 (the cube and
//! the star of figures 4.11–4.34) and for the peer comparisons.

use glam::DVec3;

use super::PolyMesh;

impl PolyMesh {
    /// The unit cube [0, 1]³ as six quads (the vertex order and faces of `cube.off` of the
    /// peer comparisons): V, E, F = 8, 12, 6.
    ///
    /// # Examples
    ///
    /// ```
    /// let cube = hi_surface::subdivision::PolyMesh::cube();
    /// assert_eq!((cube.n_vertices(), cube.n_edges(), cube.n_faces()), (8, 12, 6));
    /// assert!(cube.is_closed());
    /// ```
    ///
    /// # Panics
    ///
    /// Never: the mesh is fixed and checked by the tests.
    #[must_use]
    pub fn cube() -> Self {
        let positions = (0..8)
            .map(|i: u32| {
                let (x, y) = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][(i % 4) as usize];
                DVec3::new(x, y, f64::from(i / 4))
            })
            .collect();
        let faces =
            [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]];
        PolyMesh::try_new(positions, &faces).expect("the cube is a valid closed mesh")
    }

    /// [`PolyMesh::cube`] with each quad (a, b, c, d) split into (a, b, c) and (a, c, d): 12
    /// triangles, vertices of valence 4 and 5.
    ///
    /// # Panics
    ///
    /// Never: the mesh is fixed and checked by the tests.
    #[must_use]
    pub fn triangulated_cube() -> Self {
        let cube = PolyMesh::cube();
        let faces: Vec<[u32; 3]> =
            cube.faces().flat_map(|f| [[f[0], f[1], f[2]], [f[0], f[2], f[3]]]).collect();
        PolyMesh::try_new(cube.positions().to_vec(), &faces)
            .expect("the triangulated cube is a valid closed mesh")
    }

    /// The octahedron with vertices ±eᵢ (the order of `octa.off` of the peer comparisons: +x,
    /// −x, +y, −y, +z, −z): V, E, F = 6, 12, 8.
    ///
    /// # Panics
    ///
    /// Never: the mesh is fixed and checked by the tests.
    #[must_use]
    pub fn octahedron() -> Self {
        let positions = vec![DVec3::X, -DVec3::X, DVec3::Y, -DVec3::Y, DVec3::Z, -DVec3::Z];
        let faces = [
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 0, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ];
        PolyMesh::try_new(positions, &faces).expect("the octahedron is a valid closed mesh")
    }

    /// A star: the octahedron with a spike on each face, the tip at 0.9·(±1, ±1, ±1) joined to
    /// the face's corners (24 triangles; the octahedron's vertices get valence 8, the tips 3).
    ///
    /// # Examples
    ///
    /// ```
    /// let star = hi_surface::subdivision::PolyMesh::star();
    /// assert_eq!((star.n_vertices(), star.n_faces()), (14, 24));
    /// assert_eq!((star.valence(0), star.valence(6)), (8, 3));
    /// ```
    ///
    /// # Panics
    ///
    /// Never: the mesh is fixed and checked by the tests.
    #[must_use]
    pub fn star() -> Self {
        let octa = PolyMesh::octahedron();
        let mut positions = octa.positions().to_vec();
        let mut faces = Vec::with_capacity(24);
        for f in octa.faces() {
            let tip = positions.len() as u32;
            let dir: DVec3 = f.iter().map(|&k| octa.positions()[k as usize]).sum();
            positions.push(0.9 * dir);
            for i in 0..3 {
                faces.push([f[i], f[(i + 1) % 3], tip]);
            }
        }
        PolyMesh::try_new(positions, &faces).expect("the star is a valid closed mesh")
    }
}
