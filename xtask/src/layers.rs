// SPDX-License-Identifier: MIT
//! The layer rule of docs/architecture.md: a crate may depend only on crates below it.
//!
//! {hi-interval, hi-bezier, hi-par} → {hi-curve, hi-mesh} → {hi-surface, hi-compare, hi-scan} →
//! {hi-geomimage, hi-raytrace} → hi-fit → {hi-cli, hi-py},
//! with xtask on top. Every `[dependencies]`, `[dev-dependencies]` and
//! `[build-dependencies]` table (and the same under `[target.'…']`) of every crate under
//! `crates/`, of xtask, and of the fuzz crates under `crates/*/fuzz/` is read with a TOML
//! parser; a `hi-*` dependency whose layer is not strictly lower than the crate's own is an
//! error. A fuzz crate stands on the crate it fuzzes: it may depend on it and below. A crate's
//! dev-dependency on itself (its tests asking for a feature such as `testing`) is allowed.
//! `hi-testkit` lies below every layer: any crate may have it as a dev-dependency, none as
//! anything else but xtask (the developers' tool on top, which nothing depends on: its figures
//! and benches sample what the tests sample), and it depends on no `hi-*` crate.

use std::path::Path;

use anyhow::{Context, Result, bail};

/// Each crate and its layer; 0 is the foundation.
pub(crate) const LAYERS: [(&str, u32); 14] = [
    ("hi-interval", 0),
    ("hi-par", 0),
    ("hi-bezier", 0),
    ("hi-mesh", 1),
    ("hi-curve", 1),
    ("hi-surface", 2),
    ("hi-compare", 2),
    ("hi-scan", 2),
    ("hi-geomimage", 3),
    ("hi-raytrace", 3),
    ("hi-fit", 4),
    ("hi-cli", 5),
    ("hi-py", 5),
    ("xtask", 6),
];

fn layer_of(name: &str) -> Option<u32> {
    LAYERS.iter().find(|(n, _)| *n == name).map(|(_, l)| *l)
}

/// The crate every crate's tests may use: a dev-dependency of any crate (a dependency of
/// xtask's), below every layer, itself depending on no `hi-*` crate.
pub(crate) const TEST_KIT: &str = "hi-testkit";

/// A `hi-*` dependency of a manifest: the package, and whether it is a dev-dependency.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Dependency {
    pub(crate) package: String,
    pub(crate) dev: bool,
}

/// The `hi-*` crates a manifest depends on, from its dependency tables (`[dependencies]`,
/// `[dev-dependencies]`, `[build-dependencies]`, and the same under `[target.'…']`), by the
/// package each entry names (its `package` key, for a renamed dependency).
///
/// # Errors
///
/// When the manifest is not valid TOML.
pub(crate) fn hi_dependencies(manifest: &str) -> Result<Vec<Dependency>> {
    let table: toml::Table = manifest.parse().context("the manifest is not valid TOML")?;
    let kinds = ["dependencies", "dev-dependencies", "build-dependencies"];
    let targets = table.get("target").and_then(toml::Value::as_table);
    let scopes = std::iter::once(&table)
        .chain(targets.into_iter().flat_map(|t| t.values().filter_map(toml::Value::as_table)));
    let mut res = Vec::new();
    for scope in scopes {
        for kind in kinds {
            let Some(deps) = scope.get(kind).and_then(toml::Value::as_table) else { continue };
            for (key, value) in deps {
                let package = value.get("package").and_then(toml::Value::as_str).unwrap_or(key);
                if package.starts_with("hi-") {
                    res.push(Dependency {
                        package: package.to_owned(),
                        dev: kind == "dev-dependencies",
                    });
                }
            }
        }
    }
    res.sort();
    Ok(res)
}

/// A crate's manifest: its name, the crate whose fuzz targets it holds (for a fuzz crate), and
/// its text.
struct Manifest {
    name: String,
    fuzzes: Option<String>,
    text: String,
}

/// Checks every crate under `crates/` and `xtask/`, and the fuzz crates under `crates/*/fuzz/`.
pub(crate) fn check(root: &Path) -> Result<()> {
    let mut found = vec![("xtask".to_owned(), None, root.join("xtask/Cargo.toml"))];
    for entry in std::fs::read_dir(root.join("crates")).context("reading crates/")? {
        let dir = entry?.path();
        let name = dir.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_owned();
        let fuzz = dir.join("fuzz/Cargo.toml");
        if fuzz.is_file() {
            found.push((format!("{name}/fuzz"), Some(name.clone()), fuzz));
        }
        found.push((name, None, dir.join("Cargo.toml")));
    }
    found.sort();
    let mut manifests = Vec::new();
    for (name, fuzzes, path) in found {
        let text = std::fs::read_to_string(&path)
            .with_context(|| format!("reading {}", path.display()))?;
        manifests.push(Manifest { name, fuzzes, text });
    }
    let problems = violations(&manifests)?;
    if problems.is_empty() { Ok(()) } else { bail!("layer rule broken:\n{}", problems.join("\n")) }
}

/// The layer-rule violations among the manifests. A fuzz crate stands on the crate it fuzzes:
/// it may depend on that crate and on what that crate may depend on.
///
/// # Errors
///
/// When a manifest is not valid TOML.
fn violations(manifests: &[Manifest]) -> Result<Vec<String>> {
    let mut problems = Vec::new();
    for Manifest { name, fuzzes, text } in manifests {
        let deps = hi_dependencies(text).with_context(|| format!("reading {name}'s manifest"))?;
        if name == TEST_KIT {
            problems.extend(deps.iter().map(|d| {
                format!("{name} depends on {}: the test kit depends on no hi-* crate", d.package)
            }));
            continue;
        }
        let Some(own) = layer_of(fuzzes.as_deref().unwrap_or(name)) else {
            problems.push(format!(
                "{name} has no layer in docs/architecture.md (add it to xtask/src/layers.rs)"
            ));
            continue;
        };
        for Dependency { package: dep, dev } in deps {
            if dep == TEST_KIT {
                if !dev && name != "xtask" {
                    problems.push(format!("{name} depends on {dep} outside its dev-dependencies"));
                }
                continue;
            }
            match layer_of(&dep) {
                None => problems.push(format!("{name} depends on {dep}, which has no layer")),
                // A fuzz crate on its crate; a crate's tests on itself, with a test feature.
                Some(_) if fuzzes.as_deref() == Some(dep.as_str()) || dep == *name => {}
                Some(l) if l >= own => problems.push(format!(
                    "{name} (layer {own}) depends on {dep} (layer {l}): crates may depend only on lower layers"
                )),
                Some(_) => {}
            }
        }
    }
    Ok(problems)
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
        let names = |m: &str| -> Vec<(String, bool)> {
            hi_dependencies(m).unwrap().into_iter().map(|d| (d.package, d.dev)).collect()
        };
        let dep = |p: &str, dev: bool| (p.to_owned(), dev);
        assert_eq!(
            names(manifest),
            [dep("hi-cli", false), dep("hi-raytrace", true), dep("hi-surface", false)]
        );
        let deps = names("[package]\nname = \"hi-x\"\n[features]\nhi-y = []\n");
        assert!(deps.is_empty(), "features are not dependencies: {deps:?}");
        // A renamed dependency counts by its package; a target's tables count too.
        let renamed = "[dependencies]\ncurve = { package = \"hi-curve\", path = \"x\" }\n\
                       [target.'cfg(unix)'.dev-dependencies]\nhi-mesh = \"0.1\"\n";
        assert_eq!(names(renamed), [dep("hi-curve", false), dep("hi-mesh", true)]);
        assert!(hi_dependencies("[dependencies\nhi-x = 1").is_err(), "not TOML");
    }

    #[test]
    fn an_upward_or_sideways_dependency_is_an_error() {
        let m = |name: &str, text: &str| Manifest {
            name: name.to_owned(),
            fuzzes: None,
            text: text.to_owned(),
        };
        let ok = [m("hi-surface", "[dependencies]\nhi-curve.workspace = true\n")];
        assert!(violations(&ok).unwrap().is_empty());
        let upward = [m("hi-curve", "[dependencies]\nhi-surface.workspace = true\n")];
        assert_eq!(violations(&upward).unwrap().len(), 1);
        let sideways = [m(
            "hi-raytrace",
            "[dev-dependencies]\nhi-geomimage = { path = \"../hi-geomimage\" }\n",
        )];
        assert_eq!(violations(&sideways).unwrap().len(), 1);
        let itself = [m("hi-curve", "[dev-dependencies]\nhi-curve = { path = \".\" }\n")];
        assert!(violations(&itself).unwrap().is_empty(), "its tests, with a feature");
        // The test kit: any crate's dev-dependency, nobody's dependency, and on nothing.
        let kit = [m("hi-interval", "[dev-dependencies]\nhi-testkit.workspace = true\n")];
        assert!(violations(&kit).unwrap().is_empty());
        let kit = [m("hi-curve", "[dependencies]\nhi-testkit.workspace = true\n")];
        assert_eq!(violations(&kit).unwrap().len(), 1, "outside the dev-dependencies");
        let kit = [m("xtask", "[dependencies]\nhi-testkit.workspace = true\n")];
        assert!(violations(&kit).unwrap().is_empty(), "xtask, which nothing depends on");
        let kit = [m("hi-testkit", "[dependencies]\nhi-interval.workspace = true\n")];
        assert_eq!(violations(&kit).unwrap().len(), 1, "the kit depends on no hi-* crate");
        let foundation = [m("hi-bezier", "[dependencies]\nhi-interval.workspace = true\n")];
        assert_eq!(
            violations(&foundation).unwrap().len(),
            1,
            "foundations depend on no hi-* crate"
        );
        let unknown = [m("hi-new", "")];
        assert_eq!(violations(&unknown).unwrap().len(), 1);
        // A fuzz crate may depend on the crate it fuzzes and below, not beside or above it.
        let fuzz = |text: &str| Manifest {
            name: "hi-mesh/fuzz".to_owned(),
            fuzzes: Some("hi-mesh".to_owned()),
            text: text.to_owned(),
        };
        let ok = [fuzz("[dependencies]\nhi-mesh = { path = \"..\" }\nhi-bezier = \"0.1\"\n")];
        assert!(violations(&ok).unwrap().is_empty());
        let sideways = [fuzz("[dependencies]\nhi-curve = { path = \"../../hi-curve\" }\n")];
        assert_eq!(violations(&sideways).unwrap().len(), 1);
    }

    #[test]
    fn every_crate_directory_has_a_layer() {
        for entry in std::fs::read_dir(crate::project_root().join("crates")).unwrap() {
            let name = entry.unwrap().file_name().into_string().unwrap();
            assert!(name == TEST_KIT || layer_of(&name).is_some(), "crates/{name} has no layer");
        }
    }
}
