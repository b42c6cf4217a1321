// SPDX-License-Identifier: MIT
//! Steps 5 and 6 of the repair: pinched vertices split into one vertex per fan, and holes
//! found and closed by faired rings of triangles.

use glam::DVec3;
use hi_par::*;

use super::band::ArrowBand;
use super::edges::EdgeIndex;
use super::{ADDED_VERTEX, Repair};

/// Splits every vertex whose triangles form several fans (joined through edges at the
/// vertex) into one vertex per fan.
pub(super) fn split_fans(
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
pub(super) fn boundary_loops(faces: &[[u32; 3]], n: usize) -> Vec<Vec<u32>> {
    let half = EdgeIndex::directed(faces);
    // After the fans are split, each boundary vertex starts exactly one boundary edge.
    let mut next = vec![u32::MAX; n];
    for (a, next) in next.iter_mut().enumerate() {
        let a = u32::try_from(a).unwrap_or(u32::MAX);
        for &(b, _) in half.of(a) {
            if half.find(b, a).is_none() {
                *next = b;
            }
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

/// The most vertices on a cap's first ring ([`fill_hole`]): a wider hole's cap is made of
/// triangles wider than the mesh's, so that its size and the fairing's work stay bounded
/// however long the hole's rim is.
const CAP_RING_MAX: usize = 256;

/// The most rings of a cap's fairing ([`fill_hole`]).
const CAP_RINGS_MAX: usize = 64;

/// The rings next to the loop that a cap keeps whole ([`CapShape::kept_rings`]).
const CAP_FULL_RINGS: usize = 2;

/// The most rings of the fairing between two rings a cap keeps ([`CapShape::kept_rings`]).
pub(super) const CAP_STEP_MAX: usize = 8;

/// The fewest vertices on a ring a cap keeps ([`CapShape::kept_rings`]).
const CAP_RING_MIN: usize = 6;

/// Closes every loop of `loops` (each in the order the mesh's triangles run along it) by
/// [`fill_hole`]. The neighbours of the loops' vertices in the mesh, which each cap's fairing
/// holds fixed, are found in one pass over the triangles before any cap is added (each vertex
/// of a mesh whose pinched vertices are split lies on one loop at most, so a cap changes no
/// other loop's neighbours). The caps are independent and made in parallel; each cap's new
/// vertices are numbered after those of the caps of the loops before it, and the caps are
/// added in the loops' order, so that the mesh is the same as one cap after another.
pub(super) fn fill_holes(
    loops: &[Vec<u32>],
    faces: &mut Vec<[u32; 3]>,
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
    filled: &mut Vec<bool>,
) {
    fill_holes_with(loops, faces, positions, scan_vertex, filled, true);
}

/// [`fill_holes`], its caps graded ([`CapShape::kept_rings`]) if `graded`; else every ring of
/// each cap's fairing is kept (the fairing itself, for the tests).
pub(super) fn fill_holes_with(
    loops: &[Vec<u32>],
    faces: &mut Vec<[u32; 3]>,
    positions: &mut Vec<DVec3>,
    scan_vertex: &mut Vec<u32>,
    filled: &mut Vec<bool>,
    graded: bool,
) {
    // The loops' vertices' neighbours, in one pass over the faces (each vertex's place among
    // the loops' vertices looked up by index).
    let rims: Vec<u32> = loops.iter().flatten().copied().collect();
    let mut slot = vec![u32::MAX; positions.len()];
    for (i, &v) in rims.iter().enumerate() {
        if let Some(s) = slot.get_mut(v as usize) {
            *s = u32::try_from(i).unwrap_or(u32::MAX);
        }
    }
    let mut lists: Vec<Vec<u32>> = vec![Vec::new(); rims.len()];
    for t in faces.iter() {
        for k in 0..3 {
            let Some(list) = slot.get(t[k] as usize).and_then(|&s| lists.get_mut(s as usize))
            else {
                continue;
            };
            for other in [t[(k + 1) % 3], t[(k + 2) % 3]] {
                if !list.contains(&other) {
                    list.push(other);
                }
            }
        }
    }
    let around: std::collections::HashMap<u32, Vec<u32>> = rims.into_iter().zip(lists).collect();
    let mut next = positions.len();
    let shapes: Vec<(CapShape, usize)> = loops
        .iter()
        .map(|lp| {
            let shape = CapShape { graded, ..CapShape::of(lp, positions) };
            let first = next;
            next += shape.vertices();
            (shape, first)
        })
        .collect();
    let old: &[DVec3] = positions;
    let caps: Vec<Cap> = loops
        .par_iter()
        .zip(shapes.par_iter())
        .map(|(lp, (shape, first))| fill_hole(lp, shape, &around, old, *first))
        .collect();
    for cap in caps {
        scan_vertex.resize(scan_vertex.len() + cap.positions.len(), ADDED_VERTEX);
        positions.extend(cap.positions);
        faces.extend(cap.triangles);
    }
    filled.resize(faces.len(), true);
}

/// A hole's cap ([`fill_hole`]): its new vertices, numbered on from the index it was given,
/// and its triangles.
struct Cap {
    positions: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
}

/// The size of a hole's cap ([`fill_hole`]), from its loop alone.
struct CapShape {
    /// The loop's centroid.
    centre: DVec3,
    /// Rings of new vertices inside the loop.
    rings: usize,
    /// Vertices on each ring.
    count: usize,
    /// Whether the cap keeps fewer rings than its fairing, and fewer vertices on them, inwards
    /// ([`CapShape::kept_rings`]).
    graded: bool,
}

impl CapShape {
    /// The cap of the loop `lp` of a mesh with vertices `positions`.
    fn of(lp: &[u32], positions: &[DVec3]) -> Self {
        let m = lp.len();
        let at = |k: u32| positions[k as usize];
        let centre = lp.iter().map(|&k| at(k)).sum::<DVec3>() / m as f64;
        let perimeter = (0..m).map(|i| at(lp[i]).distance(at(lp[(i + 1) % m]))).sum::<f64>();
        // The spacing of the first ring's vertices: the loop's own, or wider for a long loop.
        let edge = perimeter / m.min(CAP_RING_MAX) as f64;
        let radius = lp.iter().map(|&k| at(k).distance(centre)).sum::<f64>() / m as f64;
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "clamped to 0..=CAP_RINGS_MAX"
        )]
        let rings = if edge > 0.0 {
            (radius / edge).round().clamp(0.0, CAP_RINGS_MAX as f64) as usize
        } else {
            0
        };
        // Every ring as many vertices as the first: with the umbrella operator's equal weights,
        // rings of equal counts settle evenly spaced (rings that thin out inwards would be
        // drawn towards the centre, leaving long triangles at the rim).
        CapShape { centre, rings, count: m.min(CAP_RING_MAX), graded: true }
    }

    /// The rings the cap keeps ([`fill_hole`]): each as (k, c), ring k (from 1, counted from
    /// the loop) of the [`CapShape::rings`] of the fairing, with c vertices. The first
    /// [`CAP_FULL_RINGS`] are kept whole, so that the cap leaves the loop in triangles as
    /// narrow as the loop's edges; then every second ring the step to the next kept ring
    /// doubles (up to [`CAP_STEP_MAX`] rings), and a ring of step s at the fraction t of the
    /// way to the centre keeps about count · (1 − t) / s vertices (its circumference over the
    /// spacing of its rings, so that its triangles stay about as wide as they are long), at
    /// least [`CAP_RING_MIN`] and no more than the ring before. The last ring kept lies within
    /// a step of the centre.
    fn kept_rings(&self) -> Vec<(usize, usize)> {
        if !self.graded {
            return (1..=self.rings).map(|k| (k, self.count)).collect();
        }
        let mut kept: Vec<(usize, usize)> = Vec::new();
        let (mut k, mut step) = (1, 1);
        while k <= self.rings {
            let c = if kept.len() < CAP_FULL_RINGS {
                self.count
            } else {
                let t = k as f64 / (self.rings + 1) as f64;
                #[expect(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "at most count"
                )]
                let c = (self.count as f64 * (1.0 - t) / step as f64).round() as usize;
                c.max(CAP_RING_MIN).min(kept.last().map_or(self.count, |r| r.1))
            };
            kept.push((k, c));
            if kept.len() >= CAP_FULL_RINGS && kept.len().is_multiple_of(2) {
                step = (2 * step).min(CAP_STEP_MAX);
            }
            k += step;
        }
        kept
    }

    /// The new vertices of the cap: its kept rings' ([`CapShape::kept_rings`]) and the centre.
    fn vertices(&self) -> usize {
        self.kept_rings().iter().map(|r| r.1).sum::<usize>() + 1
    }
}

/// Adds to `around[v]`, for each vertex v it holds, the other corners of the triangles of
/// `faces` at v (each once).
fn gather_neighbours(faces: &[[u32; 3]], around: &mut std::collections::HashMap<u32, Vec<u32>>) {
    for t in faces {
        for k in 0..3 {
            if let Some(list) = around.get_mut(&t[k]) {
                for other in [t[(k + 1) % 3], t[(k + 2) % 3]] {
                    if !list.contains(&other) {
                        list.push(other);
                    }
                }
            }
        }
    }
}

/// The triangles of the strip between two closed rings of vertices going the same way round,
/// `outer` and `inner` (of any counts), the outer ring's vertex i at the fraction i / a of the
/// way round and the inner ring's j at j / b, both from 0: the triangles advance along
/// whichever ring's next vertex comes first, so each is as wide as the rings' spacing allows.
/// Oriented as the mesh whose boundary runs along `outer` in its order.
fn zip_rings(outer: &[u32], inner: &[u32]) -> Vec<[u32; 3]> {
    let (a, b) = (outer.len(), inner.len());
    let mut out = Vec::with_capacity(a + b);
    let (mut i, mut j) = (0, 0);
    while i < a || j < b {
        if j == b || (i < a && (i + 1) * b <= (j + 1) * a) {
            out.push([outer[(i + 1) % a], outer[i], inner[j % b]]);
            i += 1;
        } else {
            out.push([outer[i % a], inner[j], inner[(j + 1) % b]]);
            j += 1;
        }
    }
    out
}

/// The cap closing the boundary loop `lp` (in the order the mesh's triangles run along it) of
/// a mesh with vertices `old`, its new vertices numbered from `first_new`: rings of new
/// vertices shrinking towards the loop's centroid, one ring per mean edge length of the loop's
/// radius (at most [`CAP_RINGS_MAX`]), each of as many vertices as the loop (a loop longer
/// than [`CAP_RING_MAX`] edges: that many, on rings spaced as widely as their vertices, so
/// that the cap's size is bounded), joined by [`zip_rings`], then a fan around the centroid.
/// The new vertices are moved to the thin plate the surface around it continues into: the
/// umbrella operator vanishes, in the least-squares sense, at every new vertex and every vertex
/// of the loop (Kobbelt 1998, discrete fairing; the loop and the scan's triangles about it
/// fixed; [`fair`]), so the cap leaves the rim along the surface's own tangent plane, with no
/// crease for the harmonic surface to ring on. Should that system be singular to rounding, they
/// go to the discrete membrane instead (each the mean of its neighbours, the loop fixed: as
/// flat as its border allows; [`membrane`]). The cap kept is then graded ([`graded`]): the
/// rings next to the loop whole, those further in fewer and sparser, each vertex on the faired
/// surface, so that a wide hole's cap costs the later stages (handle search, parameterisation)
/// about as many vertices as the loop has rather than its square, while it leaves the loop as
/// smoothly as the fairing does. `shape` is the cap's size ([`CapShape::of`] the loop); `around`
/// holds the loop's vertices' neighbours in the mesh ([`fill_holes`]).
fn fill_hole(
    lp: &[u32],
    shape: &CapShape,
    around: &std::collections::HashMap<u32, Vec<u32>>,
    old: &[DVec3],
    first_new: usize,
) -> Cap {
    let &CapShape { centre, rings, count, .. } = shape;
    let m = lp.len();
    let at = |k: u32| old[k as usize];
    // The loop's point at the fraction s of the way round (by vertex index, from lp[0]).
    let on_loop = |s: f64| {
        let x = s * m as f64;
        #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "in 0..m")]
        let i = (x.floor() as usize).min(m - 1);
        at(lp[i]).lerp(at(lp[(i + 1) % m]), x - i as f64)
    };
    let mut new: Vec<DVec3> = Vec::with_capacity(rings * count + 1);
    let mut triangles: Vec<[u32; 3]> = Vec::new();
    let index = |new: &Vec<DVec3>| u32::try_from(first_new + new.len()).unwrap_or(u32::MAX);
    let mut outer: Vec<u32> = lp.to_vec();
    for k in 1..=rings {
        let t = k as f64 / (rings + 1) as f64;
        let inner: Vec<u32> = (0..count)
            .map(|j| {
                let i = index(&new);
                new.push(on_loop(j as f64 / count as f64).lerp(centre, t));
                i
            })
            .collect();
        triangles.extend(zip_rings(&outer, &inner));
        outer = inner;
    }
    let c = index(&new);
    new.push(centre);
    let n = outer.len();
    for i in 0..n {
        triangles.push([outer[(i + 1) % n], outer[i], c]);
    }
    // The new vertices' neighbours, then the fairing.
    let free = new.len();
    if free <= 1 {
        return Cap { positions: new, triangles };
    }
    let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); free];
    for t in &triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            for (x, y) in [(a, b), (b, a)] {
                if x as usize >= first_new && !neighbours[x as usize - first_new].contains(&y) {
                    neighbours[x as usize - first_new].push(y);
                }
            }
        }
    }
    // The loop's vertices' neighbours on both sides: the mesh's, and the cap's.
    let mut rim: std::collections::HashMap<u32, Vec<u32>> =
        lp.iter().map(|&v| (v, around.get(&v).cloned().unwrap_or_default())).collect();
    gather_neighbours(&triangles, &mut rim);
    if !fair(lp, &rim, (old, &mut new), first_new, &neighbours, (rings, count)) {
        membrane((old, &mut new), first_new, &neighbours, (16 * (rings + 1)).max(20));
    }
    graded(lp, shape, &new, first_new)
}

/// The cap a hole keeps ([`fill_hole`]) from its fairing's vertices `fine` (rings of `count`
/// vertices each, ring k's vertex j numbered (k − 1) · `count` + j, and the centre last): the
/// rings of [`CapShape::kept_rings`], each vertex at the fraction i / c of the way round its
/// ring of c placed on the fairing's ring by linear interpolation between the two vertices
/// about it (a ring kept whole keeps its vertices), joined by [`zip_rings`] from the loop `lp`
/// inwards, then a fan around the centre; numbered from `first_new`.
fn graded(lp: &[u32], shape: &CapShape, fine: &[DVec3], first_new: usize) -> Cap {
    let count = shape.count;
    let mut positions: Vec<DVec3> = Vec::new();
    let mut triangles: Vec<[u32; 3]> = Vec::new();
    let index = |at: usize| u32::try_from(first_new + at).unwrap_or(u32::MAX);
    let mut outer: Vec<u32> = lp.to_vec();
    for (k, c) in shape.kept_rings() {
        let ring = &fine[(k - 1) * count..k * count];
        let inner: Vec<u32> = (0..c)
            .map(|i| {
                let at = index(positions.len());
                let x = (i * count) as f64 / c as f64;
                #[expect(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "in 0..count"
                )]
                let j = (x.floor() as usize).min(count - 1);
                positions.push(ring[j].lerp(ring[(j + 1) % count], x - j as f64));
                at
            })
            .collect();
        triangles.extend(zip_rings(&outer, &inner));
        outer = inner;
    }
    let centre = index(positions.len());
    positions.push(fine[fine.len() - 1]);
    let n = outer.len();
    for i in 0..n {
        triangles.push([outer[(i + 1) % n], outer[i], centre]);
    }
    Cap { positions, triangles }
}

/// The discrete membrane over a hole's cap (see [`fill_hole`]): its new vertices `new`
/// (numbered from `first_new`, with their `neighbours`; the mesh's vertices `old`, fixed) each
/// placed at the mean of its neighbours, deg(v) v − Σ neighbours = 0, a symmetric positive
/// definite system in the new vertices (the graph Laplacian with the loop fixed), by conjugate
/// gradients (three coordinates at once, from the places given) until the residual has fallen
/// by a factor of 10¹⁰, at most `iterations` steps (conjugate gradients need a few times the
/// cap's rings, where Gauss–Seidel sweeps need their square).
pub(super) fn membrane(
    (old, new): (&[DVec3], &mut [DVec3]),
    first_new: usize,
    neighbours: &[Vec<u32>],
    iterations: usize,
) {
    let free = |k: u32| (k as usize).checked_sub(first_new);
    // L x with L the Laplacian restricted to the new vertices; b the fixed neighbours' sum.
    let apply = |x: &[DVec3], out: &mut [DVec3]| {
        for ((o, list), xi) in out.iter_mut().zip(neighbours).zip(x) {
            *o = *xi * list.len() as f64
                - list.iter().filter_map(|&k| free(k)).map(|j| x[j]).sum::<DVec3>();
        }
    };
    let b: Vec<DVec3> = neighbours
        .iter()
        .map(|list| list.iter().filter(|&&k| free(k).is_none()).map(|&k| old[k as usize]).sum())
        .collect();
    let dot = |a: &[DVec3], c: &[DVec3]| -> DVec3 { a.iter().zip(c).map(|(x, y)| *x * *y).sum() };
    let mut x: Vec<DVec3> = new.to_vec();
    let mut q = vec![DVec3::ZERO; x.len()];
    apply(&x, &mut q);
    let mut r: Vec<DVec3> = b.iter().zip(&q).map(|(bi, qi)| *bi - *qi).collect();
    let mut p = r.clone();
    let mut rr = dot(&r, &r);
    let start = rr.max_element();
    for _ in 0..iterations {
        if rr.max_element() <= 1e-20 * start.max(f64::MIN_POSITIVE) {
            break;
        }
        apply(&p, &mut q);
        let pq = dot(&p, &q);
        let alpha = DVec3::select(pq.cmpgt(DVec3::ZERO), rr / pq, DVec3::ZERO);
        for ((xi, ri), (pi, qi)) in x.iter_mut().zip(r.iter_mut()).zip(p.iter().zip(&q)) {
            *xi += alpha * *pi;
            *ri -= alpha * *qi;
        }
        let next = dot(&r, &r);
        let beta = DVec3::select(rr.cmpgt(DVec3::ZERO), next / rr, DVec3::ZERO);
        for (pi, ri) in p.iter_mut().zip(&r) {
            *pi = *ri + beta * *pi;
        }
        rr = next;
    }
    if x.iter().all(|v| v.is_finite()) {
        new.copy_from_slice(&x);
    }
}

/// One vertex's umbrella operator in [`fair`]: the vertex, its coefficients by place of the free
/// vertices, and the part from the fixed ones.
type UmbrellaRow = (u32, Vec<(usize, f64)>, DVec3);

/// The thin-plate fairing of a hole's cap (see [`fill_hole`]): the cap's new vertices `new`
/// (numbered from `first_new`, with their `neighbours`; the mesh's vertices `old`;
/// `around_loop` holds the loop's vertices' neighbours on both sides) placed where the umbrella
/// operator U(v) = mean of v's neighbours − v vanishes, in the least-squares sense, at every
/// vertex of the cap and of the loop `lp` (the loop and the rest of the mesh fixed): the normal
/// equations Aᵀ A x = −Aᵀ f of the rows U(v) = A x + f, solved directly. The cap is `rings`
/// rings of `count` vertices each (ring k's vertex j numbered (k − 1) · `count` + j) and its
/// centre last ([`CapShape`]): ordered spoke by spoke, the spokes taken 0, 1, count − 1, 2,
/// count − 2, … so that neighbouring spokes lie at most two apart, a vertex couples in Aᵀ A
/// only to those within about 4 · `rings` places, but for the centre, whose own row joins the
/// whole innermost ring. So Aᵀ A less the centre's row is an [`ArrowBand`] (the centre last),
/// factorised by banded Cholesky, and the centre's row u is added back by Sherman and Morrison:
/// (B + u uᵀ)⁻¹ c = y − z (uᵀ y) / (1 + uᵀ z) with B y = c and B z = u.
/// Returns `false`, leaving `new` as it was, if the system is singular to rounding.
fn fair(
    lp: &[u32],
    around_loop: &std::collections::HashMap<u32, Vec<u32>>,
    (old, new): (&[DVec3], &mut [DVec3]),
    first_new: usize,
    neighbours: &[Vec<u32>],
    (rings, count): (usize, usize),
) -> bool {
    let free = neighbours.len();
    if free != rings * count + 1 || count < 3 {
        return false;
    }
    // The place of each free vertex in the order.
    let spoke = |j: usize| {
        if j == 0 {
            0
        } else if j <= count - j {
            2 * j - 1
        } else {
            2 * (count - j)
        }
    };
    let place =
        |c: usize| if c + 1 == free { free - 1 } else { spoke(c % count) * rings + c / count };
    let centre = (first_new + free - 1) as u32;
    // One row per vertex of the loop and the cap: U(v) as coefficients of the free vertices'
    // places, and its fixed part.
    let rows: Vec<UmbrellaRow> = lp
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
                    coefficients.push((place(k as usize - first_new), c));
                } else {
                    fixed += old[k as usize] * c;
                }
            }
            (v, coefficients, fixed)
        })
        .collect();
    let last = free - 1;
    let band = rows
        .iter()
        .filter(|(v, ..)| *v != centre)
        .map(|(_, c, _)| {
            let inside = c.iter().map(|&(k, _)| k).filter(|&k| k != last);
            inside.clone().max().unwrap_or(0) - inside.min().unwrap_or(0)
        })
        .max()
        .unwrap_or(0);
    let mut b = ArrowBand::zeros(free, band);
    let mut rhs = vec![DVec3::ZERO; free];
    let mut u = vec![DVec3::ZERO; free];
    for (v, coefficients, fixed) in &rows {
        for &(k, w) in coefficients {
            rhs[k] -= *fixed * w;
            if *v == centre {
                u[k] = DVec3::splat(w);
                continue;
            }
            for &(l, x) in coefficients {
                if l <= k && !b.add(k, l, w * x) {
                    return false;
                }
            }
        }
    }
    let Some(factor) = b.cholesky() else {
        return false;
    };
    factor.solve(&mut rhs);
    let mut z = u.clone();
    factor.solve(&mut z);
    let dot = |a: &[DVec3], c: &[DVec3]| -> DVec3 { a.iter().zip(c).map(|(x, y)| *x * *y).sum() };
    let scale = dot(&u, &rhs) / (1.0 + dot(&u, &z).x);
    if !scale.is_finite() || rhs.iter().any(|v| !v.is_finite()) {
        return false;
    }
    for (c, out) in new.iter_mut().enumerate() {
        let k = place(c);
        *out = rhs[k] - z[k] * scale;
    }
    true
}
