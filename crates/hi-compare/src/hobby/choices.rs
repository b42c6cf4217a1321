// SPDX-License-Identifier: MIT
//! METAPOST's `make_choices`, transcribed (section numbers of `mp.w` as of METAPOST 2.0). Angles
//! are in radians rather than METAPOST's 1/16 degrees, and METAPOST's `fraction` scaling by
//! 4096 is dropped; both only change the rounding at the level of 1e-16.

use glam::DVec2;

use super::HOBBY_A;

/// The kind of one side of a knot (METAPOST's `left_type`/`right_type`), in METAPOST's order
/// `endpoint` < `explicit` < `given` < `curl` < `open` < `end_cycle`. Given directions
/// (`{dir}`) are not offered by this API and never arise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Side {
    /// The end of an open path: no segment on this side.
    Endpoint,
    /// The control point on this side is already known.
    Explicit,
    /// A curl end condition with this curl γ.
    Curl(f64),
    /// To be chosen by the mock-curvature equations.
    Open,
    /// Marks the first knot of a closed path with no breakpoint.
    EndCycle,
}

impl Side {
    /// True for `given`, `curl`, `open` and `end_cycle`: METAPOST's `type >= mp_given`.
    fn is_at_least_given(self) -> bool {
        matches!(self, Side::Curl(_) | Side::Open | Side::EndCycle)
    }
}

/// A knot while its controls are being chosen. Tensions are signed: negative means `atleast`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Knot {
    pub(super) point: DVec2,
    pub(super) left: Side,
    pub(super) right: Side,
    pub(super) left_tension: f64,
    pub(super) right_tension: f64,
    pub(super) pre: DVec2,
    pub(super) post: DVec2,
}

/// Chooses the control points of the cyclic knot list (an open path links its last knot to
/// its first with endpoint sides): METAPOST's `make_choices`.
pub(super) fn make_choices(knots: &mut [Knot]) {
    let n = knots.len();
    let next = |i: usize| (i + 1) % n;
    // Coincident neighbours are joined by a degenerate explicit segment, with curl 1 on the
    // other side of each (§331).
    for p in 0..n {
        let q = next(p);
        if knots[p].point == knots[q].point && knots[p].right.is_at_least_given() {
            knots[p].right = Side::Explicit;
            if knots[p].left == Side::Open {
                knots[p].left = Side::Curl(1.0);
            }
            knots[q].left = Side::Explicit;
            if knots[q].right == Side::Open {
                knots[q].right = Side::Curl(1.0);
            }
            knots[p].post = knots[p].point;
            knots[q].pre = knots[p].point;
        }
    }
    // The first breakpoint h; a cycle without one gets an artificial one at knot 0 (§332).
    let mut h = 0;
    loop {
        if knots[h].left != Side::Open || knots[h].right != Side::Open {
            break;
        }
        h = next(h);
        if h == 0 {
            knots[0].left = Side::EndCycle;
            break;
        }
    }
    // Fill in the controls between consecutive breakpoints (§333).
    let mut p = h;
    loop {
        let mut q = next(p);
        if knots[p].right.is_at_least_given() {
            while knots[q].left == Side::Open && knots[q].right == Side::Open {
                q = next(q);
            }
            solve_between(knots, p, q);
        } else if knots[p].right == Side::Endpoint {
            knots[p].post = knots[p].point;
            knots[q].pre = knots[q].point;
        }
        p = q;
        if p == h {
            break;
        }
    }
}

/// The chord data of the segments from breakpoint p to breakpoint q (§343).
struct Chords {
    dx: Vec<f64>,
    dy: Vec<f64>,
    len: Vec<f64>,
    /// ψₖ, the turning angle of the polygon at knot k (ψ₀ unused).
    psi: Vec<f64>,
}

/// Computes the chords and turning angles from p to q, then solves for the angles and sets the
/// controls (§339, §343, §344).
fn solve_between(knots: &mut [Knot], p: usize, q: usize) {
    let n_knots = knots.len();
    let mut chords = Chords { dx: Vec::new(), dy: Vec::new(), len: Vec::new(), psi: vec![0.0] };
    let mut k = 0;
    let mut s = p;
    let mut n = usize::MAX;
    loop {
        let t = (s + 1) % n_knots;
        let delta = knots[t].point - knots[s].point;
        chords.dx.push(delta.x);
        chords.dy.push(delta.y);
        chords.len.push(delta.x.hypot(delta.y));
        if k > 0 {
            let sine = chords.dy[k - 1] / chords.len[k - 1];
            let cosine = chords.dx[k - 1] / chords.len[k - 1];
            chords.psi.push(f64::atan2(
                chords.dy[k] * cosine - chords.dx[k] * sine,
                chords.dx[k] * cosine + chords.dy[k] * sine,
            ));
        }
        k += 1;
        s = t;
        if s == q {
            n = k;
        }
        if k >= n && knots[s].left != Side::EndCycle {
            break;
        }
    }
    let last = if k == n { 0.0 } else { chords.psi[1] };
    chords.psi.push(last);
    // A breakpoint's open side would take its direction from the explicit control on its other
    // side (§344); the sides this module creates never leave one open there.
    debug_assert!(knots[q].left != Side::Open, "open left side at a breakpoint");
    debug_assert!(
        !(knots[p].right == Side::Open && knots[p].left == Side::Explicit),
        "open right side next to an explicit one"
    );
    solve_choices(knots, p, n, &chords);
}

/// Solves the mock-curvature equations for θ₀, …, θₙ on the n segments starting at knot p and
/// sets their control points: METAPOST's `solve_choices` (§§ 350–366).
fn solve_choices(knots: &mut [Knot], p: usize, n: usize, chords: &Chords) {
    let n_knots = knots.len();
    let at = |k: usize| (p + k) % n_knots;
    let (psi, len) = (&chords.psi, &chords.len);
    let mut theta = vec![0.0; n + 1];
    let mut uu = vec![0.0; n + 1];
    let mut vv = vec![0.0; n + 1];
    let mut ww = vec![0.0; n + 1];
    let mut k = 0;
    loop {
        let (s, t) = (at(k), at(k + 1));
        if k == 0 {
            // Start the equations, or finish a straight segment at once (§351).
            if let Side::Curl(gamma) = knots[s].right {
                if let Side::Curl(_) = knots[t].left {
                    straight_line(knots, s, t, chords);
                    return;
                }
                let lt = knots[t].left_tension.abs();
                let rt = knots[s].right_tension.abs();
                uu[0] = if rt == 1.0 && lt == 1.0 {
                    (gamma + gamma + 1.0) / (gamma + 2.0)
                } else {
                    curl_ratio(gamma, rt, lt)
                };
                vv[0] = -(psi[1] * uu[0]);
                ww[0] = 0.0;
            } else {
                // An open side: this begins a cycle.
                uu[0] = 0.0;
                vv[0] = 0.0;
                ww[0] = 1.0;
            }
        } else if let Side::Curl(gamma) = knots[s].left {
            // A curl at θₙ (§363).
            let r = at(k - 1);
            let lt = knots[s].left_tension.abs();
            let rt = knots[r].right_tension.abs();
            let ff = if rt == 1.0 && lt == 1.0 {
                (gamma + gamma + 1.0) / (gamma + 2.0)
            } else {
                curl_ratio(gamma, lt, rt)
            };
            theta[n] = -((vv[n - 1] * ff) / (1.0 - ff * uu[n - 1]));
            break;
        } else {
            // Match the mock curvatures at zₖ (§§ 353–356).
            let r = at(k - 1);
            let (aa, mut dd) = tension_terms(knots[r].right_tension, len[k]);
            let (bb, mut ee) = tension_terms(knots[t].left_tension, len[k - 1]);
            let cc = 1.0 - uu[k - 1] * aa;
            dd *= cc;
            let lt = knots[s].left_tension.abs();
            let rt = knots[s].right_tension.abs();
            if lt < rt {
                let ratio = lt / rt;
                dd *= ratio * ratio;
            } else if rt < lt {
                let ratio = rt / lt;
                ee *= ratio * ratio;
            }
            let mut ff = ee / (ee + dd);
            uu[k] = ff * bb;
            let mut acc = -(psi[k + 1] * uu[k]);
            if let Side::Curl(_) = knots[r].right {
                ww[k] = 0.0;
                vv[k] = acc - psi[1] * (1.0 - ff);
            } else {
                ff = (1.0 - ff) / cc;
                acc -= psi[k] * ff;
                ff *= aa;
                vv[k] = acc - vv[k - 1] * ff;
                ww[k] = if ww[k - 1] == 0.0 { 0.0 } else { -(ww[k - 1] * ff) };
            }
            if knots[s].left == Side::EndCycle {
                // Back at the start of the cycle: θₙ = θ₀ closes the system (§357).
                theta[n] = close_cycle(k, n, &uu, &mut vv, &ww);
                break;
            }
        }
        k += 1;
    }
    // Back substitution and the control points (§366).
    for k in (0..n).rev() {
        theta[k] = vv[k] - theta[k + 1] * uu[k];
    }
    for k in 0..n {
        let (st, ct) = theta[k].sin_cos();
        let (sf, cf) = (-psi[k + 1] - theta[k + 1]).sin_cos();
        set_controls(knots, at(k), at(k + 1), k, [st, ct, sf, cf], chords);
    }
}

/// The last stage of the cyclic system in [`solve_choices`], back at the start of the cycle
/// after equation k: θₙ = θ₀ found by running the recurrence backwards (§357), with the
/// `vv` updated by it; returns θₙ.
fn close_cycle(k: usize, n: usize, uu: &[f64], vv: &mut [f64], ww: &[f64]) -> f64 {
    let (mut a, mut b) = (0.0, 1.0);
    let mut j = k;
    loop {
        j -= 1;
        if j == 0 {
            j = n;
        }
        a = vv[j] - a * uu[j];
        b = ww[j] - b * uu[j];
        if j == n {
            break;
        }
    }
    a /= 1.0 - b;
    vv[0] = a;
    for j in 1..n {
        vv[j] += a * ww[j];
    }
    a
}

/// A = 1/(3τ − 1) (relative to B) and (3 − 1/τ)·d for the tension τ of a neighbouring segment
/// and the chord d of the other one (§354).
fn tension_terms(tension: f64, chord: f64) -> (f64, f64) {
    let tension = tension.abs();
    if tension == 1.0 {
        (0.5, 2.0 * chord)
    } else {
        (1.0 / (3.0 * tension - 1.0), chord * (3.0 - 1.0 / tension))
    }
}

/// The curl ratio ((3 − α)α²γ + β³) / (α³γ + (3 − β)β²), at most 4, with α = 1/`a_tension`
/// and β = 1/`b_tension` (§365).
///
/// Transcribed from METAPOST 2.02 with `-numbersystem=double` including its arithmetic: when
/// α > β it divides the `fraction` (β/α)², stored as 4096·(β/α)², by METAPOST's `scaled`
/// constant 1365/65536 (≈ 4096/3 in the 16.16 fixed-point system, where the division yields
/// 3·(β/α)²), so the term that should be 3(β/α)² comes out as (β/α)²·2²⁸/1365. The reference
/// output (`fixtures/curve/mpost_hobby.json`) shows this, so the quirk is kept for agreement
/// with `-numbersystem=double`. METAPOST's default fixed-point arithmetic computes the intended
/// ratio: postcontrol 0 of `(0,0)..tension 1 and 2..(3,1)..(4,4)..(1,5)..(-1,2)` is
/// (1.07178, 0.0335) there and (1.00101, 0.33366) in double. It only matters at an end with a
/// curl whose own tension is smaller than the other tension of its segment.
pub(super) fn curl_ratio(gamma: f64, a_tension: f64, b_tension: f64) -> f64 {
    let alpha = 1.0 / a_tension;
    let mut beta = 1.0 / b_tension;
    let mut gamma = gamma;
    let mut denom;
    if alpha <= beta {
        let ff = alpha / beta;
        let ff = ff * ff;
        gamma *= ff;
        denom = gamma * alpha + 3.0;
    } else {
        let ff = beta / alpha;
        let ff = ff * ff;
        beta *= ff;
        // METAPOST double: ff·4096 / (1365/65536).
        denom = gamma * alpha + (ff * 4096.0) / (1365.0 / 65536.0);
    }
    denom -= beta;
    let num = gamma * (3.0 - alpha) + beta;
    if num >= 4.0 * denom { 4.0 } else { num / denom }
}

/// METAPOST's `velocity`: ρ(θ, φ)/(3τ) from the sines and cosines, limited to 4
/// (`mp_double_velocity` of mpmathdouble.w).
fn velocity(st: f64, ct: f64, sf: f64, cf: f64, tension: f64) -> f64 {
    let acc = (st - sf / 16.0) * (sf - st / 16.0);
    let acc = acc * (ct - cf);
    let mut num = 2.0 + acc * HOBBY_A;
    let root5 = 5f64.sqrt();
    let denom = 3.0 + ct * (1.5 * (root5 - 1.0)) + cf * (1.5 * (3.0 - root5));
    if tension != 1.0 {
        num /= tension;
    }
    if num / 4.0 >= denom { 4.0 } else { num / denom }
}

/// Sets the controls of segment k from knot s to knot t, given sin θ, cos θ, sin φ, cos φ
/// (§§ 370–372).
fn set_controls(
    knots: &mut [Knot],
    s: usize,
    t: usize,
    k: usize,
    [st, ct, sf, cf]: [f64; 4],
    chords: &Chords,
) {
    let right_tension = knots[s].right_tension;
    let left_tension = knots[t].left_tension;
    let mut rr = velocity(st, ct, sf, cf, right_tension.abs());
    let mut ss = velocity(sf, cf, st, ct, left_tension.abs());
    // `atleast`: stay inside the bounding triangle, rr ≤ sin φ/sin(θ + φ) and
    // ss ≤ sin θ/sin(θ + φ), when sin θ, sin φ and sin(θ + φ) have the same sign.
    if (right_tension < 0.0 || left_tension < 0.0)
        && ((st >= 0.0 && sf >= 0.0) || (st <= 0.0 && sf <= 0.0))
    {
        let sine = st.abs() * cf + sf.abs() * ct;
        if sine > 0.0 {
            // METAPOST's safety factor 1 + 2⁻¹² (fraction_one + unity).
            let sine = sine * (1.0 + 1.0 / 4096.0);
            if right_tension < 0.0 && sf.abs() < rr * sine {
                rr = sf.abs() / sine;
            }
            if left_tension < 0.0 && st.abs() < ss * sine {
                ss = st.abs() / sine;
            }
        }
    }
    let (dx, dy) = (chords.dx[k], chords.dy[k]);
    knots[s].post = knots[s].point + DVec2::new(dx * ct - dy * st, dy * ct + dx * st) * rr;
    knots[t].pre = knots[t].point - DVec2::new(dx * cf + dy * sf, dy * cf - dx * sf) * ss;
    knots[s].right = Side::Explicit;
    knots[t].left = Side::Explicit;
}

/// Curls at both ends of a single segment: a straight line with controls at 1/(3τ) of the
/// chord from each end (§374).
fn straight_line(knots: &mut [Knot], s: usize, t: usize, chords: &Chords) {
    let delta = DVec2::new(chords.dx[0], chords.dy[0]);
    let rt = knots[s].right_tension.abs();
    let lt = knots[t].left_tension.abs();
    let third = |tension: f64| {
        if tension == 1.0 {
            // METAPOST double: (Δ ± 2⁻⁵²)/3, the rounding its fixed-point ancestor needed.
            DVec2::new(
                (chords.dx[0] + f64::EPSILON.copysign(chords.dx[0] + 0.0)) / 3.0,
                (chords.dy[0] + f64::EPSILON.copysign(chords.dy[0] + 0.0)) / 3.0,
            )
        } else {
            delta * (1.0 / (3.0 * tension))
        }
    };
    knots[s].post = knots[s].point + third(rt);
    knots[t].pre = knots[t].point - third(lt);
    knots[s].right = Side::Explicit;
    knots[t].left = Side::Explicit;
}
