//! Material properties that depend on a state: water and steam
//! ([`water`], the laws of `VARI 'HLS'` …) and properties given as a
//! curve of a parameter ([`curve`], `MATE … 'YOUN' EVOLUTIO`), and the
//! cubic spline of sampled values ([`spline`], IPOL 'SPLI') and functions
//! of several variables known at scattered points ([`scatter`], IPOL on a
//! NUAGE). Numbers
//! only: never the language side.
pub mod curve;
pub mod scatter;
pub mod spline;
pub mod water;
