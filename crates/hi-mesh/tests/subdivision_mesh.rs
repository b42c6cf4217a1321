// SPDX-License-Identifier: MIT
//! The polygon mesh of the subdivision module: validation errors naming the offending face,
//! edge or vertex; boundary detection; OBJ and OFF round trips and malformed files; the
//! conversion to the glTF export path.

use glam::DVec3;
use hi_mesh::Error as MeshError;
use hi_mesh::subdivision::PolyMesh;

fn square_positions() -> Vec<DVec3> {
    vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y, DVec3::Z]
}

#[test]
fn validation_names_the_offending_element() {
    let p = square_positions;
    let err = PolyMesh::try_new(p(), &[vec![0, 1, 7]]).expect_err("index 7");
    assert_eq!(err, MeshError::IndexOutOfRange { face: 0, index: 7, n_vertices: 5 });
    assert_eq!(err.to_string(), "face 0 names vertex 7, but the mesh has 5 vertices");

    let err = PolyMesh::try_new(p(), &[vec![0, 1, 2], vec![0, 1]]).expect_err("two corners");
    assert_eq!(err, MeshError::TooFewCorners { face: 1, corners: 2 });
    assert_eq!(err.to_string(), "face 1 is degenerate: it has 2 corners, at least 3 are needed");
    let err = PolyMesh::try_new(p(), &[vec![0, 1, 2], vec![2, 3, 2]]).expect_err("repeat");
    assert_eq!(err, MeshError::RepeatedVertex { face: 1, vertex: 2 });
    assert!(err.to_string().starts_with("face 1 is degenerate: it names vertex 2 twice"), "{err}");

    let mut q = p();
    q[3].y = f64::NAN;
    let err = PolyMesh::try_new(q, &[[0, 1, 2]]).expect_err("NaN");
    assert_eq!(err, MeshError::NonFinitePosition { vertex: 3 });

    // Three triangles on the edge 0–1.
    let err = PolyMesh::try_new(p(), &[[0, 1, 2], [1, 0, 3], [0, 1, 4]]).expect_err("fin");
    assert_eq!(err, MeshError::NonManifoldEdge { edge: [0, 1], faces: vec![0, 1, 2] });
    assert!(err.to_string().contains("edge (0, 1) is non-manifold"));

    // Consistent neighbours, then a second face traversing 2 → 0 as the first does.
    assert!(PolyMesh::try_new(p(), &[[0, 1, 2], [0, 2, 3]]).is_ok());
    let err = PolyMesh::try_new(p(), &[[0, 1, 2], [2, 0, 3]]).expect_err("same direction");
    assert_eq!(err, MeshError::InconsistentOrientation { edge: [2, 0], faces: [0, 1] });
    let err = PolyMesh::try_new(p(), &[[0, 1, 2], [0, 2, 3], [0, 2, 4]]).expect_err("3 on 0-2");
    assert_eq!(err, MeshError::NonManifoldEdge { edge: [0, 2], faces: vec![0, 1, 2] });

    // An octahedron with one face turned over.
    let octa = PolyMesh::octahedron();
    let mut faces: Vec<Vec<u32>> = octa.faces().map(<[u32]>::to_vec).collect();
    faces[5].reverse();
    let err = PolyMesh::try_new(octa.positions().to_vec(), &faces).expect_err("flipped face");
    let MeshError::InconsistentOrientation { faces: pair, edge } = err.clone() else {
        panic!("expected an orientation error, got {err}");
    };
    assert!(pair.contains(&5), "{err}");
    assert!(faces[5].contains(&edge[0]) && faces[5].contains(&edge[1]));
    assert!(err.to_string().contains("orientations disagree"));

    // Two tetrahedra sharing only vertex 0: a non-manifold vertex.
    let mut pos = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    pos.extend([-DVec3::X, -DVec3::Y, -DVec3::Z]);
    let tet = |a: u32, b: u32, c: u32| [[0, b, a], [0, a, c], [0, c, b], [a, b, c]];
    let mut faces = tet(1, 2, 3).to_vec();
    faces.extend(tet(4, 6, 5));
    let err = PolyMesh::try_new(pos, &faces).expect_err("bowtie");
    assert_eq!(err, MeshError::NonManifoldVertex { vertex: 0 });
}

#[test]
fn boundary_detection() {
    let p = square_positions;
    let m = PolyMesh::try_new(p(), &[[0, 1, 2], [0, 2, 3]]).expect("square");
    assert!(!m.is_closed());
    let mut b = m.boundary_edges();
    b.sort_unstable();
    assert_eq!(b, vec![[0, 1], [1, 2], [2, 3], [3, 0]]);
    assert!((0..4).all(|v| m.is_boundary_vertex(v)));
    assert!(!m.is_boundary_vertex(4)); // unused
    assert_eq!(m.valence(0), 3);
    assert_eq!(m.neighbors(0), vec![1, 2, 3]);
    assert!(PolyMesh::cube().boundary_edges().is_empty());
}

#[test]
fn obj_and_off_round_trip_exactly() {
    let dir = std::env::temp_dir().join(format!("hi-subdiv-io-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let star = PolyMesh::star()
        .try_map_positions(|p| p * std::f64::consts::PI + DVec3::splat(1e-7))
        .expect("finite");
    for (mesh, name) in [(star, "star"), (PolyMesh::cube(), "cube")] {
        for ext in ["obj", "off", "OBJ"] {
            let path = dir.join(format!("{name}.{ext}"));
            mesh.save(&path).expect("write");
            let back = PolyMesh::load(&path).expect("read");
            assert_eq!(back, mesh, "{name}.{ext}");
        }
    }
    let err = PolyMesh::cube().save(dir.join("x.stl")).expect_err("stl");
    assert!(
        err.to_string().contains("unknown mesh file extension: expected .obj or .off"),
        "{err}"
    );
    let err = PolyMesh::load(dir.join("missing.obj")).expect_err("missing");
    assert!(matches!(err, MeshError::Io { .. } | MeshError::UnknownExtension { .. }));
}

#[test]
fn obj_reader_accepts_common_records() {
    let text = "# comment\nmtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0 1.0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\ns off\nusemtl m\nf 1/1/1 2/1/1 3/1/1 4/1/1\nf -4 -2 -1\n";
    let err = PolyMesh::try_from_obj_str(text).expect_err("same direction");
    // `f -4 -2 -1` is `f 1 3 4`, which runs 3 → 4 as the quad `f 1 2 3 4` does.
    assert!(matches!(err, MeshError::InconsistentOrientation { .. }), "{err}");
    let ok = PolyMesh::try_from_obj_str(&text.replace("f -4 -2 -1\n", "")).expect("quad");
    assert_eq!((ok.n_vertices(), ok.n_faces(), ok.face(0).len()), (4, 1, 4));
}

#[test]
fn malformed_files_report_the_line() {
    let cases_obj = [
        ("v 0 0\n", 1, "expected 3 coordinates after `v`, found 2"),
        ("v 0 0 0\nv 1 0 zero\n", 2, "not a number"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n", 5, "face index 4 is out of range"),
        ("v 0 0 0\nv 1 0 0\nf 1 2\n", 3, "at least 3 vertices, found 2"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", 4, "face index 0"),
        ("v 0 0 0\nf a b c\n", 2, "not a vertex index"),
    ];
    for (text, line, what) in cases_obj {
        let err = PolyMesh::try_from_obj_str(text).expect_err(text);
        let MeshError::Parse { format: "OBJ", line: l, ref message } = err else {
            panic!("{text:?}: {err}");
        };
        assert_eq!(l, Some(line), "{text:?}: {err}");
        assert!(message.contains(what), "{text:?}: {err}");
    }
    // A non-finite coordinate parses, and the mesh refuses it by vertex.
    let err = PolyMesh::try_from_obj_str("v 0 0 0\nv 0 0 inf\n").expect_err("infinite");
    assert!(matches!(err, MeshError::NonFinitePosition { vertex: 1 }), "{err}");
    let cases_off = [
        ("PLY\n", Some(1), "expected the keyword OFF"),
        ("OFF\n3 1\n", None, "ends after 0 of 3 vertices"),
        ("OFF\n3 1 0\n0 0 0\n1 0 0\n", None, "ends after 2 of 3 vertices"),
        ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", Some(6), "out of range"),
        ("OFF\n3 1 0\n0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n", Some(4), "not a number"),
        ("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n3 0 1 2\n", Some(6), "3 of its 4"),
        ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", Some(6), "at least 3"),
        ("OFF BINARY\n", Some(1), "binary"),
        ("OFF\n-3 1 0\n", Some(2), "not a whole number"),
    ];
    for (text, line, what) in cases_off {
        let err = PolyMesh::try_from_off_str(text).expect_err(text);
        let MeshError::Parse { format: "OFF", line: l, ref message } = err else {
            panic!("{text:?}: {err}");
        };
        assert_eq!(l, line, "{text:?}: {err}");
        assert!(message.contains(what), "{text:?}: {err}");
    }
    // OFF with the counts on the header line, comments and colours after a face.
    let m =
        PolyMesh::try_from_off_str("OFF 3 1 0 # counts\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n")
            .expect("valid");
    assert_eq!(m.n_faces(), 1);
}

#[test]
fn readers_never_panic_on_mutated_files() {
    let mut obj = Vec::new();
    PolyMesh::star().write_obj(&mut obj).expect("write");
    let mut off = Vec::new();
    PolyMesh::cube().write_off(&mut off).expect("write");
    let alphabet = b" \n-0123456789./#fvOFe+";
    let mut state = 12345_u64;
    let mut rand = |n: usize| {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 33) as usize % n
    };
    for round in 0..2000 {
        let base = if round % 2 == 0 { &obj } else { &off };
        let mut bytes = base.clone();
        for _ in 0..1 + rand(6) {
            let i = rand(bytes.len());
            match rand(3) {
                0 => bytes[i] = alphabet[rand(alphabet.len())],
                1 => {
                    bytes.remove(i);
                }
                _ => bytes.truncate(i),
            }
            if bytes.is_empty() {
                break;
            }
        }
        let text = String::from_utf8_lossy(&bytes);
        let _ = PolyMesh::try_from_obj_str(&text);
        let _ = PolyMesh::try_from_off_str(&text);
    }
}

#[test]
#[cfg(feature = "gltf")]
fn to_triangle_mesh_goes_to_gltf() {
    let cube = PolyMesh::cube();
    let tri = cube.to_triangle_mesh().expect("faces");
    assert_eq!((tri.n_vertices(), tri.n_triangles()), (8, 12));
    // Corner (0,0,0) is in two triangles of the faces z = 0 and y = 0 and one of x = 0: the
    // area-weighted normal is (−1, −2, −2)/3.
    assert!((tri.normals()[0] - DVec3::new(-1.0, -2.0, -2.0) / 3.0).length() < 1e-12);
    let mut glb = Vec::new();
    hi_mesh::export::write_glb(&tri, &mut glb).expect("glb");
    let dir = std::env::temp_dir().join(format!("hi-subdiv-gltf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("cube.glb");
    std::fs::write(&path, &glb).expect("write");
    let back = hi_mesh::export::load(&path).expect("read back");
    assert_eq!(back.n_triangles(), 12);
    let empty = PolyMesh::try_new(vec![DVec3::ZERO], &Vec::<[u32; 3]>::new()).expect("no faces");
    assert!(matches!(
        empty.to_triangle_mesh(),
        Err(MeshError::InvalidCount { what: "number of triangles", .. })
    ));
}

#[test]
fn a_real_mesh_with_a_pinched_vertex_is_rejected() {
    // cow.obj has one vertex where two fans of faces touch (checked independently when the
    // peers were chosen); spot.obj is a closed manifold.
    let (Some(cow), Some(spot)) =
        (hi_testkit::shared_model("cow.obj"), hi_testkit::shared_model("spot.obj"))
    else {
        return;
    };
    let (cow, spot) =
        (std::fs::read_to_string(cow).unwrap(), std::fs::read_to_string(spot).unwrap());
    let err = PolyMesh::try_from_obj_str(&cow).expect_err("pinched vertex");
    assert!(matches!(err, MeshError::NonManifoldVertex { .. }), "{err}");
    let spot = PolyMesh::try_from_obj_str(&spot).expect("spot");
    assert!(spot.is_closed());
    assert_eq!((spot.n_vertices(), spot.n_faces()), (2930, 5856));
    assert_eq!(spot.n_vertices() + spot.n_faces(), spot.n_edges() + 2);
}
