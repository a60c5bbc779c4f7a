//! The primitive of a curve (PRIM on an EVOLUTIO): the running integral by
//! trapezoids, 0 at the first abscissa, given at the curve's own abscissae.

use super::model::Curve;

impl Curve {
    /// The primitive; the abscissae must increase.
    pub fn primitive(&self) -> Result<Curve, String> {
        if let Some(w) = self.x.windows(2).find(|w| w[1] < w[0]) {
            return Err(format!("the abscissae of the curve must increase, found {} after {}", w[1], w[0]));
        }
        let mut y = Vec::with_capacity(self.y.len());
        let mut acc = 0.0;
        for i in 0..self.x.len().min(self.y.len()) {
            if i > 0 {
                acc += 0.5 * (self.y[i] + self.y[i - 1]) * (self.x[i] - self.x[i - 1]);
            }
            y.push(acc);
        }
        Ok(Curve {
            legend: self.legend.clone(),
            x_name: self.x_name.clone(),
            y_name: self.y_name.clone(),
            x: self.x.clone(),
            y,
        })
    }
}
