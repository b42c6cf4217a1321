// SPDX-License-Identifier: MIT
//! Steps 1 to 3 of the repair: points welded, degenerate, repeated and non-manifold triangles
//! dropped, and the connected parts found and wound consistently.

use glam::DVec3;
use hi_par::*;

use super::edges::EdgeIndex;
use super::{MeshPart, MeshParts, area, neighbours};
use crate::{Error, NonFiniteInput};

/// Steps 1 to 3 of the module documentation: the mesh (`points`, `triangles`) with coincident
/// points welded, degenerate, repeated and non-manifold triangles dropped, split into its
/// connected parts, each wound consistently (a part is turned over if most of its triangles
/// would otherwise be), largest area first.
///
/// # Errors
///
/// [`Error::NonFinite`] for a non-finite point; [`Error::InvalidOption`] for a triangle index
/// out of range; [`Error::Topology`] for a mesh with no triangle of three distinct corners.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::repair::mesh_parts;
///
/// // Two triangles apart, and a third sharing an edge with the first.
/// let p = [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [5., 0., 0.], [6., 0., 0.], [5., 1., 0.], [1., 1., 0.]]
///     .map(DVec3::from_array)
///     .to_vec();
/// let parts = mesh_parts(&p, &[[0, 1, 2], [3, 4, 5], [2, 1, 6]]).unwrap();
/// assert_eq!(parts.parts.len(), 2);
/// assert_eq!(parts.parts[0].triangles.len(), 2);
/// assert!((parts.parts[0].area - 1.0).abs() < 1e-12);
/// ```
pub fn mesh_parts(points: &[DVec3], triangles: &[[u32; 3]]) -> Result<MeshParts, Error> {
    if let Some(k) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinite { what: NonFiniteInput::Point(k) });
    }
    if let Some(&k) = triangles.iter().flatten().find(|&&k| k as usize >= points.len()) {
        return Err(Error::InvalidOption {
            name: "triangle index",
            value: f64::from(k),
            expected: "below the number of points",
        });
    }
    let (weld, welded_points) = weld(points);
    let mut faces = clean_triangles(triangles, &weld);
    if faces.is_empty() {
        return Err(Error::Topology {
            what: "the mesh has no triangle with three distinct corners".to_owned(),
        });
    }
    let orientation = orient(points, &mut faces);
    let dropped_triangles = triangles.len() - faces.len();
    let mut parts = compact_parts(points, &faces, &orientation);
    // Largest first; equal areas in the order found.
    parts.sort_by(|a, b| b.area.total_cmp(&a.area));
    Ok(MeshParts { parts, welded_points, dropped_triangles })
}

/// Step 1: points at the same position welded (the first copy stays): each point's vertex,
/// and how many points were merged.
fn weld(points: &[DVec3]) -> (Vec<u32>, usize) {
    let mut welded_points = 0;
    let mut order: Vec<([u64; 3], u32)> = points
        .iter()
        .enumerate()
        // +0.0 and −0.0 are one position (adding 0 makes −0 +0).
        .map(|(k, p)| ((*p + DVec3::ZERO).to_array().map(f64::to_bits), k as u32))
        .collect();
    order.sort_unstable();
    let mut weld: Vec<u32> = (0..u32::try_from(points.len()).unwrap_or(u32::MAX)).collect();
    for w in order.windows(2) {
        if w[0].0 == w[1].0 {
            weld[w[1].1 as usize] = weld[w[0].1 as usize];
            welded_points += 1;
        }
    }
    (weld, welded_points)
}

/// Step 2: the triangles on the welded vertices, less the degenerate and repeated ones and
/// third triangles on an edge.
fn clean_triangles(triangles: &[[u32; 3]], weld: &[u32]) -> Vec<[u32; 3]> {
    let mut faces: Vec<[u32; 3]> = Vec::with_capacity(triangles.len());
    let mapped: Vec<[u32; 3]> = triangles.iter().map(|t| t.map(|k| weld[k as usize])).collect();
    let mut seen: Vec<([u32; 3], usize)> = mapped
        .iter()
        .enumerate()
        .filter(|(_, t)| t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
        .map(|(f, t)| {
            let mut s = *t;
            s.sort_unstable();
            (s, f)
        })
        .collect();
    // Keys are distinct, so any sort gives the same order.
    seen.par_sort_unstable();
    seen.dedup_by_key(|(s, _)| *s);
    let mut keep: Vec<usize> = seen.into_iter().map(|(_, f)| f).collect();
    keep.sort_unstable();
    // At most two triangles per edge, first come first served: a triangle is dropped if
    // two earlier (kept) triangles already use one of its edges. Edges are numbered in the
    // order of their ends, and counted in order.
    let kept: Vec<[u32; 3]> = keep.iter().map(|&f| mapped[f]).collect();
    let mut edge_of = vec![[0u32; 3]; keep.len()];
    let mut slot = vec![0u8; keep.len()];
    let mut edges = 0u32;
    for (id, (_, _, sides)) in EdgeIndex::undirected(&kept).groups().enumerate() {
        let id = u32::try_from(id).unwrap_or(u32::MAX);
        for &(_, h) in sides {
            let i = h as usize / 3;
            edge_of[i][slot[i] as usize] = id;
            slot[i] += 1;
        }
        edges = id + 1;
    }
    let mut uses = vec![0u8; edges as usize];
    for (i, &f) in keep.iter().enumerate() {
        if edge_of[i].iter().any(|&e| uses[e as usize] >= 2) {
            continue;
        }
        for &e in &edge_of[i] {
            uses[e as usize] += 1;
        }
        faces.push(mapped[f]);
    }
    faces
}

/// The connected parts of the cleaned faces and how step 3 wound them.
struct Orientation {
    /// Each face's part.
    part: Vec<usize>,
    /// Each part's area.
    part_area: Vec<f64>,
    /// Whether each part cannot be oriented.
    one_sided: Vec<bool>,
    /// Whether each face was turned over.
    flipped: Vec<bool>,
}

/// Step 3: each connected part of `faces` found and wound consistently, by a walk across the
/// edges from a seed face (faces turned over in place).
fn orient(points: &[DVec3], faces: &mut [[u32; 3]]) -> Orientation {
    // Half-edges sorted by undirected edge: neighbours across each edge.
    let n_faces = faces.len();
    let across = neighbours(faces);
    let original = faces.to_vec();
    let mut part = vec![usize::MAX; n_faces];
    let mut part_area: Vec<f64> = Vec::new();
    let mut one_sided: Vec<bool> = Vec::new();
    let mut flipped = vec![false; n_faces];
    let mut stack = Vec::new();
    for seed in 0..n_faces {
        if part[seed] != usize::MAX {
            continue;
        }
        let id = part_area.len();
        part_area.push(0.0);
        one_sided.push(false);
        part[seed] = id;
        stack.push(seed);
        while let Some(f) = stack.pop() {
            part_area[id] += area(points, faces[f]);
            for k in 0..3 {
                let Some(g) = across[3 * f + k] else { continue };
                let g = g as usize;
                // The edge of original slot k, directed as f has it now (after its own flip);
                // g agrees if it has it the other way.
                let (mut a, mut b) = (original[f][k], original[f][(k + 1) % 3]);
                if !(0..3).any(|m| faces[f][m] == a && faces[f][(m + 1) % 3] == b) {
                    (a, b) = (b, a);
                }
                let agrees = (0..3).any(|m| faces[g][m] == b && faces[g][(m + 1) % 3] == a);
                if part[g] == usize::MAX {
                    part[g] = id;
                    if !agrees {
                        faces[g].swap(1, 2);
                        flipped[g] = true;
                    }
                    stack.push(g);
                } else if !agrees && part[g] == id {
                    one_sided[id] = true;
                }
            }
        }
    }
    Orientation { part, part_area, one_sided, flipped }
}

/// Each part compacted (its own vertices, numbered in order of use), turned over if most of
/// its faces were flipped (the seed's winding was the odd one out); in the order found.
fn compact_parts(points: &[DVec3], faces: &[[u32; 3]], o: &Orientation) -> Vec<MeshPart> {
    let Orientation { part, part_area, one_sided, flipped } = o;
    let mut members: Vec<Vec<usize>> = vec![Vec::new(); part_area.len()];
    for (f, &id) in part.iter().enumerate() {
        members[id].push(f);
    }
    let mut new_index = vec![u32::MAX; points.len()];
    members
        .iter()
        .enumerate()
        .map(|(id, faces_of)| {
            let mut kept: Vec<[u32; 3]> = faces_of.iter().map(|&f| faces[f]).collect();
            let mut reoriented = faces_of.iter().filter(|&&f| flipped[f]).count();
            if 2 * reoriented > kept.len() {
                for t in &mut kept {
                    t.swap(1, 2);
                }
                reoriented = kept.len() - reoriented;
            }
            let mut positions = Vec::new();
            let mut scan_vertex = Vec::new();
            for t in &mut kept {
                for k in t.iter_mut() {
                    if new_index[*k as usize] == u32::MAX {
                        new_index[*k as usize] = u32::try_from(positions.len()).unwrap_or(u32::MAX);
                        positions.push(points[*k as usize]);
                        scan_vertex.push(*k);
                    }
                    *k = new_index[*k as usize];
                }
            }
            // Ready for the next part (whose vertices are others).
            for &v in &scan_vertex {
                new_index[v as usize] = u32::MAX;
            }
            MeshPart {
                positions,
                triangles: kept,
                scan_vertex,
                area: part_area[id],
                one_sided: one_sided[id],
                reoriented_triangles: reoriented,
            }
        })
        .collect()
}
