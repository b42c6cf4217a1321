// SPDX-License-Identifier: MIT
//! The committed figures stay within their budget: `docs/figures` under 60 MB (10⁶ bytes), so
//! that a clone and the gallery stay light.

use std::path::Path;

/// The budget of `docs/figures`, in bytes.
const BUDGET: u64 = 60_000_000;

#[test]
fn docs_figures_stay_under_60_mb() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/figures");
    let mut total = 0u64;
    let mut largest: Vec<(u64, String)> = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("docs/figures is readable") {
        let entry = entry.expect("an entry of docs/figures");
        let meta = entry.metadata().expect("its size");
        if meta.is_file() {
            total += meta.len();
            largest.push((meta.len(), entry.file_name().to_string_lossy().into_owned()));
        }
    }
    largest.sort_unstable_by(|a, b| b.cmp(a));
    // Something is there to weigh: the gallery and hundreds of figures.
    assert!(largest.len() > 400, "{} files in docs/figures", largest.len());
    assert!(
        total < BUDGET,
        "docs/figures holds {total} bytes, above its budget of {BUDGET}; the largest: {:?}",
        &largest[..5]
    );
}
