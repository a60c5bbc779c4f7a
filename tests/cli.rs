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

/// Every operator's catalogue example is Gibiane (it parses) and runs in a
/// sandboxed interpreter (no file access, a step limit) without an
/// internal error, after a setup that defines the objects examples name.
#[test]
fn every_catalogue_example_runs() {
    const SETUP: &str = "
opti echo 0 dime 2 elem qua4 mode plan cont ;
p0 = 0. 0. ; p1 = 0. 0. ; p2 = 1. 0. ; p3 = 1. 1. ; p4 = 0. 1. ; o = 0. 0. ; p = p3 ;
bas = droi 2 p1 p2 ; dro = droi 2 p2 p3 ; hau = droi 2 p3 p4 ; gau = droi 2 p4 p1 ;
l = bas ; l1 = bas ; l2 = dro ; s = dall bas dro hau gau ; s1 = s ; s2 = s plus (0. 1.) ;
mo = mode s mecanique elastique ; ma = mate mo youn 100. nu 0.3 ;
k = rigi mo ma ; cl = bloq 'UX' 'UY' gau ; f = forc 'FX' 1. p3 ; f1 = f ; f2 = forc 'FY' 1. p3 ; f3 = f ;
u = reso (k et cl) f ; r = reac cl u ; sig = sigm mo ma u ; eps = epsi mo ma u ;
x = 2.5 ; i = 3 ; n = 2 ; m = 'ABC' ; lr = prog 1. 2. 3. ; le = lect 1 2 3 ; l1r = lr ; l2r = lr ;
t = table ; t . 1 = 2. ; ev = evol 'MANU' lr lr ; ev1 = ev ; ev2 = ev ;
u1 = u ; u2 = u ; haut = hau ; pa = p1 ; pb = p2 ; err = 0. ;
";
    let mut ran = 0;
    let mut failed = Vec::new();
    let ops = gibi::Interpreter::new().registry().all();
    for op in &ops {
        let ex = op.example;
        if let Err(e) = gibi::syntax::parse(ex) {
            panic!("{}: the example does not parse: {}\n{}", op.name, ex, e.render());
        }
        let mut g = gibi::Interpreter::builder().files(gibi::FilePolicy::Nothing).step_limit(10_000).build();
        g.run_str("setup", SETUP).expect("setup runs");
        match g.run_str("example", ex) {
            Ok(_) => ran += 1,
            Err(e) if e.kind == gibi::ErrorKind::Internal => {
                panic!("{}: the example ends in an internal error: {}\n{}", op.name, ex, e.render())
            }
            Err(e) => failed.push(format!("{}: {} -> {}", op.name, ex, e.message)),
        }
    }
    eprintln!("{} of {} examples ran; the others failed cleanly:\n{}", ran, ops.len(), failed.join("\n"));
    // The setup must make real runs of most examples, not only errors.
    assert!(ran * 4 > ops.len() * 3, "only {} of {} examples ran:\n{}", ran, ops.len(), failed.join("\n"));
}

/// The file policy follows real paths: a symbolic link in the working
/// directory that leads outside cannot be written or read through (files
/// and directories), the refusal has its own exit code (77), an error
/// about a file never shows its content, and each file written is named
/// on a line of its own, relative to the working directory (--quiet: not).
#[cfg(unix)]
#[test]
fn file_policy_and_symbolic_links() {
    use std::os::unix::fs::symlink;
    let base = std::env::temp_dir().join(format!("gibi-cli-links-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&base);
    let (work, outside) = (base.join("work"), base.join("outside"));
    std::fs::create_dir_all(&work).unwrap();
    std::fs::create_dir_all(&outside).unwrap();
    std::fs::write(outside.join("secret.msh"), "root:x:0:0:TOP-SECRET\n").unwrap();
    std::fs::write(work.join("notamesh.msh"), "TOP-SECRET too\n").unwrap();
    symlink(&outside, work.join("link")).unwrap();
    symlink(outside.join("secret.msh"), work.join("p.msh")).unwrap();
    symlink(outside.join("new.vtu"), work.join("dangling.vtu")).unwrap();
    let run = |args: &[&str]| gibi().current_dir(&work).args(args).output().unwrap();
    let mesh = "opti dime 2 elem seg2 ; s = d 2 (0. 0.) (1. 0.) ;";

    // Writing through a directory link, or to a dangling link.
    for target in ["link/x", "link/sub/x", "dangling"] {
        let out = run(&["-e", &format!("{} opti sort '{}' ; sort 'VTK' s ;", mesh, target)]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(77), "{}: {}", target, err);
        assert!(err.contains("outside the directory") || err.contains("leads nowhere"), "{}", err);
    }
    assert_eq!(std::fs::read_dir(&outside).unwrap().count(), 1, "nothing written outside");

    // Reading through a file link; reading a file that is not a mesh.
    let out = run(&["-e", "opti dime 2 ; t = lire 'GMSH' 'p.msh' ;"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(77), "{}", err);
    assert!(err.contains("through a symbolic link") && !err.contains("SECRET"), "{}", err);
    let out = run(&["-e", "opti dime 2 ; t = lire 'GMSH' 'notamesh.msh' ;"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(66), "{}", err);
    assert!(err.contains("not a Gmsh mesh") && !err.contains("SECRET"), "{}", err);

    // Files written are named, relative to the working directory.
    let out = run(&["-e", &format!("{} opti sort 'res/plate' ; sort 'VTK' s ; trac s ;", mesh)]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "wrote res/plate.vtu\nwrote res/plate.svg\n");
    assert!(work.join("res/plate.vtu").is_file());
    let out = run(&["--quiet", "-e", &format!("{} opti sort 'res/plate' ; sort 'VTK' s ;", mesh)]);
    assert_eq!((out.status.code(), out.stdout.len()), (Some(0), 0));

    // A file that cannot be written (a directory stands in its place): 73.
    std::fs::create_dir_all(work.join("busy.vtu")).unwrap();
    let out = run(&["-e", &format!("{} opti sort 'busy' ; sort 'VTK' s ;", mesh)]);
    assert_eq!(out.status.code(), Some(73), "{}", String::from_utf8_lossy(&out.stderr));
}

/// Ctrl-C (SIGINT) ends a deck run with exit 130 and names the line it
/// reached, even inside a loop whose body is empty.
#[cfg(unix)]
#[test]
fn interrupt_ends_a_run_with_130() {
    for (name, text, line) in [
        ("int1.dgibi", "x = 1 ;\nrepeter c 20 ;\n  repeter b 100000000 ; y = &b ; fin b ;\nfin c ;\n", ":3:"),
        ("int2.dgibi", "x = 1 ;\n\nrepeter b ; fin b ;\n", ":3:1: interrupted"),
    ] {
        let d = deck(name, text);
        let child = gibi().arg(&d).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
        std::thread::sleep(std::time::Duration::from_millis(300));
        let t = std::time::Instant::now();
        Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
        let out = child.wait_with_output().unwrap();
        assert!(t.elapsed() < std::time::Duration::from_secs(2), "{:?}", t.elapsed());
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(130), "{}", err);
        assert!(err.contains(&format!("{}{}", name, line)) && err.contains("interrupted"), "{}", err);
    }
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
    assert!(line("DYNE").contains("\"status\": \"refused\"") && line("DYNE").contains("\"kind\": \"operator\""));
    assert!(line("MAILSTRU").contains("\"status\": \"procedure\""));
    // A Cast3M procedure that gibi implements natively.
    assert!(line("PASAPAS").contains("\"status\": \"implemented\""));
    let rows = s.lines().filter(|l| l.contains("\"status\"")).count();
    assert!(rows > 1000, "{} rows", rows);
}
