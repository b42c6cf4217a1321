// SPDX-License-Identifier: MIT
//! Indexed triangle meshes with one normal and one UV per vertex and optional vertex colours:
//! the polygonal form of a surface (Hardy 2005, §5.5) that the exporters write and the ray
//! tracer draws.
//!
//! **Precision.** Positions, normals and UVs are kept in f64 ([`DVec3`], [`DVec2`]); the
//! exporters round each value once to the f32 of the file formats. Colours are display data
//! and are kept as f32 linear RGB.

use glam::{DVec2, DVec3};
use hi_bezier::Aabb;

use crate::Error;
use crate::colormap::{ColorLegend, ColorMapping};

/// Tolerance on the length of a normal given to [`TriangleMesh::try_new`].
const UNIT_TOLERANCE: f64 = 1e-6;

/// An indexed triangle mesh with one normal and one UV per vertex and optional vertex colours.
///
/// Invariants (checked by [`TriangleMesh::try_new`]): at least one triangle; every index less
/// than the number of vertices, which is less than 2³² − 1; finite positions and UVs; normals
/// of unit length (to 10⁻⁶); colours, if any, one per vertex with components in [0, 1].
///
/// UVs are (s, t) = ((u − u0)/(u1 − u0), (v − v0)/(v1 − v0)) for a mesh of a surface, in
/// glTF's convention (t down the texture image); the OBJ writer stores (s, 1 − t).
///
/// # Examples
///
/// ```
/// use glam::{DVec2, DVec3};
/// use hi_mesh::TriangleMesh;
///
/// // One square of two triangles, facing +z.
/// let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
/// let uv = p.iter().map(|q| q.truncate()).collect::<Vec<DVec2>>();
/// let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 4], uv, vec![[0, 1, 2], [0, 2, 3]])?;
/// assert_eq!((mesh.n_vertices(), mesh.n_triangles()), (4, 2));
/// // A normal that is not of unit length is refused, and the error says which.
/// let (p, n) = (vec![DVec3::ZERO; 3], vec![DVec3::X * 2.0; 3]);
/// let bad = TriangleMesh::try_new(p, n, vec![DVec2::ZERO; 3], vec![[0, 1, 2]]);
/// let message = "length of normal 0 = 2 is invalid: expected 1 (within 1e-6)";
/// assert_eq!(bad.unwrap_err().to_string(), message);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleMesh {
    positions: Vec<DVec3>,
    normals: Vec<DVec3>,
    uvs: Vec<DVec2>,
    colors: Option<Vec<[f32; 3]>>,
    triangles: Vec<[u32; 3]>,
    pub(crate) legend: Option<ColorLegend>,
}

impl TriangleMesh {
    /// A mesh of bare positions and triangles (a program's arrays), with area-weighted vertex
    /// normals from its triangles (as the OBJ reader gives a file without normals) and every UV
    /// at the origin.
    ///
    /// # Errors
    ///
    /// As [`TriangleMesh::try_new`]: no triangles, an index out of range, a non-finite position.
    pub fn from_triangles(positions: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Result<Self, Error> {
        let normals = area_weighted_normals(&positions, triangles.iter().copied());
        let uvs = vec![DVec2::ZERO; positions.len()];
        Self::try_new(positions, normals, uvs, triangles)
    }

    /// A mesh from its parts, checked against the invariants of [`TriangleMesh`].
    ///
    /// # Errors
    ///
    /// [`Error::TooLarge`] for 2³² − 1 vertices or more; [`Error::NonFinitePosition`];
    /// [`Error::InvalidCount`] for no triangles, a normal or UV count different from the
    /// number of positions, or an index out of range; [`Error::InvalidValue`] for a non-finite
    /// UV coordinate or a normal whose length is not 1.
    pub fn try_new(
        positions: Vec<DVec3>,
        normals: Vec<DVec3>,
        uvs: Vec<DVec2>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Self, Error> {
        let n = positions.len();
        if n >= u32::MAX as usize {
            return Err(Error::TooLarge { what: "vertices", count: n });
        }
        if triangles.is_empty() {
            return Err(Error::InvalidCount {
                what: "number of triangles",
                value: 0,
                expected: "at least 1",
            });
        }
        for (what, len) in [("number of normals", normals.len()), ("number of UVs", uvs.len())] {
            if len != n {
                return Err(Error::InvalidCount { what, value: len, expected: "one per position" });
            }
        }
        if let Some(vertex) = positions.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePosition { vertex });
        }
        if let Some(i) = uvs.iter().position(|t| !t.is_finite()) {
            let value = uvs[i].to_array().into_iter().find(|c| !c.is_finite()).unwrap_or(f64::NAN);
            return Err(Error::InvalidValue {
                what: "coordinate of UV",
                index: Some(i),
                value,
                expected: "a finite number",
            });
        }
        if let Some(i) = normals.iter().position(|v| !is_unit(*v)) {
            return Err(Error::InvalidValue {
                what: "length of normal",
                index: Some(i),
                value: normals[i].length(),
                expected: "1 (within 1e-6)",
            });
        }
        if let Some(&bad) = triangles.iter().flatten().find(|&&k| k as usize >= n) {
            return Err(Error::InvalidCount {
                what: "triangle vertex index",
                value: bad as usize,
                expected: "less than the number of vertices",
            });
        }
        Ok(TriangleMesh { positions, normals, uvs, colors: None, triangles, legend: None })
    }

    /// The mesh with vertex colours (linear RGB, one per vertex), replacing any it had, and
    /// no legend.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] if there is not one colour per vertex, [`Error::InvalidValue`]
    /// for a component outside [0, 1] (or NaN).
    pub fn try_with_colors(mut self, colors: Vec<[f32; 3]>) -> Result<Self, Error> {
        if colors.len() != self.positions.len() {
            return Err(Error::InvalidCount {
                what: "number of colours",
                value: colors.len(),
                expected: "one per vertex",
            });
        }
        if let Some(i) = colors.iter().position(|c| !c.iter().all(|x| (0.0..=1.0).contains(x))) {
            let value = colors[i]
                .into_iter()
                .find(|x| !(0.0..=1.0).contains(x))
                .map_or(f64::NAN, f64::from);
            return Err(Error::InvalidValue {
                what: "component of colour",
                index: Some(i),
                value,
                expected: "in [0, 1]",
            });
        }
        self.colors = Some(colors);
        self.legend = None;
        Ok(self)
    }

    /// The mesh with the colours of a colour mapping ([`crate::ColorMap::try_apply`]) and its
    /// legend.
    ///
    /// # Errors
    ///
    /// Those of [`TriangleMesh::try_with_colors`].
    pub fn try_with_mapping(self, mapping: ColorMapping) -> Result<Self, Error> {
        let mut mesh = self.try_with_colors(mapping.colors)?;
        mesh.legend = Some(mapping.legend);
        Ok(mesh)
    }

    /// The mesh without vertex colours.
    #[must_use]
    pub fn without_colors(mut self) -> Self {
        self.colors = None;
        self.legend = None;
        self
    }

    /// Number of vertices.
    #[must_use]
    pub fn n_vertices(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    #[must_use]
    pub fn n_triangles(&self) -> usize {
        self.triangles.len()
    }

    /// Vertex positions.
    #[must_use]
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// Unit vertex normals.
    #[must_use]
    pub fn normals(&self) -> &[DVec3] {
        &self.normals
    }

    /// Vertex UVs (s, t), glTF convention (see [`TriangleMesh`]).
    #[must_use]
    pub fn uvs(&self) -> &[DVec2] {
        &self.uvs
    }

    /// Vertex colours, linear RGB in [0, 1], if any.
    #[must_use]
    pub fn colors(&self) -> Option<&[[f32; 3]]> {
        self.colors.as_deref()
    }

    /// The triangles: vertex indices, counter-clockwise about the normal.
    #[must_use]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The legend of the colour map the colours came from, if they did.
    #[must_use]
    pub fn legend(&self) -> Option<&ColorLegend> {
        self.legend.as_ref()
    }

    /// The box of the positions (f64).
    #[must_use]
    pub fn bounds(&self) -> Aabb<DVec3> {
        // A mesh has a triangle, so a position.
        Aabb::from_points(&self.positions).unwrap_or(Aabb::from_point(DVec3::ZERO))
    }

    /// The volume the triangles enclose, Σ a·(b × c)/6 over the triangles (divergence
    /// theorem): positive when a closed mesh is wound counter-clockwise seen from outside,
    /// negative when it is wound inwards; for an open mesh, the signed volume of the cone
    /// from the origin.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::{DVec2, DVec3};
    /// use hi_mesh::TriangleMesh;
    ///
    /// // The tetrahedron on the unit axes, wound outwards: volume 1/6.
    /// let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    /// let t = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 4], vec![DVec2::ZERO; 4], t)?;
    /// assert!((mesh.signed_volume() - 1.0 / 6.0).abs() < 1e-15);
    /// # Ok::<(), hi_mesh::Error>(())
    /// ```
    #[must_use]
    pub fn signed_volume(&self) -> f64 {
        let p = &self.positions;
        self.triangles
            .iter()
            .map(|t| p[t[0] as usize].dot(p[t[1] as usize].cross(p[t[2] as usize])) / 6.0)
            .sum()
    }
}

/// Whether `v` has length 1 to [`UNIT_TOLERANCE`] (false for NaN).
/// Area-weighted vertex normals of `triangles` over `positions`: each vertex's normal is the
/// normalised sum of the cross products of its triangles' edges, +z where that sum vanishes (an
/// isolated or degenerate vertex). Triangles with a corner out of range are passed over.
pub(crate) fn area_weighted_normals(
    positions: &[DVec3],
    triangles: impl IntoIterator<Item = [u32; 3]>,
) -> Vec<DVec3> {
    let mut normals = vec![DVec3::ZERO; positions.len()];
    for t in triangles {
        let corner = |k: u32| positions.get(k as usize).copied();
        let (Some(a), Some(b), Some(c)) = (corner(t[0]), corner(t[1]), corner(t[2])) else {
            continue;
        };
        let n = (b - a).cross(c - a);
        for k in t {
            normals[k as usize] += n;
        }
    }
    normals.into_iter().map(|n| n.try_normalize().unwrap_or(DVec3::Z)).collect()
}

fn is_unit(v: DVec3) -> bool {
    (v.length() - 1.0).abs() <= UNIT_TOLERANCE
}
