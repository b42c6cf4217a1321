// SPDX-License-Identifier: MIT
//! Stanford PLY: ASCII, binary little-endian and binary big-endian; `vertex` positions and
//! normals, `face` lists and `tristrips`; every other element is read past.

use glam::DVec3;

use super::text::{lines, show, tokens};
use super::{Scan, ScanFormat};
use crate::Error;

const F: ScanFormat = ScanFormat::Ply;

/// The storage of a PLY file's body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Encoding {
    Ascii,
    Little,
    Big,
}

/// A PLY scalar type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(name: &[u8]) -> Option<Self> {
        Some(match name {
            b"char" | b"int8" => Self::I8,
            b"uchar" | b"uint8" => Self::U8,
            b"short" | b"int16" => Self::I16,
            b"ushort" | b"uint16" => Self::U16,
            b"int" | b"int32" => Self::I32,
            b"uint" | b"uint32" => Self::U32,
            b"float" | b"float32" => Self::F32,
            b"double" | b"float64" => Self::F64,
            _ => return None,
        })
    }

    const fn size(self) -> usize {
        match self {
            Self::I8 | Self::U8 => 1,
            Self::I16 | Self::U16 => 2,
            Self::I32 | Self::U32 | Self::F32 => 4,
            Self::F64 => 8,
        }
    }

    const fn is_integer(self) -> bool {
        !matches!(self, Self::F32 | Self::F64)
    }
}

/// A property of an element: a scalar, or a list (count type, item type).
#[derive(Clone, Debug)]
enum Property {
    Scalar(Scalar, Vec<u8>),
    List(Scalar, Scalar, Vec<u8>),
}

impl Property {
    fn name(&self) -> &[u8] {
        match self {
            Self::Scalar(_, n) | Self::List(_, _, n) => n,
        }
    }
}

/// An element declared in the header.
#[derive(Clone, Debug)]
struct Element {
    name: Vec<u8>,
    count: usize,
    properties: Vec<Property>,
    line: usize,
}

/// The header: encoding, elements, and where the body starts.
struct Header {
    encoding: Encoding,
    elements: Vec<Element>,
    body: usize,
    body_line: usize,
}

fn header(bytes: &[u8]) -> Result<Header, Error> {
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    let mut offset = 0;
    for (n, line) in lines(bytes) {
        // Offset of the next line: this line, its '\r' if any, and '\n'.
        let raw_len = bytes[offset..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len() - offset, |p| p + 1);
        offset += raw_len;
        let mut it = tokens(line, false);
        let keyword = it.next().unwrap_or_default();
        if n == 1 {
            if keyword != b"ply" || it.next().is_some() {
                return Err(Error::line(F, 1, "the file does not start with the line `ply`"));
            }
            continue;
        }
        match keyword {
            b"format" => {
                let kind = it.next().unwrap_or_default();
                encoding = Some(match kind {
                    b"ascii" => Encoding::Ascii,
                    b"binary_little_endian" => Encoding::Little,
                    b"binary_big_endian" => Encoding::Big,
                    _ => {
                        return Err(Error::line(F, n, format!("unknown format {:?}", show(kind))));
                    }
                });
                if it.next() != Some(b"1.0".as_slice()) {
                    return Err(Error::line(F, n, "expected format version 1.0"));
                }
            }
            b"comment" | b"obj_info" | b"" => {}
            b"element" => {
                let name = it.next().unwrap_or_default().to_vec();
                let count = it
                    .next()
                    .and_then(|t| std::str::from_utf8(t).ok()?.parse::<usize>().ok())
                    .ok_or_else(|| Error::line(F, n, "`element` needs a name and a count"))?;
                elements.push(Element { name, count, properties: Vec::new(), line: n });
            }
            b"property" => {
                let Some(element) = elements.last_mut() else {
                    return Err(Error::line(F, n, "`property` before any `element`"));
                };
                let kind = it.next().unwrap_or_default();
                let property = if kind == b"list" {
                    let count = it.next().and_then(Scalar::parse);
                    let item = it.next().and_then(Scalar::parse);
                    let name = it.next();
                    match (count, item, name) {
                        (Some(c), Some(i), Some(name)) if c.is_integer() => {
                            Property::List(c, i, name.to_vec())
                        }
                        _ => {
                            return Err(Error::line(
                                F,
                                n,
                                "expected `property list <integer type> <type> <name>`",
                            ));
                        }
                    }
                } else {
                    match (Scalar::parse(kind), it.next()) {
                        (Some(s), Some(name)) => Property::Scalar(s, name.to_vec()),
                        _ => {
                            return Err(Error::line(
                                F,
                                n,
                                format!("unknown property type {:?}", show(kind)),
                            ));
                        }
                    }
                };
                element.properties.push(property);
            }
            b"end_header" => {
                let encoding = encoding
                    .ok_or_else(|| Error::line(F, n, "`end_header` before any `format` line"))?;
                return Ok(Header { encoding, elements, body: offset, body_line: n + 1 });
            }
            other => {
                return Err(Error::line(F, n, format!("unknown header keyword {:?}", show(other))));
            }
        }
    }
    Err(Error::file(F, "the header has no `end_header` line"))
}

/// Reads the scalars of the body, in ASCII (tokens, with their line numbers) or binary.
enum Body<'a> {
    Ascii { tokens: Box<dyn Iterator<Item = (usize, &'a [u8])> + 'a>, line: usize },
    Binary { bytes: &'a [u8], at: usize, big: bool },
}

impl Body<'_> {
    fn error(&self, message: impl Into<String>) -> Error {
        match self {
            Self::Ascii { line, .. } => Error::line(F, *line, message),
            Self::Binary { at, .. } => Error::byte(F, *at, message),
        }
    }

    fn read(&mut self, t: Scalar) -> Result<f64, Error> {
        match self {
            Self::Ascii { tokens, line } => {
                let Some((n, token)) = tokens.next() else {
                    return Err(Error::file(
                        F,
                        "the file ends before the data the header announces",
                    ));
                };
                *line = n;
                let text = std::str::from_utf8(token).ok();
                let value = if t.is_integer() {
                    text.and_then(|s| s.parse::<i64>().ok()).map(|v| v as f64)
                } else {
                    text.and_then(|s| s.parse::<f64>().ok())
                };
                value.ok_or_else(|| {
                    Error::line(F, n, format!("{:?} is not a {t:?} value", show(token)))
                })
            }
            Self::Binary { bytes, at, big } => {
                let size = t.size();
                let Some(raw) = bytes.get(*at..*at + size) else {
                    return Err(Error::byte(
                        F,
                        *at,
                        "the file ends before the data the header announces",
                    ));
                };
                let mut b = [0u8; 8];
                b[..size].copy_from_slice(raw);
                if *big {
                    b[..size].reverse();
                }
                *at += size;
                Ok(match t {
                    Scalar::I8 => f64::from(i8::from_le_bytes([b[0]])),
                    Scalar::U8 => f64::from(b[0]),
                    Scalar::I16 => f64::from(i16::from_le_bytes([b[0], b[1]])),
                    Scalar::U16 => f64::from(u16::from_le_bytes([b[0], b[1]])),
                    Scalar::I32 => f64::from(i32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                    Scalar::U32 => f64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                    Scalar::F32 => f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                    Scalar::F64 => f64::from_le_bytes(b),
                })
            }
        }
    }

    /// Reads a list's length (an integer type, so the value is whole).
    fn length(&mut self, t: Scalar) -> Result<usize, Error> {
        let v = self.read(t)?;
        if v < 0.0 {
            return Err(self.error(format!("negative list length {v}")));
        }
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a whole number in 0..2³²"
        )]
        Ok(v as usize)
    }
}

/// Reads a PLY file.
pub(super) fn parse(bytes: &[u8]) -> Result<Scan, Error> {
    let h = header(bytes)?;
    let vertex = h.elements.iter().find(|e| e.name == b"vertex");
    let Some(vertex) = vertex else {
        return Err(Error::file(F, "the header declares no `vertex` element"));
    };
    let position = |name: &[u8]| vertex.properties.iter().position(|p| p.name() == name);
    let (Some(x), Some(y), Some(z)) = (position(b"x"), position(b"y"), position(b"z")) else {
        return Err(Error::line(F, vertex.line, "the `vertex` element lacks x, y or z"));
    };
    let normal = match (position(b"nx"), position(b"ny"), position(b"nz")) {
        (Some(a), Some(b), Some(c)) => Some([a, b, c]),
        _ => None,
    };
    let vertices = vertex.count;
    let mut body = match h.encoding {
        Encoding::Ascii => Body::Ascii {
            tokens: Box::new(
                lines(&bytes[h.body..])
                    .flat_map(|(n, l)| tokens(l, false).map(move |t| (n + h.body_line - 1, t))),
            ),
            line: h.body_line,
        },
        Encoding::Little | Encoding::Big => {
            Body::Binary { bytes, at: h.body, big: h.encoding == Encoding::Big }
        }
    };
    let min_record = 1;
    let mut points = Vec::with_capacity(vertices.min(bytes.len() / min_record));
    let mut normals = Vec::with_capacity(if normal.is_some() { points.capacity() } else { 0 });
    let mut polygons: Vec<Vec<u32>> = Vec::new();
    let mut values = Vec::new();
    for element in &h.elements {
        let is_vertex = std::ptr::eq(element, vertex);
        let kind = match element.name.as_slice() {
            b"face" => 1,
            b"tristrips" => 2,
            _ => 0,
        };
        let list = element.properties.iter().position(|p| {
            matches!(p, Property::List(..))
                && (p.name() == b"vertex_indices" || p.name() == b"vertex_index")
        });
        if element.properties.is_empty() {
            continue; // nothing stored, however large the count
        }
        for _ in 0..element.count {
            values.clear();
            let mut indices = Vec::new();
            for (j, p) in element.properties.iter().enumerate() {
                match p {
                    Property::Scalar(t, _) => values.push(body.read(*t)?),
                    Property::List(c, t, _) => {
                        let len = body.length(*c)?;
                        values.push(0.0);
                        let keep = kind != 0 && Some(j) == list;
                        for _ in 0..len {
                            let v = body.read(*t)?;
                            if keep {
                                indices.push(v);
                            }
                        }
                    }
                }
            }
            if is_vertex {
                points.push(DVec3::new(values[x], values[y], values[z]));
                if let Some([a, b, c]) = normal {
                    normals.push(DVec3::new(values[a], values[b], values[c]));
                }
            } else if kind == 1 {
                if indices.len() < 3 {
                    return Err(
                        body.error(format!("a face has {} vertices; it needs 3", indices.len()))
                    );
                }
                polygons.push(checked(&body, &indices, vertices)?);
            } else if kind == 2 {
                for strip in indices.split(|&k| k == -1.0) {
                    let strip = checked(&body, strip, vertices)?;
                    for i in 0..strip.len().saturating_sub(2) {
                        let (a, b, c) = (strip[i], strip[i + 1], strip[i + 2]);
                        if a == b || b == c || a == c {
                            continue; // the degenerate triangles that join strips
                        }
                        polygons.push(if i % 2 == 0 { vec![a, b, c] } else { vec![b, a, c] });
                    }
                }
            }
        }
    }
    if list_missing(&h.elements) {
        return Err(Error::file(F, "a `face` or `tristrips` element has no `vertex_indices` list"));
    }
    let normals = normal.map(|_| normals);
    Ok(Scan::assemble(points, normals, &polygons))
}

/// Whether a face or strip element lacks its index list.
fn list_missing(elements: &[Element]) -> bool {
    elements.iter().any(|e| {
        (e.name == b"face" || e.name == b"tristrips")
            && e.count > 0
            && !e.properties.iter().any(|p| {
                matches!(p, Property::List(..))
                    && (p.name() == b"vertex_indices" || p.name() == b"vertex_index")
            })
    })
}

/// Face indices as `u32`, each checked against the vertex count.
fn checked(body: &Body<'_>, indices: &[f64], vertices: usize) -> Result<Vec<u32>, Error> {
    indices
        .iter()
        .map(|&k| {
            if k >= 0.0 && k < vertices as f64 && k.fract() == 0.0 {
                #[expect(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "checked: a whole number below the vertex count"
                )]
                Ok(k as u32)
            } else {
                Err(body.error(format!(
                    "face index {k} is out of range (the file has {vertices} vertices)"
                )))
            }
        })
        .collect()
}
