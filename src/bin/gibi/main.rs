//! The `gibi` command: run decks, a snippet, stdin, or open the REPL.
//! Exit codes follow sysexits: 65 for a syntax error, 70 for a runtime
//! error or an aborting ERRE, 66 for an unreadable file.

mod repl;

use clap::Parser;
use gibi::{ErrorKind, FilePolicy, Interpreter, Outcome};
use std::io::{IsTerminal, Read};
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "gibi", version, about = "An interpreter for Gibiane, the command language of Cast3M")]
struct Cli {
    /// Deck files to run in order ('-' reads a deck from standard input).
    files: Vec<String>,
    /// Run these instructions (before the files).
    #[arg(short = 'e', long = "eval", value_name = "INSTRUCTIONS")]
    eval: Vec<String>,
    /// Only parse: report syntax errors, run nothing.
    #[arg(long)]
    check: bool,
    /// Print the operator catalogue as JSON and exit.
    #[arg(long = "list-operators")]
    list_operators: bool,
}

fn exit_code(kind: ErrorKind) -> u8 {
    match kind {
        ErrorKind::Syntax => 65,
        ErrorKind::Io => 66,
        _ => 70,
    }
}

fn main() -> ExitCode {
    // Operator panics are turned into errors by the evaluator and reported
    // with their location; keep Rust's default panic text out of the way.
    // Anything else is caught below and reported as an internal error.
    std::panic::set_hook(Box::new(|_| {}));
    match std::panic::catch_unwind(run) {
        Ok(code) => code,
        Err(p) => {
            let msg = p.downcast_ref::<String>().map(String::as_str).or_else(|| p.downcast_ref::<&str>().copied());
            eprintln!("gibi: internal error ({}); please report it with the deck", msg.unwrap_or("unknown cause"));
            ExitCode::from(70)
        }
    }
}

fn run() -> ExitCode {
    let cli = Cli::parse();
    let cwd = std::env::current_dir().unwrap_or_else(|_| ".".into());
    let mut gibi = Interpreter::builder().output(std::io::stdout()).files(FilePolicy::Under(cwd)).build();

    if cli.list_operators {
        println!("{}", repl::catalogue_json(gibi.registry()));
        return ExitCode::SUCCESS;
    }

    let mut inputs: Vec<(String, Result<String, String>)> = Vec::new();
    for (i, e) in cli.eval.iter().enumerate() {
        inputs.push((format!("-e#{}", i + 1), Ok(e.clone())));
    }
    for f in &cli.files {
        if f == "-" {
            let mut s = String::new();
            let r = std::io::stdin().read_to_string(&mut s).map(|_| s).map_err(|e| e.to_string());
            inputs.push(("<stdin>".into(), r));
        } else {
            inputs.push((f.clone(), std::fs::read_to_string(f).map_err(|e| e.to_string())));
        }
    }
    if inputs.is_empty() {
        if std::io::stdin().is_terminal() && !cli.check {
            return repl::run(gibi);
        }
        let mut s = String::new();
        let r = std::io::stdin().read_to_string(&mut s).map(|_| s).map_err(|e| e.to_string());
        inputs.push(("<stdin>".into(), r));
    }

    for (name, text) in inputs {
        let text = match text {
            Ok(t) => t,
            Err(e) => {
                eprintln!("gibi: cannot read {}: {}", name, e);
                return ExitCode::from(66);
            }
        };
        let r = if cli.check {
            gibi::syntax::parse(&text).map(|_| Outcome::EndOfInput).map_err(|mut e| {
                e.source = Some(gibi::source::Source::new(name.clone(), text.clone()));
                e
            })
        } else {
            gibi.run_str(&name, &text)
        };
        match r {
            Ok(Outcome::Finished) => return ExitCode::SUCCESS,
            Ok(Outcome::EndOfInput) => {}
            Err(e) => {
                eprint!("{}", e.render());
                return ExitCode::from(exit_code(e.kind));
            }
        }
    }
    ExitCode::SUCCESS
}
