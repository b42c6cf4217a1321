// SPDX-License-Identifier: MIT
//! Fuzzes every scan reader: the first byte picks the format, the rest is the file.
//! Run with `cargo +nightly fuzz run scan` in `crates/hi-geomimage/fuzz`.
#![no_main]

use hi_geomimage::scan::{ScanFormat, parse_scan};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Some((&first, rest)) = data.split_first() {
        let format = ScanFormat::ALL[usize::from(first) % ScanFormat::ALL.len()];
        if let Ok(scan) = parse_scan(rest, format) {
            let n = scan.points.len();
            assert!(scan.points.iter().all(|p| p.is_finite()));
            assert!(scan.triangles.iter().flatten().all(|&k| (k as usize) < n));
        }
    }
});
