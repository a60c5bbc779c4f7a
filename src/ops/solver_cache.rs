//! What a RIGIDITE object remembers between RESO calls: the symbolic and
//! numeric factorisations and the final status of its unilateral
//! conditions (warm start).

#[derive(Debug, Default)]
pub struct SolverCache {
    /// Final status of the unilateral conditions after the last RESO.
    pub status: Option<Vec<bool>>,
}
