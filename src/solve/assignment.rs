//! The assignment problem: the permutation `p` of 0..n minimising
//! `sum_i cost[i][p[i]]` (ORDO 'COUT').

/// Hungarian method with potentials (Kuhn–Munkres, O(n^3)): rows are
/// added one by one and the assignment is grown along shortest
/// augmenting paths of reduced cost. `cost` is row-major, n x n.
pub fn hungarian(cost: &[f64], n: usize) -> Vec<usize> {
    debug_assert_eq!(cost.len(), n * n);
    // 1-based arrays with a dummy column 0, as the method is usually written.
    let (mut u, mut v) = (vec![0.0; n + 1], vec![0.0; n + 1]);
    let mut row_of = vec![0usize; n + 1]; // row_of[j]: row assigned to column j
    let mut way = vec![0usize; n + 1];
    for i in 1..=n {
        row_of[0] = i;
        let mut j0 = 0;
        let mut minv = vec![f64::INFINITY; n + 1];
        let mut used = vec![false; n + 1];
        loop {
            used[j0] = true;
            let i0 = row_of[j0];
            let (mut delta, mut j1) = (f64::INFINITY, 0);
            for j in 1..=n {
                if !used[j] {
                    let cur = cost[(i0 - 1) * n + (j - 1)] - u[i0] - v[j];
                    if cur < minv[j] {
                        minv[j] = cur;
                        way[j] = j0;
                    }
                    if minv[j] < delta {
                        delta = minv[j];
                        j1 = j;
                    }
                }
            }
            for j in 0..=n {
                if used[j] {
                    u[row_of[j]] += delta;
                    v[j] -= delta;
                } else {
                    minv[j] -= delta;
                }
            }
            j0 = j1;
            if row_of[j0] == 0 {
                break;
            }
        }
        loop {
            let j1 = way[j0];
            row_of[j0] = row_of[j1];
            j0 = j1;
            if j0 == 0 {
                break;
            }
        }
    }
    let mut p = vec![0; n];
    for j in 1..=n {
        p[row_of[j] - 1] = j - 1;
    }
    p
}

/// Every permutation tried (Heap's algorithm): the exhaustive search
/// ORDO 'COUT' 'COMP' asks for; the first minimum found is kept.
pub fn exhaustive(cost: &[f64], n: usize) -> Vec<usize> {
    let total = |p: &[usize]| p.iter().enumerate().map(|(i, &j)| cost[i * n + j]).sum::<f64>();
    let mut p: Vec<usize> = (0..n).collect();
    let (mut best, mut best_cost) = (p.clone(), total(&p));
    let mut c = vec![0usize; n];
    let mut i = 0;
    while i < n {
        if c[i] < i {
            if i % 2 == 0 {
                p.swap(0, i);
            } else {
                p.swap(c[i], i);
            }
            let t = total(&p);
            if t < best_cost {
                best_cost = t;
                best = p.clone();
            }
            c[i] += 1;
            i = 0;
        } else {
            c[i] = 0;
            i += 1;
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hungarian_matches_exhaustive() {
        let cost = [4.0, 1.0, 3.0, 2.0, 0.0, 5.0, 3.0, 2.0, 2.0];
        let p = hungarian(&cost, 3);
        let q = exhaustive(&cost, 3);
        let t = |p: &[usize]| p.iter().enumerate().map(|(i, &j)| cost[i * 3 + j]).sum::<f64>();
        assert_eq!(t(&p), 5.0);
        assert_eq!(t(&q), 5.0);
    }
}
