// SPDX-License-Identifier: MIT
//! Spherical parameterisation of mesh scans: timing and quality per model.
//!
//! `cargo run --release -p hi-geomimage --example param_eval -- MODEL...`

use std::time::Instant;

use hi_geomimage::repair::close_mesh;
use hi_geomimage::scan::read_scan;
use hi_geomimage::sphereparam::{SphereParamOptions, parameterise};

fn main() {
    for arg in std::env::args().skip(1) {
        let t0 = Instant::now();
        let scan = match read_scan(std::path::Path::new(&arg)) {
            Ok(s) => s,
            Err(e) => {
                println!("{arg}: {e}");
                continue;
            }
        };
        let mut scan = scan;
        if !scan.triangles.is_empty() {
            let mut used = vec![false; scan.points.len()];
            for t in &scan.triangles {
                for &k in t {
                    used[k as usize] = true;
                }
            }
            let n0 = scan.points.len();
            let mut map = vec![u32::MAX; n0];
            let mut pts = Vec::new();
            for (i, p) in scan.points.iter().enumerate() {
                if used[i] {
                    map[i] = pts.len() as u32;
                    pts.push(*p);
                }
            }
            scan.triangles.iter_mut().for_each(|t| *t = t.map(|k| map[k as usize]));
            scan.points = pts;
            if n0 != scan.points.len() {
                println!("  {} unused vertices dropped", n0 - scan.points.len());
            }
        }
        let t1 = Instant::now();
        let closed = match close_mesh(&scan.points, &scan.triangles) {
            Ok(c) => c,
            Err(e) => {
                println!("{arg}: {e}");
                continue;
            }
        };
        let t2 = Instant::now();
        let env =
            |k: &str, d: usize| std::env::var(k).ok().and_then(|x| x.parse().ok()).unwrap_or(d);
        let opts = SphereParamOptions {
            sweeps: env("HI_SWEEPS", 4),
            final_sweeps: env("HI_FINAL", 4),
            fine_vertices: env("HI_FINE", 20_000),
        };
        let param = parameterise(&closed, &opts);
        let t3 = Instant::now();
        match param {
            Ok(p) => {
                let q = p.quality();
                if let Ok(side) = std::env::var("SIDE") {
                    let side: usize = side.parse().unwrap_or(256);
                    let t4 = Instant::now();
                    let img = p.image(hi_geomimage::Layout::FlatOctahedron, side, side).unwrap();
                    let how = match std::env::var("REG").as_deref() {
                        Ok("off") => hi_geomimage::regularise::Regularisation::Off,
                        _ => hi_geomimage::regularise::Regularisation::Auto,
                    };
                    let (reg, rep) = hi_geomimage::regularise::regularise(&img.image, how).unwrap();
                    println!("  regularised: {rep:?}");
                    let surface = reg.surface().unwrap();
                    let t5 = Instant::now();
                    let d = hi_geomimage::distance::distances_to_surface(&surface, &scan.points, 2)
                        .unwrap();
                    let [m, _, x] = d.relative();
                    {
                        // The texels themselves, as a triangle mesh (no interpolation).
                        let (r, c) = (side, side);
                        let mut tris = Vec::new();
                        for i in 0..r {
                            for j in 0..c {
                                let q = |a: usize, b: usize| ((a % r) * c + b % c) as u32;
                                tris.push([q(i, j), q(i + 1, j), q(i + 1, j + 1)]);
                                tris.push([q(i, j), q(i + 1, j + 1), q(i, j + 1)]);
                            }
                        }
                        let dt = hi_geomimage::distance::distances_to_mesh(
                            &scan.points,
                            img.image.texels(),
                            &tris,
                        )
                        .unwrap();
                        let rel = dt.mean / d.diagonal;
                        let relx = dt.max / d.diagonal;
                        let k = (0..dt.per_point.len())
                            .max_by(|&a, &b| dt.per_point[a].total_cmp(&dt.per_point[b]))
                            .unwrap();
                        // Sampling density around the worst point: sphere area / surface area, relative to the mean.
                        let mesh = p.mesh();
                        let sph = p.sphere();
                        let vi = mesh.scan_vertex.iter().position(|&s| s as usize == k);
                        if let Some(vi) = vi {
                            let scale = mesh.area() / (4.0 * std::f64::consts::PI);
                            for t in mesh.triangles.iter().filter(|t| t.contains(&(vi as u32))) {
                                let [a, b, c2] = t.map(|q| sph[q as usize]);
                                let [pa, pb, pc] = t.map(|q| mesh.positions[q as usize]);
                                let ap = 0.5 * (pb - pa).cross(pc - pa).length();
                                let as_ = 0.5 * (b - a).cross(c2 - a).length();
                                println!(
                                    "      face {t:?} surface area {ap:.3e} density {:.3} edges {:.2e} {:.2e} {:.2e}",
                                    as_ * scale / ap,
                                    (pb - pa).length(),
                                    (pc - pb).length(),
                                    (pa - pc).length()
                                );
                            }
                        }
                        println!(
                            "    texel mesh: mean {:.4}% max {:.3}% at {:?}",
                            100.0 * rel,
                            100.0 * relx,
                            scan.points[k]
                        );
                    }
                    let mut idx: Vec<usize> = (0..d.per_point.len()).collect();
                    idx.sort_by(|&a, &b| d.per_point[b].total_cmp(&d.per_point[a]));
                    for &k in idx.iter().take(5) {
                        println!(
                            "    worst point {k} at {:?}: {:.3}%",
                            scan.points[k],
                            100.0 * d.per_point[k] / d.diagonal
                        );
                    }
                    println!(
                        "  image {side}: {:.3}s, filled {:.4}, scan->surface mean {:.4}% max {:.3}%",
                        (t5 - t4).as_secs_f64(),
                        img.filled_fraction,
                        100.0 * m,
                        100.0 * x
                    );
                    let opts = hi_surface::MeshOptions {
                        n_u: side / 2,
                        n_v: side,
                        u_range: [0.0, 0.5],
                        v_range: [0.0, 1.0],
                        ..Default::default()
                    };
                    let mesh = hi_surface::TriangleMesh::try_from_surface(&surface, &opts).unwrap();
                    let name = std::path::Path::new(&arg)
                        .file_stem()
                        .unwrap()
                        .to_string_lossy()
                        .to_string();
                    hi_surface::export::save(&mesh, format!("/tmp/pe/{name}-param.glb")).unwrap();
                }
                println!(
                    "{arg}: V {} F {} | read {:.3}s repair {:.3}s param {:.3}s | {:?} | {:?}",
                    closed.positions.len(),
                    closed.triangles.len(),
                    (t1 - t0).as_secs_f64(),
                    (t2 - t1).as_secs_f64(),
                    (t3 - t2).as_secs_f64(),
                    closed.repair,
                    q
                );
            }
            Err(e) => println!("{arg}: param failed: {e} ({:?})", closed.repair),
        }
    }
}
