// SPDX-License-Identifier: MIT
//! Rendering (Hardy 2005, §5.5, §5.6): determinism, image size, PNG output, shadows without
//! self-shadowing, and an error for each kind of bad input.

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_raytrace::{
    BezierObject, BezierSettings, Camera, Error, Geometry, HarmonicObject, HarmonicSettings,
    IntervalMethod, Light, MeshObject, RenderSettings, Scene, SceneObject, SurfaceColor, render,
};
use hi_surface::{ColorMap, CurvatureQuantity, MeshOptions, TriangleMesh, sphere, torus};

fn small(width: u32, height: u32, spp: u32) -> RenderSettings {
    RenderSettings { width, height, samples_per_pixel: spp, tile_size: 8 }
}

fn sun(direction: DVec3) -> Light {
    Light::Directional { direction, intensity: [1.0, 1.0, 1.0] }
}

fn harmonic(surface: hi_surface::HarmonicSurface<DVec3>, method: IntervalMethod) -> Geometry {
    let settings = HarmonicSettings { method, ..HarmonicSettings::default() };
    Geometry::Harmonic(HarmonicObject::try_new(surface, &settings).unwrap())
}

#[test]
fn renders_are_deterministic_and_decode_as_png() {
    let torus_mesh = TriangleMesh::try_from_surface(
        &torus(2.0, 0.6),
        &MeshOptions { n_u: 16, n_v: 32, ..MeshOptions::default() },
    )
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
    assert_eq!(decoded, a.image, "decodes to the rendered pixels");
    // Corners see the background, converted to sRGB.
    let bg = [0.02f32, 0.03, 0.05].map(|c| (hi_surface::linear_to_srgb(c) * 255.0).round() as u8);
    assert_eq!(a.image.get_pixel(0, 0).0, bg, "background in sRGB");
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
    let patches =
        sphere(1.0).to_bezier(BezierScheme::Hermite(HermiteDegree::Cubic), Some(1e-4)).unwrap();
    let bez = BezierObject::from_surface(&patches, &BezierSettings::default()).unwrap();
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

#[test]
fn curvature_colours_differ_across_the_torus() {
    let object = HarmonicObject::try_new(torus(2.0, 1.0), &HarmonicSettings::default())
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
    let mut colours: Vec<[u8; 3]> = out.image.pixels().map(|p| p.0).collect();
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
        BezierObject::try_new(vec![], &BezierSettings::default()),
        Err(Error::EmptyScene)
    ));
    // Bad settings.
    let bad = HarmonicSettings { distance_tolerance: f64::NAN, ..HarmonicSettings::default() };
    assert!(HarmonicObject::try_new(sphere(1.0), &bad).is_err(), "NaN tolerance");
    let bad = HarmonicSettings { cells: (0, 4), ..HarmonicSettings::default() };
    assert!(HarmonicObject::try_new(sphere(1.0), &bad).is_err(), "no cells");
    // Messages are one line.
    for e in [Error::EmptyScene, Error::ZeroSizeImage { width: 0, height: 3 }] {
        assert!(!e.to_string().contains('\n'), "{e}");
    }
}
