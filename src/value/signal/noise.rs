//! Random values for BRUI: one generator per interpreter, started from the
//! same seed on every run, so a deck gives the same values each time it
//! runs while consecutive draws in one run differ (brui.notice: the
//! generator restarts at each launch, and a loop gets distinct series).

use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Exp, Normal, Open01, Poisson};

/// The fixed seed every run starts from.
const SEED: u64 = 0x6769_6269;

/// The law of the values drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Law {
    /// Mean and standard deviation.
    Gauss { mean: f64, sd: f64 },
    /// Uniform on `mean ± half_width`.
    Uniform { mean: f64, half_width: f64 },
    /// Exponential of the given mean (which is also its standard deviation).
    Exponential { mean: f64 },
}

#[derive(Debug, Clone)]
pub struct Noise {
    rng: ChaCha8Rng,
}

impl Default for Noise {
    fn default() -> Self {
        Noise { rng: ChaCha8Rng::seed_from_u64(SEED) }
    }
}

impl Noise {
    /// Pass over `n` draws, as if that many values had been drawn: the
    /// stream is a counter, so this costs nothing however large `n` is.
    pub fn skip(&mut self, n: u64) {
        // A uniform f64 uses one u64, that is two 32-bit words.
        let pos = self.rng.get_word_pos();
        self.rng.set_word_pos(pos.wrapping_add(2 * n as u128));
    }

    /// `n` values of `law`. Its parameters must be finite and the spread
    /// positive (the caller words the error).
    pub fn draw(&mut self, law: Law, n: usize) -> Result<Vec<f64>, String> {
        let rng = &mut self.rng;
        Ok(match law {
            Law::Gauss { mean, sd } => {
                let d = Normal::new(mean, sd).map_err(|e| e.to_string())?;
                (0..n).map(|_| d.sample(rng)).collect()
            }
            Law::Uniform { mean, half_width } => (0..n)
                .map(|_| {
                    let u: f64 = Open01.sample(rng);
                    mean + (2.0 * u - 1.0) * half_width
                })
                .collect(),
            Law::Exponential { mean } => {
                let d = Exp::new(1.0 / mean).map_err(|e| e.to_string())?;
                (0..n).map(|_| d.sample(rng)).collect()
            }
        })
    }

    /// `n` counts of a Poisson law of the given mean.
    pub fn poisson(&mut self, mean: f64, n: usize) -> Result<Vec<i64>, String> {
        if mean == 0.0 {
            return Ok(vec![0; n]);
        }
        let d = Poisson::new(mean).map_err(|e| e.to_string())?;
        Ok((0..n).map(|_| d.sample(&mut self.rng) as i64).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_stream_and_skip_matches_draws() {
        let (mut a, mut b) = (Noise::default(), Noise::default());
        let law = Law::Uniform { mean: 0.0, half_width: 1.0 };
        let x = a.draw(law, 5).unwrap();
        b.skip(3);
        let y = b.draw(law, 2).unwrap();
        assert_eq!(&x[3..], &y[..]);
        assert!(x.iter().all(|v| v.abs() < 1.0));
    }
}
