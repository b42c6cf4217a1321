// SPDX-License-Identifier: MIT
use super::multigrid::DENSE_MAX;
use super::*;

/// A patch of the equilateral triangle lattice, `n × n` vertices, in the plane z = 0.
fn lattice(n: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let h = 3f64.sqrt() / 2.0;
    let mut p = Vec::new();
    for i in 0..n {
        for j in 0..n {
            p.push(DVec3::new(j as f64 + 0.5 * i as f64, h * i as f64, 0.0));
        }
    }
    let at = |i: usize, j: usize| (i * n + j) as u32;
    let mut t = Vec::new();
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            t.push([at(i, j), at(i, j + 1), at(i + 1, j)]);
            t.push([at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)]);
        }
    }
    (p, t)
}

/// Cotangent weights reproduce linear functions (linear precision): fix the boundary of
/// an equilateral lattice to a linear function and the solve returns it inside.
#[test]
fn linear_functions_are_reproduced() {
    let (p, t) = lattice(30);
    let topo = Topology::new(p.len(), &t).unwrap();
    let mut lap = Laplacian::new(&topo, &t);
    lap.set_cotangent_weights(&p, &t, None);
    // Every interior edge of the lattice has weight ½(cot 60° + cot 60°) = 1/√3.
    let (_, ws, _) = lap.row(31);
    for &w in ws {
        assert!((w - 1.0 / 3f64.sqrt()).abs() < 1e-12, "weight {w}");
    }
    let mut fixed = vec![false; p.len()];
    for &h in &topo.boundary {
        fixed[tail(&t, h) as usize] = true;
    }
    let f = |x: DVec3| [2.0 * x.x - 3.0 * x.y + 1.0, 0.5 * x.x + x.y];
    let mut x: Vec<[f64; 2]> =
        p.iter().zip(&fixed).map(|(q, &fx)| if fx { f(*q) } else { [0.0; 2] }).collect();
    let b = vec![[0.0; 2]; p.len()];
    let opts = CgOptions::new(1e-13, 1000);
    let report = lap
        .solve(Some(&fixed), &b, &mut x, opts, lap.preconditioner(Some(&fixed), opts).as_ref())
        .unwrap();
    assert!(report.residual <= 1e-13, "{report:?}");
    for (q, xi) in p.iter().zip(&x) {
        let e = f(*q);
        assert!((xi[0] - e[0]).abs() < 1e-9 && (xi[1] - e[1]).abs() < 1e-9, "{xi:?} vs {e:?}");
    }
    // A warm start at the answer takes no iteration.
    let again = lap
        .solve(Some(&fixed), &b, &mut x, opts, lap.preconditioner(Some(&fixed), opts).as_ref())
        .unwrap();
    assert_eq!(again.iterations, 0, "{again:?}");
}

/// The solve against a dense Cholesky factorisation of the same system, with a right-hand
/// side and a warm start of random values.
#[test]
fn solve_matches_a_dense_factorisation() {
    let (mut p, t) = lattice(8);
    // Irregular positions: some weights negative before the clamp.
    let mut s = 12345u64;
    let mut rnd = || {
        s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for q in &mut p {
        *q += DVec3::new(0.4 * rnd(), 0.4 * rnd(), 0.3 * rnd());
    }
    let topo = Topology::new(p.len(), &t).unwrap();
    let mut lap = Laplacian::new(&topo, &t);
    let scale: Vec<f64> = t.iter().map(|_| 0.5 + rnd().abs()).collect();
    lap.set_cotangent_weights(&p, &t, Some(&scale));
    let n = p.len();
    // Symmetric with positive weights.
    for i in 0..n {
        let (cols, ws, _) = lap.row(i);
        for (&j, &w) in cols.iter().zip(ws) {
            assert!(w > 0.0, "weight {w}");
            let (cj, wj, _) = lap.row(j as usize);
            let back = cj.iter().position(|&k| k as usize == i).map(|k| wj[k]);
            assert_eq!(back, Some(w), "symmetric");
        }
    }
    let fixed: Vec<bool> = (0..n).map(|i| i == 5).collect();
    let b: Vec<[f64; 1]> = (0..n).map(|i| [if i == 5 { 0.0 } else { rnd() }]).collect();
    let mut x: Vec<[f64; 1]> = (0..n).map(|_| [rnd()]).collect();
    let held = x[5][0];
    let opts = CgOptions::new(1e-14, 10_000);
    lap.solve(Some(&fixed), &b, &mut x, opts, lap.preconditioner(Some(&fixed), opts).as_ref())
        .unwrap();
    // Dense: A y = b − (column 5)·held over the free rows, by Cholesky.
    let free: Vec<usize> = (0..n).filter(|&i| i != 5).collect();
    let m = free.len();
    let mut a = vec![vec![0.0; m]; m];
    let mut rhs = vec![0.0; m];
    for (r, &i) in free.iter().enumerate() {
        a[r][r] = lap.diagonal()[i];
        rhs[r] = b[i][0];
        let (cols, ws, _) = lap.row(i);
        for (&j, &w) in cols.iter().zip(ws) {
            if j == 5 {
                rhs[r] += w * held;
            } else {
                let c = free.iter().position(|&k| k == j as usize).unwrap();
                a[r][c] -= w;
            }
        }
    }
    for k in 0..m {
        a[k][k] = a[k][k].sqrt();
        for i in k + 1..m {
            a[i][k] /= a[k][k];
        }
        for j in k + 1..m {
            for i in j..m {
                a[i][j] -= a[i][k] * a[j][k];
            }
        }
    }
    let mut y = rhs;
    for i in 0..m {
        for k in 0..i {
            y[i] -= a[i][k] * y[k];
        }
        y[i] /= a[i][i];
    }
    for i in (0..m).rev() {
        for k in i + 1..m {
            y[i] -= a[k][i] * y[k];
        }
        y[i] /= a[i][i];
    }
    for (r, &i) in free.iter().enumerate() {
        assert!((x[i][0] - y[r]).abs() < 1e-9 * (1.0 + y[r].abs()), "{} vs {}", x[i][0], y[r]);
    }
    assert_eq!(x[5][0], held, "the fixed value is kept");
}

/// Multigrid and the diagonal precondition the same system: the same solution, in far
/// fewer iterations; and linear functions are still reproduced.
#[test]
fn multigrid_solves_the_same_system() {
    let (p, t) = lattice(80);
    let topo = Topology::new(p.len(), &t).unwrap();
    let mut lap = Laplacian::new(&topo, &t);
    lap.set_cotangent_weights(&p, &t, None);
    let n = p.len();
    let mut fixed = vec![false; n];
    for &h in &topo.boundary {
        fixed[tail(&t, h) as usize] = true;
    }
    let mut s = 99u64;
    let mut rnd = || {
        s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let b: Vec<[f64; 2]> = (0..n).map(|_| [rnd(), rnd()]).collect();
    let start: Vec<[f64; 2]> = p.iter().map(|q| [q.x - 2.0 * q.y, 0.3 * q.x]).collect();
    let (mut x_mg, mut x_j) = (start.clone(), start.clone());
    let mg = CgOptions::new(1e-12, 10_000);
    let jacobi = CgOptions { multigrid_above: usize::MAX, ..mg };
    let r_mg = lap
        .solve(Some(&fixed), &b, &mut x_mg, mg, lap.preconditioner(Some(&fixed), mg).as_ref())
        .unwrap();
    let r_j = lap
        .solve(
            Some(&fixed),
            &b,
            &mut x_j,
            jacobi,
            lap.preconditioner(Some(&fixed), jacobi).as_ref(),
        )
        .unwrap();
    assert!(r_mg.iterations * 4 < r_j.iterations, "{r_mg:?} vs {r_j:?}");
    let scale = x_j.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    for (a, c) in x_mg.iter().zip(&x_j) {
        for k in 0..2 {
            assert!((a[k] - c[k]).abs() < 1e-8 * scale, "{a:?} vs {c:?}");
        }
    }
    // Linear precision through the multigrid path.
    let f = |x: DVec3| [2.0 * x.x - 3.0 * x.y + 1.0, 0.5 * x.x + x.y];
    let mut x: Vec<[f64; 2]> =
        p.iter().zip(&fixed).map(|(q, &fx)| if fx { f(*q) } else { [0.0; 2] }).collect();
    let zero = vec![[0.0; 2]; n];
    lap.solve(Some(&fixed), &zero, &mut x, mg, lap.preconditioner(Some(&fixed), mg).as_ref())
        .unwrap();
    for (q, xi) in p.iter().zip(&x) {
        let e = f(*q);
        assert!((xi[0] - e[0]).abs() < 1e-8 && (xi[1] - e[1]).abs() < 1e-8, "{xi:?} vs {e:?}");
    }
}

/// A hierarchy whose coarsening stalls (here at once: two of the lattice's three colour
/// classes held, so no two free vertices are neighbours and no aggregate forms) above
/// [`DENSE_MAX`] rows smooths its coarsest level rather than factoring it, and still
/// preconditions the solve to the same answer as the diagonal.
#[test]
fn a_stalled_hierarchy_is_not_factored() {
    let n = 80;
    let (p, t) = lattice(n);
    let topo = Topology::new(p.len(), &t).unwrap();
    let mut lap = Laplacian::new(&topo, &t);
    lap.set_cotangent_weights(&p, &t, None);
    let fixed: Vec<bool> = (0..n * n).map(|k| (k / n + 2 * (k % n)) % 3 != 0).collect();
    let free = fixed.iter().filter(|&&f| !f).count();
    assert!(free > DENSE_MAX, "{free} free vertices");
    let mg = Multigrid::new(&lap, Some(&fixed));
    assert!(mg.levels.is_empty() && mg.factor.is_none(), "{} levels", mg.levels.len());
    assert_eq!(mg.coarsest.rows(), free, "the coarsest level is the free rows");
    let b: Vec<[f64; 2]> = (0..n * n).map(|k| [(k % 7) as f64 - 3.0, (k % 5) as f64]).collect();
    let start: Vec<[f64; 2]> = p.iter().map(|q| [q.x, q.y]).collect();
    let opts = CgOptions::new(1e-12, 1000);
    let (mut x_mg, mut x_j) = (start.clone(), start);
    let r_mg = lap.solve(Some(&fixed), &b, &mut x_mg, opts, Some(&mg)).unwrap();
    let r_j = lap.solve(Some(&fixed), &b, &mut x_j, opts, None).unwrap();
    assert!(r_mg.iterations <= r_j.iterations, "{r_mg:?} vs {r_j:?}");
    for (a, c) in x_mg.iter().zip(&x_j) {
        for k in 0..2 {
            assert!((a[k] - c[k]).abs() < 1e-9 * (1.0 + c[k].abs()), "{a:?} vs {c:?}");
        }
    }
}

#[test]
fn failures_are_errors() {
    let (p, t) = lattice(6);
    let topo = Topology::new(p.len(), &t).unwrap();
    let mut lap = Laplacian::new(&topo, &t);
    lap.set_cotangent_weights(&p, &t, None);
    let n = p.len();
    let fixed: Vec<bool> = (0..n).map(|i| i == 0).collect();
    let b: Vec<[f64; 1]> = (0..n).map(|i| [if i == 3 { 1.0 } else { 0.0 }]).collect();
    let mut x = vec![[0.0]; n];
    let few = CgOptions::new(1e-14, 2);
    let e = lap
        .solve(Some(&fixed), &b, &mut x, few, lap.preconditioner(Some(&fixed), few).as_ref())
        .unwrap_err();
    assert!(e.to_string().contains("did not converge"), "{e}");
    let mut bad = b.clone();
    bad[4] = [f64::NAN];
    let opts = CgOptions::new(1e-10, 100);
    assert!(
        lap.solve(
            Some(&fixed),
            &bad,
            &mut x,
            opts,
            lap.preconditioner(Some(&fixed), opts).as_ref()
        )
        .is_err(),
        "NaN"
    );
    // Wrong sizes.
    assert!(
        lap.solve(
            Some(&fixed),
            &b[1..],
            &mut x,
            opts,
            lap.preconditioner(Some(&fixed), opts).as_ref()
        )
        .is_err(),
        "size"
    );
}

#[test]
fn topology_errors_name_the_problem() {
    let t = [[0, 1, 2], [0, 1, 3]];
    let e = Topology::new(4, &t).unwrap_err().to_string();
    assert!(e.contains("same direction"), "{e}");
    let e = Topology::new(5, &[[0, 1, 2], [2, 1, 3]]).unwrap_err().to_string();
    assert!(e.contains("vertex 4 is in no triangle"), "{e}");
    let e = Topology::new(3, &[[0, 1, 1]]).unwrap_err().to_string();
    assert!(e.contains("repeats"), "{e}");
    let e = Topology::new(3, &[[0, 1, 7]]).unwrap_err().to_string();
    assert!(e.contains("vertex 7"), "{e}");
    // Two triangles touching at vertex 0 only.
    let e = Topology::new(5, &[[0, 1, 2], [0, 3, 4]]).unwrap_err().to_string();
    assert!(e.contains("vertex 0 joins 2 separate fans"), "{e}");
    // A good strip: counts.
    let topo = Topology::new(4, &[[0, 1, 2], [2, 1, 3]]).unwrap();
    assert_eq!(topo.edge_count(), 5);
    assert_eq!(topo.euler_characteristic(), 1);
    assert_eq!(topo.boundary_loops(&[[0, 1, 2], [2, 1, 3]]).len(), 1);
}
