// SPDX-License-Identifier: MIT
//! The invariants of [`TriangleMesh`]: every bad part is refused with an error naming it.

use glam::{DVec2, DVec3};
use hi_mesh::{ColorMap, ColorScale, Error, TriangleMesh};

#[test]
fn try_new_checks_the_invariants() {
    let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
    let n = vec![DVec3::Z; 3];
    let uv = vec![DVec2::ZERO; 3];
    let ok = TriangleMesh::try_new(p.clone(), n.clone(), uv.clone(), vec![[0, 1, 2]]).unwrap();
    assert_eq!((ok.n_vertices(), ok.n_triangles()), (3, 1), "one triangle");
    let cases: Vec<(&str, Result<TriangleMesh, Error>)> = vec![
        ("no triangles", TriangleMesh::try_new(p.clone(), n.clone(), uv.clone(), vec![])),
        ("index", TriangleMesh::try_new(p.clone(), n.clone(), uv.clone(), vec![[0, 1, 3]])),
        ("normals", TriangleMesh::try_new(p.clone(), n[..2].to_vec(), uv.clone(), vec![[0, 1, 2]])),
        ("uvs", TriangleMesh::try_new(p.clone(), n.clone(), uv[..1].to_vec(), vec![[0, 1, 2]])),
        (
            "length",
            TriangleMesh::try_new(p.clone(), vec![DVec3::Z * 1.1; 3], uv.clone(), vec![[0, 1, 2]]),
        ),
        (
            "zero",
            TriangleMesh::try_new(p.clone(), vec![DVec3::ZERO; 3], uv.clone(), vec![[0, 1, 2]]),
        ),
        ("nan", TriangleMesh::try_new(vec![DVec3::NAN; 3], n.clone(), uv.clone(), vec![[0, 1, 2]])),
        (
            "uv nan",
            TriangleMesh::try_new(p.clone(), n.clone(), vec![DVec2::NAN; 3], vec![[0, 1, 2]]),
        ),
        ("colours", ok.clone().try_with_colors(vec![[0.5; 3]; 2])),
        ("colour range", ok.clone().try_with_colors(vec![[0.5, 1.5, 0.0]; 3])),
        ("colour nan", ok.clone().try_with_colors(vec![[0.5, f32::NAN, 0.0]; 3])),
    ];
    for (what, r) in cases {
        let e = r.expect_err(what);
        let expected = match what {
            "nan" => matches!(e, Error::NonFinitePosition { vertex: 0 }),
            "no triangles" | "index" | "normals" | "uvs" | "colours" => {
                matches!(e, Error::InvalidCount { .. })
            }
            _ => matches!(e, Error::InvalidValue { .. }),
        };
        assert!(expected, "{what}: {e:?}");
        assert!(!e.to_string().contains('\n'), "{what}: one line");
    }
    let colored = ok.try_with_colors(vec![[0.0, 0.5, 1.0]; 3]).unwrap();
    assert_eq!(colored.colors().unwrap()[2], [0.0, 0.5, 1.0], "kept");
    assert!(colored.without_colors().colors().is_none(), "removed");
}

#[test]
fn a_colour_mapping_brings_its_legend() {
    let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
    let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 3], vec![DVec2::ZERO; 3], vec![[0, 1, 2]])
        .expect("one triangle");
    let map = ColorMap { scale: ColorScale::MinMax, ..ColorMap::default() };
    let mapping = map.try_apply(&[1.0, 2.0, 3.0]).expect("finite values");
    let coloured = mesh.try_with_mapping(mapping).expect("one colour per vertex");
    let legend = coloured.legend().expect("a legend");
    assert_eq!((legend.min, legend.max), (1.0, 3.0), "the data's range");
    assert!(coloured.clone().try_with_colors(vec![[0.5; 3]; 3]).expect("valid").legend().is_none());
    let short = map.try_apply(&[1.0, 2.0]).expect("finite values");
    assert!(matches!(coloured.try_with_mapping(short), Err(Error::InvalidCount { .. })));
}

/// Without its features the crate still knows the formats, and says which feature a file
/// needs rather than writing nothing.
#[test]
#[cfg(not(all(feature = "gltf", feature = "obj")))]
fn a_format_left_out_names_its_feature() {
    let mesh = hi_mesh::PolyMesh::cube().to_triangle_mesh().expect("a cube");
    let dir = std::env::temp_dir();
    let (path, feature) = if cfg!(feature = "gltf") {
        (dir.join("hi-mesh-no-obj.obj"), "obj")
    } else {
        (dir.join("hi-mesh-no-gltf.glb"), "gltf")
    };
    let error = if feature == "gltf" {
        hi_mesh::export::save(&mesh, &path).expect_err("no glTF writer")
    } else {
        hi_mesh::export::save(&mesh, &path).expect("OBJ is always written");
        hi_mesh::export::load(&path).expect_err("no OBJ reader")
    };
    assert!(
        matches!(&error, Error::FeatureDisabled { feature: f, .. } if *f == feature),
        "{error}"
    );
    assert!(error.to_string().contains(&format!("`{feature}` feature")), "{error}");
}

/// An OBJ of bare positions and faces (as most programs write it) reads with area-weighted
/// vertex normals and zero texture coordinates: a unit square in the plane z = 0 split into two
/// counter-clockwise triangles has the normal +z at every corner, and a right angle bent along
/// its diagonal has normals halfway between its two faces' at the shared corners.
#[test]
#[cfg(feature = "obj")]
fn an_obj_without_normals_reads_with_normals_from_its_faces() {
    let dir = std::env::temp_dir().join(format!("hi-mesh-bare-obj-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let square = dir.join("square.obj");
    std::fs::write(&square, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n").unwrap();
    let mesh = hi_mesh::export::load(&square).expect("a bare OBJ reads");
    assert_eq!(mesh.triangles().len(), 2);
    for (n, uv) in mesh.normals().iter().zip(mesh.uvs()) {
        assert_eq!(*n, DVec3::Z);
        assert_eq!(*uv, DVec2::ZERO);
    }
    // Two faces at a right angle: z = 0 (normal +z) and x = 0 (normal +x, by its winding).
    let bent = dir.join("bent.obj");
    std::fs::write(&bent, "v 0 0 0\nv 0 1 0\nv 1 0 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n").unwrap();
    let mesh = hi_mesh::export::load(&bent).expect("a bare OBJ reads");
    let half = std::f64::consts::FRAC_1_SQRT_2;
    let by_position = |p: DVec3| {
        let k = mesh.positions().iter().position(|q| *q == p).expect("the corner is there");
        mesh.normals()[k]
    };
    assert!((by_position(DVec3::ZERO) - DVec3::new(half, 0.0, half)).length() < 1e-15);
    assert!((by_position(DVec3::X) - DVec3::Z).length() < 1e-15);
    assert!((by_position(DVec3::Z) - DVec3::X).length() < 1e-15);
    // Normals for only some vertices are refused, with the object named.
    let partial = dir.join("partial.obj");
    std::fs::write(&partial, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3\n").unwrap();
    let result = hi_mesh::export::load(&partial);
    std::fs::remove_dir_all(&dir).ok();
    let error = result.expect_err("normals for one corner of three");
    assert!(error.to_string().contains("only some vertices"), "{error}");
}
