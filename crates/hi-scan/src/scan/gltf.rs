// SPDX-License-Identifier: MIT
//! glTF 2.0 scans (`.gltf` with embedded or external buffers, and binary `.glb`): the positions
//! of every mesh primitive that the scene places, in world space.
//!
//! The scene read is the default one, or, when there is none, every scene; each node's world
//! transform (its own matrix or translation–rotation–scale, after its parents') is applied to the
//! positions of its mesh, and normals, when every primitive has them, by the inverse transpose.
//! A file with no scene at all has its meshes read as they are. Triangles come from
//! `TRIANGLES`, `TRIANGLE_STRIP` and `TRIANGLE_FAN` primitives (indexed or not); `POINTS` and `LINES`
//! primitives give points only. Malformed files are a [`Error`]: the `gltf` crate parses and
//! validates the document, the GLB header is checked here first, and an accessor that claims
//! more elements than the file could hold is refused before anything is allocated for it.

use std::path::Path;

use glam::{DMat3, DVec3};
use hi_mesh::export::primitive_triangles;

use super::{Scan, ScanFormat};
use crate::Error;

/// An accessor may not claim more elements than this many per byte of the file (a sparse
/// accessor with no buffer view is all zeros but for its few listed values).
const ELEMENTS_PER_BYTE: usize = 4;

/// Reads a glTF or GLB scan from its bytes; external buffers are resolved against `base`, and
/// refused when there is none.
pub(super) fn parse(bytes: &[u8], base: Option<&Path>, format: ScanFormat) -> Result<Scan, Error> {
    let error = |message: String| Error::file(format, message);
    if bytes.starts_with(b"glTF") {
        check_glb_header(bytes).map_err(|m| error(m.to_owned()))?;
    }
    // The `gltf` crate validates; a panic inside it on hostile input must not escape.
    let result = std::panic::catch_unwind(|| read(bytes, base));
    match result {
        Ok(Ok(raw)) => Ok(raw),
        Ok(Err(message)) => Err(error(message)),
        Err(_) => Err(error("malformed glTF (the parser gave up on it)".to_owned())),
    }
}

/// The GLB header: magic, version 2, and a length that covers the header and no more than the
/// bytes there are.
fn check_glb_header(bytes: &[u8]) -> Result<(), &'static str> {
    if bytes.len() < 12 {
        return Err("the GLB header is cut short");
    }
    let word = |k: usize| u32::from_le_bytes([bytes[k], bytes[k + 1], bytes[k + 2], bytes[k + 3]]);
    if word(4) != 2 {
        return Err("only glTF 2 binaries are read");
    }
    let length = word(8) as usize;
    if length < 12 || length > bytes.len() {
        return Err("the GLB header's length does not match the file");
    }
    Ok(())
}

fn read(bytes: &[u8], base: Option<&Path>) -> Result<Scan, String> {
    let gltf = hi_mesh::export::parse_gltf(bytes).map_err(|e| match e {
        // The scan error names the format already.
        hi_mesh::Error::Format { message, .. } => {
            message.strip_prefix("glTF: ").map_or(message.clone(), str::to_owned)
        }
        other => other.to_string(),
    })?;
    let ::gltf::Gltf { document, blob } = gltf;
    let buffers = ::gltf::import_buffers(&document, base, blob).map_err(|e| match e {
        ::gltf::Error::ExternalReferenceInSliceImport => {
            "a buffer is in another file, which cannot be read from the bytes alone".to_owned()
        }
        other => format!("glTF buffers: {other}"),
    })?;
    let limit = ELEMENTS_PER_BYTE * bytes.len() + 1024;
    let instances = hi_mesh::export::placed_meshes(&document)?;
    let (mut points, mut normals, mut faces): (Vec<DVec3>, Vec<DVec3>, Vec<Vec<u32>>) =
        (Vec::new(), Vec::new(), Vec::new());
    let mut all_normals = true;
    for (mesh, world) in &instances {
        let normal_matrix = DMat3::from_mat4(*world).inverse().transpose();
        let flips = world.determinant() < 0.0;
        for primitive in mesh.primitives() {
            if let Some(problem) = hi_mesh::export::accessor_problem(&primitive) {
                return Err(problem);
            }
            let reader = primitive.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
            let Some(accessor) = primitive.get(&::gltf::Semantic::Positions) else { continue };
            if accessor.count() > limit {
                return Err(format!(
                    "a POSITION accessor claims {} elements, more than the file can hold",
                    accessor.count()
                ));
            }
            let Some(positions) = reader.read_positions() else {
                return Err("a POSITION accessor cannot be read".to_owned());
            };
            let base = u32::try_from(points.len()).map_err(|_| "too many points".to_owned())?;
            let before = points.len();
            points.extend(positions.map(|p| world.transform_point3(DVec3::from(p.map(f64::from)))));
            let n = points.len() - before;
            match (primitive.get(&::gltf::Semantic::Normals), reader.read_normals()) {
                (Some(a), Some(ns)) if a.count() == n => {
                    normals.extend(ns.map(|v| {
                        (normal_matrix * DVec3::from(v.map(f64::from))).normalize_or_zero()
                    }))
                }
                _ => all_normals = false,
            }
            let indices: Vec<u32> = match (primitive.indices(), reader.read_indices()) {
                (Some(a), _) if a.count() > limit => {
                    return Err(format!(
                        "an index accessor claims {} elements, more than the file can hold",
                        a.count()
                    ));
                }
                (Some(_), Some(i)) => i.into_u32().collect(),
                (Some(_), None) => return Err("an index accessor cannot be read".to_owned()),
                (None, _) => {
                    (0..u32::try_from(n).map_err(|_| "too many points".to_owned())?).collect()
                }
            };
            if let Some(&k) = indices.iter().find(|&&k| k as usize >= n) {
                return Err(format!("index {k} is beyond the primitive's {n} positions"));
            }
            for t in primitive_triangles(primitive.mode(), &indices).unwrap_or_default() {
                let t = t.map(|k| k + base);
                faces.push(if flips { vec![t[0], t[2], t[1]] } else { t.to_vec() });
            }
        }
    }
    let normals = (all_normals && normals.len() == points.len()).then_some(normals);
    Ok(Scan::assemble(points, normals, &faces))
}
