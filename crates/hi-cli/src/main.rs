// SPDX-License-Identifier: MIT
//! `hi`: the harmonic curves and surfaces of A. Hardy's 2005 thesis on the command line, with
//! JSON in and out ([`hi_cli::run`]; `hi --help` and `hi COMMAND --help` give every option).

use std::process::ExitCode;

/// mimalloc keeps the memory of one stage for the next (the system allocator hands large
/// blocks back and faults them in again): `hi fit` of a 35k-point scan, 0.43 → 0.36 s.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    hi_cli::run()
}
