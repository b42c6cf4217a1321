// SPDX-License-Identifier: MIT
//! Meshes built for the tests, whose answers are known.

use glam::DVec3;

/// The icosahedron subdivided `levels` times, projected onto the sphere of radius `r`.
#[allow(dead_code, reason = "not every test file that shares this module builds a sphere")]
pub(crate) fn icosphere(levels: usize, r: f64) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let mut p: Vec<DVec3> = [
        [-1., g, 0.],
        [1., g, 0.],
        [-1., -g, 0.],
        [1., -g, 0.],
        [0., -1., g],
        [0., 1., g],
        [0., -1., -g],
        [0., 1., -g],
        [g, 0., -1.],
        [g, 0., 1.],
        [-g, 0., -1.],
        [-g, 0., 1.],
    ]
    .iter()
    .map(|a| DVec3::from_array(*a).normalize())
    .collect();
    let mut t: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..levels {
        let mut mid = std::collections::HashMap::new();
        let mut next = Vec::with_capacity(4 * t.len());
        for tri in &t {
            let m: Vec<u32> = (0..3)
                .map(|k| {
                    let (a, b) = (tri[k].min(tri[(k + 1) % 3]), tri[k].max(tri[(k + 1) % 3]));
                    *mid.entry((a, b)).or_insert_with(|| {
                        p.push(((p[a as usize] + p[b as usize]) / 2.0).normalize());
                        (p.len() - 1) as u32
                    })
                })
                .collect();
            next.extend([
                [tri[0], m[0], m[2]],
                [tri[1], m[1], m[0]],
                [tri[2], m[2], m[1]],
                [m[0], m[1], m[2]],
            ]);
        }
        t = next;
    }
    (p.into_iter().map(|x| x * r).collect(), t)
}

/// A torus of `major × minor` quads (two triangles each) about the z axis, radii `big` (of
/// the ring) and `small` (of the tube), wound outward.
#[allow(dead_code, reason = "not every test file that shares this module builds a torus")]
pub(crate) fn torus(
    major: usize,
    minor: usize,
    big: f64,
    small: f64,
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let tau = std::f64::consts::TAU;
    let mut p = Vec::with_capacity(major * minor);
    for i in 0..major {
        for j in 0..minor {
            let (u, v) = (tau * i as f64 / major as f64, tau * j as f64 / minor as f64);
            let ring = big + small * v.cos();
            p.push(DVec3::new(ring * u.cos(), ring * u.sin(), small * v.sin()));
        }
    }
    let at = |i: usize, j: usize| ((i % major) * minor + j % minor) as u32;
    let mut t = Vec::with_capacity(2 * major * minor);
    for i in 0..major {
        for j in 0..minor {
            t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    (p, t)
}
