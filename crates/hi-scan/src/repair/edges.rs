// SPDX-License-Identifier: MIT
//! The half-edges of a triangle mesh grouped by vertex: what the repair's steps look up
//! (the face across an edge, the boundary, the faces on each side of an edge), found by a
//! counting sort on the vertices rather than a sort of every half-edge.

/// The half-edges of a triangle list, half-edge 3f + k running from corner k of face f to
/// corner k + 1, bucketed by one end (the first, or the lower for [`EdgeIndex::undirected`]),
/// each bucket sorted by (the other end, half-edge).
#[derive(Debug)]
pub(super) struct EdgeIndex {
    /// Where each vertex's bucket starts in `to`, and where the last one's ends.
    start: Vec<usize>,
    /// (the other end, half-edge) of each half-edge, bucket after bucket.
    to: Vec<(u32, u32)>,
}

impl EdgeIndex {
    /// The half-edges of `faces`, each in the bucket of the vertex it starts from.
    pub(super) fn directed(faces: &[[u32; 3]]) -> Self {
        Self::new(faces, |a, b| (a, b))
    }

    /// The half-edges of `faces`, each in the bucket of its lower end (the two half-edges of
    /// an edge side by side in one bucket).
    pub(super) fn undirected(faces: &[[u32; 3]]) -> Self {
        Self::new(faces, |a, b| (a.min(b), a.max(b)))
    }

    /// The index with each half-edge a → b filed as `ends(a, b)` = (bucket, other end).
    fn new(faces: &[[u32; 3]], ends: impl Fn(u32, u32) -> (u32, u32)) -> Self {
        let n = faces.iter().flatten().max().map_or(0, |&v| v as usize + 1);
        let mut start = vec![0usize; n + 1];
        for t in faces {
            for k in 0..3 {
                start[ends(t[k], t[(k + 1) % 3]).0 as usize + 1] += 1;
            }
        }
        for v in 1..=n {
            start[v] += start[v - 1];
        }
        let mut next = start.clone();
        let mut to = vec![(0u32, 0u32); 3 * faces.len()];
        for (f, t) in faces.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = ends(t[k], t[(k + 1) % 3]);
                let h = u32::try_from(3 * f + k).unwrap_or(u32::MAX);
                to[next[a as usize]] = (b, h);
                next[a as usize] += 1;
            }
        }
        for v in 0..n {
            to[start[v]..start[v + 1]].sort_unstable();
        }
        Self { start, to }
    }

    /// The number of vertices with a bucket (one more than the highest vertex of the faces).
    pub(super) fn vertices(&self) -> usize {
        self.start.len() - 1
    }

    /// The bucket of vertex `v`: (the other end, half-edge), sorted; empty for a vertex
    /// beyond [`EdgeIndex::vertices`].
    pub(super) fn of(&self, v: u32) -> &[(u32, u32)] {
        let v = v as usize;
        if v + 1 < self.start.len() { &self.to[self.start[v]..self.start[v + 1]] } else { &[] }
    }

    /// The first half-edge filed as (a, b) (for [`EdgeIndex::directed`], a half-edge a → b).
    pub(super) fn find(&self, a: u32, b: u32) -> Option<u32> {
        let bucket = self.of(a);
        let i = bucket.partition_point(|&(w, _)| w < b);
        bucket.get(i).filter(|&&(w, _)| w == b).map(|&(_, h)| h)
    }

    /// Each group of half-edges filed under one edge: (lower end, other end, their
    /// half-edges), in the order of (bucket, other end).
    pub(super) fn groups(&self) -> impl Iterator<Item = (u32, u32, &[(u32, u32)])> {
        (0..self.vertices()).flat_map(move |a| {
            let a32 = u32::try_from(a).unwrap_or(u32::MAX);
            self.of(a32).chunk_by(|x, y| x.0 == y.0).map(move |g| (a32, g[0].0, g))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::EdgeIndex;

    /// Two triangles sharing the edge 1–2 (a square split along its diagonal).
    const SQUARE: [[u32; 3]; 2] = [[0, 1, 2], [2, 1, 3]];

    #[test]
    fn the_directed_index_finds_each_half_edge_and_its_face() {
        let index = EdgeIndex::directed(&SQUARE);
        assert_eq!(index.vertices(), 4);
        // Half-edge 3f + k runs from corner k of face f to corner k + 1.
        for (f, t) in SQUARE.iter().enumerate() {
            for k in 0..3 {
                let h = index.find(t[k], t[(k + 1) % 3]).expect("a half-edge of the faces");
                assert_eq!(h as usize, 3 * f + k);
            }
        }
        // 0 → 2 runs the other way round (2 → 0 is a half-edge), 0 → 3 is no edge, 7 no vertex.
        assert_eq!(index.find(0, 2), None);
        assert_eq!(index.find(0, 3), None);
        assert_eq!(index.find(7, 0), None);
        assert_eq!(index.of(1).iter().map(|x| x.0).collect::<Vec<_>>(), vec![2, 3]);
    }

    #[test]
    fn the_undirected_index_pairs_the_two_sides_of_each_edge() {
        let index = EdgeIndex::undirected(&SQUARE);
        let groups: Vec<(u32, u32, Vec<u32>)> =
            index.groups().map(|(a, b, g)| (a, b, g.iter().map(|x| x.1).collect())).collect();
        // Five edges in (lower, upper) order; only 1–2 has two sides: 1 → 2 (face 0, k = 1)
        // and 2 → 1 (face 1, k = 0).
        assert_eq!(
            groups,
            vec![
                (0, 1, vec![0]),
                (0, 2, vec![2]),
                (1, 2, vec![1, 3]),
                (1, 3, vec![4]),
                (2, 3, vec![5]),
            ]
        );
    }
}
