// SPDX-License-Identifier: MIT
//! The parameterisation of disc-like meshes over the unit square and the mirror doubling of its
//! images, checked on meshes built here whose answers are known: a hemisphere (its surface,
//! its equator), a height field over a square (its function, its corners), and meshes of the
//! wrong topology; and on a sheet as messy as the zero sets of scans, for what the solves take.

use std::f64::consts::{FRAC_PI_2, TAU};

use glam::{DVec2, DVec3};
use hi_geomimage::discparam::{
    DiscParam, DiscParamOptions, parameterise_disc, reflect_periodic, reflect_periodic_mask,
};
use hi_geomimage::{Error, NonFiniteInput};

mod common;
use common::{assert_within_budget, icosphere, max_valence, zero_set};

/// A small deterministic generator (`SplitMix64`), uniform in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The upper unit hemisphere, open at the equator: a pole and `rings` rings of `around`
/// vertices (each ring turned by a random fraction of a step), wound outward.
fn hemisphere(rings: usize, around: usize, rng: &mut Rng) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut p = vec![DVec3::Z];
    for k in 1..=rings {
        let th = FRAC_PI_2 * k as f64 / rings as f64;
        let turn = if k < rings { rng.next() } else { 0.0 };
        for j in 0..around {
            let ph = TAU * (j as f64 + turn) / around as f64;
            p.push(DVec3::new(th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()));
        }
    }
    let at = |k: usize, j: usize| (1 + (k - 1) * around + j % around) as u32;
    let mut t = Vec::new();
    for j in 0..around {
        t.push([0, at(1, j), at(1, j + 1)]);
    }
    for k in 1..rings {
        for j in 0..around {
            t.push([at(k, j), at(k + 1, j), at(k + 1, j + 1)]);
            t.push([at(k, j), at(k + 1, j + 1), at(k, j + 1)]);
        }
    }
    (p, t)
}

/// The height z = 0.3 sin 3x cos 2y.
fn height(x: f64, y: f64) -> f64 {
    0.3 * (3.0 * x).sin() * (2.0 * y).cos()
}

/// The height field over [−1, 1]² on an n × n grid: interior vertices jittered by up to 0.3 of
/// a cell, boundary ones along their side only (the corners stay), each quad split along a
/// random diagonal; wound counter-clockwise seen from +z.
fn height_field(n: usize, rng: &mut Rng) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let h = 2.0 / (n - 1) as f64;
    let mut p = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (mut x, mut y) = (-1.0 + h * j as f64, -1.0 + h * i as f64);
            let (inner_i, inner_j) = (i > 0 && i < n - 1, j > 0 && j < n - 1);
            if inner_j {
                x += 0.3 * h * (2.0 * rng.next() - 1.0);
            }
            if inner_i {
                y += 0.3 * h * (2.0 * rng.next() - 1.0);
            }
            p.push(DVec3::new(x, y, height(x, y)));
        }
    }
    let mut t = Vec::new();
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            let a = (i * n + j) as u32;
            let (b, c, d) = (a + 1, a + n as u32 + 1, a + n as u32);
            if rng.next() < 0.5 {
                t.push([a, b, c]);
                t.push([a, c, d]);
            } else {
                t.push([a, b, d]);
                t.push([b, c, d]);
            }
        }
    }
    (p, t)
}

/// The boundary loop's segments: the edges in one triangle only.
fn boundary_segments(t: &[[u32; 3]]) -> Vec<(u32, u32)> {
    let mut edges = std::collections::HashMap::new();
    for tri in t {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    edges.into_iter().filter(|&(_, c)| c == 1).map(|(e, _)| e).collect()
}

/// The distance from x to the segment ab.
fn segment_distance(x: DVec3, a: DVec3, b: DVec3) -> f64 {
    let d = b - a;
    let s = ((x - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    (a + s * d - x).length()
}

/// The checks every disc map must pass: no fold, area 1, boundary on the square's boundary,
/// interior inside, boundary texels on the boundary polyline, orientation, and the
/// reflection's symmetry and interpolation.
fn check_disc(param: &DiscParam, p: &[DVec3], t: &[[u32; 3]], label: &str) {
    let q = param.quality();
    println!("{label}: {:?}, aspect {:.4}", param.report(), param.aspect());
    assert_eq!(q.folded_triangles, 0, "{label}");
    assert_eq!(q.flat_triangles, 0, "{label}");
    let mut area = 0.0;
    for f in 0..t.len() {
        let [a, b, c] = param.uv_triangle(f);
        let d = (b - a).perp_dot(c - a);
        assert!(d > 0.0, "{label}: triangle {f} not counter-clockwise in (u, v)");
        area += 0.5 * d;
    }
    assert!((area - 1.0).abs() < 1e-12, "{label}: (u, v) area {area}");
    let segments = boundary_segments(t);
    let mut on_boundary = vec![false; p.len()];
    for &(a, b) in &segments {
        on_boundary[a as usize] = true;
        on_boundary[b as usize] = true;
    }
    for (v, uv) in param.uv().iter().enumerate() {
        let edge = uv.x == 0.0 || uv.x == 1.0 || uv.y == 0.0 || uv.y == 1.0;
        let inside = uv.x > 0.0 && uv.x < 1.0 && uv.y > 0.0 && uv.y < 1.0;
        if on_boundary[v] {
            assert!(
                edge && uv.clamp(DVec2::ZERO, DVec2::ONE) == *uv,
                "{label}: boundary vertex {v} at {uv}"
            );
        } else {
            assert!(inside, "{label}: interior vertex {v} at {uv}");
        }
    }
    for corner in param.corner_vertices() {
        let uv = param.uv()[corner as usize];
        assert!(uv.x.fract() == 0.0 && uv.y.fract() == 0.0, "{label}: corner at {uv}");
    }
    // The image: boundary texels on the boundary polyline; interior texels facing the way
    // the mesh's normals do (checked by the caller's normal).
    let (rows, cols) = (33, 41);
    let image = param.image(rows, cols).unwrap();
    for i in 0..rows {
        for j in 0..cols {
            if i == 0 || j == 0 || i == rows - 1 || j == cols - 1 {
                let x = image.image.get(i, j);
                let d = segments
                    .iter()
                    .map(|&(a, b)| segment_distance(x, p[a as usize], p[b as usize]))
                    .fold(f64::INFINITY, f64::min);
                assert!(d < 1e-12, "{label}: boundary texel ({i}, {j}) {d} off the boundary");
            }
        }
    }
    // The doubling: exact mirror symmetry, the square in its first quarter.
    let doubled = reflect_periodic(&image.image).unwrap();
    let (big_r, big_c) = (2 * (rows - 1), 2 * (cols - 1));
    assert_eq!((doubled.rows(), doubled.cols()), (big_r, big_c), "doubled size");
    for i in 0..big_r {
        for j in 0..big_c {
            let x = doubled.get(i, j);
            assert_eq!(x, doubled.get((big_r - i) % big_r, j), "mirror in u");
            assert_eq!(x, doubled.get(i, (big_c - j) % big_c), "mirror in v");
            if i < rows && j < cols {
                assert_eq!(x, image.image.get(i, j), "the first quarter is the square");
            }
        }
    }
    let mask = reflect_periodic_mask(&image.filled, rows, cols).unwrap();
    assert_eq!(mask.len(), big_r * big_c, "doubled mask");
    // The harmonic surface through it: through the square's texels, even about u = ½ and
    // v = ½, flat across the boundary.
    let surface = doubled.surface().unwrap();
    let scale = image.image.texels().iter().map(|x| x.length()).fold(0.0, f64::max);
    for i in (0..rows).step_by(4) {
        for j in (0..cols).step_by(5) {
            let x = surface.eval(i as f64 / big_r as f64, j as f64 / big_c as f64);
            assert!(
                (x - image.image.get(i, j)).length() < 1e-11 * scale,
                "{label}: interpolation at ({i}, {j})"
            );
        }
    }
    let mut rng = Rng(5);
    for _ in 0..50 {
        let (s, v) = (0.5 * rng.next(), rng.next());
        let (a, b) = (surface.eval(0.5 + s, v), surface.eval(0.5 - s, v));
        assert!((a - b).length() < 1e-11 * scale, "{label}: symmetry about u = ½");
        let (a, b) = (surface.eval(v, 0.5 + s), surface.eval(v, 0.5 - s));
        assert!((a - b).length() < 1e-11 * scale, "{label}: symmetry about v = ½");
        for edge in [0.0, 0.5] {
            let du = surface.eval_deriv(edge, v, 1, 0);
            let dv = surface.eval_deriv(v, edge, 0, 1);
            assert!(
                du.length() < 1e-9 * scale && dv.length() < 1e-9 * scale,
                "{label}: derivative across the boundary"
            );
        }
    }
}

#[test]
fn a_hemisphere_maps_onto_the_square() {
    let mut rng = Rng(11);
    // 6401 vertices: the solves go through multigrid.
    let (p, t) = hemisphere(40, 160, &mut rng);
    let filled = vec![false; t.len()];
    for options in [DiscParamOptions::harmonic(), DiscParamOptions::default()] {
        let param = parameterise_disc(&p, &t, &filled, &options).unwrap();
        check_disc(&param, &p, &t, "hemisphere");
        // Every texel lies on a triangle, so no nearer the centre than the triangles' planes:
        // |x| ≥ √(1 − R²), R the largest circumradius (the triangle lies in its circumcircle,
        // which is the sphere's section by its plane).
        let big_r = t
            .iter()
            .map(|tri| {
                let [a, b, c] = tri.map(|k| p[k as usize]);
                let (x, y, z) = ((b - c).length(), (c - a).length(), (a - b).length());
                x * y * z / (2.0 * (b - a).cross(c - a).length())
            })
            .fold(0.0, f64::max);
        let floor = (1.0 - big_r * big_r).sqrt();
        let image = param.image(40, 40).unwrap();
        for x in image.image.texels() {
            assert!(
                x.length() >= floor - 1e-12 && x.length() <= 1.0 + 1e-12,
                "texel {x} at {}",
                x.length()
            );
            assert!(x.z >= -1e-12, "on the upper half");
        }
        // Outward: the texels' grid turns the way the sphere's outward normal does.
        for i in 1..39 {
            for j in 1..39 {
                let x = image.image.get(i, j);
                let n = (image.image.get(i + 1, j) - x).cross(image.image.get(i, j + 1) - x);
                assert!(n.dot(x) > 0.0, "texel ({i}, {j}): normal points inward");
            }
        }
        // The harmonic surface through the doubled image faces out on its open sheet.
        let surface = reflect_periodic(&image.image).unwrap().surface().unwrap();
        for k in 1..10 {
            for l in 1..10 {
                let (u, v) = (0.05 * k as f64, 0.05 * l as f64);
                let (x, pu, pv) = surface.eval_with_partials(u, v);
                assert!(pu.cross(pv).dot(x) > 0.0, "surface normal at ({u}, {v}) points inward");
            }
        }
    }
}

#[test]
fn a_height_field_maps_onto_the_square_with_its_corners_at_the_corners() {
    let mut rng = Rng(23);
    let n = 33;
    let (p, t) = height_field(n, &mut rng);
    let filled = vec![false; t.len()];
    let harmonic = parameterise_disc(&p, &t, &filled, &DiscParamOptions::harmonic()).unwrap();
    let param = parameterise_disc(&p, &t, &filled, &DiscParamOptions::default()).unwrap();
    for (name, m) in [("harmonic", &harmonic), ("relaxed", &param)] {
        check_disc(m, &p, &t, name);
        let mut corners = m.corner_vertices();
        corners.sort_unstable();
        let last = (n * n - 1) as u32;
        assert_eq!(
            corners,
            [0, n as u32 - 1, last + 1 - n as u32, last],
            "{name}: the grid's corners"
        );
        // Interior texels on the height field within the linear interpolation error
        // ½ M h², M = 0.3 · 13 bounding the second derivative of 0.3 sin 3x cos 2y along any
        // unit direction (0.3 (3|a| + 2|b|)² ≤ 0.3 · 13), h the longest edge in the plane.
        let h = t
            .iter()
            .flat_map(|tri| (0..3).map(move |k| (tri[k], tri[(k + 1) % 3])))
            .map(|(a, b)| (p[a as usize] - p[b as usize]).truncate().length())
            .fold(0.0, f64::max);
        let bound = 0.5 * 0.3 * 13.0 * h * h;
        let image = m.image(48, 48).unwrap();
        let mut worst = 0.0f64;
        for x in image.image.texels() {
            worst = worst.max((x.z - height(x.x, x.y)).abs());
            assert!(x.x.abs() <= 1.0 + 1e-12 && x.y.abs() <= 1.0 + 1e-12, "texel {x} outside");
        }
        println!("{name}: texels off the height field by {worst:.2e} (bound {bound:.2e})");
        assert!(worst <= bound, "{name}: {worst} > {bound}");
        // Facing +z, as the mesh does.
        for i in 1..47 {
            for j in 1..47 {
                let x = image.image.get(i, j);
                let nrm = (image.image.get(i + 1, j) - x).cross(image.image.get(i, j + 1) - x);
                assert!(nrm.z > 0.0, "{name}: texel ({i}, {j}) faces down");
            }
        }
        // Square in the plane: the period ratio near 1 (the slopes along x and y differ a
        // little: mean 1 + f_x² about 1.2, 1 + f_y² about 1.09).
        assert!(m.aspect() > 0.85 && m.aspect() < 1.18, "{name}: aspect {}", m.aspect());
    }
    assert!(param.quality().stretch_efficiency >= harmonic.quality().stretch_efficiency);
}

#[test]
fn a_rectangle_keeps_its_corners_and_its_aspect() {
    // A plane 2 × 1 rectangle, interior jittered, random diagonals: the map onto the square
    // puts its corners at the square's, and with linear boundary data on a plane the
    // cotangent map is the affine one (up to the weights the clamp changes), so the aspect is
    // the side ratio, 2 (or ½, depending on which side becomes u).
    let mut rng = Rng(8);
    let (m, n) = (33, 17);
    let (hx, hy) = (2.0 / (m - 1) as f64, 1.0 / (n - 1) as f64);
    let mut p = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let mut q = DVec3::new(hx * j as f64, hy * i as f64, 0.0);
            if i > 0 && i < n - 1 && j > 0 && j < m - 1 {
                q.x += 0.25 * hx * (2.0 * rng.next() - 1.0);
                q.y += 0.25 * hy * (2.0 * rng.next() - 1.0);
            }
            p.push(q);
        }
    }
    let mut t = Vec::new();
    for i in 0..n - 1 {
        for j in 0..m - 1 {
            let a = (i * m + j) as u32;
            let (b, c, d) = (a + 1, a + m as u32 + 1, a + m as u32);
            if rng.next() < 0.5 {
                t.extend([[a, b, c], [a, c, d]]);
            } else {
                t.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    let filled = vec![false; t.len()];
    for options in [DiscParamOptions::harmonic(), DiscParamOptions::default()] {
        let param = parameterise_disc(&p, &t, &filled, &options).unwrap();
        let mut corners = param.corner_vertices();
        corners.sort_unstable();
        let last = (m * n - 1) as u32;
        assert_eq!(corners, [0, m as u32 - 1, last + 1 - m as u32, last], "the corners");
        let a = param.aspect();
        println!("rectangle: aspect {a}, {:?}", param.quality());
        assert!((a.max(1.0 / a) / 2.0 - 1.0).abs() < 0.02, "aspect {a}");
        check_disc(&param, &p, &t, "rectangle");
    }
}

#[test]
fn ears_on_the_sides_lie_flat_and_the_rest_stays_bijective() {
    // A 9 × 9 grid over the unit square with an ear (a triangle with two boundary edges)
    // below every other bottom edge: each ear's apex lies on the bottom side between its
    // base's ends, so the ear has no area in (u, v).
    let n = 9;
    let mut p: Vec<DVec3> =
        (0..n * n).map(|k| DVec3::new((k % n) as f64 / 8.0, (k / n) as f64 / 8.0, 0.0)).collect();
    let mut t = Vec::new();
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            let a = (i * n + j) as u32;
            t.push([a, a + 1, a + n as u32 + 1]);
            t.push([a, a + n as u32 + 1, a + n as u32]);
        }
    }
    let mut ears = 0;
    for j in (1..n - 2).step_by(2) {
        let apex = p.len() as u32;
        p.push(DVec3::new((j as f64 + 0.5) / 8.0, -0.05, 0.0));
        t.push([j as u32, apex, j as u32 + 1]);
        ears += 1;
    }
    let filled = vec![false; t.len()];
    let param = parameterise_disc(&p, &t, &filled, &DiscParamOptions::default()).unwrap();
    let q = param.quality();
    println!("ears: {q:?}, corners {:?}", param.corner_vertices());
    assert_eq!(q.folded_triangles, 0);
    assert!(q.flat_triangles >= 1 && q.flat_triangles <= ears, "{q:?}");
    let mut area = 0.0;
    let mut flat = 0;
    for f in 0..t.len() {
        let [a, b, c] = param.uv_triangle(f);
        let d = (b - a).perp_dot(c - a);
        if d == 0.0 {
            flat += 1;
        } else {
            assert!(d > 0.0, "triangle {f}");
            area += 0.5 * d;
        }
    }
    assert_eq!(flat, q.flat_triangles);
    assert!((area - 1.0).abs() < 1e-12, "area {area}");
    // Every texel on the mesh: in the plane z = 0, inside the square or an ear.
    let image = param.image(17, 17).unwrap();
    for x in image.image.texels() {
        assert!(x.z == 0.0 && x.x >= 0.0 && x.x <= 1.0 && x.y >= -0.05 && x.y <= 1.0, "texel {x}");
    }
}

#[test]
fn flaps_cut_off_by_an_edge_lie_flat_with_their_inner_vertices() {
    // A 9 × 9 grid over the unit square with a flap below every other bottom edge (j, j + 1):
    // boundary j → a → b → j + 1 around an inner vertex c, so that (j, j + 1) is an edge inside
    // the mesh joining two vertices of one side; what it cuts off lies flat on that side.
    let n = 9;
    let h = 1.0 / 8.0;
    let mut p: Vec<DVec3> =
        (0..n * n).map(|k| DVec3::new((k % n) as f64 * h, (k / n) as f64 * h, 0.0)).collect();
    let mut t = Vec::new();
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            let a = (i * n + j) as u32;
            t.push([a, a + 1, a + n as u32 + 1]);
            t.push([a, a + n as u32 + 1, a + n as u32]);
        }
    }
    let mut inner = Vec::new();
    for j in (1..n - 2).step_by(2) {
        let x = j as f64 * h;
        let k = p.len() as u32;
        p.push(DVec3::new(x + 0.25 * h, -0.1, 0.0));
        p.push(DVec3::new(x + 0.75 * h, -0.1, 0.0));
        p.push(DVec3::new(x + 0.5 * h, -0.05, 0.0));
        let (a, b, c, j) = (k, k + 1, k + 2, j as u32);
        t.extend([[j, a, c], [a, b, c], [b, j + 1, c], [j + 1, j, c]]);
        inner.push(c);
    }
    let filled = vec![false; t.len()];
    let param = parameterise_disc(&p, &t, &filled, &DiscParamOptions::default()).unwrap();
    let q = param.quality();
    println!("flaps: {q:?}, corners {:?}", param.corner_vertices());
    assert_eq!(q.folded_triangles, 0);
    let mut area = 0.0;
    let flat: Vec<bool> = (0..t.len())
        .map(|f| {
            let [a, b, c] = param.uv_triangle(f);
            let d = (b - a).perp_dot(c - a);
            assert!(d >= 0.0, "triangle {f}");
            area += 0.5 * d;
            d == 0.0
        })
        .collect();
    assert!((area - 1.0).abs() < 1e-12, "area {area}");
    assert_eq!(flat.iter().filter(|&&x| x).count(), q.flat_triangles);
    // A corner can rescue one flap at most: the others lie flat, all four triangles, their
    // inner vertex exactly on the square's boundary.
    let on_edge = |uv: DVec2| uv.x == 0.0 || uv.x == 1.0 || uv.y == 0.0 || uv.y == 1.0;
    let first = t.len() - 4 * inner.len();
    let mut flat_flaps = 0;
    for (k, &c) in inner.iter().enumerate() {
        if flat[first + 4 * k..first + 4 * k + 4].iter().all(|&x| x) {
            flat_flaps += 1;
            let uv = param.uv()[c as usize];
            assert!(on_edge(uv), "inner vertex {c} at {uv}");
        }
    }
    assert!(flat_flaps + 1 >= inner.len(), "{flat_flaps} flat flaps");
    for uv in param.uv() {
        assert!(uv.clamp(DVec2::ZERO, DVec2::ONE) == *uv, "{uv} outside the square");
    }
    let image = param.image(17, 17).unwrap();
    for x in image.image.texels() {
        assert!(x.z == 0.0 && x.x >= 0.0 && x.x <= 1.0 && x.y >= -0.1 && x.y <= 1.0, "texel {x}");
    }
}

#[test]
fn a_single_quad_is_the_square_itself() {
    // Two triangles, four boundary vertices, nothing inside: the corners are the square's, and
    // the image is the two triangles' linear interpolation.
    let p =
        [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 1.0, 0.5], [0.0, 1.0, 0.5]].map(DVec3::from_array);
    let t = [[0, 1, 2], [0, 2, 3]];
    let param = parameterise_disc(&p, &t, &[false, true], &DiscParamOptions::default()).unwrap();
    let mut uv: Vec<DVec2> = param.uv().to_vec();
    uv.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    assert_eq!(uv, [DVec2::ZERO, DVec2::Y, DVec2::X, DVec2::ONE], "the corners");
    let image = param.image(5, 9).unwrap();
    // Whichever corner went to (0, 0), every texel lies in the quad's plane z = y / 2.
    for x in image.image.texels() {
        assert!((x.z - 0.5 * x.y).abs() < 1e-15 && x.x >= 0.0 && x.x <= 2.0, "texel {x}");
    }
    assert!(
        image.filled_fraction > 0.3 && image.filled_fraction < 0.7,
        "{}",
        image.filled_fraction
    );
    let e = parameterise_disc(&p, &t[..1], &[false], &DiscParamOptions::default()).unwrap_err();
    assert!(e.to_string().contains("1 triangle cannot make a disc"), "{e}");
}

#[test]
fn other_topologies_are_errors() {
    let topo = |e: Error| match e {
        Error::Topology { what } => what,
        other => panic!("expected a topology error, got {other:?}"),
    };
    let options = DiscParamOptions::default();
    // Closed.
    let (p, t) = icosphere(1, 1.0);
    let e = topo(parameterise_disc(&p, &t, &vec![false; t.len()], &options).unwrap_err());
    assert!(e.contains("closed"), "{e}");
    // An annulus: two boundary loops.
    let (m, k) = (24, 4);
    let mut p = Vec::new();
    for i in 0..k {
        for j in 0..m {
            let (r, a) = (1.0 + i as f64 / k as f64, TAU * j as f64 / m as f64);
            p.push(DVec3::new(r * a.cos(), r * a.sin(), 0.0));
        }
    }
    let at = |i: usize, j: usize| (i * m + j % m) as u32;
    let mut t = Vec::new();
    for i in 0..k - 1 {
        for j in 0..m {
            t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    let e = topo(parameterise_disc(&p, &t, &vec![false; t.len()], &options).unwrap_err());
    assert!(e.contains("2 boundary loops"), "{e}");
    // One boundary loop but a handle: a torus with a hole.
    let (tm, tn) = (12, 8);
    let mut tp = Vec::new();
    for i in 0..tm {
        for j in 0..tn {
            let (a, b) = (TAU * i as f64 / tm as f64, TAU * j as f64 / tn as f64);
            let rho = 1.0 + 0.3 * b.cos();
            tp.push(DVec3::new(rho * a.cos(), rho * a.sin(), 0.3 * b.sin()));
        }
    }
    let tat = |i: usize, j: usize| ((i % tm) * tn + j % tn) as u32;
    let mut tt = Vec::new();
    for i in 0..tm {
        for j in 0..tn {
            if (i, j) != (0, 0) {
                tt.push([tat(i, j), tat(i + 1, j), tat(i + 1, j + 1)]);
                tt.push([tat(i, j), tat(i + 1, j + 1), tat(i, j + 1)]);
            }
        }
    }
    let e = topo(parameterise_disc(&tp, &tt, &vec![false; tt.len()], &options).unwrap_err());
    assert!(e.contains("not a disc") && e.contains("χ = V − E + F = -1"), "{e}");
    // A NaN position, mismatched flags.
    let mut rng = Rng(1);
    let (mut p, t) = height_field(6, &mut rng);
    let e = parameterise_disc(&p, &t, &vec![false; t.len() + 1], &options).unwrap_err();
    assert!(topo(e).contains("filled"));
    p[4].x = f64::INFINITY;
    let e = parameterise_disc(&p, &t, &vec![false; t.len()], &options).unwrap_err();
    assert!(matches!(e, Error::NonFinite { what: NonFiniteInput::Vertex(4) }), "{e:?}");
    // A mask of the wrong size.
    assert!(matches!(
        reflect_periodic_mask(&[true; 5], 2, 3).unwrap_err(),
        Error::InvalidResolution { .. }
    ));
}

#[test]
fn filled_triangles_are_flagged_in_the_image() {
    let mut rng = Rng(3);
    let n = 17;
    let (p, t) = height_field(n, &mut rng);
    // Flag the triangles with every corner at x < 0: half the square, give or take a row of
    // triangles along x = 0.
    let filled: Vec<bool> =
        t.iter().map(|tri| tri.iter().all(|&k| p[k as usize].x < -1e-9)).collect();
    let param = parameterise_disc(&p, &t, &filled, &DiscParamOptions::harmonic()).unwrap();
    let image = param.image(41, 41).unwrap();
    for (x, &f) in image.image.texels().iter().zip(&image.filled) {
        if f {
            assert!(x.x <= 1e-12, "a filled texel at {x}");
        }
    }
    println!("filled fraction {}", image.filled_fraction);
    assert!(
        image.filled_fraction > 0.35 && image.filled_fraction < 0.5,
        "{}",
        image.filled_fraction
    );
}

/// An open sheet as the fit finds them in the zero set of a scan's signed distance: the part
/// of a noisy unit sphere above a ragged rim that reaches down in long thin fingers, with
/// small holes filled by fans, by surface nets on a grid of spacing `h` (about
/// 7.5 / h² vertices).
fn messy_sheet(h: f64) -> (Vec<DVec3>, Vec<[u32; 3]>, Vec<bool>) {
    let holes: Vec<(DVec3, f64)> = (0..10)
        .map(|k| {
            let (lon, lat) = (0.7 * k as f64 + 0.3, 0.6 + 0.09 * (k % 7) as f64);
            let c = DVec3::new(lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin());
            (c, h * (1.5 + 0.5 * (k % 6) as f64))
        })
        .collect();
    let f = |x: DVec3, noise: f64| {
        let (lat, lon) = (x.z.atan2(x.truncate().length()), x.y.atan2(x.x));
        let fingers = 0.9 * (7.0 * lon).sin().max(0.0).powi(12)
            + 0.6 * (3.0 * lon + 1.0).sin().max(0.0).powi(20);
        if lat < 0.35 - fingers || holes.iter().any(|&(c, r)| (x - c).length() < r) {
            return f64::NAN;
        }
        x.length() - 1.0 + 0.6 * h * noise
    };
    let corner = DVec3::splat(1.2);
    zero_set(&f, -corner, corner, h, hi_scan::repair::Closing::Disc, 1)
}

/// On a sheet as messy as a scan's zero set, whose fingers the harmonic map squeezes so much
/// that its triangles fold until the solve is pushed far below its tolerance, the solves take
/// what their budgets allow: tens of multigrid iterations for the harmonic map, and for the
/// relaxation at most six times as many (192 at least). With one hierarchy built for the
/// first round's weights the later rounds took a thousand iterations here, and tens of
/// thousands on the largest part of the zero set of CGAL's `radar.xyz`.
#[test]
fn a_messy_sheet_maps_within_its_iteration_budget() {
    let (p, t, filled) = messy_sheet(0.03);
    let most = max_valence(p.len(), &t);
    println!("messy sheet: {} vertices, valence up to {most}", p.len());
    assert!(p.len() > 5000, "multigrid: {} vertices", p.len());
    assert!(filled.iter().any(|&f| f) && most >= 20, "filled holes");
    let harmonic = parameterise_disc(&p, &t, &filled, &DiscParamOptions::harmonic()).unwrap();
    let param = parameterise_disc(&p, &t, &filled, &DiscParamOptions::default()).unwrap();
    let (h, r) = (harmonic.report(), param.report());
    println!("messy sheet: harmonic {h:?}\nmessy sheet: relaxed {r:?}");
    assert_within_budget(&h, &r);
    for (name, m) in [("harmonic", &harmonic), ("relaxed", &param)] {
        assert_eq!(m.quality().folded_triangles, 0, "{name}");
        let mut area = 0.0;
        for f in 0..t.len() {
            let [a, b, c] = m.uv_triangle(f);
            let d = (b - a).perp_dot(c - a);
            assert!(d >= 0.0, "{name}: triangle {f} folds");
            area += 0.5 * d;
        }
        assert!((area - 1.0).abs() < 1e-9, "{name}: (u, v) area {area}");
    }
}

/// Timings of large hemispheres, the best of five runs each (run with `--ignored --nocapture`,
/// in release for real numbers).
#[test]
#[ignore = "a timing to read, not a check"]
fn timing_of_large_discs() {
    for (rings, around) in [(50, 200), (158, 632)] {
        let (p, t) = hemisphere(rings, around, &mut Rng(4));
        let filled = vec![false; t.len()];
        for (name, options) in
            [("harmonic", DiscParamOptions::harmonic()), ("default", DiscParamOptions::default())]
        {
            let (mut took, mut sampled) = (f64::INFINITY, f64::INFINITY);
            let mut last = None;
            for _ in 0..5 {
                let start = std::time::Instant::now();
                let param = parameterise_disc(&p, &t, &filled, &options).unwrap();
                took = took.min(start.elapsed().as_secs_f64());
                let (rows, cols) = param.resolution(p.len());
                let start = std::time::Instant::now();
                let image = param.image(rows, cols).unwrap();
                sampled = sampled.min(start.elapsed().as_secs_f64());
                assert_eq!(image.image.rows(), rows, "image size");
                last = Some((param, rows, cols));
            }
            let Some((param, rows, cols)) = last else { continue };
            println!(
                "{} vertices, {name}: parameterise {took:.3} s ({} CG iterations, {} rounds), image {rows}×{cols} {sampled:.3} s; {:?}",
                p.len(),
                param.report().solve_iterations,
                param.report().rounds,
                param.quality()
            );
        }
    }
}
