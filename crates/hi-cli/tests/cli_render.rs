// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi render` (Hardy 2005, §5.5, §5.6): PNG files of the right size, the
//! same bytes twice, and one-line errors with exit status 2.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use common::{TempFile, bad, ok};

/// Width and height from a PNG's IHDR chunk.
fn png_size(path: &std::path::Path) -> (u32, u32) {
    let bytes = std::fs::read(path).expect("the PNG was written");
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR", "IHDR first");
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    (be(16), be(20))
}

/// The grid file of the torus example.
fn torus_grid() -> TempFile {
    let grid = TempFile::path_with("json");
    ok(&["surface", "example", "torus", "-o", grid.path()]);
    grid
}

#[test]
fn quick_renders_have_the_requested_size_and_are_reproducible() {
    let grid = torus_grid();
    // `interval`: the deprecated alias of `krawczyk`.
    for method in ["bezier", "krawczyk", "interval", "bisection", "mesh"] {
        let png = TempFile::path_with("png");
        let out = ok(&[
            "render",
            "--quick",
            grid.path(),
            "--method",
            method,
            "--width",
            "24",
            "--height",
            "16",
            "--spp",
            "1",
            "-o",
            png.path(),
        ]);
        assert_eq!(png_size(png.as_path()), (24, 16), "{method}");
        assert_eq!(out["width"], 24, "{method}");
        assert_eq!(out["rays"]["camera"], 24 * 16, "{method}");
        assert!(out["rays"]["hits"].as_u64().unwrap() > 20, "{method}: the torus is in view");
        let first = std::fs::read(png.as_path()).unwrap();
        ok(&[
            "render",
            "--quick",
            grid.path(),
            "--method",
            method,
            "--width",
            "24",
            "--height",
            "16",
            "--spp",
            "1",
            "-o",
            png.path(),
        ]);
        assert_eq!(std::fs::read(png.as_path()).unwrap(), first, "{method}: same bytes twice");
    }
}

#[test]
fn a_scene_file_renders() {
    let grid = torus_grid();
    let mesh = TempFile::path_with("obj");
    ok(&["surface", "mesh", "--input", grid.path(), "--resolution", "16x16", "-o", mesh.path()]);
    let patches = TempFile::path_with("json");
    ok(&[
        "surface",
        "bezier",
        "--input",
        grid.path(),
        "--scheme",
        "thesis-cubic",
        "-o",
        patches.path(),
    ]);
    let scene = format!(
        r#"{{"camera": {{"eye": [0, -14, 9], "target": [0, 0, 0], "fov": 45}},
            "image": {{"width": 20, "height": 14, "spp": 2}},
            "background": [0.1, 0.1, 0.2],
            "lights": [{{"type": "directional", "direction": [1, -1, 2], "intensity": 0.9}},
                       {{"type": "point", "position": [4, -4, 6], "intensity": [20, 20, 20]}}],
            "objects": [{{"type": "harmonic", "file": "{}", "method": "krawczyk", "curvature": "gaussian"}},
                        {{"type": "mesh", "file": "{}", "material": {{"color": [0.9, 0.5, 0.2], "specular": 0.1}}}},
                        {{"type": "bezier", "file": "{}"}}]}}"#,
        grid.path(),
        mesh.path(),
        patches.path()
    );
    let scene_file = TempFile::new(&scene);
    let png = TempFile::path_with("png");
    let out = ok(&["render", scene_file.path(), "-o", png.path()]);
    assert_eq!(png_size(png.as_path()), (20, 14), "size from the scene file");
    assert_eq!(out["spp"], 2, "samples from the scene file");
    let png2 = TempFile::path_with("png");
    ok(&["render", scene_file.path(), "--width", "8", "--height", "6", "-o", png2.path()]);
    assert_eq!(png_size(png2.as_path()), (8, 6), "flags override the scene");
}

#[test]
fn bad_input_exits_2_with_one_line() {
    let grid = torus_grid();
    let png = TempFile::path_with("png");
    // Unreadable object files.
    bad(&["render", "--quick", "/nonexistent/torus.json", "-o", png.path()], "cannot read");
    let scene =
        TempFile::new(r#"{"objects": [{"type": "harmonic", "file": "/nonexistent/grid.json"}]}"#);
    bad(&["render", scene.path(), "-o", png.path()], "objects[0]");
    let not_a_grid = TempFile::new("[[1, 2]]");
    bad(&["render", "--quick", not_a_grid.path(), "-o", png.path()], not_a_grid.path());
    // A degenerate camera.
    let scene = TempFile::new(&format!(
        r#"{{"camera": {{"eye": [1, 2, 3], "target": [1, 2, 3]}},
            "objects": [{{"type": "harmonic", "file": "{}"}}]}}"#,
        grid.path()
    ));
    bad(&["render", scene.path(), "-o", png.path()], "degenerate camera");
    let scene = TempFile::new(&format!(
        r#"{{"camera": {{"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 0, 1]}},
            "objects": [{{"type": "harmonic", "file": "{}"}}]}}"#,
        grid.path()
    ));
    bad(&["render", scene.path(), "-o", png.path()], "parallel");
    // A bad field, named by its path.
    let scene = TempFile::new(&format!(
        r#"{{"objects": [{{"type": "harmonic", "file": "{0}"}},
                        {{"type": "harmonic", "file": "{0}", "material": {{"color": [0, 1.5, 0]}}}}]}}"#,
        grid.path()
    ));
    bad(
        &["render", scene.path(), "-o", png.path()],
        "objects[1].material.color: colour [0, 1.5, 0]",
    );
    let scene = TempFile::new(&format!(
        r#"{{"camera": {{"eye": [0, 0, 5], "forward": [0, 0, -1], "fov_y": 0.7}},
            "objects": [{{"type": "harmonic", "file": "{}"}}]}}"#,
        grid.path()
    ));
    bad(&["render", scene.path(), "-o", png.path()], "camera.forward: unknown field `forward`");
    let scene = TempFile::new(&format!(
        r#"{{"objects": [{{"type": "harmonic", "file": "{}", "method": "newton"}}]}}"#,
        grid.path()
    ));
    bad(&["render", scene.path(), "-o", png.path()], "objects[0].method: unknown variant `newton`");
    // Zero size.
    bad(&["render", "--quick", grid.path(), "--width", "0", "-o", png.path()], "no pixels");
    bad(&["render", "--quick", grid.path(), "--height", "0", "-o", png.path()], "no pixels");
    // An empty scene, a wrong output extension, no scene at all.
    let empty = TempFile::new(r#"{"objects": []}"#);
    bad(&["render", empty.path(), "-o", png.path()], "no objects");
    bad(&["render", "--quick", grid.path(), "-o", "out.jpg"], ".png");
    bad(&["render", "-o", png.path()], "SCENE");
}

#[test]
fn a_glb_without_normals_renders() {
    let (positions, triangles) = common::ellipsoid_mesh(12, 24, [1.0, 0.8, 0.6]);
    let scene = TempFile::path_with("glb");
    let bytes = common::glb_without_normals(&positions, &triangles, 1.0, [0.0; 3]);
    std::fs::write(scene.as_path(), bytes).expect("temp file is writable");
    let png = TempFile::path_with("png");
    let out = ok(&[
        "render",
        "--quick",
        scene.path(),
        "--width",
        "24",
        "--height",
        "16",
        "--spp",
        "1",
        "-o",
        png.path(),
    ]);
    assert_eq!(png_size(png.as_path()), (24, 16));
    assert!(out["rays"]["hits"].as_u64().unwrap() > 20, "the ellipsoid is in view: {out}");
}
