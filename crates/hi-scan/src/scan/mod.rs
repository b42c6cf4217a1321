// SPDX-License-Identifier: MIT
//! Reading scans: unorganised points, with normals and faces where the file has them — the
//! input of the geometry-image algorithms of §5.3 and §5.8.
//!
//! | format | extension | what is read |
//! |---|---|---|
//! | Wavefront OBJ | `.obj` | `v` (and `vn` when there is one per `v`) lines; `f` faces of any size and index syntax (`v`, `v/vt`, `v//vn`, `v/vt/vn`, negative), fan-triangulated |
//! | Stanford PLY | `.ply` | ASCII, binary little- and big-endian; `vertex` x y z (nx ny nz); `face` lists and `tristrips` (−1 restarts); other elements skipped |
//! | Object File Format | `.off` | `OFF`, `COFF`, `NOFF`, `CNOFF` headers, `#` comments, polygon faces |
//! | STL | `.stl` | ASCII and binary; the repeated corners of each facet are welded into shared points |
//! | XYZ | `.xyz`, `.pwn` (CGAL's points with normals) | `x y z` or `x y z nx ny nz` per line (spaces, tabs or commas), `#` comments |
//! | Hoppe's PTS | `.pts` | `p x y z` lines; every other line is skipped |
//! | glTF 2.0 | `.gltf`, `.glb` | the positions of every mesh primitive the scene places, node transforms applied; triangles of `TRIANGLES`, `TRIANGLE_STRIP` and `TRIANGLE_FAN` primitives; normals when every primitive has them; `read_scan` resolves external buffers beside the file |
//!
//! Every reader returns a [`Error::Read`] naming the format, the line (text) or byte offset
//! (binary) and what is wrong for malformed input; none panics or allocates more than the input
//! can justify, whatever the bytes. Points with a non-finite coordinate are dropped and counted
//! in [`Scan::dropped_points`]; faces that used them are dropped and counted in
//! [`Scan::dropped_faces`].
//!
//! OBJ and OFF files are read by `hi-mesh`'s [`hi_mesh::PolygonSoup`] rather than `tobj`:
//! `tobj` reads coordinates as f32 by default, reports no line numbers, and returns no positions
//! for point-only files (the usual way scanners write OBJ). The tests check this reader against
//! `tobj` on meshes.
//!
//! # Examples
//!
//! ```
//! use hi_scan::scan::{ScanFormat, parse_scan};
//!
//! let pts = b"# Hoppe's format\np 0 0 1\np 1 0 0\nd 0 0 0\np 0 1 nan\n";
//! let scan = parse_scan(pts, ScanFormat::Pts).unwrap();
//! assert_eq!(scan.points.len(), 2);
//! assert_eq!(scan.dropped_points, 1); // the NaN point
//!
//! let err = parse_scan(b"p 0 0\n", ScanFormat::Pts).unwrap_err();
//! assert_eq!(err.to_string(), "PTS, line 1: expected 3 coordinates after `p`, found 2");
//! ```

mod gltf;
mod obj;
mod off;
mod ply;
mod stl;
mod text;
mod xyz;

use std::fmt;
use std::path::Path;

use glam::DVec3;

use crate::Error;

/// The file formats [`read_scan`] understands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ScanFormat {
    /// Wavefront OBJ.
    Obj,
    /// Stanford PLY (ASCII or binary).
    Ply,
    /// Object File Format.
    Off,
    /// Stereolithography (ASCII or binary).
    Stl,
    /// One point per line: `x y z` or `x y z nx ny nz`.
    Xyz,
    /// Hoppe's point format: `p x y z` lines.
    Pts,
    /// glTF 2.0 as JSON (`.gltf`), buffers embedded or in files beside it.
    Gltf,
    /// glTF 2.0 binary (`.glb`).
    Glb,
}

impl ScanFormat {
    /// Every format, in the order of the module table.
    pub const ALL: [Self; 8] =
        [Self::Obj, Self::Ply, Self::Off, Self::Stl, Self::Xyz, Self::Pts, Self::Gltf, Self::Glb];

    /// The format named by a file extension (case-insensitive, without the dot), if any: each
    /// format's [`ScanFormat::extension`], and `pwn` for XYZ (CGAL's name for points with
    /// normals, `x y z nx ny nz` per line).
    #[must_use]
    pub fn from_extension(extension: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|f| f.extension().eq_ignore_ascii_case(extension))
            .or_else(|| extension.eq_ignore_ascii_case("pwn").then_some(Self::Xyz))
    }

    /// The format of `path`, from its extension.
    ///
    /// # Errors
    ///
    /// [`Error::Read`] if the extension is missing or not one of [`ScanFormat::ALL`].
    pub fn try_from_path(path: &Path) -> Result<Self, Error> {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        Self::from_extension(ext).ok_or_else(|| Error::Read {
            format: None,
            location: Location::None,
            message: format!(
                "{}: unknown scan format {:?}; expected one of .obj, .ply, .off, .stl, .xyz, .pwn, .pts, .gltf, .glb",
                path.display(),
                ext
            ),
        })
    }

    /// The usual file extension, lower case: `"obj"`, `"ply"`, ….
    #[must_use]
    pub const fn extension(self) -> &'static str {
        match self {
            Self::Obj => "obj",
            Self::Ply => "ply",
            Self::Off => "off",
            Self::Stl => "stl",
            Self::Xyz => "xyz",
            Self::Pts => "pts",
            Self::Gltf => "gltf",
            Self::Glb => "glb",
        }
    }

    /// The name used in messages: `"OBJ"`, `"PLY"`, ….
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Obj => "OBJ",
            Self::Ply => "PLY",
            Self::Off => "OFF",
            Self::Stl => "STL",
            Self::Xyz => "XYZ",
            Self::Pts => "PTS",
            Self::Gltf => "glTF",
            Self::Glb => "GLB",
        }
    }
}

impl fmt::Display for ScanFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A scan: points in space, with a normal per point and triangles where the file has them.
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Scan {
    /// The points, all finite.
    pub points: Vec<DVec3>,
    /// One normal per point, as stored (not normalised), when the file gives one for every point.
    pub normals: Option<Vec<DVec3>>,
    /// Triangles as indices into `points` (polygons are fan-triangulated, strips unrolled).
    pub triangles: Vec<[u32; 3]>,
    /// Points dropped because a coordinate was NaN or infinite.
    pub dropped_points: usize,
    /// Faces dropped because they used a dropped point.
    pub dropped_faces: usize,
}

impl Scan {
    /// A scan from points and triangles held in memory (a program's arrays rather than a file),
    /// treated as a file's are: points with a NaN or infinite coordinate dropped and counted,
    /// with the triangles that use them. `triangles` may be empty (a point set).
    ///
    /// # Errors
    ///
    /// [`Error::Read`] naming the first triangle with an index past the points, and
    /// [`Error::TooFewPoints`] when no point is given.
    pub fn from_arrays(points: Vec<DVec3>, triangles: &[[u32; 3]]) -> Result<Self, Error> {
        if points.is_empty() {
            return Err(Error::TooFewPoints { found: 0, needed: 1 });
        }
        let n = points.len();
        if let Some((t, bad)) = triangles
            .iter()
            .enumerate()
            .find_map(|(t, tri)| tri.iter().find(|&&k| k as usize >= n).map(|&k| (t, k)))
        {
            return Err(Error::Read {
                format: None,
                location: Location::None,
                message: format!(
                    "triangle {t} uses vertex {bad}, and there are {n} points (indices from 0)"
                ),
            });
        }
        let faces: Vec<Vec<u32>> = triangles.iter().map(|t| t.to_vec()).collect();
        Ok(Self::assemble(points, None, &faces))
    }

    /// Builds a scan from raw points, normals and polygon faces (indices into `points`), dropping
    /// non-finite points and the faces that use them, and triangulating polygons as fans.
    ///
    /// Faces must already have been checked to index existing points.
    fn assemble(raw: Vec<DVec3>, raw_normals: Option<Vec<DVec3>>, faces: &[Vec<u32>]) -> Self {
        let mut remap = vec![u32::MAX; raw.len()];
        let mut points = Vec::with_capacity(raw.len());
        let mut normals = raw_normals.as_ref().map(|n| Vec::with_capacity(n.len()));
        let mut dropped_points = 0;
        for (i, p) in raw.iter().enumerate() {
            if p.is_finite() {
                remap[i] = u32::try_from(points.len()).unwrap_or(u32::MAX);
                points.push(*p);
                if let (Some(out), Some(src)) = (normals.as_mut(), raw_normals.as_ref()) {
                    out.push(src[i]);
                }
            } else {
                dropped_points += 1;
            }
        }
        let mut triangles = Vec::with_capacity(faces.len());
        let mut dropped_faces = 0;
        for face in faces {
            let mapped: Option<Vec<u32>> = face
                .iter()
                .map(|&k| remap.get(k as usize).copied().filter(|&m| m != u32::MAX))
                .collect();
            match mapped {
                Some(f) => {
                    for w in 1..f.len().saturating_sub(1) {
                        triangles.push([f[0], f[w], f[w + 1]]);
                    }
                }
                None => dropped_faces += 1,
            }
        }
        Self { points, normals, triangles, dropped_points, dropped_faces }
    }
}

/// Where in a file an error was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Location {
    /// A line of a text file, counted from 1.
    Line(usize),
    /// A byte offset into a binary file, counted from 0.
    Byte(usize),
    /// The file as a whole (for instance, it ended too soon or is empty).
    None,
}

/// Constructors of [`Error::Read`] for the readers.
impl Error {
    /// A scan error at a line of a text file.
    pub(crate) fn line(format: ScanFormat, line: usize, message: impl Into<String>) -> Self {
        Self::Read { format: Some(format), location: Location::Line(line), message: message.into() }
    }

    /// A scan error at a byte offset of a binary file.
    pub(crate) fn byte(format: ScanFormat, offset: usize, message: impl Into<String>) -> Self {
        Self::Read {
            format: Some(format),
            location: Location::Byte(offset),
            message: message.into(),
        }
    }

    /// A scan error from `hi-mesh`'s parser of OBJ and OFF ([`hi_mesh::PolygonSoup`]): its
    /// line and message, in this crate's form.
    pub(crate) fn from_parse(format: ScanFormat, e: hi_mesh::Error) -> Self {
        match e {
            hi_mesh::Error::Parse { line, message, .. } => Self::Read {
                format: Some(format),
                location: line.map_or(Location::None, Location::Line),
                message,
            },
            other => Self::file(format, other.to_string()),
        }
    }

    /// A scan error about the file as a whole.
    pub(crate) fn file(format: ScanFormat, message: impl Into<String>) -> Self {
        Self::Read { format: Some(format), location: Location::None, message: message.into() }
    }
}

/// Reads the scan in `path`, choosing the reader by the file's extension.
///
/// # Errors
///
/// [`Error::Read`] if the extension is unknown, the file cannot be read, or its contents are
/// malformed (with the line or byte offset).
pub fn read_scan(path: &Path) -> Result<Scan, Error> {
    let format = ScanFormat::try_from_path(path)?;
    let bytes = std::fs::read(path).map_err(|e| Error::Read {
        format: Some(format),
        location: Location::None,
        message: format!("cannot read {}: {e}", path.display()),
    })?;
    if matches!(format, ScanFormat::Gltf | ScanFormat::Glb) {
        // External buffers are files beside this one.
        let base = path.parent().unwrap_or_else(|| Path::new("."));
        return checked(gltf::parse(&bytes, Some(base), format)?, format);
    }
    parse_scan(&bytes, format)
}

/// Reads a scan from the bytes of a file in `format`.
///
/// # Errors
///
/// [`Error::Read`] naming the line (text formats) or byte offset (binary PLY and STL) of the
/// first malformed record, or the problem with the file as a whole (empty, no points,
/// truncated, a glTF buffer in another file, which bytes alone cannot reach).
pub fn parse_scan(bytes: &[u8], format: ScanFormat) -> Result<Scan, Error> {
    let scan = match format {
        ScanFormat::Obj => obj::parse(bytes),
        ScanFormat::Ply => ply::parse(bytes),
        ScanFormat::Off => off::parse(bytes),
        ScanFormat::Stl => stl::parse(bytes),
        ScanFormat::Xyz => xyz::parse_xyz(bytes),
        ScanFormat::Pts => xyz::parse_pts(bytes),
        ScanFormat::Gltf | ScanFormat::Glb => gltf::parse(bytes, None, format),
    }?;
    checked(scan, format)
}

/// The scan, unless it has no (finite) point.
fn checked(scan: Scan, format: ScanFormat) -> Result<Scan, Error> {
    if scan.points.is_empty() && scan.dropped_points == 0 {
        return Err(Error::file(format, "the file holds no points"));
    }
    if scan.points.is_empty() {
        return Err(Error::file(
            format,
            format!("all {} points have a NaN or infinite coordinate", scan.dropped_points),
        ));
    }
    Ok(scan)
}
