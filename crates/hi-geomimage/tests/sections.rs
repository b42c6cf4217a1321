// SPDX-License-Identifier: MIT
//! Algorithm 1 of §5.3 (surface fitting from cross-sections) on shapes whose answer is known:
//! rings on a sphere and an ellipsoid (the fit, insertion, alignment, interpolation), sections
//! that are not star-shaped (the failure of figure 5.9, measured), scattered points on a sphere
//! (figure 5.8), the errors, and the real scans of the shared data folder when present.

use std::f64::consts::{PI, TAU};
use std::path::PathBuf;

use glam::DVec3;
use hi_geomimage::sections::{
    Alignment, ContourOrder, Problem, SectionOptions, SliceAxis, fit_given_sections, fit_sections,
};
use hi_geomimage::{Error, NonFiniteInput, SectionFit};

/// A deterministic generator in [0, 1) (64-bit LCG, top 53 bits).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 =
            self.0.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// `v` in a random order (Fisher–Yates).
    fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            let j = ((self.next() * (i + 1) as f64) as usize).min(i);
            v.swap(i, j);
        }
    }
}

/// The ring data of an ellipsoid with semi-axes `axes`: `k` rings at the centres of `k` equal
/// slabs of z ∈ [−c, c], ring i with `counts[i]` points equally spaced in the angle φ of
/// (a·s·cos φ, b·s·sin φ, z), s = √(1 − z²/c²), starting at a random phase; shuffled.
fn rings(axes: [f64; 3], counts: &[usize], seed: u64) -> Vec<DVec3> {
    let k = counts.len();
    let mut rng = Lcg(seed);
    let mut points = Vec::new();
    for (i, &n) in counts.iter().enumerate() {
        let z = axes[2] * ((2 * i + 1) as f64 / k as f64 - 1.0);
        let s = (1.0 - (z / axes[2]).powi(2)).sqrt();
        let phase = rng.next();
        for j in 0..n {
            let phi = TAU * (j as f64 + phase) / n as f64;
            points.push(DVec3::new(axes[0] * s * phi.cos(), axes[1] * s * phi.sin(), z));
        }
    }
    rng.shuffle(&mut points);
    points
}

/// Ring sizes that grow with the radius, from 5 near the poles.
fn counts(k: usize, most: usize) -> Vec<usize> {
    (0..k)
        .map(|i| {
            let z = (2 * i + 1) as f64 / k as f64 - 1.0;
            5 + ((most - 5) as f64 * (1.0 - z * z).sqrt()).round() as usize
        })
        .collect()
}

/// The largest | |p| − 1 | over the surface sampled `f` times finer than its grid.
fn off_unit_sphere(fit: &SectionFit, f: usize) -> f64 {
    let s = &fit.surface;
    let samples = s.sample_uniform(f * s.m(), f * s.n(), 0, 0).unwrap().values;
    samples.iter().map(|p| (p.length() - 1.0).abs()).fold(0.0, f64::max)
}

fn slices(k: usize) -> SectionOptions {
    SectionOptions { slices: Some(k), ..SectionOptions::default() }
}

#[test]
fn rings_on_a_sphere_fit_within_half_a_slab() {
    let k = 16;
    let sizes = counts(k, 24);
    let points = rings([1.0; 3], &sizes, 7);
    let fit = fit_sections(&points, &slices(k)).unwrap();
    let r = &fit.report;
    // Sections: one per ring, each with its ring's points, at its height.
    assert_eq!(r.slices.len(), k);
    for (i, s) in r.slices.iter().enumerate() {
        assert_eq!(s.points, sizes[i], "section {i}");
        let z = (2 * i + 1) as f64 / k as f64 - 1.0;
        assert!((s.height - z).abs() < 1e-12, "section {i}: {}", s.height);
        assert_eq!((s.polygon_crossings, s.curve_crossings), (0, 0), "section {i}");
    }
    // Insertion: every contour has N points, N the least even number above the largest ring.
    let largest = *sizes.iter().max().unwrap();
    let n = if largest.is_multiple_of(2) { largest + 2 } else { largest + 1 };
    assert_eq!(r.contour_points, n);
    assert!(fit.rows.iter().all(|row| row.len() == n));
    assert_eq!(r.surface_size, (2 * k, n));
    // A regular polygon's harmonic curve is its circumcircle, so the inserted and turned points
    // stay on the sphere.
    for row in &fit.rows {
        for p in row {
            assert!((p.length() - 1.0).abs() < 1e-12, "{p}");
        }
    }
    // The surface passes through its grid: contour i is row i and, turned by half a period,
    // row 2K − 1 − i.
    for (i, row) in fit.rows.iter().enumerate() {
        for (j, p) in row.iter().enumerate() {
            let here = fit.surface.eval(i as f64 / (2 * k) as f64, j as f64 / n as f64);
            assert!(here.distance(*p) < 1e-12, "({i}, {j})");
            let v = (j + n / 2) as f64 / n as f64;
            let there = fit.surface.eval((2 * k - 1 - i) as f64 / (2 * k) as f64, v);
            assert!(there.distance(*p) < 1e-12, "({i}, {j}) on the other side");
        }
    }
    // The columns are meridians sampled at equally spaced heights, not angles: the surface
    // leaves the sphere by less than half the slab thickness 2/K (about 0.63/K is expected).
    let off = off_unit_sphere(&fit, 4);
    assert!(off < 1.0 / k as f64, "{off}");
    // Every input point lies on the surface (the contours pass through them); the distance is
    // that of the 4× triangulation.
    assert!(r.points_to_surface.as_ref().unwrap().max < 2e-3);
    assert!(r.problems.is_empty(), "{:?}", r.problems);
}

#[test]
fn an_ellipsoid_fits_within_half_a_slab_in_its_own_coordinates() {
    let axes = [1.5, 1.0, 0.7];
    let k = 20;
    let points = rings(axes, &counts(k, 30), 11);
    let fit = fit_sections(&points, &slices(k)).unwrap();
    // p/q lies on the ellipsoid for q = |(x/a, y/b, z/c)|, so |p − p/q| bounds the distance.
    let s = &fit.surface;
    let samples = s.sample_uniform(4 * s.m(), 4 * s.n(), 0, 0).unwrap().values;
    let worst = samples
        .iter()
        .map(|p| {
            let q = (*p / DVec3::from(axes)).length();
            p.length() * (q - 1.0).abs() / q
        })
        .fold(0.0, f64::max);
    // In coordinates scaled to the unit sphere the error is that of the sphere's fit (less
    // than half a slab, 1/K); scaling back multiplies it by at most the largest semi-axis.
    assert!(worst < axes[0] / k as f64, "{worst}");
    assert!(fit.rows.iter().all(|row| row.len() == fit.report.contour_points));
    assert!(fit.report.problems.is_empty(), "{:?}", fit.report.problems);
}

#[test]
fn the_recursive_subdivision_finds_rings_further_apart_than_their_points() {
    // Ten rings of 60 points on an ellipsoid three times as tall as wide: the rings are 0.6
    // apart, and neighbours on a ring, or on two neighbouring rings, are horizontally closer
    // (the radii differ by at most 0.28), so step 3 halves slabs until each holds one ring.
    let sizes = vec![60; 10];
    let points = rings([1.0, 1.0, 3.0], &sizes, 3);
    let fit = fit_sections(&points, &SectionOptions::default()).unwrap();
    assert_eq!(fit.report.slices.len(), 10);
    for (i, s) in fit.report.slices.iter().enumerate() {
        assert_eq!(s.points, 60, "section {i}");
        assert!((s.height - 3.0 * ((2 * i + 1) as f64 / 10.0 - 1.0)).abs() < 1e-12);
    }
    // On the unit sphere the two rings nearest each pole are closer in height (0.2) than in
    // radius (0.28): by the thesis's criterion they make one section.
    let sphere = fit_sections(&rings([1.0; 3], &sizes, 3), &SectionOptions::default()).unwrap();
    let per_section: Vec<usize> = sphere.report.slices.iter().map(|s| s.points).collect();
    assert_eq!(per_section, [120, 60, 60, 60, 60, 60, 60, 120]);
}

#[test]
fn rotation_alignment_reaches_the_least_total_deviation() {
    let k = 12;
    let sizes = counts(k, 20);
    let points = rings([1.0; 3], &sizes, 5);
    let run =
        |alignment| fit_sections(&points, &SectionOptions { alignment, ..slices(k) }).unwrap();
    let (none, steps, best) =
        (run(Alignment::None), run(Alignment::Steps), run(Alignment::Continuous));
    // The deviation measured on the rows, not taken from the report.
    let total = |fit: &SectionFit| -> f64 {
        fit.rows
            .windows(2)
            .map(|w| w[0].iter().zip(&w[1]).map(|(a, b)| a.distance_squared(*b)).sum::<f64>())
            .sum()
    };
    // Circles of radii r, r′ at heights z, z′, turned to the same phase: N·((r − r′)² + (z − z′)²)
    // each, the least possible.
    let n = best.report.contour_points as f64;
    let radius = |i: usize| (1.0 - ((2 * i + 1) as f64 / k as f64 - 1.0).powi(2)).sqrt();
    let least: f64 =
        (1..k).map(|i| n * ((radius(i) - radius(i - 1)).powi(2) + (2.0 / k as f64).powi(2))).sum();
    assert!((total(&best) - least).abs() < 1e-9 * least, "{} vs {least}", total(&best));
    assert!(total(&steps) < total(&none), "{} vs {}", total(&steps), total(&none));
    assert!(total(&best) <= total(&steps) + 1e-12);
    // The angular order starts every contour within a step of its ring at −180°, so even
    // unaligned contours are less than a step apart; alignment still takes off over 10%.
    assert!(total(&none) > 1.1 * least, "{} vs {least}", total(&none));
    assert!((best.report.deviation - total(&best)).abs() < 1e-9 * least);
    assert!((best.report.deviation_unaligned - total(&none)).abs() < 1e-9 * total(&none));
}

/// `n` points spread evenly by arc length round a C-shaped section: an annular sector of radii
/// 0.6 and 1 over ±135°, closed by half circles, scaled by `s`, at height `z`. Its centroid
/// lies in the hole, so rays from it cross the contour more than once.
fn c_section(n: usize, s: f64, z: f64) -> Vec<DVec3> {
    let alpha = 0.75 * PI;
    let at = |r: f64, a: f64| DVec3::new(r * a.cos(), r * a.sin(), 0.0);
    // A fine polyline round the boundary, counter-clockwise.
    let mut path = Vec::new();
    let fine = 2000;
    for i in 0..fine {
        path.push(at(1.0, -alpha + 2.0 * alpha * i as f64 / fine as f64));
    }
    for i in 0..fine / 4 {
        let b = PI * i as f64 / (fine / 4) as f64;
        path.push(
            at(0.8, alpha) + 0.2 * (at(1.0, alpha) * b.cos() + at(1.0, alpha + 0.5 * PI) * b.sin()),
        );
    }
    for i in 0..fine {
        path.push(at(0.6, alpha - 2.0 * alpha * i as f64 / fine as f64));
    }
    for i in 0..fine / 4 {
        let b = PI * i as f64 / (fine / 4) as f64;
        path.push(
            at(0.8, -alpha)
                + 0.2 * (-at(1.0, -alpha) * b.cos() - at(1.0, -alpha + 0.5 * PI) * b.sin()),
        );
    }
    let m = path.len();
    let mut lengths = vec![0.0];
    for i in 0..m {
        let l = lengths[i] + path[i].distance(path[(i + 1) % m]);
        lengths.push(l);
    }
    let total = lengths[m];
    let mut out = Vec::with_capacity(n);
    let mut seg = 0;
    for j in 0..n {
        let target = total * j as f64 / n as f64;
        while lengths[seg + 1] < target {
            seg += 1;
        }
        let t = (target - lengths[seg]) / (lengths[seg + 1] - lengths[seg]);
        let p = path[seg].lerp(path[(seg + 1) % m], t);
        out.push(DVec3::new(s * p.x, s * p.y, z));
    }
    out
}

/// A solid whose sections are the C of [`c_section`], shrinking towards its ends.
fn c_solid(k: usize, per_section: usize) -> Vec<DVec3> {
    let mut points = Vec::new();
    for i in 0..k {
        let z = (2 * i + 1) as f64 / k as f64 - 1.0;
        let s = (1.0 - 0.8 * z * z).sqrt();
        points.extend(c_section(per_section, s, z));
    }
    Lcg(9).shuffle(&mut points);
    points
}

#[test]
fn a_section_that_is_not_star_shaped_scrambles_the_angular_order() {
    let k = 8;
    let points = c_solid(k, 80);
    let fit = fit_sections(&points, &slices(k)).unwrap();
    let r = &fit.report;
    // Every section is a C whose centroid is in its hole: the polar angle scrambles them all,
    // into a simple polygon that zigzags between the arcs.
    for (i, s) in r.slices.iter().enumerate() {
        assert_eq!(s.polygon_crossings, 0, "section {i}");
        assert!(s.misordered > 0.5, "section {i}: {}", s.misordered);
        assert!(
            r.problems
                .iter()
                .any(|p| matches!(p, Problem::ScrambledContour { slice, .. } if *slice == i)),
            "section {i}: {:?}",
            r.problems
        );
    }
    // Nearest neighbours follow the C (its points are 0.05 apart, its mouth 0.4 wide).
    let nn = fit_sections(
        &points,
        &SectionOptions { order: ContourOrder::NearestNeighbour, ..slices(k) },
    )
    .unwrap();
    for (i, s) in nn.report.slices.iter().enumerate() {
        assert_eq!((s.polygon_crossings, s.misordered), (0, 0.0), "section {i}");
    }
    assert!(!nn.report.problems.iter().any(|p| matches!(p, Problem::ScrambledContour { .. })));
    // The scrambled contours loop; those in order do not, and the surface keeps closer to the
    // points.
    for (i, (a, b)) in r.slices.iter().zip(&nn.report.slices).enumerate() {
        assert!(
            a.curve_crossings > 0 && a.overshoot > 0.2,
            "section {i}: {} {}",
            a.curve_crossings,
            a.overshoot
        );
        assert!(
            b.curve_crossings == 0 && b.overshoot < 0.1,
            "section {i}: {} {}",
            b.curve_crossings,
            b.overshoot
        );
    }
    let strays = |f: &SectionFit| f.report.surface_to_points.as_ref().unwrap().max;
    assert!(strays(&fit) > strays(&nn), "{} vs {}", strays(&fit), strays(&nn));
}

/// `n` uniformly random points on the unit sphere (Archimedes: z uniform in [−1, 1]).
fn random_sphere(n: usize, seed: u64) -> Vec<DVec3> {
    let mut rng = Lcg(seed);
    (0..n)
        .map(|_| {
            let z = 2.0 * rng.next() - 1.0;
            let a = TAU * rng.next();
            let s = (1.0 - z * z).sqrt();
            DVec3::new(s * a.cos(), s * a.sin(), z)
        })
        .collect()
}

#[test]
fn scattered_points_on_a_sphere_are_fitted_badly() {
    // Uniformly random points: each thin section has few points at uneven angles, and the
    // curves through them overshoot and loop (figure 5.8).
    let points = random_sphere(400, 2005);
    let fit = fit_sections(&points, &slices(16)).unwrap();
    let r = &fit.report;
    assert!(!r.problems.is_empty());
    assert!(
        r.problems
            .iter()
            .any(|p| matches!(p, Problem::LoopingContour { .. } | Problem::Overshoot { .. })),
        "{:?}",
        r.problems
    );
    assert!(off_unit_sphere(&fit, 4) > 0.25);
}

#[test]
fn bad_input_is_an_error_naming_the_problem() {
    let good = rings([1.0; 3], &[8; 6], 1);
    let err = |points: &[DVec3], options: SectionOptions| match fit_sections(points, &options) {
        Ok(_) => panic!("expected an error"),
        Err(e) => e,
    };
    assert!(matches!(err(&[], slices(4)), Error::TooFewPoints { found: 0, .. }));
    assert!(matches!(err(&good[..5], slices(2)), Error::TooFewPoints { found: 5, needed: 6 }));
    let mut nan = good.clone();
    nan[3].y = f64::NAN;
    assert_eq!(err(&nan, slices(6)).to_string(), "point 3 has a NaN or infinite coordinate");
    let mut inf = good.clone();
    inf[40].x = f64::INFINITY;
    assert!(matches!(err(&inf, slices(6)), Error::NonFinite { what: NonFiniteInput::Point(40) }));
    for k in [0, 1, (1 << 16) + 1] {
        assert!(
            matches!(err(&good, slices(k)), Error::InvalidOption { name: "slices", .. }),
            "{k}"
        );
    }
    // Flat along the axis: no sections to cut.
    let flat: Vec<DVec3> = good.iter().map(|p| DVec3::new(p.x, p.y, 0.0)).collect();
    assert!(matches!(err(&flat, slices(4)), Error::Degenerate { .. }));
    // Twelve slabs over six rings: every other slab is empty.
    let e = err(&good, slices(12));
    assert!(
        matches!(e, Error::SparseSlice { slice: 1, n_slices: 12, found: 0, needed: 3, .. }),
        "{e}"
    );
    assert!(e.to_string().starts_with("section 1 of 12"), "{e}");
    // Two points alone above a sphere: twelve slabs of [−1, 1.2] leave them alone in the top
    // one, [1.0167, 1.2].
    let mut lonely = random_sphere(400, 8);
    lonely.extend([DVec3::new(0.1, 0.0, 1.2), DVec3::new(-0.1, 0.0, 1.2)]);
    let e = err(&lonely, slices(12));
    assert!(matches!(e, Error::SparseSlice { slice: 11, n_slices: 12, found: 2, .. }), "{e}");
    assert!(e.to_string().contains("has 2 points, at least 3 needed"), "{e}");
}

#[test]
fn the_principal_axis_and_the_named_axes_agree_on_an_elongated_shape() {
    // The ellipsoid lies along x; its rings are cut across x when the data are turned.
    let points: Vec<DVec3> = rings([0.7, 1.0, 1.5], &counts(10, 20), 4)
        .into_iter()
        .map(|p| DVec3::new(p.z, p.y, p.x))
        .collect();
    let by_x = fit_sections(&points, &SectionOptions { axis: SliceAxis::X, ..slices(10) }).unwrap();
    let principal =
        fit_sections(&points, &SectionOptions { axis: SliceAxis::Principal, ..slices(10) })
            .unwrap();
    assert!((principal.report.axis - DVec3::X).length() < 1e-9, "{}", principal.report.axis);
    for (a, b) in by_x.report.slices.iter().zip(&principal.report.slices) {
        assert_eq!(a.points, b.points);
    }
}

#[test]
fn given_sections_of_equally_spaced_spherical_coordinates_fit_with_some_oscillation() {
    // Eq. 4.1 sampled at polar angles iπ/M (the poles are rows of N equal points), given as
    // cross-sections (figure 5.7).
    let (m, n) = (12, 24);
    let sections: Vec<Vec<DVec3>> = (0..=m)
        .map(|i| {
            let u = PI * i as f64 / m as f64;
            (0..n)
                .map(|j| {
                    let v = TAU * (j as f64 + 0.5 * i as f64) / n as f64;
                    DVec3::new(u.sin() * v.cos(), u.sin() * v.sin(), -u.cos())
                })
                .collect()
        })
        .collect();
    let fit = fit_given_sections(&sections, &SectionOptions::default()).unwrap();
    assert_eq!(fit.report.surface_size, (2 * (m + 1), n + 2));
    // Every row of points is a pole or a regular polygon on a circle of the sphere, so the grid
    // lies on it; between the rows the surface wobbles (each pole is met twice in a row by the
    // reversed traversal), by less than the sagitta of an arc π/M between sections.
    assert!(fit.surface.points().iter().all(|p| (p.length() - 1.0).abs() < 1e-12));
    let off = off_unit_sphere(&fit, 4);
    let sagitta = 1.0 - (PI / (2 * m) as f64).cos();
    assert!(off > 1e-4 && off < sagitta, "{off} vs {sagitta}");
    assert!(fit.report.problems.is_empty(), "{:?}", fit.report.problems);
    // The poles are contours of radius 0: nothing to overshoot.
    assert_eq!(fit.report.slices[0].overshoot, 0.0);
    // Errors name the section.
    let mut bad = sections.clone();
    bad[2][5] = DVec3::NAN;
    let e = fit_given_sections(&bad, &SectionOptions::default()).map(|_| ()).unwrap_err();
    assert_eq!(e.to_string(), "section 2, point 5 has a NaN or infinite coordinate");
    let mut short = sections.clone();
    short[4].truncate(2);
    let e = fit_given_sections(&short, &SectionOptions::default()).map(|_| ()).unwrap_err();
    assert!(matches!(e, Error::SparseSlice { slice: 4, n_slices: 13, found: 2, .. }), "{e}");
    let e = fit_given_sections(&sections[..1], &SectionOptions::default()).map(|_| ()).unwrap_err();
    assert!(matches!(e, Error::InvalidOption { name: "sections", .. }), "{e}");
}

/// A model of the shared folder beside the repository, where it is (see `hi_testkit`).
fn model(file: &str) -> Option<PathBuf> {
    hi_testkit::shared_model(file)
}

#[test]
fn real_scans_run_and_report() {
    let Some(path) = model("bunny.obj") else { return };
    let scan = hi_scan::scan::read_scan(&path).unwrap();
    // The bunny stands along y; its ears make the upper sections two curves each.
    let options = SectionOptions { axis: SliceAxis::Y, error_oversample: 2, ..slices(24) };
    let fit = fit_sections(&scan.points, &options).unwrap();
    let r = &fit.report;
    eprintln!(
        "bunny: {} sections, N = {}, problems: {}",
        r.slices.len(),
        r.contour_points,
        r.problems.len()
    );
    for p in &r.problems {
        eprintln!("  {p}");
    }
    assert_eq!(r.slices.iter().map(|s| s.points).sum::<usize>(), scan.points.len());
    assert!(r.problems.iter().any(|p| matches!(p, Problem::ScrambledContour { .. })));
}
