// SPDX-License-Identifier: MIT
//! The triangle mesh of the harmonic surface of a geometry image: the part of the parameter
//! domain that covers the object once, sampled on the image's grid (refined `per_texel` times),
//! with the points that are the same point of the object welded into one vertex, so that the
//! mesh is watertight and wound outward in every [`Layout`] of the sphere and on the torus, and
//! an open sheet with one rim on the [`Domain::Sheet`].
//!
//! | domain | window | what meets what |
//! |---|---|---|
//! | [`Layout::Sphere`] | u ∈ [0, ½], v ∈ [0, 1] | v wraps; the rows u = 0 and u = ½ are the poles, one vertex each |
//! | [`Layout::FlatOctahedron`] | u ∈ [0, ½], v ∈ [0, 1] | v wraps; the rows u = 0 and u = ½ fold onto themselves (the image's half-turn symmetry) |
//! | [`Layout::Octahedron`] | the octahedral square, half a texel beyond the texel centres | each edge of the square folds onto itself about its midpoint, and the four corners meet |
//! | [`Domain::Torus`] | u, v ∈ [0, 1] | both wrap: the last row is the first, the last column the first |
//! | [`Domain::Sheet`] | u, v ∈ [0, ½] | nothing: the window's edges are the sheet's rim |
//!
//! Which grid points meet is decided by the layout's own map to directions: two points are
//! welded when they look along the same direction (to 10⁻⁹, far below the spacing of any grid
//! this crate makes). In the doubled layouts the surface takes the same value at such points
//! (the image's symmetry is exact). In the plain octahedron it does not: a periodic surface
//! cannot follow the square's folds (which is why that layout shows seams), and across the
//! square's edges it blends texels from opposite sides of the object. There the half-texel
//! border beyond the texel centres takes the values of the nearest texel-centre row or column,
//! and a welded vertex the mean of the values of the points welded.
//!
//! Positions come from the surface sampled over its whole period by FFT
//! ([`HarmonicSurface::sample_uniform`]); normals are the area-weighted means of the normals of
//! the triangles around each vertex. A closed mesh is wound so that it encloses a positive
//! volume (outward), whatever the orientation of the parameterisation; a sheet is wound so that
//! its normals are pᵤ × pᵥ.

use std::collections::HashMap;

use glam::{DVec2, DVec3};
use hi_mesh::TriangleMesh;
use hi_surface::HarmonicSurface;

use crate::domain::Domain;
use crate::spherical::{Layout, octahedral_direction};
use crate::{Error, MAX_TEXELS};

/// The mesh of a fitted surface, with the texel each vertex lies nearest to.
#[derive(Clone, Debug, PartialEq)]
pub struct LayoutMesh {
    /// The mesh: 2-manifold; closed and wound outward but on the [`Domain::Sheet`].
    pub mesh: TriangleMesh,
    /// For each vertex, the row-major index of the image texel nearest to it in the parameter
    /// domain (for masks such as the texels that bridge holes).
    pub texel: Vec<u32>,
}

/// The mesh of `surface`, an image's harmonic surface over `domain` (a [`Layout`] of the
/// sphere, or a [`Domain`]), sampled `per_texel` times per texel along each axis; see the
/// module documentation.
///
/// # Errors
///
/// [`Error::InvalidOption`] for `per_texel` 0 or a grid over 2²⁶ samples, or an odd
/// `per_texel` with the plain octahedron (its square's edges lie half a texel from the texel
/// centres); [`Error::InvalidResolution`] for an odd number of rows in a doubled layout or an
/// odd number of rows or columns on the sheet; errors of the surface layer.
///
/// # Examples
///
/// ```
/// use hi_geomimage::Layout;
/// use hi_geomimage::layout_mesh::layout_mesh;
///
/// // The exact unit sphere in the latitude–longitude layout: a closed mesh around it.
/// let sphere = hi_surface::sphere(1.0);
/// let m = layout_mesh(&sphere, Layout::Sphere, 32).unwrap().mesh;
/// let p = m.positions();
/// let volume: f64 = m
///     .triangles()
///     .iter()
///     .map(|t| p[t[0] as usize].dot(p[t[1] as usize].cross(p[t[2] as usize])) / 6.0)
///     .sum();
/// assert!((volume / (4.0 / 3.0 * std::f64::consts::PI) - 1.0).abs() < 0.01);
/// ```
pub fn layout_mesh(
    surface: &HarmonicSurface<DVec3>,
    domain: impl Into<Domain>,
    per_texel: usize,
) -> Result<LayoutMesh, Error> {
    let domain = domain.into();
    // The sphere's layout, where there is one (the torus and the sheet look along no direction).
    let layout = match domain {
        Domain::Sphere(layout) => Some(layout),
        Domain::Torus | Domain::Sheet => None,
    };
    let (m, n) = (surface.m(), surface.n());
    let k = per_texel;
    let (rows, cols) = (k.saturating_mul(m), k.saturating_mul(n));
    check_sizes(domain, layout, (m, n), k)?;
    let value = surface.sample_uniform(rows, cols, 0, 0)?.values;
    // The window's grid: (row, column) offsets, unwrapped; its direction and sample index.
    let (row_range, col_range) = grid_ranges(domain, rows, cols, k);
    let direction =
        |layout: Layout, i: i64, j: i64| grid_direction(layout, (i, j), (m, n, k), (rows, cols));
    let wrap = |i: i64, j: i64| {
        (i.rem_euclid(rows as i64) as usize) * cols + j.rem_euclid(cols as i64) as usize
    };
    // The sample a grid point takes its value from: itself, but in the plain octahedron the
    // half-texel border beyond the texel centres takes the value of the nearest texel-centre
    // row or column (the periodic surface there is the seam, a blend of the far side of the
    // square).
    let last = |count: usize| ((count - 1) * k) as i64;
    let source = |i: i64, j: i64| match layout {
        Some(Layout::Octahedron) => wrap(i.clamp(0, last(m)), j.clamp(0, last(n))),
        _ => wrap(i, j),
    };
    let (nr, nc) = (row_range.len(), col_range.len());
    // Weld grid points that look along the same direction. In the doubled layouts only the
    // last column (the first again) and the two boundary rows (each folded onto itself, or a
    // pole) can meet another point: the interior is numbered directly and only those are
    // compared by direction. In the plain octahedron every point of the square's border can.
    // On the torus the last row and column are the first again; on the sheet nothing meets.
    let key = |d: DVec3| d.to_array().map(|x| (x * 1e9).round() as i64);
    let mut vertex_of = vec![0u32; nr * nc];
    // Per vertex: the sum of its grid points' values, how many, and the first one's sample.
    let mut sum: Vec<DVec3> = Vec::with_capacity(nr * nc);
    let mut count: Vec<u32> = Vec::with_capacity(nr * nc);
    let mut first: Vec<usize> = Vec::with_capacity(nr * nc);
    let mut by_key: HashMap<[i64; 3], u32> = HashMap::new();
    for (a, &i) in row_range.iter().enumerate() {
        for (b, &j) in col_range.iter().enumerate() {
            let border = match layout {
                Some(Layout::Octahedron) => a == 0 || b == 0 || a + 1 == nr || b + 1 == nc,
                Some(_) => a == 0 || a + 1 == nr,
                None => false,
            };
            let s = source(i, j);
            let mut new_vertex = || {
                sum.push(DVec3::ZERO);
                count.push(0);
                first.push(s);
                (sum.len() - 1) as u32
            };
            let g = match layout {
                Some(layout) if border => {
                    *by_key.entry(key(direction(layout, i, j))).or_insert_with(new_vertex)
                }
                // The column that wraps around.
                Some(Layout::Sphere | Layout::FlatOctahedron) if b + 1 == nc => vertex_of[a * nc],
                None if domain == Domain::Torus && b + 1 == nc => vertex_of[a * nc],
                // The row that wraps around.
                None if domain == Domain::Torus && a + 1 == nr => vertex_of[b],
                _ => new_vertex(),
            };
            sum[g as usize] += value[s];
            count[g as usize] += 1;
            vertex_of[a * nc + b] = g;
        }
    }
    let mut positions: Vec<DVec3> =
        sum.iter().zip(&count).map(|(s, &c)| *s / f64::from(c)).collect();
    let triangles = grid_triangles(&positions, &vertex_of, (nr, nc), domain.is_closed());
    let normals = vertex_normals(&positions, &triangles);
    let (uvs, texel) = uvs_and_texels(
        (&row_range, &col_range),
        &vertex_of,
        &first,
        &source,
        (rows, cols),
        (m, n, k),
    );
    positions.shrink_to_fit();
    let mesh = TriangleMesh::try_new(positions, normals, uvs, triangles)?;
    Ok(LayoutMesh { mesh, texel })
}

/// The direction grid point (i, j) of [`layout_mesh`] looks along in `layout`, for a surface
/// of m × n texels sampled `k` times per texel (rows × cols samples).
fn grid_direction(
    layout: Layout,
    (i, j): (i64, i64),
    (m, n, k): (usize, usize, usize),
    (rows, cols): (usize, usize),
) -> DVec3 {
    match layout {
        Layout::Octahedron => {
            // Texel (a, b) of the image is at s = −1 + (2a + 1)/m: the grid point i is at
            // a = i/k.
            let s = -1.0 + (2.0 * i as f64 / k as f64 + 1.0) / m as f64;
            let t = -1.0 + (2.0 * j as f64 / k as f64 + 1.0) / n as f64;
            octahedral_direction(s, t)
        }
        _ => layout.direction(
            i.rem_euclid(rows as i64) as usize,
            j.rem_euclid(cols as i64) as usize,
            rows,
            cols,
        ),
    }
}

/// UVs of [`layout_mesh`]: the (u, v) of each vertex's first grid point; and the nearest
/// texel of the surface's m × n grid (`k` samples per texel).
fn uvs_and_texels(
    (row_range, col_range): (&[i64], &[i64]),
    vertex_of: &[u32],
    first: &[usize],
    source: &dyn Fn(i64, i64) -> usize,
    (rows, cols): (usize, usize),
    (m, n, k): (usize, usize, usize),
) -> (Vec<DVec2>, Vec<u32>) {
    let nc = col_range.len();
    let mut uvs = vec![DVec2::ZERO; first.len()];
    let mut texel = vec![0u32; first.len()];
    for (a, &i) in row_range.iter().enumerate() {
        for (b, &j) in col_range.iter().enumerate() {
            let g = vertex_of[a * nc + b] as usize;
            if first[g] == source(i, j) {
                uvs[g] = DVec2::new(i as f64 / rows as f64, j as f64 / cols as f64);
                let (ti, tj) =
                    ((i as f64 / k as f64).round() as i64, (j as f64 / k as f64).round() as i64);
                texel[g] = u32::try_from(
                    ti.rem_euclid(m as i64) as usize * n + tj.rem_euclid(n as i64) as usize,
                )
                .unwrap_or(u32::MAX);
            }
        }
    }
    (uvs, texel)
}

/// The first stage of [`layout_mesh`]: the checks of the samples per texel `k` and of the
/// surface's size (m, n) for the domain.
fn check_sizes(
    domain: Domain,
    layout: Option<Layout>,
    (m, n): (usize, usize),
    k: usize,
) -> Result<(), Error> {
    let (rows, cols) = (k.saturating_mul(m), k.saturating_mul(n));
    if k == 0 || rows.saturating_mul(cols) > MAX_TEXELS {
        return Err(Error::InvalidOption {
            name: "samples per texel",
            value: k as f64,
            expected: "at least 1, and at most 2²⁶ samples in all",
        });
    }
    if layout == Some(Layout::Octahedron) && k % 2 == 1 {
        return Err(Error::InvalidOption {
            name: "samples per texel",
            value: k as f64,
            expected: "even for the plain octahedron (its edges lie half a texel off the grid)",
        });
    }
    if matches!(layout, Some(Layout::Sphere | Layout::FlatOctahedron)) && m % 2 == 1 {
        return Err(Error::InvalidResolution {
            rows: m,
            cols: n,
            expected: "an even number of rows (both poles are texels)",
        });
    }
    if domain == Domain::Sheet && (m % 2 == 1 || n % 2 == 1) {
        return Err(Error::InvalidResolution {
            rows: m,
            cols: n,
            expected: "an even number of rows and columns (a sheet's image is mirrored)",
        });
    }
    Ok(())
}

/// The window's grid of [`layout_mesh`]: its (row, column) offsets, unwrapped.
fn grid_ranges(domain: Domain, rows: usize, cols: usize, k: usize) -> (Vec<i64>, Vec<i64>) {
    match domain {
        Domain::Sphere(Layout::Sphere | Layout::FlatOctahedron) => {
            ((0..=rows as i64 / 2).collect(), (0..=cols as i64).collect())
        }
        Domain::Sphere(Layout::Octahedron) => {
            let (h_r, h_c) = ((k / 2) as i64, (k / 2) as i64);
            ((-h_r..=rows as i64 - h_r).collect(), (-h_c..=cols as i64 - h_c).collect())
        }
        Domain::Torus => ((0..=rows as i64).collect(), (0..=cols as i64).collect()),
        Domain::Sheet => ((0..=rows as i64 / 2).collect(), (0..=cols as i64 / 2).collect()),
    }
}

/// The triangles of [`layout_mesh`]: two per grid quad (less those welded to a point), wound
/// outward (a positive enclosed volume) when the domain is `closed` (a sheet keeps pᵤ × pᵥ).
fn grid_triangles(
    positions: &[DVec3],
    vertex_of: &[u32],
    (nr, nc): (usize, usize),
    closed: bool,
) -> Vec<[u32; 3]> {
    let mut triangles = Vec::with_capacity(2 * (nr - 1) * (nc - 1));
    for a in 0..nr - 1 {
        for b in 0..nc - 1 {
            let q = [
                vertex_of[a * nc + b],
                vertex_of[(a + 1) * nc + b],
                vertex_of[(a + 1) * nc + b + 1],
                vertex_of[a * nc + b + 1],
            ];
            for t in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
                if t[0] != t[1] && t[1] != t[2] && t[2] != t[0] {
                    triangles.push(t);
                }
            }
        }
    }
    // Outward: a positive enclosed volume (a sheet keeps pᵤ × pᵥ).
    let centre = positions.iter().copied().sum::<DVec3>() / positions.len().max(1) as f64;
    let volume: f64 = triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| positions[v as usize] - centre);
            a.dot(b.cross(c))
        })
        .sum();
    let flip = closed && volume < 0.0;
    if flip {
        for t in &mut triangles {
            t.swap(1, 2);
        }
    }
    triangles
}

/// Normals: area-weighted means of the triangles' normals.
fn vertex_normals(positions: &[DVec3], triangles: &[[u32; 3]]) -> Vec<DVec3> {
    let mut normals = vec![DVec3::ZERO; positions.len()];
    for t in triangles {
        let [a, b, c] = t.map(|v| positions[v as usize]);
        let w = (b - a).cross(c - a);
        for &v in t {
            normals[v as usize] += w;
        }
    }
    for n in &mut normals {
        *n = n.try_normalize().unwrap_or(DVec3::Z);
    }
    normals
}
