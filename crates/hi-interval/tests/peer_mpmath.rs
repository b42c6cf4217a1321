// SPDX-License-Identifier: MIT
//! Inclusion property against an independent multi-precision reference: mpmath's `iv` at 160
//! bits (docs/peers.md §6), through `fixtures/interval/mpmath_interval.py`.
//!
//! For every operation, 10⁵ seeded random and adversarial cases (next to multiples of π/2, tiny,
//! subnormal, huge, signed zeros, exact points, infinite ends) are sent to the script, which
//! returns the tightest double interval containing mpmath's enclosure. Each of our results must
//! contain it, and may be wider by at most a few ulps per end (0 for the correctly rounded
//! operations). The live check needs `python3` with `mpmath`: without it the check says so and
//! passes, unless `HI_REQUIRE_PEERS=1` is set (as CI does), when it fails. The committed fixture
//! `fixtures/interval/mpmath_small.json` (written by the same script) is checked always.
//!
//! `HI_PEER_CASES=N` changes the number of live cases per operation; `HI_UPDATE_FIXTURES=1`
//! rewrites the small fixture.

use std::fmt::Write as _;
use std::io::Write as _;
use std::process::{Command, Stdio};

use hi_interval::Interval;

const FIXTURE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/interval");

/// xorshift64*: a small seeded generator, so the cases need no dependency and are reproducible.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn uniform(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn sign(&mut self) -> f64 {
        if self.next() & 1 == 0 { 1.0 } else { -1.0 }
    }
    /// 2^e for e uniform in [lo, hi), times a random mantissa.
    fn log_uniform(&mut self, lo: i32, hi: i32) -> f64 {
        let e = lo + self.below((hi - lo) as u64) as i32;
        let m = 1.0 + self.uniform();
        // Build 2^e in two steps so that subnormal powers are exact.
        m * 2f64.powi(e / 2) * 2f64.powi(e - e / 2)
    }
}

fn step_ulps(x: f64, k: i64) -> f64 {
    let mut x = x;
    for _ in 0..k.unsigned_abs() {
        x = if k > 0 { x.next_up() } else { x.next_down() };
    }
    x
}

/// One double from a mix of ordinary and adversarial distributions.
fn double(rng: &mut Rng, op: &str) -> f64 {
    let x = match rng.below(8) {
        0 | 1 => (rng.uniform() * 2.0 - 1.0) * 10.0,
        2 => rng.sign() * rng.log_uniform(-1074, 1024),
        3 => {
            // Next to a multiple of π/2, a few ulps either side.
            let k = if rng.below(4) == 0 { rng.below(1 << 40) } else { rng.below(2000) } as f64;
            let base = rng.sign() * k * std::f64::consts::FRAC_PI_2;
            step_ulps(base, rng.below(7) as i64 - 3)
        }
        4 => {
            const SPECIAL: [f64; 14] = [
                0.0,
                -0.0,
                1.0,
                -1.0,
                0.5,
                2.0,
                f64::MAX,
                -f64::MAX,
                f64::MIN_POSITIVE,
                5e-324,
                -5e-324,
                1e300,
                -1e300,
                std::f64::consts::PI,
            ];
            SPECIAL[rng.below(SPECIAL.len() as u64) as usize]
        }
        5 => rng.sign() * rng.log_uniform(-1074, -1000),
        6 => rng.sign() * (rng.below(1 << 20) as f64) / f64::from(1 << rng.below(20) as i32),
        _ => rng.sign() * rng.log_uniform(-40, 40),
    };
    match op {
        // Keep exp mostly in its interesting range.
        "exp" if rng.below(4) != 0 => (rng.uniform() * 2.0 - 1.0) * 760.0,
        _ => x,
    }
}

/// One interval built around a random double.
fn interval(rng: &mut Rng, op: &str) -> (f64, f64) {
    let x = double(rng, op);
    let (lo, hi) =
        match rng.below(8) {
            0 => (x, x),
            1 => (x, step_ulps(x, 1 + rng.below(4) as i64)),
            2 => (x, x + rng.log_uniform(-60, 4)),
            3 => (x - rng.log_uniform(-60, 4), x),
            4 => {
                let y = double(rng, op);
                (x.min(y), x.max(y))
            }
            5 => {
                if rng.below(2) == 0 {
                    (x.min(-0.0), x.max(0.0))
                } else {
                    (x.min(0.0), x.max(-0.0))
                }
            }
            6 if matches!(op, "add" | "sin" | "cos" | "exp" | "atan" | "ln") => {
                if rng.below(2) == 0 { (x, f64::INFINITY) } else { (f64::NEG_INFINITY, x) }
            }
            _ => (x, x + rng.uniform() * 7.0),
        };
    if lo.is_nan() || hi.is_nan() || lo == f64::INFINITY || hi == f64::NEG_INFINITY || lo > hi {
        (x, x)
    } else {
        (lo, hi)
    }
}

#[derive(Clone, Debug)]
struct Case {
    op: String,
    a: (f64, f64),
    b: Option<(f64, f64)>,
    n: Option<i32>,
}

fn hex(x: f64) -> String {
    format!("{:016x}", x.to_bits())
}

fn unhex(s: &str) -> f64 {
    f64::from_bits(u64::from_str_radix(s, 16).expect("16 hex digits"))
}

impl Case {
    fn line(&self) -> String {
        let mut s = format!("{} {} {}", self.op, hex(self.a.0), hex(self.a.1));
        if let Some(b) = self.b {
            write!(s, " {} {}", hex(b.0), hex(b.1)).expect("string");
        }
        if let Some(n) = self.n {
            write!(s, " {n}").expect("string");
        }
        s
    }

    fn parse(line: &str) -> Self {
        let f: Vec<&str> = line.split_whitespace().collect();
        let a = (unhex(f[1]), unhex(f[2]));
        let (b, n) = match (f[0], f.len()) {
            ("add" | "sub" | "mul" | "div", 5) => (Some((unhex(f[3]), unhex(f[4]))), None),
            ("powi", 4) => (None, Some(f[3].parse().expect("exponent"))),
            _ => (None, None),
        };
        Self { op: f[0].to_string(), a, b, n }
    }

    fn ours(&self) -> Interval {
        let a = Interval::new(self.a.0, self.a.1);
        let b = self.b.map(|b| Interval::new(b.0, b.1)).unwrap_or(Interval::EMPTY);
        match self.op.as_str() {
            "add" => a + b,
            "sub" => a - b,
            "mul" => a * b,
            "div" => a / b,
            "sqr" => a.sqr(),
            "powi" => a.powi(self.n.expect("exponent")),
            "sqrt" => a.sqrt(),
            "sin" => a.sin(),
            "cos" => a.cos(),
            "exp" => a.exp(),
            "ln" => a.ln(),
            "atan" => a.atan(),
            other => panic!("unknown op {other}"),
        }
    }
}

const OPS: [&str; 12] =
    ["add", "sub", "mul", "div", "sqr", "powi", "sqrt", "sin", "cos", "exp", "ln", "atan"];

fn cases(op: &str, n_cases: usize, seed: u64) -> Vec<Case> {
    let mut rng = Rng(seed ^ (op.bytes().fold(0u64, |h, c| h.wrapping_mul(131) + u64::from(c))));
    let mut res = Vec::with_capacity(n_cases);
    while res.len() < n_cases {
        let a = interval(&mut rng, op);
        let mut case = Case { op: op.to_string(), a, b: None, n: None };
        match op {
            "add" | "sub" | "mul" => case.b = Some(interval(&mut rng, op)),
            "div" => {
                let b = interval(&mut rng, op);
                if b.0 <= 0.0 && 0.0 <= b.1 {
                    continue; // Division by intervals holding 0 is checked in unit tests.
                }
                case.b = Some(b);
            }
            "powi" => {
                const NS: [i32; 10] = [2, 3, 4, 5, 7, 10, 17, -1, -2, -3];
                let n = NS[rng.below(NS.len() as u64) as usize];
                if n < 0 && a.0 <= 0.0 && 0.0 <= a.1 {
                    continue;
                }
                case.n = Some(n);
            }
            _ => {}
        }
        res.push(case);
    }
    res
}

/// Distance in ulps (steps of `next_up`) from x to y, y ≥ x; `u64::MAX` if one is infinite and
/// the other is not.
fn ulps_between(x: f64, y: f64) -> u64 {
    if x == y {
        return 0;
    }
    if x.is_infinite() || y.is_infinite() {
        return u64::MAX;
    }
    let ord = |v: f64| -> i64 {
        let b = v.to_bits() as i64;
        if b < 0 { i64::MIN - b } else { b }
    };
    (ord(y) - ord(x)).unsigned_abs()
}

/// Largest excess allowed per end, in ulps.
fn allowed_excess(case: &Case) -> u64 {
    match case.op.as_str() {
        // Correctly rounded bounds; in the subnormal range the exactness test is skipped (1 ulp).
        "add" | "sub" | "mul" | "div" | "sqr" | "sqrt" => 1,
        // One rounding per multiplication of the binary powering.
        "powi" => 2 * u64::from(case.n.expect("n").unsigned_abs()) + 2,
        // libm values widened by LIBM_ULPS = 2 on top of an error below 1 ulp.
        _ => 4,
    }
}

/// Is every nonzero number of the case and its reference at least 1e-280 in magnitude? Outside
/// that range the error-free transformations may underflow and we round 1 ulp blindly.
fn normal_range(case: &Case, ours: Interval, lo: f64, hi: f64) -> bool {
    let b = case.b.unwrap_or((1.0, 1.0));
    [case.a.0, case.a.1, b.0, b.1, lo, hi, ours.lo(), ours.hi()]
        .iter()
        .all(|v| *v == 0.0 || v.abs() >= 1e-280)
}

/// Largest excess per end (in ulps) of our bounds over the reference: over all cases, and over
/// the cases in the normal range (see [`normal_range`]).
#[derive(Clone, Copy, Debug, Default)]
struct Excess {
    all: u64,
    normal: u64,
}

/// Checks our results against reference lines; returns the max excess per end and failures.
fn check(cases: &[Case], refs: &[String]) -> (Excess, Vec<String>) {
    let mut worst = Excess::default();
    let mut failures = Vec::new();
    for (case, r) in cases.iter().zip(refs) {
        let ours = case.ours();
        if r.trim() == "empty" {
            if !ours.is_empty() {
                failures.push(format!("{}: reference empty, ours {ours}", case.line()));
            }
            continue;
        }
        let f: Vec<&str> = r.split_whitespace().collect();
        let (lo, hi) = (unhex(f[0]), unhex(f[1]));
        if ours.is_empty() || ours.lo() > lo || ours.hi() < hi {
            failures
                .push(format!("{}: reference [{lo:e}, {hi:e}] not in ours {ours}", case.line()));
            continue;
        }
        let excess = ulps_between(ours.lo(), lo).max(ulps_between(hi, ours.hi()));
        if excess > allowed_excess(case) {
            failures.push(format!(
                "{}: ours {ours} is {excess} ulps wider than [{lo:e}, {hi:e}]",
                case.line()
            ));
        }
        worst.all = worst.all.max(excess);
        if normal_range(case, ours, lo, hi) {
            worst.normal = worst.normal.max(excess);
        }
    }
    (worst, failures)
}

fn run_script(input: &str, extra: &[&str]) -> Result<String, String> {
    let script = format!("{FIXTURE_DIR}/mpmath_interval.py");
    let child = Command::new("python3")
        .arg(&script)
        .args(extra)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let output = child.and_then(|mut c| {
        // Write from another thread: the script answers while it reads, and a full stdout pipe
        // would otherwise block both sides.
        let mut stdin = c.stdin.take().expect("piped");
        let input = input.to_string();
        let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
        let out = c.wait_with_output()?;
        writer.join().expect("writer thread")?;
        Ok(out)
    });
    match output {
        Ok(o) if o.status.success() => Ok(String::from_utf8_lossy(&o.stdout).into_owned()),
        Ok(o) => Err(String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("").to_string()),
        Err(e) => Err(e.to_string()),
    }
}

fn live(op: &str) {
    let n_cases =
        std::env::var("HI_PEER_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(100_000usize);
    let cases = cases(op, n_cases, 0x5eed_2005);
    let input: String = cases.iter().map(|c| c.line() + "\n").collect();
    let required = hi_testkit::peers_required();
    let reply = match run_script(&input, &[]) {
        Ok(r) => r,
        Err(why) => {
            assert!(!required, "HI_REQUIRE_PEERS=1 but python3 with mpmath is not usable: {why}");
            eprintln!(
                "live mpmath check of {op} skipped: python3 with mpmath is not usable ({why})"
            );
            return;
        }
    };
    let refs: Vec<String> = reply.lines().map(str::to_string).collect();
    assert_eq!(refs.len(), cases.len(), "one answer per case");
    let (worst, failures) = check(&cases, &refs);
    let n_points = cases.iter().filter(|c| c.a.0 == c.a.1).count();
    eprintln!(
        "mpmath iv {op}: {} cases ({n_points} point arguments), max excess per end {} ulp \
         ({} ulp in the normal range), {} failures",
        cases.len(),
        worst.all,
        worst.normal,
        failures.len()
    );
    assert!(
        failures.is_empty(),
        "{} failures, first: {:#?}",
        failures.len(),
        &failures[..failures.len().min(10)]
    );
}

macro_rules! live_tests {
    ($($name:ident: $op:literal),*) => {$(
        #[test]
        fn $name() {
            live($op);
        }
    )*};
}

live_tests!(
    live_add: "add", live_sub: "sub", live_mul: "mul", live_div: "div", live_sqr: "sqr",
    live_powi: "powi", live_sqrt: "sqrt", live_sin: "sin", live_cos: "cos", live_exp: "exp",
    live_ln: "ln", live_atan: "atan"
);

#[test]
fn fixture_from_mpmath_holds() {
    let path = format!("{FIXTURE_DIR}/mpmath_small.json");
    if std::env::var("HI_UPDATE_FIXTURES").is_ok_and(|v| v == "1") {
        let input: String = OPS
            .iter()
            .flat_map(|op| cases(op, 200, 0xf1c5_2005))
            .map(|c| c.line() + "\n")
            .collect();
        run_script(&input, &["--fixture", &path]).expect("python3 with mpmath writes the fixture");
    }
    let text = std::fs::read_to_string(&path).expect("committed fixture");
    let doc: serde_json::Value = serde_json::from_str(&text).expect("fixture is JSON");
    let entries = doc["cases"].as_array().expect("cases");
    let cases: Vec<Case> =
        entries.iter().map(|e| Case::parse(e[0].as_str().expect("case"))).collect();
    let refs: Vec<String> =
        entries.iter().map(|e| e[1].as_str().expect("reference").to_string()).collect();
    for op in OPS {
        assert!(cases.iter().filter(|c| c.op == op).count() >= 200, "{op} is covered");
    }
    let (worst, failures) = check(&cases, &refs);
    assert!(failures.is_empty(), "{failures:#?}");
    eprintln!("fixture: {} cases, max excess {worst:?} ulp", cases.len());
}
