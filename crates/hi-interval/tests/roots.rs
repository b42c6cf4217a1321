// SPDX-License-Identifier: MIT
//! Root finders on functions with known zeros (Hardy 2005, §5.6): polynomials built from their
//! roots, double and triple roots, roots at the ends of the domain, trigonometric sums whose zeros
//! follow from identities, and 2-D systems. The expected zeros come from algebra, never from the
//! code under test.

use hi_interval::{
    Interval, IntervalMatrix, RootOptions, Scalar, Verdict, bisect_1d, find_roots, find_roots_1d,
};

/// Coefficients (constant first) of Π (x − rᵢ); exact for small dyadic roots.
fn poly_from_roots(roots: &[f64]) -> Vec<f64> {
    let mut c = vec![1.0];
    for &r in roots {
        let mut next = vec![0.0; c.len() + 1];
        for (i, &ci) in c.iter().enumerate() {
            next[i + 1] += ci;
            next[i] -= r * ci;
        }
        c = next;
    }
    c
}

/// Horner evaluation, written once for f64 and intervals.
fn horner<S: Scalar>(c: &[f64], x: S) -> S {
    c.iter().rev().fold(S::zero(), |acc, &ci| acc * x + S::from_f64(ci))
}

fn derivative(c: &[f64]) -> Vec<f64> {
    c.iter().enumerate().skip(1).map(|(i, &ci)| ci * i as f64).collect()
}

#[test]
fn simple_polynomial_roots_are_unique_and_enclosed() {
    let roots = [-1.5, -0.25, 0.5, 0.625, 2.0];
    let c = poly_from_roots(&roots);
    let dc = derivative(&c);
    let res = find_roots_1d(
        |x| horner(&c, x),
        |x| horner(&dc, x),
        Interval::new(-3.0, 3.0),
        &RootOptions::default(),
    );
    assert!(res.complete, "finished");
    assert_eq!(res.roots.len(), roots.len(), "{res:?}");
    for (found, &r) in res.roots.iter().zip(&roots) {
        assert_eq!(found.verdict, Verdict::Unique, "root {r}: {found:?}");
        assert!(found.enclosure.contains(r), "root {r}: {found:?}");
        assert!(found.enclosure.width() < 1e-9, "root {r}: {found:?}");
    }
}

#[test]
fn double_and_triple_roots_are_enclosed_not_claimed_unique() {
    // (x − 1)²(x + 2): the double root cannot be proven unique (F' ∋ 0 around it).
    let c = poly_from_roots(&[1.0, 1.0, -2.0]);
    let dc = derivative(&c);
    let res = find_roots_1d(
        |x| horner(&c, x),
        |x| horner(&dc, x),
        Interval::new(-4.0, 4.0),
        &RootOptions::default(),
    );
    let at = |r: f64| res.roots.iter().filter(|f| f.enclosure.contains(r)).count();
    assert_eq!((at(1.0), at(-2.0)), (1, 1), "{res:?}");
    for found in &res.roots {
        if found.enclosure.contains(1.0) {
            assert_eq!(found.verdict, Verdict::Unknown, "double root: {found:?}");
        } else {
            assert!(found.enclosure.contains(-2.0), "no spurious cluster: {found:?}");
            assert_eq!(found.verdict, Verdict::Unique);
        }
    }
    // (x − 0.5)³: a sign change proves existence, not uniqueness. Horner's form overestimates
    // by about the box width w, so boxes survive where |x − 0.5|³ < w: with w = 1e-6 that is
    // |x − 0.5| < 1e-2, about 2·10⁴ boxes.
    let c = poly_from_roots(&[0.5, 0.5, 0.5]);
    let dc = derivative(&c);
    let config = RootOptions { tolerance: 1e-6, ..RootOptions::default() };
    let res =
        find_roots_1d(|x| horner(&c, x), |x| horner(&dc, x), Interval::new(-1.0, 1.0), &config);
    assert!(res.complete, "within the box cap");
    assert!(res.roots.iter().any(|f| f.enclosure.contains(0.5)), "{res:?}");
    let hull = res.roots.iter().fold(Interval::EMPTY, |h, f| h.hull(f.enclosure));
    assert!(hull.width() < 5e-2, "{res:?}");
    assert!(res.roots.iter().any(|f| f.verdict == Verdict::Exists), "sign change: {res:?}");
    assert!(res.roots.iter().all(|f| f.verdict != Verdict::Unique), "{res:?}");
}

#[test]
fn roots_at_the_domain_ends() {
    // x(x − 1) on [0, 1]: both zeros are the domain ends, exactly.
    let f = |x: Interval| x * (x - 1.0);
    let df = |x: Interval| x * 2.0 - 1.0;
    let res = find_roots_1d(f, df, Interval::new(0.0, 1.0), &RootOptions::default());
    assert_eq!(res.roots.len(), 2, "{res:?}");
    assert!(res.roots[0].enclosure.contains(0.0) && res.roots[1].enclosure.contains(1.0));
    assert!(res.roots.iter().all(|r| r.verdict == Verdict::Unique), "{res:?}");
    assert!(res.roots.iter().all(|r| r.enclosure.is_subset(Interval::new(0.0, 1.0))), "inside");

    // sin on [0, PI]: the double PI is below π, so the zero π lies just outside the domain.
    let sin = |x: Interval| x.sin();
    let cos = |x: Interval| x.cos();
    let pi = std::f64::consts::PI;
    let res = find_roots_1d(sin, cos, Interval::new(0.0, pi), &RootOptions::default());
    assert_eq!(res.roots.len(), 1, "only 0: {res:?}");
    assert!(res.roots[0].enclosure.contains(0.0) && res.roots[0].verdict == Verdict::Unique);
    // On [1, next_up(PI)] it is inside, and enclosed.
    let res = find_roots_1d(sin, cos, Interval::new(1.0, pi.next_up()), &RootOptions::default());
    assert_eq!(res.roots.len(), 1, "{res:?}");
    assert!(res.roots[0].enclosure.overlaps(Interval::PI), "{res:?}");
    assert!(
        matches!(res.roots[0].verdict, Verdict::Unique | Verdict::AtMostOne),
        "{:?}",
        res.roots[0]
    );
}

/// sin 2πt + sin 4πt = sin 2πt (1 + 2 cos 2πt): zeros at t = k/2 and t = ±1/3 mod 1.
fn trig_sum<S: Scalar>(t: S) -> S {
    let w = S::pi() * S::from_f64(2.0) * t;
    w.sin() + (w * S::from_f64(2.0)).sin()
}

fn trig_sum_deriv<S: Scalar>(t: S) -> S {
    let two_pi = S::pi() * S::from_f64(2.0);
    let w = two_pi * t;
    two_pi * (w.cos() + S::from_f64(2.0) * (w * S::from_f64(2.0)).cos())
}

#[test]
fn trigonometric_sum_zeros() {
    let res = find_roots_1d(
        trig_sum::<Interval>,
        trig_sum_deriv::<Interval>,
        Interval::new(0.1, 1.9),
        &RootOptions::default(),
    );
    // In (0.1, 1.9): 1/3, 1/2, 2/3, 1, 4/3, 3/2, 5/3.
    let expected: Vec<Interval> =
        [(1.0, 3.0), (1.0, 2.0), (2.0, 3.0), (1.0, 1.0), (4.0, 3.0), (3.0, 2.0), (5.0, 3.0)]
            .iter()
            .map(|&(p, q)| Interval::ratio(p, q))
            .collect();
    assert_eq!(res.roots.len(), expected.len(), "{res:?}");
    for (found, want) in res.roots.iter().zip(&expected) {
        assert_eq!(found.verdict, Verdict::Unique, "{want}: {found:?}");
        assert!(found.enclosure.overlaps(*want), "{want}: {found:?}");
        assert!(found.enclosure.width() < 1e-9, "{want}: {found:?}");
    }
    // Bisection alone finds the same zeros, each as a sign change.
    let res = bisect_1d(trig_sum::<Interval>, Interval::new(0.1, 1.9), &RootOptions::default());
    assert_eq!(res.roots.len(), expected.len(), "{res:?}");
    for (found, want) in res.roots.iter().zip(&expected) {
        assert!(found.enclosure.overlaps(*want), "{want}: {found:?}");
        assert_eq!(found.verdict, Verdict::Exists, "{want}: {found:?}");
    }
}

#[test]
fn two_dimensional_system_with_exact_roots() {
    // y = x² and x = y²: zeros (0, 0) and (1, 1) (x⁴ = x over the reals).
    let f = |v: &[Interval]| vec![v[1] - v[0].sqr(), v[0] - v[1].sqr()];
    let jac = |v: &[Interval]| {
        IntervalMatrix::from_rows(vec![
            vec![v[0] * -2.0, Interval::ONE],
            vec![Interval::ONE, v[1] * -2.0],
        ])
    };
    let domain = [Interval::new(-0.5, 1.5), Interval::new(-0.6, 1.7)];
    let res = find_roots(f, jac, &domain, &RootOptions::default());
    assert!(res.complete);
    assert_eq!(res.roots.len(), 2, "{res:?}");
    for (found, want) in res.roots.iter().zip([0.0, 1.0]) {
        assert_eq!(found.verdict, Verdict::Unique, "{found:?}");
        assert!(found.enclosure.iter().all(|c| c.contains(want)), "{found:?}");
    }
    // Shift the domain so that no zero is inside: nothing is returned.
    let domain = [Interval::new(2.0, 3.0), Interval::new(2.0, 3.0)];
    assert!(find_roots(f, jac, &domain, &RootOptions::default()).roots.is_empty(), "no zeros");
}

#[test]
fn nan_and_empty_inputs_never_panic() {
    let res = find_roots_1d(|x| x, |_| Interval::ONE, Interval::EMPTY, &RootOptions::default());
    assert!(res.roots.is_empty() && res.complete);
    let config = RootOptions {
        tolerance: f64::NAN,
        newton_width: f64::NAN,
        max_iterations: 3,
        max_boxes: 50,
    };
    let res = bisect_1d(|x: Interval| x.sin(), Interval::new(-1.0, 1.0), &config);
    assert!(res.roots.iter().any(|r| r.enclosure.contains(0.0)), "{res:?}");
}
