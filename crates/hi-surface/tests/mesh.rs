// SPDX-License-Identifier: MIT
//! Triangle meshes of harmonic surfaces (§5.5): vertex and triangle counts, welding at seams and
//! poles, normals, positions on the exact sphere, curvature colours, and errors.

use std::collections::HashMap;

use glam::{DVec2, DVec3};
use hi_mesh::{ColorMap, ColorScale, TriangleMesh};
use hi_surface::{
    CurvatureColoring, CurvatureQuantity, Error, HarmonicSurface, MeshOptions, Seam, sphere, torus,
};
use hi_surface::{ParamRange, ParamWindow};
use hi_testkit::proptest_config;
use proptest::prelude::*;

fn mesh(s: &HarmonicSurface<DVec3>, opts: MeshOptions) -> TriangleMesh {
    s.to_mesh(&opts).unwrap()
}

/// How many triangles use each undirected edge.
fn edge_uses(m: &TriangleMesh) -> HashMap<(u32, u32), usize> {
    let mut uses = HashMap::new();
    for t in m.triangles() {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *uses.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    uses
}

/// Every directed edge appears once and its reverse once: a closed, consistently oriented
/// surface. Returns the number of edges.
fn assert_closed_oriented(m: &TriangleMesh) -> usize {
    let mut directed = HashMap::new();
    for t in m.triangles() {
        for e in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *directed.entry(e).or_insert(0) += 1;
        }
    }
    for (&(a, b), &n) in &directed {
        assert_eq!(n, 1, "directed edge ({a}, {b}) used {n} times");
        assert_eq!(directed.get(&(b, a)), Some(&1), "edge ({a}, {b}) has no opposite");
    }
    directed.len() / 2
}

fn all_distinct(points: &[DVec3]) -> bool {
    let mut keys: Vec<[u64; 3]> = points.iter().map(|p| p.to_array().map(f64::to_bits)).collect();
    keys.sort_unstable();
    keys.windows(2).all(|w| w[0] != w[1])
}

/// The surface parameter of a vertex, from its UV and the window.
fn param(uv: DVec2, opts: &MeshOptions) -> (f64, f64) {
    opts.window.lerp(uv.x, uv.y)
}

/// The window `[u0, u1] × [v0, v1]`.
fn window([u0, u1]: [f64; 2], [v0, v1]: [f64; 2]) -> ParamWindow {
    ParamWindow::new(ParamRange::new(u0, u1), ParamRange::new(v0, v1))
}

fn face_normal(m: &TriangleMesh, t: [u32; 3]) -> DVec3 {
    let [a, b, c] = t.map(|k| m.positions()[k as usize]);
    (b - a).cross(c - a)
}

#[test]
fn torus_welded_is_closed_with_no_duplicate_vertices() {
    let opts = MeshOptions { n_u: 12, n_v: 20, ..Default::default() };
    let m = mesh(&torus(3.0, 1.0), opts);
    assert_eq!(m.n_vertices(), 12 * 20, "one vertex per distinct sample");
    assert_eq!(m.n_triangles(), 2 * 12 * 20, "two triangles per quad");
    assert!(all_distinct(m.positions()), "no two vertices at one position");
    let n_edges = assert_closed_oriented(&m);
    // Euler characteristic of the torus: V − E + F = 0.
    assert_eq!(m.n_vertices() as i64 - n_edges as i64 + m.n_triangles() as i64, 0, "torus");
}

#[test]
fn torus_split_repeats_the_seams_with_uv_one() {
    let opts = MeshOptions { n_u: 6, n_v: 8, seam: Seam::Split, ..Default::default() };
    let m = mesh(&torus(3.0, 1.0), opts);
    assert_eq!(m.n_vertices(), 7 * 9, "seam rows and columns repeated");
    assert_eq!(m.n_triangles(), 2 * 6 * 8, "no triangle lost");
    // Grid order: vertex (i, l) is i·9 + l. Seam copies share position and normal bit for bit.
    for i in 0..7 {
        let (first, last) = (i * 9, i * 9 + 8);
        assert_eq!(m.positions()[first], m.positions()[last], "v seam, row {i}");
        assert_eq!(m.normals()[first], m.normals()[last], "v seam normal, row {i}");
        assert_eq!(m.uvs()[last].y, 1.0, "t = 1 on the v seam");
    }
    for l in 0..9 {
        assert_eq!(m.positions()[l], m.positions()[6 * 9 + l], "u seam, column {l}");
        assert_eq!(m.uvs()[6 * 9 + l].x, 1.0, "s = 1 on the u seam");
    }
    // Every edge is used by one or two triangles: open along the seams, closed elsewhere.
    let uses = edge_uses(&m);
    assert!(uses.values().all(|&n| n == 1 || n == 2), "manifold");
    assert_eq!(
        uses.values().filter(|&&n| n == 1).count(),
        2 * (6 + 8),
        "boundary = the two seams, twice"
    );
}

#[test]
fn half_sphere_window_welds_the_poles() {
    let (n_u, n_v) = (10, 16);
    let opts = MeshOptions {
        n_u,
        n_v,
        window: ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::UNIT),
        ..Default::default()
    };
    let m = mesh(&sphere(2.0), opts);
    assert_eq!(m.n_vertices(), (n_u - 1) * n_v + 2, "rings plus one vertex per pole");
    assert_eq!(m.n_triangles(), 2 * n_u * n_v - 2 * n_v, "one triangle per pole quad");
    let n_edges = assert_closed_oriented(&m);
    assert_eq!(m.n_vertices() as i64 - n_edges as i64 + m.n_triangles() as i64, 2, "a sphere");
    assert!(all_distinct(m.positions()), "no duplicates");
    // No triangle has two corners at one point.
    for t in m.triangles() {
        let [a, b, c] = t.map(|k| m.positions()[k as usize]);
        assert!(a != b && b != c && a != c, "degenerate triangle {t:?}");
    }
}

#[test]
fn sphere_vertices_lie_on_the_sphere() {
    for (u_range, seam) in
        [([0.0, 0.5], Seam::Welded), ([0.0, 0.5], Seam::Split), ([0.0, 1.0], Seam::Welded)]
    {
        let window = window(u_range, [0.0, 1.0]);
        let opts = MeshOptions { n_u: 32, n_v: 48, window, seam, ..Default::default() };
        let m = mesh(&sphere(2.0), opts);
        for p in m.positions() {
            // The sphere is exact; the FFT or basis sums round at ~1e-16 relative.
            assert!(
                (p.length() - 2.0).abs() < 1e-14,
                "{p} off the sphere by {:e}",
                p.length() - 2.0
            );
        }
        // And at f32, as exported: within one rounding of each coordinate.
        for p in m.positions() {
            assert!((p.as_vec3().length() - 2.0).abs() < 4.0 * f32::EPSILON, "f32 {p}");
        }
    }
}

#[test]
fn full_sphere_welds_both_pole_rows() {
    // u ∈ [0, 1] passes the poles at u = 0 and u = ½ (an interior row).
    let (n_u, n_v) = (12, 10);
    let m = mesh(&sphere(1.0), MeshOptions { n_u, n_v, ..Default::default() });
    assert_eq!(m.n_vertices(), (n_u - 2) * n_v + 2, "both pole rows are one vertex each");
    assert_eq!(
        m.n_triangles(),
        2 * n_u * n_v - 4 * n_v,
        "one triangle per quad at each pole, both sides"
    );
}

#[test]
fn split_sphere_keeps_pole_copies_with_their_uvs() {
    let (n_u, n_v) = (8, 12);
    let opts = MeshOptions {
        n_u,
        n_v,
        window: ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::UNIT),
        seam: Seam::Split,
        ..Default::default()
    };
    let m = mesh(&sphere(1.0), opts);
    // Each pole sample is used by one triangle (the seam copy at t = 1 by the last quad's
    // triangle at the south pole only, and not at all at the north pole, where it is removed).
    let north: Vec<usize> = (0..m.n_vertices()).filter(|&k| m.uvs()[k].x == 0.0).collect();
    let south: Vec<usize> = (0..m.n_vertices()).filter(|&k| m.uvs()[k].x == 1.0).collect();
    assert_eq!(north.len(), n_v, "north pole copies t = 0..(n−1)/n");
    assert_eq!(south.len(), n_v, "south pole copies t = 1/n..1");
    assert_eq!(m.n_triangles(), 2 * n_u * n_v - 2 * n_v, "as welded");
    // All copies of a pole share one normal: the outward axis.
    for &k in &north {
        assert!((m.normals()[k] - DVec3::Z).length() < 1e-12, "north {}", m.normals()[k]);
    }
    for &k in &south {
        assert!((m.normals()[k] + DVec3::Z).length() < 1e-12, "south {}", m.normals()[k]);
    }
}

#[test]
fn normals_are_unit_and_follow_pu_cross_pv() {
    let s = torus(2.0, 0.7);
    for flip in [false, true] {
        let opts = MeshOptions {
            n_u: 10,
            n_v: 14,
            window: ParamWindow::new(ParamRange::new(0.1, 0.8), ParamRange::new(0.3, 1.3)),
            flip,
            ..Default::default()
        };
        let m = mesh(&s, opts);
        let sign = if flip { -1.0 } else { 1.0 };
        for (k, n) in m.normals().iter().enumerate() {
            assert!((n.length() - 1.0).abs() < 1e-14, "unit");
            let (u, v) = param(m.uvs()[k], &opts);
            let expected = s.normal(u, v).unwrap() * sign;
            assert!((*n - expected).length() < 1e-12, "vertex {k}: {n} vs {expected}");
            // The torus's p_u × p_v points out of the tube.
            let axis_point =
                DVec3::new(m.positions()[k].x, m.positions()[k].y, 0.0).normalize() * 2.0;
            assert!(sign * n.dot(m.positions()[k] - axis_point) > 0.0, "outward unless flipped");
        }
        // Triangles wind counter-clockwise about the vertex normals.
        for t in m.triangles() {
            let corners: DVec3 = t.iter().map(|&k| m.normals()[k as usize]).sum();
            assert!(
                face_normal(&m, *t).dot(corners) > 0.0,
                "triangle {t:?} winds against its normals"
            );
        }
    }
}

#[test]
fn pole_normals_are_the_limit_direction_and_never_nan() {
    let opts = MeshOptions {
        n_u: 9,
        n_v: 7,
        window: ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::UNIT),
        ..Default::default()
    };
    let m = mesh(&sphere(3.0), opts);
    for (p, n) in m.positions().iter().zip(m.normals()) {
        assert!(n.is_finite() && (n.length() - 1.0).abs() < 1e-14, "unit, finite");
        // Outward everywhere, as p_u × p_v, and at the poles along the axis.
        assert!((*n - *p / 3.0).length() < 1e-12, "normal {n} at {p} is not p/r");
    }
    for t in m.triangles() {
        let corners: DVec3 = t.iter().map(|&k| m.normals()[k as usize]).sum();
        assert!(face_normal(&m, *t).dot(corners) > 0.0, "pole fans wind with their normals");
    }
}

#[test]
fn fft_and_separable_paths_sample_the_surface() {
    let grid: Vec<Vec<DVec3>> = (0..5)
        .map(|j| {
            (0..6)
                .map(|k| DVec3::new(j as f64, k as f64, ((j * 7 + k * 3) % 5) as f64 * 0.3))
                .collect()
        })
        .collect();
    let s = HarmonicSurface::new(grid);
    for (u_range, v_range) in
        [([0.0, 1.0], [0.0, 1.0]), ([0.2, 1.2], [0.0, 1.0]), ([0.1, 0.4], [-0.5, 0.25])]
    {
        let window = window(u_range, v_range);
        let opts = MeshOptions { n_u: 11, n_v: 9, window, ..Default::default() };
        let m = mesh(&s, opts);
        for (k, p) in m.positions().iter().enumerate() {
            let (u, v) = param(m.uvs()[k], &opts);
            assert!((*p - s.eval(u, v)).length() < 1e-12, "{u_range:?}×{v_range:?} at ({u}, {v})");
        }
    }
}

#[test]
fn uvs_span_the_unit_square() {
    let opts = MeshOptions {
        n_u: 4,
        n_v: 5,
        window: ParamWindow::new(ParamRange::new(0.25, 0.5), ParamRange::new(0.0, 0.3)),
        ..Default::default()
    };
    let m = mesh(&torus(2.0, 0.5), opts);
    assert_eq!(m.n_vertices(), 5 * 6, "open window: (n + 1)² samples");
    let (lo, hi) = m
        .uvs()
        .iter()
        .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(a, b), t| (a.min(*t), b.max(*t)));
    assert_eq!((lo, hi), (DVec2::ZERO, DVec2::ONE), "s, t ∈ [0, 1]");
}

#[test]
fn curvature_colours_and_legend() {
    let color =
        CurvatureColoring { quantity: CurvatureQuantity::Gaussian, map: ColorMap::default() };
    let opts = MeshOptions {
        n_u: 8,
        n_v: 8,
        window: ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::UNIT),
        color: Some(color),
        ..Default::default()
    };
    let m = mesh(&sphere(2.0), opts);
    let colors = m.colors().expect("coloured");
    assert_eq!(colors.len(), m.n_vertices(), "one colour per vertex");
    let legend = m.legend().expect("legend");
    // K = 1/4 on the sphere, undefined at the two poles (grey, counted).
    assert_eq!(legend.n_invalid, 2, "the poles");
    assert!((legend.max - 0.25).abs() < 1e-12, "extent {}", legend.max);
    assert_eq!(legend.min, 0.0, "magnitude scale starts at 0");
    let purple = hi_mesh::srgb_to_linear_rgb(hi_mesh::HIGH_SRGB);
    let grey = hi_mesh::srgb_to_linear_rgb(hi_mesh::NEUTRAL_SRGB);
    let n_grey = colors.iter().filter(|&&c| c == grey).count();
    assert_eq!(n_grey, 2, "pole vertices grey");
    for c in colors.iter().filter(|&&c| c != grey) {
        for (a, b) in c.iter().zip(&purple) {
            assert!((a - b).abs() < 1e-6, "constant K at the top of the scale: {c:?}");
        }
    }
}

#[test]
fn mean_curvature_sign_follows_the_mesh_normal() {
    let map =
        ColorMap { scale: ColorScale::MinMax, coverage: 1.0, palette: hi_mesh::Palette::Thesis };
    let color = Some(CurvatureColoring { quantity: CurvatureQuantity::Mean, map });
    let t = torus(2.0, 0.5);
    let plain = mesh(&t, MeshOptions { n_u: 16, n_v: 16, color, ..Default::default() });
    let flipped =
        mesh(&t, MeshOptions { n_u: 16, n_v: 16, color, flip: true, ..Default::default() });
    let (a, b) = (plain.legend().unwrap(), flipped.legend().unwrap());
    // p_u × p_v points out of the tube, where H < 0 (L = p_uu·n < 0); flipped, H > 0.
    assert!(a.data_max < 0.0 && b.data_min > 0.0, "{a:?} / {b:?}");
    assert!(
        (a.data_min + b.data_max).abs() < 1e-12 && (a.data_max + b.data_min).abs() < 1e-12,
        "mirror"
    );
}

#[test]
fn invalid_options_are_errors() {
    let t = torus(2.0, 0.5);
    let bad_windows = [[0.5, 0.5], [0.7, 0.2], [f64::NAN, 1.0], [0.0, f64::INFINITY]];
    for u_range in bad_windows {
        let window = window(u_range, [0.0, 1.0]);
        let r = t.to_mesh(&MeshOptions { window, ..Default::default() });
        assert!(matches!(r, Err(Error::InvalidWindow { .. })), "{u_range:?}: {r:?}");
    }
    for (n_u, u_range) in [(0, [0.0, 0.5]), (2, [0.0, 1.0]), (1 << 24, [0.0, 0.5])] {
        let window = window(u_range, [0.0, 1.0]);
        let r = t.to_mesh(&MeshOptions { n_u, window, ..Default::default() });
        assert!(matches!(r, Err(Error::InvalidCount { .. })), "n_u = {n_u}: {r:?}");
    }
    // A surface that is one point has no non-degenerate triangle.
    let point = HarmonicSurface::new(vec![vec![DVec3::ONE; 3]; 3]);
    let r = point.to_mesh(&MeshOptions::default());
    assert!(matches!(r, Err(Error::InvalidCount { value: 0, .. })), "{r:?}");
    let map =
        ColorMap { scale: ColorScale::Magnitude, coverage: 0.0, palette: hi_mesh::Palette::Thesis };
    let color = Some(CurvatureColoring { quantity: CurvatureQuantity::Mean, map });
    let r = t.to_mesh(&MeshOptions { color, ..Default::default() });
    assert!(matches!(r, Err(Error::Mesh(hi_mesh::Error::InvalidValue { .. }))), "{r:?}");
    // Messages are one line.
    for e in [r.unwrap_err(), point.to_mesh(&MeshOptions::default()).unwrap_err()] {
        assert!(!e.to_string().contains('\n'), "{e}");
    }
}

proptest! {
    #![proptest_config(proptest_config(24))]

    /// Random grids, windows and resolutions: normals unit and finite, counts as predicted for
    /// a surface without collapsed rows, triangles consistently oriented.
    #[test]
    fn random_surfaces_mesh_cleanly(
        seed in prop::collection::vec(-1.0f64..1.0, 3 * 5 * 4),
        n_u in 1usize..12,
        n_v in 3usize..12,
        u0 in -1.0f64..1.0,
        du in 0.05f64..1.5,
        closed_v in any::<bool>(),
        split in any::<bool>(),
    ) {
        let grid: Vec<Vec<DVec3>> = (0..5)
            .map(|j| {
                (0..4)
                    .map(|k| {
                        let i = 3 * (j * 4 + k);
                        let offset = DVec3::new(seed[i], seed[i + 1], seed[i + 2]);
                        DVec3::new(j as f64, k as f64, 0.0) + offset * 0.4
                    })
                    .collect()
            })
            .collect();
        let s = HarmonicSurface::new(grid);
        let v_range = if closed_v { [0.0, 1.0] } else { [0.2, 0.9] };
        let seam = if split { Seam::Split } else { Seam::Welded };
        let u_range = [u0, u0 + du];
        let window = window(u_range, v_range);
        let opts = MeshOptions { n_u, n_v, window, seam, ..Default::default() };
        let m = s.to_mesh(&opts).unwrap();
        let cols = if closed_v && !split { n_v } else { n_v + 1 };
        let rows = if (du - 1.0).abs() < 1e-12 && !split { n_u.max(3) } else { n_u + 1 };
        prop_assert_eq!(m.n_vertices(), rows * cols);
        prop_assert_eq!(m.n_triangles(), 2 * n_u * n_v);
        for n in m.normals() {
            prop_assert!(n.is_finite() && (n.length() - 1.0).abs() < 1e-12);
        }
        for (k, p) in m.positions().iter().enumerate() {
            let (u, v) = param(m.uvs()[k], &opts);
            prop_assert!((*p - s.eval(u, v)).length() < 1e-11);
        }
    }
}
