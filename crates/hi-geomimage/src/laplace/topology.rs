// SPDX-License-Identifier: MIT
//! The half-edge connectivity of a triangle mesh.

use hi_par::*;

use super::NONE;
use crate::Error;

/// The half-edges of a triangle mesh: half-edge h = 3f + k runs from corner k of triangle f to
/// corner k + 1 (mod 3).
#[derive(Clone, Debug)]
pub(crate) struct Topology {
    /// The opposite half-edge, or [`NONE`] on the boundary.
    pub(crate) twin: Vec<u32>,
    /// Outgoing half-edges of each vertex: `out[out_start[v]..out_start[v + 1]]` (one per
    /// triangle at v).
    pub(crate) out_start: Vec<u32>,
    pub(crate) out: Vec<u32>,
    /// Half-edges with no twin.
    pub(crate) boundary: Vec<u32>,
}

/// The tail (start vertex) of half-edge h.
pub(crate) fn tail(triangles: &[[u32; 3]], h: u32) -> u32 {
    triangles[(h / 3) as usize][(h % 3) as usize]
}

/// The head (end vertex) of half-edge h.
pub(crate) fn head(triangles: &[[u32; 3]], h: u32) -> u32 {
    triangles[(h / 3) as usize][((h % 3 + 1) % 3) as usize]
}

/// The half-edge before h in its triangle (ending where h starts).
pub(crate) const fn prev(h: u32) -> u32 {
    h - h % 3 + (h % 3 + 2) % 3
}

impl Topology {
    /// The connectivity of `triangles` over `vertex_count` vertices.
    ///
    /// # Errors
    ///
    /// [`Error::Topology`] naming the first problem: an index out of range, a triangle with a
    /// repeated corner, an edge used twice in the same direction (three or more triangles on
    /// an edge, or two wound inconsistently), a vertex in no triangle, or a vertex whose
    /// triangles do not form one fan (two sheets touching at a point).
    pub(crate) fn new(vertex_count: usize, triangles: &[[u32; 3]]) -> Result<Self, Error> {
        check_triangles(vertex_count, triangles)?;
        let (out_start, out) = outgoing_lists(vertex_count, triangles)?;
        let twin = twins(triangles, &out_start, &out)?;
        let boundary: Vec<u32> =
            (0..twin.len() as u32).filter(|&h| twin[h as usize] == NONE).collect();
        let topology = Self { twin, out_start, out, boundary };
        topology.check_fans(vertex_count)?;
        Ok(topology)
    }

    /// The last check of [`Topology::new`]: one fan per vertex (walking around it from one
    /// outgoing half-edge reaches all).
    fn check_fans(&self, vertex_count: usize) -> Result<(), Error> {
        let topo = |what: String| Error::Topology { what };
        for v in 0..vertex_count as u32 {
            let ring = self.outgoing(v);
            let starts = ring.iter().filter(|&&h| self.twin[h as usize] == NONE).count();
            let start = match starts {
                0 => ring[0],
                1 => {
                    ring.iter().copied().find(|&h| self.twin[h as usize] == NONE).unwrap_or(ring[0])
                }
                _ => {
                    return Err(topo(format!(
                        "vertex {v} joins {starts} separate fans of triangles (two sheets touch there)"
                    )));
                }
            };
            let (mut h, mut seen) = (start, 0usize);
            loop {
                seen += 1;
                let next = self.twin[prev(h) as usize];
                if next == NONE || next == start || seen > ring.len() {
                    break;
                }
                h = next;
            }
            if seen != ring.len() {
                return Err(topo(format!(
                    "vertex {v} joins separate fans of triangles (two sheets touch there)"
                )));
            }
        }
        Ok(())
    }

    /// The vertices.
    pub(crate) fn vertex_count(&self) -> usize {
        self.out_start.len() - 1
    }

    /// The outgoing half-edges of v.
    pub(crate) fn outgoing(&self, v: u32) -> &[u32] {
        &self.out[self.out_start[v as usize] as usize..self.out_start[v as usize + 1] as usize]
    }

    /// Edges: half-edges counted once each (a pair of twins once, a boundary half-edge once).
    pub(crate) fn edge_count(&self) -> usize {
        (self.twin.len() + self.boundary.len()) / 2
    }

    /// The Euler characteristic V − E + F.
    pub(crate) fn euler_characteristic(&self) -> i64 {
        self.vertex_count() as i64 - self.edge_count() as i64 + (self.twin.len() / 3) as i64
    }

    /// The number of connected parts (by shared vertices).
    pub(crate) fn components(&self, triangles: &[[u32; 3]]) -> usize {
        let n = self.vertex_count();
        let mut seen = vec![false; n];
        let mut stack = Vec::new();
        let mut parts = 0;
        for s in 0..n as u32 {
            if seen[s as usize] {
                continue;
            }
            parts += 1;
            seen[s as usize] = true;
            stack.push(s);
            while let Some(v) = stack.pop() {
                for &h in self.outgoing(v) {
                    // Both other corners of the triangle: the head of h, and the tail of the
                    // half-edge before it (a boundary vertex's last neighbour is only that).
                    for w in [head(triangles, h), tail(triangles, prev(h))] {
                        if !seen[w as usize] {
                            seen[w as usize] = true;
                            stack.push(w);
                        }
                    }
                }
            }
        }
        parts
    }

    /// The boundary loops, each as its half-edges in order (each ends where the next starts;
    /// the mesh lies to the left of each).
    pub(crate) fn boundary_loops(&self, triangles: &[[u32; 3]]) -> Vec<Vec<u32>> {
        // The one outgoing boundary half-edge of each boundary vertex (one fan per vertex).
        let mut next_of = std::collections::HashMap::with_capacity(self.boundary.len());
        for &h in &self.boundary {
            next_of.insert(tail(triangles, h), h);
        }
        let mut used = std::collections::HashSet::with_capacity(self.boundary.len());
        let mut loops = Vec::new();
        for &h0 in &self.boundary {
            if used.contains(&h0) {
                continue;
            }
            let mut lp = Vec::new();
            let mut h = h0;
            while used.insert(h) {
                lp.push(h);
                match next_of.get(&head(triangles, h)) {
                    Some(&g) => h = g,
                    None => break,
                }
            }
            loops.push(lp);
        }
        loops
    }
}

/// The first checks of [`Topology::new`]: indices fit in 32 bits and are in range, and no
/// triangle repeats a corner.
fn check_triangles(vertex_count: usize, triangles: &[[u32; 3]]) -> Result<(), Error> {
    let topo = |what: String| Error::Topology { what };
    if vertex_count >= NONE as usize || 3 * triangles.len() >= NONE as usize {
        return Err(topo("the mesh is too large for 32-bit indices".to_owned()));
    }
    for (f, t) in triangles.iter().enumerate() {
        if let Some(&k) = t.iter().find(|&&k| k as usize >= vertex_count) {
            return Err(topo(format!(
                "triangle {f} refers to vertex {k}, but there are {vertex_count} vertices"
            )));
        }
        if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] {
            return Err(topo(format!("triangle {f} repeats a vertex ({t:?})")));
        }
    }
    Ok(())
}

/// The outgoing half-edges of each vertex, `out_start` and `out` of [`Topology`]; an error for
/// a vertex in no triangle.
fn outgoing_lists(
    vertex_count: usize,
    triangles: &[[u32; 3]],
) -> Result<(Vec<u32>, Vec<u32>), Error> {
    let mut out_start = vec![0u32; vertex_count + 1];
    for t in triangles {
        for &k in t {
            out_start[k as usize + 1] += 1;
        }
    }
    for v in 0..vertex_count {
        out_start[v + 1] += out_start[v];
    }
    if let Some(v) = (0..vertex_count).find(|&v| out_start[v] == out_start[v + 1]) {
        return Err(Error::Topology { what: format!("vertex {v} is in no triangle") });
    }
    let mut fill = out_start.clone();
    let mut out = vec![0u32; 3 * triangles.len()];
    for (f, t) in triangles.iter().enumerate() {
        for (k, &v) in t.iter().enumerate() {
            out[fill[v as usize] as usize] = (3 * f + k) as u32;
            fill[v as usize] += 1;
        }
    }
    Ok((out_start, out))
}

/// The twin of each half-edge ([`NONE`] on the boundary): half-edge a → b finds b → a among
/// b's outgoing half-edges; a second a → b among a's is an error.
fn twins(triangles: &[[u32; 3]], out_start: &[u32], out: &[u32]) -> Result<Vec<u32>, Error> {
    let outgoing =
        |v: u32| &out[out_start[v as usize] as usize..out_start[v as usize + 1] as usize];
    // A second a → b is marked, then named below.
    const TWICE: u32 = NONE - 1;
    let twin: Vec<u32> = (0..3 * triangles.len() as u32)
        .into_par_iter()
        .with_min_len(4096)
        .map(|h| {
            let (a, b) = (tail(triangles, h), head(triangles, h));
            if outgoing(a).iter().any(|&g| g != h && head(triangles, g) == b) {
                return TWICE;
            }
            outgoing(b).iter().copied().find(|&g| head(triangles, g) == a).unwrap_or(NONE)
        })
        .collect();
    if let Some(h) = twin.iter().position(|&t| t == TWICE) {
        let h = h as u32;
        let (a, b) = (tail(triangles, h), head(triangles, h));
        let g =
            outgoing(a).iter().copied().find(|&g| g != h && head(triangles, g) == b).unwrap_or(h);
        return Err(Error::Topology {
            what: format!(
                "edge ({a}, {b}) is used in the same direction by triangles {} and {}: the mesh is not 2-manifold or not consistently oriented",
                (h / 3).min(g / 3),
                (h / 3).max(g / 3)
            ),
        });
    }
    Ok(twin)
}
