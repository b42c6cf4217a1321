// SPDX-License-Identifier: MIT
//! Ray–surface intersection (Hardy 2005, §5.6) checked against closed forms and against each
//! other: the exact harmonic sphere and torus against the analytic sphere and the torus quartic
//! (solved here by dense sampling and bisection), interval bisection against Krawczyk, Bézier
//! patches against the interval methods, and the mesh BVH against brute force and an
//! independent Möller–Trumbore test.

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_mesh::TriangleMesh;
use hi_raytrace::{
    BezierObject, BezierOptions, Camera, HarmonicObject, HarmonicOptions, IntervalMethod,
    MeshObject, Ray,
};
use hi_surface::{HarmonicSurface, MeshOptions, sphere, torus};
use hi_testkit::proptest_config;
use proptest::prelude::*;

fn settings(method: IntervalMethod) -> HarmonicOptions {
    HarmonicOptions { method, ..HarmonicOptions::default() }
}

/// The nearest t > 0 where the ray meets the sphere |x| = r (the quadratic, stably).
fn sphere_t(ray: &Ray, r: f64) -> Option<f64> {
    let (o, d) = (ray.origin, ray.dir);
    let (a, b, c) = (d.dot(d), 2.0 * o.dot(d), o.dot(o) - r * r);
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let (t0, t1) = (q / a, c / q);
    let (lo, hi) = (t0.min(t1), t0.max(t1));
    if lo > 0.0 {
        Some(lo)
    } else if hi > 0.0 {
        Some(hi)
    } else {
        None
    }
}

/// The torus (√(x² + y²) − R)² + z² = r² along the ray: the nearest sign change of the
/// implicit function on a dense sample of [0, `t_end`], refined by bisection.
fn torus_t(ray: &Ray, big_r: f64, r: f64, t_end: f64) -> Option<f64> {
    let f = |t: f64| {
        let p = ray.point_at(t);
        let q = p.x.hypot(p.y) - big_r;
        q * q + p.z * p.z - r * r
    };
    let n = 40_000;
    let step = t_end / f64::from(n);
    let mut prev = f(0.0);
    for i in 1..=n {
        let t = step * f64::from(i);
        let cur = f(t);
        if prev.signum() != cur.signum() {
            let (mut lo, mut hi) = (t - step, t);
            let s_lo = prev.signum();
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if f(mid).signum() == s_lo {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return Some(0.5 * (lo + hi));
        }
        prev = cur;
    }
    None
}

/// The rays of an n × n image through `camera`.
fn rays(camera: &Camera, n: usize) -> Vec<Ray> {
    (0..n * n)
        .map(|i| {
            let (x, y) = ((i % n) as f64 + 0.5, (i / n) as f64 + 0.5);
            camera.ray(x / n as f64, y / n as f64, 1.0)
        })
        .collect()
}

/// Pixels whose 4-neighbours differ in hit or miss (in `a` or in `b`).
fn silhouette(hit_a: &[bool], hit_b: &[bool], n: usize) -> Vec<bool> {
    (0..n * n)
        .map(|i| {
            let (x, y) = (i % n, i / n);
            let mut neighbours = vec![];
            if x > 0 {
                neighbours.push(i - 1);
            }
            if x + 1 < n {
                neighbours.push(i + 1);
            }
            if y > 0 {
                neighbours.push(i - n);
            }
            if y + 1 < n {
                neighbours.push(i + n);
            }
            neighbours.iter().any(|&j| hit_a[j] != hit_a[i] || hit_b[j] != hit_b[i])
        })
        .collect()
}

/// A bumpy m×n closed surface: a torus with a deterministic ripple.
fn bumpy(m: usize, n: usize, seed: f64) -> HarmonicSurface<DVec3> {
    let rows = (0..m)
        .map(|j| {
            (0..n)
                .map(|k| {
                    let (u, v) = (j as f64 / m as f64, k as f64 / n as f64);
                    let (tu, tv) = (std::f64::consts::TAU * u, std::f64::consts::TAU * v);
                    let r = 1.0 + 0.3 * (3.0 * tu + seed).sin() * (2.0 * tv).cos();
                    DVec3::new(
                        (3.0 + r * tv.cos()) * tu.cos(),
                        (3.0 + r * tv.cos()) * tu.sin(),
                        r * tv.sin(),
                    )
                })
                .collect()
        })
        .collect();
    HarmonicSurface::new(rows)
}

#[test]
fn harmonic_sphere_hits_match_the_analytic_sphere() {
    let camera = Camera::try_new(DVec3::new(1.0, -3.0, 2.0), DVec3::ZERO, DVec3::Z, 0.9).unwrap();
    let krawczyk =
        HarmonicObject::try_new(sphere(1.0), &settings(IntervalMethod::Krawczyk)).unwrap();
    let bisection =
        HarmonicObject::try_new(sphere(1.0), &settings(IntervalMethod::Bisection)).unwrap();
    let (mut n_hits, mut n_proven) = (0, 0);
    for ray in rays(&camera, 40) {
        let exact = sphere_t(&ray, 1.0);
        let k = krawczyk.intersect(&ray);
        let b = bisection.intersect(&ray);
        let Some(t) = exact else {
            // A miss must be a clear miss or a grazing ray.
            let closest = ray.origin + ray.dir * (-ray.origin.dot(ray.dir));
            assert!(k.is_none() || closest.length() > 1.0 - 1e-6, "Krawczyk hit a miss");
            assert!(b.is_none() || closest.length() > 1.0 - 1e-5, "bisection hit a miss");
            continue;
        };
        let cos = (ray.point_at(t).normalize().dot(ray.dir)).abs();
        if cos < 0.05 {
            continue; // a grazing ray: t is ill-conditioned
        }
        let k = k.expect("Krawczyk finds the hit");
        let b = b.expect("bisection finds the hit");
        n_hits += 1;
        n_proven += usize::from(k.proven);
        assert!((k.t - t).abs() < 1e-9, "Krawczyk t = {} vs {t}", k.t);
        assert!((b.t - t).abs() < 1e-5 / cos, "bisection t = {} vs {t}", b.t);
        // The reported parameters lie on the surface at the hit.
        let p = krawczyk.surface().eval(k.u, k.v);
        assert!((p - ray.point_at(t)).length() < 1e-8, "(u, v) of the hit");
    }
    assert!(n_hits > 400, "the sphere fills the view: {n_hits}");
    assert!(
        n_proven * 100 >= n_hits * 99,
        "Krawczyk proves almost every root: {n_proven}/{n_hits}"
    );
}

#[test]
fn harmonic_torus_hits_match_the_quartic() {
    let (big_r, r) = (2.0, 0.75);
    let camera = Camera::try_new(DVec3::new(0.5, -5.5, 3.5), DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    let krawczyk =
        HarmonicObject::try_new(torus(big_r, r), &settings(IntervalMethod::Krawczyk)).unwrap();
    let bisection =
        HarmonicObject::try_new(torus(big_r, r), &settings(IntervalMethod::Bisection)).unwrap();
    let n = 36;
    let all = rays(&camera, n);
    let exact: Vec<Option<f64>> = all.iter().map(|ray| torus_t(ray, big_r, r, 12.0)).collect();
    let hit_exact: Vec<bool> = exact.iter().map(Option::is_some).collect();
    let ks: Vec<_> = all.iter().map(|ray| krawczyk.intersect(ray)).collect();
    let hit_k: Vec<bool> = ks.iter().map(Option::is_some).collect();
    let edge = silhouette(&hit_exact, &hit_k, n);
    let mut n_compared = 0;
    for (i, ray) in all.iter().enumerate() {
        if edge[i] {
            continue;
        }
        assert_eq!(
            hit_k[i], hit_exact[i],
            "pixel {i}: Krawczyk and the quartic disagree on hit/miss"
        );
        let b = bisection.intersect(ray);
        assert_eq!(b.is_some(), hit_exact[i], "pixel {i}: bisection hit/miss");
        if let (Some(t), Some(k), Some(b)) = (exact[i], ks[i], b) {
            assert!((k.t - t).abs() < 1e-8, "pixel {i}: Krawczyk t = {} vs {t}", k.t);
            let n = krawczyk.surface().normal(k.u, k.v).expect("regular");
            assert!((b.t - t).abs() * n.dot(ray.dir).abs() < 1e-5, "pixel {i}: bisection t");
            n_compared += 1;
        }
    }
    assert!(n_compared > 300, "enough pixels on the torus: {n_compared}");
}

/// Pixels hit by Bézier patches and by interval Newton agree: hit distances within the
/// conversion's bound (projected on the normal), and no pixel hit by one and missed by the other
/// away from silhouettes.
fn bezier_agrees_with_interval(surface: HarmonicSurface<DVec3>, camera: &Camera, n: usize) {
    let patches = surface
        .to_bezier(
            BezierScheme::Hermite(HermiteDegree::Cubic),
            hi_curve::bezier::Tolerance::Absolute(1e-4),
        )
        .unwrap();
    let bound = patches.report.bound;
    assert!(bound <= 1e-4, "the conversion's bound");
    let bez = BezierObject::try_from_surface(&patches, &BezierOptions::default()).unwrap();
    let interval = HarmonicObject::try_new(surface, &HarmonicOptions::default()).unwrap();
    let all = rays(camera, n);
    let hb: Vec<_> = all.iter().map(|r| bez.intersect(r)).collect();
    let hi: Vec<_> = all.iter().map(|r| interval.intersect(r)).collect();
    let hit_b: Vec<bool> = hb.iter().map(Option::is_some).collect();
    let hit_i: Vec<bool> = hi.iter().map(Option::is_some).collect();
    let edge = silhouette(&hit_b, &hit_i, n);
    let mut n_both = 0;
    let mut n_mismatch_inside = 0;
    for i in 0..n * n {
        match (hb[i], hi[i]) {
            (Some(b), Some(h)) => {
                n_both += 1;
                let normal = interval.surface().normal(h.u, h.v).expect("regular");
                let along_normal = (b.t - h.t).abs() * normal.dot(all[i].dir).abs();
                assert!(
                    along_normal <= bound + 1e-9,
                    "pixel {i}: |Δt|·|n·d| = {along_normal:e} above the bound {bound:e}"
                );
                if !edge[i] {
                    // Away from silhouettes the two are the same root.
                    assert!((b.t - h.t).abs() < 1e-2, "pixel {i}: Δt = {}", b.t - h.t);
                }
            }
            (None, None) => {}
            _ => n_mismatch_inside += usize::from(!edge[i]),
        }
    }
    assert_eq!(n_mismatch_inside, 0, "hit by one method only, away from silhouettes");
    assert!(n_both > n * n / 5, "enough pixels hit: {n_both}");
}

#[test]
fn bezier_and_interval_agree_on_the_torus() {
    let camera = Camera::try_new(DVec3::new(0.0, -7.5, 5.0), DVec3::ZERO, DVec3::Z, 0.75).unwrap();
    bezier_agrees_with_interval(torus(2.0, 1.0), &camera, 40);
}

#[test]
fn bezier_and_interval_agree_on_a_bumpy_surface() {
    let camera = Camera::try_new(DVec3::new(2.0, -9.0, 6.0), DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    bezier_agrees_with_interval(bumpy(8, 6, 0.7), &camera, 36);
}

#[test]
fn bisection_and_krawczyk_agree() {
    let surface = bumpy(6, 6, 1.3);
    let k = HarmonicObject::try_new(surface.clone(), &settings(IntervalMethod::Krawczyk)).unwrap();
    let b = HarmonicObject::try_new(surface, &settings(IntervalMethod::Bisection)).unwrap();
    let camera = Camera::try_new(DVec3::new(-3.0, -8.0, 6.0), DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    let n = 32;
    let all = rays(&camera, n);
    let hk: Vec<_> = all.iter().map(|r| k.intersect(r)).collect();
    let hb: Vec<_> = all.iter().map(|r| b.intersect(r)).collect();
    let edge = silhouette(
        &hk.iter().map(Option::is_some).collect::<Vec<_>>(),
        &hb.iter().map(Option::is_some).collect::<Vec<_>>(),
        n,
    );
    let tol = 1e-7 * 10.0; // the distance tolerance times the size of the surface, roughly
    for i in 0..n * n {
        match (hk[i], hb[i]) {
            (Some(x), Some(y)) => {
                let normal = k.surface().normal(x.u, x.v).expect("regular");
                let off = (all[i].point_at(x.t) - all[i].point_at(y.t)).dot(normal).abs();
                assert!(
                    off < 10.0 * tol,
                    "pixel {i}: the hits are {off:e} apart across the surface"
                );
            }
            (None, None) => {}
            _ => assert!(edge[i], "pixel {i}: hit by one method only"),
        }
    }
}

/// Möller–Trumbore, written independently of the library's watertight test.
fn moller_trumbore(ray: &Ray, a: DVec3, b: DVec3, c: DVec3) -> Option<f64> {
    let (e1, e2) = (b - a, c - a);
    let p = ray.dir.cross(e2);
    let det = e1.dot(p);
    if det.abs() < 1e-14 {
        return None;
    }
    let s = ray.origin - a;
    let u = s.dot(p) / det;
    let q = s.cross(e1);
    let v = ray.dir.dot(q) / det;
    if !(0.0..=1.0).contains(&u) || v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(q) / det;
    (t > 0.0).then_some(t)
}

#[test]
fn mesh_hits_match_brute_force() {
    let options = MeshOptions { n_u: 24, n_v: 48, ..MeshOptions::default() };
    let mesh = bumpy(6, 8, 0.2).to_mesh(&options).unwrap();
    let object = MeshObject::new(mesh.clone());
    let camera = Camera::try_new(DVec3::new(1.0, -9.0, 5.0), DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    let mut n_hits = 0;
    for ray in rays(&camera, 48) {
        let bvh = object.intersect(&ray);
        let brute = hi_raytrace::testing::intersect_brute_force(&object, &ray);
        assert_eq!(bvh.map(|h| h.1.t), brute.map(|h| h.1.t), "BVH = brute force");
        let mt = mesh
            .triangles()
            .iter()
            .filter_map(|t| {
                let [a, b, c] = t.map(|k| mesh.positions()[k as usize]);
                moller_trumbore(&ray, a, b, c)
            })
            .fold(None, |acc: Option<f64>, t| Some(acc.map_or(t, |a| a.min(t))));
        match (bvh, mt) {
            (Some((_, h)), Some(t)) => {
                n_hits += 1;
                assert!((h.t - t).abs() < 1e-9, "t = {} vs Möller–Trumbore {t}", h.t);
                assert!((h.b.iter().sum::<f64>() - 1.0).abs() < 1e-12, "barycentric");
            }
            (None, None) => {}
            // An edge hit that one test takes and the other leaves: a measure-zero event that a
            // pixel grid can still produce; the other test must then graze an edge too.
            (a, b) => panic!("hit/miss differ: {a:?} vs {b:?}"),
        }
    }
    assert!(n_hits > 300, "the mesh fills the view: {n_hits}");
}

/// Shadow rays' any-hit query against the nearest hit: for every object type, a ray is
/// occluded exactly when the nearest hit exists, with the segment cut short at several
/// lengths (before, between and after the surface's layers) as a point light cuts it.
#[test]
fn any_hit_occlusion_matches_the_nearest_hit() {
    let surface = bumpy(5, 6, 0.3);
    let patches = surface
        .to_bezier(
            BezierScheme::Hermite(HermiteDegree::Cubic),
            hi_curve::bezier::Tolerance::Absolute(1e-4),
        )
        .unwrap();
    let mesh =
        surface.to_mesh(&MeshOptions { n_u: 24, n_v: 48, ..MeshOptions::default() }).unwrap();
    let mesh = MeshObject::new(mesh);
    let bezier = BezierObject::try_from_surface(&patches, &BezierOptions::default()).unwrap();
    let krawczyk =
        HarmonicObject::try_new(surface.clone(), &settings(IntervalMethod::Krawczyk)).unwrap();
    let bisection = HarmonicObject::try_new(surface, &settings(IntervalMethod::Bisection)).unwrap();
    let camera = Camera::try_new(DVec3::new(2.0, -9.0, 4.0), DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    let (mut n_occluded, mut n_clear) = (0, 0);
    for ray in rays(&camera, 24) {
        for t_max in [f64::INFINITY, 12.0, 9.0, 7.0, 3.0] {
            let r = ray.with_t_max(t_max);
            let cases = [
                ("mesh", mesh.intersect(&r).is_some(), mesh.occluded(&r)),
                ("bezier", bezier.intersect(&r).is_some(), bezier.occluded(&r)),
                ("krawczyk", krawczyk.intersect(&r).is_some(), krawczyk.occluded(&r)),
                ("bisection", bisection.intersect(&r).is_some(), bisection.occluded(&r)),
            ];
            for (name, nearest, any) in cases {
                assert_eq!(any, nearest, "{name}, t_max {t_max}: any-hit against nearest hit");
                if any {
                    n_occluded += 1;
                } else {
                    n_clear += 1;
                }
            }
        }
    }
    assert!(n_occluded > 500 && n_clear > 500, "both outcomes: {n_occluded} / {n_clear}");
}

proptest! {
    #![proptest_config(proptest_config(64))]

    /// Random rays aimed near the sphere: Krawczyk finds the analytic root.
    #[test]
    fn random_rays_hit_the_sphere_where_the_quadratic_says(
        ox in -4.0f64..4.0, oy in -4.0f64..4.0, oz in 2.5f64..4.0,
        ax in -0.55f64..0.55, ay in -0.55f64..0.55, az in -0.55f64..0.55,
        r in 0.5f64..2.0,
    ) {
        let origin = DVec3::new(ox, oy, oz) * r;
        let aim = DVec3::new(ax, ay, az) * r;
        let ray = Ray::new(origin, (aim - origin).normalize());
        let object = HarmonicObject::try_new(sphere(r), &HarmonicOptions::default()).unwrap();
        let exact = sphere_t(&ray, r).expect("aimed inside the sphere");
        let cos = ray.point_at(exact).normalize().dot(ray.dir).abs();
        prop_assume!(cos > 0.05);
        let hit = object.intersect(&ray).expect("a hit");
        prop_assert!((hit.t - exact).abs() < 1e-9 * r.max(1.0), "t = {} vs {exact}", hit.t);
    }

    /// Random triangles and rays: the BVH answers as brute force does.
    #[test]
    fn random_meshes_bvh_equals_brute_force(
        points in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0), 9..60),
        ox in -0.5f64..0.5, oy in -0.5f64..0.5,
    ) {
        let positions: Vec<DVec3> = points.iter().map(|&(x, y, z)| DVec3::new(x, y, z)).collect();
        let n_tris = positions.len() / 3;
        let triangles: Vec<[u32; 3]> =
            (0..n_tris as u32).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect();
        let normals = vec![DVec3::Z; positions.len()];
        let uvs = vec![glam::DVec2::ZERO; positions.len()];
        let mesh = TriangleMesh::try_new(positions, normals, uvs, triangles).unwrap();
        let object = MeshObject::new(mesh);
        for k in 0..16 {
            let a = f64::from(k) * 0.4;
            let ray = Ray::new(DVec3::new(ox, oy, 3.0), DVec3::new(0.2 * a.cos(), 0.2 * a.sin(), -1.0).normalize());
            let bvh = object.intersect(&ray).map(|h| h.1.t);
            let brute = hi_raytrace::testing::intersect_brute_force(&object, &ray).map(|h| h.1.t);
            prop_assert_eq!(bvh, brute);
        }
    }
}

/// Rays along an axis (direction components exactly 0) and rays that start just in front of a
/// triangle find it: the f32 BVH traversal neither loses axis-aligned rays nor culls what lies
/// within its first 10⁻⁴ of parameter. Expected hits are the algebra of a unit square at z = 0.
#[test]
fn axis_rays_and_near_starts_hit() {
    use hi_raytrace::{MeshObject, Ray};
    let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
    let mesh = TriangleMesh::try_new(
        p,
        vec![DVec3::Z; 4],
        vec![glam::DVec2::ZERO; 4],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .unwrap();
    let square = MeshObject::new(mesh);
    for (x, y) in [(0.5, 0.005), (0.5, 0.5), (0.3, 0.7), (0.999, 0.001)] {
        for height in [1.0, 1e-3, 1e-5, 1e-8] {
            let down = Ray::new(DVec3::new(x, y, height), -DVec3::Z);
            let (_, hit) =
                square.intersect(&down).unwrap_or_else(|| panic!("({x}, {y}, {height})"));
            assert!((hit.t - height).abs() <= 1e-12 * height.max(1.0), "t {} at {height}", hit.t);
            assert!(square.occluded(&down), "({x}, {y}, {height}) not occluded");
        }
    }
    // Along x and y, in the plane of a vertical square.
    let wall = TriangleMesh::try_new(
        vec![DVec3::ZERO, DVec3::Y, DVec3::new(0.0, 1.0, 1.0), DVec3::Z],
        vec![DVec3::X; 4],
        vec![glam::DVec2::ZERO; 4],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .unwrap();
    let wall = MeshObject::new(wall);
    let (_, hit) = wall.intersect(&Ray::new(DVec3::new(-2.0, 0.4, 0.6), DVec3::X)).unwrap();
    assert!((hit.t - 2.0).abs() < 1e-12);
}
