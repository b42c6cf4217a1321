// SPDX-License-Identifier: MIT
//! Replays the fuzzing corpus of the polygon-mesh readers (`fuzz/corpus/poly_mesh`, from the
//! campaigns recorded in `docs/reliability.md`) with the fuzz target's own checks: the first
//! byte picks OBJ or OFF and a subdivision scheme, the rest is the file; nothing may panic, a
//! mesh that is read has finite points and faces of at least three corners that index them,
//! and so has its refinement by the scheme when the scheme accepts it.

use std::path::Path;

use hi_mesh::PolyMesh;
use hi_mesh::subdivision::Scheme;

#[test]
fn the_fuzzing_corpus_replays_without_a_failure() {
    let fuzz = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz");
    if !fuzz.exists() {
        // A packaged crate leaves the fuzzing folder out (it is a package of its own).
        eprintln!("no fuzz folder beside this crate: the corpus is replayed in the repository");
        return;
    }
    let dir = fuzz.join("corpus/poly_mesh");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.expect("a corpus entry").path())
        .collect();
    files.sort();
    let (mut read, mut refined) = (0, 0);
    for path in &files {
        let data = std::fs::read(path).expect("a corpus file");
        let Some((&first, rest)) = data.split_first() else { continue };
        let text = String::from_utf8_lossy(rest);
        let parsed = if first & 1 == 0 {
            PolyMesh::try_from_obj_str(&text)
        } else {
            PolyMesh::try_from_off_str(&text)
        };
        let Ok(mesh) = parsed else { continue };
        read += 1;
        let n = mesh.n_vertices();
        assert!(mesh.positions().iter().all(|p| p.is_finite()), "{}", path.display());
        assert!(
            mesh.faces().all(|f| f.len() >= 3 && f.iter().all(|&k| (k as usize) < n)),
            "{}",
            path.display()
        );
        if mesh.n_faces() > 256 {
            continue;
        }
        let scheme = Scheme::ALL[usize::from(first >> 1) % Scheme::ALL.len()];
        if let Ok(out) = scheme.step(&mesh) {
            refined += 1;
            let m = out.n_vertices();
            assert!(out.positions().iter().all(|p| p.is_finite()), "{}", path.display());
            assert!(out.faces().all(|f| f.iter().all(|&k| (k as usize) < m)), "{}", path.display());
        }
    }
    assert!(read >= 4 && refined >= 6, "the corpus reads {read} meshes and refines {refined}");
}
