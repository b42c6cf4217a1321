// SPDX-License-Identifier: MIT
//! Curved point-normal triangles (Vlachos, Peters, Boyd and Mitchell, "Curved PN triangles",
//! I3D 2001): each triangle of a mesh replaced by the cubic Bézier triangle its corners'
//! positions and normals determine, tessellated. A coarse sampling of a smooth surface (the
//! thesis's §5.9 models, 48 × 16 quads) keeps its vertices but loses its polygonal outline:
//! the cubic edge between two vertices leaves each tangent to its normal's plane, so that
//! the patches of neighbouring triangles meet along one curve (with a continuous position, not
//! a continuous tangent plane), and the silhouette curves as the surface does.

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use crate::{Error, TriangleMesh};

/// The six edge control points and the centre one of a PN triangle with corners
/// `p` and normals `n`: `[b210, b120, b021, b012, b102, b201, b111]` (Vlachos et al. 2001, §3.1),
/// the edges' points taken straight along the edge where `straight[e]` (edge e from corner e to
/// corner e + 1).
fn control_points(p: [DVec3; 3], n: [DVec3; 3], straight: [bool; 3]) -> [DVec3; 7] {
    // The point near `from` on the edge to `to`: a third of the way, dropped onto `from`'s
    // tangent plane.
    let near = |from: usize, to: usize, flat: bool| {
        let w = if flat { 0.0 } else { (p[to] - p[from]).dot(n[from]) };
        (2.0 * p[from] + p[to] - w * n[from]) / 3.0
    };
    let b210 = near(0, 1, straight[0]);
    let b120 = near(1, 0, straight[0]);
    let b021 = near(1, 2, straight[1]);
    let b012 = near(2, 1, straight[1]);
    let b102 = near(2, 0, straight[2]);
    let b201 = near(0, 2, straight[2]);
    let e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    let v = (p[0] + p[1] + p[2]) / 3.0;
    [b210, b120, b021, b012, b102, b201, e + (e - v) / 2.0]
}

/// The point of the PN triangle at barycentric coordinates (u, v, w) of its corners.
fn point(p: [DVec3; 3], b: &[DVec3; 7], (u, v, w): (f64, f64, f64)) -> DVec3 {
    let [b210, b120, b021, b012, b102, b201, b111] = *b;
    p[0] * u * u * u
        + p[1] * v * v * v
        + p[2] * w * w * w
        + 3.0 * (b210 * u * u * v + b120 * u * v * v + b201 * u * u * w)
        + 3.0 * (b021 * v * v * w + b012 * v * w * w + b102 * u * w * w)
        + 6.0 * b111 * u * v * w
}

/// The quadratic normal of the PN triangle at (u, v, w) (Vlachos et al. 2001, §3.2): the mid-edge
/// normals are the corners' reflected across the plane normal to the edge, so that an
/// inflection along the edge shows in the shading.
fn normal(p: [DVec3; 3], n: [DVec3; 3], (u, v, w): (f64, f64, f64)) -> DVec3 {
    let mid = |i: usize, j: usize| {
        let d = p[j] - p[i];
        let len2 = d.length_squared();
        let s = if len2 > 0.0 { 2.0 * d.dot(n[i] + n[j]) / len2 } else { 0.0 };
        (n[i] + n[j] - s * d).normalize_or_zero()
    };
    let q = n[0] * u * u
        + n[1] * v * v
        + n[2] * w * w
        + mid(0, 1) * u * v
        + mid(1, 2) * v * w
        + mid(2, 0) * w * u;
    // Where the corners' normals cancel (opposite normals across a fold), the nearest corner's.
    let nearest = if u >= v && u >= w {
        n[0]
    } else if v >= w {
        n[1]
    } else {
        n[2]
    };
    q.try_normalize()
        .or_else(|| (n[0] * u + n[1] * v + n[2] * w).try_normalize())
        .unwrap_or(nearest)
}

/// The vertices of a curved mesh as they are made.
struct Vertices<'a> {
    source: &'a TriangleMesh,
    positions: Vec<DVec3>,
    normals: Vec<DVec3>,
    uvs: Vec<DVec2>,
    colors: Option<Vec<[f32; 3]>>,
}

impl Vertices<'_> {
    /// A new vertex at `p` with normal `n`, its UV and colour the blend of those of the source
    /// vertices `from` by the `weights`.
    fn push<const N: usize>(
        &mut self,
        p: DVec3,
        n: DVec3,
        from: [u32; N],
        weights: [f64; N],
    ) -> Result<u32, Error> {
        let k = u32::try_from(self.positions.len())
            .ok()
            .filter(|&k| k < u32::MAX)
            .ok_or(Error::TooLarge { what: "vertices", count: self.positions.len() })?;
        self.positions.push(p);
        self.normals.push(n);
        let uvs = self.source.uvs();
        self.uvs.push(from.iter().zip(weights).map(|(&i, w)| uvs[i as usize] * w).sum());
        if let (Some(out), Some(colors)) = (self.colors.as_mut(), self.source.colors()) {
            let mix = |c: usize| {
                let v: f64 = from
                    .iter()
                    .zip(weights)
                    .map(|(&i, w)| f64::from(colors[i as usize][c]) * w)
                    .sum();
                #[expect(clippy::cast_possible_truncation, reason = "a colour in [0, 1]")]
                let v = v.clamp(0.0, 1.0) as f32;
                v
            };
            out.push([mix(0), mix(1), mix(2)]);
        }
        Ok(k)
    }
}

/// The order in which an edge's ends are taken: by position (then index), so that an edge
/// between two pairs of coincident vertices is made alike from either pair.
fn before(mesh: &TriangleMesh, a: u32, b: u32) -> bool {
    let key = |k: u32| (mesh.positions()[k as usize].to_array().map(f64::to_bits), k);
    key(a) < key(b)
}

impl TriangleMesh {
    /// The mesh as curved PN triangles (Vlachos et al. 2001), each triangle cut into
    /// `level`² triangles on its cubic patch: the vertices stay where they are, the new ones lie
    /// on the patches, with the patches' quadratic normals; UVs and colours (and the legend)
    /// are interpolated linearly. An edge whose ends have other vertices at the same place with
    /// other normals (a crease, as at the rim of a cube's face) stays straight, so that the
    /// triangles on its two sides still meet. `level` 1 is the mesh itself.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] for `level` 0; [`Error::TooLarge`] for a mesh that would have
    /// 2³² − 1 vertices or more.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_mesh::{PolyMesh, TriangleMesh};
    ///
    /// // An octahedron with the unit sphere's normals: the curved mesh's new vertices lie
    /// // nearer the sphere than the flat faces do (a face's centre is 1/√3 = 0.58 from the
    /// // centre).
    /// let poly = PolyMesh::octahedron();
    /// let p = poly.positions().to_vec();
    /// let t = poly.faces().map(|f| [f[0], f[1], f[2]]).collect();
    /// let octahedron = TriangleMesh::try_new(p.clone(), p, vec![DVec2::ZERO; 6], t)?;
    /// let curved = octahedron.curved(4)?;
    /// assert_eq!(curved.n_triangles(), 16 * 8);
    /// // 6 corners, 3 new vertices on each of 12 edges, 3 inside each of 8 faces.
    /// assert_eq!(curved.n_vertices(), 6 + 12 * 3 + 8 * 3);
    /// assert!(curved.positions().iter().all(|q| q.length() > 0.8 && q.length() < 1.0 + 1e-12));
    /// # Ok::<(), hi_mesh::Error>(())
    /// ```
    pub fn curved(&self, level: usize) -> Result<TriangleMesh, Error> {
        if level == 0 {
            return Err(Error::InvalidCount {
                what: "PN triangle level",
                value: 0,
                expected: "at least 1",
            });
        }
        let creased = self.crease_vertices();
        let (positions, normals) = (self.positions(), self.normals());
        let mut out = Vertices {
            source: self,
            positions: positions.to_vec(),
            normals: normals.to_vec(),
            uvs: self.uvs().to_vec(),
            colors: self.colors().map(<[[f32; 3]]>::to_vec),
        };
        // The inner vertices of each edge, from its first end (by [`before`]), made once.
        let mut edges: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
        let mut edge_vertex = |a: u32, b: u32, steps: usize, out: &mut Vertices<'_>| {
            let (first, second, from_first) =
                if before(self, a, b) { (a, b, steps) } else { (b, a, level - steps) };
            if let Some(made) = edges.get(&(first, second)) {
                return Ok(made[from_first - 1]);
            }
            let ends = [first, second];
            let p = ends.map(|k| positions[k as usize]);
            let n = ends.map(|k| normals[k as usize]);
            let flat = creased[first as usize] || creased[second as usize];
            // The edge of a PN triangle whose third corner is its second end: its curve and
            // normal depend on its two ends only.
            let b = control_points([p[0], p[1], p[1]], [n[0], n[1], n[1]], [flat; 3]);
            let mut made = Vec::with_capacity(level - 1);
            for m in 1..level {
                let s = m as f64 / level as f64;
                let bary = (1.0 - s, s, 0.0);
                let q = point([p[0], p[1], p[1]], &b, bary);
                let nq = normal([p[0], p[1], p[1]], [n[0], n[1], n[1]], bary);
                made.push(out.push(q, nq, ends, [1.0 - s, s])?);
            }
            let k = made[from_first - 1];
            edges.insert((first, second), made);
            Ok::<u32, Error>(k)
        };
        // Row i of a triangle's lattice (i steps towards corner 1) holds j = 0..=level − i
        // (j steps towards corner 2).
        let index = |i: usize, j: usize| i * (level + 1) - i * i.saturating_sub(1) / 2 + j;
        let mut lattice = vec![u32::MAX; (level + 1) * (level + 2) / 2];
        let mut triangles = Vec::with_capacity(self.n_triangles() * level * level);
        for t in self.triangles() {
            let p = t.map(|k| positions[k as usize]);
            let n = t.map(|k| normals[k as usize]);
            let straight =
                [0, 1, 2].map(|e| creased[t[e] as usize] || creased[t[(e + 1) % 3] as usize]);
            let b = control_points(p, n, straight);
            for i in 0..=level {
                for j in 0..=level - i {
                    let vertex = match (i, j) {
                        (0, 0) => t[0],
                        (i, 0) if i == level => t[1],
                        (0, j) if j == level => t[2],
                        (i, 0) => edge_vertex(t[0], t[1], i, &mut out)?,
                        (0, j) => edge_vertex(t[0], t[2], j, &mut out)?,
                        (i, j) if i + j == level => edge_vertex(t[1], t[2], j, &mut out)?,
                        (i, j) => {
                            let w = [(level - i - j) as f64, i as f64, j as f64]
                                .map(|x| x / level as f64);
                            let bary = (w[0], w[1], w[2]);
                            out.push(point(p, &b, bary), normal(p, n, bary), *t, w)?
                        }
                    };
                    lattice[index(i, j)] = vertex;
                }
            }
            for i in 0..level {
                for j in 0..level - i {
                    let (a, b, c) =
                        (lattice[index(i, j)], lattice[index(i + 1, j)], lattice[index(i, j + 1)]);
                    triangles.push([a, b, c]);
                    if i + j + 1 < level {
                        triangles.push([b, lattice[index(i + 1, j + 1)], c]);
                    }
                }
            }
        }
        let Vertices { positions, normals, uvs, colors, .. } = out;
        let mesh = TriangleMesh::try_new(positions, normals, uvs, triangles)?;
        match (colors, self.legend()) {
            (Some(c), legend) => {
                let mut mesh = mesh.try_with_colors(c)?;
                mesh.legend = legend.cloned();
                Ok(mesh)
            }
            (None, _) => Ok(mesh),
        }
    }

    /// For each vertex, whether another vertex lies at the same place with another normal.
    fn crease_vertices(&self) -> Vec<bool> {
        let mut at: HashMap<[u64; 3], Vec<u32>> = HashMap::new();
        for (k, p) in self.positions().iter().enumerate() {
            #[expect(clippy::cast_possible_truncation, reason = "below the vertex count")]
            at.entry(p.to_array().map(f64::to_bits)).or_default().push(k as u32);
        }
        let mut creased = vec![false; self.n_vertices()];
        for same in at.values().filter(|s| s.len() > 1) {
            let n0 = self.normals()[same[0] as usize];
            if same.iter().any(|&k| self.normals()[k as usize].dot(n0) < 1.0 - 1e-9) {
                for &k in same {
                    creased[k as usize] = true;
                }
            }
        }
        creased
    }
}
