// SPDX-License-Identifier: MIT
//! The patches as a triangle mesh (figure 5.28(b)).

use glam::{DVec2, DVec3};
use hi_mesh::TriangleMesh;

use super::{SurfaceBezier, patch_color};
use crate::Error;

impl SurfaceBezier<DVec3> {
    /// A triangle mesh of the patches: each patch sampled on (k + 1)² parameters (k ≥ 1) with
    /// its own vertices, normals from its partials, UVs the surface parameters, and one colour
    /// per patch ([`patch_color`]), as in figure 5.28(b).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] for k = 0 or a mesh over 2³² vertices.
    pub fn to_triangle_mesh(&self, k: usize) -> Result<TriangleMesh, Error> {
        self.to_triangle_mesh_of(k, &(0..self.patches.len()).collect::<Vec<_>>())
    }

    /// [`SurfaceBezier::to_triangle_mesh`] of the patches `indices` only (see
    /// [`SurfaceBezier::patches_in`]); each keeps the colour of its index.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] for k = 0, no patches, an index out of range or a mesh over 2³²
    /// vertices.
    pub fn to_triangle_mesh_of(&self, k: usize, indices: &[usize]) -> Result<TriangleMesh, Error> {
        if let Some(&bad) = indices.iter().find(|&&i| i >= self.patches.len()) {
            return Err(Error::InvalidCount {
                what: "patch index",
                value: bad,
                expected: "less than the number of patches",
            });
        }
        let side = k + 1;
        let total = indices.len().saturating_mul(side * side);
        if k == 0 || indices.is_empty() || total >= u32::MAX as usize {
            return Err(Error::InvalidCount {
                what: "samples per patch side",
                value: k,
                expected: "at least 1, at least one patch, and fewer than 2³² vertices in all",
            });
        }
        let nv = self.v_breaks.len() - 1;
        let (mut positions, mut normals, mut uvs, mut colors, mut triangles) = (
            Vec::with_capacity(total),
            Vec::with_capacity(total),
            Vec::with_capacity(total),
            Vec::with_capacity(total),
            Vec::new(),
        );
        for &idx in indices {
            let patch = &self.patches[idx];
            let (a, c) = (idx / nv, idx % nv);
            let (u0, u1) = (self.u_breaks[a], self.u_breaks[a + 1]);
            let (v0, v1) = (self.v_breaks[c], self.v_breaks[c + 1]);
            let base = positions.len() as u32;
            let color = patch_color(idx);
            for i in 0..side {
                let s = i as f64 / k as f64;
                for j in 0..side {
                    let t = j as f64 / k as f64;
                    let (p, pu, pv) = patch.eval_with_partials(s, t);
                    // At a degenerate corner (a pole) step inside for the normal.
                    let n = pu.cross(pv).try_normalize().or_else(|| {
                        let (_, qu, qv) = patch.eval_with_partials(
                            s.clamp(1e-6, 1.0 - 1e-6),
                            t.clamp(1e-6, 1.0 - 1e-6),
                        );
                        qu.cross(qv).try_normalize()
                    });
                    positions.push(p);
                    normals.push(n.unwrap_or(DVec3::Z));
                    uvs.push(DVec2::new(u0 + s * (u1 - u0), v0 + t * (v1 - v0)));
                    colors.push(color);
                }
            }
            for i in 0..k as u32 {
                for j in 0..k as u32 {
                    let at = |i: u32, j: u32| base + i * side as u32 + j;
                    triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                    triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            }
        }
        Ok(TriangleMesh::try_new(positions, normals, uvs, triangles)?.try_with_colors(colors)?)
    }
}
