//! The residual `b − M x` of the doubled system accumulated in
//! double-double arithmetic, for iterative refinement.
//!
//! Refinement with a residual computed in working precision only bounds
//! the backward error: it can move a correctly rounded unknown by an ulp
//! as easily as it mends one. With the residual carried to about twice
//! the working precision (each product split exactly with an FMA, each sum
//! with its rounding error), one step brings a well-conditioned solution
//! to within an ulp of the exact one, which is what Cast3M's decks check
//! on relations.

use super::lagrange::Doubled;

/// `a + b` as a rounded sum and its exact rounding error (Knuth's TwoSum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// A running sum kept as hi + lo.
#[derive(Clone, Copy, Default)]
struct Dd {
    hi: f64,
    lo: f64,
}

impl Dd {
    fn add(&mut self, v: f64) {
        let (s, e) = two_sum(self.hi, v);
        self.hi = s;
        self.lo += e;
    }

    /// Adds the exact product `a · x` (its rounding error from an FMA).
    fn add_product(&mut self, a: f64, x: f64) {
        let p = a * x;
        let e = a.mul_add(x, -p);
        self.add(p);
        self.lo += e;
    }

    fn value(self) -> f64 {
        self.hi + self.lo
    }
}

/// `b − M x` (natural numbering), each row summed in double-double.
pub(crate) fn residual(sys: &Doubled, b: &[f64], x: &[f64]) -> Vec<f64> {
    let mut acc: Vec<Dd> = b.iter().map(|&v| Dd { hi: v, lo: 0.0 }).collect();
    for col in 0..sys.dim() {
        for k in sys.col_ptr[col]..sys.col_ptr[col + 1] {
            let r = sys.row_idx[k];
            let a = -sys.values[k];
            acc[r].add_product(a, x[col]);
            if sys.symmetric && r != col {
                acc[col].add_product(a, x[r]);
            }
        }
    }
    acc.into_iter().map(Dd::value).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_and_sums_keep_their_rounding_errors() {
        // 1 + 2⁻⁶⁰ − 1 is lost in f64 and kept here.
        let mut d = Dd { hi: 1.0, lo: 0.0 };
        d.add(2f64.powi(-60));
        d.add(-1.0);
        assert_eq!(d.value(), 2f64.powi(-60));
        // (1 + 2⁻³⁰)² = 1 + 2⁻²⁹ + 2⁻⁶⁰: the last term is the FMA's part.
        let a = 1.0 + 2f64.powi(-30);
        let mut d = Dd::default();
        d.add_product(a, a);
        d.add(-1.0 - 2f64.powi(-29));
        assert_eq!(d.value(), 2f64.powi(-60));
    }
}
