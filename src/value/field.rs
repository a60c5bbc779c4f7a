//! CHPOINT: values of named components on nodes.
//!
//! Stored densely per node over the component list with a presence mask:
//! fields mix supports (displacements on physical nodes, `LX` only on
//! multiplier nodes), and a missing (node, component) must stay missing.

use std::collections::HashMap;

/// How fields combine under `ET` (et.notice): DIFFUS fields (displacements)
/// must agree where they overlap; DISCRET fields (forces) add up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Nature {
    Diffus,
    Discret,
    Indeter,
}

impl Nature {
    pub fn name(self) -> &'static str {
        match self {
            Nature::Diffus => "DIFFUS",
            Nature::Discret => "DISCRET",
            Nature::Indeter => "INDETERMINE",
        }
    }
}

#[derive(Debug, Clone)]
pub struct Chpoint {
    pub nature: Nature,
    pub comps: Vec<String>,
    pub nodes: Vec<usize>,
    values: Vec<f64>,
    present: Vec<bool>,
    index: HashMap<usize, usize>,
}

impl Chpoint {
    pub fn new(nature: Nature) -> Self {
        Chpoint { nature, comps: vec![], nodes: vec![], values: vec![], present: vec![], index: HashMap::new() }
    }

    /// Build from (node, component, value) entries; repeated entries add
    /// up for DISCRET fields and are overwritten otherwise.
    pub fn from_entries<'a>(nature: Nature, entries: impl IntoIterator<Item = (usize, &'a str, f64)>) -> Self {
        let mut c = Chpoint::new(nature);
        for (n, comp, v) in entries {
            c.add(n, comp, v, nature == Nature::Discret);
        }
        c
    }

    fn comp_index(&mut self, comp: &str) -> usize {
        if let Some(i) = self.comps.iter().position(|c| c == comp) {
            return i;
        }
        // Widen every row by one column.
        let nc = self.comps.len();
        let mut values = Vec::with_capacity(self.nodes.len() * (nc + 1));
        let mut present = Vec::with_capacity(self.nodes.len() * (nc + 1));
        for r in 0..self.nodes.len() {
            values.extend_from_slice(&self.values[r * nc..(r + 1) * nc]);
            values.push(0.0);
            present.extend_from_slice(&self.present[r * nc..(r + 1) * nc]);
            present.push(false);
        }
        self.values = values;
        self.present = present;
        self.comps.push(comp.to_string());
        nc
    }

    fn row(&mut self, node: usize) -> usize {
        if let Some(&r) = self.index.get(&node) {
            return r;
        }
        let r = self.nodes.len();
        self.nodes.push(node);
        self.index.insert(node, r);
        self.values.extend(std::iter::repeat_n(0.0, self.comps.len()));
        self.present.extend(std::iter::repeat_n(false, self.comps.len()));
        r
    }

    /// Set (or, with `sum`, add to) one value.
    pub fn add(&mut self, node: usize, comp: &str, v: f64, sum: bool) {
        let c = self.comp_index(comp);
        let r = self.row(node);
        let k = r * self.comps.len() + c;
        if sum && self.present[k] {
            self.values[k] += v;
        } else {
            self.values[k] = v;
        }
        self.present[k] = true;
    }

    pub fn get(&self, node: usize, comp: &str) -> Option<f64> {
        let c = self.comps.iter().position(|x| x == comp)?;
        let r = *self.index.get(&node)?;
        let k = r * self.comps.len() + c;
        self.present[k].then_some(self.values[k])
    }

    /// Every defined (node, component, value), node by node.
    pub fn entries(&self) -> impl Iterator<Item = (usize, &str, f64)> + '_ {
        let nc = self.comps.len();
        self.nodes.iter().enumerate().flat_map(move |(r, &n)| {
            (0..nc).filter_map(move |c| {
                let k = r * nc + c;
                self.present[k].then(|| (n, self.comps[c].as_str(), self.values[k]))
            })
        })
    }

    pub fn len(&self) -> usize {
        self.present.iter().filter(|p| **p).count()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// A field with the same support and a function applied to each value.
    pub fn map(&self, f: impl Fn(f64) -> f64) -> Chpoint {
        let mut c = self.clone();
        for (v, p) in c.values.iter_mut().zip(&c.present) {
            if *p {
                *v = f(*v);
            }
        }
        c
    }

    /// Components actually present somewhere.
    pub fn components(&self) -> Vec<String> {
        let nc = self.comps.len();
        (0..nc)
            .filter(|&c| (0..self.nodes.len()).any(|r| self.present[r * nc + c]))
            .map(|c| self.comps[c].clone())
            .collect()
    }
}

/// The algebra of node fields: what `+ - * /` and `ET` do with two of them.
impl Chpoint {
    /// `x ± y`: the union of the supports, a value missing on one side
    /// reading as 0. DISCRET only when both are.
    pub fn combine(&self, y: &Chpoint, f: impl Fn(f64, f64) -> f64) -> Chpoint {
        let nature =
            if self.nature == Nature::Discret && y.nature == Nature::Discret { Nature::Discret } else { self.nature };
        let mut out = Chpoint::new(nature);
        for (n, c, v) in self.entries() {
            out.add(n, c, f(v, y.get(n, c).unwrap_or(0.0)), false);
        }
        for (n, c, v) in y.entries() {
            if self.get(n, c).is_none() {
                out.add(n, c, f(0.0, v), false);
            }
        }
        out
    }

    /// Product (or quotient) of two fields: a single-component SCAL field
    /// multiplies every component of the other (aaa2.notice); otherwise
    /// component by component, where both are defined.
    pub fn product(&self, y: &Chpoint, div: bool) -> Chpoint {
        let op = |p: f64, q: f64| if div { p / q } else { p * q };
        let scal = |c: &Chpoint| c.components() == ["SCAL"];
        // An undetermined side makes the product undetermined, else a
        // DISCRET side makes it DISCRET (a force times a diffuse factor).
        let nature = match (self.nature, y.nature) {
            (Nature::Indeter, _) | (_, Nature::Indeter) => Nature::Indeter,
            (Nature::Discret, _) | (_, Nature::Discret) => Nature::Discret,
            _ => Nature::Diffus,
        };
        let mut out = Chpoint::new(nature);
        if scal(y) && !scal(self) {
            for (n, c, v) in self.entries() {
                if let Some(s) = y.get(n, "SCAL") {
                    out.add(n, c, op(v, s), false);
                }
            }
        } else if scal(self) && !scal(y) && !div {
            for (n, c, v) in y.entries() {
                if let Some(s) = self.get(n, "SCAL") {
                    out.add(n, c, s * v, false);
                }
            }
        } else {
            for (n, c, v) in self.entries() {
                if let Some(w) = y.get(n, c) {
                    out.add(n, c, op(v, w), false);
                }
            }
        }
        out
    }

    /// `ET` of two fields (et.notice): DISCRET fields add up; where a
    /// DIFFUS field is involved the values must agree where both are
    /// defined (`noer`: the first one wins).
    pub fn merge(&self, b: &Chpoint, noer: bool) -> Result<Chpoint, String> {
        let a = self;
        let diffus = a.nature != Nature::Discret || b.nature != Nature::Discret;
        let nature = if diffus && (a.nature == Nature::Diffus || b.nature == Nature::Diffus) {
            Nature::Diffus
        } else {
            a.nature
        };
        let mut out = a.clone();
        out.nature = nature;
        for (n, c, v) in b.entries() {
            match a.get(n, c) {
                Some(w) if diffus => {
                    if !noer && (v - w).abs() > 1e-10 * v.abs().max(w.abs()).max(1e-300) {
                        return Err(format!(
                            "DIFFUS fields disagree at node {} on {} ({} and {}); use 'NOER' to keep the first",
                            n + 1,
                            c,
                            w,
                            v
                        ));
                    }
                }
                _ => out.add(n, c, v, !diffus),
            }
        }
        Ok(out)
    }
}
