// SPDX-License-Identifier: MIT
//! Small closed control meshes for the subdivision figures of Hardy 2005, §4.5 (the cube and
//! the star of figures 4.11–4.34: [`PolyMesh::sharp_star`]), for the peer comparisons and the
//! benchmarks ([`PolyMesh::star`]), and the fan triangulation of any mesh.

use glam::DVec3;

use super::PolyMesh;
use crate::Error;

impl PolyMesh {
    /// The unit cube [0, 1]³ as six quads (the vertex order and faces of `cube.off` of the
    /// peer comparisons): V, E, F = 8, 12, 6.
    ///
    /// # Examples
    ///
    /// ```
    /// let cube = hi_mesh::subdivision::PolyMesh::cube();
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
    /// let star = hi_mesh::subdivision::PolyMesh::star();
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

    /// A star of quadrilaterals: the cube [−1, 1]³ with a tapered spike on each face. Each
    /// face (c₀, c₁, c₂, c₃) with centre c and outward normal n keeps its corners and gains a
    /// top tᵢ = c + 0.2·(cᵢ − c) + 1.2·n, joined by four side quads (cᵢ, cᵢ₊₁, tᵢ₊₁, tᵢ) and
    /// closed by the top (t₀, t₁, t₂, t₃): V, E, F = 32, 60, 30: spikes on a convex core,
    /// vertices of valence 3 to 6, all quads, so that Catmull-Clark and Doo-Sabin see the quad
    /// star and [`PolyMesh::triangulated`] gives the triangle one. Its spikes are short: after
    /// a few steps of an approximating scheme it is a rounded blob, so the figures use
    /// [`PolyMesh::sharp_star`].
    ///
    /// # Examples
    ///
    /// ```
    /// let star = hi_mesh::subdivision::PolyMesh::quad_star();
    /// assert_eq!((star.n_vertices(), star.n_edges(), star.n_faces()), (32, 60, 30));
    /// assert!(star.is_closed() && star.faces().all(|f| f.len() == 4));
    /// ```
    ///
    /// # Panics
    ///
    /// Never: the mesh is fixed and checked by the tests.
    #[must_use]
    pub fn quad_star() -> Self {
        let cube = PolyMesh::cube();
        let mut positions: Vec<DVec3> =
            cube.positions().iter().map(|&p| 2.0 * p - DVec3::ONE).collect();
        let mut faces = Vec::with_capacity(30);
        for f in cube.faces() {
            let corners: Vec<DVec3> = f.iter().map(|&k| positions[k as usize]).collect();
            let centre = corners.iter().sum::<DVec3>() / 4.0;
            // The cube's faces are squares about the origin: the centre is the outward normal.
            let normal = centre.normalize();
            let top = positions.len() as u32;
            for &c in &corners {
                positions.push(centre + 0.2 * (c - centre) + 1.2 * normal);
            }
            for i in 0..4 {
                let j = (i + 1) % 4;
                faces.push([f[i], f[j], top + j as u32, top + i as u32]);
            }
            faces.push([top, top + 1, top + 2, top + 3]);
        }
        PolyMesh::try_new(positions, &faces).expect("the quad star is a valid closed mesh")
    }

    /// A star of quadrilaterals with long, sharp spikes, the star of the subdivision figures
    /// of Hardy 2005, §4.5 (figures 4.12–4.33; the thesis draws its star but does not give
    /// it): the cube [−1, 1]³ with a spike of two frusta on each face. Each face (c₀, c₁, c₂,
    /// c₃) with centre c and outward normal n keeps its corners and gains a neck
    /// nᵢ = c + 0.45·(cᵢ − c) + 0.9·n and a tip tᵢ = c + 0.1·(cᵢ − c) + 3.2·n, joined by the
    /// side quads (cᵢ, cᵢ₊₁, nᵢ₊₁, nᵢ) and (nᵢ, nᵢ₊₁, tᵢ₊₁, tᵢ) and closed by the tip
    /// (t₀, t₁, t₂, t₃): V, E, F = 56, 108, 54. Unlike [`PolyMesh::quad_star`], whose short
    /// frusta subdivide into a rounded blob, the spikes are long and narrow enough to stay
    /// points after three steps of an approximating scheme.
    ///
    /// # Examples
    ///
    /// ```
    /// let star = hi_mesh::subdivision::PolyMesh::sharp_star();
    /// assert_eq!((star.n_vertices(), star.n_edges(), star.n_faces()), (56, 108, 54));
    /// assert!(star.is_closed() && star.faces().all(|f| f.len() == 4));
    /// ```
    ///
    /// # Panics
    ///
    /// Never: the mesh is fixed and checked by the tests.
    #[must_use]
    pub fn sharp_star() -> Self {
        /// (scale of the corners about the face centre, distance out along the normal) of
        /// the neck and the tip.
        const RINGS: [(f64, f64); 2] = [(0.45, 0.9), (0.1, 3.2)];
        let cube = PolyMesh::cube();
        let mut positions: Vec<DVec3> =
            cube.positions().iter().map(|&p| 2.0 * p - DVec3::ONE).collect();
        let mut faces = Vec::with_capacity(54);
        for f in cube.faces() {
            let corners: Vec<DVec3> = f.iter().map(|&k| positions[k as usize]).collect();
            let centre = corners.iter().sum::<DVec3>() / 4.0;
            // The cube's faces are squares about the origin: the centre is the outward normal.
            let normal = centre.normalize();
            let mut below: [u32; 4] = [f[0], f[1], f[2], f[3]];
            for (scale, out) in RINGS {
                let ring = positions.len() as u32;
                for &c in &corners {
                    positions.push(centre + scale * (c - centre) + out * normal);
                }
                for i in 0..4 {
                    let j = (i + 1) % 4;
                    faces.push([below[i], below[j], ring + j as u32, ring + i as u32]);
                }
                below = [ring, ring + 1, ring + 2, ring + 3];
            }
            faces.push(below);
        }
        PolyMesh::try_new(positions, &faces).expect("the sharp star is a valid closed mesh")
    }

    /// The mesh with every face (v₀, v₁, …, vₖ₋₁) split into the fan of triangles
    /// (v₀, vᵢ, vᵢ₊₁), i = 1 … k − 2: the same vertices, in the same order. On the cube it
    /// gives [`PolyMesh::triangulated_cube`].
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_mesh::subdivision::PolyMesh;
    ///
    /// let t = PolyMesh::quad_star().triangulated()?;
    /// assert_eq!((t.n_vertices(), t.n_faces()), (32, 60));
    /// assert_eq!(PolyMesh::cube().triangulated()?.faces().count(), 12);
    /// # Ok::<(), hi_mesh::Error>(())
    /// ```
    ///
    /// # Errors
    ///
    /// [`Error::NonManifoldEdge`] if a new diagonal (v₀, vᵢ) is already an edge of the
    /// mesh (two faces that share two vertices that are not neighbours in one of them).
    pub fn triangulated(&self) -> Result<Self, Error> {
        let faces: Vec<[u32; 3]> = self
            .faces()
            .flat_map(|f| (1..f.len() - 1).map(move |i| [f[0], f[i], f[i + 1]]))
            .collect();
        PolyMesh::try_new(self.positions().to_vec(), &faces)
    }
}
