// SPDX-License-Identifier: MIT
use super::handles::{
    BlockGrid, BlockSearch, block_edges, block_loop, block_loop_with, cut_handles, genus_zero,
    independent_loops,
};
use super::holes::{CAP_STEP_MAX, fill_holes_with, membrane};
use super::homology::{Homology, IndependentClasses};
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
    let chi = closed.positions.len() as i64 - edges.len() as i64 + closed.triangles.len() as i64;
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

/// The faces of a closed mesh on either side of each edge, (edge, face, face), by edge.
fn face_pairs(triangles: &[[u32; 3]]) -> Vec<(u64, u32, u32)> {
    let mut sides: Vec<(u64, u32)> = triangles
        .iter()
        .enumerate()
        .flat_map(|(f, t)| (0..3).map(move |k| (edge_key(t[k], t[(k + 1) % 3]), f as u32)))
        .collect();
    sides.sort_unstable();
    sides.chunk_by(|a, b| a.0 == b.0).map(|w| (w[0].0, w[0].1, w[1].1)).collect()
}

#[test]
fn three_handles_are_cut_and_the_surface_stays_whole() {
    // A plate of 7 × 3 × 1 voxels with three square holes through it: genus 3, volume 18.
    let (p, t) = voxel_surface([7, 3, 1], |x, y, _| !(y == 1 && x % 2 == 1));
    assert!(closed_and_oriented(&t));
    let chi = |p: usize, t: &[[u32; 3]]| {
        let mut edges: Vec<u64> =
            t.iter().flat_map(|f| (0..3).map(move |k| edge_key(f[k], f[(k + 1) % 3]))).collect();
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
    let pairs = face_pairs(&closed.triangles);
    assert!(faces_connected(closed.triangles.len(), &pairs, &[]));
    // The caps of each cut lie on each other: the plate's volume is kept (to 5 %: the
    // caps are faired to the plate's sides about them and bulge a little).
    assert!((closed.volume() - 18.0).abs() < 0.9, "{}", closed.volume());
}

/// A closed surface of genus g has E − (V − 1) − (F − 1) = 2g edges in neither a spanning tree
/// of its vertices nor one of its faces across the other edges: the greedy system of loops
/// through a root has 2g loops, which a block's search gives shortest first, none of which
/// alone separates the surface.
#[test]
fn the_greedy_system_through_a_root_has_two_loops_per_handle() {
    let plate = voxel_surface([7, 3, 1], |x, y, _| !(y == 1 && x % 2 == 1));
    for ((p, t), genus) in [(torus(24, 8, 1.0, 0.3), 1), (plate, 3)] {
        let all: Vec<u32> = (0..t.len() as u32).collect();
        let loops = block_loop(&t, &p, &[], &all);
        assert_eq!(loops.len(), 2 * genus);
        assert!(loops.windows(2).all(|w| w[0].0 <= w[1].0));
        let pairs = face_pairs(&t);
        for (length, lp) in &loops {
            let m = lp.len();
            let mut barrier: Vec<u64> = (0..m).map(|i| edge_key(lp[i], lp[(i + 1) % m])).collect();
            barrier.sort_unstable();
            // A loop of the mesh's edges, as long as said.
            assert!(barrier.iter().all(|e| pairs.binary_search_by_key(e, |x| x.0).is_ok()));
            let sum: f64 =
                (0..m).map(|i| p[lp[i] as usize].distance(p[lp[(i + 1) % m] as usize])).sum();
            assert!((sum - length).abs() < 1e-12 * length);
            assert!(faces_connected(t.len(), &pairs, &barrier));
        }
    }
}

/// `genus_zero` of the faces `faces` (global vertex indices), numbered locally as
/// `block_loop` numbers them.
fn block_genus_zero(faces: &[[u32; 3]]) -> bool {
    let mut local = std::collections::HashMap::new();
    let local_faces: Vec<[u32; 3]> = faces
        .iter()
        .map(|t| {
            t.map(|v| {
                let next = local.len() as u32;
                *local.entry(v).or_insert(next)
            })
        })
        .collect();
    genus_zero(local.len(), &block_edges(&local_faces), faces.len())
}

#[test]
fn the_genus_count_tells_blocks_without_handles() {
    // χ = V − E + F against 2C − b: the whole torus has genus 1; without one ring of its
    // quads it is a tube (an annulus: χ = 0, C = 1, b = 2); a triangle is a disc.
    let (_, t) = torus(12, 6, 1.0, 0.3);
    assert!(!block_genus_zero(&t));
    assert!(block_genus_zero(&t[12..]));
    assert!(block_genus_zero(&t[..1]));
    // Two triangles meeting at one vertex: a pinch (four border edges at vertex 0), which a
    // loop could pass through without separating the faces, so not counted as genus 0.
    assert!(!block_genus_zero(&[[0, 1, 2], [0, 3, 4]]));
    // Two separate triangles: two discs.
    assert!(block_genus_zero(&[[0, 1, 2], [3, 4, 5]]));
}

#[test]
fn blocks_of_genus_zero_are_skipped_with_the_same_loops() {
    // Blocks of every size over a torus and a plate with three holes, as the handle search
    // makes them (faces by the cell of their centroid, on two grids offset by half a cell): the
    // loops found are the same with the shortcut as with the search run on every block.
    let plate = voxel_surface([7, 3, 1], |x, y, _| !(y == 1 && x % 2 == 1));
    let (mut skipped, mut with_loops, mut blocks) = (0, 0, 0);
    for (p, t) in [torus(24, 8, 1.0, 0.3), plate] {
        let at = |k: u32| p[k as usize];
        let mean_edge = t.iter().map(|f| at(f[0]).distance(at(f[1]))).sum::<f64>() / t.len() as f64;
        for side in [1.5, 2.0, 3.0, 4.0, 8.0] {
            for offset in [0.0, 0.5] {
                let mut cells: std::collections::BTreeMap<[i64; 3], Vec<u32>> =
                    std::collections::BTreeMap::new();
                for (f, tri) in t.iter().enumerate() {
                    let c = (at(tri[0]) + at(tri[1]) + at(tri[2])) / 3.0;
                    let key =
                        (c / (side * mean_edge) + offset).floor().to_array().map(|x| x as i64);
                    cells.entry(key).or_default().push(f as u32);
                }
                for block in cells.values() {
                    let fast = block_loop(&t, &p, &[], block);
                    assert_eq!(fast, block_loop_with(&t, &p, &[], block, false));
                    let faces: Vec<[u32; 3]> = block.iter().map(|&f| t[f as usize]).collect();
                    skipped += usize::from(block_genus_zero(&faces));
                    with_loops += usize::from(!fast.is_empty());
                    blocks += 1;
                }
            }
        }
    }
    // Neither side empty: most blocks are skipped, and some hold handles.
    assert!(skipped > blocks / 2 && with_loops > 0, "{skipped} of {blocks}, {with_loops}");
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
    let chosen = independent_loops(&Homology::new(&t), p.len(), found, 3);
    assert_eq!(chosen, vec![meridian(0)]);
    // With no loop in the way, the second meridian alone would do.
    let chosen = independent_loops(&Homology::new(&t), p.len(), vec![(1.0, meridian(4))], 3);
    assert_eq!(chosen, vec![meridian(4)]);
}

/// A flat annulus in z = 0 of `rings` rings of `m` quads (two triangles each) about as wide as
/// they are long, from radius 1 outwards, every triangle facing −z: its inner boundary is a
/// hole of m edges.
fn annulus(m: usize, rings: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let tau = std::f64::consts::TAU;
    ring_strip(m, rings, |r, i| {
        let radius = (tau * r as f64 / m as f64).exp();
        let a = tau * i as f64 / m as f64;
        DVec3::new(radius * a.cos(), radius * a.sin(), 0.0)
    })
}

/// Rings 0 to `rings` of `m` points each (ring r's point i at `at(r, i)`), each ring joined to
/// the next by m quads of two triangles: a strip open at its first and last rings.
fn ring_strip(
    m: usize,
    rings: usize,
    at: impl Fn(usize, usize) -> DVec3,
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let p: Vec<DVec3> =
        (0..=rings).flat_map(|r| (0..m).map(move |i| (r, i))).map(|(r, i)| at(r, i)).collect();
    let id = |r: usize, i: usize| (r * m + i % m) as u32;
    let mut t = Vec::new();
    for r in 0..rings {
        for i in 0..m {
            let (a, b, c, d) = (id(r, i), id(r, i + 1), id(r + 1, i + 1), id(r + 1, i));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    (p, t)
}

/// A hole of thousands of edges is capped by a bounded number of triangles (its first ring
/// has at most `CAP_RING_MAX` vertices) that close it, wound as the mesh, every one facing
/// −z as the flat annulus does, none longer than a few of the rim's edges (or of the first
/// ring's) next to the rim, nor than twice the widest step between kept rings further in; the
/// faired cap of a flat rim is flat, and stays inside the rim.
#[test]
fn caps_of_long_holes_stay_small_flat_and_well_shaped() {
    for m in [12, 100, 4000] {
        let (mut p, mut t) = annulus(m, 3);
        let n0 = p.len();
        let mut scan_vertex: Vec<u32> = (0..n0 as u32).collect();
        let mut filled = vec![false; t.len()];
        let loops = boundary_loops(&t, n0);
        assert_eq!(loops.len(), 2, "inner and outer rims");
        // The inner rim: the loop whose vertices lie at radius 1.
        let inner: Vec<Vec<u32>> = loops
            .into_iter()
            .filter(|lp| (p[lp[0] as usize].length() - 1.0).abs() < 1e-9)
            .collect();
        assert_eq!(inner.len(), 1);
        let before = t.len();
        fill_holes(&inner, &mut t, &mut p, &mut scan_vertex, &mut filled);
        assert_eq!(filled.len(), t.len());
        assert!(filled[before..].iter().all(|&f| f) && !filled[..before].iter().any(|&f| f));
        let added = p.len() - n0;
        assert!(added < 256 * 256 / 4, "{m} rim edges: {added} cap vertices");
        assert!(scan_vertex[n0..].iter().all(|&k| k == ADDED_VERTEX));
        // Only the outer rim is left open, and every edge is used once each way but its own.
        let open = boundary_loops(&t, p.len());
        assert_eq!(open.len(), 1);
        assert!(p[open[0][0] as usize].length() > 1.0 + 1e-9);
        let mut directed: Vec<(u32, u32)> =
            t.iter().flat_map(|f| (0..3).map(move |k| (f[k], f[(k + 1) % 3]))).collect();
        directed.sort_unstable();
        assert!(directed.windows(2).all(|w| w[0] != w[1]), "{m}: consistently wound");
        // The spacing of the fairing's rings: the rim's edges, or the 256 vertices of a long
        // rim's first ring.
        let spacing = (std::f64::consts::TAU / m as f64).max(std::f64::consts::TAU / 256.0);
        for f in &t[before..] {
            let [a, b, c] = f.map(|k| p[k as usize]);
            let normal = (b - a).cross(c - a);
            assert!(normal.z < 0.0, "{m}: a cap triangle faces +z");
            let longest = (b - a).length().max((c - b).length()).max((a - c).length());
            // As wide as that spacing within the two rings kept whole next to the rim, and no
            // wider than twice the widest step between the rings kept further in.
            let at = ((a + b + c) / 3.0).length();
            let bound = if at > 1.0 - 2.5 * spacing { 4.0 } else { 2.0 * CAP_STEP_MAX as f64 };
            assert!(longest < bound * spacing, "{m}: {longest} at {at}");
        }
        for q in &p[n0..] {
            assert!(q.z.abs() < 1e-9 && q.truncate().length() < 1.0, "{m}: {q} off the flat cap");
        }
    }
}

/// A plate with 6 × 6 round holes through it, as a closed mesh (the zero set of its signed
/// distance, [`crate::surfacenets`]): a surface of genus 36, more handles than
/// [`MAX_HANDLES`]. Closed as a sphere or a disc it fails (the handles are left uncut), as a
/// torus too, each naming the genus.
#[test]
fn a_part_of_more_handles_than_are_cut_names_its_genus() {
    let h = 0.5;
    let dims = [56, 56, 9];
    let origin = DVec3::new(-2.0, -2.0, -2.0);
    let mut values = Vec::with_capacity(dims.iter().product());
    for k in 0..dims[2] {
        for j in 0..dims[1] {
            for i in 0..dims[0] {
                let p = origin + DVec3::new(i as f64, j as f64, k as f64) * h;
                let plate =
                    ((p.x - 12.0).abs() - 12.0).max((p.y - 12.0).abs() - 12.0).max(p.z.abs() - 1.0);
                let hole = (0..36)
                    .map(|n| {
                        let c =
                            DVec3::new(2.0 + 4.0 * (n % 6) as f64, 2.0 + 4.0 * (n / 6) as f64, 0.0);
                        (p - c).truncate().length() - 1.0
                    })
                    .fold(f64::INFINITY, f64::min);
                values.push(plate.max(-hole));
            }
        }
    }
    let grid = crate::surfacenets::Grid { origin, spacing: h, dims, values: &values };
    let (p, t) = crate::surfacenets::surface_nets(&grid).unwrap();
    let parts = mesh_parts(&p, &t).unwrap();
    assert_eq!(parts.parts.len(), 1);
    let part = &parts.parts[0];
    assert_eq!(part_topology(part).genus, 36);
    for (closing, needs) in [
        (Closing::Sphere, "genus 0 a sphere"),
        (Closing::Disc, "genus 0 a disc"),
        (Closing::Torus, "genus 1 a torus"),
    ] {
        let message = close_part(part, closing).unwrap_err().to_string();
        assert!(message.contains("genus 36 once its holes are closed"), "{message}");
        assert!(message.contains(needs), "{message}");
    }
}

/// The caps of several holes, made together (in parallel, each numbering its new vertices
/// after the caps before it), are the caps made one hole at a time: the same vertices in the
/// same order and the same triangles. Two annuli side by side, their four rims filled.
#[test]
fn holes_filled_together_are_holes_filled_one_by_one() {
    let (p1, t1) = annulus(40, 3);
    let (mut p, mut t) = annulus(24, 2);
    let shift = p.len() as u32;
    p.extend(p1.iter().map(|q| *q + DVec3::new(5.0, 0.0, 0.3 * q.x * q.y)));
    t.extend(t1.iter().map(|f| f.map(|k| k + shift)));
    let loops = boundary_loops(&t, p.len());
    assert_eq!(loops.len(), 4);
    let n = p.len();
    let (mut pa, mut ta, mut sa, mut fa) = (p.clone(), t.clone(), vec![0; n], vec![false; t.len()]);
    fill_holes(&loops, &mut ta, &mut pa, &mut sa, &mut fa);
    let mut fb = vec![false; t.len()];
    let (mut pb, mut tb, mut sb) = (p, t, vec![0; n]);
    for lp in &loops {
        fill_holes(std::slice::from_ref(lp), &mut tb, &mut pb, &mut sb, &mut fb);
    }
    assert_eq!(ta, tb);
    assert_eq!(pa, pb);
    assert_eq!((sa, fa), (sb, fb));
    assert!(boundary_loops(&ta, pa.len()).is_empty(), "every rim closed");
}

/// The membrane of a cap is the discrete harmonic map with the cap's border fixed: on a square
/// grid of 20 × 20 free vertices, each joined to its four neighbours, inside a fixed border on
/// (x, y, x² − y²), it is (x, y, x² − y²) at every free vertex too (x, y and x² − y² are
/// harmonic for the five-point Laplacian: their second differences cancel exactly), reached
/// from (0, 0, 0) in far fewer steps than Gauss–Seidel sweeps would need (some 20²).
#[test]
fn the_membrane_is_the_discrete_harmonic_map() {
    let n = 22i32; // the grid with its border
    let at = |i: i32, j: i32| {
        let (x, y) = (f64::from(i) / f64::from(n - 1), f64::from(j) / f64::from(n - 1));
        DVec3::new(x, y, x * x - y * y)
    };
    let border = |i: i32, j: i32| i == 0 || j == 0 || i == n - 1 || j == n - 1;
    // Fixed vertices first, then the free ones.
    let mut fixed: Vec<(i32, i32)> = Vec::new();
    let mut free: Vec<(i32, i32)> = Vec::new();
    for i in 0..n {
        for j in 0..n {
            if border(i, j) { fixed.push((i, j)) } else { free.push((i, j)) }
        }
    }
    let first_new = fixed.len();
    let index = |c: (i32, i32)| -> u32 {
        let k = fixed
            .iter()
            .position(|&f| f == c)
            .or_else(|| free.iter().position(|&f| f == c).map(|k| k + first_new));
        k.unwrap() as u32
    };
    let old: Vec<DVec3> = fixed.iter().map(|&(i, j)| at(i, j)).collect();
    let neighbours: Vec<Vec<u32>> = free
        .iter()
        .map(|&(i, j)| [(i - 1, j), (i + 1, j), (i, j - 1), (i, j + 1)].map(index).to_vec())
        .collect();
    let mut new = vec![DVec3::ZERO; free.len()];
    membrane((&old, &mut new), first_new, &neighbours, 100);
    for (v, &(i, j)) in new.iter().zip(&free) {
        assert!(v.distance(at(i, j)) < 1e-9, "{v} at ({i}, {j}) against {}", at(i, j));
    }
}

/// A band of the unit sphere between latitudes ±60°, `around` × `along` quads (two triangles
/// each), open at both ends.
fn sphere_band(around: usize, along: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    ring_strip(around, along, |i, j| {
        let lat = (-60.0 + 120.0 * i as f64 / along as f64).to_radians();
        let lon = std::f64::consts::TAU * j as f64 / around as f64;
        DVec3::new(lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin())
    })
}

/// A cap's fairing is the thin plate of its rim: the gradient of Σ |U(v)|² over the cap's
/// vertices (U the umbrella operator, summed over the cap's vertices and its rim's, on the
/// mesh as closed) vanishes at every new vertex, to rounding. Checked from the closed mesh
/// alone (every ring of the fairing kept, [`fill_holes_with`] ungraded), on the caps of a band of the
/// sphere: rims of 48 vertices (a cap of rings of as many vertices) and of 300 (rings of 256,
/// zipped to the rim).
#[test]
fn caps_are_the_thin_plate_of_their_rim() {
    for around in [48, 300] {
        let (mut p, mut t) = sphere_band(around, 12);
        let n0 = p.len();
        let mut scan_vertex: Vec<u32> = (0..n0 as u32).collect();
        let mut filled = vec![false; t.len()];
        let loops = boundary_loops(&t, n0);
        assert_eq!(loops.len(), 2);
        let rims: Vec<u32> = loops.iter().flatten().copied().collect();
        fill_holes_with(&loops, &mut t, &mut p, &mut scan_vertex, &mut filled, false);
        assert!(boundary_loops(&t, p.len()).is_empty());
        let mut around_of: Vec<Vec<u32>> = vec![Vec::new(); p.len()];
        for f in &t {
            for k in 0..3 {
                for other in [f[(k + 1) % 3], f[(k + 2) % 3]] {
                    if !around_of[f[k] as usize].contains(&other) {
                        around_of[f[k] as usize].push(other);
                    }
                }
            }
        }
        let umbrella = |v: usize| {
            let ring = &around_of[v];
            ring.iter().map(|&k| p[k as usize]).sum::<DVec3>() / ring.len() as f64 - p[v]
        };
        // The rows: the rims' vertices and the new ones; the gradient at each new vertex c is
        // Σ_rows ∂U(row)/∂c · U(row), with ∂U(v)/∂c = 1/deg v for c beside v and −1 for c = v.
        let rows: Vec<usize> = rims.iter().map(|&v| v as usize).chain(n0..p.len()).collect();
        let mut gradient = vec![DVec3::ZERO; p.len()];
        for &v in &rows {
            let u = umbrella(v);
            for &k in &around_of[v] {
                gradient[k as usize] += u / around_of[v].len() as f64;
            }
            gradient[v] -= u;
        }
        let edge = std::f64::consts::TAU * 0.5 / around as f64;
        let worst = gradient[n0..].iter().map(|g| g.length()).fold(0.0, f64::max);
        assert!(worst < 1e-10 * edge, "{around}: gradient {worst:e} against edges of {edge}");
        // Smooth and on the sphere's side of the rim planes: a thin plate bulges outwards.
        for q in &p[n0..] {
            assert!(q.z.abs() > 0.8, "{around}: {q} inside the band");
        }
    }
}

/// The distance from `x` to the segment from `a` to `b`.
fn segment_distance(x: DVec3, a: DVec3, b: DVec3) -> f64 {
    let d = b - a;
    let s = if d.length_squared() > 0.0 {
        ((x - a).dot(d) / d.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    x.distance(a + d * s)
}

/// A cap as it is kept (graded: rings thinning and spreading inwards) lies on its fairing:
/// every new vertex on an edge of the cap made with every ring of the fairing kept (to
/// rounding), the rim's triangles the same in both; and it has less than half the fairing's
/// vertices (a tenth for the long rims), closes the hole consistently wound, and has no angle
/// smaller than the fairing's smallest. On the caps of a band of the sphere (rims of 48 and
/// 300 vertices) and of a flat annulus's inner rim of 4000.
#[test]
fn graded_caps_lie_on_their_fairing() {
    let bands = [48, 300].map(|around| (around, sphere_band(around, 12)));
    let flat = (4000, annulus(4000, 3));
    for (around, (p0, t0)) in bands.into_iter().chain([flat]) {
        let n0 = p0.len();
        let mut loops = boundary_loops(&t0, n0);
        if around == 4000 {
            loops.retain(|lp| (p0[lp[0] as usize].length() - 1.0).abs() < 1e-9);
        }
        let closed = |fine: bool| {
            let (mut p, mut t) = (p0.clone(), t0.clone());
            let mut scan_vertex: Vec<u32> = (0..n0 as u32).collect();
            let mut filled = vec![false; t.len()];
            if fine {
                fill_holes_with(&loops, &mut t, &mut p, &mut scan_vertex, &mut filled, false);
            } else {
                fill_holes(&loops, &mut t, &mut p, &mut scan_vertex, &mut filled);
            }
            (p, t)
        };
        let (pf, tf) = closed(true);
        let (pg, tg) = closed(false);
        let (fine_new, graded_new) = (pf.len() - n0, pg.len() - n0);
        let fraction = if around >= 300 { 10 } else { 2 };
        assert!(
            fraction * graded_new < fine_new,
            "{around}: {graded_new} of {fine_new} vertices kept"
        );
        // Closed (but for the annulus's outer rim) and consistently wound.
        let open = usize::from(around == 4000);
        assert_eq!(boundary_loops(&tg, pg.len()).len(), open, "{around}");
        let mut directed: Vec<(u32, u32)> =
            tg.iter().flat_map(|f| (0..3).map(move |k| (f[k], f[(k + 1) % 3]))).collect();
        directed.sort_unstable();
        assert!(directed.windows(2).all(|w| w[0] != w[1]), "{around}: consistently wound");
        // The fairing's edges between new vertices or from the rim, each new vertex's nearest
        // few of the fairing's vertices found by brute force, and their edges searched.
        let mut edges_of: Vec<Vec<u32>> = vec![Vec::new(); pf.len()];
        for f in &tf[t0.len()..] {
            for k in 0..3 {
                let (a, b) = (f[k], f[(k + 1) % 3]);
                edges_of[a as usize].push(b);
                edges_of[b as usize].push(a);
            }
        }
        let scale = pf[n0..].iter().map(|q| q.length()).fold(0.0, f64::max);
        for q in &pg[n0..] {
            let mut near: Vec<(f64, usize)> =
                (n0..pf.len()).map(|k| (pf[k].distance(*q), k)).collect();
            let few = near.len().min(8);
            near.select_nth_unstable_by(few - 1, |a, b| a.0.total_cmp(&b.0));
            let off = near[..few]
                .iter()
                .flat_map(|&(_, k)| edges_of[k].iter().map(move |&o| (k, o as usize)))
                .map(|(k, o)| segment_distance(*q, pf[k], pf[o]))
                .fold(f64::INFINITY, f64::min);
            assert!(off < 1e-12 * scale, "{around}: {q} {off:e} off the fairing's edges");
        }
        // The triangles on the rim: the same in both (the first ring is kept whole).
        let on_rim = |f: &&[u32; 3]| f.iter().filter(|&&k| (k as usize) < n0).count() == 2;
        let rim_f: Vec<[u32; 3]> = tf[t0.len()..].iter().filter(on_rim).copied().collect();
        let rim_g: Vec<[u32; 3]> = tg[t0.len()..].iter().filter(on_rim).copied().collect();
        assert_eq!(rim_f.len(), rim_g.len(), "{around}");
        for (a, b) in rim_f.iter().zip(&rim_g) {
            for k in 0..3 {
                assert_eq!(pf[a[k] as usize], pg[b[k] as usize], "{around}: a rim triangle moved");
            }
        }
        let smallest = |p: &[DVec3], t: &[[u32; 3]]| {
            t.iter()
                .flat_map(|f| {
                    let c = f.map(|k| p[k as usize]);
                    (0..3).map(move |k| {
                        let (u, v) = (c[(k + 1) % 3] - c[k], c[(k + 2) % 3] - c[k]);
                        u.angle_between(v).to_degrees()
                    })
                })
                .fold(180.0, f64::min)
        };
        let (sg, sf) = (smallest(&pg, &tg[t0.len()..]), smallest(&pf, &tf[t0.len()..]));
        assert!(sg >= sf, "{around}: a cap angle of {sg}°, the fairing's smallest {sf}°");
    }
}

/// Whether `n` faces joined across the edges of `pairs` (edge, face, face) but the sorted
/// `barrier` edges form one piece.
fn faces_connected(n: usize, pairs: &[(u64, u32, u32)], barrier: &[u64]) -> bool {
    let mut parent: Vec<u32> = (0..u32::try_from(n).unwrap_or(u32::MAX)).collect();
    let mut pieces = n;
    for &(key, f, g) in pairs {
        if barrier.binary_search(&key).is_ok() {
            continue;
        }
        let (rf, rg) = (find_root(&mut parent, f), find_root(&mut parent, g));
        if rf != rg {
            parent[rf as usize] = rg;
            pieces -= 1;
        }
    }
    pieces <= 1
}

/// Loops of the edges of `t` (over `n` vertices): for each edge outside a breadth-first tree of
/// the vertices from vertex 0, the loop it closes with the tree (up from its ends to their
/// lowest common ancestor), unless it passes through a vertex of `avoid`.
fn tree_loops(n: usize, t: &[[u32; 3]], avoid: &[bool]) -> Vec<Vec<u32>> {
    let mut edges: Vec<(u32, u32)> = t
        .iter()
        .flat_map(|f| (0..3).map(move |k| (f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3]))))
        .collect();
    edges.sort_unstable();
    edges.dedup();
    let mut around = vec![Vec::new(); n];
    for &(a, b) in &edges {
        around[a as usize].push(b);
        around[b as usize].push(a);
    }
    let (mut parent, mut depth) = (vec![u32::MAX; n], vec![usize::MAX; n]);
    depth[0] = 0;
    let mut queue = std::collections::VecDeque::from([0u32]);
    while let Some(v) = queue.pop_front() {
        for &w in &around[v as usize] {
            if depth[w as usize] == usize::MAX {
                depth[w as usize] = depth[v as usize] + 1;
                parent[w as usize] = v;
                queue.push_back(w);
            }
        }
    }
    edges
        .iter()
        .filter(|&&(a, b)| parent[a as usize] != b && parent[b as usize] != a)
        .filter_map(|&(a, b)| {
            let (mut x, mut y) = (a, b);
            let (mut up, mut down) = (vec![x], vec![y]);
            while x != y {
                if depth[x as usize] >= depth[y as usize] {
                    x = parent[x as usize];
                    up.push(x);
                } else {
                    y = parent[y as usize];
                    down.push(y);
                }
            }
            down.pop(); // the common ancestor, already the last of `up`
            up.extend(down.into_iter().rev());
            (up.len() >= 3 && up.iter().all(|&v| !avoid[v as usize])).then_some(up)
        })
        .collect()
}

#[test]
fn homology_tells_which_disjoint_loops_cut_together_leave_the_surface_whole() {
    // Sets of one to three disjoint loops on a torus, a plate with three holes (genus 3), and
    // the plate with one triangle taken out (a boundary loop, capped by the homology): their
    // classes are independent exactly when the faces stay joined across every other edge,
    // as a union of the faces tells (a different method).
    let plate = voxel_surface([7, 3, 1], |x, y, _| !(y == 1 && x % 2 == 1));
    let mut open = plate.clone();
    open.1.remove(0);
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut random = |below: usize| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % below as u64) as usize
    };
    for (name, (p, t)) in [("torus", torus(12, 6, 1.0, 0.4)), ("plate", plate), ("open", open)] {
        let mut avoid = vec![false; p.len()];
        if name == "open" {
            for &v in &boundary_loops(&t, p.len()).concat() {
                avoid[v as usize] = true;
            }
        }
        let loops = tree_loops(p.len(), &t, &avoid);
        let pairs: Vec<(u64, u32, u32)> = {
            let mut sides: Vec<(u64, u32)> = t
                .iter()
                .enumerate()
                .flat_map(|(f, tri)| {
                    (0..3).map(move |k| (edge_key(tri[k], tri[(k + 1) % 3]), f as u32))
                })
                .collect();
            sides.sort_unstable();
            sides
                .chunk_by(|a, b| a.0 == b.0)
                .filter(|w| w.len() == 2)
                .map(|w| (w[0].0, w[0].1, w[1].1))
                .collect()
        };
        let homology = Homology::new(&t);
        let mut seen = [0usize; 2];
        for _ in 0..3000 {
            let chosen: Vec<&Vec<u32>> =
                (0..1 + random(3)).map(|_| &loops[random(loops.len())]).collect();
            let mut used = std::collections::HashSet::new();
            if !chosen.iter().all(|lp| lp.iter().all(|&v| used.insert(v))) {
                continue; // not disjoint
            }
            let mut barrier: Vec<u64> = chosen
                .iter()
                .flat_map(|lp| (0..lp.len()).map(|i| edge_key(lp[i], lp[(i + 1) % lp.len()])))
                .collect();
            barrier.sort_unstable();
            let whole = faces_connected(t.len(), &pairs, &barrier);
            let mut classes = IndependentClasses::default();
            let independent =
                chosen.iter().all(|lp| classes.insert(homology.of_loop(lp).expect("edges")));
            assert_eq!(whole, independent, "{name}: {chosen:?}");
            seen[usize::from(whole)] += 1;
        }
        // Both answers, many times over.
        assert!(seen[0] > 20 && seen[1] > 20, "{name}: {seen:?}");
    }
}

#[test]
fn blocks_no_cut_touched_give_the_loops_a_new_search_finds() {
    // The plate with three holes, searched in blocks of every size; one handle cut and its
    // sides closed; then the search again, reusing what it found in the blocks whose faces the
    // cut left as they were (and where it placed them), finds what a search of every block
    // finds.
    let (mut p, mut t) = voxel_surface([7, 3, 1], |x, y, _| !(y == 1 && x % 2 == 1));
    let grid = BlockGrid::of(&t, &p).expect("a grid");
    let mut with_loops = 0;
    for side in [2.0, 3.0, 4.0, 8.0] {
        let mut search = BlockSearch::new(grid, side);
        with_loops += usize::from(!search.loops(&t, &p, &[], &[]).is_empty());
        let before = t.clone();
        let (mut scan_vertex, mut filled) = ((0..p.len() as u32).collect(), vec![false; t.len()]);
        let mut repair = Repair::default();
        cut_handles(&mut t, &mut p, &mut scan_vertex, &mut filled, -2, 1, &mut repair);
        assert_eq!(repair.handles_cut, 1);
        let changed: Vec<bool> =
            t.iter().enumerate().map(|(f, x)| before.get(f) != Some(x)).collect();
        // Most faces as they were: the reuse is not all or nothing.
        let kept = changed.iter().filter(|&&c| !c).count();
        assert!(kept > t.len() / 2, "{kept} of {}", t.len());
        let again = search.loops(&t, &p, &[], &changed);
        let mut new_search = BlockSearch::new(grid, side);
        let fresh = new_search.loops(&t, &p, &[], &[]);
        assert_eq!(again, fresh);
        // The faces placed anew only where the cut changed or added them, as if all were.
        for g in 0..2 {
            assert_eq!(search.placed(g), new_search.placed(g), "grid {g}");
        }
        (p, t) = voxel_surface([7, 3, 1], |x, y, _| !(y == 1 && x % 2 == 1));
    }
    assert!(with_loops >= 2, "{with_loops}");
}
