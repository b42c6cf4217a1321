// SPDX-License-Identifier: MIT
//! Rigorous interval arithmetic for the `harmonic` workspace.
//!
//! This crate will hold `Interval`, a closed interval of `f64` whose every operation rounds
//! outward (with `f64::next_down`/`f64::next_up`), enclosures of the elementary functions the
//! harmonic basis needs (sin, cos, sqrt, powers), interval boxes in two and three dimensions,
//! and interval Newton (Krawczyk) and bisection root isolation, as §5.6 of Hardy's thesis uses
//! them to ray-trace harmonic surfaces.
//!
//! It is a foundation crate: it depends on no other `hi-*` crate. Nothing is implemented yet.
