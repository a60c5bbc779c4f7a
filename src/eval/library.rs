//! The procedure library: Cast3M procedures loaded from files on first use.
//!
//! Cast3M keeps its procedures (MAILSTRU, PASAPAS, …, written in Gibiane)
//! in a library that it reads when a deck names one. gibi ships none of
//! them; a host or the command line (`GIBI_PROCEDURES`, `--procedures`)
//! names where they are:
//!
//! - a file of procedures in Cast3M's `$$$$ NAME` format (UTILPROC's): each
//!   procedure's text follows a `$$$$ NAME` line, up to the next `$$$$`
//!   line;
//! - a folder of `*.procedur` files (Cast3M's `procedur/`), one procedure
//!   per file, named after the file (each file may itself be in the
//!   `$$$$` format).
//!
//! The names are indexed once, at the first word that could name a
//! procedure; a procedure's text is parsed when a deck first names it, and
//! only its own file (or its own part of a `$$$$` file) is read. The first
//! path that has a name wins.

use crate::error::{Error, Result};
use crate::source::{decode, Source};
use crate::syntax::ast::{ProcDef, Stmt};
use crate::syntax::Reader;
use crate::value::Value;
use rustc_hash::FxHashMap as HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

/// Where a procedure's text is.
#[derive(Debug, Clone)]
struct Place {
    /// Index into `Library::files`.
    file: usize,
    /// Byte range of its text in a `$$$$` file, after the `$$$$ NAME`
    /// line; `None` for a whole `.procedur` file.
    range: Option<(usize, usize)>,
}

#[derive(Debug, Default)]
pub struct Library {
    paths: Vec<PathBuf>,
    /// Name -> place, built at the first lookup.
    index: Option<HashMap<String, Place>>,
    /// The files of the index, and their text once read.
    files: Vec<(PathBuf, Option<Rc<Source>>)>,
    /// Procedures parsed so far, by name, with the text that defines them.
    loaded: HashMap<String, (Rc<ProcDef>, Rc<Source>)>,
}

impl Library {
    pub fn new(paths: Vec<PathBuf>) -> Self {
        Library { paths, ..Library::default() }
    }

    /// Whether any path was given.
    pub fn is_configured(&self) -> bool {
        !self.paths.is_empty()
    }

    pub fn paths(&self) -> &[PathBuf] {
        &self.paths
    }

    /// Whether the library holds a procedure of that name (indexing the
    /// paths on the first call).
    pub fn contains(&mut self, name: &str) -> Result<bool> {
        if self.paths.is_empty() {
            return Ok(false);
        }
        Ok(self.index()?.contains_key(name))
    }

    /// The procedure of that name with the text it comes from, parsed on
    /// first use. `None` when the library has no such name.
    pub fn get(&mut self, name: &str) -> Result<Option<(Rc<ProcDef>, Rc<Source>)>> {
        if let Some(p) = self.loaded.get(name) {
            return Ok(Some(p.clone()));
        }
        let Some(place) = self.index()?.get(name).cloned() else { return Ok(None) };
        let source = self.text(place.file)?;
        let ranges = match place.range {
            Some(r) => vec![(name.to_string(), r)],
            None => chunks(&source.text).unwrap_or_else(|| vec![(name.to_string(), (0, source.text.len()))]),
        };
        for (chunk_name, (start, end)) in ranges {
            let procs = parse_chunk(&source, start, end)?;
            if procs.is_empty() && chunk_name == name {
                return Err(Error::runtime(format!(
                    "the procedure library's {} holds no DEBPROC {} (file {})",
                    name, name, source.name
                )));
            }
            for p in procs {
                self.loaded.entry(p.name.clone()).or_insert_with(|| (p.clone(), source.clone()));
            }
        }
        match self.loaded.get(name) {
            Some(p) => Ok(Some(p.clone())),
            None => Err(Error::runtime(format!(
                "the procedure library's file {} does not define {} (its DEBPROC names another procedure)",
                source.name, name
            ))),
        }
    }

    /// Whether a procedure definition comes from the library.
    pub fn owns(&self, p: &Rc<ProcDef>) -> bool {
        self.loaded.get(&p.name).is_some_and(|(q, _)| Rc::ptr_eq(p, q))
    }

    fn index(&mut self) -> Result<&HashMap<String, Place>> {
        if self.index.is_none() {
            let mut index = HashMap::default();
            for path in self.paths.clone() {
                self.index_path(&path, &mut index)?;
            }
            self.index = Some(index);
        }
        Ok(self.index.as_ref().expect("built above"))
    }

    fn index_path(&mut self, path: &Path, index: &mut HashMap<String, Place>) -> Result<()> {
        let unreadable =
            |e: std::io::Error| Error::io(format!("cannot read the procedure library {}: {}", path.display(), e));
        if path.is_dir() {
            let mut names: Vec<(String, PathBuf)> = std::fs::read_dir(path)
                .map_err(unreadable)?
                .flatten()
                .map(|f| f.path())
                .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("procedur")))
                .filter_map(|p| Some((p.file_stem()?.to_string_lossy().to_uppercase(), p)))
                .collect();
            // The same order on every system, so the first of two files
            // naming one procedure is always the same.
            names.sort();
            for (name, p) in names {
                let file = self.files.len();
                self.files.push((p, None));
                index.entry(name).or_insert(Place { file, range: None });
            }
        } else {
            let bytes = std::fs::read(path).map_err(unreadable)?;
            let source = Source::new(path.display().to_string(), decode(&bytes));
            let file = self.files.len();
            for (name, range) in chunks(&source.text).unwrap_or_default() {
                index.entry(name).or_insert(Place { file, range: Some(range) });
            }
            self.files.push((path.to_path_buf(), Some(source)));
        }
        Ok(())
    }

    /// The text of a file of the index, read once.
    fn text(&mut self, file: usize) -> Result<Rc<Source>> {
        let (path, text) = &mut self.files[file];
        if let Some(s) = text {
            return Ok(s.clone());
        }
        let bytes = std::fs::read(&*path)
            .map_err(|e| Error::io(format!("cannot read the procedure file {}: {}", path.display(), e)))?;
        let s = Source::new(path.display().to_string(), decode(&bytes));
        *text = Some(s.clone());
        Ok(s)
    }
}

/// The procedures of a `$$$$` text: (name, byte range of its text), or
/// `None` when the text has no `$$$$ NAME` line (a plain Gibiane file).
fn chunks(text: &str) -> Option<Vec<(String, (usize, usize))>> {
    let mut out: Vec<(String, (usize, usize))> = Vec::new();
    let mut open: Option<(String, usize)> = None;
    let mut pos = 0;
    for line in text.split_inclusive('\n') {
        let next = pos + line.len();
        if let Some(rest) = line.strip_prefix("$$$$") {
            if let Some((name, start)) = open.take() {
                out.push((name, (start, pos)));
            }
            let name = rest.split_whitespace().next().unwrap_or("").to_uppercase();
            if !name.is_empty() {
                open = Some((name, next));
            }
        }
        pos = next;
    }
    if let Some((name, start)) = open {
        out.push((name, (start, text.len())));
    }
    (!out.is_empty()).then_some(out)
}

/// Parse one procedure's text: its DEBPROC definitions (anything else in
/// it is never run). Errors point into the file.
fn parse_chunk(source: &Rc<Source>, start: usize, end: usize) -> Result<Vec<Rc<ProcDef>>> {
    let mut procs = Vec::new();
    for stmt in Reader::range(&source.text, start, end) {
        match stmt {
            Ok(Stmt::Proc(p)) => procs.push(p),
            Ok(_) => {}
            Err(mut e) => {
                e.source = Some(source.clone());
                return Err(e);
            }
        }
    }
    Ok(procs)
}

impl super::Interp {
    /// The library procedure a word names, loaded on first use, unless
    /// gibi implements it natively: an operator of the registry wins over
    /// a library procedure of the same name (its own name, or a form of
    /// its Cast3M name: JEU, but not TRANSGEN for TRAN). Objects, and so
    /// procedures defined by the deck, were looked up before.
    pub(super) fn library_proc(&mut self, word: &str, span: crate::source::Span) -> Result<Option<Rc<ProcDef>>> {
        if !self.library.is_configured()
            || !self.library.contains(word).map_err(|e| e.with_span_if_missing(span, &self.source))?
        {
            return Ok(None);
        }
        let native = self.registry.find(word).is_some_and(|op| {
            op.name == word || super::catalogue::operator(op.name).is_some_and(|e| e.name.starts_with(word))
        });
        if native {
            return Ok(None);
        }
        let found = self.library.get(word).map_err(|e| e.with_span_if_missing(span, &self.source))?;
        Ok(found.map(|(p, source)| {
            self.proc_sources.insert(super::proc::proc_key(&p), source);
            p
        }))
    }
}

/// The procedures of a file read by LIRE 'PROC' (`name` as its user wrote
/// it): in the `$$$$ NAME` format, every procedure (or only `only`);
/// otherwise the DEBPROCs it holds, or, with none, the whole file as a
/// procedure without arguments named `only`. Errors point into the file.
pub(crate) fn file_procs(name: &str, bytes: &[u8], only: Option<&str>) -> Result<(Vec<Rc<ProcDef>>, Rc<Source>)> {
    let source = Source::new(name.to_string(), decode(bytes));
    let text = &source.text;
    let mut procs = Vec::new();
    match chunks(text) {
        Some(list) => {
            for (chunk, (start, end)) in list {
                if only.is_none_or(|o| o == chunk) {
                    procs.extend(parse_chunk(&source, start, end)?);
                }
            }
            if let Some(o) = only {
                procs.retain(|p| p.name == o);
                if procs.is_empty() {
                    return Err(Error::runtime(format!(
                        "'{}' has no procedure {} ($$$$ {} then DEBPROC {})",
                        name, o, o, o
                    )));
                }
            }
        }
        None => {
            procs = parse_chunk(&source, 0, text.len())?;
            if procs.is_empty() {
                let Some(o) = only else {
                    return Err(Error::runtime(format!(
                        "'{}' defines no procedure (DEBPROC): name the procedure its instructions make (LIRE 'PROC' file 'NAME')",
                        name
                    )));
                };
                let mut body = Vec::new();
                for stmt in Reader::range(text, 0, text.len()) {
                    body.push(stmt.map_err(|mut e| {
                        e.source = Some(source.clone());
                        e
                    })?);
                }
                let span = crate::source::Span::new(0, 0);
                let results = crate::syntax::ast::Instr { targets: vec![], items: vec![], span };
                procs.push(Rc::new(ProcDef { name: o.to_string(), params: vec![], body, results, span }));
            }
        }
    }
    Ok((procs, source))
}

impl super::Interp {
    /// Define the procedures LIRE 'PROC' read, as if the deck had them
    /// (errors inside them point into their file). Returns their names.
    pub(crate) fn define_file_procs(&mut self, procs: Vec<Rc<ProcDef>>, source: Rc<Source>) -> Vec<String> {
        let mut names = Vec::new();
        for p in procs {
            self.proc_sources.insert(super::proc::proc_key(&p), source.clone());
            let name = p.name.clone();
            self.store.set(&name, Value::Proc(p));
            names.push(name);
        }
        names
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dollar_lines_cut_the_text() {
        let t = "$$$$ AA\nx = 1 ;\n$$$$ bb extra\ny = 2 ;\n$$$$\n";
        let c = chunks(t).unwrap();
        assert_eq!(c.len(), 2);
        assert_eq!(c[0].0, "AA");
        assert_eq!(&t[c[0].1 .0..c[0].1 .1], "x = 1 ;\n");
        assert_eq!(c[1].0, "BB");
        assert_eq!(&t[c[1].1 .0..c[1].1 .1], "y = 2 ;\n");
        assert!(chunks("debproc f ; finproc ;\n").is_none());
    }
}
