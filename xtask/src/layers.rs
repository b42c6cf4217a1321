// SPDX-License-Identifier: MIT
//! The layer rule of docs/architecture.md: a crate may depend only on crates below it.
//!
//! {hi-interval, hi-bezier} → {hi-curve, hi-mesh} → {hi-surface, hi-compare, hi-scan} →
//! {hi-geomimage, hi-raytrace} → hi-cli,
//! with xtask on top. Every `[dependencies]`, `[dev-dependencies]` and
//! `[build-dependencies]` table of every crate under `crates/` is read; a `hi-*` entry whose
//! layer is not strictly lower than the crate's own is an error.

use std::path::Path;

use anyhow::{Context, Result, bail};

/// Each crate and its layer; 0 is the foundation.
pub(crate) const LAYERS: [(&str, u32); 11] = [
    ("hi-interval", 0),
    ("hi-bezier", 0),
    ("hi-mesh", 1),
    ("hi-curve", 1),
    ("hi-surface", 2),
    ("hi-compare", 2),
    ("hi-scan", 2),
    ("hi-geomimage", 3),
    ("hi-raytrace", 3),
    ("hi-cli", 4),
    ("xtask", 5),
];

fn layer_of(name: &str) -> Option<u32> {
    LAYERS.iter().find(|(n, _)| *n == name).map(|(_, l)| *l)
}

/// The `hi-*` crates a manifest depends on, from its dependency tables.
pub(crate) fn hi_dependencies(manifest: &str) -> Vec<String> {
    let mut in_deps = false;
    let mut res = Vec::new();
    for line in manifest.lines().map(str::trim) {
        if line.starts_with('[') {
            let table = line.trim_matches(|c| c == '[' || c == ']');
            // [dependencies], [dev-dependencies], [target.'…'.dependencies], and a dotted
            // table such as [dependencies.hi-curve].
            let last = table.rsplit('.').next().unwrap_or(table);
            if last.starts_with("hi-") && table.contains("dependencies.") {
                res.push(last.to_string());
                in_deps = false;
            } else {
                in_deps = table.ends_with("dependencies");
            }
            continue;
        }
        if in_deps {
            let key = line.split(['=', '.', ' ']).next().unwrap_or("").trim_matches('"');
            if key.starts_with("hi-") {
                res.push(key.to_string());
            }
        }
    }
    res
}

/// Checks every crate under `crates/` and `xtask/`.
pub(crate) fn check(root: &Path) -> Result<()> {
    let mut manifests = vec![("xtask".to_string(), root.join("xtask/Cargo.toml"))];
    for entry in std::fs::read_dir(root.join("crates")).context("reading crates/")? {
        let dir = entry?.path();
        let name = dir.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_string();
        manifests.push((name, dir.join("Cargo.toml")));
    }
    manifests.sort();
    let mut texts = Vec::new();
    for (name, path) in manifests {
        let text = std::fs::read_to_string(&path)
            .with_context(|| format!("reading {}", path.display()))?;
        texts.push((name, text));
    }
    let problems = violations(&texts);
    if problems.is_empty() { Ok(()) } else { bail!("layer rule broken:\n{}", problems.join("\n")) }
}

/// The layer-rule violations among (crate name, manifest text) pairs.
fn violations(manifests: &[(String, String)]) -> Vec<String> {
    let mut problems = Vec::new();
    for (name, text) in manifests {
        let Some(own) = layer_of(name) else {
            problems.push(format!(
                "{name} has no layer in docs/architecture.md (add it to xtask/src/layers.rs)"
            ));
            continue;
        };
        for dep in hi_dependencies(text) {
            match layer_of(&dep) {
                None => problems.push(format!("{name} depends on {dep}, which has no layer")),
                Some(l) if l >= own => problems.push(format!(
                    "{name} (layer {own}) depends on {dep} (layer {l}): crates may depend only on lower layers"
                )),
                Some(_) => {}
            }
        }
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn workspace_obeys_the_layer_rule() {
        check(&crate::project_root()).unwrap();
    }

    #[test]
    fn upward_edges_are_found() {
        let manifest = "[package]\nname = \"hi-curve\"\n\n[dependencies]\nglam.workspace = true\nhi-surface = { path = \"../hi-surface\" }\n\n[dev-dependencies]\nhi-raytrace.workspace = true\n\n[dependencies.hi-cli]\npath = \"x\"\n";
        assert_eq!(hi_dependencies(manifest), ["hi-surface", "hi-raytrace", "hi-cli"]);
        let deps = hi_dependencies("[package]\nname = \"hi-x\"\n[features]\nhi-y = []\n");
        assert!(deps.is_empty(), "features are not dependencies: {deps:?}");
    }

    #[test]
    fn an_upward_or_sideways_dependency_is_an_error() {
        let m = |name: &str, text: &str| (name.to_string(), text.to_string());
        let ok = [m("hi-surface", "[dependencies]\nhi-curve.workspace = true\n")];
        assert!(violations(&ok).is_empty());
        let upward = [m("hi-curve", "[dependencies]\nhi-surface.workspace = true\n")];
        assert_eq!(violations(&upward).len(), 1, "{:?}", violations(&upward));
        let sideways = [m(
            "hi-raytrace",
            "[dev-dependencies]\nhi-geomimage = { path = \"../hi-geomimage\" }\n",
        )];
        assert_eq!(violations(&sideways).len(), 1);
        let foundation = [m("hi-bezier", "[dependencies]\nhi-interval.workspace = true\n")];
        assert_eq!(violations(&foundation).len(), 1, "foundations depend on no hi-* crate");
        let unknown = [m("hi-new", "")];
        assert_eq!(violations(&unknown).len(), 1);
    }

    #[test]
    fn every_crate_directory_has_a_layer() {
        for entry in std::fs::read_dir(crate::project_root().join("crates")).unwrap() {
            let name = entry.unwrap().file_name().into_string().unwrap();
            assert!(layer_of(&name).is_some(), "crates/{name} has no layer");
        }
    }
}
