// SPDX-License-Identifier: MIT
//! Fuzzes the readers `hi subdivide` uses and one step of every scheme that accepts the mesh:
//! the first byte picks OBJ or OFF and the scheme, the rest is the file. Run with
//! `cargo +nightly fuzz run poly_mesh` in `crates/hi-mesh/fuzz`.
#![no_main]

use hi_mesh::PolyMesh;
use hi_mesh::subdivision::Scheme;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else { return };
    let text = String::from_utf8_lossy(rest);
    let read =
        if first & 1 == 0 { PolyMesh::try_from_obj_str(&text) } else { PolyMesh::try_from_off_str(&text) };
    let Ok(mesh) = read else { return };
    let n = mesh.n_vertices();
    assert!(mesh.positions().iter().all(|p| p.is_finite()));
    assert!(mesh.faces().all(|f| f.len() >= 3 && f.iter().all(|&k| (k as usize) < n)));
    if mesh.n_faces() > 256 {
        return;
    }
    let scheme = Scheme::ALL[usize::from(first >> 1) % Scheme::ALL.len()];
    if let Ok(refined) = scheme.step(&mesh) {
        let m = refined.n_vertices();
        assert!(refined.positions().iter().all(|p| p.is_finite()));
        assert!(refined.faces().all(|f| f.iter().all(|&k| (k as usize) < m)));
    }
});
