//! Classes of events for HIST: each event is a tuple of reals, each
//! coordinate sorted into the intervals of its own list of bounds; the
//! classes of the coordinates combine into one global number, the first
//! coordinate varying fastest.

/// The global class (from 1) of each event, 0 when a coordinate lies
/// outside its bounds, and the number of events in each class.
/// `values[d][e]` is coordinate `d` of event `e`; `bounds[d]` are the
/// strictly increasing bounds of coordinate `d`. Intervals are closed
/// below and open above, except the last, which keeps its upper bound.
pub fn classify(values: &[&[f64]], bounds: &[&[f64]]) -> (Vec<i64>, Vec<i64>) {
    let events = values.first().map_or(0, |v| v.len());
    let total: usize = bounds.iter().map(|b| b.len().saturating_sub(1)).product();
    let mut occurrences = vec![0i64; total];
    let classes = (0..events)
        .map(|e| {
            let mut global = 0;
            let mut stride = 1;
            for (v, b) in values.iter().zip(bounds) {
                match interval(v[e], b) {
                    Some(k) => global += k * stride,
                    None => return 0,
                }
                stride *= b.len() - 1;
            }
            occurrences[global] += 1;
            global as i64 + 1
        })
        .collect();
    (classes, occurrences)
}

/// The interval (from 0) of `bounds` holding `x`.
fn interval(x: f64, bounds: &[f64]) -> Option<usize> {
    let n = bounds.len().checked_sub(1)?;
    if n == 0 || x < bounds[0] || x > bounds[n] {
        return None;
    }
    // The number of bounds ≤ x, less one, is the interval; x on the
    // top bound goes in the last one.
    Some((bounds.partition_point(|b| *b <= x) - 1).min(n - 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_coordinates() {
        let x1 = [0.2, 0.1, 1.1, 0.5, 0.4];
        let x2 = [4.0, 14.0, 9.0, 10.0, 1.0];
        let (c, o) = classify(&[&x1, &x2], &[&[0.0, 0.5, 1.0], &[0.0, 5.0, 10.0, 15.0, 20.0]]);
        assert_eq!(c, vec![1, 5, 0, 6, 1]);
        assert_eq!(o, vec![2, 0, 0, 0, 1, 1, 0, 0]);
    }
}
