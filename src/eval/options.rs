//! OPTI settings, the file-access policy and per-operator timing (TEMP).

use crate::error::{Error, Result};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
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
    /// Anything else given to OPTI, kept for VALE.
    pub other: BTreeMap<String, String>,
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
            other: BTreeMap::new(),
        }
    }
}

/// Where a script may read or write files. The library allows nothing by
/// default; the CLI allows its working directory.
#[derive(Debug, Clone)]
pub enum FilePolicy {
    Nothing,
    Under(PathBuf),
    Anywhere,
}

impl FilePolicy {
    /// Resolve a path a script asked for, or refuse it.
    pub fn check(&self, path: &str) -> Result<PathBuf> {
        let p = Path::new(path);
        match self {
            FilePolicy::Anywhere => Ok(p.to_path_buf()),
            FilePolicy::Nothing => {
                Err(Error::io(format!("file access to '{}' is not allowed by the host application", path)))
            }
            FilePolicy::Under(root) => {
                let full = if p.is_absolute() { p.to_path_buf() } else { root.join(p) };
                let ok =
                    !p.components().any(|c| matches!(c, std::path::Component::ParentDir)) && full.starts_with(root);
                if ok {
                    Ok(full)
                } else {
                    Err(Error::io(format!("'{}' is outside the directory this run may use ({})", path, root.display())))
                }
            }
        }
    }
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
}

impl Default for Timers {
    fn default() -> Self {
        let now = std::time::Instant::now();
        Timers { phases: BTreeMap::new(), origin: now, last: now }
    }
}

impl Timers {
    pub fn phase(&mut self, name: &str, seconds: f64) {
        let e = self.phases.entry(name.to_string()).or_default();
        e.0 += 1;
        e.1 += Duration::from_secs_f64(seconds.max(0.0));
    }
}
