//! Gibiane objects. `Value` is a closed enum of the Cast3M types plus a
//! `Host` slot for objects an embedding application defines. Values are
//! cheap to clone (big objects sit behind `Rc`); assignment never mutates an
//! object, except TABLE which Gibiane mutates in place (`T . k = v`).

pub mod arith;
pub mod by_components;
pub mod chargement;
mod curve_primitive;
mod describe;
mod display;
pub mod field;
pub mod finite;
mod mchaml_broadcast;
mod mchaml_resultant;
pub(crate) mod mchaml_scale;
pub mod model;
mod model_union;
pub mod nuage;
pub mod objet;
pub mod projection;
pub mod rigidity;
pub mod signal;
pub mod table;

pub use chargement::Chargement;
pub use display::{fmt_float, list_value, list_value_short};
pub use field::{Chpoint, Nature};
pub use model::{Evolution, Mchaml, Model};
pub use nuage::Nuage;
pub use rigidity::Rigidite;
pub use table::{Key, Table};

use crate::fem::mesh::Mesh;
use crate::syntax::ast::ProcDef;
use std::any::Any;
use std::cell::RefCell;
use std::fmt::Debug;
use std::rc::Rc;

/// An object defined by an embedding application (see `Interpreter::register`).
pub trait HostObject: Debug + Any {
    /// The 8-character Gibiane type name reported by `TYPE`.
    fn type_name(&self) -> &str;
    /// Text printed by `LIST`.
    fn describe(&self) -> String {
        format!("{:?}", self)
    }
    fn as_any(&self) -> &dyn Any;
}

#[derive(Debug, Clone)]
pub enum Value {
    Int(i64),
    Float(f64),
    Mot(Rc<str>),
    Bool(bool),
    /// A node of the interpreter's node table.
    Point(usize),
    ListReel(Rc<Vec<f64>>),
    ListEnti(Rc<Vec<i64>>),
    ListMots(Rc<Vec<String>>),
    Table(Rc<RefCell<Table>>),
    Proc(Rc<ProcDef>),
    /// A REPETER block (the value of its name while it runs).
    Bloc(Rc<str>),
    Mesh(Rc<Mesh>),
    Chpo(Rc<Chpoint>),
    /// LISTCHPO: an ordered list of fields (several load cases, solved
    /// together by RESO).
    ListChpo(Rc<Vec<Rc<Chpoint>>>),
    Rigi(Rc<Rigidite>),
    Model(Rc<Model>),
    Mchaml(Rc<Mchaml>),
    Evol(Rc<Evolution>),
    /// CHARGEMENT: loads in space and time (CHAR).
    Charge(Rc<Chargement>),
    /// NUAGE: tuples of named components (NUAG).
    Nuage(Rc<Nuage>),
    Host(Rc<dyn HostObject>),
}

/// The Gibiane type names, for signatures and errors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ty {
    Entier,
    Flottant,
    Mot,
    Logique,
    Point,
    ListReel,
    ListEnti,
    ListMots,
    Table,
    Procedur,
    Bloc,
    Maillage,
    Chpoint,
    ListChpo,
    Rigidite,
    Mmodel,
    Mchaml,
    Evolutio,
    Chargeme,
    Nuage,
    Host,
}

impl Ty {
    pub fn name(self) -> &'static str {
        match self {
            Ty::Entier => "ENTIER",
            Ty::Flottant => "FLOTTANT",
            Ty::Mot => "MOT",
            Ty::Logique => "LOGIQUE",
            Ty::Point => "POINT",
            Ty::ListReel => "LISTREEL",
            Ty::ListEnti => "LISTENTI",
            Ty::ListMots => "LISTMOTS",
            Ty::Table => "TABLE",
            Ty::Procedur => "PROCEDUR",
            Ty::Bloc => "BLOC",
            Ty::Maillage => "MAILLAGE",
            Ty::Chpoint => "CHPOINT",
            Ty::ListChpo => "LISTCHPO",
            Ty::Rigidite => "RIGIDITE",
            Ty::Mmodel => "MMODEL",
            Ty::Mchaml => "MCHAML",
            Ty::Evolutio => "EVOLUTIO",
            Ty::Chargeme => "CHARGEME",
            Ty::Nuage => "NUAGE",
            Ty::Host => "HOST",
        }
    }

    /// Parse a type name as written in `DEBPROC x*TYPE` (8 letters count).
    pub fn from_name(s: &str) -> Option<Ty> {
        let s: String = s.trim().to_uppercase().chars().take(8).collect();
        [
            Ty::Entier,
            Ty::Flottant,
            Ty::Mot,
            Ty::Logique,
            Ty::Point,
            Ty::ListReel,
            Ty::ListEnti,
            Ty::ListMots,
            Ty::Table,
            Ty::Procedur,
            Ty::Bloc,
            Ty::Maillage,
            Ty::Chpoint,
            Ty::ListChpo,
            Ty::Rigidite,
            Ty::Mmodel,
            Ty::Mchaml,
            Ty::Evolutio,
            Ty::Chargeme,
            Ty::Nuage,
        ]
        .into_iter()
        .find(|t| t.name() == s)
    }
}

impl Value {
    pub fn ty(&self) -> Ty {
        match self {
            Value::Int(_) => Ty::Entier,
            Value::Float(_) => Ty::Flottant,
            Value::Mot(_) => Ty::Mot,
            Value::Bool(_) => Ty::Logique,
            Value::Point(_) => Ty::Point,
            Value::ListReel(_) => Ty::ListReel,
            Value::ListEnti(_) => Ty::ListEnti,
            Value::ListMots(_) => Ty::ListMots,
            Value::Table(_) => Ty::Table,
            Value::Proc(_) => Ty::Procedur,
            Value::Bloc(_) => Ty::Bloc,
            Value::Mesh(_) => Ty::Maillage,
            Value::Chpo(_) => Ty::Chpoint,
            Value::ListChpo(_) => Ty::ListChpo,
            Value::Rigi(_) => Ty::Rigidite,
            Value::Model(_) => Ty::Mmodel,
            Value::Mchaml(_) => Ty::Mchaml,
            Value::Evol(_) => Ty::Evolutio,
            Value::Charge(_) => Ty::Chargeme,
            Value::Nuage(_) => Ty::Nuage,
            Value::Host(_) => Ty::Host,
        }
    }

    /// The type name `TYPE` reports (host objects name their own).
    pub fn type_name(&self) -> String {
        match self {
            Value::Host(h) => h.type_name().to_string(),
            v => v.ty().name().to_string(),
        }
    }

    pub fn mot(s: impl AsRef<str>) -> Value {
        Value::Mot(Rc::from(s.as_ref()))
    }

    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Int(i) => Some(*i as f64),
            Value::Float(f) => Some(*f),
            _ => None,
        }
    }

    pub fn as_mot(&self) -> Option<&str> {
        match self {
            Value::Mot(s) => Some(s),
            _ => None,
        }
    }

    pub fn is_number(&self) -> bool {
        matches!(self, Value::Int(_) | Value::Float(_))
    }
}

impl From<f64> for Value {
    fn from(x: f64) -> Self {
        Value::Float(x)
    }
}
impl From<i64> for Value {
    fn from(x: i64) -> Self {
        Value::Int(x)
    }
}
impl From<bool> for Value {
    fn from(x: bool) -> Self {
        Value::Bool(x)
    }
}
impl From<&str> for Value {
    fn from(x: &str) -> Self {
        Value::mot(x)
    }
}
