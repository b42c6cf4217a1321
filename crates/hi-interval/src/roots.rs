// SPDX-License-Identifier: MIT
//! Interval root finding (Hardy 2005, §5.6, "Interval Root Finding"): the bisection method, the
//! Krawczyk operator K(X, y, Y) = y − Y f(y) + (I − Y F′(X))(X − y), and interval Newton
//! iteration Xₙ₊₁ = K(Xₙ, m(Xₙ), Yₙ) ∩ Xₙ with the thesis's preconditioner update
//!
//! ```text
//! Yₙ = Yₙ₋₁            if rₙ = ‖I − Yₙ₋₁ F′(Xₙ)‖ ≤ rₙ₋₁,
//!      m(F′(Xₙ))⁻¹     otherwise,
//! ```
//!
//! to which we add one condition: a kept Yₙ₋₁ must also give rₙ ≤ 1/2, or the iteration only
//! converges linearly at the rate rₙ (see `KEEP_BELOW`).
//!
//! Every search is bounded by [`RootOptions::max_iterations`] and [`RootOptions::max_boxes`], so it
//! always stops; a search cut short says so with `complete = false`, and nothing it found is
//! lost: boxes not yet examined are returned with [`Verdict::Unknown`].
//!
//! Uniqueness follows Krawczyk's theorem: if K(X, y, Y) ⊂ int X then X holds exactly one zero
//! (Theorem 5.5 gives the same from K ⊆ X and r < 1, which is also used). If K ∩ X = ∅ then X
//! holds no zero. Every zero in X lies in K ∩ X, so no iteration loses a root.

use crate::Interval;
use crate::linalg::{IntervalMatrix, hull, intersection, max_width, midpoint, real_inverse};

/// Tolerances and caps of the root finders.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RootOptions {
    /// Target width of the enclosures: bisection stops splitting a box whose widest side is at
    /// most this (§5.6: ε), and interval Newton iterates until its box is this narrow.
    pub tolerance: f64,
    /// When derivatives are given, bisection hands boxes to interval Newton once they are this
    /// narrow (or `tolerance`, if larger), since Newton converges much faster (§5.6). Zeros closer
    /// together than this end in one enclosure, which Newton cannot then prove unique.
    pub newton_width: f64,
    /// Cap on interval Newton iterations per verdict.
    pub max_iterations: usize,
    /// Cap on the number of boxes the bisection examines.
    pub max_boxes: usize,
}

impl Default for RootOptions {
    /// `tolerance = 1e-10`, `newton_width = 1e-6`, `max_iterations = 60`, `max_boxes = 200_000`.
    fn default() -> Self {
        Self { tolerance: 1e-10, newton_width: 1e-6, max_iterations: 60, max_boxes: 200_000 }
    }
}

/// What is proven about the zeros of f in an enclosure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Verdict {
    /// Exactly one zero in the enclosure, and the enclosure lies in the search domain
    /// (Krawczyk's test, or in 1-D a sign change with F′ bounded away from 0).
    Unique,
    /// At least one zero (in 1-D: a strict sign change of f across the enclosure); uniqueness not
    /// shown, e.g. a triple root.
    Exists,
    /// At most one zero: unique in a box that extends past the search domain, so the zero may lie
    /// just outside it (a root at or next to an end of the domain).
    AtMostOne,
    /// Not decided: none, one or several zeros (e.g. a double root, where 0 ∈ F′ near the zero).
    Unknown,
}

/// One enclosure of zeros, with what is known about it.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Root {
    /// A box containing every zero that the search attributes to this entry.
    pub enclosure: Vec<Interval>,
    /// What is proven about the zeros in `enclosure`.
    pub verdict: Verdict,
}

/// The result of a root search: every zero of f in the domain lies in some enclosure.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Roots {
    /// Disjoint-or-touching enclosures, sorted by their first coordinate.
    pub roots: Vec<Root>,
    /// False if a cap stopped the search early (then some enclosures are coarse, `Unknown`).
    pub complete: bool,
}

/// One zero of a 1-D function (see [`Root`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Root1 {
    /// An interval containing every zero attributed to this entry.
    pub enclosure: Interval,
    /// What is proven about the zeros in `enclosure`.
    pub verdict: Verdict,
}

/// The result of a 1-D root search (see [`Roots`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Roots1 {
    /// Enclosures in increasing order.
    pub roots: Vec<Root1>,
    /// False if a cap stopped the search early.
    pub complete: bool,
}

/// The outcome of [`interval_newton`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NewtonOutcome {
    /// The final box, or `None` when it is proven that X holds no zero (K ∩ X = ∅).
    pub enclosure: Option<Vec<Interval>>,
    /// `Unique` when Krawczyk's test succeeded, otherwise `Unknown`.
    pub verdict: Verdict,
    /// Iterations performed.
    pub n_iterations: usize,
}

/// The Krawczyk operator K(X, y, Y) = y − Y f(y) + (I − Y F′(X))(X − y) (§5.6), given an
/// enclosure `f_y` of f(y), the interval Jacobian `jacobian` = F′(X), a point y and any real
/// matrix Y (the preconditioner).
///
/// Every zero of f in X lies in K(X, y, Y). Returns empty entries when the sizes disagree.
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, IntervalMatrix, krawczyk};
/// // f(x) = x² − 2 on X = [1.3, 1.5]; F'(X) = 2X.
/// let x = [Interval::new(1.3, 1.5)];
/// let y = [1.4];
/// let fy = [Interval::point(1.4).sqr() - 2.0];
/// let jac = IntervalMatrix::from_rows(vec![vec![x[0] * 2.0]]);
/// let k = krawczyk(&fy, &jac, &x, &y, &[vec![1.0 / 2.8]]);
/// assert!(k[0].is_interior(x[0])); // K ⊂ int X: exactly one zero, √2
/// assert!(k[0].contains(2f64.sqrt()));
/// ```
#[must_use]
pub fn krawczyk(
    f_y: &[Interval],
    jacobian: &IntervalMatrix,
    x: &[Interval],
    y: &[f64],
    precond: &[Vec<f64>],
) -> Vec<Interval> {
    let n = x.len();
    if f_y.len() != n || y.len() != n || precond.len() != n || jacobian.n_rows() != n {
        return vec![Interval::EMPTY; n];
    }
    let yp = IntervalMatrix::from_real_rows(precond);
    let y_f = yp.mul_vec(f_y);
    let residual = IntervalMatrix::identity(n).sub_mat(&yp.mul_mat(jacobian));
    let dx: Vec<Interval> = x.iter().zip(y).map(|(xi, &yi)| *xi - yi).collect();
    let corr = residual.mul_vec(&dx);
    (0..n).map(|i| (Interval::point(y[i]) - y_f[i]) + corr[i]).collect()
}

/// ‖I − Y F′(X)‖ (§5.6: r), rounded up.
fn contraction(jacobian: &IntervalMatrix, precond: &[Vec<f64>]) -> f64 {
    let n = jacobian.n_rows();
    IntervalMatrix::identity(n)
        .sub_mat(&IntervalMatrix::from_real_rows(precond).mul_mat(jacobian))
        .norm()
}

/// Interval Newton (Krawczyk) iteration Xₙ₊₁ = K(Xₙ, m(Xₙ), Yₙ) ∩ Xₙ (§5.6) with the thesis's
/// preconditioner update (keep Yₙ₋₁ while rₙ ≤ rₙ₋₁).
///
/// `f` evaluates an interval extension of f on a box, `jacobian` one of F′. Stops when Krawczyk's
/// test has succeeded and the box is narrower than `options.tolerance`, when the iteration makes no
/// progress, when X is proven to hold no zero, or after `options.max_iterations`. Boxes whose
/// midpoint Jacobian is singular end with `Unknown`.
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, IntervalMatrix, RootOptions, Verdict, interval_newton};
/// // The unit circle meets the line x = y at (√½, √½).
/// let f = |v: &[Interval]| vec![v[0].sqr() + v[1].sqr() - 1.0, v[0] - v[1]];
/// let jac = |v: &[Interval]| {
///     IntervalMatrix::from_rows(vec![
///         vec![v[0] * 2.0, v[1] * 2.0],
///         vec![Interval::ONE, -Interval::ONE],
///     ])
/// };
/// let x = [Interval::new(0.6, 0.8), Interval::new(0.6, 0.8)];
/// let out = interval_newton(f, jac, &x, &RootOptions::default());
/// assert_eq!(out.verdict, Verdict::Unique);
/// let b = out.enclosure.unwrap();
/// assert!(b[0].contains(0.5f64.sqrt()) && b[0].width() < 1e-10);
/// ```
pub fn interval_newton<F, J>(
    f: F,
    jacobian: J,
    x: &[Interval],
    options: &RootOptions,
) -> NewtonOutcome
where
    F: Fn(&[Interval]) -> Vec<Interval>,
    J: Fn(&[Interval]) -> IntervalMatrix,
{
    let mut x = x.to_vec();
    let mut previous: Option<(Vec<Vec<f64>>, f64)> = None;
    let mut unique = false;
    for it in 0..options.max_iterations {
        if x.iter().any(|v| v.is_empty() || !v.is_bounded()) {
            return NewtonOutcome {
                enclosure: Some(x),
                verdict: Verdict::Unknown,
                n_iterations: it,
            };
        }
        let jac = jacobian(&x);
        // The preconditioner update of §5.6, plus a floor on the contraction (see KEEP_BELOW).
        let kept = previous.take().and_then(|(yp, rp)| {
            let r = contraction(&jac, &yp);
            (r <= rp && r <= KEEP_BELOW).then_some((yp, r))
        });
        let (precond, r) = match kept {
            Some(pair) => pair,
            None => match real_inverse(&jac.midpoint()) {
                Some(inv) => {
                    let r = contraction(&jac, &inv);
                    (inv, r)
                }
                None => {
                    let verdict = if unique { Verdict::Unique } else { Verdict::Unknown };
                    return NewtonOutcome { enclosure: Some(x), verdict, n_iterations: it };
                }
            },
        };
        let y = midpoint(&x);
        let y_box: Vec<Interval> = y.iter().map(|&v| Interval::point(v)).collect();
        let f_y = f(&y_box);
        let k = krawczyk(&f_y, &jac, &x, &y, &precond);
        if k.iter().any(|v| v.is_empty()) {
            // f undefined at y (or a size mismatch): nothing can be concluded.
            let verdict = if unique { Verdict::Unique } else { Verdict::Unknown };
            return NewtonOutcome { enclosure: Some(x), verdict, n_iterations: it + 1 };
        }
        let interior = k.iter().zip(&x).all(|(a, b)| a.is_interior(*b));
        let contained = k.iter().zip(&x).all(|(a, b)| a.is_subset(*b));
        unique = unique || interior || (contained && r < 1.0);
        let Some(next) = intersection(&k, &x) else {
            return NewtonOutcome {
                enclosure: None,
                verdict: Verdict::Unknown,
                n_iterations: it + 1,
            };
        };
        let stalled = next == x;
        x = next;
        previous = Some((precond, r));
        if (unique && max_width(&x) <= options.tolerance) || stalled {
            let verdict = if unique { Verdict::Unique } else { Verdict::Unknown };
            return NewtonOutcome { enclosure: Some(x), verdict, n_iterations: it + 1 };
        }
    }
    let verdict = if unique { Verdict::Unique } else { Verdict::Unknown };
    NewtonOutcome { enclosure: Some(x), verdict, n_iterations: options.max_iterations }
}

/// A kept preconditioner must also give r ≤ this. The thesis keeps Yₙ₋₁ whenever rₙ ≤ rₙ₋₁, but
/// the widths then shrink only by the factor r per step, and a Y from a wide first box can leave r
/// just below 1 for many steps (measured: zeros of σ′ for n = 44 stalled at width 7e-5 after 60
/// steps). Recomputing Y = m(F′(X))⁻¹ whenever r > 1/2 restores the quadratic convergence.
const KEEP_BELOW: f64 = 0.5;

type BoxFn<'a> = &'a dyn Fn(&[Interval]) -> Vec<Interval>;
type JacFn<'a> = &'a dyn Fn(&[Interval]) -> IntervalMatrix;

/// The interval bisection of §5.6 on boxes: keep a box while 0 ∈ F(box), split its widest side
/// at the midpoint until it is narrower than the tolerance. Returns the small boxes and whether
/// the search finished within `max_boxes`.
fn bisect_boxes(
    f: BoxFn<'_>,
    domain: &[Interval],
    leaf_width: f64,
    options: &RootOptions,
) -> (Vec<Vec<Interval>>, bool) {
    let mut stack = vec![domain.to_vec()];
    let mut leaves = Vec::new();
    let mut n_boxes = 0usize;
    let tol = if leaf_width.is_nan() { 0.0 } else { leaf_width };
    while let Some(b) = stack.pop() {
        n_boxes += 1;
        if n_boxes > options.max_boxes {
            stack.push(b);
            leaves.extend(stack);
            return (leaves, false);
        }
        if b.iter().any(|v| v.is_empty()) {
            continue;
        }
        let fb = f(&b);
        if fb.iter().any(|v| !v.contains(0.0)) {
            continue;
        }
        // Widest side; a side that can no longer be split (adjacent doubles) counts as narrow.
        let (dim, w) = b
            .iter()
            .enumerate()
            .map(|(i, v)| (i, if v.lo().next_up() >= v.hi() { 0.0 } else { v.width() }))
            .fold((0, 0.0), |acc, c| if c.1 > acc.1 { c } else { acc });
        if w <= tol {
            leaves.push(b);
            continue;
        }
        let (left, right) = b[dim].bisect();
        let mut lb = b.clone();
        lb[dim] = left;
        let mut rb = b;
        rb[dim] = right;
        stack.push(rb);
        stack.push(lb);
    }
    (leaves, true)
}

/// Groups boxes that touch or overlap, returning the hull of each group, sorted by first lower end.
fn cluster(mut boxes: Vec<Vec<Interval>>) -> Vec<Vec<Interval>> {
    boxes.sort_by(|a, b| a[0].lo().total_cmp(&b[0].lo()));
    let n = boxes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for i in 0..n {
        for j in i + 1..n {
            if boxes[j][0].lo() > boxes[i][0].hi() {
                break;
            }
            if intersection(&boxes[i], &boxes[j]).is_some() {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                parent[a] = b;
            }
        }
    }
    let mut groups: Vec<Option<Vec<Interval>>> = vec![None; n];
    for (i, b) in boxes.iter().enumerate() {
        let r = find(&mut parent, i);
        groups[r] = Some(match groups[r].take() {
            Some(h) => hull(&h, b),
            None => b.clone(),
        });
    }
    let mut res: Vec<Vec<Interval>> = groups.into_iter().flatten().collect();
    res.sort_by(|a, b| a[0].lo().total_cmp(&b[0].lo()));
    res
}

/// How many times [`decide`] may halve a cluster whose Krawczyk test fails.
const MAX_SPLIT_DEPTH: u32 = 12;

/// Decides a cluster with interval Newton on a slightly inflated box. When Krawczyk's test fails
/// (typically because F′ over the box still contains 0 from overestimation, not from a multiple
/// zero), the cluster is halved and each half decided again, up to [`MAX_SPLIT_DEPTH`] times.
/// Returns the enclosures of the zeros in `h` (none if every part is proven empty).
fn decide(
    f: BoxFn<'_>,
    jac: JacFn<'_>,
    domain: &[Interval],
    h: Vec<Interval>,
    options: &RootOptions,
    depth: u32,
) -> Vec<Root> {
    if f(&h).iter().any(|v| !v.contains(0.0)) {
        return Vec::new(); // No zero in h.
    }
    let eps = max_width(&h) * 0.25 + options.tolerance.max(0.0) + f64::MIN_POSITIVE;
    let z: Vec<Interval> = h.iter().map(|v| v.inflate(eps)).collect();
    let out = interval_newton(f, jac, &z, options);
    let Some(e) = out.enclosure else {
        return Vec::new(); // No zero in z ⊇ h.
    };
    if out.verdict != Verdict::Unique {
        let (dim, w) = h
            .iter()
            .enumerate()
            .map(|(i, v)| (i, if v.lo().next_up() >= v.hi() { 0.0 } else { v.width() }))
            .fold((0, 0.0), |acc, c| if c.1 > acc.1 { c } else { acc });
        if depth == 0 || w <= options.tolerance {
            return vec![Root { enclosure: h, verdict: Verdict::Unknown }];
        }
        let (left, right) = h[dim].bisect();
        let mut parts = Vec::new();
        for half in [left, right] {
            let mut b = h.clone();
            b[dim] = half;
            parts.extend(decide(f, jac, domain, b, options, depth - 1));
        }
        return merge_overlapping(parts)
            .into_iter()
            .map(|r| {
                if r.verdict != Verdict::Exists {
                    return r;
                }
                // Two unique zeros with overlapping enclosures: one zero on the cut, or two?
                // Krawczyk on the (narrow) hull decides it.
                let out = interval_newton(f, jac, &r.enclosure, options);
                match out.enclosure {
                    Some(e) if out.verdict == Verdict::Unique => {
                        Root { enclosure: e, verdict: Verdict::Unique }
                    }
                    _ => r,
                }
            })
            .collect();
    }
    let inside = e.iter().zip(domain).all(|(a, d)| a.is_subset(*d));
    if inside {
        return vec![Root { enclosure: e, verdict: Verdict::Unique }];
    }
    // The unique zero of z may lie outside the domain.
    intersection(&e, domain)
        .map(|enclosure| Root { enclosure, verdict: Verdict::AtMostOne })
        .into_iter()
        .collect()
}

/// Merges enclosures that overlap (the halves of a split cluster may both enclose a zero on the
/// cut). Two overlapping enclosures may hold one zero or two, so the merged verdict is `Exists`
/// when both were `Unique`, and `Unknown` otherwise.
fn merge_overlapping(mut roots: Vec<Root>) -> Vec<Root> {
    let mut res: Vec<Root> = Vec::new();
    roots.sort_by(|a, b| a.enclosure[0].lo().total_cmp(&b.enclosure[0].lo()));
    'next: for r in roots {
        for kept in &mut res {
            if intersection(&kept.enclosure, &r.enclosure).is_some() {
                kept.enclosure = hull(&kept.enclosure, &r.enclosure);
                kept.verdict = if kept.verdict == Verdict::Unique && r.verdict == Verdict::Unique {
                    Verdict::Exists
                } else {
                    Verdict::Unknown
                };
                continue 'next;
            }
        }
        res.push(r);
    }
    res
}

fn search(
    f: BoxFn<'_>,
    jac: Option<JacFn<'_>>,
    domain: &[Interval],
    options: &RootOptions,
) -> Roots {
    if domain.is_empty() || domain.iter().any(|v| v.is_empty()) {
        return Roots { roots: Vec::new(), complete: true };
    }
    let leaf_width = match jac {
        Some(_) => options.tolerance.max(options.newton_width),
        None => options.tolerance,
    };
    let (leaves, complete) = bisect_boxes(f, domain, leaf_width, options);
    let clusters = cluster(leaves);
    let mut roots: Vec<Root> = clusters
        .into_iter()
        .flat_map(|h| match jac {
            Some(jac) => decide(f, jac, domain, h, options, MAX_SPLIT_DEPTH),
            None => vec![Root { enclosure: h, verdict: Verdict::Unknown }],
        })
        .collect();
    roots.sort_by(|a, b| a.enclosure[0].lo().total_cmp(&b.enclosure[0].lo()));
    Roots { roots, complete }
}

/// All zeros of f: ℝⁿ → ℝⁿ in the box `domain` by interval bisection (§5.6), with uniqueness
/// verdicts from interval Newton (Krawczyk) on each cluster of small boxes.
///
/// Every zero in `domain` lies in some returned enclosure (if `complete`). Enclosures proven to
/// hold no zero are dropped.
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, IntervalMatrix, RootOptions, Verdict, find_roots};
/// // x² + y² = 1 and y = x² : two zeros, (±0.786, 0.618).
/// let f = |v: &[Interval]| vec![v[0].sqr() + v[1].sqr() - 1.0, v[1] - v[0].sqr()];
/// let jac = |v: &[Interval]| {
///     IntervalMatrix::from_rows(vec![
///         vec![v[0] * 2.0, v[1] * 2.0],
///         vec![v[0] * -2.0, Interval::ONE],
///     ])
/// };
/// let domain = [Interval::new(-2.0, 2.0), Interval::new(-2.0, 2.0)];
/// let res = find_roots(f, jac, &domain, &RootOptions::default());
/// assert_eq!(res.roots.len(), 2);
/// assert!(res.roots.iter().all(|r| r.verdict == Verdict::Unique));
/// let y = (5f64.sqrt() - 1.0) / 2.0;
/// assert!(res.roots[1].enclosure[1].contains(y) || res.roots[1].enclosure[1].width() < 1e-9);
/// ```
pub fn find_roots<F, J>(f: F, jacobian: J, domain: &[Interval], options: &RootOptions) -> Roots
where
    F: Fn(&[Interval]) -> Vec<Interval>,
    J: Fn(&[Interval]) -> IntervalMatrix,
{
    search(&f, Some(&jacobian), domain, options)
}

/// All zeros of f in `domain` by plain interval bisection (§5.6), without derivatives: every
/// enclosure is `Unknown` (bisection alone proves only where zeros are not).
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, RootOptions, bisect};
/// let f = |v: &[Interval]| vec![v[0].sqr() - 2.0];
/// let res = bisect(f, &[Interval::new(0.0, 4.0)], &RootOptions::default());
/// assert_eq!(res.roots.len(), 1);
/// assert!(res.roots[0].enclosure[0].contains(2f64.sqrt()));
/// ```
pub fn bisect<F>(f: F, domain: &[Interval], options: &RootOptions) -> Roots
where
    F: Fn(&[Interval]) -> Vec<Interval>,
{
    search(&f, None, domain, options)
}

/// All zeros of a real function f in the interval `domain` (§5.6 bisection, then Krawczyk on each
/// cluster), given interval extensions `f` of f and `df` of f′.
///
/// Verdicts: `Unique` from Krawczyk's test, or from a strict sign change of f across the
/// enclosure with 0 ∉ F′(enclosure); `Exists` from a sign change alone (an odd-order multiple
/// root); `AtMostOne` for a unique zero that may lie just outside the domain; `Unknown` otherwise
/// (e.g. a double root).
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, RootOptions, Verdict, find_roots_1d};
/// // (x − 1)(x − 2)²: a simple zero at 1 and a double zero at 2.
/// let f = |x: Interval| (x - 1.0) * (x - 2.0).sqr();
/// let df = |x: Interval| (x - 2.0).sqr() + (x - 1.0) * (x - 2.0) * 2.0;
/// let res = find_roots_1d(f, df, Interval::new(0.0, 3.0), &RootOptions::default());
/// assert_eq!(res.roots.len(), 2);
/// assert_eq!(res.roots[0].verdict, Verdict::Unique);
/// assert!(res.roots[0].enclosure.contains(1.0));
/// assert!(res.roots[1].enclosure.contains(2.0)); // the double zero: enclosed, not unique
/// ```
pub fn find_roots_1d<F, D>(f: F, df: D, domain: Interval, options: &RootOptions) -> Roots1
where
    F: Fn(Interval) -> Interval,
    D: Fn(Interval) -> Interval,
{
    let fv = |v: &[Interval]| vec![f(v[0])];
    let jac = |v: &[Interval]| IntervalMatrix::from_rows(vec![vec![df(v[0])]]);
    let res = search(&fv, Some(&jac), &[domain], options);
    refine_1d(&f, Some(&df), res)
}

/// All zeros of f in `domain` by interval bisection alone (§5.6); verdicts are `Exists` (strict
/// sign change across the enclosure) or `Unknown`.
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, RootOptions, Verdict, bisect_1d};
/// let res = bisect_1d(|x: Interval| x.cos(), Interval::new(0.0, 10.0), &RootOptions::default());
/// assert_eq!(res.roots.len(), 3); // π/2, 3π/2, 5π/2
/// assert!(res.roots.iter().all(|r| r.verdict == Verdict::Exists));
/// ```
pub fn bisect_1d<F>(f: F, domain: Interval, options: &RootOptions) -> Roots1
where
    F: Fn(Interval) -> Interval,
{
    let fv = |v: &[Interval]| vec![f(v[0])];
    let res = search(&fv, None, &[domain], options);
    refine_1d(&f, None::<&fn(Interval) -> Interval>, res)
}

/// Adds the 1-D sign-change verdicts.
fn refine_1d<F, D>(f: &F, df: Option<&D>, res: Roots) -> Roots1
where
    F: Fn(Interval) -> Interval,
    D: Fn(Interval) -> Interval,
{
    let roots = res
        .roots
        .into_iter()
        .map(|r| {
            let enclosure = r.enclosure[0];
            let mut verdict = r.verdict;
            if matches!(verdict, Verdict::Unknown | Verdict::AtMostOne) {
                let a = f(Interval::point(enclosure.lo()));
                let b = f(Interval::point(enclosure.hi()));
                let sign_change = (a.hi() < 0.0 && b.lo() > 0.0) || (a.lo() > 0.0 && b.hi() < 0.0);
                let exact_end = a == Interval::ZERO || b == Interval::ZERO;
                let monotone = df.is_some_and(|d| !d(enclosure).contains(0.0));
                verdict = match (sign_change || exact_end, monotone) {
                    (true, true) => Verdict::Unique,
                    (true, false) if verdict == Verdict::Unknown => Verdict::Exists,
                    _ => verdict,
                };
            }
            Root1 { enclosure, verdict }
        })
        .collect();
    Roots1 { roots, complete: res.complete }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn preconditioner_is_kept_while_it_contracts() {
        // A linear system: F' is constant, so Y from the first step stays (r does not grow),
        // and one Krawczyk step gives the root exactly enclosed.
        let f = |v: &[Interval]| vec![v[0] * 3.0 + v[1] - 1.0, v[0] - v[1] * 2.0];
        let jac = |_: &[Interval]| {
            IntervalMatrix::from_rows(vec![
                vec![Interval::point(3.0), Interval::ONE],
                vec![Interval::ONE, Interval::point(-2.0)],
            ])
        };
        let x = [Interval::new(-5.0, 5.0), Interval::new(-5.0, 5.0)];
        let out = interval_newton(f, jac, &x, &RootOptions::default());
        assert_eq!(out.verdict, Verdict::Unique);
        let b = out.enclosure.expect("a root");
        // 3x + y = 1, x = 2y: y = 1/7, x = 2/7.
        assert!(b[0].contains(2.0 / 7.0) && b[1].contains(1.0 / 7.0), "{b:?}");
        assert!(max_width(&b) < 1e-14, "{b:?}");
    }

    #[test]
    fn no_root_is_proven_empty() {
        let f = |v: &[Interval]| vec![v[0].sqr() + 1.0];
        let jac = |v: &[Interval]| IntervalMatrix::from_rows(vec![vec![v[0] * 2.0]]);
        let out = interval_newton(f, jac, &[Interval::new(2.0, 3.0)], &RootOptions::default());
        assert!(out.enclosure.is_none(), "x² + 1 has no real zero");
    }

    #[test]
    fn caps_stop_the_search() {
        // f ≡ 0: every box holds zeros; the box cap must stop the bisection.
        let options =
            RootOptions { tolerance: 0.0, newton_width: 0.0, max_iterations: 5, max_boxes: 1000 };
        let res = bisect_1d(|x: Interval| x * 0.0, Interval::new(0.0, 1.0), &options);
        assert!(bisect(|v: &[Interval]| v.to_vec(), &[], &options).roots.is_empty(), "no dims");
        assert!(!res.complete, "capped");
        // f vanishes exactly at the cluster ends, so zeros exist there, but nothing is unique.
        assert!(res.roots.iter().all(|r| r.verdict != Verdict::Unique), "not unique");
        let h = res.roots.iter().fold(Interval::EMPTY, |h, r| h.hull(r.enclosure));
        assert_eq!(h, Interval::new(0.0, 1.0), "nothing lost");
    }
}
