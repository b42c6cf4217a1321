// SPDX-License-Identifier: MIT
//! Hobby's algorithm against METAPOST itself (docs/peers.md §1) and against analytic truths
//! (Hardy 2005, §2.14).
//!
//! Two peer checks: the committed fixture (cases and `mpost -numbersystem=double`'s control
//! points, written by `fixtures/curve/mpost_hobby.py --fixture`), and a live run of mpost on
//! fresh seeded cases when mpost is installed. Without mpost the live check says so and passes,
//! unless `HI_REQUIRE_PEERS=1` is set (as CI does), when it fails.

use std::f64::consts::PI;
use std::io::Write;
use std::process::{Command, Stdio};

use glam::DVec2;
use hi_compare::hobby::{HobbyCurve, HobbyOptions, Join, Tension, rho};
use hi_curve::ParamCurve;
use serde_json::{Value, json};

const FIXTURE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/curve");

/// Agreement required with METAPOST, relative to the size of the coordinates.
const TOLERANCE: f64 = 1e-9;

fn number(v: &Value) -> f64 {
    v.as_f64().expect("number")
}

fn tension(v: f64) -> Tension {
    if v < 0.0 { Tension::at_least(-v) } else { Tension::new(v) }
}

/// A case in the JSON format of `mpost_hobby.py`.
#[derive(Clone, Debug)]
struct Case {
    name: String,
    points: Vec<DVec2>,
    closed: bool,
    curls: (f64, f64),
    joins: Vec<(f64, f64)>,
}

impl Case {
    fn from_json(v: &Value) -> Self {
        let points = v["points"]
            .as_array()
            .expect("points")
            .iter()
            .map(|p| DVec2::new(number(&p[0]), number(&p[1])))
            .collect();
        let joins = v["joins"].as_array().map_or_else(Vec::new, |js| {
            js.iter().map(|j| (number(&j[0]), number(&j[1]))).collect()
        });
        Case {
            name: v["name"].as_str().expect("name").to_string(),
            points,
            closed: v["closed"].as_bool().expect("closed"),
            curls: (v.get("start_curl").map_or(1.0, number), v.get("end_curl").map_or(1.0, number)),
            joins,
        }
    }

    fn to_json(&self) -> Value {
        json!({
            "name": self.name,
            "points": self.points.iter().map(|p| [p.x, p.y]).collect::<Vec<_>>(),
            "closed": self.closed,
            "start_curl": self.curls.0,
            "end_curl": self.curls.1,
            "joins": self.joins.iter().map(|&(a, b)| [a, b]).collect::<Vec<_>>(),
        })
    }

    fn curve(&self) -> HobbyCurve {
        let config = if self.closed { HobbyOptions::closed() } else { HobbyOptions::open() }
            .with_curls(self.curls.0, self.curls.1)
            .with_joins(
                self.joins.iter().map(|&(a, b)| Join::new(tension(a), tension(b))).collect(),
            );
        HobbyCurve::try_new(self.points.clone(), &config)
            .unwrap_or_else(|e| panic!("{}: {e}", self.name))
    }

    /// Largest coordinate, at least 1: the scale of the absolute tolerance.
    fn size(&self) -> f64 {
        self.points.iter().map(|p| p.abs().max_element()).fold(1.0, f64::max)
    }
}

/// Largest coordinate difference between our knots and METAPOST's rows
/// [x, y, prex, prey, postx, posty].
fn difference(curve: &HobbyCurve, rows: &Value) -> f64 {
    let rows = rows.as_array().expect("rows");
    assert_eq!(rows.len(), curve.knots().len(), "knot count");
    let mut worst = 0.0f64;
    for (knot, row) in curve.knots().iter().zip(rows) {
        let ours = [
            knot.point.x,
            knot.point.y,
            knot.precontrol.x,
            knot.precontrol.y,
            knot.postcontrol.x,
            knot.postcontrol.y,
        ];
        for (a, b) in ours.iter().zip(row.as_array().expect("row")) {
            worst = worst.max((a - number(b)).abs());
        }
    }
    worst
}

#[test]
fn fixture_from_metapost_matches() {
    let text = std::fs::read_to_string(format!("{FIXTURE_DIR}/mpost_hobby.json")).expect("fixture");
    let fixture: Value = serde_json::from_str(&text).expect("fixture is JSON");
    let cases = fixture["cases"].as_array().expect("cases");
    assert!(cases.len() >= 60, "fixture has {} cases", cases.len());
    let (mut closed, mut open, mut worst) = (0, 0, 0.0f64);
    for v in cases {
        let case = Case::from_json(v);
        let err = difference(&case.curve(), &v["knots"]) / case.size();
        assert!(err < TOLERANCE, "{}: differs from METAPOST by {err:e}", case.name);
        worst = worst.max(err);
        if case.closed { closed += 1 } else { open += 1 }
    }
    assert!(closed > 20 && open > 20, "{closed} closed and {open} open cases");
    eprintln!("fixture: {} cases, worst relative difference {worst:.2e}", cases.len());
    // The transcription follows METAPOST's double arithmetic: only the radian/degree
    // conversions and library trigonometry differ.
    assert!(worst < 1e-13, "worst relative difference {worst:e}");
}

/// A small deterministic generator (xorshift64*), so the live check needs no dependency.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let u = (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * u
    }
}

fn live_cases() -> Vec<Case> {
    let mut rng = Rng(0x2005_1122_dead_beef);
    let mut cases = Vec::new();
    for trial in 0..40 {
        let n = 2 + trial % 11;
        let star = trial % 2 == 0;
        let points: Vec<DVec2> = (0..n)
            .map(|k| {
                if star {
                    let a = 2.0 * PI * (k as f64 + rng.uniform(-0.3, 0.3)) / n as f64;
                    DVec2::from_angle(a) * rng.uniform(0.2, 5.0)
                } else {
                    DVec2::new(rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0))
                }
            })
            .collect();
        let closed = trial % 3 != 0;
        let n_joins = if closed { n } else { n - 1 };
        let joins = match trial % 4 {
            0 => Vec::new(),
            1 => vec![(1.5, 1.5); n_joins],
            _ => (0..n_joins)
                .map(|_| {
                    let mut a = rng.uniform(0.75, 4.0);
                    let mut b = rng.uniform(0.75, 4.0);
                    if rng.uniform(0.0, 1.0) < 0.25 {
                        a = -a;
                    }
                    if rng.uniform(0.0, 1.0) < 0.25 {
                        b = -b;
                    }
                    (a, b)
                })
                .collect(),
        };
        let curls = (rng.uniform(0.0, 3.0), rng.uniform(0.0, 3.0));
        cases.push(Case { name: format!("live case {trial}"), points, closed, curls, joins });
    }
    cases
}

#[test]
fn live_metapost_matches() {
    let cases = live_cases();
    let input = json!({"cases": cases.iter().map(Case::to_json).collect::<Vec<_>>()});
    let script = format!("{FIXTURE_DIR}/mpost_hobby.py");
    let required = hi_testkit::peers_required();
    let child = Command::new("python3")
        .arg(&script)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let output = child.and_then(|mut c| {
        c.stdin.take().expect("piped").write_all(input.to_string().as_bytes())?;
        c.wait_with_output()
    });
    let output = match output {
        Ok(o) if o.status.success() => o,
        other => {
            let why = match other {
                Ok(o) => {
                    String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("").to_string()
                }
                Err(e) => e.to_string(),
            };
            assert!(!required, "HI_REQUIRE_PEERS=1 but python3 with mpost is not usable: {why}");
            eprintln!("live METAPOST check skipped: python3 with mpost is not usable ({why})");
            return;
        }
    };
    let reply: Value = serde_json::from_slice(&output.stdout).expect("mpost reply is JSON");
    let results = reply["results"].as_array().expect("results");
    assert_eq!(results.len(), cases.len(), "one result per case");
    let mut worst = 0.0f64;
    for (case, rows) in cases.iter().zip(results) {
        let err = difference(&case.curve(), rows) / case.size();
        assert!(err < TOLERANCE, "{}: differs from METAPOST by {err:e}", case.name);
        worst = worst.max(err);
    }
    eprintln!(
        "live {} check: {} cases, worst relative difference {worst:.2e}",
        reply["mpost"],
        cases.len()
    );
}

#[test]
fn regular_heptagon_arms_are_rho_times_chord() {
    // docs/peers.md §1: every control arm of METAPOST's regular heptagon is ρ(π/7, π/7)·chord/3.
    let points: Vec<DVec2> = (0..7).map(|k| DVec2::from_angle(2.0 * PI * k as f64 / 7.0)).collect();
    let closed = HobbyCurve::new(points.clone(), &HobbyOptions::closed());
    let arm = 0.304_324_632_520_2;
    let theta = PI / 7.0;
    assert!((rho(theta, theta) / 3.0 * 2.0 * theta.sin() - arm).abs() < 1e-16);
    for knot in closed.knots() {
        assert!(((knot.postcontrol - knot.point).length() - arm).abs() < 1e-15);
        assert!(((knot.precontrol - knot.point).length() - arm).abs() < 1e-15);
        // The arms are tangent to the circle.
        assert!((knot.postcontrol - knot.point).dot(knot.point).abs() < 1e-15);
    }
    // Open, curl 1 reproduces the arcs: the interior knots are the same as in the closed path.
    let open = HobbyCurve::new(points, &HobbyOptions::open());
    for k in 1..6 {
        let (a, b) = (open.knots()[k], closed.knots()[k]);
        assert!((a.precontrol - b.precontrol).length() < 1e-14, "knot {k}");
        assert!((a.postcontrol - b.postcontrol).length() < 1e-14, "knot {k}");
    }
}

#[test]
fn square_gives_a_symmetric_near_circle() {
    // Four points on the unit circle: a curve with the square's symmetries, within 0.03% of
    // the circle (the usual cubic approximation of a quarter circle has arm 4(√2 − 1)/3).
    let square = vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
    let curve = HobbyCurve::new(square, &HobbyOptions::closed());
    let arm = rho(PI / 4.0, PI / 4.0) / 3.0 * 2f64.sqrt();
    assert!((arm - 4.0 * (2f64.sqrt() - 1.0) / 3.0).abs() < 1e-15, "{arm}");
    for (k, knot) in curve.knots().iter().enumerate() {
        assert!(((knot.postcontrol - knot.point).length() - arm).abs() < 1e-15, "knot {k}");
        assert!(((knot.precontrol - knot.point).length() - arm).abs() < 1e-15, "knot {k}");
    }
    for i in 0..400 {
        let t = i as f64 / 400.0;
        let p = curve.eval(t);
        // Rotating by a quarter turn is shifting t by 1/4.
        assert!((curve.eval(t + 0.25) - p.perp()).length() < 1e-15, "t = {t}");
        // Reflection in the x axis is t ↦ −t.
        assert!((curve.eval(-t) - DVec2::new(p.x, -p.y)).length() < 1e-15, "t = {t}");
        assert!((p.length() - 1.0).abs() < 3e-4, "t = {t}: radius {}", p.length());
    }
}

#[test]
fn collinear_knots_give_a_straight_path() {
    let points: Vec<DVec2> =
        [0.0, 1.0, 3.0, 3.5, 7.0].iter().map(|&s| DVec2::new(1.0, 2.0) * s).collect();
    for tension in [Tension::new(1.0), Tension::new(2.5), Tension::at_least(1.0)] {
        let config = HobbyOptions::open().with_tension(tension);
        let curve = HobbyCurve::new(points.clone(), &config);
        for knot in curve.knots() {
            for c in [knot.precontrol, knot.postcontrol] {
                assert!(c.perp_dot(DVec2::new(1.0, 2.0)).abs() < 1e-14, "{c}");
            }
        }
        for i in 0..=200 {
            let p = curve.eval(i as f64 / 200.0);
            assert!(p.perp_dot(DVec2::new(1.0, 2.0)).abs() < 1e-13, "{p}");
        }
        // Monotone along the line: the controls stay between the knots.
        let xs: Vec<f64> = (0..=200).map(|i| curve.eval(i as f64 / 200.0).x).collect();
        assert!(xs.windows(2).all(|w| w[1] >= w[0]), "{tension:?}");
    }
}

#[test]
fn interpolates_and_converts_to_bezier() {
    let points = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(2.0, 3.0),
        DVec2::new(5.0, 1.0),
        DVec2::new(6.0, 6.0),
        DVec2::new(1.0, 4.0),
    ];
    for config in [HobbyOptions::open(), HobbyOptions::closed()] {
        let curve = HobbyCurve::new(points.clone(), &config);
        let s = curve.n_segments();
        assert_eq!(s, if config.closed { 5 } else { 4 });
        assert!(curve.segment(s).is_none());
        for k in 0..=s {
            let expected = points[k % points.len()];
            assert!((curve.eval(k as f64 / s as f64) - expected).length() < 1e-14, "knot {k}");
        }
        let bezier = curve.to_bezier();
        assert_eq!(bezier.segments().len(), s);
        for i in 0..=100 {
            let t = i as f64 / 100.0;
            assert!((bezier.eval(t) - curve.eval(t)).length() < 1e-14, "t = {t}");
        }
        // G¹ at the interior knots: the arms on both sides are collinear.
        let interior = if config.closed { 0..points.len() } else { 1..points.len() - 1 };
        for knot in &curve.knots()[interior] {
            let (a, b) = (knot.point - knot.precontrol, knot.postcontrol - knot.point);
            assert!(a.perp_dot(b).abs() < 1e-13 * a.length() * b.length(), "{knot:?}");
            assert!(a.dot(b) > 0.0, "{knot:?}");
        }
        assert_eq!(curve.is_periodic(), config.closed);
    }
}
