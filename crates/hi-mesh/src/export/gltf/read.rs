// SPDX-License-Identifier: MIT
//! glTF 2.0 read back: the document parsed with checks added before the `gltf` crate's own,
//! its meshes placed by their nodes, and their triangles appended to one mesh.

use std::path::Path;

use ::gltf::json;
use glam::{DMat3, DMat4, DVec2, DVec3, Vec3};
use json::validation::Checked::Valid;

use super::gltf_error;
use crate::export::{MeshBuilder, format_error, io_error};
use crate::{Error, TriangleMesh};

/// A `.gltf` or `.glb` file's document (and a GLB's binary chunk), read by the `gltf` crate with
/// a check added before its validation: `gltf-json` 1.4 validates by looking up a primitive's
/// `POSITION` accessor before checking that the index is in range, and panics on a file whose
/// index is not (found by fuzzing the scan readers; see `docs/reliability.md`). The JSON is
/// parsed once. Both readers of the workspace go through here.
///
/// # Errors
///
/// [`Error::Format`](crate::Error::Format) for a file the `gltf` crate rejects, whose
/// primitive names a `POSITION` accessor the file does not have, or whose buffer has a relative
/// URI that is not UTF-8 once percent-decoded (the `gltf` crate's import panics on it).
///
/// # Examples
///
/// ```
/// // "accessors" misspelt: the POSITION accessor 0 does not exist.
/// let bad = br#"{"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"accesors":[]}"#;
/// let err = hi_mesh::export::parse_gltf(bad).unwrap_err();
/// assert!(err.to_string().contains("POSITION names accessor 0"), "{err}");
/// // "%AA" alone decodes to a byte that is not UTF-8; "%C3%A9" (é) is fine.
/// let bad = br#"{"asset":{"version":"2.0"},"buffers":[{"uri":"a%AA.bin","byteLength":4}]}"#;
/// let err = hi_mesh::export::parse_gltf(bad).unwrap_err();
/// assert!(err.to_string().contains("buffer 0: its URI is not UTF-8"), "{err}");
/// let good = br#"{"asset":{"version":"2.0"},"buffers":[{"uri":"caf%C3%A9.bin","byteLength":4}]}"#;
/// assert!(hi_mesh::export::parse_gltf(good).is_ok());
/// ```
pub fn parse_gltf(bytes: &[u8]) -> Result<::gltf::Gltf, Error> {
    let ::gltf::Gltf { document, blob } =
        ::gltf::Gltf::from_slice_without_validation(bytes).map_err(|e| gltf_error(e, None))?;
    let root = document.into_json();
    if let Some(problem) = position_accessor_problem(&root).or_else(|| buffer_uri_problem(&root)) {
        return Err(format_error(format!("glTF: {problem}"), None));
    }
    let document = ::gltf::Document::from_json(root).map_err(|e| gltf_error(e, None))?;
    Ok(::gltf::Gltf { document, blob })
}

/// A primitive whose `POSITION` is not an index of the document's accessors, named.
fn position_accessor_problem(root: &json::Root) -> Option<String> {
    let accessors = root.accessors.len();
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            let position = primitive.attributes.get(&Valid(json::mesh::Semantic::Positions));
            if let Some(index) = position
                && index.value() >= accessors
            {
                return Some(format!(
                    "mesh {m}, primitive {p}: POSITION names accessor {}, but the file has {accessors}",
                    index.value()
                ));
            }
        }
    }
    None
}

/// A buffer whose URI is a relative path (no `:`) that is not UTF-8 once percent-decoded
/// (`%AA` on its own, say), named: the `gltf` crate's buffer import decodes such a URI with an
/// `unwrap` and panics (found by fuzzing the scan readers). URIs with a scheme (`data:`,
/// `file:`) are not decoded there.
fn buffer_uri_problem(root: &json::Root) -> Option<String> {
    root.buffers.iter().enumerate().find_map(|(b, buffer)| {
        let uri = buffer.uri.as_deref()?;
        (!uri.contains(':') && String::from_utf8(percent_decoded(uri.as_bytes())).is_err())
            .then(|| format!("buffer {b}: its URI is not UTF-8 once percent-decoded"))
    })
}

/// `%XX` (two hex digits) replaced by the byte XX; everything else kept (as the `urlencoding`
/// crate that `gltf` uses decodes).
fn percent_decoded(data: &[u8]) -> Vec<u8> {
    let hex = |c: u8| char::from(c).to_digit(16).and_then(|d| u8::try_from(d).ok());
    let mut out = Vec::with_capacity(data.len());
    let mut i = 0;
    while i < data.len() {
        if data[i] == b'%'
            && let (Some(h), Some(l)) =
                (data.get(i + 1).copied().and_then(hex), data.get(i + 2).copied().and_then(hex))
        {
            out.push(h << 4 | l);
            i += 3;
        } else {
            out.push(data[i]);
            i += 1;
        }
    }
    out
}

/// Why the `gltf` crate's reader could not read a primitive's positions, normals, first UV
/// set, first colour set or indices: an accessor of a type the glTF 2.0 specification does not
/// allow there (§3.7.2.1), with no elements or an extent that overflows, or read through a
/// buffer view whose byte stride is shorter than its element, all of which that reader meets
/// with an assertion, an overflow or `unreachable!` rather than an error (found by fuzzing the
/// scan readers). `None` when every one it has is readable.
#[must_use]
pub fn accessor_problem(primitive: &::gltf::Primitive<'_>) -> Option<String> {
    use ::gltf::Semantic;
    use ::gltf::accessor::{DataType, Dimensions};
    let allowed =
        |semantic: &Semantic| -> (&'static str, &'static [Dimensions], &'static [DataType]) {
            match semantic {
                Semantic::Positions => ("POSITION", &[Dimensions::Vec3], &[DataType::F32]),
                Semantic::Normals => ("NORMAL", &[Dimensions::Vec3], &[DataType::F32]),
                Semantic::TexCoords(_) => {
                    ("TEXCOORD", &[Dimensions::Vec2], &[DataType::U8, DataType::U16, DataType::F32])
                }
                _ => (
                    "COLOR",
                    &[Dimensions::Vec3, Dimensions::Vec4],
                    &[DataType::U8, DataType::U16, DataType::F32],
                ),
            }
        };
    for semantic in
        [Semantic::Positions, Semantic::Normals, Semantic::TexCoords(0), Semantic::Colors(0)]
    {
        let Some(accessor) = primitive.get(&semantic) else { continue };
        let (name, dimensions, types) = allowed(&semantic);
        if !extent_fits(&accessor) {
            return Some(format!(
                "a {name} accessor of {} elements at offset {} has no elements or overflows \
                 the address space",
                accessor.count(),
                accessor.offset()
            ));
        }
        if let Some(problem) = stride_problem(&accessor) {
            return Some(format!("a {name} accessor's {problem}"));
        }
        if !dimensions.contains(&accessor.dimensions()) || !types.contains(&accessor.data_type()) {
            return Some(format!(
                "a {name} accessor holds {:?} of {:?}, which glTF does not allow there",
                accessor.dimensions(),
                accessor.data_type()
            ));
        }
    }
    let index_types = [DataType::U8, DataType::U16, DataType::U32];
    if let Some(a) = primitive.indices()
        && !extent_fits(&a)
    {
        return Some(format!(
            "an index accessor of {} elements at offset {} has no elements or overflows the \
             address space",
            a.count(),
            a.offset()
        ));
    }
    if let Some(problem) = primitive.indices().as_ref().and_then(stride_problem) {
        return Some(format!("an index accessor's {problem}"));
    }
    match primitive.indices() {
        Some(a)
            if a.dimensions() != Dimensions::Scalar || !index_types.contains(&a.data_type()) =>
        {
            Some(format!(
                "an index accessor holds {:?} of {:?}; indices are unsigned scalars",
                a.dimensions(),
                a.data_type()
            ))
        }
        _ => None,
    }
}

/// Whether the byte ranges the `gltf` crate's reader computes for `accessor` (and for its sparse
/// indices and values) exist: at least one element (glTF 2.0 asks `count ≥ 1`), and
/// offset + stride·(count − 1) + size without overflow, which that reader computes unchecked.
fn extent_fits(accessor: &::gltf::Accessor<'_>) -> bool {
    let end = |offset: usize, stride: Option<usize>, count: usize, size: usize| {
        let last = count.checked_sub(1)?;
        offset.checked_add(stride.unwrap_or(size).checked_mul(last)?)?.checked_add(size)
    };
    let size = accessor.size();
    let stride = accessor.view().and_then(|v| v.stride());
    if end(accessor.offset(), stride, accessor.count(), size).is_none() {
        return false;
    }
    accessor.sparse().is_none_or(|sparse| {
        let (indices, values) = (sparse.indices(), sparse.values());
        let index_size = indices.index_type().size();
        end(indices.offset(), indices.view().stride(), sparse.count(), index_size).is_some()
            && end(values.offset(), values.view().stride(), sparse.count(), size).is_some()
    })
}

/// Why the `gltf` crate's reader cannot step through `accessor` (or its sparse indices and
/// values): a buffer view whose byte stride is less than the element it holds, which glTF 2.0
/// forbids (the validator's `ACCESSOR_SMALL_BYTESTRIDE`) and which that reader meets with an
/// assertion or reads past the element (found by fuzzing the scan readers).
fn stride_problem(accessor: &::gltf::Accessor<'_>) -> Option<String> {
    let small = |stride: Option<usize>, size: usize, what: &str| {
        stride.filter(|&s| s < size).map(|s| {
            format!("{what} has a byte stride of {s}, less than its element's {size} bytes")
        })
    };
    let size = accessor.size();
    small(accessor.view().and_then(|v| v.stride()), size, "buffer view").or_else(|| {
        accessor.sparse().and_then(|sparse| {
            let (indices, values) = (sparse.indices(), sparse.values());
            small(
                indices.view().stride(),
                indices.index_type().size(),
                "sparse indices' buffer view",
            )
            .or_else(|| small(values.view().stride(), size, "sparse values' buffer view"))
        })
    })
}

/// The meshes a glTF document draws, each with its node's world transform (glTF 2.0 §3.5.3:
/// the product of the transforms from the root down), depth first in document order: the
/// default scene's, or every scene's when none is the default, or every mesh untransformed
/// when the document has no scene at all. Shared by the mesh loader and the scan reader of
/// `hi-geomimage`.
///
/// # Errors
///
/// A message when the node hierarchy is deeper than 1024 (the glTF validator rejects cycles;
/// the cap guards the stack all the same).
///
/// # Examples
///
/// ```
/// let gltf = gltf::Gltf::from_slice(br#"{"asset":{"version":"2.0"},"scene":0,
///     "scenes":[{"nodes":[0]}],"nodes":[{"translation":[1,2,3],"children":[1]},{"mesh":0}],
///     "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
///     "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",
///         "min":[0,0,0],"max":[0,0,0]}],
///     "bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36}]}"#)
///     .unwrap();
/// let placed = hi_mesh::export::placed_meshes(&gltf.document).unwrap();
/// assert_eq!(placed.len(), 1);
/// assert_eq!(placed[0].1.w_axis.truncate(), glam::DVec3::new(1.0, 2.0, 3.0));
/// ```
pub fn placed_meshes(
    document: &::gltf::Document,
) -> Result<Vec<(::gltf::Mesh<'_>, DMat4)>, String> {
    Ok(placed_nodes(document)?.into_iter().map(|(_, mesh, world)| (mesh, world)).collect())
}

/// The meshes a glTF document draws as [`placed_meshes`] lists them, each with the node that
/// places it (`None` for the meshes of a document with no scene).
type Placed<'a> = (Option<::gltf::Node<'a>>, ::gltf::Mesh<'a>, DMat4);

fn placed_nodes(document: &::gltf::Document) -> Result<Vec<Placed<'_>>, String> {
    let mut instances = Vec::new();
    let scenes: Vec<::gltf::Scene<'_>> = match document.default_scene() {
        Some(s) => vec![s],
        None => document.scenes().collect(),
    };
    if scenes.is_empty() {
        instances.extend(document.meshes().map(|m| (None, m, DMat4::IDENTITY)));
    }
    for scene in scenes {
        // Depth first in document order: the stack holds siblings last first.
        let mut stack: Vec<(::gltf::Node<'_>, DMat4, usize)> =
            scene.nodes().map(|n| (n, DMat4::IDENTITY, 0)).collect();
        stack.reverse();
        while let Some((node, parent, depth)) = stack.pop() {
            if depth > 1024 {
                return Err("the node hierarchy is more than 1024 deep".to_owned());
            }
            let local = node.transform().matrix().map(|c| c.map(f64::from));
            let world = parent * DMat4::from_cols_array_2d(&local);
            if let Some(mesh) = node.mesh() {
                instances.push((Some(node.clone()), mesh, world));
            }
            let first = stack.len();
            stack.extend(node.children().map(|c| (c, world, depth + 1)));
            stack[first..].reverse();
        }
    }
    Ok(instances)
}

/// The triangles of a primitive drawn in `mode` from `indices` (glTF 2.0 §3.7.2.1):
/// `TRIANGLES` by threes (a remainder is left out), `TRIANGLE_STRIP` with every other
/// triangle's first two corners swapped so that all wind alike, `TRIANGLE_FAN` around the first
/// index; `None` for points and lines.
///
/// # Examples
///
/// ```
/// use gltf::mesh::Mode;
/// use hi_mesh::export::primitive_triangles;
///
/// let strip = primitive_triangles(Mode::TriangleStrip, &[0, 1, 2, 3]).unwrap();
/// assert_eq!(strip, [[0, 1, 2], [2, 1, 3]]);
/// assert_eq!(primitive_triangles(Mode::TriangleFan, &[0, 1, 2, 3]).unwrap(), [[0, 1, 2], [0, 2, 3]]);
/// assert_eq!(primitive_triangles(Mode::Lines, &[0, 1]), None);
/// ```
#[must_use]
pub fn primitive_triangles(mode: ::gltf::mesh::Mode, indices: &[u32]) -> Option<Vec<[u32; 3]>> {
    use ::gltf::mesh::Mode;
    Some(match mode {
        Mode::Triangles => indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
        Mode::TriangleStrip => indices
            .windows(3)
            .enumerate()
            .map(|(k, t)| if k % 2 == 0 { [t[0], t[1], t[2]] } else { [t[1], t[0], t[2]] })
            .collect(),
        Mode::TriangleFan => match indices.split_first() {
            Some((&first, rest)) => rest.windows(2).map(|t| [first, t[0], t[1]]).collect(),
            None => Vec::new(),
        },
        Mode::Points | Mode::Lines | Mode::LineLoop | Mode::LineStrip => return None,
    })
}

/// Reads a `.gltf` (with its buffers) or `.glb` file: the triangle primitives (`TRIANGLES`,
/// `TRIANGLE_STRIP`, `TRIANGLE_FAN`) of every mesh the scene places, concatenated in world space
/// (points and lines, such as the edges of
/// [`write_glb_with_edges`](super::write_glb_with_edges), are left out).
///
/// The scene is the default one, or every scene when there is none (a file with no scene at
/// all has its meshes read as they are). Each node's world transform is applied to its mesh's
/// positions, and its inverse transpose to the normals (renormalised); a transform that mirrors
/// (negative determinant) reverses the triangles' winding, as the glTF 2.0 specification says
/// (§3.7.4). A primitive without `NORMAL` gets flat normals, as the specification asks of a client
/// (§3.7.2.1): each triangle its own normal, its corners not shared with its neighbours. A
/// primitive without `TEXCOORD_0` gets UV (0, 0). Vertex colours are kept when every primitive
/// has them.
pub(in crate::export) fn read_gltf(path: &Path) -> Result<TriangleMesh, Error> {
    let (document, buffers) = open(path)?;
    let mut all = MeshBuilder::default();
    for (_, mesh, world) in &placed_nodes(&document).map_err(|e| format_error(e, Some(path)))? {
        append_mesh(mesh, world, &buffers, &mut all)?;
    }
    if all.is_empty() {
        return Err(format_error("glTF file has no triangles", None));
    }
    all.finish()
}

/// Reads a `.gltf` or `.glb` file as [`read_gltf`] does, one mesh per node that places a mesh
/// with triangles, in the order [`placed_meshes`] lists them, each named by its node, or by
/// its mesh when the node has no name, or `mesh_k` for the k-th mesh of the file when neither
/// has one.
pub(in crate::export) fn read_gltf_scene(
    path: &Path,
) -> Result<Vec<(String, TriangleMesh)>, Error> {
    let (document, buffers) = open(path)?;
    let mut parts = Vec::new();
    for (node, mesh, world) in &placed_nodes(&document).map_err(|e| format_error(e, Some(path)))? {
        let mut part = MeshBuilder::default();
        append_mesh(mesh, world, &buffers, &mut part)?;
        if part.is_empty() {
            continue;
        }
        let name = [node.as_ref().and_then(::gltf::Node::name), mesh.name()]
            .into_iter()
            .flatten()
            .find(|n| !n.is_empty())
            .map_or_else(|| format!("mesh_{}", mesh.index()), str::to_owned);
        parts.push((name, part.finish()?));
    }
    if parts.is_empty() {
        return Err(format_error("glTF file has no triangles", None));
    }
    Ok(parts)
}

/// The document of a `.gltf` or `.glb` file and its buffers' data.
fn open(path: &Path) -> Result<(::gltf::Document, Vec<::gltf::buffer::Data>), Error> {
    let bytes = std::fs::read(path).map_err(|e| io_error(&e, Some(path)))?;
    let ::gltf::Gltf { document, blob } =
        parse_gltf(&bytes).map_err(|e| crate::export::at_path(e, path))?;
    let buffers = ::gltf::import_buffers(&document, path.parent(), blob)
        .map_err(|e| gltf_error(e, Some(path)))?;
    Ok((document, buffers))
}

/// Appends the triangle primitives of `mesh`, placed by `world`, to `out`.
fn append_mesh(
    mesh: &::gltf::Mesh<'_>,
    world: &DMat4,
    buffers: &[::gltf::buffer::Data],
    out: &mut MeshBuilder,
) -> Result<(), Error> {
    let normal_matrix = DMat3::from_mat4(*world).inverse().transpose();
    let mirrors = world.determinant() < 0.0;
    for primitive in mesh.primitives() {
        use ::gltf::mesh::Mode;
        // Points and lines (an edge overlay, as `write_glb_with_edges` writes) bound no
        // surface: the triangle mesh is the other primitives.
        if !matches!(primitive.mode(), Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan) {
            continue;
        }
        if let Some(problem) = accessor_problem(&primitive) {
            return Err(format_error(format!("glTF: {problem}"), None));
        }
        let reader = primitive.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
        let p: Vec<DVec3> = reader
            .read_positions()
            .ok_or_else(|| format_error("a primitive has no POSITION", None))?
            .map(|p| world.transform_point3(Vec3::from(p).as_dvec3()))
            .collect();
        let n = p.len();
        let nrm: Option<Vec<DVec3>> = reader.read_normals().map(|it| {
            it.map(|v| {
                let n = Vec3::from(v).as_dvec3();
                // Untransformed normals are kept bit for bit (a written file reads back
                // exactly); transformed ones are unit again.
                if *world == DMat4::IDENTITY {
                    n
                } else {
                    (normal_matrix * n).normalize_or(DVec3::Z)
                }
            })
            .collect()
        });
        let uv: Vec<DVec2> = match reader.read_tex_coords(0) {
            Some(t) => t.into_f32().map(|t| glam::Vec2::from(t).as_dvec2()).collect(),
            None => vec![DVec2::ZERO; n],
        };
        let col: Option<Vec<[f32; 3]>> = reader.read_colors(0).map(|c| c.into_rgb_f32().collect());
        if nrm.as_ref().is_some_and(|v| v.len() != n)
            || uv.len() != n
            || col.as_ref().is_some_and(|c| c.len() != n)
        {
            return Err(format_error("attribute counts differ within a primitive", None));
        }
        let idx: Vec<u32> = match reader.read_indices() {
            Some(i) => i.into_u32().collect(),
            None => (0..u32::try_from(n).map_err(|_| format_error("too many vertices", None))?)
                .collect(),
        };
        if idx.iter().any(|&k| k as usize >= n) {
            return Err(format_error("an index is beyond the primitive's vertices", None));
        }
        if primitive.mode() == Mode::Triangles && !idx.len().is_multiple_of(3) {
            return Err(format_error("index count is not a multiple of 3", None));
        }
        let mut tris = primitive_triangles(primitive.mode(), &idx).unwrap_or_default();
        if mirrors {
            tris.iter_mut().for_each(|t| t.swap(1, 2));
        }
        let base = out.next_vertex()?;
        if col.is_none() {
            out.uncolored = true;
        }
        match nrm {
            Some(nrm) => {
                out.positions.extend(p);
                out.normals.extend(nrm);
                out.uvs.extend(uv);
                out.colors.extend(col.into_iter().flatten());
                out.triangles.extend(tris.iter().map(|t| t.map(|k| k.saturating_add(base))));
            }
            None => {
                // Flat normals: every corner its own vertex with its triangle's normal.
                for (f, t) in tris.iter().enumerate() {
                    let [a, b, c] = t.map(|k| p[k as usize]);
                    let normal = (b - a).cross(c - a).normalize_or(DVec3::Z);
                    for &k in t {
                        out.positions.push(p[k as usize]);
                        out.normals.push(normal);
                        out.uvs.push(uv[k as usize]);
                        if let Some(c) = &col {
                            out.colors.push(c[k as usize]);
                        }
                    }
                    let first = base.saturating_add(u32::try_from(3 * f).unwrap_or(u32::MAX));
                    out.triangles.push([first, first.saturating_add(1), first.saturating_add(2)]);
                }
            }
        }
    }
    Ok(())
}
