//! The `gibi` binary: exit codes, file names in errors, -e, stdin, --check.

use std::io::Write;
use std::process::{Command, Stdio};

fn gibi() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gibi"))
}

fn deck(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("gibi-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn exit_codes() {
    let ok = gibi().arg(deck("ok.dgibi", "mess 'hello' ; fin ; mess 'not printed' ;")).output().unwrap();
    assert_eq!(ok.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&ok.stdout), "hello\n");

    let syn = gibi().current_dir(std::env::temp_dir()).arg(deck("syn.dgibi", "a = 1 ;\nb = 'x ;\n")).output().unwrap();
    assert_eq!(syn.status.code(), Some(65));
    assert!(String::from_utf8_lossy(&syn.stderr).contains("syn.dgibi:2:5:"));

    let run = gibi().arg(deck("run.dgibi", "a = 1 ;\nerre 5 ;\n")).output().unwrap();
    assert_eq!(run.status.code(), Some(70));
    assert!(String::from_utf8_lossy(&run.stderr).contains("run.dgibi:2:1:"));

    let missing = gibi().arg("/nonexistent/deck.dgibi").output().unwrap();
    assert_eq!(missing.status.code(), Some(66));
}

#[test]
fn eval_stdin_and_check() {
    let e = gibi().args(["-e", "x = 1 + 2 * 3 ; mess x ;"]).output().unwrap();
    assert_eq!(String::from_utf8_lossy(&e.stdout), "9\n");

    let mut child = gibi().stdin(Stdio::piped()).stdout(Stdio::piped()).spawn().unwrap();
    child.stdin.take().unwrap().write_all(b"mess 'piped' ;\n").unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(String::from_utf8_lossy(&out.stdout), "piped\n");

    let c = gibi().arg("--check").arg(deck("chk.dgibi", "erre 5 ;")).output().unwrap();
    assert_eq!(c.status.code(), Some(0));
    let c = gibi().arg("--check").arg(deck("chk2.dgibi", "x = (1 ;")).output().unwrap();
    assert_eq!(c.status.code(), Some(65));
}

#[test]
fn catalogue_is_json() {
    let out = gibi().arg("--list-operators").output().unwrap();
    let s = String::from_utf8_lossy(&out.stdout);
    assert!(s.trim_start().starts_with('[') && s.trim_end().ends_with(']'));
    assert!(s.contains("\"name\": \"PROG\""));
}

/// The manual is complete: every operator has a signature, a description
/// and an example (they feed errors, `:help` and editor support).
#[test]
fn every_operator_is_documented() {
    let out = gibi().arg("--list-operators").output().unwrap();
    let s = String::from_utf8_lossy(&out.stdout);
    for line in s.lines().filter(|l| l.contains("\"name\"")) {
        for field in ["signature", "doc", "example"] {
            assert!(!line.contains(&format!("\"{}\": \"\"", field)), "{} lacks {}", line, field);
        }
    }
}

/// French decks in ISO-8859-1 run: bytes that are not UTF-8 are read as
/// Latin-1, in files, on stdin and in -e.
#[test]
fn latin1_decks_are_accepted() {
    let text: &[u8] = b"* D\xe9formation de la poutre\nmess 'r\xe9sultat' ;\nfin ;\n";
    let dir = std::env::temp_dir().join(format!("gibi-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("latin1.dgibi");
    std::fs::write(&p, text).unwrap();
    let out = gibi().arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "résultat\n");

    let mut child = gibi().arg("-").stdin(Stdio::piped()).stdout(Stdio::piped()).spawn().unwrap();
    child.stdin.take().unwrap().write_all(text).unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "résultat\n");

    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        let arg = std::ffi::OsStr::from_bytes(b"mess '\xe0 bient\xf4t' ;");
        let out = gibi().arg("-e").arg(arg).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(String::from_utf8_lossy(&out.stdout), "à bientôt\n");
    }
}

/// A deck is read one instruction at a time: what precedes a syntax error
/// runs (the error still exits 65 at its line), and notes after a
/// top-level FIN are never read, by --check either.
#[test]
fn reading_is_incremental() {
    let d = deck("partial.dgibi", "mess 'first' ;\nx = (1 ;\nmess 'never' ;\n");
    let out = gibi().current_dir(d.parent().unwrap()).arg("partial.dgibi").output().unwrap();
    assert_eq!(out.status.code(), Some(65));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "first\n");
    assert!(String::from_utf8_lossy(&out.stderr).starts_with("partial.dgibi:2:8: syntax error"));
    let notes = deck("notes.dgibi", "mess 'done' ;\nfin ;\nRemarques : l'auteur (2019\n");
    let out = gibi().arg(&notes).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "done\n");
    assert_eq!(gibi().arg("--check").arg(&notes).output().unwrap().status.code(), Some(0));
}

/// `--procedures PATH` (repeatable) and `GIBI_PROCEDURES` (paths joined
/// like PATH) name procedure libraries; the flags are searched first.
#[test]
fn procedure_libraries_from_the_flag_and_the_environment() {
    let lib = |p: &str| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/procedures").join(p);
    let run = |cmd: &mut Command| {
        let out = cmd.args(["-e", "mess (carre 3.) (double 2.) ;"]).output().unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    // A run with no GIBI_PROCEDURES of its own.
    let bare = || {
        let mut c = gibi();
        c.env_remove("GIBI_PROCEDURES");
        c
    };
    let (code, out, err) =
        run(bare().arg("--procedures").arg(lib("folder")).arg("--procedures").arg(lib("utilproc.txt")));
    assert_eq!(code, Some(0), "{}", err);
    assert_eq!(out, "9.00000E+00 4.00000E+00\n");

    let both = std::env::join_paths([lib("utilproc.txt"), lib("folder")]).unwrap();
    let (code, out, err) = run(gibi().env("GIBI_PROCEDURES", &both));
    assert_eq!(code, Some(0), "{}", err);
    assert_eq!(out, "-9.00000E+00 4.00000E+00\n", "utilproc.txt's CARRE comes first");

    // The flag is searched before the environment's paths.
    let (code, out, err) = run(gibi().arg("--procedures").arg(lib("folder")).env("GIBI_PROCEDURES", &both));
    assert_eq!(code, Some(0), "{}", err);
    assert_eq!(out, "9.00000E+00 4.00000E+00\n");

    // Without a library, CARRE is a word, and a Cast3M procedure is
    // refused by name.
    let (code, out, _) = run(&mut bare());
    assert_eq!((code, out.as_str()), (Some(0), "CARRE 3.00000E+00 DOUBLE 2.00000E+00\n"));
    // A library that does not exist stops the run before it starts.
    let out = bare().args(["--procedures", "/nonexistent/gibi/lib", "-e", "x = 1 ;"]).output().unwrap();
    assert_eq!(out.status.code(), Some(66));
    assert!(String::from_utf8_lossy(&out.stderr).contains("/nonexistent/gibi/lib"));
    let out = bare().args(["-e", "t = tabl ; mailstru t 1. ;"]).output().unwrap();
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("MAILSTRU is a Cast3M procedure that gibi does not implement")
    );
}

/// `--list-operators` marks every name of Cast3M's catalogue.
#[test]
fn the_catalogue_marks_every_cast3m_name() {
    let out = gibi().arg("--list-operators").output().unwrap();
    let s = String::from_utf8_lossy(&out.stdout);
    let line = |name: &str| {
        s.lines().find(|l| l.contains(&format!("\"name\": \"{}\"", name))).unwrap_or_else(|| panic!("{} missing", name))
    };
    assert!(line("RESO").contains("\"status\": \"implemented\""));
    assert!(line("SI").contains("\"status\": \"implemented\""), "a directive of the language");
    assert!(line("VIBR").contains("\"status\": \"refused\"") && line("VIBR").contains("VIBRATION"));
    assert!(line("PASAPAS").contains("\"status\": \"procedure\""));
    let rows = s.lines().filter(|l| l.contains("\"status\"")).count();
    assert!(rows > 1000, "{} rows", rows);
}
