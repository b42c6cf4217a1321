// SPDX-License-Identifier: MIT
//! The parameterisation of genus-1 meshes over the flat torus, checked on meshes built here
//! whose answers are known: the analytic torus of revolution (its conformal period ratio
//! r/√(R² − r²), its surface), a tube about a torus knot, a torus with one side swollen into a
//! body (a mug: a body with a thin handle), and meshes of the wrong topology; and on a torus as
//! messy as the zero sets of scans, for what the solves take.

use std::f64::consts::{PI, TAU};
use std::time::Instant;

use glam::{DVec2, DVec3};
use hi_geomimage::Error;
use hi_geomimage::torusparam::{TorusParam, TorusParamOptions, parameterise_torus};

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

/// A closed m × n grid of quads on the surface s(a, b), a, b ∈ [0, 2π), a the first index,
/// each quad split along a diagonal (the same one everywhere, or chosen at random with
/// `rng`); the parameters of each vertex jittered by up to `jitter` cells. Wound so that the
/// enclosed volume is positive (outward).
fn grid(
    m: usize,
    n: usize,
    s: &dyn Fn(f64, f64) -> DVec3,
    jitter: f64,
    mut rng: Option<&mut Rng>,
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut p = Vec::with_capacity(m * n);
    for i in 0..m {
        for j in 0..n {
            let (mut a, mut b) = (i as f64, j as f64);
            if let Some(r) = rng.as_deref_mut() {
                a += jitter * (2.0 * r.next() - 1.0);
                b += jitter * (2.0 * r.next() - 1.0);
            }
            p.push(s(TAU * a / m as f64, TAU * b / n as f64));
        }
    }
    let at = |i: usize, j: usize| ((i % m) * n + j % n) as u32;
    let mut t = Vec::with_capacity(2 * m * n);
    for i in 0..m {
        for j in 0..n {
            let flip = rng.as_deref_mut().is_some_and(|r| r.next() < 0.5);
            if flip {
                t.push([at(i, j), at(i + 1, j), at(i, j + 1)]);
                t.push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
            } else {
                t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
    }
    if volume(&p, &t) < 0.0 {
        for tri in &mut t {
            tri.swap(1, 2);
        }
    }
    (p, t)
}

/// The signed volume enclosed (positive for outward winding).
fn volume(p: &[DVec3], t: &[[u32; 3]]) -> f64 {
    t.iter()
        .map(|tri| p[tri[0] as usize].dot(p[tri[1] as usize].cross(p[tri[2] as usize])))
        .sum::<f64>()
        / 6.0
}

/// The torus of revolution about z with radii `big` and `small`: a around the axis, b around
/// the tube.
fn torus_point(big: f64, small: f64) -> impl Fn(f64, f64) -> DVec3 {
    move |a: f64, b: f64| {
        let rho = big + small * b.cos();
        DVec3::new(rho * a.cos(), rho * a.sin(), small * b.sin())
    }
}

/// The distance from x to the torus of revolution.
fn torus_distance(x: DVec3, big: f64, small: f64) -> f64 {
    ((x.x.hypot(x.y) - big).hypot(x.z) - small).abs()
}

/// An upper bound on the distance from any point of a triangle with vertices on the torus,
/// whose parameters lie within `da` × `db` of each other, to the torus: for x = Σλₖvₖ in
/// parameter space, |s(x) − Σλₖ s(vₖ)| ≤ ½ max Q(vₖ − x) with
/// Q(d) = (R + r)d₁² + 2r|d₁d₂| + r d₂² bounding the second derivative along d (|s₁₁| ≤ R + r,
/// |s₁₂| ≤ r, |s₂₂| = r, the indices 1 around the axis and 2 around the tube).
fn chord_bound(big: f64, small: f64, da: f64, db: f64) -> f64 {
    0.5 * ((big + small) * da * da + 2.0 * small * da * db + small * db * db)
}

/// Every (u, v) triangle counter-clockwise, and their total area.
fn uv_area(param: &TorusParam) -> (usize, f64) {
    let mut folded = 0;
    let mut area = 0.0;
    for f in 0..param.triangles().len() {
        let [a, b, c] = param.uv_triangle(f);
        let d = (b - a).perp_dot(c - a);
        if d <= 0.0 {
            folded += 1;
        }
        area += 0.5 * d;
    }
    (folded, area)
}

/// A random point of a random triangle: its position and its (u, v).
fn mesh_sample(param: &TorusParam, rng: &mut Rng) -> (DVec3, DVec2) {
    let f =
        ((rng.next() * param.triangles().len() as f64) as usize).min(param.triangles().len() - 1);
    let (mut s, mut t) = (rng.next(), rng.next());
    if s + t > 1.0 {
        (s, t) = (1.0 - s, 1.0 - t);
    }
    let l = [1.0 - s - t, s, t];
    let tri = param.triangles()[f];
    let c = param.uv_triangle(f);
    let p = (0..3).map(|k| param.positions()[tri[k] as usize] * l[k]).sum();
    let uv = (0..3).map(|k| c[k] * l[k]).sum::<DVec2>();
    (p, uv.rem_euclid(DVec2::ONE))
}

/// The torus of revolution R = 1, r = 0.35: no fold, area 1, every texel on the torus, the
/// harmonic surface through the image near the torus and facing out, and the period ratio of
/// the conformal map, r/√(R² − r²).
fn check_analytic_torus(
    p: &[DVec3],
    t: &[[u32; 3]],
    da: f64,
    db: f64,
    aspect_tolerance: f64,
    label: &str,
) {
    let (big, small) = (1.0, 0.35);
    let chord = chord_bound(big, small, da, db);
    let filled = vec![false; t.len()];
    // The harmonic map alone: the conformal period ratio.
    let harmonic = parameterise_torus(p, t, &filled, &TorusParamOptions::harmonic()).unwrap();
    let conformal = small / (big * big - small * small).sqrt();
    println!(
        "{label}: harmonic {:?}, aspect {:.5} (conformal {conformal:.5}), {} iterations",
        harmonic.quality(),
        harmonic.aspect(),
        harmonic.report().solve_iterations
    );
    assert!(
        (harmonic.aspect() / conformal - 1.0).abs() < aspect_tolerance,
        "{label}: aspect {}",
        harmonic.aspect()
    );
    // A map of a torus of revolution that keeps its symmetry has no shear.
    assert!(harmonic.quality().shear.abs() < 0.05, "{label}: {:?}", harmonic.quality());
    let param = parameterise_torus(p, t, &filled, &TorusParamOptions::default()).unwrap();
    let q = param.quality();
    println!("{label}: relaxed {q:?}, aspect {:.5}, {:?}", param.aspect(), param.report());
    for (name, m) in [("harmonic", &harmonic), ("relaxed", &param)] {
        let (folded, area) = uv_area(m);
        assert_eq!(folded, 0, "{label} {name}: folded (u, v) triangles");
        assert_eq!(m.quality().folded_triangles, 0, "{label} {name}");
        assert!((area - 1.0).abs() < 1e-9, "{label} {name}: (u, v) area {area}");
        for uv in m.uv() {
            assert!((0.0..1.0).contains(&uv.x) && (0.0..1.0).contains(&uv.y), "{uv} in [0, 1)²");
        }
    }
    assert!(q.stretch_efficiency >= param.report().harmonic.stretch_efficiency, "relaxation");
    // The L² stretch E = ∫ ½(|pᵤ|² + |pᵥ|²) dA over maps (u, v) = (f(b), a/2π) is least for
    // f' ∝ ρ^{1/3}, ρ = R + r cos b (the Euler–Lagrange equation of
    // ∫ π r ρ (r²/f'² + 4π²ρ²) db with ∫ f' = 1); its period ratio
    // √(∫ r²/f' db / ∫ 4π²ρ² f' db) lies a little below the conformal one.
    let steps = 4096;
    let quad = |g: &dyn Fn(f64) -> f64| {
        (0..steps).map(|k| g(TAU * (k as f64 + 0.5) / steps as f64)).sum::<f64>() * TAU
            / steps as f64
    };
    let rho = |b: f64| big + small * b.cos();
    let k = 1.0 / quad(&|b| rho(b).cbrt());
    let fp = |b: f64| k * rho(b).cbrt();
    let optimal = (quad(&|b| small * small / fp(b))
        / quad(&|b| 4.0 * PI * PI * rho(b) * rho(b) * fp(b)))
    .sqrt();
    println!("{label}: stretch-optimal symmetric aspect {optimal:.5}");
    let (lo, hi) = (optimal.min(conformal), optimal.max(conformal));
    assert!(
        param.aspect() > 0.95 * lo && param.aspect() < 1.05 * hi,
        "{label}: relaxed aspect {}",
        param.aspect()
    );
    // The image at the aspect asked for.
    let cols = 192;
    let rows = ((cols as f64 * param.aspect()).round() as usize).max(2);
    let image = param.image(rows, cols).unwrap();
    assert_eq!(image.filled_fraction, 0.0, "nothing filled");
    for x in image.image.texels() {
        let d = torus_distance(*x, big, small);
        assert!(d <= chord, "{label}: texel {x} is {d} off the torus (bound {chord})");
    }
    // The harmonic surface through the image: near the torus, facing out, and through the
    // mesh point of each (u, v).
    let surface = image.image.surface().unwrap();
    let mut rng = Rng(7);
    let (mut worst, mut worst_on_mesh) = (0.0f64, 0.0f64);
    for _ in 0..400 {
        let (u, v) = (rng.next(), rng.next());
        let (x, pu, pv) = surface.eval_with_partials(u, v);
        worst = worst.max(torus_distance(x, big, small));
        let core = DVec3::new(x.x, x.y, 0.0).normalize() * big;
        let n = pu.cross(pv);
        assert!(n.dot(x - core) > 0.0, "{label}: the normal at ({u}, {v}) points into the tube");
        let (at, uv) = mesh_sample(&param, &mut rng);
        worst_on_mesh = worst_on_mesh.max((surface.eval(uv.x, uv.y) - at).length());
    }
    println!(
        "{label}: surface off the torus by {worst:.2e}, off the mesh point by {worst_on_mesh:.2e} (chord bound {chord:.2e})"
    );
    assert!(worst < 2.0 * chord, "{label}: surface {worst} off the torus");
    assert!(worst_on_mesh < 3.0 * chord, "{label}: surface {worst_on_mesh} off the mesh point");
}

#[test]
fn the_analytic_torus_maps_onto_the_flat_torus() {
    let (m, n) = (96, 32);
    let (p, t) = grid(m, n, &torus_point(1.0, 0.35), 0.0, None);
    // The discrete conformal structure of a regular grid is close to the smooth one.
    check_analytic_torus(&p, &t, TAU / m as f64, TAU / n as f64, 0.01, "regular 96×32");
}

#[test]
fn an_irregular_shuffled_torus_maps_the_same_way() {
    let (m, n) = (96, 32);
    let mut rng = Rng(42);
    let jitter = 0.3;
    let (p, t) = grid(m, n, &torus_point(1.0, 0.35), jitter, Some(&mut rng));
    // Shuffle the vertices, the triangles and each triangle's first corner.
    let mut order: Vec<usize> = (0..p.len()).collect();
    for k in (1..order.len()).rev() {
        order.swap(k, (rng.next() * (k + 1) as f64) as usize);
    }
    let mut new_index = vec![0u32; p.len()];
    for (new, &old) in order.iter().enumerate() {
        new_index[old] = new as u32;
    }
    let q: Vec<DVec3> = order.iter().map(|&old| p[old]).collect();
    let mut s: Vec<[u32; 3]> = t
        .iter()
        .map(|tri| {
            let r = tri.map(|k| new_index[k as usize]);
            let k = (rng.next() * 3.0) as usize % 3;
            [r[k], r[(k + 1) % 3], r[(k + 2) % 3]]
        })
        .collect();
    for k in (1..s.len()).rev() {
        s.swap(k, (rng.next() * (k + 1) as f64) as usize);
    }
    let spread = 1.0 + 2.0 * jitter;
    // Jittered cells with random diagonals have obtuse angles whose clamped weights bias the
    // discrete conformal structure by a few per cent.
    check_analytic_torus(
        &q,
        &s,
        spread * TAU / m as f64,
        spread * TAU / n as f64,
        0.05,
        "jittered, shuffled",
    );
    // The harmonic map does not depend on the order: same quality and aspect as unshuffled.
    let filled = vec![false; t.len()];
    let a = parameterise_torus(&p, &t, &filled, &TorusParamOptions::harmonic()).unwrap();
    let b = parameterise_torus(&q, &s, &filled, &TorusParamOptions::harmonic()).unwrap();
    assert!((a.aspect() - b.aspect()).abs() < 1e-6, "{} vs {}", a.aspect(), b.aspect());
    let (qa, qb) = (a.quality(), b.quality());
    assert!((qa.stretch_efficiency - qb.stretch_efficiency).abs() < 1e-6, "{qa:?} vs {qb:?}");
}

/// A tube of radius `r` about the closed curve c (periodic on [0, 2π)), `m` rings of `n`,
/// with Frenet frames.
fn tube(c: &dyn Fn(f64) -> DVec3, r: f64, m: usize, n: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let h = 1e-4;
    let frame = |s: f64| {
        let d1 = (c(s + h) - c(s - h)) / (2.0 * h);
        let d2 = (c(s + h) - 2.0 * c(s) + c(s - h)) / (h * h);
        let t = d1.normalize();
        let nn = (d2 - d2.dot(t) * t).normalize();
        (nn, t.cross(nn))
    };
    grid(
        m,
        n,
        &|a, b| {
            let (nn, bb) = frame(a);
            c(a) + r * (b.cos() * nn + b.sin() * bb)
        },
        0.0,
        None,
    )
}

#[test]
fn a_torus_knot_tube_maps_without_folds() {
    // The (2, 3) torus knot (a trefoil) on the torus of radii 2 and 1.
    let knot = |s: f64| {
        let rho = 2.0 + (3.0 * s).cos();
        DVec3::new(rho * (2.0 * s).cos(), rho * (2.0 * s).sin(), (3.0 * s).sin())
    };
    let (m, n) = (720, 16);
    let (p, t) = tube(&knot, 0.1, m, n);
    let filled = vec![false; t.len()];
    let harmonic = parameterise_torus(&p, &t, &filled, &TorusParamOptions::harmonic()).unwrap();
    let param = parameterise_torus(&p, &t, &filled, &TorusParamOptions::default()).unwrap();
    println!("knot: {:?}, aspect {:.5}", param.report(), param.aspect());
    // The tube's length, for the period ratio: 2π r over the length, give or take the
    // difference between the core and the tube's mean circle.
    let length: f64 = (0..m)
        .map(|i| (knot(TAU * (i + 1) as f64 / m as f64) - knot(TAU * i as f64 / m as f64)).length())
        .sum();
    let expected = TAU * 0.1 / length;
    println!(
        "knot: length {length:.4}, aspect expected about {expected:.5}, harmonic {:.5}",
        harmonic.aspect()
    );
    assert!((harmonic.aspect() / expected - 1.0).abs() < 0.1, "aspect {}", harmonic.aspect());
    for (name, m) in [("harmonic", &harmonic), ("relaxed", &param)] {
        let (folded, area) = uv_area(m);
        assert_eq!(folded, 0, "{name}");
        assert!((area - 1.0).abs() < 1e-9, "{name}: area {area}");
        // The reduced basis: |cos| of the angle between rows and columns at most aspect / 2
        // (|a₁·a₂| ≤ |a₁|²/2), with some room for the map not being conformal.
        assert!(m.quality().shear.abs() <= 0.5 * m.aspect() + 0.02, "{name}: {:?}", m.quality());
    }
    // The image: every texel on the tube (within its chord error).
    let (rows, cols) = param.resolution(8 * 1024);
    let image = param.image(rows, cols).unwrap();
    println!("knot image {rows} × {cols}");
    let chord = 0.1 * (1.0 - (PI / n as f64).cos()) + 0.02;
    for x in image.image.texels().iter().step_by(7) {
        // The distance to the core curve, by brute force over a fine sampling of it.
        let d = (0..4 * m)
            .map(|i| (knot(TAU * i as f64 / (4 * m) as f64) - *x).length())
            .fold(f64::INFINITY, f64::min);
        assert!((d - 0.1).abs() < chord, "texel {x} at {d} from the core");
    }
}

/// A torus whose tube swells on one side into a body of radius 0.75 and thins to 0.12 on
/// the other: a body with a thin handle.
fn mug(m: usize, n: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    grid(
        m,
        n,
        &|a, b| {
            let r = 0.12 + 0.63 * (0.5 * (1.0 + a.cos())).powi(4);
            let rho = 1.0 + r * b.cos();
            DVec3::new(rho * a.cos(), rho * a.sin(), r * b.sin())
        },
        0.0,
        None,
    )
}

#[test]
fn relaxation_evens_out_a_mug() {
    let (p, t) = mug(256, 64);
    let filled = vec![false; t.len()];
    let harmonic = parameterise_torus(&p, &t, &filled, &TorusParamOptions::harmonic()).unwrap();
    let param = parameterise_torus(&p, &t, &filled, &TorusParamOptions::default()).unwrap();
    let (h, q) = (harmonic.quality(), param.quality());
    println!(
        "mug: harmonic {h:?}\nmug: relaxed {q:?}\nmug: {:?}, aspect {:.4} → {:.4}",
        param.report(),
        harmonic.aspect(),
        param.aspect()
    );
    assert_eq!(param.report().harmonic, h, "the report keeps the harmonic map's quality");
    for (name, m) in [("harmonic", &harmonic), ("relaxed", &param)] {
        let (folded, area) = uv_area(m);
        assert_eq!(folded, 0, "{name}");
        assert!((area - 1.0).abs() < 1e-9, "{name}: area {area}");
    }
    assert!(q.stretch_efficiency > h.stretch_efficiency + 0.05, "relaxation: {h:?} → {q:?}");
    assert!(q.area_ratio < h.area_ratio, "relaxation: {h:?} → {q:?}");
}

#[test]
fn other_topologies_are_errors() {
    let topo = |e: Error| match e {
        Error::Topology { what } => what,
        other => panic!("expected a topology error, got {other:?}"),
    };
    let options = TorusParamOptions::default();
    // A sphere: genus 0.
    let (p, t) = icosphere(2, 1.0);
    let e = topo(parameterise_torus(&p, &t, &vec![false; t.len()], &options).unwrap_err());
    assert!(e.contains("genus 0"), "{e}");
    // Two tori joined by a tube: genus 2. Each loses one quad; the two square holes are
    // joined by four quads.
    let (m, n) = (12, 8);
    let (mut p, mut t) = grid(m, n, &torus_point(1.0, 0.35), 0.0, None);
    let (q, s) = grid(m, n, &torus_point(1.0, 0.35), 0.0, None);
    let base = p.len() as u32;
    p.extend(q.iter().map(|x| *x + DVec3::new(3.0, 0.0, 0.0)));
    let at = |i: usize, j: usize| ((i % m) * n + j % n) as u32;
    let hole = [at(0, 0), at(1, 0), at(1, 1), at(0, 1)];
    let keep = |tri: &[u32; 3]| !tri.iter().all(|k| hole.contains(k));
    t.retain(keep);
    t.extend(s.iter().filter(|tri| keep(tri)).map(|tri| tri.map(|k| k + base)));
    // The hole's loop a → b → c → d, joined to the other's in reverse.
    let other = |k: usize| hole[(4 - k) % 4] + base;
    for k in 0..4 {
        let (a, b) = (hole[k], hole[(k + 1) % 4]);
        let (c, d) = (other(k + 1), other(k));
        t.push([a, b, c]);
        t.push([a, c, d]);
    }
    let e = topo(parameterise_torus(&p, &t, &vec![false; t.len()], &options).unwrap_err());
    assert!(e.contains("genus 2"), "{e}");
    // Open: a torus with one quad missing.
    let (p, mut t) = grid(m, n, &torus_point(1.0, 0.35), 0.0, None);
    t.retain(keep);
    let e = topo(parameterise_torus(&p, &t, &vec![false; t.len()], &options).unwrap_err());
    assert!(e.contains("not closed"), "{e}");
    // Two tori apart: two parts.
    let (p, t) = grid(m, n, &torus_point(1.0, 0.35), 0.0, None);
    let mut p2 = p.clone();
    p2.extend(p.iter().map(|x| *x + DVec3::X * 5.0));
    let mut t2 = t.clone();
    t2.extend(t.iter().map(|tri| tri.map(|k| k + p.len() as u32)));
    let e = topo(parameterise_torus(&p2, &t2, &vec![false; t2.len()], &options).unwrap_err());
    assert!(e.contains("2 separate parts"), "{e}");
    // The filled flags must match the triangles.
    let e = topo(parameterise_torus(&p, &t, &vec![false; t.len() - 1], &options).unwrap_err());
    assert!(e.contains("filled"), "{e}");
    // Too few triangles.
    let e = topo(parameterise_torus(&p, &t[..10], &[false; 10], &options).unwrap_err());
    assert!(e.contains("at least 14"), "{e}");
    // A NaN position.
    let mut bad = p.clone();
    bad[17].y = f64::NAN;
    let e = parameterise_torus(&bad, &t, &vec![false; t.len()], &options).unwrap_err();
    assert!(
        matches!(e, Error::NonFinite { what: hi_geomimage::NonFiniteInput::Vertex(17) }),
        "{e:?}"
    );
    // A bad option.
    let e = parameterise_torus(
        &p,
        &t,
        &vec![false; t.len()],
        &TorusParamOptions { tolerance: 0.0, ..options },
    )
    .unwrap_err();
    assert!(matches!(e, Error::InvalidOption { name: "tolerance", .. }), "{e:?}");
    // A triangle wound the other way.
    let mut flipped = t.clone();
    flipped[3].swap(0, 1);
    let e = topo(parameterise_torus(&p, &flipped, &vec![false; t.len()], &options).unwrap_err());
    assert!(e.contains("same direction"), "{e}");
}

#[test]
fn filled_triangles_are_flagged_in_the_image() {
    let (m, n) = (48, 16);
    let (p, t) = grid(m, n, &torus_point(1.0, 0.35), 0.0, None);
    // Flag the triangles of a band a ∈ [0, 2π/8): an eighth of the surface's a-range.
    let filled: Vec<bool> =
        t.iter().map(|tri| tri.iter().all(|&k| (k as usize / n) <= m / 8)).collect();
    let param = parameterise_torus(&p, &t, &filled, &TorusParamOptions::harmonic()).unwrap();
    let image = param.image(24, 64).unwrap();
    // The conformal map is uniform in a (v follows a linearly by the symmetry of rotation), so
    // the flagged band covers its share of the columns: 6 of 48 steps of a, less the band's
    // ragged edge.
    println!("filled fraction {}", image.filled_fraction);
    assert!((image.filled_fraction - 6.0 / 48.0).abs() < 1.5 / 48.0, "{}", image.filled_fraction);
    let counted = image.filled.iter().filter(|&&f| f).count() as f64 / image.filled.len() as f64;
    assert_eq!(counted, image.filled_fraction);
}

/// The same map and image on one thread as on all: every parallel loop writes its own slots
/// or sums in fixed blocks.
#[cfg(feature = "parallel")]
#[test]
fn results_do_not_depend_on_the_number_of_threads() {
    let (p, t) = mug(128, 40);
    let filled: Vec<bool> = (0..t.len()).map(|f| f % 7 == 0).collect();
    let run = || {
        let param = parameterise_torus(&p, &t, &filled, &TorusParamOptions::default()).unwrap();
        let image = param.image(40, 96).unwrap();
        (param.uv().to_vec(), param.offsets().to_vec(), param.report(), image)
    };
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap().install(run);
    let many = rayon::ThreadPoolBuilder::new().num_threads(4).build().unwrap().install(run);
    assert!(one == many, "one thread and four differ");
}

/// Triangles of zero area (coincident vertices) and slivers: the clamped weights stay
/// positive, so the map is still an embedding.
#[test]
fn degenerate_triangles_still_map_without_folds() {
    let (m, n) = (48, 16);
    let (mut p, t) = grid(m, n, &torus_point(1.0, 0.35), 0.0, None);
    // Every fifth vertex of one ring onto its neighbour, a few onto the middle of an edge.
    for j in (0..n).step_by(5) {
        p[5 * n + j] = p[5 * n + (j + 1) % n];
        p[20 * n + j] = 0.5 * (p[19 * n + j] + p[21 * n + j]);
    }
    let filled = vec![false; t.len()];
    for options in [TorusParamOptions::harmonic(), TorusParamOptions::default()] {
        let param = parameterise_torus(&p, &t, &filled, &options).unwrap();
        let (folded, area) = uv_area(&param);
        println!("degenerate: {:?}", param.report());
        assert_eq!(folded, 0, "folds");
        assert!((area - 1.0).abs() < 1e-9, "area {area}");
        let image = param.image(24, 64).unwrap();
        let chord = chord_bound(1.0, 0.35, 2.0 * TAU / m as f64, 2.0 * TAU / n as f64);
        for x in image.image.texels() {
            assert!(torus_distance(*x, 1.0, 0.35) <= chord, "texel {x} off the torus");
        }
    }
}

/// A torus as the fit finds them in the zero set of a scan's signed distance: a noisy ring of
/// radii 1 and 0.3 (the tube's radius waving by 0.05), with thin tentacles sticking out of it
/// and small holes filled by fans, by surface nets on a grid of spacing `h` (about
/// 25 / h² vertices).
fn messy_torus(h: f64) -> (Vec<DVec3>, Vec<[u32; 3]>, Vec<bool>) {
    let around = |a: f64, b: f64| {
        let dir = DVec3::new(b.cos() * a.cos(), b.cos() * a.sin(), b.sin());
        (DVec3::new(a.cos(), a.sin(), 0.0), dir)
    };
    let holes: Vec<(DVec3, f64)> = (0..12)
        .map(|k| {
            let (core, dir) = around(0.53 * k as f64, 1.7 * k as f64 + 0.4);
            (core + 0.3 * dir, h * (1.5 + 0.4 * (k % 9) as f64))
        })
        .collect();
    let tentacles: Vec<(DVec3, DVec3, f64)> = (0..6)
        .map(|k| {
            let (core, dir) = around(1.05 * k as f64 + 0.2, 2.3 * k as f64);
            let base = core + 0.2 * dir;
            (base, base + (0.4 + 0.05 * k as f64) * dir, h * (1.6 + 0.15 * k as f64))
        })
        .collect();
    let f = |x: DVec3, noise: f64| {
        if holes.iter().any(|&(c, r)| (x - c).length() < r) {
            return f64::NAN;
        }
        let tube = 0.3 + 0.05 * (5.0 * x.y.atan2(x.x)).sin();
        let mut d = (x.truncate().length() - 1.0).hypot(x.z) - tube;
        for &(a, b, r) in &tentacles {
            let s = ((x - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
            d = d.min((x - a - s * (b - a)).length() - r);
        }
        d + 0.6 * h * noise
    };
    let corner = DVec3::new(1.9, 1.9, 0.9);
    zero_set(&f, -corner, corner, h, hi_scan::repair::Closing::Torus, 2)
}

/// On a torus as messy as a scan's zero set, whose tentacles the harmonic map squeezes so much
/// that the relaxation's solves are pushed far below their tolerance before their maps stop
/// folding, the solves take what their budgets allow: tens of multigrid iterations for the
/// harmonic map, and for the relaxation at most six times as many (192 at least). With one
/// hierarchy built for the first round's weights the later rounds took over a thousand
/// iterations here.
#[test]
fn a_messy_torus_maps_within_its_iteration_budget() {
    let (p, t, filled) = messy_torus(0.04);
    let most = max_valence(p.len(), &t);
    println!("messy torus: {} vertices, valence up to {most}", p.len());
    assert!(p.len() > 10_000, "multigrid: {} vertices", p.len());
    assert!(filled.iter().any(|&f| f) && most >= 20, "filled holes");
    let harmonic = parameterise_torus(&p, &t, &filled, &TorusParamOptions::harmonic()).unwrap();
    let param = parameterise_torus(&p, &t, &filled, &TorusParamOptions::default()).unwrap();
    let (h, r) = (harmonic.report(), param.report());
    println!("messy torus: harmonic {h:?}\nmessy torus: relaxed {r:?}");
    assert_within_budget(&h, &r);
    for (name, m) in [("harmonic", &harmonic), ("relaxed", &param)] {
        let (folded, area) = uv_area(m);
        assert_eq!(folded, 0, "{name}");
        assert!((area - 1.0).abs() < 1e-9, "{name}: area {area}");
    }
}

/// Timings of large tori, the best of five runs each (run with `--ignored --nocapture`, in
/// release for real numbers).
#[test]
#[ignore = "a timing to read, not a check"]
fn timing_of_large_tori() {
    for (m, n) in [(168, 60), (528, 190)] {
        let (p, t) = grid(m, n, &torus_point(1.0, 0.35), 0.2, Some(&mut Rng(3)));
        let filled = vec![false; t.len()];
        for (name, options) in
            [("harmonic", TorusParamOptions::harmonic()), ("default", TorusParamOptions::default())]
        {
            let (mut took, mut sampled) = (f64::INFINITY, f64::INFINITY);
            let mut last = None;
            for _ in 0..5 {
                let start = Instant::now();
                let param = parameterise_torus(&p, &t, &filled, &options).unwrap();
                took = took.min(start.elapsed().as_secs_f64());
                let (rows, cols) = param.resolution(p.len());
                let start = Instant::now();
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
