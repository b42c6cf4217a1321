// SPDX-License-Identifier: MIT
//! Which disjoint loops of a mesh may be cut together: the mod-2 homology classes of its edges
//! from a tree–cotree decomposition (Eppstein, "Dynamic generators of topologically embedded
//! graphs", 2003), so that step 7 of the repair tells in a few word operations per loop what a
//! walk over every face would tell.
//!
//! Cap each boundary loop of the mesh with one face: a closed orientable surface S of genus g.
//! Disjoint simple loops cut from S leave it in one piece exactly when no non-empty subset of
//! them bounds, that is, when their classes in H₁(S; Z₂) = Z₂²ᵍ are linearly independent (a
//! piece cut off is bounded by the loops about it, whose classes then sum to zero; conversely
//! loops whose classes sum to zero bound a set of faces, which their cut separates). The caps
//! change nothing of this for loops clear of the boundary, whose faces are joined round each
//! boundary vertex's fan whatever is cut.
//!
//! A spanning tree T of the vertices, a spanning tree C of the faces across the edges not in
//! T, and the 2g edges L left over: each edge e not in T closes one loop of T, and the classes
//! of the loops of L are a basis of H₁. A loop of T's edges and e ∈ L has the class that is 1
//! at e and 0 elsewhere; a face's boundary bounds, so the classes of the non-tree edges about
//! each face sum to zero, which gives the class of each edge of C from the faces below it in C,
//! leaves first. A loop's class is then the sum of its edges' classes (T's are 0).

use super::edges::EdgeIndex;
use super::find_root;

/// The mod-2 homology class of every edge of a closed-but-for-boundaries oriented mesh, in the
/// basis of its leftover edges (see the module documentation).
pub(super) struct Homology {
    /// The undirected half-edges, to find an edge from its ends.
    index: EdgeIndex,
    /// The edge of each half-edge (half-edge 3f + k on face f).
    edge_of_half: Vec<u32>,
    /// Words per class (64 classes' bits to a word).
    words: usize,
    /// The classes, `words` words per edge.
    class: Vec<u64>,
}

impl Homology {
    /// The classes of the edges of `faces`: consistently oriented, every edge on one or two
    /// faces, each vertex's faces one fan.
    pub(super) fn new(faces: &[[u32; 3]]) -> Self {
        let index = EdgeIndex::undirected(faces);
        let mut edge_of_half = vec![u32::MAX; 3 * faces.len()];
        let mut ends: Vec<(u32, u32)> = Vec::new();
        let mut sides: Vec<(u32, u32)> = Vec::new();
        for (a, b, group) in index.groups() {
            let e = u32::try_from(ends.len()).unwrap_or(u32::MAX);
            for &(_, h) in group {
                edge_of_half[h as usize] = e;
            }
            ends.push((a, b));
            let f = group[0].1 / 3;
            sides.push((f, group.get(1).map_or(u32::MAX, |x| x.1 / 3)));
        }
        let n_faces = faces.len();
        let n_vertices = index.vertices();
        // Each boundary loop capped by a face of its own, numbered after the triangles: the
        // boundary edges joined through their shared vertices.
        let mut vertex_parent: Vec<u32> =
            (0..u32::try_from(n_vertices).unwrap_or(u32::MAX)).collect();
        for (e, &(a, b)) in ends.iter().enumerate() {
            if sides[e].1 == u32::MAX {
                let (ra, rb) = (find_root(&mut vertex_parent, a), find_root(&mut vertex_parent, b));
                if ra != rb {
                    vertex_parent[ra as usize] = rb;
                }
            }
        }
        let mut cap_of_root = vec![u32::MAX; n_vertices];
        let mut caps = 0u32;
        for (e, &(a, _)) in ends.iter().enumerate() {
            if sides[e].1 == u32::MAX {
                let r = find_root(&mut vertex_parent, a) as usize;
                if cap_of_root[r] == u32::MAX {
                    cap_of_root[r] = u32::try_from(n_faces).unwrap_or(u32::MAX) + caps;
                    caps += 1;
                }
                sides[e].1 = cap_of_root[r];
            }
        }
        let all_faces = n_faces + caps as usize;
        // T: a spanning forest of the vertices (Kruskal's order is any order).
        let mut in_tree = vec![false; ends.len()];
        let mut vertex_parent: Vec<u32> =
            (0..u32::try_from(n_vertices).unwrap_or(u32::MAX)).collect();
        for (e, &(a, b)) in ends.iter().enumerate() {
            let (ra, rb) = (find_root(&mut vertex_parent, a), find_root(&mut vertex_parent, b));
            if ra != rb {
                vertex_parent[ra as usize] = rb;
                in_tree[e] = true;
            }
        }
        // C: a spanning forest of the faces across the other edges; L: the rest.
        let mut face_parent: Vec<u32> = (0..u32::try_from(all_faces).unwrap_or(u32::MAX)).collect();
        let mut cotree: Vec<u32> = Vec::new();
        let mut leftover: Vec<u32> = Vec::new();
        for (e, &(f, g)) in sides.iter().enumerate() {
            if in_tree[e] {
                continue;
            }
            let (rf, rg) = (find_root(&mut face_parent, f), find_root(&mut face_parent, g));
            let e = u32::try_from(e).unwrap_or(u32::MAX);
            if rf == rg {
                leftover.push(e);
            } else {
                face_parent[rf as usize] = rg;
                cotree.push(e);
            }
        }
        let words = leftover.len().div_ceil(64).max(1);
        let mut class = vec![0u64; words * ends.len()];
        for (bit, &e) in leftover.iter().enumerate() {
            class[e as usize * words + bit / 64] |= 1 << (bit % 64);
        }
        // C rooted: each face's edges (the triangles' three, the caps' boundary edges), the
        // faces in breadth-first order from each root with the edge of C they were reached by.
        let mut start = vec![0usize; all_faces + 1];
        for &e in &cotree {
            let (f, g) = sides[e as usize];
            start[f as usize + 1] += 1;
            start[g as usize + 1] += 1;
        }
        for k in 1..=all_faces {
            start[k] += start[k - 1];
        }
        let mut next = start.clone();
        let mut adjacent = vec![0u32; start[all_faces]];
        for &e in &cotree {
            let (f, g) = sides[e as usize];
            adjacent[next[f as usize]] = e;
            next[f as usize] += 1;
            adjacent[next[g as usize]] = e;
            next[g as usize] += 1;
        }
        let mut reached_by = vec![u32::MAX; all_faces];
        let mut seen = vec![false; all_faces];
        let mut order: Vec<u32> = Vec::with_capacity(all_faces);
        for root in 0..all_faces {
            if seen[root] {
                continue;
            }
            seen[root] = true;
            let first = order.len();
            order.push(u32::try_from(root).unwrap_or(u32::MAX));
            let mut k = first;
            while k < order.len() {
                let f = order[k] as usize;
                k += 1;
                for &e in &adjacent[start[f]..start[f + 1]] {
                    let (a, b) = sides[e as usize];
                    let g = if a as usize == f { b } else { a } as usize;
                    if !seen[g] {
                        seen[g] = true;
                        reached_by[g] = e;
                        order.push(u32::try_from(g).unwrap_or(u32::MAX));
                    }
                }
            }
        }
        // The caps' edges.
        let mut cap_start = vec![0usize; caps as usize + 1];
        for (e, &(_, g)) in sides.iter().enumerate() {
            if g as usize >= n_faces && !in_tree[e] {
                cap_start[g as usize - n_faces + 1] += 1;
            }
        }
        for k in 1..=caps as usize {
            cap_start[k] += cap_start[k - 1];
        }
        let mut cap_next = cap_start.clone();
        let mut cap_edges = vec![0u32; cap_start[caps as usize]];
        for (e, &(_, g)) in sides.iter().enumerate() {
            if g as usize >= n_faces && !in_tree[e] {
                let c = g as usize - n_faces;
                cap_edges[cap_next[c]] = u32::try_from(e).unwrap_or(u32::MAX);
                cap_next[c] += 1;
            }
        }
        // Leaves first: the edge a face was reached by takes the sum of its other non-tree
        // edges' classes (all known by then: L's, and C's to the faces below it).
        let mut sum = vec![0u64; words];
        for &f in order.iter().rev() {
            let f = f as usize;
            let up = reached_by[f];
            if up == u32::MAX {
                continue;
            }
            sum.fill(0);
            let add = |e: u32, sum: &mut [u64]| {
                if e != up && !in_tree[e as usize] {
                    let at = e as usize * words;
                    for (s, c) in sum.iter_mut().zip(&class[at..at + words]) {
                        *s ^= c;
                    }
                }
            };
            if f < n_faces {
                for k in 0..3 {
                    add(edge_of_half[3 * f + k], &mut sum);
                }
            } else {
                let c = f - n_faces;
                for &e in &cap_edges[cap_start[c]..cap_start[c + 1]] {
                    add(e, &mut sum);
                }
            }
            let at = up as usize * words;
            class[at..at + words].copy_from_slice(&sum);
        }
        Self { index, edge_of_half, words, class }
    }

    /// The class of the closed loop through the vertices `lp` in order (and back to the
    /// first), `None` if two of them in a row are not an edge of the mesh.
    pub(super) fn of_loop(&self, lp: &[u32]) -> Option<Vec<u64>> {
        let mut sum = vec![0u64; self.words];
        let m = lp.len();
        for i in 0..m {
            let (a, b) = (lp[i], lp[(i + 1) % m]);
            let h = self.index.find(a.min(b), a.max(b))?;
            let at = self.edge_of_half[h as usize] as usize * self.words;
            for (s, c) in sum.iter_mut().zip(&self.class[at..at + self.words]) {
                *s ^= c;
            }
        }
        Some(sum)
    }
}

/// Classes kept linearly independent over Z₂ (Gaussian elimination, each kept class reduced
/// by those before it and filed under its lowest bit).
#[derive(Default)]
pub(super) struct IndependentClasses {
    /// (the lowest bit, the reduced class).
    basis: Vec<(usize, Vec<u64>)>,
}

impl IndependentClasses {
    /// Whether `class` is independent of the classes kept (nonzero once reduced by them); if so
    /// it is kept.
    pub(super) fn insert(&mut self, mut class: Vec<u64>) -> bool {
        for (pivot, b) in &self.basis {
            if class[pivot / 64] >> (pivot % 64) & 1 == 1 {
                for (c, x) in class.iter_mut().zip(b) {
                    *c ^= x;
                }
            }
        }
        let Some(pivot) = class
            .iter()
            .enumerate()
            .find(|(_, w)| **w != 0)
            .map(|(k, w)| 64 * k + w.trailing_zeros() as usize)
        else {
            return false;
        };
        self.basis.push((pivot, class));
        true
    }
}
