// SPDX-License-Identifier: MIT
//! What the workspace's tests share: the one configuration of the property tests
//! ([`proptest_config`]), the one rule for checks that need something outside the
//! repository, a peer program or a data set ([`skip`], [`shared_model`], [`cgal_demo_data`]),
//! and the points spread evenly over the sphere that the fitting tests sample
//! ([`fibonacci_sphere`]).
//! Only the tests and `xtask` depend on this crate (by path), so nothing here reaches a user of
//! the libraries.

use proptest::test_runner::{Config, RngSeed};

/// The seed of every property test unless `PROPTEST_RNG_SEED` names another (a fixed seed, so
/// that a run is the same on every machine).
pub const SEED: u64 = 20_051_122;

/// The configuration of a property test: `cases` cases from the fixed [`SEED`], unless the
/// environment asks for others (`PROPTEST_CASES`, `PROPTEST_RNG_SEED`), and no failure files
/// written into the source tree (a failure found is kept as a named test instead).
///
/// ```
/// let config = hi_testkit::proptest_config(64);
/// assert!(config.failure_persistence.is_none());
/// if std::env::var_os("PROPTEST_CASES").is_none() {
///     assert_eq!(config.cases, 64);
/// }
/// ```
#[must_use]
pub fn proptest_config(cases: u32) -> Config {
    let mut config = Config::default();
    if std::env::var_os("PROPTEST_CASES").is_none() {
        config.cases = cases;
    }
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(SEED);
    }
    config.failure_persistence = None;
    config
}

/// `n` unit directions spread evenly over the sphere (a Fibonacci lattice): point k at height
/// z = 1 − (2k + 1)/n, turned by k·π(3 − √5) (the golden angle) about the z axis.
///
/// ```
/// let points: Vec<[f64; 3]> = hi_testkit::fibonacci_sphere(1000).collect();
/// assert_eq!(points.len(), 1000);
/// // On the unit sphere, as many above the equator as below, centred at the origin.
/// assert!(points.iter().all(|p| (p[0].hypot(p[1]).hypot(p[2]) - 1.0).abs() < 1e-12));
/// assert_eq!(points.iter().filter(|p| p[2] > 0.0).count(), 500);
/// let mean: f64 = points.iter().map(|p| p[0] + p[1] + p[2]).sum::<f64>() / 1000.0;
/// assert!(mean.abs() < 1e-2);
/// ```
pub fn fibonacci_sphere(n: usize) -> impl Iterator<Item = [f64; 3]> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n).map(move |k| {
        let z = 1.0 - (2 * k + 1) as f64 / n as f64;
        let s = (1.0 - z * z).sqrt();
        let phi = k as f64 * golden;
        [s * phi.cos(), s * phi.sin(), z]
    })
}

/// The next of a linear congruential sequence (Knuth's MMIX constants) from `seed`, which it
/// advances: uniform in [0, 1), its 53 highest bits.
///
/// ```
/// let mut seed = 1;
/// let xs: Vec<f64> = (0..10_000).map(|_| hi_testkit::lcg(&mut seed)).collect();
/// assert!(xs.iter().all(|x| (0.0..1.0).contains(x)));
/// assert!((xs.iter().sum::<f64>() / 10_000.0 - 0.5).abs() < 0.01);
/// ```
pub fn lcg(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// `n` points about the unit sphere: the directions of [`fibonacci_sphere`], each at the radius
/// 1 + σ g, g a standard normal deviate (Box–Muller on a linear congruential sequence started
/// from `seed`): a noisy scan whose noise is known.
///
/// ```
/// let points = hi_testkit::noisy_sphere(20_000, 0.05, 7);
/// let radii: Vec<f64> = points.iter().map(|p| p[0].hypot(p[1]).hypot(p[2])).collect();
/// let mean = radii.iter().sum::<f64>() / 20_000.0;
/// let sd = (radii.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / 20_000.0).sqrt();
/// assert!((mean - 1.0).abs() < 0.002 && (sd / 0.05 - 1.0).abs() < 0.03, "{mean} {sd}");
/// ```
#[must_use]
pub fn noisy_sphere(n: usize, sigma: f64, seed: u64) -> Vec<[f64; 3]> {
    let mut state = seed;
    // In (0, 1), for the logarithm.
    let mut uniform = move || lcg(&mut state) + 0.5 / (1u64 << 53) as f64;
    fibonacci_sphere(n)
        .map(|p| {
            let (u, v) = (uniform(), uniform());
            let r = 1.0 + sigma * (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos();
            p.map(|x| r * x)
        })
        .collect()
}

/// The variable that makes every check needing something outside the repository run (a peer
/// program, a data set): `HI_REQUIRE_PEERS=1`, as CI sets. Without it, such a check that cannot
/// run says so and passes.
pub const REQUIRE_PEERS: &str = "HI_REQUIRE_PEERS";

/// The variable that tells the checks reading the shared models (`../shared/data/models`,
/// beside the repository) to skip them even under [`REQUIRE_PEERS`]: for a machine that cannot
/// have that folder, which then says so.
pub const SKIP_SHARED_DATA: &str = "HI_SKIP_SHARED_DATA";

/// Debian's `libcgal-demo` data: meshes and point sets of every topology, read where installed
/// and never committed.
pub const CGAL_DEMO_DATA: &str = "/usr/share/doc/libcgal-demo/data.tar.gz";

fn set(variable: &str) -> bool {
    std::env::var(variable).is_ok_and(|v| v == "1")
}

/// Whether the checks that need something outside the repository must run
/// ([`REQUIRE_PEERS`]`=1`).
#[must_use]
pub fn peers_required() -> bool {
    set(REQUIRE_PEERS)
}

/// Says that a check is skipped because `what` is missing, on standard error; a failure
/// instead when [`peers_required`].
///
/// # Panics
///
/// When [`REQUIRE_PEERS`]`=1`: a check that must run could not.
#[track_caller]
pub fn skip(what: &str) {
    assert!(!peers_required(), "{REQUIRE_PEERS}=1, but {what}");
    eprintln!("skipped: {what}");
}

/// The workspace's root directory.
#[must_use]
pub fn workspace_root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The folder of third-party models beside the repository (`../shared/data/models`), if it is
/// there. Where it is not, the check is skipped ([`skip`]: a failure under [`REQUIRE_PEERS`]),
/// unless [`SKIP_SHARED_DATA`]`=1` says the machine cannot have it.
///
/// # Panics
///
/// When the folder is absent, [`REQUIRE_PEERS`]`=1` and [`SKIP_SHARED_DATA`] is not set.
#[track_caller]
#[must_use]
pub fn shared_models() -> Option<std::path::PathBuf> {
    let dir = workspace_root().join("../shared/data/models");
    if dir.is_dir() {
        return Some(dir);
    }
    if set(SKIP_SHARED_DATA) {
        eprintln!("skipped, as {SKIP_SHARED_DATA}=1 asks: the shared models are not here");
    } else {
        skip(&format!(
            "the shared models (../shared/data/models) are absent; {SKIP_SHARED_DATA}=1 skips \
             their checks on a machine that cannot have them"
        ));
    }
    None
}

/// The model `file` of [`shared_models`], if the folder is there; a missing file in a present
/// folder is skipped as [`skip`] says.
///
/// # Panics
///
/// As [`shared_models`], and when the folder is there without the file under
/// [`REQUIRE_PEERS`]`=1`.
#[track_caller]
#[must_use]
pub fn shared_model(file: &str) -> Option<std::path::PathBuf> {
    let path = shared_models()?.join(file);
    if path.is_file() {
        Some(path)
    } else {
        skip(&format!("the shared model {file} is absent"));
        None
    }
}

/// [`CGAL_DEMO_DATA`], if `libcgal-demo` is installed; else the check is skipped ([`skip`]).
///
/// # Panics
///
/// When the archive is absent and [`REQUIRE_PEERS`]`=1`.
#[track_caller]
#[must_use]
pub fn cgal_demo_data() -> Option<std::path::PathBuf> {
    let path = std::path::PathBuf::from(CGAL_DEMO_DATA);
    if path.is_file() {
        Some(path)
    } else {
        skip(&format!("{CGAL_DEMO_DATA} is absent (Debian's libcgal-demo)"));
        None
    }
}
