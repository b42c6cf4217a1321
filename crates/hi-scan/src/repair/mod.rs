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
//!    triangles shrinking to a new vertex at the loop's centroid (faired to the thin plate
//!    the surface continues into; the rings further from the loop sparser), flagged in
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
//! within each block (faces grouped by their centroids, on two grids offset by half a block, so
//! that a short loop seldom straddles blocks of both), a shortest-path tree from a root and a
//! spanning tree of the faces across the other edges, taken longest loop first; an edge that
//! would close a cycle of faces closes a loop of the tree that does not separate the block,
//! hence not the surface. The loops of every block, every size and a few roots are taken
//! shortest first, and each search cuts as many of them as share no vertex and, cut together,
//! leave the surface in one piece (then each lowers the genus by one; the greedy shortest
//! system of loops): disjoint loops do exactly when their mod-2 homology classes are
//! independent, which a tree–cotree decomposition of the mesh gives each loop (`homology`). The
//! whole mesh, as one block, always holds one while the genus is above 0. The search is
//! repeated until the genus is 0, on the blocks of the first search (the mesh's mean edge and
//! box as they were): a block whose faces no cut changed gives the loops it gave before. A
//! block whose Euler characteristic V − E + F is 2C − b over its C pieces and b border loops,
//! and where no vertex joins two fans of its faces, is a surface of genus 0: every loop in it
//! separates it, so it is not searched (most blocks of the smaller sizes; the loops found are
//! the same).
//!
//! Steps 1 to 3 are in `parts`, the fans and holes of steps 5 and 6 in `holes`, and the handles
//! of step 7 in `handles` (which loops to cut together in `homology`); `edges` indexes the
//! half-edges by vertex (a counting sort) for the lookups of every step, and `band` solves the
//! caps' fairing (a banded Cholesky factorisation).

mod band;
mod edges;
mod handles;
mod holes;
mod homology;
mod parts;

use glam::DVec3;

use crate::Error;
use edges::EdgeIndex;
use handles::{cut_handles, euler_characteristic};
use holes::{boundary_loops, fill_holes, split_fans};

pub(crate) use handles::find_root;
pub use handles::{HANDLE_BLOCKS, MAX_HANDLES, shortest_handle};
pub use parts::mesh_parts;

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
#[cfg(test)]
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
    let edges = 3 * faces.len() as i64;
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
    close_part_cutting(part, closing, MAX_HANDLES)
}

/// [`close_part`], cutting up to `max_handles` handles rather than [`MAX_HANDLES`] (more for a
/// surface whose many handles are worth cutting however long it takes; a part with more fails
/// as it does there).
///
/// # Errors
///
/// As [`close_part`]'s, with `max_handles` for [`MAX_HANDLES`].
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::repair::{Closing, close_part_cutting, mesh_parts};
///
/// // A torus of 24 × 8 quads: one handle, so a sphere needs one cut.
/// let (nu, nv) = (24u32, 8u32);
/// let at = |i: u32, j: u32| {
///     let (a, b) = (std::f64::consts::TAU * f64::from(i % nu) / f64::from(nu), std::f64::consts::TAU * f64::from(j % nv) / f64::from(nv));
///     DVec3::new((1.0 + 0.3 * b.cos()) * a.cos(), (1.0 + 0.3 * b.cos()) * a.sin(), 0.3 * b.sin())
/// };
/// let points: Vec<DVec3> = (0..nu * nv).map(|k| at(k / nv, k % nv)).collect();
/// let id = |i: u32, j: u32| (i % nu) * nv + j % nv;
/// let triangles: Vec<[u32; 3]> = (0..nu)
///     .flat_map(|i| (0..nv).flat_map(move |j| [[id(i, j), id(i + 1, j), id(i + 1, j + 1)], [id(i, j), id(i + 1, j + 1), id(i, j + 1)]]))
///     .collect();
/// let part = &mesh_parts(&points, &triangles).unwrap().parts[0];
/// assert_eq!(close_part_cutting(part, Closing::Sphere, 1).unwrap().repair.handles_cut, 1);
/// assert!(close_part_cutting(part, Closing::Sphere, 0).is_err());
/// ```
pub fn close_part_cutting(
    part: &MeshPart,
    closing: Closing,
    max_handles: usize,
) -> Result<ClosedMesh, Error> {
    close(part, closing, max_handles, false).map(|(closed, _)| closed)
}

/// [`close_part_cutting`] as a disc ([`Closing::Disc`]), or, should the disc keep a handle that
/// no loop clear of its boundary cuts, as a sphere: the disc's boundary capped and the cutting
/// carried on from the disc's cuts (not begun again), up to `max_handles` in all. The disc's
/// failure is returned with the sphere (`None` with the disc).
///
/// # Errors
///
/// As [`close_part_cutting`]'s for a disc, and for the sphere should it fail too.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::repair::{close_disc_or_sphere, mesh_parts};
///
/// // A square sheet of 8 × 8 quads: a disc as it is, with no cut.
/// let points: Vec<DVec3> = (0..81).map(|k| DVec3::new(f64::from(k % 9), f64::from(k / 9), 0.0)).collect();
/// let id = |i: u32, j: u32| j * 9 + i;
/// let triangles: Vec<[u32; 3]> = (0..8)
///     .flat_map(|i| (0..8).flat_map(move |j| [[id(i, j), id(i + 1, j), id(i + 1, j + 1)], [id(i, j), id(i + 1, j + 1), id(i, j + 1)]]))
///     .collect();
/// let part = &mesh_parts(&points, &triangles).unwrap().parts[0];
/// let (disc, failed) = close_disc_or_sphere(part, 32).unwrap();
/// assert!(failed.is_none());
/// assert_eq!((disc.triangles.len(), disc.repair.handles_cut), (128, 0));
/// ```
pub fn close_disc_or_sphere(
    part: &MeshPart,
    max_handles: usize,
) -> Result<(ClosedMesh, Option<Error>), Error> {
    close(part, Closing::Disc, max_handles, true)
}

/// [`close_part_cutting`]; with `else_sphere`, a disc that keeps a handle closed on as a
/// sphere ([`close_disc_or_sphere`]), with the disc's failure.
fn close(
    part: &MeshPart,
    closing: Closing,
    max_handles: usize,
    else_sphere: bool,
) -> Result<(ClosedMesh, Option<Error>), Error> {
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
    // Closing the holes leaves the genus as it is: a part with more handles than step 7 cuts
    // (or a torus of another genus) fails here, before its holes are filled at a cost.
    let boundary: i64 = loops.iter().map(|l| l.len() as i64).sum();
    let genus =
        (2 - euler_characteristic(positions.len(), kept.len(), boundary) - loops.len() as i64) / 2;
    let hopeless = match closing {
        Closing::Torus => genus != 1,
        Closing::Sphere | Closing::Disc => genus > max_handles as i64,
    };
    if hopeless {
        let open = i64::from(closing == Closing::Disc && !loops.is_empty());
        return Err(genus_error(closing, 2 - 2 * genus - open, open));
    }
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
    fill_holes(&loops, &mut kept, &mut positions, &mut scan_vertex, &mut filled);
    repair.holes += loops.len();
    repair.hole_edges += loops.iter().map(Vec::len).sum::<usize>();

    // 7. Cut handles, but a torus's; none if there are more than can be cut.
    let chi_wanted = match closing {
        Closing::Sphere => 2,
        Closing::Torus => 0,
        Closing::Disc => 1,
    };
    let boundary_edges = open.as_ref().map_or(0, Vec::len) as i64;
    let handles =
        (chi_wanted - euler_characteristic(positions.len(), kept.len(), boundary_edges)) / 2;
    if closing != Closing::Torus && handles <= max_handles as i64 {
        cut_handles(
            &mut kept,
            &mut positions,
            &mut scan_vertex,
            &mut filled,
            chi_wanted,
            max_handles,
            &mut repair,
        );
    }

    // 8. The Euler characteristic (a disc's one boundary loop counts one edge per edge).
    let e = (3 * kept.len() as i64 + boundary_edges) / 2;
    let chi = positions.len() as i64 - e + kept.len() as i64;
    let mut closing = closing;
    let mut failed = None;
    if chi != chi_wanted {
        let error = genus_error(closing, chi, i64::from(open.is_some()));
        // A disc that keeps a handle: its boundary capped, and cut on as a sphere.
        let Some(lp) = open.filter(|_| else_sphere) else {
            return Err(error);
        };
        fill_holes(
            std::slice::from_ref(&lp),
            &mut kept,
            &mut positions,
            &mut scan_vertex,
            &mut filled,
        );
        repair.holes += 1;
        repair.hole_edges += lp.len();
        closing = Closing::Sphere;
        cut_handles(
            &mut kept,
            &mut positions,
            &mut scan_vertex,
            &mut filled,
            2,
            max_handles,
            &mut repair,
        );
        let chi = euler_characteristic(positions.len(), kept.len(), 0);
        if chi != 2 {
            return Err(genus_error(closing, chi, 0));
        }
        failed = Some(error);
    }

    // 9. Outward, for a closed surface.
    if closing != Closing::Disc && signed_volume(&positions, &kept) < 0.0 {
        for t in &mut kept {
            t.swap(1, 2);
        }
        repair.flipped = true;
    }
    Ok((ClosedMesh { positions, triangles: kept, scan_vertex, filled, repair }, failed))
}

/// The error of [`close_part`] for a closed surface of Euler characteristic `chi` with `open`
/// boundary loops (1 for a disc's, else 0), of another genus than `closing` needs.
fn genus_error(closing: Closing, chi: i64, open: i64) -> Error {
    Error::Topology {
        what: format!(
            "the surface has genus {} once its holes are closed (Euler characteristic {chi}), not the genus {} a {} needs",
            (2 - chi - open) / 2,
            if closing == Closing::Torus { 1 } else { 0 },
            match closing {
                Closing::Sphere => "sphere",
                Closing::Torus => "torus",
                Closing::Disc => "disc",
            }
        ),
    }
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
pub(super) fn neighbours(faces: &[[u32; 3]]) -> Vec<Option<u32>> {
    let mut across = vec![None; 3 * faces.len()];
    for (_, _, g) in EdgeIndex::undirected(faces).groups() {
        if let [(_, a), (_, b)] = g {
            across[*a as usize] = Some(b / 3);
            across[*b as usize] = Some(a / 3);
        }
    }
    across
}

#[cfg(test)]
mod tests;
