// SPDX-License-Identifier: MIT
//! What the workspace's tests share. Only the tests depend on this crate (a dev-dependency by
//! path), so nothing here reaches a user of the libraries.

use proptest::test_runner::{Config, RngSeed};

/// The seed of every property test unless `PROPTEST_RNG_SEED` names another: the date of the
/// thesis, 2005-11-22.
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
