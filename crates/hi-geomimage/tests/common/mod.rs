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

/// The messy meshes the fit takes apart: the zero set of `f` sampled at the nodes of a grid of
/// spacing `h` over the box from `lo` to `hi`, by surface nets, its largest part closed as
/// `closing` asks (holes filled by fans of triangles, flagged) — irregular triangles,
/// slivers, high-valence fans. `f(x, noise)` is given a noise value in [−½, ½) drawn for each
/// node from `seed`; NaN where unknown ends the zero set there. Returns the vertices, the
/// triangles and the filled flags.
#[allow(dead_code, reason = "not every test file that shares this module builds a zero set")]
pub(crate) fn zero_set(
    f: &dyn Fn(DVec3, f64) -> f64,
    lo: DVec3,
    hi: DVec3,
    h: f64,
    closing: hi_scan::repair::Closing,
    seed: u64,
) -> (Vec<DVec3>, Vec<[u32; 3]>, Vec<bool>) {
    let dims = [0, 1, 2].map(|k| ((hi[k] - lo[k]) / h).ceil() as usize + 1);
    let mut state = seed;
    let mut noise = || {
        // SplitMix64.
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let mut values = Vec::with_capacity(dims[0] * dims[1] * dims[2]);
    for k in 0..dims[2] {
        for j in 0..dims[1] {
            for i in 0..dims[0] {
                values.push(f(lo + DVec3::new(i as f64, j as f64, k as f64) * h, noise()));
            }
        }
    }
    let grid = hi_scan::surfacenets::Grid { origin: lo, spacing: h, dims, values: &values };
    let (points, triangles) = hi_scan::surfacenets::surface_nets(&grid).unwrap();
    let parts = hi_scan::repair::mesh_parts(&points, &triangles).unwrap();
    let closed = hi_scan::repair::close_part(&parts.parts[0], closing).unwrap();
    (closed.positions, closed.triangles, closed.filled)
}

/// The most triangles at one vertex.
#[allow(dead_code, reason = "not every test file that shares this module builds a zero set")]
pub(crate) fn max_valence(vertices: usize, triangles: &[[u32; 3]]) -> usize {
    let mut valence = vec![0usize; vertices];
    for tri in triangles {
        for &k in tri {
            valence[k as usize] += 1;
        }
    }
    valence.into_iter().max().unwrap_or(0)
}

/// The iteration budgets of a flat parameterisation, from the reports of its harmonic map
/// `h` alone and relaxed `r` (same mesh): the harmonic solve in tens of multigrid iterations,
/// the relaxation's rounds within six times as many (192 at least), and a relaxation that
/// does not lower the stretch efficiency.
#[allow(dead_code, reason = "not every test file that shares this module parameterises flat")]
pub(crate) fn assert_within_budget(h: &hi_geomimage::FlatReport, r: &hi_geomimage::FlatReport) {
    assert_eq!(h.solve_iterations, h.harmonic_iterations, "the harmonic map alone");
    assert_eq!(r.harmonic_iterations, h.harmonic_iterations, "the same harmonic solve");
    assert!(h.harmonic_iterations <= 60, "{h:?}");
    let budget = (6 * r.harmonic_iterations).max(192);
    assert!(r.solve_iterations <= r.harmonic_iterations + budget, "{r:?}");
    assert!(r.rounds <= 8 && r.sweeps == 2, "{r:?}");
    assert!(r.relaxed.stretch_efficiency >= r.harmonic.stretch_efficiency, "{r:?}");
}
