//! Numerics on sampled signals and random values: the generator behind
//! BRUI, Fourier transforms of curves (TFR), and what is built on them.
//! Plain numbers in, plain numbers out; the operators (`ops/noise.rs`, `ops/fourier.rs`)
//! read the arguments and wrap the results.

pub mod complex;
pub mod covariance;
pub mod fit;
pub mod fourier;
pub mod histogram;
pub mod levmar;
pub mod noise;
pub mod oscillator;
pub mod pearson;
pub mod weibull;
