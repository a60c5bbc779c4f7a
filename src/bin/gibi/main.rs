//! The `gibi` command: run decks, a snippet, stdin, or open the REPL.
//! Exit codes follow sysexits: 65 for a syntax error, 70 for a runtime
//! error or an aborting ERRE, 66 for an unreadable file, 73 for a file
//! that could not be written, 77 for a path the file policy refuses.

mod repl;

use clap::Parser;
use gibi::source::decode;
use gibi::{CommandPolicy, ErrorKind, FilePolicy, Interpreter, Outcome};
use std::ffi::{OsStr, OsString};
use std::io::{IsTerminal, Read};
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "gibi", version, about = "An interpreter for Gibiane, the command language of Cast3M")]
struct Cli {
    /// Deck files to run in order ('-' reads a deck from standard input).
    files: Vec<String>,
    /// Run these instructions (before the files).
    #[arg(short = 'e', long = "eval", value_name = "INSTRUCTIONS", value_parser = clap::value_parser!(OsString))]
    eval: Vec<OsString>,
    /// Only parse: report syntax errors, run nothing.
    #[arg(long)]
    check: bool,
    /// Print the operator catalogue as JSON and exit.
    #[arg(long = "list-operators")]
    list_operators: bool,
    /// Do not print a line for each file written (and no REPL banner).
    #[arg(short = 'q', long)]
    quiet: bool,
    /// A Cast3M procedure library: a file of `$$$$ NAME` procedures or a
    /// folder of *.procedur files (repeatable; searched before the paths
    /// of $GIBI_PROCEDURES).
    #[arg(long = "procedures", value_name = "PATH")]
    procedures: Vec<std::path::PathBuf>,
    /// Let decks run any program of this machine (EXTE). Off by default:
    /// a deck then reaches no more than the files of its directory.
    #[arg(long = "allow-commands")]
    allow_commands: bool,
    /// Let decks run this program (EXTE), named as the deck writes it
    /// (repeatable).
    #[arg(long = "allow-command", value_name = "PROGRAM")]
    allow_command: Vec<String>,
}

fn exit_code(kind: ErrorKind) -> u8 {
    match kind {
        ErrorKind::Syntax => 65,
        ErrorKind::Io => 66,
        ErrorKind::Write => 73,
        ErrorKind::Denied => 77,
        ErrorKind::Interrupted => 130,
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

/// Ctrl-C stops the running instruction (the REPL gets its prompt back
/// with every object, a deck run ends with exit 130 naming the line). A
/// second Ctrl-C before the first is acted on (a long operator that does
/// not poll the flag) ends the process.
pub(crate) fn catch_ctrl_c(gibi: &Interpreter) {
    let stop = gibi.interrupt_handle();
    let _ = ctrlc::set_handler(move || {
        if stop.is_pending() {
            eprintln!("\ngibi: interrupted");
            std::process::exit(130);
        }
        stop.interrupt();
    });
}

/// The progress of long operators (PASAPAS's steps) as a bar on the
/// terminal: shown once a run has lasted half a second, cleared at its end.
fn progress_bar() -> impl FnMut(usize, usize) {
    let mut bar: Option<indicatif::ProgressBar> = None;
    let mut start = std::time::Instant::now();
    move |done, total| {
        if done <= 1 {
            start = std::time::Instant::now();
            if let Some(b) = bar.take() {
                b.finish_and_clear();
            }
        }
        if bar.is_none() && done < total && start.elapsed().as_secs_f64() > 0.5 {
            let b = indicatif::ProgressBar::new(total as u64);
            b.set_style(
                indicatif::ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} steps, {elapsed} (eta {eta})")
                    .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
                    .progress_chars("=> "),
            );
            b.set_message("PASAPAS");
            bar = Some(b);
        }
        if let Some(b) = &bar {
            b.set_length(total as u64);
            b.set_position(done as u64);
            if done >= total {
                b.finish_and_clear();
                bar = None;
            }
        }
    }
}

/// Standard input as deck text (Latin-1 bytes accepted, see `decode`).
fn read_stdin() -> Result<String, String> {
    let mut b = Vec::new();
    std::io::stdin().read_to_end(&mut b).map(|_| decode(&b)).map_err(|e| e.to_string())
}

/// The bytes of a command-line argument: on Unix they are the raw bytes,
/// so a Latin-1 `-e` snippet survives; elsewhere the lossy conversion.
fn os_bytes(s: &OsStr) -> std::borrow::Cow<'_, [u8]> {
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        std::borrow::Cow::Borrowed(s.as_bytes())
    }
    #[cfg(not(unix))]
    {
        std::borrow::Cow::Owned(s.to_string_lossy().into_owned().into_bytes())
    }
}

fn run() -> ExitCode {
    let cli = Cli::parse();
    let cwd = std::env::current_dir().unwrap_or_else(|_| ".".into());
    let env_procedures = std::env::var_os("GIBI_PROCEDURES");
    let procedures: Vec<_> = cli
        .procedures
        .iter()
        .cloned()
        .chain(env_procedures.iter().flat_map(std::env::split_paths))
        .filter(|p| !p.as_os_str().is_empty())
        .collect();
    if let Some(p) = procedures.iter().find(|p| !p.exists()) {
        eprintln!("gibi: cannot read the procedure library {}: no such file or folder", p.display());
        return ExitCode::from(66);
    }
    let mut builder = Interpreter::builder()
        .output(std::io::stdout())
        .files(FilePolicy::Under(cwd))
        .commands(match (cli.allow_commands, cli.allow_command.is_empty()) {
            (true, _) => CommandPolicy::Anything,
            (false, false) => CommandPolicy::Only(cli.allow_command.clone()),
            (false, true) => CommandPolicy::Nothing,
        })
        .procedures(procedures)
        .report_files(!cli.quiet);
    if std::io::stderr().is_terminal() {
        builder = builder.progress(progress_bar());
    }
    let mut gibi = builder.build();

    if cli.list_operators {
        // A reader that stops early (`| head`) is not an error of gibi's.
        use std::io::Write;
        let _ = writeln!(std::io::stdout(), "{}", repl::catalogue_json(gibi.registry()));
        return ExitCode::SUCCESS;
    }

    let mut inputs: Vec<(String, Result<String, String>)> = Vec::new();
    for (i, e) in cli.eval.iter().enumerate() {
        inputs.push((format!("-e#{}", i + 1), Ok(decode(os_bytes(e).as_ref()))));
    }
    for f in &cli.files {
        if f == "-" {
            inputs.push(("<stdin>".into(), read_stdin()));
        } else {
            inputs.push((f.clone(), std::fs::read(f).map(|b| decode(&b)).map_err(|e| e.to_string())));
        }
    }
    if inputs.is_empty() {
        if std::io::stdin().is_terminal() && !cli.check {
            return repl::run(gibi, cli.quiet);
        }
        inputs.push(("<stdin>".into(), read_stdin()));
    }

    catch_ctrl_c(&gibi);
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
