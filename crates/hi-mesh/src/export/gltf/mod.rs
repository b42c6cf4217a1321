// SPDX-License-Identifier: MIT
//! glTF 2.0, as JSON with a binary buffer beside it or as one `.glb`, built with `gltf-json`
//! (the surface as polygons for other software, Hardy 2005, §5.5) and read back with
//! `gltf::import`.
//!
//! This module writes; `read` reads back.

mod read;

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::io::Write;
use std::path::Path;

use ::gltf::json;
use glam::Vec3;
use json::validation::Checked::Valid;
use json::validation::USize64;

use super::{GENERATOR, NamedMesh, check_scene, format_error, io_error};
use crate::{Error, TriangleMesh};

pub use read::{accessor_problem, parse_gltf, placed_meshes, primitive_triangles};
pub(super) use read::{read_gltf, read_gltf_scene};

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

    // TEXCOORD_0 only for a mesh with texture coordinates: one with every UV at the origin
    // (`TriangleMesh::from_triangles`, a subdivided polygon mesh) has none, and a reader gives
    // a primitive without them UV (0, 0), as the mesh had.
    if mesh.uvs().iter().any(|t| *t != glam::DVec2::ZERO) {
        let start = bin.len();
        push_f32s(bin, mesh.uvs().iter().flat_map(|t| t.as_vec2().to_array()));
        let view = push_view(root, buffer, bin, start, Target::ArrayBuffer);
        let acc = root.push(accessor(view, n, ComponentType::F32, Type::Vec2, None));
        attributes.insert(Valid(json::mesh::Semantic::TexCoords(0)), acc);
    }

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

fn gltf_error(e: ::gltf::Error, path: Option<&Path>) -> Error {
    match e {
        ::gltf::Error::Io(e) => io_error(&e, path),
        other => format_error(format!("glTF: {other}"), path),
    }
}
