// SPDX-License-Identifier: MIT
//! The patches written as an OBJ free-form surface file.

use std::io::Write;

use glam::DVec3;
use hi_bezier::BezierPatch;

use super::SurfaceBezier;

impl SurfaceBezier<DVec3> {
    /// Writes the patches as an OBJ free-form surface file: the control points as `v` lines,
    /// then per patch `cstype bezier`, `deg du dv`, `surf 0 1 0 1` with the control-point
    /// indices (u varying fastest, as the OBJ specification orders surface control points),
    /// `parm u 0 1`, `parm v 0 1` and `end`.
    ///
    /// # Errors
    ///
    /// Those of `w`.
    pub fn write_obj<W: Write>(&self, w: W) -> std::io::Result<()> {
        self.write_obj_of(w, &(0..self.patches.len()).collect::<Vec<_>>())
    }

    /// [`SurfaceBezier::write_obj`] of the patches `indices` only.
    ///
    /// # Errors
    ///
    /// Those of `w`.
    ///
    /// # Panics
    ///
    /// If an index is not less than the number of patches.
    pub fn write_obj_of<W: Write>(&self, mut w: W, indices: &[usize]) -> std::io::Result<()> {
        let patches: Vec<&BezierPatch<DVec3>> = indices.iter().map(|&i| &self.patches[i]).collect();
        writeln!(w, "# harmonic surface as {} Bézier patches (Hardy 2005, §5.7)", patches.len())?;
        for patch in &patches {
            let rows = patch.rows();
            for j in 0..rows[0].len() {
                for row in &rows {
                    let p = row[j];
                    writeln!(w, "v {} {} {}", p.x, p.y, p.z)?;
                }
            }
        }
        let mut next = 1_usize;
        for patch in &patches {
            let (du, dv) = (patch.degree_u(), patch.degree_v());
            let count = (du + 1) * (dv + 1);
            writeln!(w, "cstype bezier\ndeg {du} {dv}")?;
            write!(w, "surf 0 1 0 1")?;
            for i in next..next + count {
                write!(w, " {i}")?;
            }
            writeln!(w, "\nparm u 0 1\nparm v 0 1\nend")?;
            next += count;
        }
        w.flush()
    }
}
