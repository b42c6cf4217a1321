// SPDX-License-Identifier: MIT
//! What each figure is drawn from, hashed: a figure whose inputs are the same as when its files
//! were written is not drawn again.
//!
//! A figure's inputs are the source files its drawing can reach and the data they read:
//!
//! - the files of its topic module (`curves.rs`, or every file of `masks/`), of the modules
//!   they name (`plot::`, `super::{data, glb}`, …, followed to a fixed point), of the driver
//!   (`mod.rs`) and, for a model or a render, of [`renders`](super::renders);
//! - every file of each `hi-*` crate those files name (`hi_surface`), and of the `hi-*` crates
//!   below it (from the manifests' `[dependencies]`), manifests included;
//! - all of `fixtures/` if any of those files names it; the compiler's version (`rustc -V`),
//!   and the packages with their versions that `xtask` is built from, but the `hi-*` crates
//!   the figure does not read and what only they bring in (`cargo tree --prune`): a new
//!   dependency of another crate changes no figure's key.
//!
//! The key of a figure is the SHA-256 of all of them (names and bytes, in sorted order) with
//! the figure's number. `docs/figures/inputs.json` records the keys of the files as they were
//! last written; `cargo xtask figures` and `--check` draw only the figures whose key differs
//! from it, or whose files are missing (`--all` draws every figure). The reach is found by
//! reading the sources' text, so it over-approximates: a figure may be drawn again for nothing,
//! never skipped when something it reads has changed.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use sha2::{Digest, Sha256};

use super::{Figure, Format};

/// The manifest of keys inside `docs/figures`.
pub(crate) const MANIFEST: &str = "inputs.json";

/// The files of the tree that figures are drawn from, read once, and the keys made of them.
pub(crate) struct Inputs {
    root: PathBuf,
    /// Every file read, by path relative to the root, with the SHA-256 of its bytes.
    digests: BTreeMap<String, [u8; 32]>,
    /// The text of the sources of `xtask/src`, by path relative to the root.
    sources: BTreeMap<String, String>,
    /// The compiler's version line.
    rustc: String,
    /// The packages `xtask` is built from (`cargo tree`), by line, unpruned.
    tree: Vec<String>,
    /// The packages a figure is built from, by the `hi-*` crates it reads.
    packages: BTreeMap<BTreeSet<String>, String>,
}

impl Inputs {
    /// Reads the tree under `root`.
    ///
    /// # Errors
    ///
    /// If a source cannot be read.
    pub(crate) fn read(root: &Path) -> Result<Self> {
        let mut inputs = Inputs {
            root: root.to_path_buf(),
            digests: BTreeMap::new(),
            sources: BTreeMap::new(),
            rustc: run(root, "RUSTC", "rustc", &["-V"]).trim().to_owned(),
            tree: Vec::new(),
            packages: BTreeMap::new(),
        };
        inputs.tree = inputs.cargo_tree(&[]);
        for file in files_under(&root.join("xtask/src"))? {
            let text = std::fs::read_to_string(&file)
                .with_context(|| format!("reading {}", file.display()))?;
            inputs.sources.insert(inputs.relative(&file), text);
        }
        Ok(inputs)
    }

    /// `path` relative to the root, with `/` between its parts.
    fn relative(&self, path: &Path) -> String {
        let rel = path.strip_prefix(&self.root).unwrap_or(path);
        rel.components().map(|c| c.as_os_str().to_string_lossy()).collect::<Vec<_>>().join("/")
    }

    /// The SHA-256 of the file at `rel` (relative to the root), read on first use; a missing
    /// file hashes as empty.
    fn digest(&mut self, rel: &str) -> [u8; 32] {
        if let Some(d) = self.digests.get(rel) {
            return *d;
        }
        let bytes = std::fs::read(self.root.join(rel)).unwrap_or_default();
        let d: [u8; 32] = Sha256::digest(&bytes).into();
        self.digests.insert(rel.to_owned(), d);
        d
    }

    /// The key of `figure`, drawn by the topic module `module` (its file or folder name).
    ///
    /// # Errors
    ///
    /// If a crate's folder or the fixtures cannot be listed.
    pub(crate) fn key(&mut self, figure: &Figure, module: &str) -> Result<String> {
        let (all, crates) = self.files(figure, module)?;
        let packages = self.packages(crates);
        let mut hasher = Sha256::new();
        let (chapter, number) = figure.number;
        hasher.update(format!("figure {chapter}.{number}\n{}\n{packages}\n", self.rustc));
        for rel in &all {
            let d = self.digest(rel);
            hasher.update(rel.as_bytes());
            hasher.update(d);
        }
        Ok(hasher.finalize().iter().map(|b| format!("{b:02x}")).collect())
    }

    /// The packages, with their versions, that a figure reading the `hi-*` crates `crates` is
    /// built from: those of `xtask` but the `hi-*` crates it does not read and what only they
    /// bring in (so that a dependency added for another crate changes no figure's key).
    fn packages(&mut self, crates: BTreeSet<String>) -> String {
        if let Some(p) = self.packages.get(&crates) {
            return p.clone();
        }
        let unread: Vec<String> = self
            .tree
            .iter()
            .filter_map(|l| l.split(' ').next())
            .filter(|name| name.starts_with("hi-") && !crates.contains(*name))
            .map(str::to_owned)
            .collect::<BTreeSet<String>>()
            .into_iter()
            .collect();
        let p = self.cargo_tree(&unread).join("\n");
        self.packages.insert(crates, p.clone());
        p
    }

    /// The lines of `cargo tree` for `xtask` with the packages `prune` left out, as
    /// "name vX.Y.Z" (without a workspace crate's folder, which differs between clones),
    /// sorted and without repeats.
    fn cargo_tree(&self, prune: &[String]) -> Vec<String> {
        let mut args = vec!["tree", "-p", "xtask", "-e", "normal,build", "--prefix", "none"];
        for p in prune {
            args.extend(["--prune", p.as_str()]);
        }
        let tree = run(&self.root, "CARGO", "cargo", &args);
        let lines: BTreeSet<String> = tree
            .lines()
            .map(|l| l.split(" (").next().unwrap_or(l).trim().to_owned())
            .filter(|l| !l.is_empty() && !l.starts_with("xtask "))
            .collect();
        lines.into_iter().collect()
    }

    /// The files `figure` (of the topic module `module`) is drawn from, relative to the root,
    /// and the `hi-*` crates among them.
    fn files(&self, figure: &Figure, module: &str) -> Result<(BTreeSet<String>, BTreeSet<String>)> {
        // The driver (`mod.rs`) is read but not followed: it names every module. It renders a
        // model's file, with a colour bar for a curvature picture.
        let mut modules = BTreeSet::from([module.to_owned()]);
        if matches!(figure.format, Format::Glb | Format::Webp) || !figure.views.is_empty() {
            modules.extend(["renders".to_owned(), "surfaces".to_owned()]);
        }
        let mut files = self.reach(modules);
        files.insert("xtask/src/figures/mod.rs".to_owned());
        let mut all: BTreeSet<String> = files.iter().cloned().collect();
        let text: String = files.iter().map(|f| self.sources[f].as_str()).collect();
        let crates = crates_below(&self.root, &crates_named(&text))?;
        for krate in &crates {
            let dir = self.root.join("crates").join(&krate);
            all.insert(format!("crates/{krate}/Cargo.toml"));
            for file in files_under(&dir.join("src"))? {
                all.insert(self.relative(&file));
            }
        }
        if text.contains("fixtures") {
            for file in files_under(&self.root.join("fixtures"))? {
                all.insert(self.relative(&file));
            }
        }
        Ok((all, crates))
    }

    /// The source files of the figure modules in `start` and of every module they name, to a
    /// fixed point; paths relative to the root.
    fn reach(&self, start: BTreeSet<String>) -> BTreeSet<String> {
        const DIR: &str = "xtask/src/figures/";
        let module_of = |path: &str| -> Option<String> {
            let rest = path.strip_prefix(DIR)?;
            let name = rest.split('/').next()?;
            Some(name.trim_end_matches(".rs").to_owned())
        };
        let known: BTreeSet<String> =
            self.sources.keys().filter_map(|p| module_of(p)).filter(|m| m != "mod").collect();
        let mut modules = start;
        loop {
            let files: BTreeSet<String> = self
                .sources
                .keys()
                .filter(|p| module_of(p).is_some_and(|m| modules.contains(&m)))
                .cloned()
                .collect();
            let mut grown = modules.clone();
            for file in &files {
                let text = &self.sources[file];
                grown.extend(known.iter().filter(|m| names_module(text, m)).cloned());
                // Code outside the figures (`crate::project_root`, `crate::bench::…`).
                for name in words_after(text, "crate::") {
                    if name != "figures" {
                        grown.insert(format!("../{name}"));
                    }
                }
            }
            if grown == modules {
                let outside = modules.iter().filter_map(|m| m.strip_prefix("../"));
                let outside: Vec<String> = outside
                    .flat_map(|name| {
                        let base = format!("xtask/src/{name}");
                        self.sources
                            .keys()
                            .filter(move |p| {
                                **p == format!("{base}.rs") || p.starts_with(&format!("{base}/"))
                            })
                            .cloned()
                    })
                    .collect();
                let mut all = files;
                all.extend(outside);
                all.insert("xtask/src/main.rs".to_owned());
                return all;
            }
            modules = grown;
        }
    }
}

/// Whether `text` names the figure module `m`: `m::` after a non-word character, or `m` in a
/// `use super::{…}` or `use crate::figures::{…}` list.
fn names_module(text: &str, m: &str) -> bool {
    let path = format!("{m}::");
    let by_path = text.match_indices(&path).any(|(i, _)| {
        !text[..i].chars().next_back().is_some_and(|c| c.is_alphanumeric() || c == '_')
    });
    by_path
        || text.lines().map(str::trim_start).any(|line| {
            (line.starts_with("use super::{") || line.starts_with("use crate::figures::{"))
                && line.split(|c: char| !(c.is_alphanumeric() || c == '_')).any(|w| w == m)
        })
}

/// The identifiers that follow `prefix` in `text`.
fn words_after<'a>(text: &'a str, prefix: &'a str) -> impl Iterator<Item = String> + 'a {
    text.match_indices(prefix).filter_map(move |(i, _)| {
        let rest = &text[i + prefix.len()..];
        let word: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        (!word.is_empty()).then_some(word)
    })
}

/// The `hi-*` crates `text` names (`hi_surface` → `hi-surface`).
fn crates_named(text: &str) -> BTreeSet<String> {
    words_after(text, "hi_").map(|w| format!("hi-{w}")).filter(|c| !c.contains('_')).collect()
}

/// `named` and every `hi-*` crate below them (their manifests' `[dependencies]`), those with a
/// folder under `crates/`.
fn crates_below(root: &Path, named: &BTreeSet<String>) -> Result<BTreeSet<String>> {
    let mut all = BTreeSet::new();
    let mut todo: Vec<String> = named.iter().cloned().collect();
    while let Some(krate) = todo.pop() {
        let manifest = root.join("crates").join(&krate).join("Cargo.toml");
        let Ok(text) = std::fs::read_to_string(&manifest) else { continue };
        if !all.insert(krate) {
            continue;
        }
        let table: toml::Table =
            text.parse().with_context(|| format!("reading {}", manifest.display()))?;
        if let Some(deps) = table.get("dependencies").and_then(toml::Value::as_table) {
            todo.extend(deps.keys().filter(|k| k.starts_with("hi-")).cloned());
        }
    }
    Ok(all)
}

/// Every file under `dir`, sorted; none if it does not exist.
fn files_under(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    if !dir.exists() {
        return Ok(out);
    }
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).with_context(|| format!("listing {}", d.display()))? {
            let path = entry?.path();
            if path.is_dir() {
                stack.push(path);
            } else {
                out.push(path);
            }
        }
    }
    out.sort();
    Ok(out)
}

/// What `program` (or the one the environment variable `var` names, as cargo sets it) prints
/// with `args` in `root`; "" if it cannot be run.
fn run(root: &Path, var: &str, program: &str, args: &[&str]) -> String {
    let program = std::env::var(var).unwrap_or_else(|_| program.to_owned());
    std::process::Command::new(program)
        .args(args)
        .current_dir(root)
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).into_owned())
        .unwrap_or_default()
}

/// The keys recorded in the manifest `path` (none if it is missing or unreadable).
pub(crate) fn recorded(path: &Path) -> BTreeMap<String, String> {
    std::fs::read_to_string(path)
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or_default()
}

/// The manifest's text: one key per figure, by number, sorted.
pub(crate) fn manifest(keys: &BTreeMap<String, String>) -> String {
    let mut text = serde_json::to_string_pretty(keys).unwrap_or_default();
    text.push('\n');
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modules_are_named_by_path_or_in_use_lists() {
        assert!(names_module("let p = plot::Plot::new();", "plot"));
        assert!(names_module("use super::{Figure, data, glb};", "glb"));
        assert!(!names_module("use super::{Figure, data};", "glb"));
        assert!(!names_module("hi_bezier::Aabb", "bezier"), "a crate is not the module");
        assert_eq!(crates_named("hi_surface::sphere(hi_curve::X); hi_mesh"), {
            ["hi-curve", "hi-mesh", "hi-surface"].map(str::to_owned).into_iter().collect()
        });
    }

    /// A curve plot reads no renderer and no scan code; a model's render reads the renderer
    /// and every crate below it; a change to one of a figure's files changes its key and no
    /// other figure's.
    #[test]
    fn a_figure_reads_what_it_can_reach() {
        let root = crate::project_root();
        let mut inputs = Inputs::read(&root).expect("the sources");
        let find = |label: &str| {
            super::super::modules()
                .into_iter()
                .flat_map(|(m, f)| f.iter().map(move |f| (m, *f)))
                .find(|(_, f)| f.label() == label)
                .expect("a figure")
        };
        let (plot_module, plot) = find("2.10");
        let (model_module, model) = find("4.11");
        let (plot_files, plot_crates) = inputs.files(&plot, plot_module).unwrap();
        let (model_files, _) = inputs.files(&model, model_module).unwrap();
        let packages = inputs.packages(plot_crates);
        assert!(packages.contains("\nplotters v"), "{packages}");
        assert!(packages.contains("hi-curve v"), "{packages}");
        assert!(!packages.contains("hi-raytrace v"), "{packages}");
        assert!(!packages.contains("obvhs v"), "only the renderer brings in obvhs: {packages}");
        let under = |files: &BTreeSet<String>, dir: &str| files.iter().any(|f| f.starts_with(dir));
        assert!(under(&plot_files, "crates/hi-curve/src/"), "{plot_files:?}");
        assert!(!under(&plot_files, "crates/hi-raytrace/"), "{plot_files:?}");
        assert!(!under(&plot_files, "crates/hi-scan/"), "{plot_files:?}");
        assert!(under(&model_files, "crates/hi-raytrace/src/"), "{model_files:?}");
        assert!(under(&model_files, "crates/hi-interval/src/"), "below hi-raytrace");
        assert!(model_files.contains("xtask/src/figures/renders.rs"));
        let (plot_key, model_key) =
            (inputs.key(&plot, plot_module).unwrap(), inputs.key(&model, model_module).unwrap());
        // The renderer's file changes: the model's key changes, the plot's does not.
        let lib = "crates/hi-raytrace/src/lib.rs".to_owned();
        inputs.digests.insert(lib, [7; 32]);
        assert_ne!(inputs.key(&model, model_module).unwrap(), model_key);
        assert_eq!(inputs.key(&plot, plot_module).unwrap(), plot_key);
    }
}
