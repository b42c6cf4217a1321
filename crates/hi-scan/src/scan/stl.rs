// SPDX-License-Identifier: MIT
//! STL, ASCII and binary. STL stores every facet's three corners separately; equal corners
//! (bit for bit) are welded into one point.

use std::collections::HashMap;

use glam::DVec3;

use super::text::{lines, point, show, tokens};
use super::{Scan, ScanFormat};
use crate::Error;

const F: ScanFormat = ScanFormat::Stl;

/// Reads an STL file: binary when its size is exactly 84 + 50·(the triangle count in bytes
/// 80–83), otherwise ASCII if it starts with `solid`.
pub(super) fn parse(bytes: &[u8]) -> Result<Scan, Error> {
    if bytes.len() >= 84 {
        let count = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
        if count.checked_mul(50).and_then(|b| b.checked_add(84)) == Some(bytes.len()) {
            return Ok(binary(bytes, count));
        }
    }
    if bytes.trim_ascii_start().starts_with(b"solid") {
        return ascii(bytes);
    }
    if bytes.len() < 84 {
        return Err(Error::file(
            F,
            format!(
                "{} bytes is too short for binary STL (84-byte header) and it is not ASCII STL",
                bytes.len()
            ),
        ));
    }
    let count = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]);
    Err(Error::byte(
        F,
        80,
        format!(
            "the binary header announces {count} triangles, {} bytes, but the file has {}",
            84 + 50 * u64::from(count),
            bytes.len()
        ),
    ))
}

/// Welds corners into shared points.
#[derive(Default)]
struct Welder {
    points: Vec<DVec3>,
    index: HashMap<[u64; 3], u32>,
}

impl Welder {
    fn add(&mut self, p: DVec3) -> u32 {
        // +0.0 and −0.0 are the same point.
        let key = (p + DVec3::ZERO).to_array().map(f64::to_bits);
        let next = u32::try_from(self.points.len()).unwrap_or(u32::MAX);
        *self.index.entry(key).or_insert_with(|| {
            self.points.push(p);
            next
        })
    }
}

fn binary(bytes: &[u8], count: usize) -> Scan {
    let mut w = Welder::default();
    let mut faces = Vec::with_capacity(count);
    for t in 0..count {
        let record = &bytes[84 + 50 * t..84 + 50 * (t + 1)];
        let corner = |c: usize| {
            let f = |i: usize| {
                let o = 12 + 12 * c + 4 * i;
                f64::from(f32::from_le_bytes([
                    record[o],
                    record[o + 1],
                    record[o + 2],
                    record[o + 3],
                ]))
            };
            DVec3::new(f(0), f(1), f(2))
        };
        faces.push(vec![w.add(corner(0)), w.add(corner(1)), w.add(corner(2))]);
    }
    Scan::assemble(w.points, None, &faces)
}

fn ascii(bytes: &[u8]) -> Result<Scan, Error> {
    let mut w = Welder::default();
    let mut faces = Vec::new();
    let mut corners: Vec<u32> = Vec::with_capacity(3);
    let mut in_facet = None;
    let mut last = 0;
    for (n, line) in lines(bytes) {
        let mut it = tokens(line, false);
        let Some(keyword) = it.next() else { continue };
        last = n;
        match keyword {
            b"solid" | b"endsolid" | b"outer" | b"endloop" => {}
            b"facet" => {
                if in_facet.is_some() {
                    return Err(Error::line(F, n, "`facet` inside a facet (missing `endfacet`)"));
                }
                in_facet = Some(n);
                corners.clear();
            }
            b"vertex" => {
                if in_facet.is_none() {
                    return Err(Error::line(F, n, "`vertex` outside a facet"));
                }
                corners.push(w.add(point(F, n, &mut it, "after `vertex`")?));
            }
            b"endfacet" => {
                if corners.len() != 3 {
                    return Err(Error::line(
                        F,
                        n,
                        format!("a facet has {} vertices; STL facets are triangles", corners.len()),
                    ));
                }
                faces.push(corners.clone());
                in_facet = None;
            }
            other => {
                return Err(Error::line(F, n, format!("unknown keyword {:?}", show(other))));
            }
        }
    }
    if let Some(start) = in_facet {
        return Err(Error::line(F, last, format!("the facet begun on line {start} never ends")));
    }
    Ok(Scan::assemble(w.points, None, &faces))
}
