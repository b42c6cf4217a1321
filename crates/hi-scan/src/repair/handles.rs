// SPDX-License-Identifier: MIT
//! Step 7 of the repair: the shortest loops that do not separate the surface, found block by
//! block (Erickson and Whittlesey 2005), and the handles cut along them.

use glam::DVec3;
use hi_par::*;

use super::edges::EdgeIndex;
use super::holes::{boundary_loops, fill_holes};
use super::homology::{Homology, IndependentClasses};
use super::{ClosedMesh, Repair};

/// The length of the shortest loop found on the closed mesh `mesh` that does not separate it
/// (the loop [`close_part`](super::close_part) would cut first, found the same way), or
/// `None` for a surface of genus 0. A handle's loop as short as a few edges is a tunnel
/// between two sheets that nearly touch, not a handle of the object.
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
        .flat_map(|&side| handle_loops(&mesh.triangles, &mesh.positions, &[], side))
        .map(|(length, _)| length)
        .min_by(f64::total_cmp)
}

/// The sides of the blocks in which [`close_mesh`](super::close_mesh) looks for loops that
/// cut handles (then over the whole mesh), in mean edge lengths of the mesh.
pub const HANDLE_BLOCKS: [f64; 3] = [8.0, 32.0, 128.0];

/// At most this many handles are cut.
pub const MAX_HANDLES: usize = 32;

/// The highest block index along an axis in [`handle_loops`] (21 bits).
const BLOCK_INDEX_MAX: u64 = (1 << 21) - 1;

/// Roots tried per block: the first vertex of the block, then a vertex of the best loop so far.
const HANDLE_ROOTS: usize = 3;

/// V − E + F of a triangle mesh with `boundary_edges` edges on one triangle (every other edge
/// on two).
pub(super) fn euler_characteristic(vertices: usize, faces: usize, boundary_edges: i64) -> i64 {
    let (v, f) = (vertices as i64, faces as i64);
    v - (3 * f + boundary_edges) / 2 + f
}

/// Step 7 of [`close_mesh`](super::close_mesh) on a closed, consistently oriented mesh: while
/// its genus is above 0, cuts the shortest non-separating loops found ([`handle_loops`], in
/// blocks of every size of [`HANDLE_BLOCKS`] and over the whole mesh; several at once when
/// they are disjoint and do not separate the surface together, [`independent_loops`]) and
/// closes both sides of each cut; at most `max_handles` in all.
pub(super) fn cut_handles(
    faces: &mut Vec<[u32; 3]>,
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
    filled: &mut Vec<bool>,
    chi_wanted: i64,
    max_handles: usize,
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
    // The vertices of the boundary kept open (a disc's): no loop may pass through them.
    let mut on_boundary = vec![false; positions.len()];
    for &v in kept_open.iter().flatten() {
        on_boundary[v as usize] = true;
    }
    let Some(grid) = BlockGrid::of(faces, positions) else {
        return;
    };
    // Every size of block and the whole mesh, side by side (the largest blocks, one of them
    // the whole mesh, are each one thread's work), their loops in the sizes' order.
    let mut searches: Vec<BlockSearch> = HANDLE_BLOCKS
        .iter()
        .chain(&[f64::INFINITY])
        .map(|&blocks| BlockSearch::new(grid, blocks))
        .collect();
    // The faces a cut changed or made since the last search (none searched yet: all).
    let mut changed: Vec<bool> = Vec::new();
    while repair.handles_cut < max_handles {
        let chi = euler_characteristic(positions.len(), faces.len(), open);
        if chi >= chi_wanted {
            return;
        }
        // Every block's loop at every size of block (a loop may fit a block of one grid and
        // not the next, and the roots differ), shortest first; as many of them cut at once as
        // are disjoint and, together, do not separate the surface (by the homology of the
        // faces as they are).
        let mut found: Vec<(f64, Vec<u32>)> = searches
            .par_iter_mut()
            .flat_map_iter(|search| search.loops(faces, positions, &on_boundary, &changed))
            .collect();
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        let wanted = usize::try_from((chi_wanted - chi) / 2)
            .unwrap_or(0)
            .min(max_handles - repair.handles_cut)
            .max(1);
        let loops = independent_loops(&Homology::new(faces), positions.len(), found, wanted);
        if loops.is_empty() {
            return;
        }
        // The loops share no vertex: each is walked round on the faces as they were before
        // any of them was cut (a cut changes only its own loop's corners).
        let before = faces.clone();
        let half = EdgeIndex::directed(&before);
        let mut cut = 0;
        for lp in &loops {
            if !cut_along(lp, (&before, &half), faces, positions, scan_vertex) {
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
        let cuts: Vec<Vec<u32>> = boundary_loops(faces, positions.len())
            .into_iter()
            .filter(|lp| {
                let mut key = lp.clone();
                key.sort_unstable();
                !kept_open.contains(&key)
            })
            .collect();
        fill_holes(&cuts, faces, positions, scan_vertex, filled);
        changed = faces.iter().enumerate().map(|(f, t)| before.get(f) != Some(t)).collect();
        if euler_characteristic(positions.len(), faces.len(), open) != chi + 2 * cut as i64 {
            // Cannot happen for non-separating loops of a closed mesh; stop rather than loop.
            return;
        }
        repair.handles_cut += cut;
    }
}

/// Of the loops `found` (shortest first), at most `wanted` that share no vertex and that,
/// cut together, leave the faces of the closed mesh of `homology` ([`Homology::new`], over
/// `vertices` vertices) connected: each would lower the genus by one (the greedy choice of a
/// shortest system of loops, Erickson and Whittlesey 2005). Disjoint loops cut together leave
/// the surface in one piece exactly when their mod-2 homology classes are independent
/// ([`Homology`]); a loop that separates the surface alone (class 0) is never taken.
pub(super) fn independent_loops(
    homology: &Homology,
    vertices: usize,
    found: Vec<(f64, Vec<u32>)>,
    wanted: usize,
) -> Vec<Vec<u32>> {
    let mut classes = IndependentClasses::default();
    let mut used = vec![false; vertices];
    let mut chosen: Vec<Vec<u32>> = Vec::new();
    for (_, lp) in found {
        if chosen.len() >= wanted {
            break;
        }
        if lp.iter().any(|&v| used.get(v as usize).is_none_or(|&u| u)) {
            continue;
        }
        let Some(class) = homology.of_loop(&lp) else {
            continue;
        };
        if classes.insert(class) {
            for &v in &lp {
                used[v as usize] = true;
            }
            chosen.push(lp);
        }
    }
    chosen
}

/// The root of `x` in the union-find forest `parent` (each entry its parent, a root its own),
/// halving the path on the way.
pub(crate) fn find_root(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        parent[x as usize] = parent[parent[x as usize] as usize];
        x = parent[x as usize];
    }
    x
}

/// The face holding the half-edge a → b.
fn face_of(half: &EdgeIndex, a: u32, b: u32) -> Option<usize> {
    half.find(a, b).map(|h| h as usize / 3)
}

/// The non-separating loops of a mesh found within each block of `blocks` mean edge lengths
/// ([`block_loop`]; infinite for the whole mesh), on both grids of blocks: each loop's length
/// and vertices in order; none when no block holds one. The mesh is
/// closed but for at most one boundary loop, whose vertices `on_boundary` marks (all `false`, or
/// shorter than the vertices, for none); no loop passes through them.
fn handle_loops(
    faces: &[[u32; 3]],
    positions: &[DVec3],
    on_boundary: &[bool],
    blocks: f64,
) -> Vec<(f64, Vec<u32>)> {
    let Some(grid) = BlockGrid::of(faces, positions) else {
        return Vec::new();
    };
    let mut search = BlockSearch::new(grid, blocks);
    search.loops(faces, positions, on_boundary, &[])
}

/// Where the blocks of a handle search lie: the mean edge length of the mesh and the low corner
/// of its box, fixed over the rounds of [`cut_handles`] so that a block the last round's cuts
/// did not touch holds the same faces again.
#[derive(Clone, Copy)]
pub(super) struct BlockGrid {
    /// The mesh's mean edge length.
    mean_edge: f64,
    /// The low corner of its vertices' box.
    lo: DVec3,
}

impl BlockGrid {
    /// The grid of the mesh `faces` over `positions`; `None` for a mesh with no extent.
    pub(super) fn of(faces: &[[u32; 3]], positions: &[DVec3]) -> Option<Self> {
        let at = |k: u32| positions[k as usize];
        let mean_edge = faces
            .iter()
            .map(|t| {
                at(t[0]).distance(at(t[1]))
                    + at(t[1]).distance(at(t[2]))
                    + at(t[2]).distance(at(t[0]))
            })
            .sum::<f64>()
            / (3 * faces.len()).max(1) as f64;
        let lo = positions.iter().fold(DVec3::INFINITY, |a, p| a.min(*p));
        (mean_edge > 0.0 && mean_edge.is_finite() && lo.is_finite())
            .then_some(Self { mean_edge, lo })
    }
}

/// Loops with their lengths, shortest first.
type Loops = Vec<(f64, Vec<u32>)>;

/// The blocks of one size of a handle search, with the loops each block held when it was last
/// searched ([`block_loop`]), by block and grid offset.
pub(super) struct BlockSearch {
    /// The grid.
    grid: BlockGrid,
    /// The blocks' side in mean edge lengths (infinite for the whole mesh).
    blocks: f64,
    /// The loops of each block searched, on each grid (offset 0, then 0.5).
    found: [std::collections::HashMap<u64, Loops>; 2],
    /// Where the faces of the last search lay, on each grid ([`BlockSearch::place`]).
    placed: [Placed; 2],
}

/// The faces of a mesh by block ([`BlockSearch::place`]): 4 bytes a face.
#[derive(Default)]
struct Placed {
    /// The faces, block after block, each block's in increasing order.
    faces: Vec<u32>,
    /// Each block's key and where its faces start in `faces`, in increasing order of key.
    blocks: Vec<(u64, u32)>,
    /// How many faces the mesh had when they were placed.
    count: usize,
}

impl Placed {
    /// The blocks, each its key and faces.
    fn blocks(&self) -> impl Iterator<Item = (u64, &[u32])> {
        self.blocks.iter().enumerate().map(|(b, &(key, start))| {
            let end = self.blocks.get(b + 1).map_or(self.faces.len(), |x| x.1 as usize);
            (key, &self.faces[start as usize..end])
        })
    }

    /// Whether face `f` lies in the block of key `key`.
    fn holds(&self, key: u64, f: u32) -> bool {
        let Ok(b) = self.blocks.binary_search_by_key(&key, |x| x.0) else {
            return false;
        };
        let end = self.blocks.get(b + 1).map_or(self.faces.len(), |x| x.1 as usize);
        self.faces[self.blocks[b].1 as usize..end].binary_search(&f).is_ok()
    }

    /// The faces placed by their (key, face) in increasing order, faces joining the blocks of
    /// their keys.
    fn from_sorted(keyed: &[(u64, u32)], count: usize) -> Self {
        let mut placed = Self { faces: Vec::with_capacity(keyed.len()), blocks: Vec::new(), count };
        for block in keyed.chunk_by(|a, b| a.0 == b.0) {
            let start = u32::try_from(placed.faces.len()).unwrap_or(u32::MAX);
            placed.blocks.push((block[0].0, start));
            placed.faces.extend(block.iter().map(|x| x.1));
        }
        placed
    }

    /// These faces with the faces `added` (by (key, face) in increasing order, every face
    /// numbered after those placed) joining the blocks of their keys.
    fn with(&self, added: &[(u64, u32)], count: usize) -> Self {
        let mut placed = Self {
            faces: Vec::with_capacity(self.faces.len() + added.len()),
            blocks: Vec::with_capacity(self.blocks.len()),
            count,
        };
        let mut old = self.blocks().peekable();
        let mut new = added.chunk_by(|a, b| a.0 == b.0).peekable();
        loop {
            let key = match (old.peek(), new.peek()) {
                (Some(o), Some(n)) => o.0.min(n[0].0),
                (Some(o), None) => o.0,
                (None, Some(n)) => n[0].0,
                (None, None) => break,
            };
            let start = u32::try_from(placed.faces.len()).unwrap_or(u32::MAX);
            placed.blocks.push((key, start));
            // The block's old faces, then its new ones (numbered after them).
            if let Some((_, faces)) = old.next_if(|o| o.0 == key) {
                placed.faces.extend_from_slice(faces);
            }
            if let Some(faces) = new.next_if(|n| n[0].0 == key) {
                placed.faces.extend(faces.iter().map(|x| x.1));
            }
        }
        placed
    }
}

impl BlockSearch {
    /// A search of blocks of `blocks` mean edge lengths on `grid`, nothing searched yet.
    pub(super) fn new(grid: BlockGrid, blocks: f64) -> Self {
        Self { grid, blocks, found: Default::default(), placed: Default::default() }
    }

    /// The loops of every block of the mesh `faces` (see [`handle_loops`]); a block with no face
    /// flagged in `changed` (shorter than the faces: those beyond it are new) that was searched
    /// before gives the loops it gave then, which a search would find again.
    pub(super) fn loops(
        &mut self,
        faces: &[[u32; 3]],
        positions: &[DVec3],
        on_boundary: &[bool],
        changed: &[bool],
    ) -> Vec<(f64, Vec<u32>)> {
        let mut all: Vec<(f64, Vec<u32>)> = Vec::new();
        for (grid, offset) in [0.0, 0.5].into_iter().enumerate() {
            if self.blocks.is_infinite() && offset > 0.0 {
                // One block either way.
                break;
            }
            self.place(grid, offset, faces, positions, changed);
            let blocks: Vec<(u64, &[u32])> = self.placed[grid].blocks().collect();
            if self.blocks.is_finite() && blocks.len() == 1 {
                // One block holding the whole mesh: the search over the whole mesh, which
                // every caller runs as well (and would find the same loops).
                self.found[grid].clear();
                continue;
            }
            let cache = &self.found[grid];
            let searched: Vec<(u64, Loops)> = blocks
                .par_iter()
                .map(|&(key, block)| {
                    let clean = block.iter().all(|&f| changed.get(f as usize).is_some_and(|&c| !c));
                    if clean && let Some(loops) = cache.get(&key) {
                        return (key, loops.clone());
                    }
                    (key, block_loop(faces, positions, on_boundary, block))
                })
                .collect();
            all.extend(searched.iter().flat_map(|(_, loops)| loops.iter().cloned()));
            self.found[grid] = searched.into_iter().collect();
        }
        all
    }

    /// The faces of the last search by block on grid `grid` ([`BlockSearch::place`]).
    #[cfg(test)]
    pub(super) fn placed(&self, grid: usize) -> Vec<(u64, u32)> {
        let placed = &self.placed[grid];
        placed.blocks().flat_map(|(key, faces)| faces.iter().map(move |&f| (key, f))).collect()
    }

    /// Places the faces of the mesh `faces` by block on grid `grid` (shifted by `offset`
    /// blocks) in `placed[grid]`, blocks in the order of their keys: a block's indices (from 0,
    /// as the centroids lie above the grid's low corner) packed into 21 bits each, which keeps
    /// their order (blocks beyond 2²¹ along an axis, on no real mesh, share the last); one
    /// block, 0, for an infinite side.
    /// After a search, only the faces added since and those flagged in `changed` are placed
    /// again (a cut gives a face a copy of its corner, which lies where the corner does, so
    /// the face stays in its block); the list is made anew if one of them moved to another
    /// block, or if nothing is flagged (a new mesh).
    fn place(
        &mut self,
        grid: usize,
        offset: f64,
        faces: &[[u32; 3]],
        positions: &[DVec3],
        changed: &[bool],
    ) {
        let at = |k: u32| positions[k as usize];
        let side = self.blocks * self.grid.mean_edge;
        let lo = self.grid.lo;
        let key = |t: &[u32; 3]| {
            let c = (at(t[0]) + at(t[1]) + at(t[2])) / 3.0;
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "a block index"
            )]
            ((c - lo) / side + offset)
                .floor()
                .to_array()
                .iter()
                .fold(0u64, |key, &x| (key << 21) | (x.max(0.0) as u64).min(BLOCK_INDEX_MAX))
        };
        let face = |f: usize| u32::try_from(f).unwrap_or(u32::MAX);
        let placed = &self.placed[grid];
        let old = placed.count;
        let kept = !changed.is_empty()
            && old <= faces.len()
            && (0..old).all(|f| {
                !changed.get(f).copied().unwrap_or(true) || placed.holds(key(&faces[f]), face(f))
            });
        let mut keyed: Vec<(u64, u32)> = if kept {
            faces[old..].par_iter().enumerate().map(|(k, t)| (key(t), face(old + k))).collect()
        } else {
            faces.par_iter().enumerate().map(|(f, t)| (key(t), face(f))).collect()
        };
        keyed.par_sort_unstable();
        self.placed[grid] = if kept {
            placed.with(&keyed, faces.len())
        } else {
            Placed::from_sorted(&keyed, faces.len())
        };
    }
}

/// The loops found in the faces `block` of a mesh that do not separate them (each alone): their
/// lengths and vertices, shortest first. They are the greedy system through the root whose
/// shortest loop is the shortest of a few roots tried ([`HANDLE_ROOTS`]): the system has two
/// loops per handle (about it and along it), of which at most one is cut ([`cut_handles`]
/// chooses), and cutting the loops of several handles found in one search takes fewer searches
/// than one at a time.
/// The mesh is closed but for at most one boundary loop (the vertices `on_boundary` marks): the
/// loops avoid its vertices, and the faces about it count as joined, as the band of faces along
/// the whole loop joins them (so a loop whose sides both reach the boundary does not separate
/// the mesh).
pub(super) fn block_loop(
    faces: &[[u32; 3]],
    positions: &[DVec3],
    on_boundary: &[bool],
    block: &[u32],
) -> Vec<(f64, Vec<u32>)> {
    block_loop_with(faces, positions, on_boundary, block, true)
}

/// [`block_loop`], with the search skipped for a block of genus 0 ([`genus_zero`]) if
/// `shortcut`, as [`block_loop`] does (the tests compare the two).
pub(super) fn block_loop_with(
    faces: &[[u32; 3]],
    positions: &[DVec3],
    on_boundary: &[bool],
    block: &[u32],
    shortcut: bool,
) -> Vec<(f64, Vec<u32>)> {
    // Local vertices (in the order the block's faces first reach them), the block's faces on
    // them, and the faces with a vertex on the boundary.
    let boundary = |v: u32| on_boundary.get(v as usize).copied().unwrap_or(false);
    let (verts, local_faces) = LOCAL.with_borrow_mut(|local| {
        if local.len() < positions.len() {
            local.resize(positions.len(), u32::MAX);
        }
        let mut verts: Vec<u32> = Vec::new();
        let local_faces: Vec<[u32; 3]> = block
            .iter()
            .map(|&f| {
                faces[f as usize].map(|v| {
                    let slot = &mut local[v as usize];
                    if *slot == u32::MAX {
                        *slot = u32::try_from(verts.len()).unwrap_or(u32::MAX);
                        verts.push(v);
                    }
                    *slot
                })
            })
            .collect();
        for &v in &verts {
            local[v as usize] = u32::MAX;
        }
        (verts, local_faces)
    });
    let band: Vec<u32> = (0..block.len())
        .filter(|&i| faces[block[i] as usize].iter().any(|&v| boundary(v)))
        .map(|i| u32::try_from(i).unwrap_or(u32::MAX))
        .collect();
    let list = block_edges(&local_faces);
    let n = verts.len();
    // Most blocks of the smaller sizes hold no handle, which a count shows at less cost than
    // a search.
    if shortcut && band.is_empty() && genus_zero(n, &list, block.len()) {
        return Vec::new();
    }
    let adjacency = Adjacency::new(n, &list, |a, b| {
        positions[verts[a as usize] as usize].distance(positions[verts[b as usize] as usize])
    });
    let excluded: Vec<bool> = verts.iter().map(|&v| boundary(v)).collect();
    let mut best: Vec<(f64, Vec<u32>)> = Vec::new();
    let Some(mut root) = excluded.iter().position(|&e| !e).and_then(|r| u32::try_from(r).ok())
    else {
        return best;
    };
    let graph = BlockGraph { adjacency: &adjacency, edges: &list, faces: block.len(), band: &band };
    for _ in 0..HANDLE_ROOTS {
        let loops = loop_through(root, &graph, &excluded);
        let Some((length, lp)) = loops.first() else {
            break;
        };
        let improved = best.first().is_none_or(|(b, _)| *length < *b - 1e-12 * b.abs());
        if improved {
            // Next, a root across the loop from this one.
            root = lp[lp.len() / 2];
            best = loops;
        } else {
            break;
        }
    }
    // Two loops per handle, crossing each other: at most one of each pair is cut, and both are
    // offered, so that where the shorter is kept out by another handle's cut (a vertex shared,
    // or a class their cuts would repeat) the other may still be cut in the same round.
    best.into_iter()
        .map(|(length, lp)| (length, lp.iter().map(|&v| verts[v as usize]).collect()))
        .collect()
}

thread_local! {
    /// Each vertex's index among the vertices of the block being searched ([`block_loop`]),
    /// `u32::MAX` for none: one array per thread, cleared after each block.
    static LOCAL: std::cell::RefCell<Vec<u32>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// The undirected edges of a block's faces `faces` (on local vertices) as
/// (a, b, face, the other face or `None` on the block's border), a < b, ordered by (a, b)
/// ([`EdgeIndex::undirected`]; half-edge 3f + k is on face f).
pub(super) fn block_edges(faces: &[[u32; 3]]) -> Vec<(u32, u32, u32, Option<u32>)> {
    EdgeIndex::undirected(faces)
        .groups()
        .map(|(a, b, sides)| (a, b, sides[0].1 / 3, sides.get(1).map(|x| x.1 / 3)))
        .collect()
}

/// Whether a block of `faces` faces on `n` vertices with the edges `list` ([`block_edges`]) is
/// a surface of genus 0 with no pinched vertex, so that no loop of its edges leaves its faces
/// joined ([`loop_through`] would find none): every edge on at most two of its faces, every
/// vertex on none or two of its border edges (one fan of faces about it: the mesh about the
/// block is closed and its fans split), and V − E + F = 2C − b over its C pieces and b border
/// loops. A simple loop on a surface of genus 0 separates it (Jordan), its two sides lying in
/// different pieces; a pinched vertex, where the surface touches itself, would let a loop
/// through it join two border loops without separating the faces.
pub(super) fn genus_zero(n: usize, list: &[(u32, u32, u32, Option<u32>)], faces: usize) -> bool {
    let sides: usize = list.iter().map(|e| 1 + usize::from(e.3.is_some())).sum();
    if sides != 3 * faces {
        return false; // an edge on three faces or more
    }
    let mut border = vec![0u8; n];
    let mut vertex_parent: Vec<u32> = (0..u32::try_from(n).unwrap_or(u32::MAX)).collect();
    let mut face_parent: Vec<u32> = (0..u32::try_from(faces).unwrap_or(u32::MAX)).collect();
    let (mut pieces, mut loops) = (faces as i64, 0i64);
    for &(a, b, f, g) in list {
        match g {
            Some(g) => {
                let (rf, rg) = (find_root(&mut face_parent, f), find_root(&mut face_parent, g));
                if rf != rg {
                    face_parent[rf as usize] = rg;
                    pieces -= 1;
                }
            }
            None => {
                for v in [a, b] {
                    border[v as usize] = border[v as usize].saturating_add(1);
                }
                let (ra, rb) = (find_root(&mut vertex_parent, a), find_root(&mut vertex_parent, b));
                if ra == rb {
                    loops += 1; // the edge closes a border loop
                } else {
                    vertex_parent[ra as usize] = rb;
                }
            }
        }
    }
    if border.iter().any(|&count| count != 0 && count != 2) {
        return false; // a pinched vertex
    }
    let chi = n as i64 - list.len() as i64 + faces as i64;
    chi == 2 * pieces - loops
}

/// A block of faces as [`loop_through`] searches it.
struct BlockGraph<'a> {
    /// Its vertices' edges.
    adjacency: &'a Adjacency,
    /// Its edges (a, b, face, the other face or `None` on the block's border).
    edges: &'a [(u32, u32, u32, Option<u32>)],
    /// Its number of faces.
    faces: usize,
    /// Its faces with a vertex on the mesh's boundary, joined along it.
    band: &'a [u32],
}

/// The greedy system of non-separating loops through the shortest-path tree from `root`
/// (Erickson and Whittlesey 2005): Dijkstra from the root, then the faces joined across the
/// non-tree edges (the faces of the band about the boundary joined from the start), longest
/// loop first; each edge whose faces are already joined closes a loop that does not separate
/// them, the shortest such loop first and each next one the shortest that does not separate
/// them together with those before it. The loops are returned from one end of the edge up the
/// tree to the ends' lowest common ancestor and down to the other end, with their lengths,
/// shortest first. The `excluded` vertices (the boundary's) are never reached. None when every
/// loop of the tree separates the faces (an empty list).
fn loop_through(root: u32, graph: &BlockGraph<'_>, excluded: &[bool]) -> Vec<(f64, Vec<u32>)> {
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;
    let (adjacency, edges, n_faces) = (graph.adjacency, graph.edges, graph.faces);
    let n = adjacency.len();
    let mut dist = vec![f64::INFINITY; n];
    let mut parent = vec![u32::MAX; n];
    let mut heap = BinaryHeap::new();
    dist[root as usize] = 0.0;
    // The heap orders distances by their bits, as `f64::total_cmp` orders them (they are
    // finite and at least +0, whose bits grow with them), in fewer steps.
    heap.push((Reverse(0.0f64.to_bits()), root));
    while let Some((Reverse(bits), v)) = heap.pop() {
        let d = f64::from_bits(bits);
        if d > dist[v as usize] {
            continue;
        }
        for &(w, len) in adjacency.of(v) {
            if excluded[w as usize] {
                continue;
            }
            let nd = d + len;
            if nd < dist[w as usize] {
                dist[w as usize] = nd;
                parent[w as usize] = v;
                heap.push((Reverse(nd.to_bits()), w));
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
            let w = adjacency.of(a).iter().find(|x| x.0 == b).map_or(0.0, |x| x.1);
            Some((da + db + w, a, b, f, g))
        })
        .collect();
    candidates.sort_unstable_by(|x, y| y.0.total_cmp(&x.0));
    let mut parent_face: Vec<u32> = (0..u32::try_from(n_faces).unwrap_or(u32::MAX)).collect();
    if let Some((&first, rest)) = graph.band.split_first() {
        for &f in rest {
            let (rf, r0) = (find_root(&mut parent_face, f), find_root(&mut parent_face, first));
            parent_face[rf as usize] = r0;
        }
    }
    // The edges that close a cycle of faces: their loops do not separate them (the greedy
    // system of loops through the root), shortest first.
    let mut closing: Vec<(f64, u32, u32)> = Vec::new();
    for &(length, a, b, f, g) in &candidates {
        let (rf, rg) = (find_root(&mut parent_face, f), find_root(&mut parent_face, g));
        if rf == rg {
            closing.push((length, a, b));
        } else {
            parent_face[rf as usize] = rg;
        }
    }
    closing.reverse();
    // Up from a and from b to their lowest common ancestor.
    let up = |mut v: u32| {
        let mut path = vec![v];
        while parent[v as usize] != u32::MAX {
            v = parent[v as usize];
            path.push(v);
        }
        path
    };
    let mut loops: Vec<(f64, Vec<u32>)> = closing
        .into_iter()
        .filter_map(|(length, a, b)| {
            let (pa, pb) = (up(a), up(b));
            let mut common = 0;
            while common < pa.len().min(pb.len())
                && pa[pa.len() - 1 - common] == pb[pb.len() - 1 - common]
            {
                common += 1;
            }
            // pa[..=pa.len() − common] runs a → ancestor; pb the same for b; the loop is
            // a → ancestor → b → a, shorter than the loop through the root by twice the
            // ancestor's distance from it.
            let ancestor = pa[pa.len() - common];
            let mut lp: Vec<u32> = pa[..=pa.len() - common].to_vec();
            lp.extend(pb[..pb.len() - common].iter().rev());
            (lp.len() >= 3).then_some((length - 2.0 * dist[ancestor as usize], lp))
        })
        .collect();
    loops.sort_by(|x, y| x.0.total_cmp(&y.0));
    loops
}

/// The edges of a block's vertices with their lengths, each vertex's in one slice (in the
/// order of the edge list: each edge a–b gives a its entry b and b its entry a).
struct Adjacency {
    /// Where each vertex's neighbours start in `to`, and where the last one's end.
    start: Vec<usize>,
    /// Each vertex's neighbours and the lengths of the edges to them.
    to: Vec<(u32, f64)>,
}

impl Adjacency {
    /// The adjacency of `n` vertices joined by the edges (a, b, …) of `edges`, each of the
    /// length `length(a, b)`.
    fn new(
        n: usize,
        edges: &[(u32, u32, u32, Option<u32>)],
        length: impl Fn(u32, u32) -> f64,
    ) -> Self {
        let mut start = vec![0usize; n + 1];
        for &(a, b, _, _) in edges {
            start[a as usize + 1] += 1;
            start[b as usize + 1] += 1;
        }
        for k in 1..=n {
            start[k] += start[k - 1];
        }
        let mut next = start.clone();
        let mut to = vec![(0u32, 0.0f64); start[n]];
        for &(a, b, _, _) in edges {
            let w = length(a, b);
            to[next[a as usize]] = (b, w);
            next[a as usize] += 1;
            to[next[b as usize]] = (a, w);
            next[b as usize] += 1;
        }
        Self { start, to }
    }

    /// The number of vertices.
    fn len(&self) -> usize {
        self.start.len() - 1
    }

    /// The neighbours of vertex `v` and the lengths of the edges to them.
    fn of(&self, v: u32) -> &[(u32, f64)] {
        &self.to[self.start[v as usize]..self.start[v as usize + 1]]
    }
}

/// Cuts a closed, consistently oriented mesh along the simple loop `lp`: each vertex of the
/// loop gets a copy, which the triangles on the loop's right side take, so the loop becomes two
/// boundary loops. The fans about the loop's vertices are walked on `before` (the faces before
/// this round's cuts, with their half-edges `half`, [`EdgeIndex::directed`]): the other loops cut
/// since share no vertex with this one, and changed only their own corners. `false` (and
/// nothing changed) if a fan around a loop vertex does not close.
fn cut_along(
    lp: &[u32],
    (before, half): (&[[u32; 3]], &EdgeIndex),
    faces: &mut [[u32; 3]],
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
) -> bool {
    let m = lp.len();
    let mut changes: Vec<(usize, usize)> = Vec::new(); // (face, corner) taking the copy of lp[i]
    let mut owners: Vec<usize> = Vec::new(); // loop index of each change
    for i in 0..m {
        let (prev, v, next) = (lp[(i + m - 1) % m], lp[i], lp[(i + 1) % m]);
        // Around v from the face right of v → next to the face right of prev → v: from the
        // face with half-edge next → v, each next face holds the half-edge (outgoing
        // neighbour) → v, until the face with the half-edge v → prev.
        let Some(mut f) = face_of(half, next, v) else { return false };
        let mut steps = 0;
        loop {
            let t = before[f];
            let Some(c) = t.iter().position(|&x| x == v) else { return false };
            changes.push((f, c));
            owners.push(i);
            let out = t[(c + 1) % 3];
            if out == prev {
                break;
            }
            steps += 1;
            let Some(g) = face_of(half, out, v).filter(|_| steps < 4096) else { return false };
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
