//! Every UNIL method through `solve_unilateral` (the sparse path) against
//! CONDENSE on the cases of unilateral-cases.md and on random problems.

use super::kit::*;
use super::status::{chain, cycling, two_spans};
use crate::solve::problem::{Condition, Kind, Load, Matrix, Problem, Solution};
use crate::solve::unilateral::{solve_unilateral, Method, UnilCache, UnilOptions};
use crate::solve::SolveError;
use faer::Mat;

/// The sparse problem of a dense test case (diagonal always stored, so that
/// a zero stiffness still touches its unknown).
pub(super) fn sparse(d: &Dense) -> (Problem, Load) {
    let n = d.n();
    let mut entries = Vec::new();
    for j in 0..n {
        for i in 0..n {
            if i == j || d.k[(i, j)] != 0.0 {
                entries.push((i, j, d.k[(i, j)]));
            }
        }
    }
    let conditions = d
        .rows
        .iter()
        .zip(&d.sense)
        .map(|(r, &s)| Condition { terms: r.clone(), kind: if s > 0.0 { Kind::Mini } else { Kind::Maxi }, dual: None })
        .collect();
    (Problem { k: Matrix { n, entries, symmetric: true }, conditions }, Load { f: d.f.clone(), d: d.d.clone() })
}

fn run(p: &Problem, l: &Load, method: Method) -> Result<Solution, SolveError> {
    let o = UnilOptions { method, ..Default::default() };
    solve_unilateral(p, l, &o, &mut UnilCache::default(), &mut |_| {}).map(|r| r.0)
}

/// KKT check of a sparse candidate: equilibrium `K u + Σ cᵢᵀ λᵢ = F`,
/// equalities met, unilateral feasibility, signs and complementarity,
/// relative to the problem's scales.
pub(super) fn sparse_kkt_ok(p: &Problem, l: &Load, s: &Solution, tol: f64) -> bool {
    let n = p.k.n;
    let umax = s.u.iter().fold(1e-300_f64, |a, v| a.max(v.abs()));
    let fmax = l.f.iter().chain(&s.lambda).fold(1e-300_f64, |a, v| a.max(v.abs()));
    let kmax = p.k.entries.iter().fold(0.0_f64, |a, e| a.max(e.2.abs()));
    let mut r: Vec<f64> = l.f.iter().map(|f| -f).collect();
    for &(i, j, v) in &p.k.entries {
        r[i] += v * s.u[j];
    }
    for (c, lam) in p.conditions.iter().zip(&s.lambda) {
        for &(j, v) in &c.terms {
            r[j] += v * lam;
        }
    }
    let balanced = (0..n).all(|i| r[i].abs() <= tol * (fmax + kmax * umax));
    let rows_ok = p.conditions.iter().enumerate().all(|(i, c)| {
        let chat = c.terms.iter().fold(1.0_f64, |a, t| a.max(t.1.abs()));
        let cu: f64 = c.terms.iter().map(|&(j, v)| v * s.u[j]).sum();
        let gap = (cu - l.d[i]) / chat;
        // Lengths: the displacements, the limit, and force over stiffness
        // (u may be all round-off when every support acts).
        let scale = tol * (umax + l.d[i].abs() / chat + fmax / kmax.max(f64::MIN_POSITIVE));
        let lam = s.lambda[i];
        let sense = match c.kind {
            Kind::Equal => return gap.abs() <= scale,
            Kind::Mini => 1.0,
            Kind::Maxi => -1.0,
        };
        sense * gap >= -scale && sense * lam <= tol * fmax && (lam.abs() <= tol * fmax || gap.abs() <= scale)
    });
    balanced && rows_ok
}

/// Same answer (or the same kind of error) as CONDENSE.
/// Returns whether the case was solved (not an error).
///
/// Statuses may differ only on degenerate conditions (zero gap and zero
/// multiplier: both statuses are solutions, unilateral-cases a3), which
/// depend on the starting status. CONDENSE reports dependent unilateral
/// rows as soon as its cold start (all active) meets them; a method that
/// starts elsewhere may never activate the dependent set, and then its
/// answer must be a KKT point.
pub(super) fn same_as_condense(name: &str, p: &Problem, l: &Load, method: Method, tol: f64) -> bool {
    let want = run(p, l, Method::Condense);
    let got = run(p, l, method);
    match (&want, &got) {
        (Ok(a), Ok(b)) => {
            let scale = a.u.iter().chain(&a.lambda).fold(1.0_f64, |s, v| s.max(v.abs()));
            for (k, (x, y)) in a.u.iter().zip(&b.u).enumerate() {
                assert!((x - y).abs() <= tol * scale, "{name} {method:?}: u[{k}] {y} vs {x}");
            }
            for (k, (x, y)) in a.lambda.iter().zip(&b.lambda).enumerate() {
                assert!((x - y).abs() <= tol * scale, "{name} {method:?}: λ[{k}] {y} vs {x}");
            }
            for (i, c) in p.conditions.iter().enumerate() {
                if a.active[i] != b.active[i] {
                    let cu: f64 = c.terms.iter().map(|&(j, v)| v * a.u[j]).sum();
                    let degenerate = a.lambda[i].abs() <= tol * scale && (cu - l.d[i]).abs() <= tol * scale;
                    assert!(degenerate, "{name} {method:?}: status of condition {i}: {:?} vs {:?}", b.active, a.active);
                }
            }
            assert!(sparse_kkt_ok(p, l, b, tol), "{name} {method:?}: not a KKT point: {b:?}");
            true
        }
        (Err(a), Err(b)) => {
            assert_eq!(std::mem::discriminant(a), std::mem::discriminant(b), "{name} {method:?}: {b:?} vs {a:?}");
            false
        }
        (Err(SolveError::DependentConditions { .. }), Ok(b)) => {
            assert!(sparse_kkt_ok(p, l, b, tol), "{name} {method:?}: not a KKT point: {b:?}");
            true
        }
        _ => panic!("{name} {method:?}: {got:?} vs CONDENSE {want:?}"),
    }
}

/// What a case must give, whatever the method: the answer, or the error
/// its physics calls for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Expect {
    Solved,
    /// The load drives a rigid mode away from every support.
    Infeasible,
    /// Limits that cross (u ≥ a and u ≤ b with a > b).
    Conflicting,
}

/// The case's outcome, as [`Expect`] names it.
fn outcome(r: &Result<Solution, SolveError>) -> Option<Expect> {
    match r {
        Ok(_) => Some(Expect::Solved),
        Err(SolveError::Infeasible { .. }) => Some(Expect::Infeasible),
        Err(SolveError::Conflicting { .. }) => Some(Expect::Conflicting),
        Err(_) => None,
    }
}

/// The cases of unilateral-cases.md as sparse problems, with what each
/// must give.
pub(super) fn cases() -> Vec<(String, Problem, Load, Expect)> {
    use Expect::*;
    let mut out: Vec<(String, Dense, Expect)> = Vec::new();
    for g in [1.0, 0.2, 0.5] {
        out.push((format!("a g={g}"), spring(10.0, 5.0).cond(&[(0, 1.0)], MAXI, g), Solved));
    }
    out.push(("a4".into(), spring(10.0, -5.0).cond(&[(0, 1.0)], MINI, -0.2), Solved));
    for load in [0.4, 1.0, 3.0] {
        out.push((format!("b P={load}"), chain(load), Solved));
    }
    out.push(("c".into(), two_spans(1.0), Solved));
    // Uplift at every support: nothing holds the beam.
    out.push(("c2".into(), two_spans(-1.0), Infeasible));
    for (p, expect) in [(1.0, Solved), (-1.0, Infeasible)] {
        let mut f = vec![0.0; 6];
        f[2] = -p;
        let d = Dense::new(beam(&[0.0, 1.0, 4.0], 1.0), f).cond(&[(0, 1.0)], MINI, 0.0).cond(&[(4, 1.0)], MINI, 0.0);
        out.push((format!("d/e2 P={p}"), d, expect));
    }
    // A free unknown pushed away from its stop, then onto it.
    out.push(("e1".into(), spring(0.0, 1.0).cond(&[(0, 1.0)], MINI, 0.0), Infeasible));
    out.push(("e1'".into(), spring(0.0, -1.0).cond(&[(0, 1.0)], MINI, 0.0), Solved));
    // A load beyond the last support tips the beam off the first one.
    let mut f = vec![0.0; 6];
    f[4] = -1.0;
    let e3 = Dense::new(beam(&[0.0, 3.0, 4.0], 1.0), f).cond(&[(0, 1.0)], MINI, 0.0).cond(&[(2, 1.0)], MINI, 0.0);
    out.push(("e3".into(), e3, Infeasible));
    let crossed = spring(10.0, 0.0).cond(&[(0, 1.0)], MINI, 1.0).cond(&[(0, 1.0)], MAXI, 0.0);
    out.push(("e4".into(), crossed, Conflicting));
    out.push(("f".into(), cycling(), Solved));
    let k2 = Mat::from_fn(2, 2, |i, j| if i == j { [2.0, 3.0][i] } else { 0.0 });
    for load in [5.0, 1.5] {
        out.push((
            format!("g {load}"),
            Dense::new(k2.clone(), vec![load, 0.0]).cond(&[(1, 1.0), (0, -1.0)], MINI, -1.0),
            Solved,
        ));
    }
    let twice = spring(10.0, -5.0).cond(&[(0, 1.0)], MINI, -0.2).cond(&[(0, 1.0)], MINI, -0.2);
    out.push(("h".into(), twice, Solved));
    out.push(("i".into(), spring(10.0, 5.0).cond(&[(0, 1.0)], MAXI, 0.5), Solved));
    for scale in [1.0, 7.0, 0.01] {
        let row = [(0, 2.5 * scale), (1, -scale), (2, 3.0 * scale)];
        let d = Dense::new(Mat::identity(3, 3), vec![0.0; 3]).cond(&row, MINI, 0.3 * scale);
        out.push((format!("k {scale}"), d, Solved));
    }
    for (f, dmin, dmax) in [(5.0, -0.1, 0.2), (-5.0, -0.1, 0.2), (1.0, -0.1, 0.2), (1.0, 0.3, 0.2)] {
        let d = spring(10.0, f).cond(&[(0, 1.0)], MINI, dmin).cond(&[(0, 1.0)], MAXI, dmax);
        let expect = if dmin > dmax { Conflicting } else { Solved };
        out.push((format!("l F={f} [{dmin}, {dmax}]"), d, expect));
    }
    let mut all: Vec<(String, Problem, Load, Expect)> = out
        .into_iter()
        .map(|(name, d, expect)| {
            let (p, l) = sparse(&d);
            (name, p, l, expect)
        })
        .collect();
    // Mixed: a spring chain with UX blocked at 0 (bilateral) and a MAXI
    // stop at the free end, for several loads.
    for load in [1.0, 3.0, -1.0] {
        let mut entries = vec![];
        for i in 0..3 {
            entries.extend([(i, i, 1.0), (i + 1, i + 1, 1.0), (i, i + 1, -1.0), (i + 1, i, -1.0)]);
        }
        let p = Problem {
            k: Matrix { n: 4, entries, symmetric: true },
            conditions: vec![
                Condition { terms: vec![(0, 1.0)], kind: Kind::Equal, dual: None },
                Condition { terms: vec![(3, 1.0)], kind: Kind::Maxi, dual: None },
                Condition { terms: vec![(2, 1.0), (1, -0.5)], kind: Kind::Mini, dual: None },
            ],
        };
        all.push((format!("mixed {load}"), p, Load { f: vec![0.0, 0.0, 0.3, load], d: vec![0.1, 1.0, -0.2] }, Solved));
    }
    all
}

/// Every case gives what it must, with CONDENSE and with `method`, and
/// both give the same answer.
fn check_cases(method: Method, tol: f64) {
    for (name, p, l, expect) in cases() {
        assert_eq!(outcome(&run(&p, &l, Method::Condense)), Some(expect), "{name}: CONDENSE");
        assert_eq!(outcome(&run(&p, &l, method)), Some(expect), "{name}: {method:?}");
        assert_eq!(same_as_condense(&name, &p, &l, method, tol), expect == Expect::Solved, "{name}");
    }
}

#[test]
fn ancien_matches_condense_on_the_cases() {
    check_cases(Method::Ancien, 1e-9);
}

#[test]
fn bilateral_rows_on_contact_unknowns() {
    // A relation between two supported unknowns, and a BLOQ on a third
    // one tied to them by another relation: every method agrees.
    let mut entries = vec![(0, 0, 1.0)];
    for i in 0..3 {
        entries.extend([(i, i, 1.0), (i + 1, i + 1, 1.0), (i, i + 1, -1.0), (i + 1, i, -1.0)]);
    }
    let p = Problem {
        k: Matrix { n: 4, entries, symmetric: true },
        conditions: vec![
            Condition { terms: vec![(1, 1.0)], kind: Kind::Maxi, dual: None },
            Condition { terms: vec![(2, 1.0)], kind: Kind::Mini, dual: None },
            Condition { terms: vec![(2, 1.0), (3, -0.5)], kind: Kind::Equal, dual: None },
        ],
    };
    for f in [0.4, 1.0, -3.0] {
        let l = Load { f: vec![0.0, f, 0.2, -f], d: vec![0.3, -0.2, 0.1] };
        assert!(same_as_condense("relation", &p, &l, Method::Ancien, 1e-9));
        assert!(same_as_condense("relation", &p, &l, Method::Creux, 1e-9));
        assert!(same_as_condense("relation", &p, &l, Method::Iter, 1e-8));
    }
    let mut entries = vec![];
    for i in 0..4 {
        entries.extend([(i, i, 2.0), (i + 1, i + 1, 1.0), (i, i + 1, -1.0), (i + 1, i, -1.0)]);
    }
    let p = Problem {
        k: Matrix { n: 5, entries, symmetric: true },
        conditions: vec![
            Condition { terms: vec![(1, 1.0)], kind: Kind::Maxi, dual: None },
            Condition { terms: vec![(1, 1.0), (3, -1.0)], kind: Kind::Equal, dual: None },
            // Touches P only once the previous relation has moved.
            Condition { terms: vec![(3, 1.0), (4, 1.0)], kind: Kind::Equal, dual: None },
            Condition { terms: vec![(0, 1.0)], kind: Kind::Mini, dual: None },
        ],
    };
    for f in [1.0, -2.0] {
        let l = Load { f: vec![-0.5, f, 0.0, 0.3, -f], d: vec![0.1, 0.02, 0.05, -0.2] };
        for m in [Method::Ancien, Method::Creux, Method::Iter] {
            assert!(same_as_condense("chained", &p, &l, m, 1e-9));
        }
    }
}

#[test]
fn creux_matches_condense_on_the_cases() {
    check_cases(Method::Creux, 1e-9);
}

/// A random sparse problem: a banded K (sometimes with one rigid mode),
/// single-unknown and multi-unknown unilateral rows, a few bilateral rows.
pub(super) fn random_problem(rng: &mut Rng) -> (Problem, Load) {
    let n = 2 + rng.below(12);
    let mut entries = Vec::new();
    let free = rng.below(3) == 0;
    for i in 0..n {
        // Springs between neighbours and to the ground (unless free).
        let k = 1.0 + 2.0 * rng.sym().abs();
        if i + 1 < n {
            entries.extend([(i, i, k), (i + 1, i + 1, k), (i, i + 1, -k), (i + 1, i, -k)]);
        }
        if i + 2 < n && rng.below(2) == 0 {
            let k2 = 0.3 * rng.sym().abs();
            entries.extend([(i, i, k2), (i + 2, i + 2, k2), (i, i + 2, -k2), (i + 2, i, -k2)]);
        }
        if !free {
            entries.push((i, i, 0.2 + rng.sym().abs()));
        }
    }
    let mut conditions = Vec::new();
    let mut d = Vec::new();
    let m = 1 + rng.below(n);
    let mut used = vec![false; n];
    for _ in 0..m {
        let j = rng.below(n);
        let kind = if rng.below(2) == 0 { Kind::Mini } else { Kind::Maxi };
        let terms = if rng.below(3) == 0 {
            let l = (j + 1 + rng.below(n - 1)) % n;
            used[l] = true;
            vec![(j, 1.0), (l, -0.5 - rng.sym().abs())]
        } else {
            vec![(j, if rng.below(2) == 0 { 1.0 } else { -2.0 })]
        };
        used[j] = true;
        conditions.push(Condition { terms, kind, dual: None });
        d.push(0.3 * rng.sym());
    }
    if rng.below(3) == 0 {
        if let Some(j) = (0..n).find(|&j| !used[j]) {
            conditions.push(Condition { terms: vec![(j, 1.0)], kind: Kind::Equal, dual: None });
            d.push(0.1 * rng.sym());
            used[j] = true;
        }
    }
    if rng.below(4) == 0 {
        // A bilateral relation between two unknowns free of equalities.
        let free: Vec<usize> = (0..n).filter(|&j| !used[j]).collect();
        if free.len() >= 2 {
            let (a, b) = (free[0], free[free.len() - 1]);
            conditions.push(Condition { terms: vec![(a, 1.0), (b, -1.5)], kind: Kind::Equal, dual: None });
            d.push(0.1 * rng.sym());
        }
    }
    let f = (0..n).map(|_| 2.0 * rng.sym()).collect();
    (Problem { k: Matrix { n, entries, symmetric: true }, conditions }, Load { f, d })
}

#[test]
fn creux_matches_condense_on_random_problems() {
    let mut rng = Rng(0x5EED_C4E7);
    let mut solved = 0;
    for case in 0..400 {
        let (p, l) = random_problem(&mut rng);
        solved += usize::from(same_as_condense(&format!("random {case}"), &p, &l, Method::Creux, 1e-8));
    }
    // Both outcomes must be exercised.
    assert!((200..400).contains(&solved), "{solved} of 400 solved");
}

#[test]
fn ancien_matches_condense_on_random_problems() {
    let mut rng = Rng(0xA7C1_E700);
    let mut solved = 0;
    for case in 0..400 {
        let (p, l) = random_problem(&mut rng);
        solved += usize::from(same_as_condense(&format!("random {case}"), &p, &l, Method::Ancien, 1e-8));
    }
    assert!((200..400).contains(&solved), "{solved} of 400 solved");
}

#[test]
fn iter_matches_condense_on_the_cases() {
    check_cases(Method::Iter, 1e-8);
}

#[test]
fn iter_matches_condense_on_random_problems() {
    let mut rng = Rng(0x17E2_0001);
    let mut solved = 0;
    for case in 0..300 {
        let (p, l) = random_problem(&mut rng);
        solved += usize::from(same_as_condense(&format!("random {case}"), &p, &l, Method::Iter, 1e-8));
    }
    assert!((150..300).contains(&solved), "{solved} of 300 solved");
}

#[test]
fn iter_eliminates_bilateral_relations() {
    let (mut p, mut l) = sparse(&chain(1.0));
    p.conditions.push(Condition { terms: vec![(1, 1.0), (2, -1.0)], kind: Kind::Equal, dual: None });
    l.d.push(0.05);
    assert!(same_as_condense("chain + relation", &p, &l, Method::Iter, 1e-9));
    // A relation that repeats the others is reported, not guessed.
    p.conditions.push(Condition { terms: vec![(2, 2.0), (1, -2.0)], kind: Kind::Equal, dual: None });
    l.d.push(-0.1);
    assert!(matches!(run(&p, &l, Method::Iter), Err(SolveError::DependentConditions { .. })));
}

/// Two bodies that share nothing: the tail of the interrupted
/// factorisation is not connected by the elimination, so CONDENSE needs
/// the explicit tail pairs (its fallback). Checked against the dense
/// reference, and every method against CONDENSE.
#[test]
fn disconnected_contact_zones() {
    let k = Mat::<f64>::from_fn(6, 6, |i, j| {
        let (bi, bj) = (i / 3, j / 3);
        if bi != bj {
            0.0
        } else if i == j {
            2.5
        } else if i.abs_diff(j) == 1 {
            -1.0
        } else {
            0.0
        }
    });
    let d = Dense::new(k, vec![1.0, -0.5, 2.0, 1.0, 0.3, -2.0])
        .cond(&[(2, 1.0)], MAXI, 0.05)
        .cond(&[(0, 1.0), (1, -1.0)], MAXI, 0.1)
        .cond(&[(3, 1.0)], MINI, -0.2)
        .cond(&[(5, 1.0)], MINI, -0.1);
    let want = solve(&d, &Default::default()).unwrap();
    let (p, l) = sparse(&d);
    let got = run(&p, &l, Method::Condense).unwrap();
    for (a, b) in got.u.iter().zip(&want.u) {
        assert!((a - b).abs() < 1e-10, "{:?} vs {:?}", got.u, want.u);
    }
    assert_eq!(got.active, want.active);
    assert!(want.active.iter().any(|a| *a) && want.active.iter().any(|a| !*a), "{want:?}");
    for m in [Method::Ancien, Method::Creux, Method::Iter] {
        assert!(same_as_condense("disconnected", &p, &l, m, 1e-9), "{m:?}");
    }
}

/// Rows that depend on others: a relation between two unknowns that
/// bilateral conditions fix (u0 − u1 ⋈ d with u0, u1 blocked), and a row
/// that is the sum of two others. Each is left out of the iteration; it
/// must hold at the end (every method), else the conditions conflict.
#[test]
fn rows_fixed_by_other_conditions_are_dropped_or_conflict() {
    let mut entries = vec![];
    for i in 0..3 {
        entries.extend([(i, i, 1.0), (i + 1, i + 1, 1.0), (i, i + 1, -1.0), (i + 1, i, -1.0)]);
    }
    let k = Matrix { n: 4, entries, symmetric: true };
    let eq = |j: usize| Condition { terms: vec![(j, 1.0)], kind: Kind::Equal, dual: None };
    let fixed = Problem {
        k: k.clone(),
        conditions: vec![
            eq(0),
            eq(1),
            Condition { terms: vec![(0, 1.0), (1, -1.0)], kind: Kind::Mini, dual: None },
            Condition { terms: vec![(3, 1.0)], kind: Kind::Maxi, dual: None },
        ],
    };
    // u0 = 0.2, u1 = 0: u0 − u1 = 0.2 ≥ −0.1 holds; the stop u3 ≤ 0.5 acts
    // under F3 = 1 (free: u3 = u1 + 2 = 2).
    let holds = Load { f: vec![0.0, 0.0, 0.0, 1.0], d: vec![0.2, 0.0, -0.1, 0.5] };
    for m in [Method::Condense, Method::Creux, Method::Ancien, Method::Iter] {
        let s = run(&fixed, &holds, m).unwrap_or_else(|e| panic!("{m:?}: {e:?}"));
        assert!(!s.active[2] && s.lambda[2] == 0.0, "{m:?}: {s:?}");
        assert!(s.active[3] && (s.u[3] - 0.5).abs() < 1e-10, "{m:?}: {s:?}");
        assert!(sparse_kkt_ok(&fixed, &holds, &s, 1e-9), "{m:?}: {s:?}");
    }
    // u0 − u1 = 0.2 ≥ 0.3 cannot hold. From the cold start (all active)
    // the row is dropped and found violated at the end; CREUX starts from
    // all inactive and meets it as a singular activation instead, which
    // the spec reports as dependent rows (§7.5: do not guess).
    let conflict = Load { d: vec![0.2, 0.0, 0.3, 0.5], ..holds.clone() };
    for m in [Method::Condense, Method::Ancien, Method::Iter] {
        assert!(matches!(run(&fixed, &conflict, m), Err(SolveError::Conflicting { .. })), "{m:?}");
    }
    let creux = run(&fixed, &conflict, Method::Creux);
    assert!(
        matches!(creux, Err(SolveError::DependentConditions { ref conditions }) if conditions.contains(&2)),
        "{creux:?}"
    );
    // u0 ≥ 0, u1 ≥ 0 and u0 + u1 ≥ 0 pressed down by F = −1 on both
    // (springs to the ground keep K regular): the third row depends on the
    // other two; it is deferred (its value follows from theirs) and the
    // answer is a KKT point with the first two active.
    let mut ground = k.clone();
    ground.entries.extend((0..4).map(|i| (i, i, 0.5)));
    let sum = Problem {
        k: ground,
        conditions: vec![
            Condition { terms: vec![(0, 1.0)], kind: Kind::Mini, dual: None },
            Condition { terms: vec![(1, 1.0)], kind: Kind::Mini, dual: None },
            Condition { terms: vec![(0, 1.0), (1, 1.0)], kind: Kind::Mini, dual: None },
        ],
    };
    let down = Load { f: vec![-1.0, -1.0, 0.0, 0.0], d: vec![0.0; 3] };
    let r = run(&sum, &down, Method::Condense).unwrap();
    assert_eq!(&r.active[..3], &[true, true, false]);
    assert!(sparse_kkt_ok(&sum, &down, &r, 1e-9), "{r:?}");
}

/// A BLOQ on an unknown that no stiffness touches (UX of a spring node):
/// every method solves it (CREUX imposes such rows on a stored diagonal).
#[test]
fn bloq_on_an_unknown_without_stiffness() {
    // u0, u1: springs 2 and 3; u2 touched by nothing but its BLOQ.
    let p = Problem {
        k: Matrix { n: 3, entries: vec![(0, 0, 2.0), (1, 1, 3.0)], symmetric: true },
        conditions: vec![
            Condition { terms: vec![(1, 1.0), (0, -1.0)], kind: Kind::Mini, dual: None },
            Condition { terms: vec![(2, 1.0)], kind: Kind::Equal, dual: None },
        ],
    };
    // F0 = 5 pushes u0 up to 2.5; u1 − u0 ≥ −1 makes it 1.6 / 0.6.
    let l = Load { f: vec![5.0, 0.0, 0.0], d: vec![-1.0, 0.25] };
    for m in [Method::Condense, Method::Creux, Method::Ancien, Method::Iter] {
        let s = run(&p, &l, m).unwrap_or_else(|e| panic!("{m:?}: {e:?}"));
        assert!((s.u[0] - 1.6).abs() < 1e-12 && (s.u[1] - 0.6).abs() < 1e-12, "{m:?}: {s:?}");
        assert!((s.u[2] - 0.25).abs() < 1e-12 && s.lambda[1].abs() < 1e-12, "{m:?}: {s:?}");
    }
}
