//! OPTI settings, per-operator timing (TEMP) and the state the export
//! operators keep between calls.

use std::collections::BTreeMap;
use std::time::Duration;

/// The options set by OPTI and read by VALE.
#[derive(Debug, Clone)]
pub struct Options {
    /// Space dimension (0 until `OPTI DIME`).
    pub dime: usize,
    /// Element type produced by the meshing operators.
    pub elem: String,
    /// Analysis mode: PLAN CONT, PLAN DEFO, AXIS, TRID, ...
    pub mode: String,
    /// -1..2; 1 echoes each instruction.
    pub echo: i64,
    /// Default density of new points.
    pub dens: f64,
    /// NORMAL, FATAL, CONTROLE, IGNORE.
    pub erre: String,
    /// Linear solver: DIRECTE or ITERATIVE.
    pub reso: String,
    /// The other options given to OPTI, as read (ops/opti.rs), for VALE
    /// and for the operators that use them (SORT, FTRA, TRAC, EPTR); ECHO
    /// too, to know that it was given (PASAPAS's step lines).
    pub kept: BTreeMap<&'static str, crate::value::Value>,
}

impl Options {
    /// A word or file name given to OPTI `key`, if any.
    pub fn text(&self, key: &str) -> Option<&str> {
        match self.kept.get(key)? {
            crate::value::Value::Mot(s) => Some(s),
            _ => None,
        }
    }

    /// An ENTIER given to OPTI `key`, if any.
    pub fn int(&self, key: &str) -> Option<i64> {
        match self.kept.get(key)? {
            crate::value::Value::Int(n) => Some(*n),
            _ => None,
        }
    }
}

impl Default for Options {
    fn default() -> Self {
        Options {
            dime: 0,
            elem: "SEG2".into(),
            mode: "PLAN CONT".into(),
            echo: 0,
            dens: 0.0,
            erre: "NORMAL".into(),
            reso: "DIRECTE".into(),
            kept: BTreeMap::new(),
        }
    }
}

/// What the export operators remember between calls.
#[derive(Debug, Clone, Default)]
pub struct Exports {
    /// The `.pvd` collection being written by `SORT 'VTK' … 'TEMPS' t`:
    /// its base name and its steps so far (time, `.vtu` file). A new base
    /// name starts a new collection.
    pub pvd: Option<(String, Vec<(f64, String)>)>,
    /// Pictures drawn without an OPTI SORT name (`gibi_trac_N`).
    pub pictures: u64,
    /// The AVS file SORT 'AVS' wrote in this run: 'SUIT' appends to it
    /// (and only to it, never to a file left by an earlier run).
    pub avs_written: Option<String>,
    /// The text file SORT 'CHAI' writes to in this run: later lines are
    /// appended while OPTI SORT names the same file.
    pub text_written: Option<String>,
    /// The AVS file LIRE 'AVS' reads (OPTI LECT) and where its next
    /// structure starts (byte offset, line number): each LIRE reads one.
    pub avs_read: Option<(String, usize, usize)>,
    /// The file ACQU reads (OPTI ACQU) and the line its next read starts at.
    pub acqu_read: Option<(String, usize)>,
}

/// Cumulative time and call count per operator, for TEMP.
#[derive(Debug, Clone)]
pub struct Timers {
    /// Named phases reported by long operators (factorisation, status loop).
    pub phases: BTreeMap<String, (u64, Duration)>,
    /// The interpreter's start, the origin of TEMP's clock.
    pub origin: std::time::Instant,
    /// The last TEMP call, for the time elapsed since.
    pub last: std::time::Instant,
    /// TEMP 'ZERO' was the last TEMP call: its own call, recorded after
    /// the reset, is not one TEMP counts.
    pub zeroed: bool,
}

impl Default for Timers {
    fn default() -> Self {
        let now = std::time::Instant::now();
        Timers { phases: BTreeMap::new(), origin: now, last: now, zeroed: false }
    }
}

impl Timers {
    pub fn phase(&mut self, name: &str, seconds: f64) {
        let e = self.phases.entry(name.to_string()).or_default();
        e.0 += 1;
        e.1 += Duration::from_secs_f64(seconds.max(0.0));
    }
}
