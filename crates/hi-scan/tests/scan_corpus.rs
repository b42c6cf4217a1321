// SPDX-License-Identifier: MIT
//! Replays the fuzzing corpus of the scan readers (`fuzz/corpus/scan`, minimised from the
//! campaigns recorded in `docs/reliability.md`) with the fuzz target's own checks: the first
//! byte picks the format, the rest is the file; no input may panic (not even a panic the
//! glTF reader's safety net would catch: the `gltf` crate's assertions are checked for before
//! reading), and a scan that is read has finite points and triangles that index them. Every
//! crash a campaign found is kept in the corpus, so it stays fixed.

use std::path::Path;
use std::sync::Mutex;

use hi_scan::scan::{ScanFormat, parse_scan};

#[test]
fn the_fuzzing_corpus_replays_without_a_failure() {
    let fuzz = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz");
    if !fuzz.exists() {
        // A packaged crate leaves the fuzzing folder out (it is a package of its own).
        eprintln!("no fuzz folder beside this crate: the corpus is replayed in the repository");
        return;
    }
    let dir = fuzz.join("corpus/scan");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.expect("a corpus entry").path())
        .collect();
    files.sort();
    let mut read = [0usize; ScanFormat::ALL.len()];
    // Any panic, caught or not, is recorded (this file holds this one test).
    static PANICS: Mutex<Vec<String>> = Mutex::new(Vec::new());
    std::panic::set_hook(Box::new(|info| {
        PANICS.lock().unwrap_or_else(std::sync::PoisonError::into_inner).push(info.to_string());
    }));
    for path in &files {
        let data = std::fs::read(path).expect("a corpus file");
        let Some((&first, rest)) = data.split_first() else { continue };
        let k = usize::from(first) % ScanFormat::ALL.len();
        if let Ok(scan) = parse_scan(rest, ScanFormat::ALL[k]) {
            let n = scan.points.len();
            assert!(scan.points.iter().all(|p| p.is_finite()), "{}", path.display());
            assert!(
                scan.triangles.iter().flatten().all(|&i| (i as usize) < n),
                "{}",
                path.display()
            );
            read[k] += 1;
        }
        let panics = std::mem::take(&mut *PANICS.lock().expect("not poisoned"));
        assert!(panics.is_empty(), "{}: {panics:?}", path.display());
    }
    let _ = std::panic::take_hook();
    assert!(files.len() >= ScanFormat::ALL.len(), "a corpus of {} files", files.len());
    // The corpus reaches a valid file of every format.
    for (format, count) in ScanFormat::ALL.iter().zip(read) {
        assert!(count > 0, "no file of the corpus reads as {format:?}");
    }
}
