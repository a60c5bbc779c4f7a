//! NUAGE: a set of M tuples of N named components (NUAG), each
//! component a column of objects of one type. IPOL reads a NUAGE of
//! numbers as a function of several variables.

use super::Value;

#[derive(Debug, Clone, Default)]
pub struct Nuage {
    /// (component name, its M objects), in the order given.
    pub comps: Vec<(String, Vec<Value>)>,
}

impl Nuage {
    /// Number of tuples.
    pub fn len(&self) -> usize {
        self.comps.first().map_or(0, |c| c.1.len())
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn column(&self, name: &str) -> Option<&[Value]> {
        self.comps.iter().find(|c| c.0 == name).map(|c| c.1.as_slice())
    }

    /// A column of numbers, None when an item is not a number.
    pub fn numbers(&self, name: &str) -> Option<Vec<f64>> {
        self.column(name)?.iter().map(Value::as_f64).collect()
    }
}
