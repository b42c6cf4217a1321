// SPDX-License-Identifier: MIT
//! glTF 2.0, as JSON with a binary buffer beside it or as one `.glb`, built with `gltf-json`
//! (the surface as polygons for other software, Hardy 2005, §5.5) and read back with
//! `gltf::import`.

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::io::Write;
use std::path::Path;

use ::gltf::json;
use glam::{DMat3, DMat4, DVec2, DVec3, Vec3};
use json::validation::Checked::Valid;
use json::validation::USize64;

use super::{GENERATOR, MeshBuilder, NamedMesh, check_scene, format_error, io_error};
use crate::{Error, TriangleMesh};

/// Largest vertex count written with `u16` indices: 65 535 itself is the primitive-restart
/// value, which glTF forbids in indices.
const MAX_U16_VERTICES: usize = u16::MAX as usize;

/// The JSON document and its one binary buffer.
struct Encoded {
    root: json::Root,
    bin: Vec<u8>,
}

fn push_f32s(bin: &mut Vec<u8>, values: impl IntoIterator<Item = f32>) {
    for x in values {
        bin.extend_from_slice(&x.to_le_bytes());
    }
}

/// Appends a buffer view of `bin[start..]` (padding `bin` to 4 bytes after it).
fn push_view(
    root: &mut json::Root,
    buffer: json::Index<json::Buffer>,
    bin: &mut Vec<u8>,
    start: usize,
    target: json::buffer::Target,
) -> json::Index<json::buffer::View> {
    let view = root.push(json::buffer::View {
        buffer,
        byte_length: USize64::from(bin.len() - start),
        byte_offset: Some(USize64::from(start)),
        byte_stride: None,
        extensions: None,
        extras: Default::default(),
        name: None,
        target: Some(Valid(target)),
    });
    bin.resize(bin.len().next_multiple_of(4), 0);
    view
}

fn accessor(
    view: json::Index<json::buffer::View>,
    count: usize,
    component: json::accessor::ComponentType,
    type_: json::accessor::Type,
    bounds: Option<([f32; 3], [f32; 3])>,
) -> json::Accessor {
    json::Accessor {
        buffer_view: Some(view),
        byte_offset: Some(USize64(0)),
        count: USize64::from(count),
        component_type: Valid(json::accessor::GenericComponentType(component)),
        extensions: None,
        extras: Default::default(),
        type_: Valid(type_),
        min: bounds.map(|(lo, _)| json::Value::from(lo.to_vec())),
        max: bounds.map(|(_, hi)| json::Value::from(hi.to_vec())),
        name: None,
        normalized: false,
        sparse: None,
    }
}

/// A part of a glTF scene: its name, its mesh, and the lines drawn over it (pairs of vertex
/// indices, checked in range by the caller; none for a scene's parts).
pub(super) type Part<'a> = (NamedMesh<'a>, &'a [[u32; 2]]);

/// The parts of a scene, with no lines.
pub(super) fn unedged<'a>(parts: &[NamedMesh<'a>]) -> Vec<Part<'a>> {
    parts.iter().map(|&p| (p, &[][..])).collect()
}

/// The accessors of one part's mesh.
struct PartAccessors {
    attributes:
        BTreeMap<json::validation::Checked<json::mesh::Semantic>, json::Index<json::Accessor>>,
    positions: json::Index<json::Accessor>,
    indices: json::Index<json::Accessor>,
    /// The lines' indices, when the part has lines.
    edges: Option<json::Index<json::Accessor>>,
}

/// Appends the views and accessors of `mesh` (and of `edges` over it, if any) to `root` and
/// `bin`.
fn push_part(
    root: &mut json::Root,
    buffer: json::Index<json::Buffer>,
    bin: &mut Vec<u8>,
    mesh: &TriangleMesh,
    edges: &[[u32; 2]],
) -> PartAccessors {
    use json::accessor::{ComponentType, Type};
    use json::buffer::Target;

    let n = mesh.n_vertices();
    let mut attributes = BTreeMap::new();

    // POSITION, with min and max of the f32 values actually written.
    let positions: Vec<Vec3> = mesh.positions().iter().map(|p| p.as_vec3()).collect();
    let (lo, hi) = positions
        .iter()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let start = bin.len();
    push_f32s(bin, positions.iter().flat_map(|p| p.to_array()));
    let view = push_view(root, buffer, bin, start, Target::ArrayBuffer);
    let acc = root.push(accessor(
        view,
        n,
        ComponentType::F32,
        Type::Vec3,
        Some((lo.to_array(), hi.to_array())),
    ));
    attributes.insert(Valid(json::mesh::Semantic::Positions), acc);
    let positions_accessor = acc;

    let start = bin.len();
    push_f32s(bin, mesh.normals().iter().flat_map(|v| v.as_vec3().to_array()));
    let view = push_view(root, buffer, bin, start, Target::ArrayBuffer);
    let acc = root.push(accessor(view, n, ComponentType::F32, Type::Vec3, None));
    attributes.insert(Valid(json::mesh::Semantic::Normals), acc);

    let start = bin.len();
    push_f32s(bin, mesh.uvs().iter().flat_map(|t| t.as_vec2().to_array()));
    let view = push_view(root, buffer, bin, start, Target::ArrayBuffer);
    let acc = root.push(accessor(view, n, ComponentType::F32, Type::Vec2, None));
    attributes.insert(Valid(json::mesh::Semantic::TexCoords(0)), acc);

    if let Some(colors) = mesh.colors() {
        let start = bin.len();
        push_f32s(bin, colors.iter().flatten().copied());
        let view = push_view(root, buffer, bin, start, Target::ArrayBuffer);
        let acc = root.push(accessor(view, n, ComponentType::F32, Type::Vec3, None));
        attributes.insert(Valid(json::mesh::Semantic::Colors(0)), acc);
    }

    let start = bin.len();
    let component = if n <= MAX_U16_VERTICES {
        for &k in mesh.triangles().iter().flatten() {
            // k < n ≤ 65 535.
            bin.extend_from_slice(&(k as u16).to_le_bytes());
        }
        ComponentType::U16
    } else {
        for &k in mesh.triangles().iter().flatten() {
            bin.extend_from_slice(&k.to_le_bytes());
        }
        ComponentType::U32
    };
    let view = push_view(root, buffer, bin, start, Target::ElementArrayBuffer);
    let indices = root.push(accessor(view, 3 * mesh.n_triangles(), component, Type::Scalar, None));
    let edges = (!edges.is_empty()).then(|| {
        let start = bin.len();
        for &k in edges.iter().flatten() {
            if component == ComponentType::U16 {
                // k < n ≤ 65 535.
                bin.extend_from_slice(&(k as u16).to_le_bytes());
            } else {
                bin.extend_from_slice(&k.to_le_bytes());
            }
        }
        let view = push_view(root, buffer, bin, start, Target::ElementArrayBuffer);
        root.push(accessor(view, 2 * edges.len(), component, Type::Scalar, None))
    });
    PartAccessors { attributes, positions: positions_accessor, indices, edges }
}

/// The glTF document and buffer of a scene: one buffer holding every part's data, part after
/// part; one mesh per part with its own accessors (a primitive of triangles, and one of lines
/// when the part has lines), one node per part named as its mesh, one scene of all the nodes.
/// `uri` is the buffer's URI (`None` for `.glb`).
fn encode(parts: &[Part<'_>], uri: Option<String>) -> Encoded {
    let mut root = json::Root::default();
    root.asset.generator = Some(GENERATOR.to_string());
    let buffer = root.push(json::Buffer {
        byte_length: USize64(0), // set below, once the buffer is complete
        extensions: None,
        extras: Default::default(),
        name: None,
        uri,
    });
    let size: usize =
        parts.iter().map(|(p, _)| p.mesh.n_vertices() * 44 + p.mesh.n_triangles() * 12).sum();
    let mut bin = Vec::with_capacity(size);
    let accessors: Vec<PartAccessors> = parts
        .iter()
        .map(|(part, edges)| push_part(&mut root, buffer, &mut bin, part.mesh, edges))
        .collect();
    root.buffers[buffer.value()].byte_length = USize64::from(bin.len());

    let material = root.push(json::Material {
        name: Some("harmonic surface".to_string()),
        // A window of a closed surface is open, and seen from both sides.
        double_sided: true,
        pbr_metallic_roughness: json::material::PbrMetallicRoughness {
            metallic_factor: json::material::StrengthFactor(0.0),
            roughness_factor: json::material::StrengthFactor(0.6),
            ..Default::default()
        },
        ..Default::default()
    });
    let mut dark = None;
    let mut meshes = Vec::with_capacity(parts.len());
    for ((part, _), acc) in parts.iter().zip(accessors) {
        let mut primitives = vec![json::mesh::Primitive {
            attributes: acc.attributes,
            extensions: None,
            extras: Default::default(),
            indices: Some(acc.indices),
            material: Some(material),
            mode: Valid(json::mesh::Mode::Triangles),
            targets: None,
        }];
        if let Some(edge_indices) = acc.edges {
            let dark = *dark.get_or_insert_with(|| {
                root.push(json::Material {
                    name: Some("edges".to_string()),
                    pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                        base_color_factor: json::material::PbrBaseColorFactor([
                            0.02, 0.02, 0.02, 1.0,
                        ]),
                        metallic_factor: json::material::StrengthFactor(0.0),
                        ..Default::default()
                    },
                    ..Default::default()
                })
            });
            primitives.push(json::mesh::Primitive {
                attributes: BTreeMap::from([(
                    Valid(json::mesh::Semantic::Positions),
                    acc.positions,
                )]),
                extensions: None,
                extras: Default::default(),
                indices: Some(edge_indices),
                material: Some(dark),
                mode: Valid(json::mesh::Mode::Lines),
                targets: None,
            });
        }
        let mesh_index = root.push(json::Mesh {
            extensions: None,
            extras: Default::default(),
            name: Some(part.name.to_string()),
            primitives,
            weights: None,
        });
        meshes.push(mesh_index);
    }
    let nodes = meshes
        .into_iter()
        .zip(parts)
        .map(|(mesh, (part, _))| {
            root.push(json::Node {
                mesh: Some(mesh),
                name: Some(part.name.to_string()),
                ..Default::default()
            })
        })
        .collect();
    let scene =
        root.push(json::Scene { extensions: None, extras: Default::default(), name: None, nodes });
    root.scene = Some(scene);
    Encoded { root, bin }
}

/// Writes `mesh` as glTF 2.0 JSON to `gltf` and its binary buffer to `bin`; `bin_uri` is the
/// buffer's URI as it goes into the JSON, relative to the JSON file and already
/// percent-encoded (e.g. `surface.bin`). [`super::save`] picks the name and encodes it.
///
/// # Errors
///
/// [`Error::Io`](crate::Error::Io) when writing fails.
///
/// # Examples
///
/// ```
/// use glam::{DVec2, DVec3};
/// use hi_mesh::{TriangleMesh, export};
///
/// // One unit square of two triangles, facing +z.
/// let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
/// let uv = p.iter().map(|q| q.truncate()).collect::<Vec<DVec2>>();
/// let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 4], uv, vec![[0, 1, 2], [0, 2, 3]])?;
/// let (mut json, mut bin) = (Vec::new(), Vec::new());
/// export::write_gltf(&mesh, &mut json, &mut bin, "square.bin")?;
/// let text = String::from_utf8(json).unwrap();
/// assert!(text.contains("\"uri\": \"square.bin\"") && text.contains("\"generator\": \"harmonic"));
/// // Positions, normals, UVs (12 + 12 + 8 bytes per vertex), six u16 indices.
/// assert_eq!(bin.len(), 4 * 32 + 12);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn write_gltf<W: Write, B: Write>(
    mesh: &TriangleMesh,
    gltf: W,
    bin: B,
    bin_uri: &str,
) -> Result<(), Error> {
    write_gltf_parts(&[(NamedMesh::new(SINGLE_NAME, mesh), &[])], gltf, bin, bin_uri)
}

/// Writes the parts of a scene as glTF 2.0 JSON to `gltf` and their one binary buffer to
/// `bin`, as [`write_gltf`] writes one mesh: one mesh per part with its own accessors, one node
/// per part named as its mesh, one scene of all the nodes, in the order of `parts`.
///
/// # Errors
///
/// Those of [`check_part_names`](super::check_part_names) (no parts, a name empty, repeated
/// or not printable on one line); [`Error::Io`](crate::Error::Io) when writing fails.
///
/// # Examples
///
/// ```
/// use hi_mesh::export::{self, NamedMesh};
/// use hi_mesh::PolyMesh;
///
/// let (cube, octahedron) =
///     (PolyMesh::cube().to_triangle_mesh()?, PolyMesh::octahedron().to_triangle_mesh()?);
/// let parts = [NamedMesh::new("cube", &cube), NamedMesh::new("octahedron", &octahedron)];
/// let (mut json, mut bin) = (Vec::new(), Vec::new());
/// export::write_scene_gltf(&parts, &mut json, &mut bin, "shapes.bin")?;
/// let doc = gltf::Gltf::from_slice(&json).unwrap();
/// let names: Vec<_> = doc.nodes().map(|n| n.name().unwrap()).collect();
/// assert_eq!(names, ["cube", "octahedron"]);
/// assert_eq!(doc.buffers().count(), 1);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn write_scene_gltf<W: Write, B: Write>(
    parts: &[NamedMesh<'_>],
    gltf: W,
    bin: B,
    bin_uri: &str,
) -> Result<(), Error> {
    check_scene(parts)?;
    write_gltf_parts(&unedged(parts), gltf, bin, bin_uri)
}

/// The mesh and node name of a single mesh written as glTF.
const SINGLE_NAME: &str = super::SINGLE_GLTF_NAME;

/// Writes `parts` (names not checked) as glTF JSON and its buffer: the one writer behind
/// [`write_gltf`], [`write_scene_gltf`] and [`super::save`].
pub(super) fn write_gltf_parts<W: Write, B: Write>(
    parts: &[Part<'_>],
    mut gltf: W,
    mut bin: B,
    bin_uri: &str,
) -> Result<(), Error> {
    let Encoded { root, bin: data } = encode(parts, Some(bin_uri.to_string()));
    let text = json::serialize::to_vec_pretty(&root)
        .map_err(|e| format_error(format!("glTF JSON: {e}"), None))?;
    gltf.write_all(&text).and_then(|()| gltf.flush()).map_err(|e| io_error(&e, None))?;
    bin.write_all(&data).and_then(|()| bin.flush()).map_err(|e| io_error(&e, None))
}

/// Writes `mesh` as binary glTF 2.0 (`.glb`: a JSON chunk and a BIN chunk).
///
/// # Errors
///
/// [`Error::InvalidCount`] if the file would exceed the 4 GiB limit of the format;
/// [`Error::Io`](crate::Error::Io) when writing fails.
///
/// # Examples
///
/// ```
/// use glam::{DVec2, DVec3};
/// use hi_mesh::{TriangleMesh, export};
///
/// // One unit square of two triangles, facing +z.
/// let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
/// let uv = p.iter().map(|q| q.truncate()).collect::<Vec<DVec2>>();
/// let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 4], uv, vec![[0, 1, 2], [0, 2, 3]])?;
/// let mut glb = Vec::new();
/// export::write_glb(&mesh, &mut glb)?;
/// assert_eq!(&glb[..4], b"glTF");
/// assert_eq!(u32::from_le_bytes(glb[8..12].try_into().unwrap()) as usize, glb.len());
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn write_glb<W: Write>(mesh: &TriangleMesh, writer: W) -> Result<(), Error> {
    write_glb_with_edges(mesh, &[], writer)
}

/// Writes `mesh` as binary glTF 2.0 as [`write_glb`] does, with `edges` (pairs of vertex
/// indices: a polygon mesh's edges, say, which its triangles do not show) as a second
/// primitive of the mesh, of mode `LINES`, on the same positions, in a dark material; glTF
/// viewers draw them over the surface. No edges: the file of [`write_glb`].
///
/// # Errors
///
/// [`Error::InvalidCount`] for an edge's vertex index out of range; as [`write_glb`].
///
/// # Examples
///
/// ```
/// use glam::{DVec2, DVec3};
/// use hi_mesh::{TriangleMesh, export};
///
/// // One unit square of two triangles, facing +z.
/// let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
/// let uv = p.iter().map(|q| q.truncate()).collect::<Vec<DVec2>>();
/// let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 4], uv, vec![[0, 1, 2], [0, 2, 3]])?;
/// let mut glb = Vec::new();
/// export::write_glb_with_edges(&mesh, &[[0, 1], [1, 2]], &mut glb)?;
/// let (doc, _, _) = gltf::import_slice(&glb).unwrap();
/// let modes: Vec<_> = doc.meshes().next().unwrap().primitives().map(|p| p.mode()).collect();
/// assert_eq!(modes, [gltf::mesh::Mode::Triangles, gltf::mesh::Mode::Lines]);
/// assert!(export::write_glb_with_edges(&mesh, &[[0, 999]], Vec::new()).is_err());
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn write_glb_with_edges<W: Write>(
    mesh: &TriangleMesh,
    edges: &[[u32; 2]],
    writer: W,
) -> Result<(), Error> {
    if let Some(&bad) = edges.iter().flatten().find(|&&k| k as usize >= mesh.n_vertices()) {
        return Err(Error::InvalidCount {
            what: "edge vertex index",
            value: bad as usize,
            expected: "less than the number of vertices",
        });
    }
    write_glb_parts(&[(NamedMesh::new(SINGLE_NAME, mesh), edges)], writer)
}

/// Writes the parts of a scene as binary glTF 2.0 (`.glb`), laid out as [`write_scene_gltf`]
/// lays them out.
///
/// # Errors
///
/// Those of [`check_part_names`](super::check_part_names) (no parts, a name empty, repeated
/// or not printable on one line); as [`write_glb`].
///
/// # Examples
///
/// ```
/// use hi_mesh::export::{self, NamedMesh};
/// use hi_mesh::PolyMesh;
///
/// let cube = PolyMesh::cube().to_triangle_mesh()?;
/// let mut glb = Vec::new();
/// let parts = [NamedMesh::new("pot", &cube), NamedMesh::new("lid", &cube)];
/// export::write_scene_glb(&parts, &mut glb)?;
/// let (doc, _, _) = gltf::import_slice(&glb).unwrap();
/// let names: Vec<_> = doc.meshes().map(|m| m.name().unwrap()).collect();
/// assert_eq!(names, ["pot", "lid"]);
/// // A name must be unique: the error says which part repeats which.
/// let err = export::write_scene_glb(&[NamedMesh::new("lid", &cube); 2], Vec::new()).unwrap_err();
/// let message = "scene part 1 (\"lid\"): its name is that of part 0";
/// assert!(err.to_string().starts_with(message), "{err}");
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn write_scene_glb<W: Write>(parts: &[NamedMesh<'_>], writer: W) -> Result<(), Error> {
    check_scene(parts)?;
    write_glb_parts(&unedged(parts), writer)
}

/// Writes `parts` (names and edges not checked) as GLB: the one writer behind [`write_glb`],
/// [`write_glb_with_edges`], [`write_scene_glb`] and [`super::save`].
pub(super) fn write_glb_parts<W: Write>(parts: &[Part<'_>], mut writer: W) -> Result<(), Error> {
    let Encoded { root, bin } = encode(parts, None);
    let text = json::serialize::to_vec(&root)
        .map_err(|e| format_error(format!("glTF JSON: {e}"), None))?;
    // Header, JSON chunk and BIN chunk, each chunk padded to 4 bytes.
    let length = 12 + 8 + text.len().next_multiple_of(4) + 8 + bin.len();
    let length = u32::try_from(length).map_err(|_| Error::InvalidCount {
        what: "size of the GLB file in bytes",
        value: length,
        expected: "less than 2^32",
    })?;
    let glb = ::gltf::binary::Glb {
        header: ::gltf::binary::Header { magic: *b"glTF", version: 2, length },
        json: Cow::Owned(text),
        bin: Some(Cow::Borrowed(&bin)),
    };
    glb.to_writer(&mut writer).map_err(|e| gltf_error(e, None))?;
    writer.flush().map_err(|e| io_error(&e, None))
}

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

fn gltf_error(e: ::gltf::Error, path: Option<&Path>) -> Error {
    match e {
        ::gltf::Error::Io(e) => io_error(&e, path),
        other => format_error(format!("glTF: {other}"), path),
    }
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
/// (points and lines, such as the edges of [`write_glb_with_edges`], are left out).
///
/// The scene is the default one, or every scene when there is none (a file with no scene at
/// all has its meshes read as they are). Each node's world transform is applied to its mesh's
/// positions, and its inverse transpose to the normals (renormalised); a transform that mirrors
/// (negative determinant) reverses the triangles' winding, as the glTF 2.0 specification says
/// (§3.7.4). A primitive without `NORMAL` gets flat normals, as the specification asks of a client
/// (§3.7.2.1): each triangle its own normal, its corners not shared with its neighbours. A
/// primitive without `TEXCOORD_0` gets UV (0, 0). Vertex colours are kept when every primitive
/// has them.
pub(super) fn read_gltf(path: &Path) -> Result<TriangleMesh, Error> {
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
pub(super) fn read_gltf_scene(path: &Path) -> Result<Vec<(String, TriangleMesh)>, Error> {
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
        parse_gltf(&bytes).map_err(|e| super::at_path(e, path))?;
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
