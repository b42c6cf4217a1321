// SPDX-License-Identifier: MIT
//! A scan's parts and their topology: a mesh of a sphere, a torus and an open sheet with a
//! small hole, split into its three parts; each part's genus and boundary loops against the
//! construction; each made a sphere, a torus or a disc, with the Euler characteristic counted
//! here from the edges; a Möbius band refused.

use std::collections::HashMap;
use std::f64::consts::TAU;

use glam::DVec3;
use hi_scan::repair::{Closing, close_disc_or_sphere, close_part, mesh_parts, part_topology};

/// A u × v grid of quads over `at(i, j)`, wrapping in u and/or v, as triangles; vertex (i, j)
/// is `i * nv + j` (the unwrapped last row or column included).
fn grid(
    nu: u32,
    nv: u32,
    wrap: (bool, bool),
    at: impl Fn(u32, u32) -> DVec3,
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let (ru, rv) = (if wrap.0 { nu } else { nu + 1 }, if wrap.1 { nv } else { nv + 1 });
    let points: Vec<DVec3> = (0..ru * rv).map(|k| at(k / rv, k % rv)).collect();
    let id = |i: u32, j: u32| (i % ru) * rv + j % rv;
    let mut triangles = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            let q = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            triangles.push([q[0], q[1], q[2]]);
            triangles.push([q[0], q[2], q[3]]);
        }
    }
    (points, triangles)
}

/// Appends a mesh to another.
fn append(into: &mut (Vec<DVec3>, Vec<[u32; 3]>), mesh: (Vec<DVec3>, Vec<[u32; 3]>)) {
    let offset = into.0.len() as u32;
    into.0.extend(mesh.0);
    into.1.extend(mesh.1.into_iter().map(|t| t.map(|k| k + offset)));
}

/// V − E + F of a triangle mesh, its edges counted here.
fn euler(points: usize, triangles: &[[u32; 3]]) -> i64 {
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            *edges.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    points as i64 - edges.len() as i64 + triangles.len() as i64
}

/// The three parts: a UV sphere (poles welded), a torus, and a wavy sheet with a small square
/// hole, far apart.
fn three_parts() -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut scan = (Vec::new(), Vec::new());
    // The sphere: rings of a UV grid, its poles welded (same positions).
    append(
        &mut scan,
        grid(24, 32, (false, true), |i, j| {
            let (a, b) = (std::f64::consts::PI * f64::from(i) / 24.0, TAU * f64::from(j) / 32.0);
            match i {
                0 => DVec3::new(0.0, 0.0, 2.0),
                24 => DVec3::new(0.0, 0.0, -2.0),
                _ => DVec3::new(a.sin() * b.cos(), a.sin() * b.sin(), a.cos()) * 2.0,
            }
        }),
    );
    append(
        &mut scan,
        grid(48, 16, (true, true), |i, j| {
            let (a, b) = (TAU * f64::from(i) / 48.0, TAU * f64::from(j) / 16.0);
            DVec3::new(
                (1.0 + 0.3 * b.cos()) * a.cos(),
                (1.0 + 0.3 * b.cos()) * a.sin(),
                0.3 * b.sin(),
            ) + DVec3::new(6.0, 0.0, 0.0)
        }),
    );
    // The sheet, 20 × 20 quads over [0, 2]², with the two triangles of one quad removed.
    let (p, mut t) = grid(20, 20, (false, false), |i, j| {
        let (x, y) = (f64::from(i) / 10.0, f64::from(j) / 10.0);
        DVec3::new(x - 1.0, y - 1.0, 0.2 * (3.0 * x).sin() * y.cos()) + DVec3::new(0.0, 6.0, 0.0)
    });
    t.drain(2 * (10 * 20 + 10)..2 * (10 * 20 + 10) + 2);
    append(&mut scan, (p, t));
    scan
}

#[test]
fn a_scan_splits_into_its_parts_with_their_topology() {
    let (points, triangles) = three_parts();
    let parts = mesh_parts(&points, &triangles).unwrap();
    // The sphere's pole rows are welded: 32 copies of each pole, 31 welded away each.
    assert_eq!(parts.welded_points, 2 * 31);
    assert_eq!(parts.parts.len(), 3);
    // Largest first: the sphere (area ≈ 16π), then the torus (4π² · 0.3 ≈ 11.8), then the sheet
    // (a little over 4).
    let areas: Vec<f64> = parts.parts.iter().map(|p| p.area).collect();
    assert!((areas[0] / (16.0 * std::f64::consts::PI) - 1.0).abs() < 0.02, "{areas:?}");
    assert!((areas[1] / (TAU * TAU * 0.3) - 1.0).abs() < 0.02, "{areas:?}");
    assert!(areas[2] > 4.0 && areas[2] < 4.6, "{areas:?}");
    let topologies: Vec<_> = parts.parts.iter().map(part_topology).collect();
    assert_eq!((topologies[0].genus, topologies[0].loops.len()), (0, 0));
    assert_eq!((topologies[1].genus, topologies[1].loops.len()), (1, 0));
    assert_eq!((topologies[2].genus, topologies[2].loops.len()), (0, 2));
    // The sheet's rim first (80 edges around a cap of about 4), then the hole (4 edges).
    let rim = &topologies[2].loops;
    assert_eq!((rim[0].edges, rim[1].edges), (80, 4));
    assert!(rim[0].span > 3.9 && (rim[1].span - 0.01).abs() < 1e-3, "{rim:?}");
}

#[test]
fn each_part_becomes_the_surface_asked_for() {
    let (points, triangles) = three_parts();
    let parts = mesh_parts(&points, &triangles).unwrap().parts;
    let sphere = close_part(&parts[0], Closing::Sphere).unwrap();
    assert_eq!(euler(sphere.positions.len(), &sphere.triangles), 2);
    assert!(sphere.volume() > 0.0);
    // The torus kept whole, or cut to a sphere.
    let torus = close_part(&parts[1], Closing::Torus).unwrap();
    assert_eq!(euler(torus.positions.len(), &torus.triangles), 0);
    assert_eq!(torus.repair.handles_cut, 0);
    // 2π²Rr², less the few per cent the polygons cut off.
    let ratio = torus.volume() / (2.0 * std::f64::consts::PI.powi(2) * 0.09);
    assert!(ratio > 0.95 && ratio < 1.0, "{ratio}");
    let cut = close_part(&parts[1], Closing::Sphere).unwrap();
    assert_eq!((euler(cut.positions.len(), &cut.triangles), cut.repair.handles_cut), (2, 1));
    assert!(close_part(&parts[0], Closing::Torus).is_err(), "a sphere is no torus");
    assert!(close_part(&parts[0], Closing::Disc).is_err(), "a sphere has no rim");
    // The sheet: its hole closed, its rim kept as a disc's; or both closed as a sphere's.
    let disc = close_part(&parts[2], Closing::Disc).unwrap();
    assert_eq!((disc.repair.holes, euler(disc.positions.len(), &disc.triangles)), (1, 1));
    assert_eq!(disc.filled.iter().filter(|&&f| f).count(), disc.triangles.len() - 798);
    let closed = close_part(&parts[2], Closing::Sphere).unwrap();
    assert_eq!((closed.repair.holes, euler(closed.positions.len(), &closed.triangles)), (2, 2));
}

/// A torus with a hole is a disc once its handle is cut, whatever the hole's size: the loop
/// cut keeps clear of the boundary, and the band of faces along the boundary joins both sides
/// of it. (A search that let the boundary's edges break the cycles of faces found no loop once
/// the hole was a few edges round.)
#[test]
fn a_torus_with_a_hole_is_cut_into_a_disc() {
    for (di, dj) in [(1, 1), (4, 3), (12, 6)] {
        let (nu, nv) = (48u32, 16u32);
        let (points, mut triangles) = grid(nu, nv, (true, true), |i, j| {
            let (a, b) = (TAU * f64::from(i) / f64::from(nu), TAU * f64::from(j) / f64::from(nv));
            DVec3::new(
                (1.0 + 0.3 * b.cos()) * a.cos(),
                (1.0 + 0.3 * b.cos()) * a.sin(),
                0.3 * b.sin(),
            )
        });
        // The quads (i, j) for i < di and j < dj taken out: one boundary loop of 2 (di + dj)
        // edges.
        let quad = |t: usize| ((t / 2) as u32 / nv, (t / 2) as u32 % nv);
        triangles = triangles
            .iter()
            .enumerate()
            .filter(|&(t, _)| {
                let (i, j) = quad(t);
                i >= di || j >= dj
            })
            .map(|(_, t)| *t)
            .collect();
        let parts = mesh_parts(&points, &triangles).unwrap();
        let topology = part_topology(&parts.parts[0]);
        assert_eq!((topology.genus, topology.loops.len()), (1, 1));
        let disc = close_part(&parts.parts[0], Closing::Disc).unwrap();
        assert_eq!(euler(disc.positions.len(), &disc.triangles), 1, "hole {di} × {dj}");
        assert_eq!((disc.repair.handles_cut, disc.repair.holes), (1, 0), "hole {di} × {dj}");
        // The same through the disc-else-sphere closing, which keeps the disc.
        let (again, failed) = close_disc_or_sphere(&parts.parts[0], 32).unwrap();
        assert!(failed.is_none(), "{failed:?}");
        assert_eq!(again.triangles, disc.triangles);
    }
}

/// A disc that keeps a handle no loop clear of its boundary cuts goes on as a sphere from its
/// cuts: a torus whose tube is 3 edges round, with a hole that takes in a vertex of every ring
/// of the tube and of every loop along it (quads (i, 0) for i ≤ 12, then (i, 1) for i ≥ 12).
#[test]
fn a_disc_that_keeps_a_handle_is_closed_as_a_sphere() {
    let (nu, nv) = (24u32, 3u32);
    let (points, triangles) = grid(nu, nv, (true, true), |i, j| {
        let (a, b) = (TAU * f64::from(i) / f64::from(nu), TAU * f64::from(j) / f64::from(nv));
        DVec3::new((1.0 + 0.3 * b.cos()) * a.cos(), (1.0 + 0.3 * b.cos()) * a.sin(), 0.3 * b.sin())
    });
    let hole = |i: u32, j: u32| (j == 0 && i <= 12) || (j == 1 && (12..nu - 1).contains(&i));
    let triangles: Vec<[u32; 3]> = triangles
        .iter()
        .enumerate()
        .filter(|&(t, _)| !hole((t / 2) as u32 / nv, (t / 2) as u32 % nv))
        .map(|(_, t)| *t)
        .collect();
    let parts = mesh_parts(&points, &triangles).unwrap();
    let topology = part_topology(&parts.parts[0]);
    assert_eq!((topology.genus, topology.loops.len()), (1, 1));
    let err = close_part(&parts.parts[0], Closing::Disc).unwrap_err().to_string();
    assert!(err.contains("genus 1"), "{err}");
    let (sphere, failed) = close_disc_or_sphere(&parts.parts[0], 32).unwrap();
    assert_eq!(failed.map(|e| e.to_string()), Some(err));
    // Closed, genus 0: the hole capped and the handle cut.
    assert_eq!(euler(sphere.positions.len(), &sphere.triangles), 2);
    assert_eq!((sphere.repair.holes, sphere.repair.handles_cut), (1, 1));
    assert!(sphere.volume() > 0.0);
}

#[test]
fn a_moebius_band_is_refused() {
    // A strip of 40 × 2 quads whose ends are joined with a half twist.
    let n = 40u32;
    let at = |i: u32, j: u32| {
        let a = TAU * f64::from(i) / f64::from(n);
        let w = f64::from(j) - 1.0;
        let (c, s) = ((a / 2.0).cos(), (a / 2.0).sin());
        DVec3::new((2.0 + 0.5 * w * c) * a.cos(), (2.0 + 0.5 * w * c) * a.sin(), 0.5 * w * s)
    };
    let points: Vec<DVec3> = (0..n * 3).map(|k| at(k / 3, k % 3)).collect();
    let id = |i: u32, j: u32| if i == n { 2 - j } else { 3 * i + j };
    let triangles: Vec<[u32; 3]> = (0..n)
        .flat_map(|i| {
            (0..2).flat_map(move |j| {
                let q = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
                [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]
            })
        })
        .collect();
    let parts = mesh_parts(&points, &triangles).unwrap();
    assert!(parts.parts[0].one_sided);
    let err = close_part(&parts.parts[0], Closing::Disc).unwrap_err().to_string();
    assert!(err.contains("one-sided"), "{err}");
}

/// A hole's cap continues the surface around it: a sphere with its top cut off (every
/// triangle above z = 0.8) is closed by a dome close to the sphere itself, not by a flat lid
/// (which would lie 0.2 below the pole), and the dome meets the rim along the sphere's
/// tangent plane (the angle between the normals across a rim edge stays small).
#[test]
fn a_cap_continues_the_surface_it_closes() {
    let mut mesh = (Vec::new(), Vec::new());
    append(
        &mut mesh,
        grid(48, 64, (false, true), |i, j| {
            let (a, b) = (std::f64::consts::PI * f64::from(i) / 48.0, TAU * f64::from(j) / 64.0);
            match i {
                0 => DVec3::Z,
                48 => -DVec3::Z,
                _ => DVec3::new(a.sin() * b.cos(), a.sin() * b.sin(), a.cos()),
            }
        }),
    );
    let (points, all) = mesh;
    let centroid = |t: &[u32; 3]| t.iter().map(|&k| points[k as usize]).sum::<DVec3>() / 3.0;
    let triangles: Vec<[u32; 3]> = all.into_iter().filter(|t| centroid(t).z <= 0.8).collect();
    let parts = mesh_parts(&points, &triangles).unwrap();
    let closed = close_part(&parts.parts[0], Closing::Sphere).unwrap();
    assert_eq!(closed.repair.holes, 1);
    let cap: Vec<DVec3> = closed
        .positions
        .iter()
        .zip(&closed.scan_vertex)
        .filter(|&(_, &s)| s == hi_scan::repair::ADDED_VERTEX)
        .map(|(p, _)| *p)
        .collect();
    assert!(!cap.is_empty());
    let off = cap.iter().map(|p| (p.length() - 1.0).abs()).fold(0.0, f64::max);
    assert!(off < 0.05, "the cap is {off} off the sphere");
    let top = cap.iter().map(|p| p.z).fold(f64::NEG_INFINITY, f64::max);
    assert!(top > 0.97, "the dome's top at {top}");
    // Across every edge between a scan triangle and a cap triangle, the normals turn by little
    // more than they do between the sphere's own triangles (about 5° at this resolution).
    let normal = |t: &[u32; 3]| {
        let [a, b, c] = t.map(|k| closed.positions[k as usize]);
        (b - a).cross(c - a).normalize()
    };
    let mut by_edge: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (f, t) in closed.triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            by_edge.entry((a.min(b), a.max(b))).or_default().push(f);
        }
    }
    let worst = by_edge
        .values()
        .filter(|fs| fs.len() == 2 && closed.filled[fs[0]] != closed.filled[fs[1]])
        .map(|fs| normal(&closed.triangles[fs[0]]).angle_between(normal(&closed.triangles[fs[1]])))
        .fold(0.0, f64::max);
    assert!(worst.to_degrees() < 12.0, "the rim turns by {}°", worst.to_degrees());
}
