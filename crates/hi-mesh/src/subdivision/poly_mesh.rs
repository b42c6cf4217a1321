// SPDX-License-Identifier: MIT
//! Polygon meshes with half-edge adjacency: the control meshes of the subdivision schemes of
//! Hardy 2005, §4.5.
//!
//! Faces are stored as one flat list of corners; corner `h` of a face is also the half-edge
//! that leaves it, towards the next corner of the face. Each half-edge knows its face, its
//! twin (the opposite half-edge of the neighbouring face, if any) and its undirected edge.
//! Faces wind counter-clockwise about the outward normal, and twins run in opposite
//! directions; [`PolyMesh::try_new`] rejects anything else.

use glam::DVec3;

use crate::Error;
use crate::TriangleMesh;

/// Marks a half-edge without a twin (a boundary edge), or a vertex without faces.
pub(crate) const NONE: u32 = u32::MAX;

/// An oriented 2-manifold polygon mesh (possibly with boundary) with half-edge adjacency.
///
/// Invariants (checked by [`PolyMesh::try_new`]): positions are finite; every face has at
/// least three distinct vertices, all in range; every edge is shared by at most two faces,
/// which traverse it in opposite directions; the faces around each vertex form one fan.
/// Vertices that no face uses are allowed; the schemes keep them where they keep vertices.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_mesh::subdivision::PolyMesh;
///
/// // A square pyramid without its base: four triangles, open at the bottom.
/// let positions = vec![
///     DVec3::new(0.0, 0.0, 1.0),
///     DVec3::new(1.0, 0.0, 0.0),
///     DVec3::new(0.0, 1.0, 0.0),
///     DVec3::new(-1.0, 0.0, 0.0),
///     DVec3::new(0.0, -1.0, 0.0),
/// ];
/// let faces = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]];
/// let mesh = PolyMesh::try_new(positions, &faces)?;
/// assert_eq!((mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()), (5, 8, 4));
/// assert!(!mesh.is_closed());
/// assert_eq!(mesh.valence(0), 4);
/// assert!(mesh.is_boundary_vertex(1) && !mesh.is_boundary_vertex(0));
/// # Ok::<(), hi_mesh::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PolyMesh {
    positions: Vec<DVec3>,
    /// Invariant: `face_start[0] == 0`, increasing by at least 3, last = `corners.len()`.
    face_start: Vec<u32>,
    /// The vertex at each corner (= the origin of the half-edge with the same index).
    corners: Vec<u32>,
    /// The face of each half-edge.
    he_face: Vec<u32>,
    /// The opposite half-edge, or [`NONE`] on the boundary.
    twin: Vec<u32>,
    /// The undirected edge of each half-edge, numbered 0..`n_edges`.
    he_edge: Vec<u32>,
    n_edges: usize,
    /// One outgoing half-edge per vertex, [`NONE`] for unused vertices; for a boundary vertex
    /// the outgoing boundary half-edge, so that the counter-clockwise fan starts there.
    vertex_he: Vec<u32>,
}

impl PolyMesh {
    /// A mesh from vertex positions and faces (lists of vertex indices, counter-clockwise
    /// about the outward normal).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinitePosition`], [`Error::IndexOutOfRange`],
    /// [`Error::TooFewCorners`] or [`Error::RepeatedVertex`] for a face with fewer than 3 corners or
    /// a vertex named twice,
    /// [`Error::NonManifoldEdge`], [`Error::InconsistentOrientation`],
    /// [`Error::NonManifoldVertex`], [`Error::TooLarge`]; each names the first
    /// offending vertex, face or edge.
    pub fn try_new<F: AsRef<[u32]>>(positions: Vec<DVec3>, faces: &[F]) -> Result<Self, Error> {
        if let Some(vertex) = positions.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePosition { vertex });
        }
        let n_corners: usize = faces.iter().map(|f| f.as_ref().len()).sum();
        let mut corners = Vec::with_capacity(n_corners);
        let mut face_start = Vec::with_capacity(faces.len() + 1);
        face_start.push(0);
        for (face, f) in faces.iter().enumerate() {
            let f = f.as_ref();
            if f.len() < 3 {
                return Err(Error::TooFewCorners { face, corners: f.len() });
            }
            for (i, &k) in f.iter().enumerate() {
                if k as usize >= positions.len() {
                    return Err(Error::IndexOutOfRange {
                        face,
                        index: k as usize,
                        n_vertices: positions.len(),
                    });
                }
                if f[..i].contains(&k) {
                    return Err(Error::RepeatedVertex { face, vertex: k });
                }
            }
            corners.extend_from_slice(f);
            let end = u32::try_from(corners.len())
                .ok()
                .filter(|&e| e != NONE)
                .ok_or(Error::TooLarge { what: "face corners", count: n_corners })?;
            face_start.push(end);
        }
        Self::from_parts(positions, face_start, corners)
    }

    /// Builds the adjacency of checked faces (every face ≥ 3 distinct in-range vertices).
    pub(crate) fn from_parts(
        positions: Vec<DVec3>,
        face_start: Vec<u32>,
        corners: Vec<u32>,
    ) -> Result<Self, Error> {
        if positions.len() >= NONE as usize {
            return Err(Error::TooLarge { what: "vertices", count: positions.len() });
        }
        let n_he = corners.len();
        let n_faces = face_start.len() - 1;
        let mut he_face = vec![0_u32; n_he];
        for f in 0..n_faces {
            for h in face_start[f]..face_start[f + 1] {
                he_face[h as usize] = f as u32;
            }
        }
        let mut mesh = PolyMesh {
            positions,
            face_start,
            corners,
            he_face,
            twin: vec![NONE; n_he],
            he_edge: vec![NONE; n_he],
            n_edges: 0,
            vertex_he: Vec::new(),
        };
        // Pair half-edges by the undirected edge (min, max); edges are numbered in (min, max)
        // order.
        let keys = mesh.edge_keys();
        mesh.pair_half_edges(&keys)?;
        // One outgoing half-edge per vertex, the boundary one where there is one.
        let mut vertex_he = vec![NONE; mesh.positions.len()];
        let mut n_out = vec![0_u32; mesh.positions.len()];
        for h in 0..n_he as u32 {
            let v = mesh.corners[h as usize] as usize;
            n_out[v] += 1;
            if vertex_he[v] == NONE || mesh.twin[h as usize] == NONE {
                if mesh.twin[h as usize] == NONE
                    && vertex_he[v] != NONE
                    && mesh.twin[vertex_he[v] as usize] == NONE
                {
                    return Err(Error::NonManifoldVertex { vertex: v });
                }
                vertex_he[v] = h;
            }
        }
        mesh.vertex_he = vertex_he;
        // Each vertex's fan must reach all of its outgoing half-edges.
        for (v, &n) in n_out.iter().enumerate() {
            if mesh.vertex_he[v] != NONE && mesh.fan(v as u32).count() != n as usize {
                return Err(Error::NonManifoldVertex { vertex: v });
            }
        }
        Ok(mesh)
    }

    /// The first stage of pairing in [`PolyMesh::from_parts`]: each half-edge keyed by its
    /// undirected edge (min, max), sorted by key: a counting sort on min (linear), then a sort
    /// on max inside each vertex's small bucket.
    fn edge_keys(&self) -> Vec<(u64, u32)> {
        let n_vertices = self.positions.len();
        let (n_he, n_faces) = (self.corners.len(), self.face_start.len() - 1);
        // The head of every half-edge, in one pass over the faces.
        let mut head = vec![0_u32; n_he];
        for f in 0..n_faces {
            let (start, end) = (self.face_start[f] as usize, self.face_start[f + 1] as usize);
            for (i, out) in head[start..end].iter_mut().enumerate() {
                let next = if start + i + 1 == end { start } else { start + i + 1 };
                *out = self.corners[next];
            }
        }
        let ends = |h: u32| {
            let (a, b) = (self.corners[h as usize], head[h as usize]);
            (a.min(b), a.max(b))
        };
        let mut bucket_start = vec![0_u32; n_vertices + 1];
        for h in 0..n_he as u32 {
            bucket_start[ends(h).0 as usize + 1] += 1;
        }
        for v in 0..n_vertices {
            bucket_start[v + 1] += bucket_start[v];
        }
        let mut fill = bucket_start[..n_vertices].to_vec();
        // (other end, half-edge) in buckets by the lower end, so that the small sorts inside
        // the buckets read contiguous memory.
        let mut order = vec![(0_u32, 0_u32); n_he];
        for h in 0..n_he as u32 {
            let (lo, hi) = ends(h);
            order[fill[lo as usize] as usize] = (hi, h);
            fill[lo as usize] += 1;
        }
        let mut keys: Vec<(u64, u32)> = Vec::with_capacity(n_he);
        for v in 0..n_vertices {
            let bucket = &mut order[bucket_start[v] as usize..bucket_start[v + 1] as usize];
            if bucket.len() > 1 {
                bucket.sort_unstable();
            }
            keys.extend(bucket.iter().map(|&(hi, h)| (((v as u64) << 32) | u64::from(hi), h)));
        }
        keys
    }

    /// The second stage of pairing in [`PolyMesh::from_parts`]: half-edges of one key made
    /// twins and numbered as one edge, in key order; an error for an edge of three or more
    /// faces or two wound the same way.
    fn pair_half_edges(&mut self, keys: &[(u64, u32)]) -> Result<(), Error> {
        let mut i = 0;
        let mut n_edges = 0_u32;
        while i < keys.len() {
            let mut j = i + 1;
            while j < keys.len() && keys[j].0 == keys[i].0 {
                j += 1;
            }
            let group = &keys[i..j];
            if group.len() > 2 {
                let mut faces: Vec<usize> =
                    group.iter().map(|&(_, h)| self.he_face[h as usize] as usize).collect();
                faces.sort_unstable();
                let key = group[0].0;
                return Err(Error::NonManifoldEdge {
                    edge: [(key >> 32) as u32, key as u32],
                    faces,
                });
            }
            if let [(_, h0), (_, h1)] = *group {
                if self.from(h0) == self.from(h1) {
                    let (f0, f1) = (self.he_face[h0 as usize], self.he_face[h1 as usize]);
                    return Err(Error::InconsistentOrientation {
                        edge: [self.from(h0), self.to(h0)],
                        faces: [f0.min(f1) as usize, f0.max(f1) as usize],
                    });
                }
                self.twin[h0 as usize] = h1;
                self.twin[h1 as usize] = h0;
            }
            for &(_, h) in group {
                self.he_edge[h as usize] = n_edges;
            }
            n_edges += 1;
            i = j;
        }
        self.n_edges = n_edges as usize;
        Ok(())
    }

    /// A mesh whose half-edge twins are already known: what a subdivision step builds from a
    /// valid mesh, whose new faces and their twins follow from the old ones by index
    /// arithmetic. Skips the pairing of half-edges by sorting and the manifold checks of
    /// [`PolyMesh::from_parts`] (a refinement of a valid mesh is valid), and gives the same
    /// mesh: edges numbered in (lower vertex, higher vertex) order, the same outgoing
    /// half-edge per vertex. The tests of every scheme check it against
    /// [`PolyMesh::try_new`] on the same faces.
    ///
    /// `twin[h]` is the opposite half-edge of corner `h`, or [`NONE`] on the boundary; the
    /// caller guarantees that twins are mutual and run in opposite directions.
    pub(crate) fn from_twins(
        positions: Vec<DVec3>,
        face_start: Vec<u32>,
        corners: Vec<u32>,
        twin: Vec<u32>,
    ) -> Result<Self, Error> {
        if positions.len() >= NONE as usize {
            return Err(Error::TooLarge { what: "vertices", count: positions.len() });
        }
        if corners.len() >= NONE as usize {
            return Err(Error::TooLarge { what: "face corners", count: corners.len() });
        }
        let n_he = corners.len();
        let n_faces = face_start.len() - 1;
        debug_assert_eq!(twin.len(), n_he, "one twin per half-edge");
        let mut he_face = vec![0_u32; n_he];
        // Each edge once, at its canonical half-edge (the one that runs upwards, or the only
        // one), in buckets by its lower vertex: counted in one pass over the faces, filled
        // with (higher vertex, half-edge) in a second.
        let canonical = |h: usize, next: usize| {
            let (a, b) = (corners[h], corners[next]);
            (twin[h] == NONE || a < b).then(|| (a.min(b), a.max(b)))
        };
        let mut bucket_start = vec![0_u32; positions.len() + 1];
        for f in 0..n_faces {
            let (start, end) = (face_start[f] as usize, face_start[f + 1] as usize);
            he_face[start..end].fill(f as u32);
            for h in start..end {
                if let Some((lo, _)) = canonical(h, if h + 1 == end { start } else { h + 1 }) {
                    bucket_start[lo as usize + 1] += 1;
                }
            }
        }
        for v in 0..positions.len() {
            bucket_start[v + 1] += bucket_start[v];
        }
        let n_edges = bucket_start[positions.len()] as usize;
        let mut fill = bucket_start[..positions.len()].to_vec();
        let mut order = vec![(0_u32, 0_u32); n_edges];
        for f in 0..n_faces {
            let (start, end) = (face_start[f] as usize, face_start[f + 1] as usize);
            for h in start..end {
                if let Some((lo, hi)) = canonical(h, if h + 1 == end { start } else { h + 1 }) {
                    let slot = &mut fill[lo as usize];
                    order[*slot as usize] = (hi, h as u32);
                    *slot += 1;
                }
            }
        }
        let mut he_edge = vec![NONE; n_he];
        for v in 0..positions.len() {
            let bucket = &mut order[bucket_start[v] as usize..bucket_start[v + 1] as usize];
            if bucket.len() > 1 {
                bucket.sort_unstable();
            }
        }
        for (e, &(_, h)) in order.iter().enumerate() {
            he_edge[h as usize] = e as u32;
            let t = twin[h as usize];
            if t != NONE {
                debug_assert_eq!(twin[t as usize], h, "twins are mutual");
                he_edge[t as usize] = e as u32;
            }
        }
        // One outgoing half-edge per vertex, the boundary one where there is one (as in
        // `from_parts`).
        let mut vertex_he = vec![NONE; positions.len()];
        for (h, (&v, &t)) in corners.iter().zip(&twin).enumerate() {
            let slot = &mut vertex_he[v as usize];
            if *slot == NONE || t == NONE {
                *slot = h as u32;
            }
        }
        Ok(PolyMesh { positions, face_start, corners, he_face, twin, he_edge, n_edges, vertex_he })
    }

    /// The vertex positions.
    #[must_use]
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// The number of vertices.
    #[must_use]
    pub fn n_vertices(&self) -> usize {
        self.positions.len()
    }

    /// The number of faces.
    #[must_use]
    pub fn n_faces(&self) -> usize {
        self.face_start.len() - 1
    }

    /// The number of (undirected) edges.
    #[must_use]
    pub fn n_edges(&self) -> usize {
        self.n_edges
    }

    /// The vertex indices of face `f`, counter-clockwise.
    ///
    /// # Panics
    ///
    /// If `f >= self.n_faces()`.
    #[must_use]
    pub fn face(&self, f: usize) -> &[u32] {
        &self.corners[self.face_start[f] as usize..self.face_start[f + 1] as usize]
    }

    /// The faces in order, each as its vertex indices.
    pub fn faces(&self) -> impl ExactSizeIterator<Item = &[u32]> + '_ {
        (0..self.n_faces()).map(|f| self.face(f))
    }

    /// Whether every edge has two faces (no boundary).
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.twin.iter().all(|&t| t != NONE)
    }

    /// The boundary edges (from, to), each in the direction of its face.
    #[must_use]
    pub fn boundary_edges(&self) -> Vec<[u32; 2]> {
        (0..self.twin.len() as u32)
            .filter(|&h| self.twin[h as usize] == NONE)
            .map(|h| [self.from(h), self.to(h)])
            .collect()
    }

    /// Whether vertex `v` lies on the boundary (false for a vertex without faces).
    ///
    /// # Panics
    ///
    /// If `v >= self.n_vertices()`.
    #[must_use]
    pub fn is_boundary_vertex(&self, v: usize) -> bool {
        let h = self.vertex_he[v];
        h != NONE && self.twin[h as usize] == NONE
    }

    /// The number of edges at vertex `v`.
    ///
    /// # Panics
    ///
    /// If `v >= self.n_vertices()`.
    #[must_use]
    pub fn valence(&self, v: usize) -> usize {
        let n_fan = self.fan(v as u32).count();
        n_fan + usize::from(self.is_boundary_vertex(v))
    }

    /// The neighbours of vertex `v`, counter-clockwise about the outward normal; for a boundary
    /// vertex, from one boundary neighbour (the head of the outgoing boundary edge) to the
    /// other.
    ///
    /// # Panics
    ///
    /// If `v >= self.n_vertices()`.
    #[must_use]
    pub fn neighbors(&self, v: usize) -> Vec<u32> {
        let mut res = Vec::new();
        self.ring_into(v as u32, &mut res);
        res
    }

    /// The vertex positions replaced (same connectivity); the caller passes one finite
    /// position per vertex.
    fn with_positions(mut self, positions: Vec<DVec3>) -> Result<Self, Error> {
        if let Some(vertex) = positions.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePosition { vertex });
        }
        self.positions = positions;
        Ok(self)
    }

    /// The mesh with every vertex mapped by `f` (e.g. an affine map).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinitePosition`] if `f` gives a non-finite point.
    pub fn try_map_positions(&self, f: impl Fn(DVec3) -> DVec3) -> Result<Self, Error> {
        self.clone().with_positions(self.positions.iter().map(|&p| f(p)).collect())
    }

    /// A triangle mesh for the export path of [`crate::export`]: each face is split into a
    /// fan from its first corner, and each vertex normal is the area-weighted mean of the
    /// normals of its triangles (+z where that vanishes). UVs are zero.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] if the mesh has no faces.
    pub fn to_triangle_mesh(&self) -> Result<TriangleMesh, Error> {
        let mut triangles = Vec::with_capacity(self.corners.len());
        for face in self.faces() {
            for i in 1..face.len() - 1 {
                triangles.push([face[0], face[i], face[i + 1]]);
            }
        }
        let normals =
            crate::triangle_mesh::area_weighted_normals(&self.positions, triangles.iter().copied());
        let uvs = vec![glam::DVec2::ZERO; self.positions.len()];
        TriangleMesh::try_new(self.positions.clone(), normals, uvs, triangles)
    }

    // ---- half-edge navigation (crate-internal) ----

    /// The first half-edge (corner) of face `f`.
    #[inline]
    pub(crate) fn face_he(&self, f: usize) -> u32 {
        self.face_start[f]
    }

    /// The face of half-edge `h`.
    #[inline]
    pub(crate) fn he_face(&self, h: u32) -> u32 {
        self.he_face[h as usize]
    }

    /// The undirected edge of half-edge `h`.
    #[inline]
    pub(crate) fn he_edge(&self, h: u32) -> u32 {
        self.he_edge[h as usize]
    }

    /// The next half-edge in the face of `h`.
    #[inline]
    pub(crate) fn next(&self, h: u32) -> u32 {
        let f = self.he_face[h as usize] as usize;
        if h + 1 == self.face_start[f + 1] { self.face_start[f] } else { h + 1 }
    }

    /// The previous half-edge in the face of `h`.
    #[inline]
    pub(crate) fn prev(&self, h: u32) -> u32 {
        let f = self.he_face[h as usize] as usize;
        if h == self.face_start[f] { self.face_start[f + 1] - 1 } else { h - 1 }
    }

    /// The twin of `h`, or [`NONE`].
    #[inline]
    pub(crate) fn twin(&self, h: u32) -> u32 {
        self.twin[h as usize]
    }

    /// The vertex `h` leaves.
    #[inline]
    pub(crate) fn from(&self, h: u32) -> u32 {
        self.corners[h as usize]
    }

    /// The vertex `h` enters.
    #[inline]
    pub(crate) fn to(&self, h: u32) -> u32 {
        self.corners[self.next(h) as usize]
    }

    /// The half-edges (corners) of face `f`: `start..end`.
    #[inline]
    pub(crate) fn face_range(&self, f: usize) -> (u32, u32) {
        (self.face_start[f], self.face_start[f + 1])
    }

    /// For every vertex, the sum of the positions at the heads of its outgoing half-edges and
    /// their number: its neighbours' sum and valence for an interior vertex (one neighbour
    /// short on the boundary). One pass over the faces, with no walk around the vertices.
    pub(crate) fn neighbour_sums(&self) -> (Vec<DVec3>, Vec<u32>) {
        let p = &self.positions;
        let mut sum = vec![DVec3::ZERO; p.len()];
        let mut count = vec![0_u32; p.len()];
        for f in 0..self.n_faces() {
            let (start, end) = self.face_range(f);
            for h in start..end {
                let next = if h + 1 == end { start } else { h + 1 };
                let v = self.corners[h as usize] as usize;
                sum[v] += p[self.corners[next as usize] as usize];
                count[v] += 1;
            }
        }
        (sum, count)
    }

    /// The number of corners of the face of `h`.
    #[inline]
    pub(crate) fn face_len(&self, f: usize) -> usize {
        (self.face_start[f + 1] - self.face_start[f]) as usize
    }

    /// The outgoing half-edges of `v`, counter-clockwise (h → twin(prev(h))), starting at the
    /// boundary one for a boundary vertex.
    pub(crate) fn fan(&self, v: u32) -> Fan<'_> {
        let start = self.vertex_he[v as usize];
        Fan { mesh: self, start, cur: start }
    }

    /// The neighbours of `v` counter-clockwise into `out` (cleared first); returns whether `v`
    /// is a boundary vertex.
    pub(crate) fn ring_into(&self, v: u32, out: &mut Vec<u32>) -> bool {
        out.clear();
        let mut last = NONE;
        for h in self.fan(v) {
            out.push(self.to(h));
            last = h;
        }
        let boundary = self.is_boundary_vertex(v as usize);
        if boundary {
            out.push(self.from(self.prev(last)));
        }
        boundary
    }

    /// The first half-edge without a twin, as an error for `scheme`, if the mesh is open.
    pub(crate) fn require_closed(&self, scheme: &'static str) -> Result<(), Error> {
        match self.twin.iter().position(|&t| t == NONE) {
            None => Ok(()),
            Some(h) => {
                let h = h as u32;
                Err(Error::OpenMesh { scheme, edge: [self.from(h), self.to(h)] })
            }
        }
    }

    /// An error for `scheme` naming the first face that is not a triangle.
    pub(crate) fn require_triangles(&self, scheme: &'static str) -> Result<(), Error> {
        match (0..self.n_faces()).find(|&f| self.face_len(f) != 3) {
            None => Ok(()),
            Some(face) => Err(Error::WrongPrimitive {
                scheme,
                face,
                n_sides: self.face_len(face),
                expected: "a triangle mesh",
            }),
        }
    }

    /// The total number of half-edges (face corners).
    #[inline]
    pub(crate) fn n_halfedges(&self) -> usize {
        self.corners.len()
    }
}

/// The outgoing half-edges of a vertex, counter-clockwise; see [`PolyMesh::fan`].
#[derive(Clone, Debug)]
pub(crate) struct Fan<'a> {
    mesh: &'a PolyMesh,
    start: u32,
    cur: u32,
}

impl Iterator for Fan<'_> {
    type Item = u32;

    fn next(&mut self) -> Option<u32> {
        if self.cur == NONE {
            return None;
        }
        let h = self.cur;
        let t = self.mesh.twin(self.mesh.prev(h));
        self.cur = if t == self.start { NONE } else { t };
        Some(h)
    }
}

/// The counter-clockwise one-rings of all vertices, in compressed rows.
#[derive(Clone, Debug)]
pub(crate) struct Rings {
    start: Vec<u32>,
    verts: Vec<u32>,
    boundary: Vec<bool>,
}

impl Rings {
    /// The rings of every vertex of `mesh`.
    pub(crate) fn new(mesh: &PolyMesh) -> Self {
        let n = mesh.n_vertices();
        let mut start = Vec::with_capacity(n + 1);
        let mut verts = Vec::with_capacity(mesh.n_halfedges() + n);
        let mut boundary = Vec::with_capacity(n);
        let mut buf = Vec::new();
        start.push(0);
        for v in 0..n as u32 {
            boundary.push(mesh.ring_into(v, &mut buf));
            verts.extend_from_slice(&buf);
            start.push(verts.len() as u32);
        }
        Rings { start, verts, boundary }
    }

    /// The ring of `v`.
    #[inline]
    pub(crate) fn ring(&self, v: u32) -> &[u32] {
        &self.verts[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }

    /// Whether `v` is on the boundary.
    #[inline]
    pub(crate) fn is_boundary(&self, v: u32) -> bool {
        self.boundary[v as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetra() -> PolyMesh {
        let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
        PolyMesh::try_new(p, &[[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]]).expect("tetrahedron")
    }

    #[test]
    fn tetrahedron_adjacency() {
        let m = tetra();
        assert!(m.is_closed());
        assert_eq!(m.n_edges(), 6);
        for v in 0..4 {
            assert_eq!(m.valence(v), 3);
            let ring = m.neighbors(v);
            assert_eq!(ring.len(), 3);
        }
        for h in 0..m.n_halfedges() as u32 {
            let t = m.twin(h);
            assert_eq!(m.twin(t), h);
            assert_eq!((m.from(t), m.to(t)), (m.to(h), m.from(h)));
            assert_eq!(m.next(m.prev(h)), h);
        }
    }

    #[test]
    fn ring_is_counter_clockwise() {
        // Vertex 3 = apex (0,0,1) seen from above: neighbours 0 (origin), 1 (x), 2 (y).
        let m = tetra();
        let ring = m.neighbors(3);
        let p = |k: u32| m.positions()[k as usize];
        let apex = p(3);
        let n = (p(ring[0]) - apex).cross(p(ring[1]) - apex);
        // Outward normal at the apex points away from the centroid.
        assert!(n.dot(apex - DVec3::splat(0.25)) > 0.0, "ring {ring:?}");
    }
}
