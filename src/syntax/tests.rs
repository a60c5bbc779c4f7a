//! Lexing and structure: the rules of language.md §1 and §9.

use super::ast::*;
use super::*;

fn items(src: &str) -> Vec<ItemKind> {
    let p = parse(src).unwrap_or_else(|e| panic!("{}: {}", src, e.message));
    match &p.stmts[0] {
        Stmt::Instr(i) => i.items.iter().map(|i| i.kind.clone()).collect(),
        s => panic!("not an instruction: {:?}", s),
    }
}

use ItemKind::*;

#[test]
fn sign_rule() {
    // `A -1` is two operands, `A - 1` and `A-1` subtract, `CRIT*-1` multiplies.
    assert_eq!(items("A -1 ;"), vec![Word("A".into()), Int(-1)]);
    assert_eq!(items("A - 1 ;"), vec![Word("A".into()), Sym("-"), Int(1)]);
    assert_eq!(items("A-1 ;"), vec![Word("A".into()), Sym("-"), Int(1)]);
    assert_eq!(items("CRIT*-1 ;"), vec![Word("CRIT".into()), Sym("*"), Int(-1)]);
    assert_eq!(items("x + -0.5e1 ;"), vec![Word("X".into()), Sym("+"), Float(-5.0)]);
}

#[test]
fn a_sign_glued_to_an_exponent_is_a_number() {
    // language.md §1: `-D5` or `-E2` lexes as a number (mantissa 0), since
    // E and D are exponent letters; glued to a value, the sign subtracts.
    assert_eq!(items("1 -e2 ;"), vec![Int(1), Float(-0.0)]);
    assert_eq!(items("2 * +D5 ;"), vec![Int(2), Sym("*"), Float(0.0)]);
    assert_eq!(items("A-E2 ;"), vec![Word("A".into()), Sym("-"), Word("E2".into())]);
    assert_eq!(items("A -E2X ;"), vec![Word("A".into()), Sym("-"), Word("E2X".into())]);
}

#[test]
fn numbers() {
    assert_eq!(
        items("1. .5 1.e-5 1D-13 2.1E11 1E-5 12 ;"),
        vec![Float(1.0), Float(0.5), Float(1e-5), Float(1e-13), Float(2.1e11), Float(1e-5), Int(12)]
    );
    // More than 9 digits turns an integer into a float.
    assert_eq!(items("1234567890 ;"), vec![Float(1234567890.0)]);
    // Every digit counts, leading zeros too (redlec.eso).
    assert_eq!(items("000000012 0000000012 ;"), vec![Int(12), Float(12.0)]);
    // Beyond the range of a FLOTTANT: refused where it is written.
    let e = crate::syntax::parse("x = 1 + 1.e999 ;").unwrap_err();
    assert_eq!((e.span.map(|s| (s.start, s.end)), e.message.contains("beyond the range")), (Some((8, 14)), true));
}

#[test]
fn upper_case_outside_quotes_and_quote_escape() {
    assert_eq!(items("bloq 'ux' 'it''s' ;"), vec![Word("BLOQ".into()), Str("ux".into()), Str("it's".into())]);
}

#[test]
fn dots_index_tables() {
    assert_eq!(items("T.1 ;"), vec![Word("T".into()), Dot, Int(1)]);
    assert_eq!(items("T . 'K' . 2 ;"), vec![Word("T".into()), Dot, Str("K".into()), Dot, Int(2)]);
    assert_eq!(items("T . 3.68 ;"), vec![Word("T".into()), Dot, Float(3.68)]);
}

#[test]
fn column_one_comments_inside_an_instruction() {
    let src = "a = 1\n* a comment ; with a semicolon\n + 2 ;\n";
    let p = parse(src).unwrap();
    assert_eq!(p.stmts.len(), 1);
}

#[test]
fn star_elsewhere_multiplies() {
    assert_eq!(items(" 2 * 3 ;"), vec![Int(2), Sym("*"), Int(3)]);
    assert_eq!(items("2. ** 3 ;"), vec![Float(2.0), Sym("**"), Int(3)]);
}

#[test]
fn counters_and_groups() {
    assert_eq!(items("(&bouc / 2) ;").len(), 1);
    assert!(matches!(&items("&B ;")[0], Counter(n) if n == "B"));
}

#[test]
fn quotes_close_on_their_line() {
    let e = parse("a = 1 ;\nb = 'open ;\n").unwrap_err();
    assert_eq!(e.kind, crate::error::ErrorKind::Syntax);
    assert!(e.message.contains("quote"));
    assert_eq!(e.span.unwrap().start, 12);
}

#[test]
fn instruction_limit() {
    let long = format!("x = {} ;", "1 + ".repeat(130) + "1");
    let e = parse(&long).unwrap_err();
    assert!(e.message.contains("500"), "{}", e.message);
    // Blanks are squeezed before counting.
    let spaced = format!("x = 1{} ;", " ".repeat(2000));
    assert!(parse(&spaced).is_ok());
}

#[test]
fn structure_is_rebuilt() {
    let p = parse("si (a > 1) ; x = 1 ; sinon ; x = 2 ; finsi ; repeter b 3 ; fin b ; repeter 5 c ; fin c ;").unwrap();
    assert!(matches!(&p.stmts[0], Stmt::If { otherwise: Some(_), .. }));
    assert!(matches!(&p.stmts[1], Stmt::Loop { name, count: Some(_), .. } if name == "B"));
    assert!(matches!(&p.stmts[2], Stmt::Loop { name, count: Some(_), .. } if name == "C"));
    let p = parse("debproc f x*flottant k/entier ; finproc x ;").unwrap();
    match &p.stmts[0] {
        Stmt::Proc(d) => {
            assert_eq!(d.params.len(), 2);
            assert!(!d.params[0].optional && d.params[1].optional);
            assert_eq!(d.params[0].ty.as_deref(), Some("FLOTTANT"));
        }
        s => panic!("{:?}", s),
    }
}

#[test]
fn unclosed_blocks_and_strays() {
    assert!(parse("si (a) ; x = 1 ;").unwrap_err().message.contains("never closed"));
    // A FINSI that closes nothing does nothing (as in Cast3M), noted.
    let mut r = Reader::new("finsi ; x = 1 ;");
    assert!(matches!(r.next(), Some(Ok(Stmt::Instr(_)))));
    assert_eq!(r.take_warnings().len(), 1);
    // A text read to run closes an SI left open at its end.
    let mut r = Reader::to_run("si (a) ; x = 1 ; sinon ; x = 2 ;");
    assert!(matches!(r.next(), Some(Ok(Stmt::If { otherwise: Some(_), .. }))));
    assert!(r.next().is_none());
    // A REPETER left open runs once: Cast3M meets the end of the text in
    // its first pass. A DEBPROC left open is an error.
    let mut r = Reader::to_run("repeter b 5 ; si (a) ; x = 1 ;");
    match r.next() {
        Some(Ok(Stmt::Loop { count: Some(c), body, .. })) => {
            assert_eq!(c.items[0].kind, Int(1));
            assert!(matches!(body[0], Stmt::If { .. }));
        }
        s => panic!("{:?}", s),
    }
    assert!(Reader::to_run("debproc f ; si (a) ; x = 1 ;").next().unwrap().is_err());
    assert!(parse("repeter a ; fin b ;").is_err());
    assert!(parse("x = (1 + 2 ;").unwrap_err().message.contains("'('"));
    assert!(parse("x = 1 + 2) ;").is_err());
}

#[test]
fn completeness_for_the_repl() {
    assert!(matches!(check_complete("x = 1"), Completeness::Incomplete));
    assert!(matches!(check_complete("si (x > 1) ;\n y = 2 ;"), Completeness::Incomplete));
    assert!(matches!(check_complete("x = (1"), Completeness::Incomplete));
    assert!(matches!(check_complete("x = 1 ;"), Completeness::Complete(_)));
    assert!(matches!(check_complete("x = 1) ;"), Completeness::Invalid(_)));
    assert!(matches!(check_complete("fin b ;"), Completeness::Invalid(_)));
}

#[test]
fn forms_of_cast3m_procedures() {
    // A broken instruction inside a block raises its error when it runs.
    let p = parse("si (a) ; x = (1 ; finsi ;").unwrap();
    match &p.stmts[0] {
        Stmt::If { branches, .. } => assert!(matches!(branches[0].body[0], Stmt::Broken { .. })),
        s => panic!("{:?}", s),
    }
    assert!(parse("x = (1 ; si (a) ; finsi ;").is_err(), "at top level it is an error at once");
    // FINSI followed by a directive or a quoted operator: two instructions.
    let p = parse("si (a) ; x = 1 ; 'FINSI' 'SI' b ; y = 2 ; finsi ;").unwrap();
    assert_eq!(p.stmts.len(), 2);
    assert!(parse("si (a) ; finsi garbage ;").is_err());
    // Names may begin with digits; numbers end at a separator.
    assert_eq!(
        items("4filtre 1.5e3 2*3 ;"),
        vec![
            ItemKind::Word("4FILTRE".into()),
            ItemKind::Float(1500.0),
            ItemKind::Int(2),
            ItemKind::Sym("*"),
            ItemKind::Int(3),
        ]
    );
    // `<` and `>` glued to a name are part of it (`T.<PLAN`, `>X`).
    assert_eq!(
        items("t.<plan >eg >x ;"),
        vec![Word("T".into()), Dot, Word("<PLAN".into()), Sym(">EG"), Word(">X".into()),]
    );
    // Targets: a quoted type, a group before keys, &NAME.
    let p = parse("x*'FLOTTANT' = 1. ; (t . 1) . 'K' = 2 ; &d = 3 ;").unwrap();
    let targets: Vec<_> = p
        .stmts
        .iter()
        .map(|s| match s {
            Stmt::Instr(i) => i.targets[0].clone(),
            s => panic!("{:?}", s),
        })
        .collect();
    assert_eq!(targets[0].typed.as_deref(), Some("FLOTTANT"));
    assert!(targets[1].base.is_some() && targets[1].keys.len() == 1);
    assert_eq!(targets[2].name, "&D");
}

#[test]
fn reading_stops_at_a_top_level_fin() {
    // Anything may follow a top-level FIN; a FIN inside a block is read on.
    let p = parse("a = 1 ;\nfin ;\nnotes ' ( without ) si ;\n").unwrap();
    assert_eq!(p.stmts.len(), 2);
    let p = parse("si (a) ; fin ; finsi ; b = 2 ; fin ; ' garbage").unwrap();
    assert_eq!(p.stmts.len(), 3);
    assert!(parse("si (a) ; fin ; ' garbage").is_err());
}

#[test]
fn statements_come_one_at_a_time_before_an_error() {
    let mut r = Reader::new("a = 1 ;\nrepeter b 2 ; x = 1 ; fin b ;\nc = (2 ;\nd = 3 ;");
    assert!(matches!(r.next(), Some(Ok(Stmt::Instr(_)))));
    assert!(matches!(r.next(), Some(Ok(Stmt::Loop { .. }))));
    let e = r.next().unwrap().unwrap_err();
    assert_eq!(e.span.unwrap().start as usize, "a = 1 ;\nrepeter b 2 ; x = 1 ; fin b ;\nc = (2 ".len());
    assert!(r.next().is_none());
}

#[test]
fn deep_nesting_is_a_syntax_error() {
    let parens = format!("x = {}1{} ;", "(".repeat(MAX_PAREN_DEPTH + 1), ")".repeat(MAX_PAREN_DEPTH + 1));
    assert!(parse(&parens).unwrap_err().message.contains("nested"));
    let ok = format!("x = {}1{} ;", "(".repeat(MAX_PAREN_DEPTH), ")".repeat(MAX_PAREN_DEPTH));
    assert!(parse(&ok).is_ok());
    let blocks = "si vrai ;\n".repeat(MAX_BLOCK_DEPTH + 1) + &"finsi ;\n".repeat(MAX_BLOCK_DEPTH + 1);
    let e = parse(&blocks).unwrap_err();
    assert!(e.message.contains("nested more than"), "{}", e.message);
    assert_eq!(e.span.unwrap().start as usize, "si vrai ;\n".len() * MAX_BLOCK_DEPTH);
}

#[test]
fn else_if_and_closers_with_garbage() {
    let p = parse("si a ; x = 1 ; sinon b ; x = 2 ; sinon c ; x = 3 ; sinon ; x = 4 ; finsi ;").unwrap();
    match &p.stmts[0] {
        Stmt::If { branches, otherwise: Some(o), .. } => {
            assert_eq!(branches.len(), 3);
            assert!(branches.iter().all(|b| b.body.len() == 1) && o.len() == 1);
        }
        s => panic!("{:?}", s),
    }
    assert!(parse("si a ; sinon ; sinon b ; finsi ;").is_err());
    let e = parse("si a ; finsi garbage ;").unwrap_err();
    assert_eq!((e.message.as_str(), e.span.unwrap().start), ("FINSI takes nothing after it", 13));
    let e = parse("repeter b ; fin b garbage ;").unwrap_err();
    assert_eq!((e.message.as_str(), e.span.unwrap().start), ("FIN takes a block name or nothing", 18));
}

#[test]
fn object_member_and_method_syntax() {
    // `%ELE = …` names an entry of the current OBJET; in operands `%` stays
    // a symbol, and the evaluator tells `o%METH` from `%ELE` (obje.notice).
    let p = parse("%rea = %ima * 2 ;").unwrap();
    match &p.stmts[0] {
        Stmt::Instr(i) => {
            assert_eq!(i.targets[0].name, "%REA");
            assert_eq!(i.items[..2], [Item { kind: Sym("%"), span: i.items[0].span }, i.items[1].clone()]);
            assert_eq!(i.items[1].kind, Word("IMA".into()));
        }
        s => panic!("{:?}", s),
    }
    assert_eq!(items("r = com%get_rea 2.5 ;"), vec![Word("COM".into()), Sym("%"), Word("GET_REA".into()), Float(2.5)]);
    assert_eq!(items("%METHODE M1 P1 ;"), vec![Sym("%"), Word("METHODE".into()), Word("M1".into()), Word("P1".into())]);
}

#[test]
fn debmeth_is_a_procedure_definition() {
    let p = parse("debmeth m x*flottant ; %v = x ; finmeth ;").unwrap();
    match &p.stmts[0] {
        Stmt::Proc(d) => assert_eq!((d.name.as_str(), d.params.len(), d.body.len()), ("M", 1, 1)),
        s => panic!("{:?}", s),
    }
    assert!(parse("debmeth m ; finsi ;").is_err());
}
