//! The syntax tree: plain data with byte spans, no pest types.

use crate::source::Span;

/// One token of an instruction. Words are already upper-cased (outside
/// quotes, as Cast3M does); quoted text keeps its case.
#[derive(Debug, Clone, PartialEq)]
pub enum ItemKind {
    Int(i64),
    Float(f64),
    /// Quoted text (`'…'`, with `''` already turned into `'`).
    Str(String),
    /// An unquoted word: an object name, an operator, or else a MOT.
    Word(String),
    /// `&name`: the pass counter of loop `name`.
    Counter(String),
    /// `+ - * / ** < > <EG >EG %`.
    Sym(&'static str),
    /// `.`: table indexing.
    Dot,
    /// A parenthesised group, evaluated innermost first.
    Group(Vec<Item>),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Item {
    pub kind: ItemKind,
    pub span: Span,
}

/// A name receiving a result: `x`, `K*ENTIER`, `T . 'K' . 2`.
#[derive(Debug, Clone, PartialEq)]
pub struct Target {
    /// Empty when the table is given by a group (`base`).
    pub name: String,
    /// `(T . 1) . 'K' = …`: the group that gives the table whose keys follow.
    pub base: Option<Vec<Item>>,
    pub typed: Option<String>,
    pub keys: Vec<Item>,
    pub span: Span,
}

/// `[targets =] items ;`
#[derive(Debug, Clone, PartialEq)]
pub struct Instr {
    pub targets: Vec<Target>,
    pub items: Vec<Item>,
    pub span: Span,
}

/// A procedure parameter: `x*FLOTTANT` (required) or `k/ENTIER` (optional).
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    pub name: String,
    pub ty: Option<String>,
    pub optional: bool,
    pub span: Span,
}

/// Statements after structure has been rebuilt.
#[derive(Debug, Clone, PartialEq)]
pub enum Stmt {
    Instr(Instr),
    /// `SI c1 ; … (SINON c2 ; …)* (SINON ; …) FINSI ;`: the first branch
    /// whose condition is VRAI runs, else `otherwise`.
    If {
        branches: Vec<Branch>,
        otherwise: Option<Vec<Stmt>>,
        span: Span,
    },
    Loop {
        name: String,
        count: Option<Instr>,
        body: Vec<Stmt>,
        span: Span,
    },
    Proc(std::rc::Rc<ProcDef>),
    Quit {
        name: String,
        span: Span,
    },
    Iter {
        name: String,
        span: Span,
    },
    /// `ARGU params ;` inside a procedure.
    Argu {
        params: Vec<Param>,
        span: Span,
    },
    /// `RESPRO items ;` inside a procedure.
    Respro(Instr),
    /// `FIN ;`: ends the whole run.
    End {
        span: Span,
    },
    /// An instruction inside a block that is not Gibiane: its syntax error
    /// is raised when the instruction runs, as Cast3M reads an instruction
    /// only when it gets there (a procedure's unused branch may be broken).
    Broken {
        message: String,
        span: Span,
    },
}

/// One conditional branch: `SI cond ;` or the else-if `SINON cond ;`.
#[derive(Debug, Clone, PartialEq)]
pub struct Branch {
    pub cond: Instr,
    pub body: Vec<Stmt>,
}

/// `DEBPROC name params ; body FINPROC results ;`
#[derive(Debug, Clone, PartialEq)]
pub struct ProcDef {
    pub name: String,
    pub params: Vec<Param>,
    pub body: Vec<Stmt>,
    pub results: Instr,
    pub span: Span,
}

/// A parsed source.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Program {
    pub stmts: Vec<Stmt>,
}
