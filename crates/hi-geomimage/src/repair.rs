// SPDX-License-Identifier: MIT
//! Closing a scan's triangle mesh into a surface of genus 0, ready for a spherical
//! parameterisation ([`crate::sphereparam`]). The thesis (§5.3) casts rays from a centre and
//! so needs a star-shaped object; a parameterisation of the surface itself needs instead a
//! closed, connected, consistently oriented 2-manifold of genus 0, which real scans seldom
//! are: they have repeated points, holes (the Stanford bunny's base), loose parts, faces
//! listed twice or wound the wrong way, and vertices where two sheets touch.
//!
//! [`close_mesh`] repairs what can be repaired without changing the surface, in this order,
//! and counts every change in a [`Repair`]:
//!
//! 1. points at exactly the same position are welded into one vertex;
//! 2. triangles with a repeated vertex and second copies of a triangle are dropped, and so is
//!    every triangle that would be the third (or later) on an edge;
//! 3. each connected part is wound consistently (faces flipped to agree with their
//!    neighbours); a part that cannot be (a Möbius band) is an error;
//! 4. the part with the largest area is kept and the others are dropped;
//! 5. a vertex where several fans of triangles meet is split into one vertex per fan;
//! 6. each hole (a loop of edges with a triangle on one side only) is closed by a fan of
//!    triangles around a new vertex at the loop's centroid, flagged in
//!    [`ClosedMesh::filled`];
//! 7. the Euler characteristic V − E + F must then be 2 (genus 0), else
//!    [`Error::Topology`] says which genus the surface has;
//! 8. the whole mesh is flipped if its signed volume is negative, so that it winds outward.

use crate::par::*;
use glam::DVec3;

use crate::{Error, NonFiniteInput};

/// Marks a vertex of a [`ClosedMesh`] that no scan point gave (the centre of a filled hole).
pub const ADDED_VERTEX: u32 = u32::MAX;

/// What [`close_mesh`] changed to make the scan's mesh a closed surface of genus 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Repair {
    /// Scan points merged into another point at exactly the same position.
    pub welded_points: usize,
    /// Triangles dropped: a repeated vertex, a second copy, or a third triangle on an edge.
    pub dropped_triangles: usize,
    /// Triangles whose winding was reversed to agree with their neighbours.
    pub reoriented_triangles: usize,
    /// Connected parts of the mesh (after the steps above).
    pub components: usize,
    /// Triangles of the parts other than the largest, dropped.
    pub dropped_component_triangles: usize,
    /// Vertices split because several fans of triangles met there.
    pub split_vertices: usize,
    /// Holes closed.
    pub holes: usize,
    /// Edges around the holes.
    pub hole_edges: usize,
    /// Whether the whole mesh was flipped to wind outward.
    pub flipped: bool,
}

/// A closed, connected, consistently oriented triangle mesh of genus 0, wound outward (its
/// signed volume is positive), with where each vertex and triangle came from.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedMesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Triangles, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// For each vertex, the index of the scan point it is, or [`ADDED_VERTEX`] for the centre
    /// of a filled hole.
    pub scan_vertex: Vec<u32>,
    /// For each triangle, whether it was added to close a hole.
    pub filled: Vec<bool>,
    /// What was changed.
    pub repair: Repair,
}

impl ClosedMesh {
    /// The enclosed volume (positive).
    #[must_use]
    pub fn volume(&self) -> f64 {
        signed_volume(&self.positions, &self.triangles)
    }

    /// The surface area.
    #[must_use]
    pub fn area(&self) -> f64 {
        self.triangles.iter().map(|t| area(&self.positions, *t)).sum()
    }
}

fn area(p: &[DVec3], t: [u32; 3]) -> f64 {
    let [a, b, c] = t.map(|k| p[k as usize]);
    0.5 * (b - a).cross(c - a).length()
}

fn signed_volume(p: &[DVec3], triangles: &[[u32; 3]]) -> f64 {
    // About the centroid, so that far-off meshes lose no digits.
    let centre = p.iter().copied().sum::<DVec3>() / p.len().max(1) as f64;
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|k| p[k as usize] - centre);
            a.dot(b.cross(c))
        })
        .sum::<f64>()
        / 6.0
}

/// The undirected key of edge (a, b).
const fn edge_key(a: u32, b: u32) -> u64 {
    if a < b { ((a as u64) << 32) | b as u64 } else { ((b as u64) << 32) | a as u64 }
}

/// Closes the mesh (`points`, `triangles`) into a genus-0 surface; see the module
/// documentation for the steps.
///
/// # Errors
///
/// [`Error::TooFewPoints`] for a mesh with no usable triangle; [`Error::NonFinite`] for a
/// non-finite point; [`Error::InvalidOption`] for a triangle index out of range;
/// [`Error::Topology`] when the largest part cannot be oriented or is not of genus 0 once its
/// holes are closed.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::repair::close_mesh;
///
/// // An open box: a cube without its top (10 triangles), listed with one face wound wrongly.
/// let p = [
///     [0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.],
///     [0., 0., 1.], [1., 0., 1.], [1., 1., 1.], [0., 1., 1.],
/// ]
/// .map(DVec3::from_array)
/// .to_vec();
/// let t = vec![
///     [0, 2, 1], [0, 3, 2], // bottom
///     [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5],
///     [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 7, 4], // the last one is wound the wrong way
/// ];
/// let closed = close_mesh(&p, &t).unwrap();
/// assert_eq!(closed.repair.holes, 1);
/// assert_eq!(closed.repair.hole_edges, 4);
/// assert_eq!(closed.repair.reoriented_triangles, 1);
/// // The top is closed by new triangles, flat across the square hole.
/// assert_eq!(closed.triangles.len(), 10 + closed.filled.iter().filter(|&&f| f).count());
/// assert!((closed.volume() - 1.0).abs() < 1e-12);
/// ```
pub fn close_mesh(points: &[DVec3], triangles: &[[u32; 3]]) -> Result<ClosedMesh, Error> {
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
    let mut repair = Repair::default();

    // 1. Weld points at the same position (the first copy stays).
    let mut order: Vec<([u64; 3], u32)> = points
        .iter()
        .enumerate()
        .map(|(k, p)| (p.to_array().map(f64::to_bits), k as u32))
        .collect();
    order.sort_unstable();
    let mut weld: Vec<u32> = (0..u32::try_from(points.len()).unwrap_or(u32::MAX)).collect();
    for w in order.windows(2) {
        if w[0].0 == w[1].0 {
            weld[w[1].1 as usize] = weld[w[0].1 as usize];
            repair.welded_points += 1;
        }
    }

    // 2. Drop degenerate and repeated triangles, and third triangles on an edge.
    let mut faces: Vec<[u32; 3]> = Vec::with_capacity(triangles.len());
    {
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
        // two earlier (kept) triangles already use one of its edges. Edges are numbered by
        // sorting, and counted in order.
        let mut edges: Vec<(u64, u32)> = Vec::with_capacity(3 * keep.len());
        for (i, &f) in keep.iter().enumerate() {
            let t = mapped[f];
            for k in 0..3 {
                edges.push((edge_key(t[k], t[(k + 1) % 3]), i as u32));
            }
        }
        edges.par_sort_unstable();
        let mut edge_of = vec![[0u32; 3]; keep.len()];
        let mut slot = vec![0u8; keep.len()];
        let mut id = 0u32;
        for (j, &(key, i)) in edges.iter().enumerate() {
            if j > 0 && edges[j - 1].0 != key {
                id += 1;
            }
            edge_of[i as usize][slot[i as usize] as usize] = id;
            slot[i as usize] += 1;
        }
        let mut uses = vec![0u8; id as usize + 1];
        for (i, &f) in keep.iter().enumerate() {
            if edge_of[i].iter().any(|&e| uses[e as usize] >= 2) {
                continue;
            }
            for &e in &edge_of[i] {
                uses[e as usize] += 1;
            }
            faces.push(mapped[f]);
        }
        repair.dropped_triangles = triangles.len() - faces.len();
    }
    if faces.is_empty() {
        return Err(Error::Topology {
            what: "the mesh has no triangle with three distinct corners".to_owned(),
        });
    }

    // Half-edges sorted by undirected edge: neighbours across each edge.
    let n_faces = faces.len();
    let across = neighbours(&faces);
    let original = faces.clone();

    // 3. Orient each part consistently, and find the parts.
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
    repair.components = part_area.len();
    let largest =
        (0..part_area.len()).max_by(|&a, &b| part_area[a].total_cmp(&part_area[b])).unwrap_or(0);
    if one_sided[largest] {
        return Err(Error::Topology {
            what: "the mesh's largest part cannot be oriented (it is one-sided)".to_owned(),
        });
    }
    // 4. Keep the largest part.
    let mut kept: Vec<[u32; 3]> = Vec::with_capacity(n_faces);
    for f in 0..n_faces {
        if part[f] == largest {
            kept.push(faces[f]);
            repair.reoriented_triangles += usize::from(flipped[f]);
        } else {
            repair.dropped_component_triangles += 1;
        }
    }
    // Orient the reoriented count against the majority: if most faces were flipped, the
    // seed's winding was the odd one out.
    let kept_len = kept.len();
    if 2 * repair.reoriented_triangles > kept_len {
        for t in &mut kept {
            t.swap(1, 2);
        }
        repair.reoriented_triangles = kept_len - repair.reoriented_triangles;
    }

    // Compact the vertices to those used.
    let mut new_index = vec![u32::MAX; points.len()];
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

    // 5. Split vertices where several fans meet.
    split_fans(&mut kept, &mut positions, &mut scan_vertex, &mut repair);

    // 6. Close the holes.
    let mut filled = vec![false; kept.len()];
    close_holes(&mut kept, &mut positions, &mut scan_vertex, &mut filled, &mut repair);

    // 7. Genus 0?
    let v = positions.len() as i64;
    let f = kept.len() as i64;
    let e = 3 * f / 2;
    let chi = v - e + f;
    if chi != 2 {
        return Err(Error::Topology {
            what: format!(
                "the surface has genus {} once its holes are closed (Euler characteristic {chi}, not 2)",
                (2 - chi) / 2
            ),
        });
    }

    // 8. Outward.
    if signed_volume(&positions, &kept) < 0.0 {
        for t in &mut kept {
            t.swap(1, 2);
        }
        repair.flipped = true;
    }
    Ok(ClosedMesh { positions, triangles: kept, scan_vertex, filled, repair })
}

/// For each half-edge 3f + k (from corner k to k + 1 of face f), the face across it, if
/// exactly one other face shares the edge.
fn neighbours(faces: &[[u32; 3]]) -> Vec<Option<u32>> {
    let mut half: Vec<(u64, u32)> = Vec::with_capacity(3 * faces.len());
    for (f, t) in faces.iter().enumerate() {
        for k in 0..3 {
            let h = u32::try_from(3 * f + k).unwrap_or(u32::MAX);
            half.push((edge_key(t[k], t[(k + 1) % 3]), h));
        }
    }
    half.par_sort_unstable();
    let mut across = vec![None; 3 * faces.len()];
    let mut i = 0;
    while i < half.len() {
        let mut j = i + 1;
        while j < half.len() && half[j].0 == half[i].0 {
            j += 1;
        }
        if j - i == 2 {
            let (a, b) = (half[i].1, half[i + 1].1);
            across[a as usize] = Some(b / 3);
            across[b as usize] = Some(a / 3);
        }
        i = j;
    }
    across
}

/// Splits every vertex whose triangles form several fans (joined through edges at the
/// vertex) into one vertex per fan.
fn split_fans(
    faces: &mut [[u32; 3]],
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
    repair: &mut Repair,
) {
    let n = positions.len();
    // Corners of each vertex: (face, corner).
    let mut start = vec![0usize; n + 1];
    for t in faces.iter() {
        for &k in t {
            start[k as usize + 1] += 1;
        }
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut corners = vec![(0u32, 0u8); start[n]];
    for (f, t) in faces.iter().enumerate() {
        for (c, &k) in t.iter().enumerate() {
            corners[fill[k as usize]] = (u32::try_from(f).unwrap_or(u32::MAX), c as u8);
            fill[k as usize] += 1;
        }
    }
    for v in 0..n {
        let mine = &corners[start[v]..start[v + 1]];
        if mine.len() < 2 {
            continue;
        }
        // Union the corners whose faces share an edge at v: face f's corner c has the
        // neighbours t[c + 1] and t[c + 2].
        let mut parent: Vec<usize> = (0..mine.len()).collect();
        fn find(p: &mut [usize], mut x: usize) -> usize {
            while p[x] != x {
                p[x] = p[p[x]];
                x = p[x];
            }
            x
        }
        let mut by_other: Vec<(u32, usize)> = Vec::with_capacity(2 * mine.len());
        for (i, &(f, c)) in mine.iter().enumerate() {
            let t = faces[f as usize];
            by_other.push((t[(c as usize + 1) % 3], i));
            by_other.push((t[(c as usize + 2) % 3], i));
        }
        by_other.sort_unstable();
        for w in by_other.windows(2) {
            if w[0].0 == w[1].0 {
                let (a, b) = (find(&mut parent, w[0].1), find(&mut parent, w[1].1));
                parent[a] = b;
            }
        }
        let roots: Vec<usize> = (0..mine.len()).map(|i| find(&mut parent, i)).collect();
        let first = roots[0];
        let mut copies: Vec<(usize, u32)> = Vec::new();
        for (i, &r) in roots.iter().enumerate() {
            if r == first {
                continue;
            }
            let index = match copies.iter().find(|(root, _)| *root == r) {
                Some(&(_, k)) => k,
                None => {
                    let k = u32::try_from(positions.len()).unwrap_or(u32::MAX);
                    positions.push(positions[v]);
                    scan_vertex.push(scan_vertex[v]);
                    copies.push((r, k));
                    repair.split_vertices += 1;
                    k
                }
            };
            let (f, c) = mine[i];
            faces[f as usize][c as usize] = index;
        }
    }
}

/// Closes every boundary loop ([`fill_hole`]).
fn close_holes(
    faces: &mut Vec<[u32; 3]>,
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
    filled: &mut Vec<bool>,
    repair: &mut Repair,
) {
    // Directed edges present; a boundary edge a→b has no b→a.
    let mut directed: Vec<u64> = Vec::with_capacity(3 * faces.len());
    for t in faces.iter() {
        for k in 0..3 {
            directed.push((u64::from(t[k]) << 32) | u64::from(t[(k + 1) % 3]));
        }
    }
    directed.par_sort_unstable();
    let has =
        |a: u32, b: u32| directed.binary_search(&((u64::from(a) << 32) | u64::from(b))).is_ok();
    // After the fans are split, each boundary vertex starts exactly one boundary edge.
    let mut next = vec![u32::MAX; positions.len()];
    for &e in &directed {
        let (a, b) = ((e >> 32) as u32, e as u32);
        if !has(b, a) {
            next[a as usize] = b;
        }
    }
    let n = positions.len();
    let mut done = vec![false; n];
    for start in 0..n {
        if next[start] == u32::MAX || done[start] {
            continue;
        }
        let mut lp = Vec::new();
        let mut v = start;
        while !done[v] && next[v] != u32::MAX {
            done[v] = true;
            lp.push(v as u32);
            v = next[v] as usize;
        }
        if v != start || lp.len() < 3 {
            // Not a closed loop (cannot happen for a split mesh); leave it.
            continue;
        }
        fill_hole(&lp, faces, positions, scan_vertex, filled);
        repair.holes += 1;
        repair.hole_edges += lp.len();
    }
}

/// Closes the boundary loop `lp` (in the order the mesh's triangles run along it) by rings of
/// new vertices shrinking towards its centroid, one ring per mean edge length of the loop's
/// radius, then a fan around the centroid; the new vertices are then moved to the discrete
/// membrane (each the mean of its neighbours, by Gauss–Seidel sweeps, the loop fixed), so the
/// patch is as flat as its border allows and its triangles have about the size of the
/// mesh's.
fn fill_hole(
    lp: &[u32],
    faces: &mut Vec<[u32; 3]>,
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
    filled: &mut Vec<bool>,
) {
    let m = lp.len();
    let at = |k: u32, positions: &[DVec3]| positions[k as usize];
    let centre = lp.iter().map(|&k| at(k, positions)).sum::<DVec3>() / m as f64;
    let edge =
        (0..m).map(|i| at(lp[i], positions).distance(at(lp[(i + 1) % m], positions))).sum::<f64>()
            / m as f64;
    let radius = lp.iter().map(|&k| at(k, positions).distance(centre)).sum::<f64>() / m as f64;
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "clamped to 0..=64"
    )]
    let rings = if edge > 0.0 { (radius / edge).round().clamp(0.0, 64.0) as usize } else { 0 };
    let first_new = positions.len();
    let mut outer: Vec<u32> = lp.to_vec();
    for k in 1..=rings {
        let t = k as f64 / (rings + 1) as f64;
        let inner: Vec<u32> = outer
            .iter()
            .enumerate()
            .map(|(i, _)| {
                let index = u32::try_from(positions.len()).unwrap_or(u32::MAX);
                positions.push(at(lp[i], positions).lerp(centre, t));
                scan_vertex.push(ADDED_VERTEX);
                index
            })
            .collect();
        for i in 0..m {
            let j = (i + 1) % m;
            faces.push([outer[j], outer[i], inner[i]]);
            faces.push([outer[j], inner[i], inner[j]]);
            filled.extend([true, true]);
        }
        outer = inner;
    }
    let c = u32::try_from(positions.len()).unwrap_or(u32::MAX);
    positions.push(centre);
    scan_vertex.push(ADDED_VERTEX);
    for i in 0..m {
        faces.push([outer[(i + 1) % m], outer[i], c]);
        filled.push(true);
    }
    // The membrane: the new vertices' neighbours, then Gauss–Seidel sweeps.
    let free = positions.len() - first_new;
    if free <= 1 {
        return;
    }
    let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); free];
    let added = faces.len() - (2 * rings * m + m);
    for t in &faces[added..] {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            for (x, y) in [(a, b), (b, a)] {
                if x as usize >= first_new && !neighbours[x as usize - first_new].contains(&y) {
                    neighbours[x as usize - first_new].push(y);
                }
            }
        }
    }
    for _ in 0..(4 * (rings + 1) * (rings + 1)).clamp(20, 2000) {
        for (i, list) in neighbours.iter().enumerate() {
            let mean =
                list.iter().map(|&k| positions[k as usize]).sum::<DVec3>() / list.len() as f64;
            positions[first_new + i] = mean;
        }
    }
}
