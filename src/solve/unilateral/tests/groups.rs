use super::*;

#[test]
fn gap_on_both_sides_makes_partners() {
    // −0.1 ≤ u ≤ 0.2 (case l), plus an unrelated row.
    let rows = vec![vec![(0, 1.0)], vec![(0, 1.0)], vec![(1, 1.0)]];
    let g = analyse(&rows, &[1.0, -1.0, 1.0], &[-0.1, 0.2, 0.0]).unwrap();
    assert_eq!(g.partner, vec![Some(1), Some(0), None]);
    assert_eq!(g.fixed_inactive, vec![false; 3]);
}

#[test]
fn crossed_limits_conflict() {
    // 0.3 ≤ u ≤ 0.2 (case l2), written with a scaled MAXI row.
    let rows = vec![vec![(0, 1.0)], vec![(0, 2.0)]];
    let e = analyse(&rows, &[1.0, -1.0], &[0.3, 0.4]).unwrap_err();
    assert_eq!(e, SolveError::Conflicting { conditions: vec![0, 1] });
}

#[test]
fn duplicates_and_dominated_stay_inactive() {
    // Three MINI on u0 − u1 (one written negated as a MAXI), the same
    // bound twice and one weaker bound.
    let rows = vec![
        vec![(0, 1.0), (1, -1.0)],
        vec![(1, 2.0), (0, -2.0)],
        vec![(0, 1.0), (1, -1.0)],
        vec![(0, 3.0), (1, -3.0)],
    ];
    // rows 0: t ≥ 1; 1: MAXI −2t ≤ −2 ⇒ t ≥ 1; 2: t ≥ 0.5; 3: 3t ≥ 3 ⇒ t ≥ 1.
    let g = analyse(&rows, &[1.0, -1.0, 1.0, 1.0], &[1.0, -2.0, 0.5, 3.0]).unwrap();
    assert_eq!(g.fixed_inactive, vec![false, true, true, true]);
    assert_eq!(g.partner, vec![None; 4]);
}

#[test]
fn empty_row_is_dependent() {
    let rows = vec![vec![(0, 0.0)]];
    assert!(matches!(analyse(&rows, &[1.0], &[0.0]), Err(SolveError::DependentConditions { .. })));
}
