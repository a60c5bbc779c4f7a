//! Numerics on sampled signals and random values: the generator behind
//! BRUI, Fourier transforms of curves (TFR), and what is built on them.
//! Plain numbers in, plain numbers out; the operators in `ops/signal*.rs`
//! read the arguments and wrap the results.

pub mod noise;
