//! The interactive prompt. An entry continues over lines until the parser
//! says it is complete (an instruction ended by ';', every SI/REPETER/
//! DEBPROC closed); an error is printed and every object survives.

use gibi::syntax::{check_complete, Completeness};
use gibi::{Interpreter, Outcome, Registry};
use rustyline::completion::{Completer, Pair};
use rustyline::error::ReadlineError;
use rustyline::validate::{ValidationContext, ValidationResult, Validator};
use rustyline::{Context, Editor, Helper, Highlighter, Hinter};
use std::cell::RefCell;
use std::path::PathBuf;
use std::process::ExitCode;
use std::rc::Rc;

const KEYWORDS: &[&str] = &[
    "SI",
    "SINON",
    "FINSI",
    "REPETER",
    "FIN",
    "QUITTER",
    "ITERER",
    "DEBPROC",
    "FINPROC",
    "ARGU",
    "RESPRO",
    "VRAI",
    "FAUX",
    "MINI",
    "MAXI",
    "DIME",
    "ELEM",
    "MODE",
    "PLAN",
    "CONT",
    "DEFO",
    "AXIS",
    "TRID",
    "MECANIQUE",
    "ELASTIQUE",
    "ISOTROPE",
    "BARR",
    "POUT",
    "TIMO",
    "COQ3",
    "DKT",
    "COQ4",
    "EPAI",
    "YOUN",
    "NU",
    "SECT",
    "INRY",
    "INRZ",
    "TORS",
    "DEPL",
    "ROTA",
    "UX",
    "UY",
    "UZ",
    "RX",
    "RY",
    "RZ",
    "FX",
    "FY",
    "FZ",
    "PAS",
    "NPAS",
];

#[derive(Helper, Hinter, Highlighter)]
struct GibiHelper {
    names: Rc<RefCell<Vec<String>>>,
}

impl Validator for GibiHelper {
    fn validate(&self, ctx: &mut ValidationContext) -> rustyline::Result<ValidationResult> {
        let input = ctx.input();
        // A blank line after an unfinished entry is passed along so the
        // user can see what the parser objects to.
        if input.ends_with("\n\n") {
            return Ok(ValidationResult::Valid(None));
        }
        Ok(match check_complete(input) {
            Completeness::Incomplete if !input.trim().starts_with(':') => ValidationResult::Incomplete,
            _ => ValidationResult::Valid(None),
        })
    }
}

impl Completer for GibiHelper {
    type Candidate = Pair;
    fn complete(&self, line: &str, pos: usize, _: &Context<'_>) -> rustyline::Result<(usize, Vec<Pair>)> {
        let start = line[..pos].rfind(|c: char| c.is_whitespace() || "=+-*/%();.'&<>".contains(c)).map_or(0, |i| i + 1);
        let word = line[start..pos].to_uppercase();
        if word.is_empty() {
            return Ok((pos, vec![]));
        }
        let lower = line[start..pos].chars().all(|c| !c.is_uppercase());
        let mut out: Vec<Pair> = self
            .names
            .borrow()
            .iter()
            .filter(|n| n.starts_with(&word))
            .map(|n| {
                let s = if lower { n.to_lowercase() } else { n.clone() };
                Pair { display: n.clone(), replacement: s }
            })
            .collect();
        out.dedup_by(|a, b| a.display == b.display);
        Ok((start, out))
    }
}

fn history_path() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("GIBI_HISTORY") {
        return Some(PathBuf::from(p));
    }
    dirs::data_dir().map(|d| d.join("gibi").join("history"))
}

fn refresh_names(gibi: &Interpreter, names: &RefCell<Vec<String>>) {
    let mut v: Vec<String> = gibi.registry().all().iter().map(|o| o.name.to_string()).collect();
    v.extend(gibi.objects().into_iter().map(|(n, _)| n));
    v.extend(KEYWORDS.iter().map(|s| s.to_string()));
    v.sort();
    v.dedup();
    *names.borrow_mut() = v;
}

/// `:help` text: the catalogue, or one operator's signature and summary.
pub fn help(registry: &Registry, what: Option<&str>) -> String {
    match what {
        None => {
            let mut s = String::from(
                "Type Gibiane instructions ended by ';'. Commands: :help [OPERATOR], :list, :quit.\nOperators:",
            );
            for (i, op) in registry.all().iter().enumerate() {
                s.push_str(if i % 10 == 0 { "\n  " } else { " " });
                s.push_str(op.name);
            }
            s
        }
        // Operators match on their first 4 letters in any case, as in decks.
        Some(w) => match registry.find(&w.to_uppercase()) {
            Some(op) => {
                let mut s = format!("{}\n  usage: {}", op.doc, op.signature);
                if !op.example.is_empty() {
                    s.push_str(&format!("\n  example: {}", op.example));
                }
                s
            }
            None => format!("no operator named {}", w.to_uppercase()),
        },
    }
}

/// The catalogue as JSON (for editors): name, signature, description, example.
pub fn catalogue_json(registry: &Registry) -> String {
    fn esc(s: &str) -> String {
        s.chars()
            .flat_map(|c| match c {
                '"' => vec!['\\', '"'],
                '\\' => vec!['\\', '\\'],
                '\n' => vec!['\\', 'n'],
                c => vec![c],
            })
            .collect()
    }
    use gibi::eval::catalogue::{self, Status};
    let mut items: Vec<String> = registry
        .all()
        .iter()
        .map(|o| {
            format!(
                "  {{\"name\": \"{}\", \"status\": \"implemented\", \"signature\": \"{}\", \"doc\": \"{}\", \"example\": \"{}\"}}",
                esc(o.name),
                esc(o.signature),
                esc(o.doc),
                esc(o.example)
            )
        })
        .collect();
    // Then every other name of Cast3M's catalogue, with what gibi does
    // with it: the language's directives, refused operators, procedures.
    for e in catalogue::entries() {
        let status = catalogue::status(e, registry);
        if status == Status::Implemented && registry.find(e.key).is_some() {
            continue;
        }
        items.push(format!(
            "  {{\"name\": \"{}\", \"status\": \"{}\", \"kind\": \"{}\", \"cast3m\": \"{}\", \"section\": \"{}\"}}",
            esc(e.key),
            status.as_str(),
            if e.kind == catalogue::Kind::Procedure { "procedure" } else { "operator" },
            esc(e.name),
            esc(e.section)
        ));
    }
    format!("[\n{}\n]", items.join(",\n"))
}

pub fn run(mut gibi: Interpreter, quiet: bool) -> ExitCode {
    let names = Rc::new(RefCell::new(Vec::new()));
    refresh_names(&gibi, &names);
    let mut rl: Editor<GibiHelper, rustyline::history::DefaultHistory> = match Editor::new() {
        Ok(r) => r,
        Err(e) => {
            eprintln!("gibi: cannot start the line editor: {}", e);
            return ExitCode::from(70);
        }
    };
    rl.set_helper(Some(GibiHelper { names: names.clone() }));
    // After the editor: rustyline takes SIGINT for itself when it starts,
    // and a Ctrl-C during a run must reach the interpreter. While a line
    // is read the terminal is raw, and Ctrl-C is a key, not a signal.
    crate::catch_ctrl_c(&gibi);
    let hist = history_path();
    if let Some(h) = &hist {
        let _ = rl.load_history(h);
    }
    if !quiet {
        println!("gibi {} — Gibiane interpreter. :help for help, Ctrl-D to leave.", env!("CARGO_PKG_VERSION"));
    }
    let mut n = 0;
    loop {
        match rl.readline("gibi> ") {
            Ok(line) => {
                if line.trim().is_empty() {
                    continue;
                }
                let _ = rl.add_history_entry(line.as_str());
                // Saved entry by entry: a killed session loses nothing.
                save_history(&mut rl, hist.as_deref());
                let t = line.trim();
                if let Some(cmd) = t.strip_prefix(':') {
                    let mut it = cmd.split_whitespace();
                    match it.next().unwrap_or("").to_lowercase().as_str() {
                        "help" | "h" => println!("{}", help(gibi.registry(), it.next())),
                        "list" | "l" => {
                            for (name, v) in gibi.objects() {
                                println!("  {:<24} {}", name, v.type_name());
                            }
                        }
                        "quit" | "q" => break,
                        other => println!("unknown command :{} (try :help)", other),
                    }
                    continue;
                }
                n += 1;
                // A Ctrl-C typed while nothing ran must not stop this entry.
                gibi.interrupt_handle().clear();
                match gibi.run_str(&format!("<repl#{}>", n), &line) {
                    Ok(Outcome::Finished) => break,
                    Ok(Outcome::EndOfInput) => {}
                    Err(e) => eprint!("{}", e.render()),
                }
                refresh_names(&gibi, &names);
            }
            Err(ReadlineError::Interrupted) => continue,
            Err(ReadlineError::Eof) => break,
            Err(e) => {
                eprintln!("gibi: {}", e);
                break;
            }
        }
    }
    save_history(&mut rl, hist.as_deref());
    ExitCode::SUCCESS
}

/// Append the entries not yet in the history file (rustyline locks the
/// file, so two sessions do not mix their lines).
fn save_history(rl: &mut Editor<GibiHelper, rustyline::history::DefaultHistory>, path: Option<&std::path::Path>) {
    let Some(h) = path else { return };
    if let Some(d) = h.parent() {
        let _ = std::fs::create_dir_all(d);
    }
    let _ = rl.append_history(h);
}
