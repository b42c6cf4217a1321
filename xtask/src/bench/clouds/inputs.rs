// SPDX-License-Identifier: MIT
//! Making the inputs: the clouds sampled from the models (cached), the models' bare vertices,
//! and the scans of other topologies found or made, as the rows that measure them.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::Result;
use glam::DVec3;
use hi_scan::scan::{Scan, read_scan};
use indicatif::ProgressBar;

use super::super::Options;
use super::super::poisson::{self, locate, path_str};
use super::super::sampling::{
    SplitMix64, cloud_file, diagonal, sample_triangles, torus_knot_tube, with_noise, write_xyz,
};
use super::report::count_name;
use super::{
    BIG, CGAL_DATA, Case, GROWTH_MODEL, Group, NOISE, SEED, Scale, Source, TOPOLOGY, Topo,
};
use crate::figures::scans::used_points;

/// Extracts the CGAL files [`TOPOLOGY`] uses into `target/xtask-bench/cgal/` (once); the
/// folder, or why not.
fn cgal_data(root: &Path) -> std::result::Result<PathBuf, String> {
    let dir = root.join("target/xtask-bench/cgal");
    let wanted: Vec<&str> = TOPOLOGY
        .iter()
        .filter_map(|t| match t.source {
            Source::Cgal(f) => Some(f),
            _ => None,
        })
        .collect();
    if wanted.iter().all(|f| dir.join(f).exists()) {
        return Ok(dir);
    }
    if !Path::new(CGAL_DATA).exists() {
        return Err(format!("{CGAL_DATA} (Debian's libcgal-demo) is not installed"));
    }
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let status = Command::new("tar")
        .arg("xzf")
        .arg(CGAL_DATA)
        .arg("-C")
        .arg(&dir)
        .args(&wanted)
        .status()
        .map_err(|e| format!("tar: {e}"))?;
    if !status.success() {
        return Err(format!("tar could not extract {} from {CGAL_DATA}", wanted.join(", ")));
    }
    Ok(dir)
}

/// The cloud of `n` points of the mesh `scan` (named `name`), from the cache or made now.
fn cloud(dir: &Path, name: &str, scan: &Scan, n: usize, bar: &ProgressBar) -> Result<PathBuf> {
    let path = cloud_file(dir, name, n, SEED);
    if !path.exists() {
        bar.set_message(format!("sampling {} points of {name}", count_name(n)));
        let mut rng = SplitMix64::new(SEED);
        let points = sample_triangles(&scan.points, &scan.triangles, n, &mut rng)?;
        let sigma = NOISE * diagonal(&used_points(scan));
        write_xyz(&path, &with_noise(points, sigma, &mut rng))?;
    }
    Ok(path)
}

/// An XYZ of `points` at `path`, unless it is there already (its content depends only on its
/// name).
fn cached_xyz(path: &Path, points: impl FnOnce() -> Vec<DVec3>) -> Result<()> {
    if !path.exists() {
        write_xyz(path, &points())?;
    }
    Ok(())
}

/// Writes a mesh as OFF.
fn write_off(path: &Path, points: &[DVec3], triangles: &[[u32; 3]]) -> Result<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(w, "OFF\n{} {} 0", points.len(), triangles.len())?;
    for p in points {
        writeln!(w, "{} {} {}", p.x, p.y, p.z)?;
    }
    for t in triangles {
        writeln!(w, "3 {} {} {}", t[0], t[1], t[2])?;
    }
    w.flush()?;
    Ok(())
}

/// A row of `group` named `label`, of `model`, reading `input` (ours) and `peer` (Poisson's),
/// measured against `reference`; no points and the default camera until set.
fn new_case(
    group: Group,
    model: &str,
    label: String,
    input: &Path,
    peer: &Path,
    reference: &str,
) -> Case {
    Case {
        group,
        model: model.to_owned(),
        stem: label.replace(' ', "-"),
        label,
        what: String::new(),
        ours_input: input.to_path_buf(),
        peer_input: peer.to_path_buf(),
        reference: reference.to_owned(),
        points: 0,
        eye: DVec3::Z,
        up: DVec3::Y,
    }
}

/// The other meshes of `fixtures/models` and the shared data, given as their bare vertices only
/// (no clouds): (row name, file, eye direction, up). Their meshes are the scans of other
/// topologies of [`super::TOPOLOGY`] (several parts, genus 3, an open sheet), a teapot, a
/// dragon whose centroid lies outside its body, and a head scan.
const VERTICES_ONLY: &[(&str, &str, [f64; 3], [f64; 3])] = &[
    ("teapot", "teapot.obj", [0.6, 0.5, 1.0], [0.0, 1.0, 0.0]),
    ("dragon", "dragon.ply", [0.3, 0.3, 1.0], [0.0, 1.0, 0.0]),
    ("cessna", "hoppe-cessna.obj", [0.8, 0.5, 0.6], [0.0, 0.0, 1.0]),
    ("mechpart", "hoppe-mechpart.obj", [0.6, 0.5, 0.8], [0.0, 1.0, 0.0]),
    ("club", "hoppe-club.obj", [0.3, 0.4, 1.0], [0.0, 1.0, 0.0]),
    ("spider", "spider.stl", [0.6, -0.8, 0.7], [0.0, 0.0, 1.0]),
    ("head", "lee-perry-smith-head.obj", [0.3, 0.2, 1.0], [0.0, 1.0, 0.0]),
];

/// The rows, their inputs made or found; and the inputs not found.
pub(super) fn cases(
    root: &Path,
    scale: &Scale,
    options: &Options,
    dir: &Path,
    bar: &ProgressBar,
) -> Result<(Vec<Case>, Vec<String>)> {
    let mut clouds = Vec::new();
    let mut vertices = Vec::new();
    let mut growth = Vec::new();
    let mut topology = Vec::new();
    let mut missing = Vec::new();
    for &(name, file, eye, up) in poisson::MODELS {
        if !options.wants(name) {
            continue;
        }
        let Some(path) = locate(root, file) else {
            missing.push(file.to_owned());
            continue;
        };
        for c in model_cases(scale, dir, bar, name, &path, (eye, up))? {
            match c.group {
                Group::Growth => growth.push(c),
                Group::Vertices => vertices.push(c),
                Group::Cloud | Group::Topology => clouds.push(c),
            }
        }
    }
    for &(name, file, eye, up) in VERTICES_ONLY {
        if !options.wants(name) {
            continue;
        }
        let Some(path) = locate(root, file) else {
            missing.push(file.to_owned());
            continue;
        };
        let scan = read_scan(&path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        vertices.push(vertices_case(dir, name, &scan, path_str(&path)?, (eye, up))?);
    }
    let mut cgal = None;
    for t in TOPOLOGY.iter().filter(|t| options.wants(t.name)) {
        let Some((input, reference)) =
            topology_input(root, scale, dir, bar, t, &mut cgal, &mut missing)?
        else {
            continue;
        };
        topology.push(topology_case(dir, t, &input, &reference)?);
    }
    growth.sort_by_key(|c| c.points);
    let mut all = clouds;
    all.extend(vertices);
    all.extend(topology);
    all.extend(growth);
    Ok((all, missing))
}

/// The rows of the mesh model `name` read from `path` and seen from `(eye, up)`: its clouds
/// (and the growth plots' clouds of [`GROWTH_MODEL`]), then its bare vertices; none for a
/// point set.
fn model_cases(
    scale: &Scale,
    dir: &Path,
    bar: &ProgressBar,
    name: &str,
    path: &Path,
    (eye, up): ([f64; 3], [f64; 3]),
) -> Result<Vec<Case>> {
    let scan = read_scan(path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    if scan.triangles.is_empty() {
        return Ok(Vec::new()); // a point set: nothing to sample
    }
    let reference = path_str(path)?.to_owned();
    let view = |mut c: Case, n: usize| {
        c.points = n;
        c.eye = DVec3::from(eye);
        c.up = DVec3::from(up);
        c
    };
    let mut sizes = vec![(Group::Cloud, scale.cloud)];
    if BIG.contains(&name) {
        sizes.push((Group::Cloud, scale.big));
    }
    if name == GROWTH_MODEL {
        sizes.extend(
            scale
                .growth
                .iter()
                .filter(|n| !sizes.iter().any(|(_, m)| m == *n))
                .map(|n| (Group::Growth, *n))
                .collect::<Vec<_>>(),
        );
    }
    let mut made = Vec::new();
    for (group, n) in sizes {
        let xyz = cloud(dir, name, &scan, n, bar)?;
        let label = format!("{name}, {} points", count_name(n));
        let mut c = view(new_case(group, name, label, &xyz, &xyz, &reference), n);
        c.stem = format!("{name}-{n}");
        made.push(c);
    }
    made.push(vertices_case(dir, name, &scan, &reference, (eye, up))?);
    Ok(made)
}

/// The row of the mesh `scan` (named `name`, read from `reference`, seen from `(eye, up)`)
/// given as its bare vertices: an XYZ of the vertices its triangles use, cached in `dir`.
fn vertices_case(
    dir: &Path,
    name: &str,
    scan: &Scan,
    reference: &str,
    (eye, up): ([f64; 3], [f64; 3]),
) -> Result<Case> {
    let xyz = dir.join(format!("{name}-vertices.xyz"));
    let points = used_points(scan);
    let n = points.len();
    cached_xyz(&xyz, || points)?;
    let label = format!("{name}, {} vertices", count_name(n));
    let mut c = new_case(Group::Vertices, name, label, &xyz, &xyz, reference);
    c.points = n;
    c.eye = DVec3::from(eye);
    c.up = DVec3::from(up);
    c.stem = format!("{name}-vertices");
    Ok(c)
}

/// The input of the scan `t` and trimesh's reference for it, found, extracted (CGAL's data,
/// once into `cgal`) or made (the torus knot); `None`, with a line added to `missing`, when it
/// is not found.
fn topology_input(
    root: &Path,
    scale: &Scale,
    dir: &Path,
    bar: &ProgressBar,
    t: &Topo,
    cgal: &mut Option<std::result::Result<PathBuf, String>>,
    missing: &mut Vec<String>,
) -> Result<Option<(PathBuf, String)>> {
    Ok(Some(match t.source {
        Source::Model(file) => match locate(root, file) {
            Some(p) => (p.clone(), path_str(&p)?.to_owned()),
            None => {
                missing.push(file.to_owned());
                return Ok(None);
            }
        },
        Source::Cgal(file) => match cgal.get_or_insert_with(|| cgal_data(root)) {
            Ok(d) => {
                let p = d.join(file);
                // CGAL's point sets (`points_3/`) are their own reference.
                let reference = if file.starts_with("data/points_3/") {
                    "-".to_owned()
                } else {
                    path_str(&p)?.to_owned()
                };
                (p, reference)
            }
            Err(why) => {
                missing.push(format!("{file} ({why})"));
                return Ok(None);
            }
        },
        Source::Knot => {
            let mesh = dir.join("torus-knot-tube.off");
            let (points, triangles) = torus_knot_tube(0.4, 720, 48);
            if !mesh.exists() {
                write_off(&mesh, &points, &triangles)?;
            }
            let scan = Scan { points, triangles, ..Scan::default() };
            let xyz = cloud(dir, "torus-knot", &scan, scale.knot, bar)?;
            (xyz, path_str(&mesh)?.to_owned())
        }
    }))
}

/// The row of the scan `t` read from `input`, measured against `reference`.
fn topology_case(dir: &Path, t: &Topo, input: &Path, reference: &str) -> Result<Case> {
    let scan = read_scan(input).map_err(|e| anyhow::anyhow!("{}: {e}", input.display()))?;
    let stem = t.name.replace(' ', "-");
    // Poisson is given the points: those the triangles use, positions only.
    let peer = if matches!(t.source, Source::Knot) {
        input.to_path_buf()
    } else {
        let xyz = dir.join(format!("{stem}-points.xyz"));
        let points = used_points(&scan);
        cached_xyz(&xyz, || points)?;
        xyz
    };
    // A point set with normals is given to both as positions only.
    let ours = if scan.triangles.is_empty() { peer.clone() } else { input.to_path_buf() };
    let n = used_points(&scan).len();
    let mut c = new_case(Group::Topology, &stem, t.name.to_owned(), &ours, &peer, reference);
    c.what = t.what.to_owned();
    c.points = n;
    c.eye = DVec3::from(t.eye);
    c.up = DVec3::from(t.up);
    Ok(c)
}
