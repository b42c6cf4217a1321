// SPDX-License-Identifier: MIT
//! Rendering (Hardy 2005, §5.5, §5.6): determinism, image size, PNG output, shadows without
//! self-shadowing, and an error for each kind of bad input.

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_mesh::ColorMap;
use hi_raytrace::{
    BezierObject, BezierOptions, Camera, Error, Geometry, HarmonicObject, HarmonicOptions,
    IntervalMethod, Light, MeshObject, RenderOptions, Scene, SceneObject, SurfaceColor, render,
};
use hi_surface::{CurvatureQuantity, MeshOptions, sphere, torus};

fn small(width: u32, height: u32, spp: u32) -> RenderOptions {
    RenderOptions { width, height, samples_per_pixel: spp, tile_size: 8, first_pass: 0 }
}

fn sun(direction: DVec3) -> Light {
    Light::Directional { direction, intensity: [1.0, 1.0, 1.0] }
}

fn harmonic(surface: hi_surface::HarmonicSurface<DVec3>, method: IntervalMethod) -> Geometry {
    let settings = HarmonicOptions { method, ..HarmonicOptions::default() };
    Geometry::Harmonic(HarmonicObject::try_new(surface, &settings).unwrap())
}

#[test]
fn renders_are_deterministic_and_decode_as_png() {
    let torus_mesh = torus(2.0, 0.6)
        .to_mesh(&MeshOptions { n_u: 16, n_v: 32, ..MeshOptions::default() })
        .unwrap();
    let objects = vec![
        SceneObject::new(harmonic(sphere(0.8), IntervalMethod::Krawczyk)),
        SceneObject::new(Geometry::Mesh(MeshObject::new(torus_mesh))),
    ];
    let lights = vec![
        sun(DVec3::new(1.0, -1.0, 2.0)),
        Light::Point { position: DVec3::new(-3.0, -3.0, 4.0), intensity: [8.0, 8.0, 8.0] },
    ];
    let scene = Scene::try_new(objects, lights, [0.02, 0.03, 0.05]).unwrap();
    let camera = Camera::try_new(DVec3::new(0.0, -6.0, 4.0), DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    let settings = small(30, 20, 4);
    let a = render(&scene, &camera, &settings, None).unwrap();
    let b = render(&scene, &camera, &settings, None).unwrap();
    let (pa, pb) = (a.png_bytes().unwrap(), b.png_bytes().unwrap());
    assert_eq!(pa, pb, "same bytes twice");
    assert_eq!(a.counts, b.counts, "same rays twice");
    assert_eq!(a.counts.camera, 30 * 20 * 4, "spp rays per pixel");
    let decoded = image::load_from_memory(&pa).expect("a PNG").to_rgb8();
    assert_eq!(decoded.dimensions(), (30, 20), "image size");
    let rendered: Vec<[u8; 3]> = decoded.pixels().map(|p| p.0).collect();
    assert_eq!(rendered, a.pixels, "decodes to the rendered pixels");
    // Corners see the background, converted to sRGB.
    let bg = [0.02f32, 0.03, 0.05].map(|c| (hi_mesh::linear_to_srgb(c) * 255.0).round() as u8);
    assert_eq!(a.pixel(0, 0), Some(bg), "background in sRGB");
    assert_eq!(a.pixel(30, 0), None, "outside the image");
    assert!(a.counts.hits > 100, "objects in view");
}

#[test]
fn progress_reports_every_tile() {
    let scene = Scene::try_new(
        vec![SceneObject::new(harmonic(sphere(1.0), IntervalMethod::Krawczyk))],
        vec![sun(DVec3::Z)],
        [0.0; 3],
    )
    .unwrap();
    let camera =
        Camera::framing(DVec3::ZERO, 1.0, DVec3::new(0.0, -1.0, 0.3), DVec3::Z, 0.7).unwrap();
    let calls = std::sync::atomic::AtomicUsize::new(0);
    let last = std::sync::Mutex::new((0, 0));
    let report = |done: usize, total: usize| {
        calls.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let mut l = last.lock().unwrap();
        if done > l.0 {
            *l = (done, total);
        }
    };
    render(&scene, &camera, &small(20, 12, 1), Some(&report)).unwrap();
    let tiles = 3 * 2;
    assert_eq!(calls.into_inner(), tiles, "one call per tile");
    assert_eq!(last.into_inner().unwrap(), (tiles, tiles), "ends at the total");
}

/// Renders `geometry` lit by a sun along `light` and checks that no hit facing the light is
/// shadowed (the surface never shadows itself there).
fn no_self_shadow(geometry: Geometry, light: DVec3, eye: DVec3) {
    let scene =
        Scene::try_new(vec![SceneObject::new(geometry)], vec![sun(light)], [0.0; 3]).unwrap();
    let camera = Camera::try_new(eye, DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    let out = render(&scene, &camera, &small(40, 40, 1), None).unwrap();
    assert!(out.counts.hits > 300, "in view: {}", out.counts.hits);
    assert!(out.counts.shadow > 100, "shadow rays cast: {}", out.counts.shadow);
    assert_eq!(out.counts.shadowed, 0, "lit pixels shadowed by their own surface");
}

#[test]
fn a_lit_sphere_does_not_shadow_itself() {
    let light = DVec3::new(0.3, -0.5, 1.0);
    let eye = DVec3::new(1.0, -3.5, 2.0);
    no_self_shadow(harmonic(sphere(1.0), IntervalMethod::Krawczyk), light, eye);
    no_self_shadow(harmonic(sphere(1.0), IntervalMethod::Bisection), light, eye);
    let patches = sphere(1.0)
        .to_bezier(
            BezierScheme::Hermite(HermiteDegree::Cubic),
            hi_curve::bezier::Tolerance::Absolute(1e-4),
        )
        .unwrap();
    let bez = BezierObject::try_from_surface(&patches, &BezierOptions::default()).unwrap();
    no_self_shadow(Geometry::Bezier(bez), light, eye);
}

#[test]
fn the_outer_side_of_a_torus_lit_from_above_is_not_shadowed() {
    // Light along +z: a point on the upper half of the tube sees the light unobstructed.
    let eye = DVec3::new(0.0, -6.0, 5.0);
    no_self_shadow(harmonic(torus(2.0, 0.8), IntervalMethod::Krawczyk), DVec3::Z, eye);
    no_self_shadow(harmonic(torus(2.0, 0.8), IntervalMethod::Bisection), DVec3::Z, eye);
}

#[test]
fn shadows_fall_where_they_should() {
    // A small sphere above a large one, the sun overhead: the top of the large sphere is in
    // shadow.
    let small_sphere = hi_surface::HarmonicSurface::new(
        sphere(0.3)
            .rows()
            .into_iter()
            .map(|r| r.into_iter().map(|p| p + DVec3::new(0.0, 0.0, 2.0)).collect())
            .collect(),
    );
    let objects = vec![
        SceneObject::new(harmonic(sphere(1.0), IntervalMethod::Krawczyk)),
        SceneObject::new(harmonic(small_sphere, IntervalMethod::Krawczyk)),
    ];
    let scene = Scene::try_new(objects, vec![sun(DVec3::Z)], [0.0; 3]).unwrap();
    let camera =
        Camera::try_new(DVec3::new(0.0, -4.0, 4.0), DVec3::new(0.0, 0.0, 0.5), DVec3::Z, 0.9)
            .unwrap();
    let out = render(&scene, &camera, &small(40, 40, 1), None).unwrap();
    assert!(out.counts.shadowed > 0, "the small sphere shadows the large one");
}

/// A fill light lights as a directional one does and casts no shadow: alone with a convex
/// sphere (which shadows nothing) the two give the same image; with a second sphere above it
/// the directional light's shadow is there and the fill light's is not.
#[test]
fn a_fill_light_lights_without_shadows() {
    let above = hi_surface::HarmonicSurface::new(
        sphere(0.3)
            .rows()
            .into_iter()
            .map(|r| r.into_iter().map(|p| p + DVec3::new(0.0, 0.0, 2.0)).collect())
            .collect(),
    );
    let camera =
        Camera::try_new(DVec3::new(0.0, -4.0, 4.0), DVec3::new(0.0, 0.0, 0.5), DVec3::Z, 0.9)
            .unwrap();
    let draw = |objects: Vec<SceneObject>, light: Light| {
        let scene = Scene::try_new(objects, vec![light], [0.0; 3]).unwrap();
        render(&scene, &camera, &small(40, 40, 1), None).unwrap()
    };
    let large = || SceneObject::new(harmonic(sphere(1.0), IntervalMethod::Krawczyk));
    let fill = Light::Fill { direction: DVec3::Z, intensity: [1.0; 3] };
    let alone_sun = draw(vec![large()], sun(DVec3::Z));
    let alone_fill = draw(vec![large()], fill);
    assert_eq!(alone_sun.pixels, alone_fill.pixels, "the same light where nothing is shadowed");
    assert_eq!(alone_fill.counts.shadow, 0, "a fill light casts no shadow rays");
    let pair =
        || vec![large(), SceneObject::new(harmonic(above.clone(), IntervalMethod::Krawczyk))];
    let (with_sun, with_fill) = (draw(pair(), sun(DVec3::Z)), draw(pair(), fill));
    assert!(with_sun.counts.shadowed > 0, "the small sphere shadows the large one");
    assert_eq!(with_fill.counts.shadowed, 0);
    let brightness = |r: &hi_raytrace::Rendering| -> u64 {
        r.pixels.iter().flatten().map(|&c| u64::from(c)).sum()
    };
    assert!(brightness(&with_fill) > brightness(&with_sun), "the shadow is lit");
}

#[test]
fn curvature_colours_differ_across_the_torus() {
    let object = HarmonicObject::try_new(torus(2.0, 1.0), &HarmonicOptions::default())
        .unwrap()
        .with_color(SurfaceColor::Curvature {
            quantity: CurvatureQuantity::Gaussian,
            map: ColorMap::default(),
        })
        .unwrap();
    let legend = *object.legend().expect("a legend");
    // K ranges over ±1/(r(R ∓ r)) = [−1, 1/3] on the torus.
    assert!(
        (legend.data_min + 1.0).abs() < 0.05 && (legend.data_max - 1.0 / 3.0).abs() < 0.05,
        "{legend:?}"
    );
    let scene = Scene::try_new(
        vec![SceneObject::new(Geometry::Harmonic(object))],
        vec![sun(DVec3::new(0.0, -1.0, 2.0))],
        [0.0; 3],
    )
    .unwrap();
    let camera = Camera::try_new(DVec3::new(0.0, -6.0, 6.0), DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    let out = render(&scene, &camera, &small(32, 32, 1), None).unwrap();
    let mut colours: Vec<[u8; 3]> = out.pixels.clone();
    colours.sort_unstable();
    colours.dedup();
    assert!(colours.len() > 50, "a range of colours: {}", colours.len());
}

#[test]
fn bad_input_is_an_error() {
    let scene = Scene::try_new(
        vec![SceneObject::new(harmonic(sphere(1.0), IntervalMethod::Krawczyk))],
        vec![],
        [0.0; 3],
    )
    .unwrap();
    let camera = Camera::try_new(DVec3::new(0.0, 0.0, 4.0), DVec3::ZERO, DVec3::Y, 0.8).unwrap();
    // Image size and sampling.
    assert!(matches!(
        render(&scene, &camera, &small(0, 10, 1), None),
        Err(Error::ZeroSizeImage { .. })
    ));
    assert!(matches!(
        render(&scene, &camera, &small(10, 0, 1), None),
        Err(Error::ZeroSizeImage { .. })
    ));
    assert!(matches!(
        render(&scene, &camera, &small(10, 10, 0), None),
        Err(Error::InvalidValue { .. })
    ));
    // Degenerate cameras.
    let eye = DVec3::new(0.0, 0.0, 4.0);
    let degenerate = |e: Result<Camera, Error>| matches!(e, Err(Error::DegenerateCamera { .. }));
    assert!(degenerate(Camera::try_new(eye, eye, DVec3::Y, 0.8)), "eye = target");
    assert!(degenerate(Camera::try_new(eye, DVec3::ZERO, DVec3::Z, 0.8)), "up along the view");
    assert!(degenerate(Camera::try_new(eye, DVec3::ZERO, DVec3::ZERO, 0.8)), "zero up");
    assert!(degenerate(Camera::try_new(eye, DVec3::ZERO, DVec3::Y, 0.0)), "fov 0");
    assert!(degenerate(Camera::try_new(eye, DVec3::ZERO, DVec3::Y, std::f64::consts::PI)), "fov π");
    // NaN anywhere.
    let nan = DVec3::new(f64::NAN, 0.0, 0.0);
    let non_finite = |e: Result<Camera, Error>| matches!(e, Err(Error::NonFinite { .. }));
    assert!(non_finite(Camera::try_new(nan, DVec3::ZERO, DVec3::Y, 0.8)), "NaN eye");
    assert!(non_finite(Camera::try_new(eye, nan, DVec3::Y, 0.8)), "NaN target");
    assert!(non_finite(Camera::try_new(eye, DVec3::ZERO, DVec3::Y, f64::NAN)), "NaN fov");
    let object = || SceneObject::new(harmonic(sphere(1.0), IntervalMethod::Krawczyk));
    assert!(matches!(
        Scene::try_new(
            vec![object()],
            vec![Light::Point { position: nan, intensity: [1.0; 3] }],
            [0.0; 3]
        ),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        Scene::try_new(vec![object()], vec![sun(DVec3::ZERO)], [0.0; 3]),
        Err(Error::InvalidValue { .. })
    ));
    assert!(matches!(
        Scene::try_new(vec![object()], vec![], [f32::NAN, 0.0, 0.0]),
        Err(Error::NonFinite { .. })
    ));
    let mut bad_material = object();
    bad_material.material.diffuse = f32::NAN;
    assert!(matches!(
        Scene::try_new(vec![bad_material], vec![], [0.0; 3]),
        Err(Error::NonFinite { .. })
    ));
    // An empty scene.
    assert_eq!(Scene::try_new(vec![], vec![], [0.0; 3]).unwrap_err(), Error::EmptyScene);
    assert!(matches!(
        BezierObject::try_new(vec![], &BezierOptions::default()),
        Err(Error::EmptyScene)
    ));
    // Bad settings.
    let bad = HarmonicOptions { distance_tolerance: f64::NAN, ..HarmonicOptions::default() };
    assert!(HarmonicObject::try_new(sphere(1.0), &bad).is_err(), "NaN tolerance");
    let bad = HarmonicOptions { cells: (0, 4), ..HarmonicOptions::default() };
    assert!(HarmonicObject::try_new(sphere(1.0), &bad).is_err(), "no cells");
    // Messages are one line.
    for e in [Error::EmptyScene, Error::ZeroSizeImage { width: 0, height: 3 }] {
        assert!(!e.to_string().contains('\n'), "{e}");
    }
}

/// Where a point falls in the image of `cam` (aspect `aspect`), in units of the half-width and
/// half-height: inside the frame when both are in [−1, 1].
fn image_position(cam: &Camera, p: DVec3, aspect: f64) -> (f64, f64) {
    let v = p - cam.eye();
    let depth = v.dot(cam.forward());
    let t = (0.5 * cam.fov_y()).tan();
    (v.dot(cam.right()) / (depth * t * aspect), v.dot(cam.up()) / (depth * t))
}

#[test]
fn fitting_frames_what_the_points_cover() {
    // A long thin rod along x and a flat disc, seen from a slanted direction.
    let rod: Vec<DVec3> =
        (0..=40).map(|k| DVec3::new(f64::from(k) * 0.25 - 3.0, 0.1, 0.05)).collect();
    let disc: Vec<DVec3> = (0..64)
        .map(|k| {
            let a = f64::from(k) * std::f64::consts::TAU / 64.0;
            DVec3::new(5.0 + a.cos(), 2.0 + a.sin(), -1.0)
        })
        .collect();
    for points in [rod, disc] {
        for from in [DVec3::new(0.9, -2.0, 1.3), DVec3::new(-1.0, 0.2, 0.4)] {
            let aspect = 4.0 / 3.0;
            let cam = Camera::fitting(&points, from, DVec3::Z, 0.6, aspect, 0.8).unwrap();
            let pos: Vec<(f64, f64)> =
                points.iter().map(|p| image_position(&cam, *p, aspect)).collect();
            let widest = pos.iter().map(|(x, y)| x.abs().max(y.abs())).fold(0.0, f64::max);
            // Every point inside 80 % of the frame, and the frame as tight as that allows.
            assert!((widest - 0.8).abs() < 1e-9, "{widest}");
            // Centred: the extent is symmetric about the middle.
            let (x0, x1) = pos
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
            let (y0, y1) = pos
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
            assert!((x0 + x1).abs() < 1e-4 && (y0 + y1).abs() < 1e-4, "{x0} {x1} {y0} {y1}");
            // Seen from `from`.
            assert!(cam.forward().dot(from.normalize()) < -0.999_999);
        }
    }
}

#[test]
fn fitting_names_bad_input() {
    let p = [DVec3::ZERO, DVec3::X];
    let err = |r: Result<Camera, Error>| r.unwrap_err().to_string();
    assert!(
        err(Camera::fitting(&[], DVec3::Y, DVec3::Z, 0.6, 1.0, 0.8)).contains("points to frame")
    );
    assert!(err(Camera::fitting(&p, DVec3::Y, DVec3::Z, 0.6, 1.0, 0.0)).contains("fill"));
    assert!(err(Camera::fitting(&p, DVec3::Y, DVec3::Z, 0.6, 0.0, 0.8)).contains("aspect"));
    let nan = [DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 0.0)];
    assert!(
        err(Camera::fitting(&nan, DVec3::Y, DVec3::Z, 0.6, 1.0, 0.8)).contains("point to frame")
    );
}

#[test]
fn a_first_pass_renders_edges_in_full_and_the_rest_from_its_samples() {
    let torus_mesh = torus(2.0, 0.6)
        .to_mesh(&MeshOptions { n_u: 24, n_v: 48, ..MeshOptions::default() })
        .unwrap();
    let scene = Scene::try_new(
        vec![SceneObject::new(Geometry::Mesh(MeshObject::new(torus_mesh)))],
        vec![sun(DVec3::new(1.0, -1.0, 2.0))],
        [1.0; 3],
    )
    .unwrap();
    let camera = Camera::try_new(DVec3::new(0.0, -6.0, 4.0), DVec3::ZERO, DVec3::Z, 0.8).unwrap();
    let full = render(&scene, &camera, &small(48, 32, 16), None).unwrap();
    let adaptive =
        render(&scene, &camera, &RenderOptions { first_pass: 4, ..small(48, 32, 16) }, None)
            .unwrap();
    // Fewer rays: 4 for every pixel of each 8 × 8 tile and of the one-pixel border around it
    // (inside the image), and the other 12 of the 16 for each pixel on an edge (its first 4
    // are kept).
    let pixels = 48 * 32;
    let border = |n: usize, size: usize| {
        (0..n).map(move |t| (8 * t + 9).min(size) - (8 * t).saturating_sub(1))
    };
    let first: usize = border(6, 48).map(|a| border(4, 32).map(|b| a * b).sum::<usize>()).sum();
    let again = (adaptive.counts.camera - 4 * first) / 12;
    assert_eq!(adaptive.counts.camera, 4 * first + 12 * again, "4, or 4 + 12, per pixel");
    assert!(again > 0 && again < pixels / 2, "{again} of {pixels} pixels taken again");
    assert!(adaptive.counts.camera < full.counts.camera, "{:?}", adaptive.counts);
    // The background and the torus's outline: both renders agree exactly where the first pass
    // took every sample; elsewhere they differ by little (a smooth pixel's 4 samples lie
    // within ADAPTIVE_SPREAD of each other).
    let (mut same, mut worst) = (0, 0u8);
    for (a, b) in full.pixels.iter().zip(&adaptive.pixels) {
        let d = (0..3).map(|k| a[k].abs_diff(b[k])).max().unwrap_or(0);
        same += usize::from(d == 0);
        worst = worst.max(d);
    }
    assert!(same >= again, "{same} identical pixels");
    assert!(worst <= 8, "largest difference {worst} of 255");
    // Corner pixels see only the background: the same from 4 samples as from 16.
    assert_eq!(full.pixel(0, 0), adaptive.pixel(0, 0));
}

/// A writer that refuses every byte.
struct Refusing;

impl std::io::Write for Refusing {
    fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
        Err(std::io::ErrorKind::PermissionDenied.into())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[test]
fn images_that_cannot_be_written_say_why() {
    let image = hi_raytrace::Rendering {
        width: 2,
        height: 2,
        pixels: vec![[255, 0, 0]; 3],
        counts: hi_raytrace::RayCounts::default(),
        elapsed: std::time::Duration::ZERO,
    };
    let error = image.png_bytes().expect_err("3 pixels for a 2×2 image");
    assert_eq!(error, Error::PixelCount { width: 2, height: 2, pixels: 3 });
    assert_eq!(error.to_string(), "the image has 3 pixels, not the 2x2 its size needs");
    let whole = hi_raytrace::Rendering { pixels: vec![[255, 0, 0]; 4], ..image };
    let error = whole.write_png(Refusing).expect_err("the writer refuses");
    assert_eq!(error, Error::WriteImage { kind: std::io::ErrorKind::PermissionDenied });
    assert_eq!(error.to_string(), "cannot write the image: permission denied");
}
