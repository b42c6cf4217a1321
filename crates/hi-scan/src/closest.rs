// SPDX-License-Identifier: MIT
//! Closest points on a triangle mesh: a bounding-volume hierarchy over the triangles, queried
//! best first, exact (the closest point of the closest triangle, by Ericson's point–triangle
//! test, [`crate::distance::closest_point_on_triangle`]).
//!
//! The triangles are ordered along a Morton (Z-order) curve through their centroids, and the
//! hierarchy halves that order down to leaves of at most four (a linear BVH: building is one
//! sort of integer keys and one pass for the boxes); a query visits the nearer child first
//! and skips every box farther than the best distance found so far, about O(log T) for a
//! point near the mesh.

use glam::DVec3;
use hi_par::*;

use crate::distance::closest_point_on_triangle;
use crate::{Error, NonFiniteInput};

/// Triangles per leaf at most.
const LEAF: usize = 4;

#[derive(Clone, Copy, Debug)]
struct Node {
    lo: DVec3,
    hi: DVec3,
    /// A leaf: the first of its `count` triangles; an inner node: its left child (the right
    /// child follows the left child's subtree).
    start: u32,
    /// Triangles in a leaf; 0 for an inner node, whose right child is `right`.
    count: u32,
    right: u32,
}

/// The closest point of a mesh to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Closest {
    /// The point on the mesh.
    pub point: DVec3,
    /// Its distance from the query.
    pub distance: f64,
    /// The index of the triangle it lies on.
    pub triangle: u32,
}

/// A bounding-volume hierarchy over a triangle mesh for closest-point queries.
#[derive(Clone, Debug)]
pub struct TriangleBvh {
    nodes: Vec<Node>,
    /// The triangles' corners, in the order of the leaves.
    corners: Vec<[DVec3; 3]>,
    /// The input index of each triangle in that order.
    index: Vec<u32>,
}

impl TriangleBvh {
    /// The hierarchy over the triangles (`vertices`, `triangles`).
    ///
    /// # Errors
    ///
    /// [`Error::TooFewPoints`] for no triangle; [`Error::InvalidOption`] for an index out of
    /// range; [`Error::NonFinite`] for a non-finite vertex.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_scan::closest::TriangleBvh;
    ///
    /// let v = [DVec3::ZERO, DVec3::X, DVec3::Y];
    /// let bvh = TriangleBvh::try_new(&v, &[[0, 1, 2]]).unwrap();
    /// let c = bvh.closest(DVec3::new(0.25, 0.25, 2.0));
    /// assert_eq!(c.point, DVec3::new(0.25, 0.25, 0.0));
    /// assert_eq!(c.distance, 2.0);
    /// ```
    pub fn try_new(vertices: &[DVec3], triangles: &[[u32; 3]]) -> Result<Self, Error> {
        check_mesh(vertices, triangles)?;
        let corners: Vec<[DVec3; 3]> =
            triangles.iter().map(|t| t.map(|k| vertices[k as usize])).collect();
        let centroids: Vec<DVec3> = corners.iter().map(|c| (c[0] + c[1] + c[2]) / 3.0).collect();
        let (lo, hi) = centroids
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), c| (lo.min(*c), hi.max(*c)));
        let scale = 1023.0 / (hi - lo).max_element().max(f64::MIN_POSITIVE);
        let mut keys: Vec<u64> = centroids
            .iter()
            .enumerate()
            .map(|(t, c)| {
                let q = ((*c - lo) * scale).round();
                #[expect(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "in 0..=1023"
                )]
                let m = morton(q.x as u32, q.y as u32, q.z as u32);
                (u64::from(m) << 32) | t as u64
            })
            .collect();
        keys.sort_unstable();
        let order: Vec<u32> = keys.iter().map(|k| (k & 0xffff_ffff) as u32).collect();
        let codes: Vec<u32> = keys.iter().map(|k| (k >> 32) as u32).collect();
        let sorted: Vec<[DVec3; 3]> = order.iter().map(|&t| corners[t as usize]).collect();
        let mut nodes = Vec::with_capacity(2 * triangles.len() / LEAF + 2);
        build(&mut nodes, &sorted, &codes, 0, sorted.len());
        Ok(Self { nodes, corners: sorted, index: order })
    }

    /// The closest point of the mesh to `p`.
    #[must_use]
    pub fn closest(&self, p: DVec3) -> Closest {
        self.closest_from(p, None).0
    }

    /// The closest point of the mesh to `p`, the search bounded from the start by the distance
    /// to triangle `hint` (in the leaves' order) when given: for a query near the previous one,
    /// its closest triangle is close too, and most boxes are skipped at once. Returns the
    /// closest point and its triangle in the leaves' order.
    fn closest_from(&self, p: DVec3, hint: Option<u32>) -> (Closest, u32) {
        let mut best = Closest { point: p, distance: f64::INFINITY, triangle: 0 };
        let mut best2 = f64::INFINITY;
        let mut best_t = 0;
        if let Some(t) = hint {
            let [a, b, c] = self.corners[t as usize];
            let q = closest_point_on_triangle(p, a, b, c);
            best2 = q.distance_squared(p);
            best = Closest { point: q, distance: 0.0, triangle: self.index[t as usize] };
            best_t = t;
        }
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = self.nodes[stack[top] as usize];
            if box_distance2(p, node.lo, node.hi) >= best2 {
                continue;
            }
            if node.count > 0 {
                for t in node.start..node.start + node.count {
                    let [a, b, c] = self.corners[t as usize];
                    let q = closest_point_on_triangle(p, a, b, c);
                    let d2 = q.distance_squared(p);
                    if d2 < best2 {
                        best2 = d2;
                        best =
                            Closest { point: q, distance: 0.0, triangle: self.index[t as usize] };
                        best_t = t;
                    }
                }
            } else {
                let (l, r) = (node.start, node.right);
                let dl = {
                    let c = self.nodes[l as usize];
                    box_distance2(p, c.lo, c.hi)
                };
                let dr = {
                    let c = self.nodes[r as usize];
                    box_distance2(p, c.lo, c.hi)
                };
                // The nearer child is visited first (pushed last); a child beyond the best
                // distance is not pushed at all. Each level splits on one of the 30 Morton bits
                // or halves a range of equal codes (at most 30 times for 2³² triangles), so
                // the tree is at most 60 levels deep and the stack, one node more per level,
                // holds at most 61.
                let (near, far, d_far) = if dl < dr { (l, r, dr) } else { (r, l, dl) };
                if d_far < best2 {
                    stack[top] = far;
                    top += 1;
                }
                stack[top] = near;
                top += 1;
            }
        }
        best.distance = best2.sqrt();
        (best, best_t)
    }

    /// The distance from each of `points` to the mesh, in parallel. Consecutive points are
    /// best near each other (a grid, a mesh's vertices in order): each query starts from the
    /// previous one's triangle.
    #[must_use]
    pub fn distances(&self, points: &[DVec3]) -> Vec<f64> {
        let mut out = vec![0.0; points.len()];
        out.par_chunks_mut(256).zip(points.par_chunks(256)).for_each(|(out, points)| {
            let mut hint = None;
            for (d, p) in out.iter_mut().zip(points) {
                let (c, t) = self.closest_from(*p, hint);
                *d = c.distance;
                hint = Some(t);
            }
        });
        out
    }
}

/// At least one triangle, every index in range, every vertex finite.
fn check_mesh(vertices: &[DVec3], triangles: &[[u32; 3]]) -> Result<(), Error> {
    if triangles.is_empty() {
        return Err(Error::TooFewPoints { found: 0, needed: 1 });
    }
    if let Some(&k) = triangles.iter().flatten().find(|&&k| k as usize >= vertices.len()) {
        return Err(Error::InvalidOption {
            name: "triangle index",
            value: f64::from(k),
            expected: "below the vertex count",
        });
    }
    if let Some(k) = vertices.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinite { what: NonFiniteInput::Vertex(k) });
    }
    Ok(())
}

fn box_distance2(p: DVec3, lo: DVec3, hi: DVec3) -> f64 {
    let d = (lo - p).max(p - hi).max(DVec3::ZERO);
    d.length_squared()
}

/// Spreads the 10 low bits of x to every third bit.
fn spread(mut x: u32) -> u32 {
    x &= 0x3ff;
    x = (x | (x << 16)) & 0x0300_00ff;
    x = (x | (x << 8)) & 0x0300_f00f;
    x = (x | (x << 4)) & 0x030c_30c3;
    (x | (x << 2)) & 0x0924_9249
}

/// The 30-bit Morton code of a point of the 1024³ grid.
fn morton(x: u32, y: u32, z: u32) -> u32 {
    spread(x) | (spread(y) << 1) | (spread(z) << 2)
}

/// Builds the subtree over the triangles `start..end` (in the Morton order, with their
/// `codes`) and returns its node index: split where the highest bit in which the range's
/// codes differ turns from 0 to 1 (a plane of the Morton grid), or in the middle when they
/// are all equal.
fn build(
    nodes: &mut Vec<Node>,
    corners: &[[DVec3; 3]],
    codes: &[u32],
    start: usize,
    end: usize,
) -> u32 {
    let me = nodes.len() as u32;
    nodes.push(Node { lo: DVec3::ZERO, hi: DVec3::ZERO, start: start as u32, count: 0, right: 0 });
    if end - start <= LEAF {
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for c in corners[start..end].iter().flatten() {
            lo = lo.min(*c);
            hi = hi.max(*c);
        }
        nodes[me as usize] =
            Node { lo, hi, start: start as u32, count: (end - start) as u32, right: 0 };
        return me;
    }
    let (first, last) = (codes[start], codes[end - 1]);
    let mid = if first == last {
        start + (end - start) / 2
    } else {
        let bit = 31 - (first ^ last).leading_zeros();
        start + codes[start..end].partition_point(|c| c >> bit & 1 == 0)
    };
    let l = build(nodes, corners, codes, start, mid);
    let r = build(nodes, corners, codes, mid, end);
    let (a, b) = (nodes[l as usize], nodes[r as usize]);
    nodes[me as usize] =
        Node { lo: a.lo.min(b.lo), hi: a.hi.max(b.hi), start: l, count: 0, right: r };
    me
}

/// Fast distances to a triangle mesh: a kd-tree over its vertices, and for a query the
/// closest point on the triangles around its nearest vertex.
///
/// That is the exact closest point whenever it lies on a triangle around that vertex, as it
/// nearly always does for a point on or near a mesh of well-shaped triangles (the fitted
/// surfaces' meshes, scans); otherwise the distance found is an upper bound, by at most the
/// size of a triangle. [`TriangleBvh`] is exact for every point, and slower.
#[derive(Debug)]
pub struct NearMesh {
    tree: kiddo::ImmutableKdTree<f64, 3>,
    vertices: Vec<DVec3>,
    /// Triangles around vertex v: `around[start[v]..start[v + 1]]`.
    start: Vec<u32>,
    around: Vec<u32>,
    triangles: Vec<[u32; 3]>,
}

impl NearMesh {
    /// The structure over the mesh (`vertices`, `triangles`).
    ///
    /// # Errors
    ///
    /// As [`TriangleBvh::try_new`].
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_scan::closest::NearMesh;
    ///
    /// let v = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE];
    /// let near = NearMesh::try_new(&v, &[[0, 1, 2], [1, 3, 2]]).unwrap();
    /// assert_eq!(near.distance(DVec3::new(0.25, 0.25, -3.0)), 3.0);
    /// ```
    pub fn try_new(vertices: &[DVec3], triangles: &[[u32; 3]]) -> Result<Self, Error> {
        check_mesh(vertices, triangles)?;
        let tree = kiddo::ImmutableKdTree::new_from_slice(crate::distance::as_arrays(vertices))
            .map_err(|_| Error::Degenerate { what: "the vertices do not form a kd-tree" })?;
        let mut start = vec![0u32; vertices.len() + 1];
        for t in triangles {
            for &k in t {
                start[k as usize + 1] += 1;
            }
        }
        for v in 0..vertices.len() {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut around = vec![0u32; start[vertices.len()] as usize];
        for (f, t) in triangles.iter().enumerate() {
            for &k in t {
                around[fill[k as usize] as usize] = u32::try_from(f).unwrap_or(u32::MAX);
                fill[k as usize] += 1;
            }
        }
        Ok(Self { tree, vertices: vertices.to_vec(), start, around, triangles: triangles.to_vec() })
    }

    /// The closest point to `p` on the triangles around its nearest vertex (see the type's
    /// documentation); for a vertex no triangle uses, that vertex, on triangle `u32::MAX`.
    #[must_use]
    pub fn closest(&self, p: DVec3) -> Closest {
        let nearest =
            self.tree.query(&p.to_array()).nearest_one::<kiddo::SquaredEuclidean<f64>>().execute();
        let v = nearest.item as usize;
        // Every triangle around v holds v, so its closest point is no farther than v.
        let mut best = (nearest.distance, self.vertices[v], u32::MAX);
        for &f in &self.around[self.start[v] as usize..self.start[v + 1] as usize] {
            let [a, b, c] = self.triangles[f as usize].map(|x| self.vertices[x as usize]);
            let q = closest_point_on_triangle(p, a, b, c);
            let d = q.distance_squared(p);
            if best.2 == u32::MAX || d < best.0 {
                best = (d, q, f);
            }
        }
        Closest { point: best.1, distance: best.0.sqrt(), triangle: best.2 }
    }

    /// The distance from `p` to the mesh (see the type's documentation).
    #[must_use]
    pub fn distance(&self, p: DVec3) -> f64 {
        self.closest(p).distance
    }

    /// The distance from each of `points` to the mesh, in parallel.
    #[must_use]
    pub fn distances(&self, points: &[DVec3]) -> Vec<f64> {
        points.par_iter().with_min_len(256).map(|p| self.distance(*p)).collect()
    }
}
