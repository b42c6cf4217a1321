// SPDX-License-Identifier: MIT
//! Sampling the map: the triangle across each edge, the walk across the sphere triangles to
//! the one a direction falls in, and the geometry image.

use glam::DVec3;
use hi_par::*;

use super::{ParamImage, SphereParam};
use crate::{Error, GeometryImage, Layout};

/// For each triangle edge k (corner k to k + 1), the triangle across it.
pub(super) fn triangle_neighbours(triangles: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let mut half: Vec<(u64, u32)> = Vec::with_capacity(3 * triangles.len());
    for (f, t) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let key = if a < b {
                (u64::from(a) << 32) | u64::from(b)
            } else {
                (u64::from(b) << 32) | u64::from(a)
            };
            half.push((key, (f as u32) * 3 + k as u32));
        }
    }
    half.par_sort_unstable();
    let mut across = vec![[u32::MAX; 3]; triangles.len()];
    for w in half.chunks_exact(2) {
        if w[0].0 == w[1].0 {
            let (a, b) = (w[0].1, w[1].1);
            across[(a / 3) as usize][(a % 3) as usize] = b / 3;
            across[(b / 3) as usize][(b % 3) as usize] = a / 3;
        }
    }
    across
}

impl SphereParam {
    /// The triangle whose sphere triangle contains direction d, found by walking from
    /// triangle `from`, and d's barycentric coordinates in it.
    fn locate(&self, d: DVec3, mut from: usize) -> (usize, [f64; 3]) {
        let limit = 4 * self.mesh.triangles.len() + 16;
        for _ in 0..limit {
            let t = self.mesh.triangles[from];
            let [a, b, c] = t.map(|k| self.sphere[k as usize]);
            // s[k]: d against the plane through the origin and edge k (corner k to k + 1).
            let s = [d.dot(a.cross(b)), d.dot(b.cross(c)), d.dot(c.cross(a))];
            let (k, worst) = (0..3)
                .map(|k| (k, s[k]))
                .fold((0, f64::INFINITY), |acc, x| if x.1 < acc.1 { x } else { acc });
            if worst >= 0.0 || self.across[from][k] == u32::MAX {
                let total = s[0] + s[1] + s[2];
                // Barycentric: a's weight is the volume against edge bc, and so on.
                let bary = if total > 0.0 {
                    [s[1].max(0.0) / total, s[2].max(0.0) / total, s[0].max(0.0) / total]
                } else {
                    [1.0 / 3.0; 3]
                };
                let sum = bary[0] + bary[1] + bary[2];
                return (from, bary.map(|x| x / sum));
            }
            from = self.across[from][k] as usize;
        }
        (from, [1.0 / 3.0; 3])
    }

    /// The geometry image of the map in `layout`: each texel the surface point its direction
    /// falls on.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidResolution`] for fewer than 2 rows or columns, too many texels, or an
    /// odd number of rows in a doubled layout.
    pub fn image(&self, layout: Layout, rows: usize, cols: usize) -> Result<ParamImage, Error> {
        crate::image::check_resolution(rows, cols)?;
        if !rows.is_multiple_of(2) && layout != Layout::Octahedron {
            return Err(Error::InvalidResolution {
                rows,
                cols,
                expected: "an even number of rows (both poles are texels)",
            });
        }
        let mirror = layout.mirror(rows, cols);
        let cast_rows = if mirror.is_some() { rows / 2 + 1 } else { rows };
        // A start triangle for each row: walk there from triangle 0 along the first column.
        let mut starts = Vec::with_capacity(cast_rows);
        let mut from = 0;
        for i in 0..cast_rows {
            let (f, _) = self.locate(layout.direction(i, 0, rows, cols), from);
            starts.push(f);
            from = f;
        }
        let rows_of: Vec<Vec<(DVec3, bool)>> = (0..cast_rows)
            .into_par_iter()
            .map(|i| {
                let mut from = starts[i];
                (0..cols)
                    .map(|j| {
                        let (f, w) = self.locate(layout.direction(i, j, rows, cols), from);
                        from = f;
                        let t = self.mesh.triangles[f];
                        let p = t
                            .iter()
                            .zip(w)
                            .map(|(&k, x)| self.mesh.positions[k as usize] * x)
                            .sum::<DVec3>();
                        (p, self.mesh.filled[f])
                    })
                    .collect()
            })
            .collect();
        let mut texels: Vec<DVec3> = rows_of.iter().flatten().map(|x| x.0).collect();
        let mut filled: Vec<bool> = rows_of.iter().flatten().map(|x| x.1).collect();
        if let Some(mirror) = &mirror {
            crate::spherical::complete_by_symmetry(&mut texels, rows, cols, mirror);
            crate::spherical::complete_by_symmetry(&mut filled, rows, cols, mirror);
        }
        let distinct = match layout {
            Layout::Sphere | Layout::FlatOctahedron => rows / 2 * cols,
            Layout::Octahedron => rows * cols,
        };
        let filled_fraction =
            filled[..distinct].iter().filter(|&&f| f).count() as f64 / distinct as f64;
        Ok(ParamImage {
            image: GeometryImage::try_new(rows, cols, texels)?,
            filled,
            filled_fraction,
        })
    }
}
