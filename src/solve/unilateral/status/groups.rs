//! Pre-pass over proportional unilateral rows (unilateral.md §7.5).
//!
//! Two conditions on the same dofs with proportional coefficients make the
//! active block of T singular when both are active (duplicate stops, or a
//! gap on both sides of one dof). Each such group is reduced, before any
//! solve, to at most two eligible conditions: the tightest lower bound and
//! the tightest upper bound on the common scalar t = ĉ·u. The others can
//! never carry a reaction that the representative could not carry, so they
//! stay inactive. The two representatives are partners: at most one of them
//! is active at a time.

use super::SolveError;
use std::collections::HashMap;

/// Relative tolerance to decide that two normalised rows are equal.
const PROPORTIONAL_TOL: f64 = 1e-10;
/// Relative tolerance on bounds (ε of §7.1).
const BOUND_TOL: f64 = 1e-10;

/// What the pre-pass found.
#[derive(Debug, Clone, PartialEq)]
pub struct Groups {
    /// The other representative of a proportional group (lower bound ↔
    /// upper bound), for conditions that have one.
    pub partner: Vec<Option<usize>>,
    /// Dominated or duplicate conditions: never active.
    pub fixed_inactive: Vec<bool>,
}

/// A row with its dofs sorted, duplicates summed and zeros dropped.
fn canonical(row: &[(usize, f64)]) -> Vec<(usize, f64)> {
    let mut r: Vec<(usize, f64)> = row.to_vec();
    r.sort_by_key(|&(j, _)| j);
    let mut out: Vec<(usize, f64)> = Vec::with_capacity(r.len());
    for (j, v) in r {
        match out.last_mut() {
            Some(last) if last.0 == j => last.1 += v,
            _ => out.push((j, v)),
        }
    }
    out.retain(|&(_, v)| v != 0.0);
    out
}

/// Groups proportional rows, checks their bounds, and picks representatives.
/// Errors: `Conflicting` when a group's largest lower bound exceeds its
/// smallest upper bound; `DependentConditions` for an empty (all-zero) row.
pub fn analyse(rows: &[Vec<(usize, f64)>], sense: &[f64], d: &[f64]) -> Result<Groups, SolveError> {
    let m = rows.len();
    let mut groups = Groups { partner: vec![None; m], fixed_inactive: vec![false; m] };
    // Normalised rows: first coefficient 1, so c_i = mu_i · ĉ with ĉ shared.
    let mut mu = vec![0.0; m];
    let mut normal: Vec<Vec<(usize, f64)>> = Vec::with_capacity(m);
    for (i, row) in rows.iter().enumerate() {
        let r = canonical(row);
        let Some(&(_, first)) = r.first() else {
            return Err(SolveError::DependentConditions { conditions: vec![i] });
        };
        mu[i] = first;
        normal.push(r.iter().map(|&(j, v)| (j, v / first)).collect());
    }
    // Bucket by dof pattern, then compare coefficients inside a bucket.
    let mut buckets: HashMap<Vec<usize>, Vec<Vec<usize>>> = HashMap::new();
    for (i, r) in normal.iter().enumerate() {
        let key: Vec<usize> = r.iter().map(|&(j, _)| j).collect();
        let list = buckets.entry(key).or_default();
        let same = |g: &Vec<usize>| {
            normal[g[0]]
                .iter()
                .zip(r)
                .all(|(&(_, a), &(_, b))| (a - b).abs() <= PROPORTIONAL_TOL * a.abs().max(b.abs()))
        };
        match list.iter_mut().find(|g| same(g)) {
            Some(g) => g.push(i),
            None => list.push(vec![i]),
        }
    }
    let mut all: Vec<Vec<usize>> = buckets.into_values().flatten().filter(|g| g.len() > 1).collect();
    all.sort();
    for g in all {
        // s_i (mu_i t − d_i) ≥ 0: a lower bound on t when s_i mu_i > 0.
        let mut lower: Option<(usize, f64)> = None;
        let mut upper: Option<(usize, f64)> = None;
        for &i in &g {
            let b = d[i] / mu[i];
            if sense[i] * mu[i] > 0.0 {
                if lower.is_none_or(|(_, l)| b > l + BOUND_TOL * b.abs().max(l.abs())) {
                    lower = Some((i, b));
                }
            } else if upper.is_none_or(|(_, u)| b < u - BOUND_TOL * b.abs().max(u.abs())) {
                upper = Some((i, b));
            }
        }
        if let (Some((il, l)), Some((iu, u))) = (lower, upper) {
            if l > u + BOUND_TOL * l.abs().max(u.abs()) {
                let mut c = vec![il, iu];
                c.sort_unstable();
                return Err(SolveError::Conflicting { conditions: c });
            }
            groups.partner[il] = Some(iu);
            groups.partner[iu] = Some(il);
        }
        let keep = [lower.map(|p| p.0), upper.map(|p| p.0)];
        for &i in &g {
            if !keep.contains(&Some(i)) {
                groups.fixed_inactive[i] = true;
            }
        }
    }
    Ok(groups)
}

#[cfg(test)]
#[path = "../tests/groups.rs"]
mod tests;
