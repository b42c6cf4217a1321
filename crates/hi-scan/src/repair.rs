// SPDX-License-Identifier: MIT
//! Closing a scan's triangle mesh into the surface a parameterisation needs: a sphere (genus 0,
//! `hi-geomimage`'s `sphereparam`), a torus (genus 1) or a disc (one boundary loop). The thesis
//! (§5.3) casts rays from a centre and so needs a star-shaped object; a parameterisation of the
//! surface itself needs instead a connected, consistently oriented 2-manifold of the right
//! topology, which real scans seldom are: they have repeated points, holes (the Stanford bunny's
//! base), loose parts, faces listed twice or wound the wrong way, and vertices where two
//! sheets touch.
//!
//! What can be repaired without changing the surface is, in this order, and every change is
//! counted ([`MeshParts`], [`Repair`]):
//!
//! 1. points at exactly the same position are welded into one vertex;
//! 2. triangles with a repeated vertex and second copies of a triangle are dropped, and so is
//!    every triangle that would be the third (or later) on an edge;
//! 3. each connected part is wound consistently (faces flipped to agree with their
//!    neighbours); a part that cannot be (a Möbius band) is flagged — [`mesh_parts`] stops
//!    here and returns every part, largest first, and [`part_topology`] tells a part's genus
//!    and boundary loops;
//! 4. [`close_mesh`] keeps the part with the largest area and drops the others;
//! 5. [`close_part`], from here on: a vertex where several fans of triangles meet is split into
//!    one vertex per fan;
//! 6. each hole (a loop of edges with a triangle on one side only) is closed by rings of
//!    triangles shrinking to a new vertex at the loop's centroid, flagged in
//!    [`ClosedMesh::filled`] (for a [`Closing::Disc`], every hole but the one whose loop spans
//!    the largest area: the disc's rim);
//! 7. handles are cut (but a [`Closing::Torus`]'s), each along the shortest loop found that
//!    does not separate the surface (searched within blocks of [`HANDLE_BLOCKS`] mean edge
//!    lengths and over the whole mesh: the tunnels and bridges a zero set grows where two
//!    sheets of a scan nearly touch, a tail that touches a body, the tube of a ring), and both
//!    sides of each cut are closed as holes are, so the genus drops by one per loop. The caps
//!    of a cut lie on each other, so the shape is kept: a ring stays a ring, closed across its
//!    tube at one place;
//! 8. the Euler characteristic V − E + F must then be 2 (sphere), 0 (torus) or 1 (disc), else
//!    [`Error::Topology`] says which genus the surface has;
//! 9. a closed result is flipped if its signed volume is negative, so that it winds outward.
//!
//! A loop is found as Erickson and Whittlesey find the shortest loops through a point (2005):
//! within each block (faces grouped by their centroids, on two grids offset by half a block,
//! so that a short loop seldom straddles blocks of both), a shortest-path tree from a root and
//! a spanning tree of the faces across the other edges, taken longest loop first; an edge that
//! would close a cycle of faces closes a loop of the tree that does not separate the block,
//! hence not the surface. The loops of every block, every size and a few roots are taken
//! shortest first, and each search cuts as many of them as share no vertex and, cut together,
//! leave the surface in one piece (then each lowers the genus by one; the greedy shortest
//! system of loops); the whole mesh, as one block, always holds one while the genus is above
//! 0. The search is repeated until the genus is 0.

use glam::DVec3;
use hi_par::*;

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
    /// Handles cut (step 7 of the module documentation).
    pub handles_cut: usize,
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

/// One connected part of a scan's mesh ([`mesh_parts`]): its triangles wound consistently
/// where that is possible, its vertices compacted.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshPart {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Triangles, wound consistently (unless [`MeshPart::one_sided`]), most of them as the scan
    /// listed them.
    pub triangles: Vec<[u32; 3]>,
    /// For each vertex, the index of the scan point it is.
    pub scan_vertex: Vec<u32>,
    /// The part's area.
    pub area: f64,
    /// Whether the part cannot be oriented (a Möbius band).
    pub one_sided: bool,
    /// Triangles whose winding was reversed to agree with their neighbours.
    pub reoriented_triangles: usize,
}

/// A scan's mesh cleaned and split into its connected parts ([`mesh_parts`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MeshParts {
    /// The parts, largest area first.
    pub parts: Vec<MeshPart>,
    /// Scan points merged into another point at exactly the same position.
    pub welded_points: usize,
    /// Triangles dropped: a repeated vertex, a second copy, or a third triangle on an edge.
    pub dropped_triangles: usize,
}

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
    let mut welded_points = 0;
    // 1. Weld points at the same position (the first copy stays).
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
    let dropped_triangles = triangles.len() - faces.len();
    // Each part compacted, turned over if most of its faces were flipped (the seed's winding
    // was the odd one out).
    let mut members: Vec<Vec<usize>> = vec![Vec::new(); part_area.len()];
    for (f, &id) in part.iter().enumerate() {
        members[id].push(f);
    }
    let mut new_index = vec![u32::MAX; points.len()];
    let mut parts: Vec<MeshPart> = members
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
        .collect();
    // Largest first; equal areas in the order found.
    parts.sort_by(|a, b| b.area.total_cmp(&a.area));
    Ok(MeshParts { parts, welded_points, dropped_triangles })
}

/// The surface [`close_part`] makes of a part.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Closing {
    /// A closed surface of genus 0: every hole closed, every handle cut.
    #[default]
    Sphere,
    /// A closed surface of genus 1: every hole closed, the handle kept.
    Torus,
    /// A disc: every hole closed but the one whose loop spans the largest area, every handle
    /// cut.
    Disc,
}

/// The topology of a part, its pinched vertices split ([`part_topology`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Topology {
    /// The genus of the closed surface the part makes once its holes are closed.
    pub genus: usize,
    /// Its boundary loops, the one spanning the largest area first.
    pub loops: Vec<BoundaryLoop>,
    /// The part's area.
    pub area: f64,
}

/// A boundary loop of a part: the rim of a hole, or of an open sheet.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BoundaryLoop {
    /// Its edges.
    pub edges: usize,
    /// Its length.
    pub length: f64,
    /// The area of the fan from its centroid across it: about the area a cap over it needs.
    pub span: f64,
}

/// The genus and boundary loops of `part` once its pinched vertices are split (step 5):
/// χ = V − E + F = 2 − 2g − b for b loops.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::repair::{mesh_parts, part_topology};
///
/// // One square of two triangles: a disc, one loop of four edges around an area of 1.
/// let p = [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]].map(DVec3::from_array).to_vec();
/// let part = &mesh_parts(&p, &[[0, 1, 2], [0, 2, 3]]).unwrap().parts[0];
/// let topology = part_topology(part);
/// assert_eq!((topology.genus, topology.loops.len(), topology.loops[0].edges), (0, 1, 4));
/// assert!((topology.loops[0].span - 1.0).abs() < 1e-12);
/// ```
#[must_use]
pub fn part_topology(part: &MeshPart) -> Topology {
    let mut faces = part.triangles.clone();
    let mut positions = part.positions.clone();
    let mut scan_vertex = part.scan_vertex.clone();
    split_fans(&mut faces, &mut positions, &mut scan_vertex, &mut Repair::default());
    let mut loops: Vec<BoundaryLoop> = boundary_loops(&faces, positions.len())
        .iter()
        .map(|lp| loop_measures(lp, &positions))
        .collect();
    loops.sort_by(|a, b| b.span.total_cmp(&a.span));
    let edges = directed_edges(&faces).len() as i64;
    let boundary_edges: i64 = loops.iter().map(|l| l.edges as i64).sum();
    // Every interior edge is two half-edges, a boundary edge one.
    let e = (edges + boundary_edges) / 2;
    let chi = positions.len() as i64 - e + faces.len() as i64;
    let genus = usize::try_from((2 - chi - loops.len() as i64).max(0) / 2).unwrap_or(0);
    Topology { genus, loops, area: part.area }
}

/// The length and span of a boundary loop.
fn loop_measures(lp: &[u32], positions: &[DVec3]) -> BoundaryLoop {
    let m = lp.len();
    let at = |i: usize| positions[lp[i % m] as usize];
    let centre = (0..m).map(at).sum::<DVec3>() / m.max(1) as f64;
    BoundaryLoop {
        edges: m,
        length: (0..m).map(|i| at(i).distance(at(i + 1))).sum(),
        span: (0..m).map(|i| 0.5 * (at(i) - centre).cross(at(i + 1) - centre).length()).sum(),
    }
}

/// Steps 5 to 9 of the module documentation for one part, making the surface `closing` asks
/// for: pinched vertices split, holes closed (for a disc, all but the loop of largest span),
/// handles cut (none for a torus), the Euler characteristic checked (2 for a sphere, 0 for a
/// torus, 1 for a disc), and a closed result wound outward. For a disc the winding is the
/// part's own.
///
/// # Errors
///
/// [`Error::Topology`] when the part is one-sided, has no boundary to keep open for a disc, or
/// is not of the genus `closing` needs once its holes are closed and up to [`MAX_HANDLES`]
/// handles cut.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::repair::{Closing, close_part, mesh_parts};
///
/// // An open box (a cube without its top): closed as a sphere, or kept open as a disc.
/// let p = [
///     [0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.],
///     [0., 0., 1.], [1., 0., 1.], [1., 1., 1.], [0., 1., 1.],
/// ]
/// .map(DVec3::from_array)
/// .to_vec();
/// let t = [[0, 2, 1], [0, 3, 2], [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]];
/// let part = &mesh_parts(&p, &t).unwrap().parts[0];
/// let closed = close_part(part, Closing::Sphere).unwrap();
/// assert_eq!(closed.repair.holes, 1);
/// // The cap leaves the walls upwards and domes over the square: more than the unit cube.
/// assert!(closed.volume() > 1.0 && closed.volume() < 1.5);
/// let disc = close_part(part, Closing::Disc).unwrap();
/// assert_eq!((disc.repair.holes, disc.triangles.len()), (0, 10));
/// assert!(close_part(part, Closing::Torus).is_err());
/// ```
pub fn close_part(part: &MeshPart, closing: Closing) -> Result<ClosedMesh, Error> {
    if part.one_sided {
        return Err(Error::Topology {
            what: "the part cannot be oriented (it is one-sided)".to_owned(),
        });
    }
    let mut repair = Repair {
        components: 1,
        reoriented_triangles: part.reoriented_triangles,
        ..Repair::default()
    };
    let mut kept = part.triangles.clone();
    let mut positions = part.positions.clone();
    let mut scan_vertex = part.scan_vertex.clone();

    // 5. Split vertices where several fans meet.
    split_fans(&mut kept, &mut positions, &mut scan_vertex, &mut repair);

    // 6. Close the holes (for a disc, all but the widest).
    let mut filled = vec![false; kept.len()];
    let mut loops = boundary_loops(&kept, positions.len());
    let open = if closing == Closing::Disc {
        let widest = (0..loops.len()).max_by(|&a, &b| {
            loop_measures(&loops[a], &positions)
                .span
                .total_cmp(&loop_measures(&loops[b], &positions).span)
        });
        match widest {
            Some(k) => Some(loops.swap_remove(k)),
            None => {
                return Err(Error::Topology {
                    what: "the part is closed: it has no boundary to keep as a disc's".to_owned(),
                });
            }
        }
    } else {
        None
    };
    for lp in &loops {
        fill_hole(lp, &mut kept, &mut positions, &mut scan_vertex, &mut filled);
        repair.holes += 1;
        repair.hole_edges += lp.len();
    }

    // 7. Cut handles, but a torus's; none if there are more than can be cut.
    let chi_wanted = match closing {
        Closing::Sphere => 2,
        Closing::Torus => 0,
        Closing::Disc => 1,
    };
    let boundary_edges = open.as_ref().map_or(0, Vec::len) as i64;
    let handles =
        (chi_wanted - euler_characteristic(positions.len(), kept.len(), boundary_edges)) / 2;
    if closing != Closing::Torus && handles <= MAX_HANDLES as i64 {
        cut_handles(
            &mut kept,
            &mut positions,
            &mut scan_vertex,
            &mut filled,
            chi_wanted,
            &mut repair,
        );
    }

    // 8. The Euler characteristic (a disc's one boundary loop counts one edge per edge).
    let e = (3 * kept.len() as i64 + boundary_edges) / 2;
    let chi = positions.len() as i64 - e + kept.len() as i64;
    if chi != chi_wanted {
        let b = i64::from(open.is_some());
        return Err(Error::Topology {
            what: format!(
                "the surface has genus {} once its holes are closed (Euler characteristic {chi}), not the genus {} a {} needs",
                (2 - chi - b) / 2,
                if closing == Closing::Torus { 1 } else { 0 },
                match closing {
                    Closing::Sphere => "sphere",
                    Closing::Torus => "torus",
                    Closing::Disc => "disc",
                }
            ),
        });
    }

    // 9. Outward, for a closed surface.
    if closing != Closing::Disc && signed_volume(&positions, &kept) < 0.0 {
        for t in &mut kept {
            t.swap(1, 2);
        }
        repair.flipped = true;
    }
    Ok(ClosedMesh { positions, triangles: kept, scan_vertex, filled, repair })
}

/// Closes the mesh (`points`, `triangles`) into a genus-0 surface: its largest part
/// ([`mesh_parts`]) closed as a sphere ([`close_part`]); see the module documentation for the
/// steps.
///
/// # Errors
///
/// [`Error::TooFewPoints`] for a mesh with no usable triangle; [`Error::NonFinite`] for a
/// non-finite point; [`Error::InvalidOption`] for a triangle index out of range;
/// [`Error::Topology`] when the largest part cannot be oriented or is not of genus 0 once its
/// holes are closed and up to [`MAX_HANDLES`] handles cut.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::repair::close_mesh;
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
/// // The top is closed by new triangles, a dome over the square hole.
/// assert_eq!(closed.triangles.len(), 10 + closed.filled.iter().filter(|&&f| f).count());
/// assert!(closed.volume() > 1.0 && closed.volume() < 1.5);
/// ```
pub fn close_mesh(points: &[DVec3], triangles: &[[u32; 3]]) -> Result<ClosedMesh, Error> {
    let cleaned = mesh_parts(points, triangles)?;
    let components = cleaned.parts.len();
    let dropped_component_triangles: usize =
        cleaned.parts.iter().skip(1).map(|p| p.triangles.len()).sum();
    let Some(largest) = cleaned.parts.first() else {
        return Err(Error::TooFewPoints { found: 0, needed: 3 });
    };
    if largest.one_sided {
        return Err(Error::Topology {
            what: "the mesh's largest part cannot be oriented (it is one-sided)".to_owned(),
        });
    }
    let mut closed = close_part(largest, Closing::Sphere)?;
    closed.repair.welded_points = cleaned.welded_points;
    closed.repair.dropped_triangles = cleaned.dropped_triangles;
    closed.repair.components = components;
    closed.repair.dropped_component_triangles = dropped_component_triangles;
    Ok(closed)
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

/// The boundary loops of `faces` (over `n` vertices, pinched vertices split), each in the order
/// the triangles run along it: a boundary edge a → b has no b → a.
fn boundary_loops(faces: &[[u32; 3]], n: usize) -> Vec<Vec<u32>> {
    let directed: Vec<u64> = directed_edges(faces).into_iter().map(|(key, _)| key).collect();
    let has =
        |a: u32, b: u32| directed.binary_search(&((u64::from(a) << 32) | u64::from(b))).is_ok();
    // After the fans are split, each boundary vertex starts exactly one boundary edge.
    let mut next = vec![u32::MAX; n];
    for &e in &directed {
        let (a, b) = ((e >> 32) as u32, e as u32);
        if !has(b, a) {
            next[a as usize] = b;
        }
    }
    let mut done = vec![false; n];
    let mut loops = Vec::new();
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
        if v == start && lp.len() >= 3 {
            loops.push(lp);
        }
        // Else not a closed loop (cannot happen for a split mesh); left alone.
    }
    loops
}

/// The most conjugate-gradient steps of a cap's fairing ([`fill_hole`]): enough for caps of
/// thousands of vertices (the steps it takes grow with the cap's radius in edges squared).
const FAIRING_ITERATIONS: usize = 4000;

/// Closes the boundary loop `lp` (in the order the mesh's triangles run along it) by rings of
/// new vertices shrinking towards its centroid, one ring per mean edge length of the loop's
/// radius, then a fan around the centroid, with triangles about the size of the mesh's. The new
/// vertices are moved first to the discrete membrane (each the mean of its neighbours, by
/// Gauss–Seidel sweeps, the loop fixed: as flat as its border allows), then to the thin plate
/// the surface around it continues into: the umbrella operator applied twice vanishes at
/// every new vertex (Kobbelt 1998, discrete fairing; the loop and the scan's triangles about it
/// fixed), so the cap leaves the rim along the surface's own tangent plane, with no crease for
/// the harmonic surface to ring on.
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
    let sweeps = (4 * (rings + 1) * (rings + 1)).clamp(20, 2000);
    for _ in 0..sweeps {
        for (i, list) in neighbours.iter().enumerate() {
            let mean =
                list.iter().map(|&k| positions[k as usize]).sum::<DVec3>() / list.len() as f64;
            positions[first_new + i] = mean;
        }
    }
    fair(lp, faces, positions, first_new, &neighbours, FAIRING_ITERATIONS);
}

/// The thin-plate fairing of a hole's cap (see [`fill_hole`]): the cap's new vertices (from
/// `first_new`, with their `neighbours`) placed where the umbrella operator
/// U(v) = mean of v's neighbours − v vanishes, in the least-squares sense, at every vertex of
/// the cap and of the loop `lp` (the loop and the rest of the mesh fixed), by conjugate
/// gradients on the normal equations (CGLS, three coordinates at once, from the membrane the
/// caller placed them on), at most `iterations` steps.
fn fair(
    lp: &[u32],
    faces: &[[u32; 3]],
    positions: &mut [DVec3],
    first_new: usize,
    neighbours: &[Vec<u32>],
    iterations: usize,
) {
    // The loop's vertices' neighbours, on the scan's side and the cap's.
    let mut around_loop: std::collections::HashMap<u32, Vec<u32>> =
        lp.iter().map(|&v| (v, Vec::new())).collect();
    for t in faces {
        for k in 0..3 {
            if let Some(list) = around_loop.get_mut(&t[k]) {
                for other in [t[(k + 1) % 3], t[(k + 2) % 3]] {
                    if !list.contains(&other) {
                        list.push(other);
                    }
                }
            }
        }
    }
    let free = neighbours.len();
    // One row per vertex of the loop and the cap: U(v) as coefficients of the free vertices
    // (cap vertex c at column c − first_new), and its fixed part.
    let rows: Vec<(Vec<(usize, f64)>, DVec3)> = lp
        .iter()
        .map(|&v| (v, around_loop.get(&v).map_or(&[][..], Vec::as_slice)))
        .chain(
            neighbours
                .iter()
                .enumerate()
                .map(|(i, ring)| ((first_new + i) as u32, ring.as_slice())),
        )
        .filter(|(_, ring)| !ring.is_empty())
        .map(|(v, ring)| {
            let w = 1.0 / ring.len() as f64;
            let mut coefficients = Vec::with_capacity(ring.len() + 1);
            let mut fixed = DVec3::ZERO;
            for (k, c) in ring.iter().map(|&k| (k, w)).chain([(v, -1.0)]) {
                if k as usize >= first_new {
                    coefficients.push((k as usize - first_new, c));
                } else {
                    fixed += positions[k as usize] * c;
                }
            }
            (coefficients, fixed)
        })
        .collect();
    let apply = |x: &[DVec3]| -> Vec<DVec3> {
        rows.iter().map(|(c, _)| c.iter().map(|&(k, w)| x[k] * w).sum()).collect()
    };
    let apply_t = |r: &[DVec3]| -> Vec<DVec3> {
        let mut out = vec![DVec3::ZERO; free];
        for ((c, _), ri) in rows.iter().zip(r) {
            for &(k, w) in c {
                out[k] += *ri * w;
            }
        }
        out
    };
    let dot = |a: &[DVec3], b: &[DVec3]| -> DVec3 { a.iter().zip(b).map(|(x, y)| *x * *y).sum() };
    let mut x: Vec<DVec3> = positions[first_new..first_new + free].to_vec();
    // r = b − A x with b = −fixed.
    let ax = apply(&x);
    let mut r: Vec<DVec3> = rows.iter().zip(&ax).map(|((_, f), a)| -*f - *a).collect();
    let mut s = apply_t(&r);
    let mut p = s.clone();
    let mut gamma = dot(&s, &s);
    let start = gamma.max_element();
    for _ in 0..iterations {
        if gamma.max_element() <= 1e-24 * start.max(f64::MIN_POSITIVE) {
            break;
        }
        let q = apply(&p);
        let qq = dot(&q, &q);
        let alpha = DVec3::select(qq.cmpgt(DVec3::ZERO), gamma / qq, DVec3::ZERO);
        for (xi, pi) in x.iter_mut().zip(&p) {
            *xi += alpha * *pi;
        }
        for (ri, qi) in r.iter_mut().zip(&q) {
            *ri -= alpha * *qi;
        }
        s = apply_t(&r);
        let next = dot(&s, &s);
        let beta = DVec3::select(gamma.cmpgt(DVec3::ZERO), next / gamma, DVec3::ZERO);
        for (pi, si) in p.iter_mut().zip(&s) {
            *pi = *si + beta * *pi;
        }
        gamma = next;
    }
    if x.iter().all(|v| v.is_finite()) {
        positions[first_new..first_new + free].copy_from_slice(&x);
    }
}

/// The length of the shortest loop found on the closed mesh `mesh` that does not separate it
/// (the loop [`close_part`] would cut first, found the same way), or `None` for a surface of
/// genus 0. A handle's loop as short as a few edges is a tunnel between two sheets that nearly
/// touch, not a handle of the object.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::repair::{Closing, close_part, mesh_parts, shortest_handle};
///
/// // A torus of tube radius 0.25 about a circle of radius 1, 48 × 16 quads: the shortest
/// // loop goes round the tube, 2π · 0.25 long (a little less on the polygon).
/// let (nu, nv) = (48u32, 16u32);
/// let at = |i: u32, j: u32| {
///     let (a, b) = (std::f64::consts::TAU * f64::from(i % nu) / f64::from(nu), std::f64::consts::TAU * f64::from(j % nv) / f64::from(nv));
///     DVec3::new((1.0 + 0.25 * b.cos()) * a.cos(), (1.0 + 0.25 * b.cos()) * a.sin(), 0.25 * b.sin())
/// };
/// let points: Vec<DVec3> = (0..nu * nv).map(|k| at(k / nv, k % nv)).collect();
/// let id = |i: u32, j: u32| (i % nu) * nv + j % nv;
/// let triangles: Vec<[u32; 3]> = (0..nu)
///     .flat_map(|i| (0..nv).flat_map(move |j| [[id(i, j), id(i + 1, j), id(i + 1, j + 1)], [id(i, j), id(i + 1, j + 1), id(i, j + 1)]]))
///     .collect();
/// let torus = close_part(&mesh_parts(&points, &triangles).unwrap().parts[0], Closing::Torus).unwrap();
/// let length = shortest_handle(&torus).unwrap();
/// assert!((length / (std::f64::consts::TAU * 0.25) - 1.0).abs() < 0.03, "{length}");
/// ```
#[must_use]
pub fn shortest_handle(mesh: &ClosedMesh) -> Option<f64> {
    HANDLE_BLOCKS
        .iter()
        .chain(&[f64::INFINITY])
        .flat_map(|&side| handle_loops(&mesh.triangles, &mesh.positions, side))
        .map(|(length, _)| length)
        .min_by(f64::total_cmp)
}

/// The sides of the blocks in which [`close_mesh`] looks for loops that cut handles (then over
/// the whole mesh), in mean edge lengths of the mesh.
pub const HANDLE_BLOCKS: [f64; 3] = [8.0, 32.0, 128.0];

/// At most this many handles are cut.
pub const MAX_HANDLES: usize = 32;

/// Roots tried per block: the first vertex of the block, then a vertex of the best loop so far.
const HANDLE_ROOTS: usize = 3;

/// V − E + F of a triangle mesh with `boundary_edges` edges on one triangle (every other edge
/// on two).
fn euler_characteristic(vertices: usize, faces: usize, boundary_edges: i64) -> i64 {
    let (v, f) = (vertices as i64, faces as i64);
    v - (3 * f + boundary_edges) / 2 + f
}

/// Step 7 of [`close_mesh`] on a closed, consistently oriented mesh: while its genus is above
/// 0, cuts the shortest non-separating loops found ([`handle_loops`], in blocks of every
/// size of [`HANDLE_BLOCKS`] and over the whole mesh; several at once when they are disjoint
/// and do not separate the surface together, [`independent_loops`]) and closes both sides of
/// each cut.
fn cut_handles(
    faces: &mut Vec<[u32; 3]>,
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
    filled: &mut Vec<bool>,
    chi_wanted: i64,
    repair: &mut Repair,
) {
    let kept_open: Vec<Vec<u32>> = boundary_loops(faces, positions.len())
        .into_iter()
        .map(|mut lp| {
            lp.sort_unstable();
            lp
        })
        .collect();
    let open = kept_open.iter().map(Vec::len).sum::<usize>() as i64;
    while repair.handles_cut < MAX_HANDLES {
        let chi = euler_characteristic(positions.len(), faces.len(), open);
        if chi >= chi_wanted {
            return;
        }
        // Every block's loop at every size of block (a loop may fit a block of one grid and
        // not the next, and the roots differ), shortest first; as many of them cut at once as
        // are disjoint and, together, do not separate the surface.
        let mut found: Vec<(f64, Vec<u32>)> = HANDLE_BLOCKS
            .iter()
            .chain(&[f64::INFINITY])
            .flat_map(|&side| handle_loops(faces, positions, side))
            .collect();
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        let wanted = usize::try_from((chi_wanted - chi) / 2)
            .unwrap_or(0)
            .min(MAX_HANDLES - repair.handles_cut)
            .max(1);
        let loops = independent_loops(faces, positions.len(), found, wanted);
        if loops.is_empty() {
            return;
        }
        let mut cut = 0;
        for lp in &loops {
            if !cut_along(lp, faces, positions, scan_vertex) {
                break;
            }
            cut += 1;
        }
        if cut == 0 {
            return;
        }
        filled.resize(faces.len(), false);
        // The two cuts are holes of their own; they are not the scan's, so not counted as such.
        // A boundary kept open (a disc's) stays open.
        for lp in boundary_loops(faces, positions.len()) {
            let mut key = lp.clone();
            key.sort_unstable();
            if !kept_open.contains(&key) {
                fill_hole(&lp, faces, positions, scan_vertex, filled);
            }
        }
        if euler_characteristic(positions.len(), faces.len(), open) != chi + 2 * cut as i64 {
            // Cannot happen for non-separating loops of a closed mesh; stop rather than loop.
            return;
        }
        repair.handles_cut += cut;
    }
}

/// Of the loops `found` (shortest first), at most `wanted` that share no vertex and that,
/// cut together, leave the faces of the closed mesh `faces` (over `vertices` vertices)
/// connected: each would lower the genus by one (the greedy choice of a shortest system of
/// loops, Erickson and Whittlesey 2005). The first loop is always taken: it does not
/// separate the surface on its own.
fn independent_loops(
    faces: &[[u32; 3]],
    vertices: usize,
    found: Vec<(f64, Vec<u32>)>,
    wanted: usize,
) -> Vec<Vec<u32>> {
    // Pairs of faces across each edge, keyed by the edge.
    let mut sides: Vec<(u64, u32)> = faces
        .iter()
        .enumerate()
        .flat_map(|(f, t)| {
            let f = u32::try_from(f).unwrap_or(u32::MAX);
            (0..3).map(move |k| (edge_key(t[k], t[(k + 1) % 3]), f))
        })
        .collect();
    sides.par_sort_unstable();
    let pairs: Vec<(u64, u32, u32)> = sides
        .chunk_by(|a, b| a.0 == b.0)
        .filter(|pair| pair.len() == 2)
        .map(|pair| (pair[0].0, pair[0].1, pair[1].1))
        .collect();
    let mut used = vec![false; vertices];
    let mut barrier: Vec<u64> = Vec::new();
    let mut chosen: Vec<Vec<u32>> = Vec::new();
    for (_, lp) in found {
        if chosen.len() >= wanted {
            break;
        }
        if lp.iter().any(|&v| used.get(v as usize).is_none_or(|&u| u)) {
            continue;
        }
        let m = lp.len();
        let mut trial = barrier.clone();
        trial.extend((0..m).map(|i| edge_key(lp[i], lp[(i + 1) % m])));
        trial.sort_unstable();
        if chosen.is_empty() || faces_connected(faces.len(), &pairs, &trial) {
            for &v in &lp {
                used[v as usize] = true;
            }
            chosen.push(lp);
            barrier = trial;
        }
    }
    chosen
}

/// Whether `n` faces joined across the edges of `pairs` (edge, face, face) but the sorted
/// `barrier` edges form one piece.
fn faces_connected(n: usize, pairs: &[(u64, u32, u32)], barrier: &[u64]) -> bool {
    let mut parent: Vec<u32> = (0..u32::try_from(n).unwrap_or(u32::MAX)).collect();
    fn find(p: &mut [u32], mut x: u32) -> u32 {
        while p[x as usize] != x {
            p[x as usize] = p[p[x as usize] as usize];
            x = p[x as usize];
        }
        x
    }
    let mut pieces = n;
    for &(key, f, g) in pairs {
        if barrier.binary_search(&key).is_ok() {
            continue;
        }
        let (rf, rg) = (find(&mut parent, f), find(&mut parent, g));
        if rf != rg {
            parent[rf as usize] = rg;
            pieces -= 1;
        }
    }
    pieces <= 1
}

/// The half-edges of `faces` sorted by (from, to): half-edge 3f + k runs from corner k of face
/// f to corner k + 1.
fn directed_edges(faces: &[[u32; 3]]) -> Vec<(u64, u32)> {
    let mut half: Vec<(u64, u32)> = Vec::with_capacity(3 * faces.len());
    for (f, t) in faces.iter().enumerate() {
        for k in 0..3 {
            let h = u32::try_from(3 * f + k).unwrap_or(u32::MAX);
            half.push(((u64::from(t[k]) << 32) | u64::from(t[(k + 1) % 3]), h));
        }
    }
    half.par_sort_unstable();
    half
}

/// The face holding the half-edge a → b.
fn face_of(half: &[(u64, u32)], a: u32, b: u32) -> Option<usize> {
    let key = (u64::from(a) << 32) | u64::from(b);
    half.binary_search_by_key(&key, |&(k, _)| k).ok().map(|i| half[i].1 as usize / 3)
}

/// The shortest non-separating loop of a closed mesh found within each block of `blocks` mean
/// edge lengths (see the module documentation; infinite for the whole mesh), on both grids of
/// blocks: each loop's length and vertices in order; none when no block holds one.
fn handle_loops(faces: &[[u32; 3]], positions: &[DVec3], blocks: f64) -> Vec<(f64, Vec<u32>)> {
    let at = |k: u32| positions[k as usize];
    let mean_edge = faces
        .iter()
        .map(|t| {
            at(t[0]).distance(at(t[1])) + at(t[1]).distance(at(t[2])) + at(t[2]).distance(at(t[0]))
        })
        .sum::<f64>()
        / (3 * faces.len()).max(1) as f64;
    let side = blocks * mean_edge;
    if !(side > 0.0 && mean_edge.is_finite()) {
        return Vec::new();
    }
    let lo = positions.iter().fold(DVec3::INFINITY, |a, p| a.min(*p));
    let mut all: Vec<(f64, Vec<u32>)> = Vec::new();
    for offset in [0.0, 0.5] {
        if blocks.is_infinite() && offset > 0.0 {
            // One block either way.
            break;
        }
        // Faces by block, blocks in a fixed order.
        let mut keyed: Vec<([i64; 3], u32)> = faces
            .iter()
            .enumerate()
            .map(|(f, t)| {
                let c = (at(t[0]) + at(t[1]) + at(t[2])) / 3.0;
                // (One block, 0, for an infinite side.)
                #[expect(clippy::cast_possible_truncation, reason = "a block index")]
                let key = ((c - lo) / side + offset).floor().to_array().map(|x| x as i64);
                (key, u32::try_from(f).unwrap_or(u32::MAX))
            })
            .collect();
        keyed.par_sort_unstable();
        let blocks: Vec<&[([i64; 3], u32)]> = keyed.chunk_by(|a, b| a.0 == b.0).collect();
        let found: Vec<(f64, Vec<u32>)> = blocks
            .par_iter()
            .filter_map(|block| {
                let block: Vec<u32> = block.iter().map(|&(_, f)| f).collect();
                block_loop(faces, positions, &block)
            })
            .collect();
        all.extend(found);
    }
    all
}

/// The shortest loop found in the faces `block` of a closed mesh that does not separate them:
/// its length and vertices. A few roots are tried ([`HANDLE_ROOTS`]).
fn block_loop(faces: &[[u32; 3]], positions: &[DVec3], block: &[u32]) -> Option<(f64, Vec<u32>)> {
    use std::collections::HashMap;
    // Local vertices and undirected edges of the block, with the faces on each.
    let mut local: HashMap<u32, u32> = HashMap::new();
    let mut verts: Vec<u32> = Vec::new();
    let mut id = |v: u32, verts: &mut Vec<u32>| {
        *local.entry(v).or_insert_with(|| {
            verts.push(v);
            u32::try_from(verts.len() - 1).unwrap_or(u32::MAX)
        })
    };
    let mut edges: Vec<(u64, u32)> = Vec::with_capacity(3 * block.len());
    for (i, &f) in block.iter().enumerate() {
        let t = faces[f as usize].map(|v| id(v, &mut verts));
        for k in 0..3 {
            edges.push((edge_key(t[k], t[(k + 1) % 3]), u32::try_from(i).unwrap_or(u32::MAX)));
        }
    }
    edges.sort_unstable();
    // (a, b, face, other face or None on the block's border)
    let mut list: Vec<(u32, u32, u32, Option<u32>)> = Vec::new();
    for pair in edges.chunk_by(|x, y| x.0 == y.0) {
        let key = pair[0].0;
        let (a, b) = ((key >> 32) as u32, key as u32);
        list.push((a, b, pair[0].1, pair.get(1).map(|x| x.1)));
    }
    let n = verts.len();
    let mut adjacency: Vec<Vec<(u32, f64)>> = vec![Vec::new(); n];
    for &(a, b, _, _) in &list {
        let w =
            positions[verts[a as usize] as usize].distance(positions[verts[b as usize] as usize]);
        adjacency[a as usize].push((b, w));
        adjacency[b as usize].push((a, w));
    }
    let mut best: Option<(f64, Vec<u32>)> = None;
    let mut root = 0u32;
    for _ in 0..HANDLE_ROOTS {
        let Some((length, lp)) = loop_through(root, &adjacency, &list, block.len()) else {
            break;
        };
        let improved = best.as_ref().is_none_or(|(b, _)| length < *b - 1e-12 * b.abs());
        if improved {
            // Next, a root across the loop from this one.
            root = lp[lp.len() / 2];
            best = Some((length, lp));
        } else {
            break;
        }
    }
    best.map(|(length, lp)| (length, lp.iter().map(|&v| verts[v as usize]).collect()))
}

/// The shortest non-separating loop through the shortest-path tree from `root` (Erickson and
/// Whittlesey's greedy step): Dijkstra from the root, then the faces joined across the
/// non-tree edges, longest loop first; the shortest edge whose faces are already joined closes
/// the loop returned (length and local vertices, from one end of the edge up the tree and down
/// to the other). `None` when every loop of the tree separates the faces.
fn loop_through(
    root: u32,
    adjacency: &[Vec<(u32, f64)>],
    edges: &[(u32, u32, u32, Option<u32>)],
    n_faces: usize,
) -> Option<(f64, Vec<u32>)> {
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;
    let n = adjacency.len();
    let mut dist = vec![f64::INFINITY; n];
    let mut parent = vec![u32::MAX; n];
    let mut heap = BinaryHeap::new();
    dist[root as usize] = 0.0;
    heap.push((Reverse(OrderedDistance(0.0)), root));
    while let Some((Reverse(OrderedDistance(d)), v)) = heap.pop() {
        if d > dist[v as usize] {
            continue;
        }
        for &(w, len) in &adjacency[v as usize] {
            let nd = d + len;
            if nd < dist[w as usize] {
                dist[w as usize] = nd;
                parent[w as usize] = v;
                heap.push((Reverse(OrderedDistance(nd)), w));
            }
        }
    }
    let tree = |a: u32, b: u32| parent[a as usize] == b || parent[b as usize] == a;
    // Interior non-tree edges reachable from the root, by the length of their loop.
    let mut candidates: Vec<(f64, u32, u32, u32, u32)> = edges
        .iter()
        .filter_map(|&(a, b, f, g)| {
            let g = g?;
            let (da, db) = (dist[a as usize], dist[b as usize]);
            if tree(a, b) || !da.is_finite() || !db.is_finite() {
                return None;
            }
            let w = adjacency[a as usize].iter().find(|x| x.0 == b).map_or(0.0, |x| x.1);
            Some((da + db + w, a, b, f, g))
        })
        .collect();
    candidates.sort_unstable_by(|x, y| y.0.total_cmp(&x.0));
    let mut parent_face: Vec<u32> = (0..u32::try_from(n_faces).unwrap_or(u32::MAX)).collect();
    fn find(p: &mut [u32], mut x: u32) -> u32 {
        while p[x as usize] != x {
            p[x as usize] = p[p[x as usize] as usize];
            x = p[x as usize];
        }
        x
    }
    let mut shortest: Option<(f64, u32, u32)> = None;
    for &(length, a, b, f, g) in &candidates {
        let (rf, rg) = (find(&mut parent_face, f), find(&mut parent_face, g));
        if rf == rg {
            // Closes a cycle of faces: the loop of a, b does not separate them.
            if shortest.is_none_or(|s| length < s.0) {
                shortest = Some((length, a, b));
            }
        } else {
            parent_face[rf as usize] = rg;
        }
    }
    let (length, a, b) = shortest?;
    // Up from a and from b to their lowest common ancestor.
    let up = |mut v: u32| {
        let mut path = vec![v];
        while parent[v as usize] != u32::MAX {
            v = parent[v as usize];
            path.push(v);
        }
        path
    };
    let (pa, pb) = (up(a), up(b));
    let mut common = 0;
    while common < pa.len().min(pb.len()) && pa[pa.len() - 1 - common] == pb[pb.len() - 1 - common]
    {
        common += 1;
    }
    // pa[..=pa.len() − common] runs a → ancestor; pb the same for b; the loop is
    // a → ancestor → b → a.
    let mut lp: Vec<u32> = pa[..=pa.len() - common].to_vec();
    lp.extend(pb[..pb.len() - common].iter().rev());
    (lp.len() >= 3).then_some((length, lp))
}

/// An `f64` distance ordered for the heap (distances are finite and non-negative).
#[derive(Clone, Copy, PartialEq)]
struct OrderedDistance(f64);

impl Eq for OrderedDistance {}

impl PartialOrd for OrderedDistance {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for OrderedDistance {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// Cuts a closed, consistently oriented mesh along the simple loop `lp`: each vertex of the
/// loop gets a copy, which the triangles on the loop's right side take, so the loop becomes two
/// boundary loops. `false` (and nothing changed) if a fan around a loop vertex does not close.
fn cut_along(
    lp: &[u32],
    faces: &mut [[u32; 3]],
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
) -> bool {
    let half = directed_edges(faces);
    let m = lp.len();
    let mut changes: Vec<(usize, usize)> = Vec::new(); // (face, corner) taking the copy of lp[i]
    let mut owners: Vec<usize> = Vec::new(); // loop index of each change
    for i in 0..m {
        let (prev, v, next) = (lp[(i + m - 1) % m], lp[i], lp[(i + 1) % m]);
        // Around v from the face right of v → next to the face right of prev → v: from the
        // face with half-edge next → v, each next face holds the half-edge (outgoing
        // neighbour) → v, until the face with the half-edge v → prev.
        let Some(mut f) = face_of(&half, next, v) else { return false };
        let mut steps = 0;
        loop {
            let t = faces[f];
            let Some(c) = t.iter().position(|&x| x == v) else { return false };
            changes.push((f, c));
            owners.push(i);
            let out = t[(c + 1) % 3];
            if out == prev {
                break;
            }
            steps += 1;
            let Some(g) = face_of(&half, out, v).filter(|_| steps < 4096) else { return false };
            f = g;
        }
    }
    let first = u32::try_from(positions.len()).unwrap_or(u32::MAX);
    for &v in lp {
        positions.push(positions[v as usize]);
        scan_vertex.push(scan_vertex[v as usize]);
    }
    for (&(f, c), &i) in changes.iter().zip(&owners) {
        faces[f][c] = first + u32::try_from(i).unwrap_or(u32::MAX);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A torus of `major × minor` quads (two triangles each), radii `big` and `small`.
    fn torus(major: usize, minor: usize, big: f64, small: f64) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let tau = std::f64::consts::TAU;
        let mut p = Vec::new();
        for i in 0..major {
            for j in 0..minor {
                let (u, v) = (tau * i as f64 / major as f64, tau * j as f64 / minor as f64);
                let ring = big + small * v.cos();
                p.push(DVec3::new(ring * u.cos(), ring * u.sin(), small * v.sin()));
            }
        }
        let id = |i: usize, j: usize| ((i % major) * minor + j % minor) as u32;
        let mut t = Vec::new();
        for i in 0..major {
            for j in 0..minor {
                let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
                t.push([a, b, c]);
                t.push([a, c, d]);
            }
        }
        (p, t)
    }

    /// Every undirected edge is used by exactly two triangles, once in each direction.
    fn closed_and_oriented(triangles: &[[u32; 3]]) -> bool {
        let mut directed: Vec<(u32, u32)> =
            triangles.iter().flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3]))).collect();
        directed.sort_unstable();
        let unique = directed.windows(2).all(|w| w[0] != w[1]);
        unique && directed.iter().all(|&(a, b)| directed.binary_search(&(b, a)).is_ok())
    }

    /// Checks that `closed` is a closed, oriented surface of genus 0 (counted from its edges)
    /// with one handle cut, whose volume is within `tolerance` of `volume`.
    fn check_cut(closed: &ClosedMesh, points: &[DVec3], volume: f64, tolerance: f64) {
        assert_eq!(closed.repair.handles_cut, 1);
        assert_eq!(closed.repair.holes, 0, "the cuts are not the scan's holes");
        assert!(closed_and_oriented(&closed.triangles));
        let mut edges: Vec<(u32, u32)> = closed
            .triangles
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
            .collect();
        edges.sort_unstable();
        edges.dedup();
        let chi =
            closed.positions.len() as i64 - edges.len() as i64 + closed.triangles.len() as i64;
        assert_eq!(chi, 2);
        // The caps lie on each other: the volume is the torus's.
        assert!(
            (closed.volume() - volume).abs() < tolerance * volume,
            "{} against {volume}",
            closed.volume()
        );
        // The torus's own vertices are all still there, where they were.
        assert!(points.iter().all(|x| closed.positions.contains(x)));
    }

    #[test]
    fn handles_are_cut_along_short_loops_and_the_shape_kept() {
        // A coarse torus (8 × 4 quads) lies within one block of eight mean edge lengths.
        let (p, t) = torus(8, 4, 1.0, 0.5);
        let polygon = close_mesh(&p, &t).expect("cut");
        check_cut(&polygon, &p, 2.0 * std::f64::consts::PI.powi(2) * 0.25, 0.5);
        // A ring: a thin tube (six edges round) around a wide hole (forty edges). It is cut
        // across its tube (a loop of six edges, so twelve vertices on the two cuts), not along
        // it.
        let (p, t) = torus(40, 6, 1.0, 0.15);
        let ring = close_mesh(&p, &t).expect("cut");
        check_cut(&ring, &p, 2.0 * std::f64::consts::PI.powi(2) * 0.15 * 0.15, 0.2);
        let on_cuts = ring.scan_vertex.iter().filter(|&&k| k != ADDED_VERTEX).count() - p.len();
        assert_eq!(on_cuts, 6, "one copy of each vertex of the cut");
    }

    /// The boundary of a union of unit voxels (`filled(x, y, z)` on `0..n[0]` × …), two
    /// triangles per face between a filled voxel and an empty one, wound outward.
    fn voxel_surface(
        n: [i32; 3],
        filled: impl Fn(i32, i32, i32) -> bool,
    ) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let inside =
            |c: [i32; 3]| (0..3).all(|k| (0..n[k]).contains(&c[k])) && filled(c[0], c[1], c[2]);
        let mut index = std::collections::HashMap::new();
        let mut p: Vec<DVec3> = Vec::new();
        let mut id = |c: [i32; 3]| {
            *index.entry(c).or_insert_with(|| {
                p.push(DVec3::new(f64::from(c[0]), f64::from(c[1]), f64::from(c[2])));
                (p.len() - 1) as u32
            })
        };
        let mut t = Vec::new();
        for x in -1..=n[0] {
            for y in -1..=n[1] {
                for z in -1..=n[2] {
                    let c = [x, y, z];
                    if !inside(c) {
                        continue;
                    }
                    for axis in 0..3 {
                        for dir in [-1, 1] {
                            let mut o = c;
                            o[axis] += dir;
                            if inside(o) {
                                continue;
                            }
                            // The face's corners, counter-clockwise seen from outside.
                            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
                            let mut base = c;
                            base[axis] += i32::from(dir > 0);
                            let corner = |du: i32, dv: i32| {
                                let mut q = base;
                                q[u] += du;
                                q[v] += dv;
                                q
                            };
                            let mut quad = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
                            if dir < 0 {
                                quad.reverse();
                            }
                            let q = quad.map(&mut id);
                            t.push([q[0], q[1], q[2]]);
                            t.push([q[0], q[2], q[3]]);
                        }
                    }
                }
            }
        }
        (p, t)
    }

    #[test]
    fn three_handles_are_cut_and_the_surface_stays_whole() {
        // A plate of 7 × 3 × 1 voxels with three square holes through it: genus 3, volume 18.
        let (p, t) = voxel_surface([7, 3, 1], |x, y, _| !(y == 1 && x % 2 == 1));
        assert!(closed_and_oriented(&t));
        let chi = |p: usize, t: &[[u32; 3]]| {
            let mut edges: Vec<u64> = t
                .iter()
                .flat_map(|f| (0..3).map(move |k| edge_key(f[k], f[(k + 1) % 3])))
                .collect();
            edges.sort_unstable();
            edges.dedup();
            p as i64 - edges.len() as i64 + t.len() as i64
        };
        assert_eq!(chi(p.len(), &t), 2 - 2 * 3, "genus 3");
        let closed = close_mesh(&p, &t).expect("cut");
        assert_eq!(closed.repair.handles_cut, 3);
        assert!(closed_and_oriented(&closed.triangles));
        assert_eq!(chi(closed.positions.len(), &closed.triangles), 2);
        // One piece: its faces joined across their edges.
        let mut sides: Vec<(u64, u32)> = closed
            .triangles
            .iter()
            .enumerate()
            .flat_map(|(f, t)| (0..3).map(move |k| (edge_key(t[k], t[(k + 1) % 3]), f as u32)))
            .collect();
        sides.sort_unstable();
        let pairs: Vec<(u64, u32, u32)> =
            sides.chunk_by(|a, b| a.0 == b.0).map(|w| (w[0].0, w[0].1, w[1].1)).collect();
        assert!(faces_connected(closed.triangles.len(), &pairs, &[]));
        // The caps of each cut lie on each other: the plate's volume is kept (to 5 %: the
        // caps are faired to the plate's sides about them and bulge a little).
        assert!((closed.volume() - 18.0).abs() < 0.9, "{}", closed.volume());
    }

    #[test]
    fn loops_around_the_same_handle_are_not_cut_together() {
        // Two meridians of a torus share no vertex, but cut together they split it in two;
        // a meridian and a parallel share a vertex. Only the first loop is taken.
        let (p, t) = torus(8, 4, 1.0, 0.5);
        let id = |i: u32, j: u32| (i % 8) * 4 + j % 4;
        let meridian = |i: u32| (0..4).map(|j| id(i, j)).collect::<Vec<u32>>();
        let parallel: Vec<u32> = (0..8).map(|i| id(i, 0)).collect();
        let found = vec![(1.0, meridian(0)), (1.0, meridian(4)), (2.0, parallel)];
        let chosen = independent_loops(&t, p.len(), found, 3);
        assert_eq!(chosen, vec![meridian(0)]);
        // With no loop in the way, the second meridian alone would do.
        let chosen = independent_loops(&t, p.len(), vec![(1.0, meridian(4))], 3);
        assert_eq!(chosen, vec![meridian(4)]);
    }
}
