// SPDX-License-Identifier: MIT
//! Fuzzes every scan reader: the first byte picks the format, the rest is the file.
//! Run with `cargo +nightly fuzz run scan` in `crates/hi-scan/fuzz`.
//!
//! A campaign on one format sets `HI_FUZZ_FORMAT` to `obj`, `ply-ascii`, `ply-binary`, `off`,
//! `stl`, `xyz`, `pts`, `gltf` or `glb`: the first byte is then ignored, and the PLY campaigns
//! skip files whose header names the other encoding. An input found that way replays in the
//! mixed corpus once its first byte is the format's index in `ScanFormat::ALL`.
#![no_main]

use std::sync::OnceLock;

use hi_scan::scan::{ScanFormat, parse_scan};
use libfuzzer_sys::fuzz_target;

/// The format a one-format campaign is fixed to, and the PLY encoding it asks for.
fn fixed() -> Option<(ScanFormat, Option<&'static [u8]>)> {
    static FIXED: OnceLock<Option<(ScanFormat, Option<&'static [u8]>)>> = OnceLock::new();
    *FIXED.get_or_init(|| {
        let name = std::env::var("HI_FUZZ_FORMAT").ok()?;
        let fixed = match name.as_str() {
            "ply-ascii" => (ScanFormat::Ply, Some(&b"format ascii"[..])),
            "ply-binary" => (ScanFormat::Ply, Some(&b"format binary"[..])),
            other => (
                ScanFormat::from_extension(other)
                    .unwrap_or_else(|| panic!("HI_FUZZ_FORMAT={other}: not a scan format")),
                None,
            ),
        };
        Some(fixed)
    })
}

fuzz_target!(|data: &[u8]| {
    if let Some((&first, rest)) = data.split_first() {
        let format = match fixed() {
            None => ScanFormat::ALL[usize::from(first) % ScanFormat::ALL.len()],
            Some((format, None)) => format,
            Some((format, Some(encoding))) => {
                let head = &rest[..rest.len().min(256)];
                if !head.windows(encoding.len()).any(|w| w == encoding) {
                    return;
                }
                format
            }
        };
        if let Ok(scan) = parse_scan(rest, format) {
            let n = scan.points.len();
            assert!(scan.points.iter().all(|p| p.is_finite()));
            assert!(scan.triangles.iter().flatten().all(|&k| (k as usize) < n));
        }
    }
});
