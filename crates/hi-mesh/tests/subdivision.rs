// SPDX-License-Identifier: MIT
//! Algebraic checks of the subdivision schemes of §4.5: counts from Euler's formula, the
//! known values of the peer agreement table (docs/peers.md §3, computed by hand below), limit
//! positions from the closed-form masks, affine invariance, planarity, interpolation.

use glam::{DMat3, DVec3};
use hi_mesh::Error as MeshError;
use hi_mesh::subdivision::{
    LoopWeights, PolyMesh, Scheme, butterfly_step, catmull_clark_limit, catmull_clark_step,
    doo_sabin_step, interpolating_sqrt3_step, loop_limit, loop_step, sqrt3_step,
};

/// A seeded linear congruential generator in [−1, 1).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
    fn vec(&mut self) -> DVec3 {
        DVec3::new(self.next(), self.next(), self.next())
    }
}

/// An m×n torus grid of quads (all valence 4), vertex (i, j) at index i·n + j, perturbed.
fn torus_quads(m: usize, n: usize, noise: f64, seed: u64) -> PolyMesh {
    let mut rng = Lcg(seed);
    let mut positions = Vec::new();
    for i in 0..m {
        for j in 0..n {
            let (u, v) = (
                std::f64::consts::TAU * i as f64 / m as f64,
                std::f64::consts::TAU * j as f64 / n as f64,
            );
            let p = DVec3::new((2.0 + v.cos()) * u.cos(), (2.0 + v.cos()) * u.sin(), v.sin());
            positions.push(p + noise * rng.vec());
        }
    }
    let id = |i: usize, j: usize| ((i % m) * n + j % n) as u32;
    let faces: Vec<[u32; 4]> = (0..m)
        .flat_map(|i| (0..n).map(move |j| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]))
        .collect();
    PolyMesh::try_new(positions, &faces).expect("torus grid")
}

/// The same torus split into triangles along one diagonal (all valence 6).
fn torus_triangles(m: usize, n: usize, noise: f64, seed: u64) -> PolyMesh {
    let quads = torus_quads(m, n, noise, seed);
    let faces: Vec<[u32; 3]> =
        quads.faces().flat_map(|f| [[f[0], f[1], f[2]], [f[0], f[2], f[3]]]).collect();
    PolyMesh::try_new(quads.positions().to_vec(), &faces).expect("torus triangles")
}

/// A flat n×n grid in the plane z = 0 (open), as quads or as triangles.
fn flat_grid(n: usize, triangles: bool) -> PolyMesh {
    let mut rng = Lcg(7);
    let positions = (0..=n)
        .flat_map(|i| (0..=n).map(move |j| (i, j)))
        .map(|(i, j)| DVec3::new(i as f64 + 0.2 * rng.next(), j as f64 + 0.2 * rng.next(), 0.0))
        .collect::<Vec<_>>();
    let id = |i: usize, j: usize| (i * (n + 1) + j) as u32;
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let q = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            if triangles {
                faces.push(vec![q[0], q[1], q[2]]);
                faces.push(vec![q[0], q[2], q[3]]);
            } else {
                faces.push(q.to_vec());
            }
        }
    }
    PolyMesh::try_new(positions, &faces).expect("flat grid")
}

fn closed_shapes() -> Vec<(&'static str, PolyMesh)> {
    vec![
        ("cube", PolyMesh::cube()),
        ("octa", PolyMesh::octahedron()),
        ("tricube", PolyMesh::triangulated_cube()),
        ("star", PolyMesh::star()),
        ("quad-star", PolyMesh::quad_star()),
        ("tri-quad-star", PolyMesh::quad_star().triangulated().expect("fan")),
        ("sharp-star", PolyMesh::sharp_star()),
        ("tri-sharp-star", PolyMesh::sharp_star().triangulated().expect("fan")),
    ]
}

/// The volume enclosed by a closed mesh (divergence theorem over the fan triangles): positive
/// when the faces are counter-clockwise about the outward normal.
fn signed_volume(m: &PolyMesh) -> f64 {
    let p = m.positions();
    m.faces()
        .flat_map(|f| (1..f.len() - 1).map(move |i| [f[0], f[i], f[i + 1]]))
        .map(|[a, b, c]| p[a as usize].dot(p[b as usize].cross(p[c as usize])) / 6.0)
        .sum()
}

#[test]
fn the_quad_star_is_the_cube_with_six_outward_frusta() {
    let star = PolyMesh::quad_star();
    assert!(star.is_closed(), "closed");
    // Cube [−1, 1]³ (volume 8) plus six frusta of height 1.2 between squares of areas 4 and
    // 0.16: h/3·(A₁ + A₂ + √(A₁A₂)) = 0.4·4.96 each.
    let expected = 8.0 + 6.0 * 0.4 * (4.0 + 0.16 + 0.8);
    let vol = signed_volume(&star);
    assert!((vol - expected).abs() < 1e-12, "volume {vol}, expected {expected}");
    let tri = star.triangulated().expect("fan");
    assert!((signed_volume(&tri) - expected).abs() < 1e-12, "the fan keeps the volume");
    assert_eq!(tri.n_edges(), 60 + 30, "one diagonal per quad");
    // The cube's corners have valence 3 + 3 (three cube edges, three spike edges), the tops 3.
    assert_eq!((star.valence(0), star.valence(8)), (6, 3), "valences");
}

#[test]
fn the_sharp_star_is_the_cube_with_six_spikes_of_two_frusta() {
    let star = PolyMesh::sharp_star();
    assert!(star.is_closed(), "closed");
    // Cube [−1, 1]³ (volume 8) plus six spikes: a frustum of height 0.9 between squares of
    // sides 2 and 0.9, and one of height 2.3 between sides 0.9 and 0.2; a frustum's volume is
    // h/3·(A₁ + A₂ + √(A₁A₂)).
    let neck = 0.9 / 3.0 * (4.0 + 0.81 + 1.8);
    let point = 2.3 / 3.0 * (0.81 + 0.04 + 0.18);
    let expected = 8.0 + 6.0 * (neck + point);
    let vol = signed_volume(&star);
    assert!((vol - expected).abs() < 1e-12, "volume {vol}, expected {expected}");
    let tri = star.triangulated().expect("fan");
    assert!((signed_volume(&tri) - expected).abs() < 1e-12, "the fan keeps the volume");
    assert_eq!(tri.n_edges(), 108 + 54, "one diagonal per quad");
    // The tips reach 4.2 from the centre along the axes, the cube's corners √3.
    let reach = star.positions().iter().map(|p| p.abs().max_element()).fold(0.0, f64::max);
    assert!((reach - 4.2).abs() < 1e-12, "reach {reach}");
    // The cube's corners have valence 6, the necks 4, the tips 3.
    assert_eq!((star.valence(0), star.valence(8), star.valence(12)), (6, 4, 3), "valences");
}

#[test]
fn the_fan_of_the_cube_is_the_triangulated_cube() {
    let fan = PolyMesh::cube().triangulated().expect("fan");
    let fixed = PolyMesh::triangulated_cube();
    assert_eq!(fan.positions(), fixed.positions(), "same vertices");
    assert!(fan.faces().eq(fixed.faces()), "same triangles in the same order");
}

fn is_triangle_mesh(m: &PolyMesh) -> bool {
    m.faces().all(|f| f.len() == 3)
}

fn nearest(mesh: &PolyMesh, q: DVec3) -> DVec3 {
    *mesh
        .positions()
        .iter()
        .min_by(|a, b| (**a - q).length().total_cmp(&(**b - q).length()))
        .expect("non-empty mesh")
}

#[test]
fn counts_follow_euler() {
    for (name, mesh) in closed_shapes() {
        for scheme in Scheme::ALL {
            if !is_triangle_mesh(&mesh)
                && !matches!(scheme, Scheme::CatmullClark | Scheme::DooSabin)
            {
                continue;
            }
            let mut m = mesh.clone();
            for step in 1..=2 {
                let (v, e, f) = (m.n_vertices(), m.n_edges(), m.n_faces());
                let sides: usize = m.faces().map(<[u32]>::len).sum();
                let next = scheme.step(&m).expect("closed mesh");
                let expected = match scheme {
                    Scheme::Loop(_) | Scheme::Butterfly => (v + e, 2 * e + 3 * f, 4 * f),
                    Scheme::Sqrt3 | Scheme::InterpolatingSqrt3 => (v + f, e + 3 * f, 3 * f),
                    Scheme::CatmullClark => (v + e + f, 2 * e + sides, sides),
                    Scheme::DooSabin => (sides, 2 * sides, f + e + v),
                    _ => unreachable!("all schemes are listed"),
                };
                let got = (next.n_vertices(), next.n_edges(), next.n_faces());
                assert_eq!(got, expected, "{} on {name}, step {step}", scheme.name());
                assert_eq!(got.0 + got.2, got.1 + 2, "Euler, {} on {name}", scheme.name());
                assert!(next.is_closed());
                m = next;
            }
        }
    }
}

// ---- the agreement table of docs/peers.md §3 (values derived by hand in the comments) ----

#[test]
fn loop_octahedron_known_values() {
    let octa = PolyMesh::octahedron();
    let once = loop_step(&octa, LoopWeights::Loop).expect("Loop");
    // β(4) = (5/8 − 9/64)/4 = 31/256; x = 1 − 4β = 132/256.
    assert_eq!(once.positions()[0], DVec3::new(0.515625, 0.0, 0.0));
    // Edge (1,0,0)–(0,1,0): 3/8·(a + b) + 1/8·((0,0,1) + (0,0,−1)).
    assert!(
        (nearest(&once, DVec3::new(0.5, 0.5, 0.0)) - DVec3::new(0.375, 0.375, 0.0)).length()
            < 1e-15
    );
    let twice = loop_step(&once, LoopWeights::Loop).expect("Loop");
    assert!((twice.positions()[0].x - 0.447510).abs() < 5e-7, "{}", twice.positions()[0]);
    let e = nearest(&twice, DVec3::new(0.5, 0.5, 0.0));
    assert!((e - DVec3::new(0.313477, 0.313477, 0.0)).abs().max_element() < 5e-7, "{e}");
}

#[test]
fn butterfly_octahedron_known_values() {
    let octa = PolyMesh::octahedron();
    let mut m = octa.clone();
    for _ in 0..2 {
        m = butterfly_step(&m).expect("butterfly");
        assert_eq!(m.positions()[0], DVec3::X);
        // Both ends valence 4: ((3/4, 1/2, 0) + (1/2, 3/4, 0))/2; after the second step the
        // edge point of the edge (1,0,0)–(.625,.625,0) lies elsewhere, but this vertex stays.
        assert!(m.positions().contains(&DVec3::new(0.625, 0.625, 0.0)));
    }
}

#[test]
fn sqrt3_octahedron_known_values() {
    let octa = PolyMesh::octahedron();
    let once = sqrt3_step(&octa).expect("√3");
    assert!((once.positions()[0].x - 5.0 / 9.0).abs() < 1e-15);
    assert!((once.positions()[6] - DVec3::splat(1.0 / 3.0)).length() < 1e-15);
    let twice = sqrt3_step(&once).expect("√3");
    // Table: 0.456790 = 37/81 (6 decimals).
    assert!((twice.positions()[0].x - 0.456790).abs() < 5e-7, "{}", twice.positions()[0]);
}

#[test]
fn interpolating_sqrt3_octahedron_known_value() {
    let once = interpolating_sqrt3_step(&PolyMesh::octahedron()).expect("interpolating √3");
    let m = nearest(&once, DVec3::splat(0.5));
    assert!((m - DVec3::new(0.481482, 0.481482, 0.481481)).abs().max_element() < 1e-6, "{m}");
}

#[test]
fn catmull_clark_cube_known_values() {
    let once = catmull_clark_step(&PolyMesh::cube()).expect("CC");
    assert!((once.positions()[0] - DVec3::splat(2.0 / 9.0)).length() < 1e-15);
    let twice = catmull_clark_step(&once).expect("CC");
    assert!((twice.positions()[0] - DVec3::splat(0.245370)).abs().max_element() < 5e-7);
}

#[test]
fn doo_sabin_cube_known_values() {
    let once = doo_sabin_step(&PolyMesh::cube()).expect("DS");
    assert!(
        (nearest(&once, DVec3::new(0.0, 0.25, 0.25)) - DVec3::new(0.0, 0.25, 0.25)).length()
            < 1e-15
    );
    let twice = doo_sabin_step(&once).expect("DS");
    let q = DVec3::new(0.208333, 0.083333, 0.208333);
    assert!((nearest(&twice, q) - q).abs().max_element() < 5e-7);
    // Every vertex is a convex combination of the corners: in the closed cube.
    assert!(twice.positions().iter().all(|p| p.min_element() >= 0.0 && p.max_element() <= 1.0));
}

// ---- limits ----

#[test]
fn loop_limit_of_regular_vertex_is_the_box_spline_mask() {
    let (m, n) = (6, 7);
    let mesh = torus_triangles(m, n, 0.1, 1);
    let p = mesh.positions();
    let limit = loop_limit(&mesh, LoopWeights::Loop).expect("limit");
    let warren = loop_limit(&mesh, LoopWeights::Warren).expect("limit");
    let id = |i: usize, j: usize| (i % m) * n + j % n;
    for i in 0..m {
        for j in 0..n {
            // The six neighbours in the grid triangulated along (i, j)–(i + 1, j + 1).
            let ring = [
                id(i + 1, j),
                id(i + 1, j + 1),
                id(i, j + 1),
                id(i + m - 1, j),
                id(i + m - 1, j + n - 1),
                id(i, j + n - 1),
            ];
            let sum: DVec3 = ring.iter().map(|&k| p[k]).sum();
            let expected = 0.5 * p[id(i, j)] + sum / 12.0;
            assert!((limit[id(i, j)].position - expected).length() < 1e-14);
            assert!((warren[id(i, j)].position - expected).length() < 1e-14);
        }
    }
}

#[test]
fn loop_limit_is_the_fixed_point_of_subdivision() {
    for mesh in [PolyMesh::octahedron(), PolyMesh::star()] {
        let limit = loop_limit(&mesh, LoopWeights::Loop).expect("limit");
        let mut m = mesh.clone();
        let mut errors = Vec::new();
        for _ in 0..6 {
            m = loop_step(&m, LoopWeights::Loop).expect("Loop");
            let err = (0..mesh.n_vertices())
                .map(|v| (m.positions()[v] - limit[v].position).length())
                .fold(0.0, f64::max);
            errors.push(err);
        }
        // The error shrinks geometrically (ratio ≤ the subdominant eigenvalue, < 0.7 here).
        assert!(errors.windows(2).all(|w| w[1] < 0.7 * w[0]), "{errors:?}");
        assert!(errors[5] < 2e-2 * errors[0], "{errors:?}");
    }
}

#[test]
fn loop_limit_normals_of_a_sphere_like_mesh_point_outward() {
    let limit = loop_limit(&PolyMesh::star(), LoopWeights::Loop).expect("limit");
    for (v, l) in limit.iter().enumerate() {
        let n = l.normal.expect("interior vertex");
        let radial = PolyMesh::star().positions()[v].normalize();
        assert!(n.dot(radial) > 0.99, "vertex {v}: {n}");
    }
}

#[test]
fn catmull_clark_limit_of_regular_vertex_is_the_bicubic_mask() {
    let (m, n) = (5, 6);
    let mesh = torus_quads(m, n, 0.1, 2);
    let p = mesh.positions();
    let limit = catmull_clark_limit(&mesh).expect("limit");
    let id = |i: usize, j: usize| (i % m) * n + j % n;
    for i in 0..m {
        for j in 0..n {
            let (ip, im, jp, jm) = (i + 1, i + m - 1, j + 1, j + n - 1);
            let e = p[id(ip, j)] + p[id(im, j)] + p[id(i, jp)] + p[id(i, jm)];
            let f = p[id(ip, jp)] + p[id(ip, jm)] + p[id(im, jp)] + p[id(im, jm)];
            // Tensor product of the cubic B-spline limit mask (1, 4, 1)/6.
            let expected = (16.0 * p[id(i, j)] + 4.0 * e + f) / 36.0;
            assert!((limit[id(i, j)].position - expected).length() < 1e-14);
            // Tangents of the bicubic B-spline: along i, (p₊ − p₋)·4 + corner differences.
            let du = 4.0 * (p[id(ip, j)] - p[id(im, j)])
                + (p[id(ip, jp)] - p[id(im, jp)])
                + (p[id(ip, jm)] - p[id(im, jm)]);
            let dv = 4.0 * (p[id(i, jp)] - p[id(i, jm)])
                + (p[id(ip, jp)] - p[id(ip, jm)])
                + (p[id(im, jp)] - p[id(im, jm)]);
            let normal = du.cross(dv).normalize();
            let got = limit[id(i, j)].normal.expect("interior");
            assert!((got - normal).length() < 1e-12, "({i}, {j}): {got} vs {normal}");
        }
    }
}

#[test]
fn catmull_clark_limit_is_the_fixed_point_of_subdivision() {
    let mesh = catmull_clark_step(&PolyMesh::cube()).expect("CC");
    let limit = catmull_clark_limit(&mesh).expect("limit");
    let mut m = mesh.clone();
    for _ in 0..5 {
        m = catmull_clark_step(&m).expect("CC");
    }
    let err = (0..mesh.n_vertices())
        .map(|v| (m.positions()[v] - limit[v].position).length())
        .fold(0.0, f64::max);
    assert!(err < 1e-3, "{err}");
}

#[test]
fn limit_normals_are_unit_and_planar_grids_have_normal_z() {
    let grid = catmull_clark_step(&flat_grid(4, false)).expect("CC");
    for (v, l) in catmull_clark_limit(&grid).expect("limit").iter().enumerate() {
        if grid.is_boundary_vertex(v) {
            assert!(l.normal.is_none());
            assert_eq!(l.position.z, 0.0);
        } else {
            assert!((l.normal.expect("interior") - DVec3::Z).length() < 1e-12);
        }
    }
    let grid = flat_grid(4, true);
    for (v, l) in loop_limit(&grid, LoopWeights::Warren).expect("limit").iter().enumerate() {
        if !grid.is_boundary_vertex(v) {
            assert!((l.normal.expect("interior") - DVec3::Z).length() < 1e-12);
        }
    }
}

// ---- invariances ----

#[test]
fn schemes_are_affine_invariant() {
    let a = DMat3::from_cols(
        DVec3::new(1.2, 0.3, -0.1),
        DVec3::new(-0.4, 0.9, 0.2),
        DVec3::new(0.1, 0.5, 1.7),
    );
    let t = DVec3::new(3.0, -2.0, 0.5);
    let map = |p: DVec3| a * p + t;
    for (name, mesh) in closed_shapes() {
        let mapped = mesh.try_map_positions(map).expect("finite");
        for scheme in Scheme::ALL.into_iter().chain([Scheme::Loop(LoopWeights::Warren)]) {
            let (Ok(x), Ok(y)) = (scheme.steps(&mesh, 2), scheme.steps(&mapped, 2)) else {
                continue;
            };
            for (p, q) in x.positions().iter().zip(y.positions()) {
                assert!((map(*p) - *q).length() < 1e-12, "{} on {name}", scheme.name());
            }
        }
    }
}

#[test]
fn planar_grids_stay_planar() {
    for (scheme, tri) in [
        (Scheme::Loop(LoopWeights::Loop), true),
        (Scheme::Loop(LoopWeights::Warren), true),
        (Scheme::CatmullClark, false),
        (Scheme::CatmullClark, true),
    ] {
        let m = scheme.steps(&flat_grid(5, tri), 2).expect("open meshes have boundary rules");
        assert!(m.positions().iter().all(|p| p.z == 0.0), "{}", scheme.name());
        assert!(!m.is_closed());
    }
}

#[test]
fn boundary_curves_follow_the_cubic_b_spline_rules() {
    // The bottom row of a flat grid is a boundary polygon; Loop and Catmull-Clark refine it
    // as a cubic B-spline curve: new edge points are midpoints, old points 1/8, 3/4, 1/8.
    let grid = flat_grid(4, false);
    let row: Vec<DVec3> = (0..5).map(|i| grid.positions()[i * 5]).collect(); // j = 0
    let once = catmull_clark_step(&grid).expect("CC");
    for i in 1..4 {
        let expected = 0.125 * (row[i - 1] + row[i + 1]) + 0.75 * row[i];
        assert!((once.positions()[i * 5] - expected).length() < 1e-15);
        assert!(
            (nearest(&once, 0.5 * (row[i] + row[i + 1])) - 0.5 * (row[i] + row[i + 1])).length()
                < 1e-15
        );
    }
}

#[test]
fn interpolating_schemes_keep_the_original_vertices_exactly() {
    let noisy = torus_triangles(5, 6, 0.2, 3);
    for mesh in [PolyMesh::octahedron(), PolyMesh::triangulated_cube(), PolyMesh::star(), noisy] {
        for scheme in [Scheme::Butterfly, Scheme::InterpolatingSqrt3] {
            assert!(scheme.is_interpolating());
            let m = scheme.steps(&mesh, 2).expect("closed triangle mesh");
            assert_eq!(&m.positions()[..mesh.n_vertices()], mesh.positions(), "{}", scheme.name());
        }
    }
}

#[test]
fn loop_and_warren_weights() {
    // Valence 6: both give β = 1/16, so on an all-valence-6 torus the steps agree.
    assert!((LoopWeights::Loop.beta(6) - 1.0 / 16.0).abs() < 1e-17);
    assert_eq!(LoopWeights::Warren.beta(6), 1.0 / 16.0);
    assert_eq!(LoopWeights::Warren.beta(3), 3.0 / 16.0);
    // Loop's β(3): cos(2π/3) = −1/2, (5/8 − (1/4)²)/3 = 3/16, the same as Warren's.
    assert!((LoopWeights::Loop.beta(3) - 3.0 / 16.0).abs() < 1e-16);
    let torus = torus_triangles(6, 6, 0.1, 4);
    let a = loop_step(&torus, LoopWeights::Loop).expect("Loop");
    let b = loop_step(&torus, LoopWeights::Warren).expect("Loop");
    for (p, q) in a.positions().iter().zip(b.positions()) {
        assert!((*p - *q).length() < 1e-15);
    }
    // On the octahedron (valence 4) they differ: Warren's β = 3/32 gives x = 1 − 12/32.
    let w = loop_step(&PolyMesh::octahedron(), LoopWeights::Warren).expect("Loop");
    assert_eq!(w.positions()[0], DVec3::new(0.625, 0.0, 0.0));
}

#[test]
fn butterfly_regular_stencil_is_the_eight_point_butterfly() {
    // On an all-valence-6 torus every edge uses the regular stencil; w = 0 is the default.
    let torus = torus_triangles(6, 7, 0.1, 5);
    let a = butterfly_step(&torus).expect("butterfly");
    let b = hi_mesh::subdivision::butterfly_step_with_tension(&torus, 0.0).expect("w = 0");
    let c = hi_mesh::subdivision::butterfly_step_with_tension(&torus, 1.0 / 32.0).expect("w");
    assert_eq!(a, b);
    assert_ne!(a.positions(), c.positions());
    // The 8-point stencil, by hand, for the edge from vertex (0,0) to (1,0) of the grid.
    let (m, n) = (6, 7);
    let p = torus.positions();
    let id = |i: usize, j: usize| (i % m) * n + j % n;
    let (va, vb) = (id(0, 0), id(1, 0));
    // Quad (i, j) → triangles [(i,j), (i+1,j), (i+1,j+1)] and [(i,j), (i+1,j+1), (i,j+1)]:
    // the edge (0,0)–(1,0) has opposite vertices (1,1) and (0,n−1), and the triangles beyond
    // its four wing edges have tips (2,1), (0,1), (1,n−1) and (m−1,n−1).
    let c_ = id(1, 1);
    let d_ = id(0, n - 1);
    let e = [id(2, 1), id(0, 1), id(1, n - 1), id(m - 1, n - 1)];
    let expected = 0.5 * (p[va] + p[vb]) + 0.125 * (p[c_] + p[d_])
        - 0.0625 * e.iter().map(|&k| p[k]).sum::<DVec3>();
    let found = nearest(&a, expected);
    assert!((found - expected).length() < 1e-14, "{found} vs {expected}");
}

// ---- errors ----

#[test]
fn wrong_primitives_and_open_meshes_are_errors() {
    let cube = PolyMesh::cube();
    for scheme in [
        Scheme::Loop(LoopWeights::Loop),
        Scheme::Butterfly,
        Scheme::Sqrt3,
        Scheme::InterpolatingSqrt3,
    ] {
        let err = scheme.step(&cube).expect_err("quads");
        assert!(matches!(err, MeshError::WrongPrimitive { face: 0, n_sides: 4, .. }), "{err}");
        assert!(err.to_string().contains("face 0 has 4 sides"), "{err}");
    }
    let open = flat_grid(3, true);
    for scheme in [Scheme::Butterfly, Scheme::Sqrt3, Scheme::InterpolatingSqrt3, Scheme::DooSabin] {
        let err = scheme.step(&open).expect_err("open mesh");
        assert!(matches!(err, MeshError::OpenMesh { .. }), "{err}");
        assert!(err.to_string().contains("boundary edge"), "{err}");
    }
    let err = catmull_clark_limit(&PolyMesh::octahedron()).expect_err("triangles");
    assert!(matches!(err, MeshError::WrongPrimitive { n_sides: 3, .. }));
    let err = loop_limit(&cube, LoopWeights::Loop).expect_err("quads");
    assert!(matches!(err, MeshError::WrongPrimitive { n_sides: 4, .. }));
}

#[test]
fn doo_sabin_and_catmull_clark_take_any_polygons() {
    // A pentagonal prism: two pentagons and five quads.
    let mut positions = Vec::new();
    for z in [0.0, 1.0] {
        for k in 0..5 {
            let a = std::f64::consts::TAU * k as f64 / 5.0;
            positions.push(DVec3::new(a.cos(), a.sin(), z));
        }
    }
    let mut faces: Vec<Vec<u32>> = vec![vec![4, 3, 2, 1, 0], vec![5, 6, 7, 8, 9]];
    for k in 0..5u32 {
        faces.push(vec![k, (k + 1) % 5, 5 + (k + 1) % 5, 5 + k]);
    }
    let prism = PolyMesh::try_new(positions, &faces).expect("prism");
    let cc = catmull_clark_step(&prism).expect("CC");
    assert_eq!((cc.n_vertices(), cc.n_faces()), (10 + 15 + 7, 30));
    assert!(cc.faces().all(|f| f.len() == 4));
    let ds = doo_sabin_step(&prism).expect("DS");
    assert_eq!((ds.n_vertices(), ds.n_faces()), (30, 7 + 15 + 10));
    // By the symmetry of the regular pentagon, the Doo-Sabin vertex of its first corner
    // (vertex 4) lies on the ray from the pentagon's centre through that corner.
    let c = ds.positions()[0];
    assert!(c.truncate().perp_dot(prism.positions()[4].truncate()).abs() < 1e-12);
}
