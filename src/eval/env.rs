//! The object store: one frame per procedure call. A procedure body reads
//! every object that existed before the call but assigns only into its own
//! frame (language.md §6.3), so lookups walk down the frames and
//! assignments stay on top.

use crate::value::Value;
use rustc_hash::FxHashMap as HashMap;

use super::tokens::GroupState;

#[derive(Debug, Default)]
pub struct Frame {
    pub vars: HashMap<String, Value>,
    /// Procedure name, None for the global frame.
    pub proc_name: Option<String>,
    /// The caller's unread arguments, for ARGU.
    pub pending: GroupState,
    /// Results appended by RESPRO.
    pub results: Vec<Value>,
    /// Active loops of this frame: (name, pass number).
    pub loops: Vec<(String, i64)>,
    /// Optional parameters that were not given: they do not exist in the
    /// procedure even if the caller has objects of those names (argu.notice:
    /// `ARGU L/ENTIER ; SI (EXISTE L)`).
    pub absent: Vec<String>,
    /// Loops of this frame that have ended, with their last pass number:
    /// in Cast3M `&name` is an ordinary ENTIER that outlives its loop
    /// (`NITER = &BOU1 ;` after the loop or after QUITTER).
    pub ended: HashMap<String, i64>,
}

#[derive(Debug)]
pub struct Store {
    pub frames: Vec<Frame>,
}

impl Default for Store {
    fn default() -> Self {
        Store { frames: vec![Frame::default()] }
    }
}

/// Names are significant to 24 characters (LONOM in Cast3M). A slice, so
/// lookups allocate nothing.
fn truncate(name: &str) -> &str {
    match name.char_indices().nth(24) {
        Some((i, _)) => &name[..i],
        None => name,
    }
}

impl Store {
    pub fn get(&self, name: &str) -> Option<&Value> {
        let name = truncate(name);
        // `!name` is never filled in from the caller (debp.notice).
        if name.starts_with('!') {
            return self.top().vars.get(name);
        }
        for f in self.frames.iter().rev() {
            if let Some(v) = f.vars.get(name) {
                return Some(v);
            }
            if !f.absent.is_empty() && f.absent.iter().any(|a| a == name) {
                return None;
            }
        }
        None
    }

    /// Make a name not exist in the current frame (an optional parameter
    /// that was not given).
    pub fn hide(&mut self, name: &str) {
        let name = truncate(name);
        let top = self.top_mut();
        top.vars.remove(name);
        if !top.absent.iter().any(|a| a == name) {
            top.absent.push(name.to_string());
        }
    }

    pub fn set(&mut self, name: &str, v: Value) {
        let name = truncate(name);
        let vars = &mut self.top_mut().vars;
        // Reassigning an existing name reuses its key (no allocation).
        match vars.get_mut(name) {
            Some(slot) => *slot = v,
            None => {
                vars.insert(name.to_string(), v);
            }
        }
    }

    /// Forget a name in the current frame (OUBL).
    pub fn remove(&mut self, name: &str) -> Option<Value> {
        self.top_mut().vars.remove(truncate(name))
    }

    pub fn top(&self) -> &Frame {
        self.frames.last().expect("the global frame always exists")
    }

    pub fn top_mut(&mut self) -> &mut Frame {
        self.frames.last_mut().expect("the global frame always exists")
    }

    /// `&name`: the innermost running loop of that name, else the last
    /// pass of an ended one, looked up from the current frame down to the
    /// global one (a procedure body reads its caller's objects, loop
    /// counters included).
    pub fn counter(&self, name: &str) -> Option<i64> {
        let name = truncate(name);
        self.frames.iter().rev().find_map(|f| {
            f.loops.iter().rev().find(|(n, _)| n == name).map(|(_, i)| *i).or_else(|| f.ended.get(name).copied())
        })
    }

    /// Names visible from the current frame, sorted, with their values.
    pub fn visible(&self) -> Vec<(String, Value)> {
        let mut m: std::collections::BTreeMap<String, Value> = Default::default();
        for f in &self.frames {
            for (k, v) in &f.vars {
                m.insert(k.clone(), v.clone());
            }
        }
        m.into_iter().collect()
    }
}
