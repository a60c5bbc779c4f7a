//! Material properties that depend on a state: water and steam
//! ([`water`], the laws of `VARI 'HLS'` …) and properties given as a
//! curve of a parameter ([`curve`], `MATE … 'YOUN' EVOLUTIO`), and the
//! cubic spline of sampled values ([`spline`], IPOL 'SPLI'). Numbers
//! only: never the language side.
pub mod curve;
pub mod spline;
pub mod water;
