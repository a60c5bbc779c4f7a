//! Round trips through the file formats of LIRE and SORT (STL, CSV, AVS,
//! Nastran) and LIRE 'PROC': each script writes a file (or the test
//! does), reads it back and checks its numbers in-deck; a failed check is
//! ERRE 5. The files go to a scratch directory, the only one the run may
//! use.

use gibi::{Capture, FilePolicy, Interpreter};
use std::path::{Path, PathBuf};

fn scratch(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gibi_io_formats_{}_{}", std::process::id(), test));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(dir: &Path, deck: &str) -> Result<String, String> {
    let out = Capture::default();
    let mut gibi = Interpreter::builder().output(out.clone()).files(FilePolicy::Under(dir.to_path_buf())).build();
    match gibi.run_str("deck", deck) {
        Ok(_) => Ok(out.text()),
        Err(e) => Err(format!("{}{}", out.text(), e.render())),
    }
}

fn ok(dir: &Path, deck: &str) -> String {
    run(dir, deck).unwrap_or_else(|e| panic!("{}", e))
}

#[test]
fn stl_surface_round_trip() {
    let dir = scratch("stl");
    // The plane through (2,0,0) and (0,1,0.5) has area |(0,-1,2)| = sqrt 5.
    ok(
        &dir,
        "opti dime 3 elem qua4 ;
         p1 = 0. 0. 0. ; p2 = 2. 0. 0. ; p3 = 2. 1. 0.5 ; p4 = 0. 1. 0.5 ;
         s = dall (p1 d 2 p2) (p2 d 1 p3) (p3 d 2 p4) (p4 d 1 p1) ;
         opti sort 'surf' ;
         sort 'STL' s ;
         m = lire 'STL' 'surf.stl' ;
         si (neg (nbel m) 4) ; erre 5 ; finsi ;
         si (neg (nbno m) 6) ; erre 5 ; finsi ;
         err = abs ((mesu m) - (5. ** 0.5)) ; 
         si (err > 1.e-6) ; erre 5 ; finsi ;
         err = abs ((maxi (coor 3 m)) - 0.5) ;
         si (err > 1.e-7) ; erre 5 ; finsi ;",
    );
    let t = gibi::io::stl::read(&dir.join("surf.stl")).unwrap();
    assert_eq!((t.tris.len(), t.coords.len()), (4, 6));
    // A volume has no STL form: its skin has.
    let e = run(&dir, "opti dime 3 elem cub8 ; p = 0. 0. 0. ; v = (p d 1 (1. 0. 0.)) trans 1 (0. 1. 0.) volu 1 tran (0. 0. 1.) ; sort 'STL' v ;")
        .unwrap_err();
    assert!(e.contains("ENVE"), "{}", e);
}

#[test]
fn csv_columns() {
    let dir = scratch("csv");
    std::fs::write(dir.join("d.csv"), "time,force\n0,1.5\n0.5,2.5e1\n1.0,-3\n").unwrap();
    std::fs::write(dir.join("fr.csv"), "0;1,25\n1;2,5\n").unwrap();
    ok(
        &dir,
        "t = lire 'CSV' 'd.csv' 'DEBU' 2 'SEPA' ',' ;
         si (neg (dime t) 2) ; erre 5 ; finsi ;
         x = t . 1 ; y = t . 2 ;
         si (neg (dime y) 3) ; erre 5 ; finsi ;
         err = abs ((extr y 2) - 25.) + (abs ((extr x 3) - 1.)) + (abs ((extr y 3) + 3.)) ;
         si (err > 1.e-12) ; erre 5 ; finsi ;
         f = lire 'CSV' 'fr.csv' ;
         err = abs ((extr (f . 2) 1) - 1.25) ;
         si (err > 1.e-12) ; erre 5 ; finsi ;",
    );
    let e = run(&dir, "t = lire 'CSV' 'd.csv' 'SEPA' ',' ;").unwrap_err();
    assert!(e.contains("'d.csv': line 1, column 1: not a number"), "{}", e);
    assert!(!e.contains("time"), "the file's text is not echoed: {}", e);
}

#[test]
fn avs_steps_round_trip() {
    let dir = scratch("avs");
    ok(
        &dir,
        "opti dime 3 elem cub8 ;
         p1 = 0. 0. 0. ; p2 = 1. 0. 0. ;
         s = (p1 d 2 p2) tran 1 (0. 1. 0.) ;
         v = s volu 1 tran (0. 0. 1.) ;
         u = manu 'CHPO' v 2 'UX' 1.5e-3 'UY' (1. / 3.) ;
         opti sort 'res' ;
         sort 'AVS' v u 'SUIT' 'TEMP' 0.25 ;
         u2 = 2. * u ;
         sort 'AVS' v u2 'SUIT' 'TEMP' 0.5 ;
         opti lect 'res.inp' ;
         t1 = lire 'AVS' ;
         t2 = lire 'AVS' ;
         si (neg (nbel (t1 . 'LEMAILLA')) 2) ; erre 5 ; finsi ;
         si (neg (nbno (t1 . 'MAILSUPP')) 12) ; erre 5 ; finsi ;
         err = abs ((t2 . 'time') - 0.5) + (abs ((t1 . 'time') - 0.25)) ;
         si (err > 1.e-15) ; erre 5 ; finsi ;
         elim (v et (t1 . 'LEMAILLA') et (t2 . 'LEMAILLA')) 1.e-9 ;
         d = (u2 - (t2 . 'LECHPOIN')) ;
         err = (abs (maxi d)) + (abs (mini d)) ;
         si (err > 0.) ; erre 5 ; finsi ;
         err = abs ((maxi (exco (t1 . 'LECHPOIN') 'UY')) - (1. / 3.)) ;
         si (err > 0.) ; erre 5 ; finsi ;",
    );
    // A third LIRE finds nothing left.
    let e = run(&dir, "opti lect 'res.inp' ; t = lire 'AVS' ; t = lire 'AVS' ; t = lire 'AVS' ;").unwrap_err();
    assert!(e.contains("no AVS structure left"), "{}", e);
}

const NAS: &str = "$ three field layouts
BEGIN BULK
GRID           1       0      0.      0.      0.
GRID           2       0      2.      0.      0.
GRID*                  3               0           2.0E0           1.0E0*
*             0.
GRID,4,,0.,1.,.5-1
CQUAD4        10       7       1       2       3       4
CTRIA3        11       8       1       3       4
SPC1           5  123456       1    THRU       2
FORCE          6       3       0     10.      0.      1.      0.
TEMP           9       1    20.5       2     30.
RBE2          12       4  123456       1       2
ENDDATA
";

#[test]
fn nastran_read_and_round_trip() {
    let dir = scratch("nas");
    std::fs::write(dir.join("in.nas"), NAS).unwrap();
    ok(
        &dir,
        "opti dime 3 ;
         t = lire 'NAS' 'in.nas' ;
         q = t . 'MAILLAGES' . 7 ; r = t . 'MAILLAGES' . 8 ;
         si ((neg (nbel q) 1) ou (neg (nbel r) 1)) ; erre 5 ; finsi ;
         si (neg (nbno (t . 'BLOCAGES' . 5)) 2) ; erre 5 ; finsi ;
         err = abs ((maxi (exco (t . 'FORCES' . 6) 'FY')) - 10.) ;
         err = err + (abs ((maxi (exco (t . 'TEMPERATURES' . 9) 'T')) - 30.)) ;
         err = err + (abs ((maxi (coor 3 q)) - 0.05)) ;
         si (err > 1.e-12) ; erre 5 ; finsi ;
         si (neg (nbno (t . 'RBE2' . 12 . 'MAILLAGE')) 3) ; erre 5 ; finsi ;
         m = q et r ;
         opti sort 'out' ;
         sort 'NAS' m ;
         t2 = lire 'NAS' 'out.nas' ;
         m2 = (t2 . 'MAILLAGES' . 1) et (t2 . 'MAILLAGES' . 2) ;
         si ((neg (nbel m2) 2) ou (neg (nbno m2) 4)) ; erre 5 ; finsi ;
         err = abs ((mesu m2) - (mesu m)) ;
         si (err > 1.e-9) ; erre 5 ; finsi ;
         elim (m et m2) 1.e-9 ;
         si (neg (nbno (m et m2)) 4) ; erre 5 ; finsi ;",
    );
}

#[test]
fn procedures_from_a_file() {
    let dir = scratch("proc");
    std::fs::write(
        dir.join("lib.procedur"),
        "$$$$ DOUBLE\nDEBP DOUBLE x*FLOTTANT ;\n  FINP (2. * x) ;\n$$$$ TRIPLE\nDEBP TRIPLE x*FLOTTANT ;\n  FINP (3. * x) ;\n",
    )
    .unwrap();
    std::fs::write(dir.join("plain.dgibi"), "MESS 'inside' ;\n").unwrap();
    let out = ok(
        &dir,
        "lire 'PROC' 'lib.procedur' 'TRIPLE' ;
         si (neg (triple 2.) 6.) ; erre 5 ; finsi ;
         lire 'PROC' 'lib.procedur' ;
         si (neg (double 2.) 4.) ; erre 5 ; finsi ;
         lire 'PROC' 'plain.dgibi' 'SAYIT' ;
         sayit ;",
    );
    assert!(out.contains("inside"), "{}", out);
    let e = run(&dir, "lire 'PROC' 'lib.procedur' 'NONE' ;").unwrap_err();
    assert!(e.contains("has no procedure NONE"), "{}", e);
}

#[test]
fn sort_chai_writes_lines() {
    let dir = scratch("chai");
    // Two calls append to the file OPTI SORT names, which is kept as named;
    // numbers and words are shown as MESS shows them.
    ok(&dir, "opti sort 'out.txt' ; sort 'CHAI' 'a' 12 ; sort 'CHAI' 'b' 'c' ; opti sort 'other.txt' ;");
    let text = std::fs::read_to_string(dir.join("out.txt")).unwrap();
    assert_eq!(text, "a 12\nb c\n");
    // A new run starts the file again.
    ok(&dir, "opti sort 'out.txt' ; sort 'CHAI' 'z' ;");
    assert_eq!(std::fs::read_to_string(dir.join("out.txt")).unwrap(), "z\n");
    let e = run(&dir, "opti sort 'out.txt' ; sort 'CHAI' (prog 1.) ;").unwrap_err();
    assert!(e.contains("writes words and numbers, not a LISTREEL"), "{}", e);
}

#[test]
fn sort_mesh_then_lire_gives_back_named_meshes() {
    let dir = scratch("sort_mesh");
    // A 2 x 1 grid of QUA4 (6 nodes, area 2) and a named mesh of one of
    // its elements; after OUBL both come back from the file under their
    // names, on new nodes shared as before. The bottom line (SEG2, not
    // elements of the grid) and AUTRE are not written.
    let out = ok(
        &dir,
        "opti dime 2 elem qua4 ;
         bas = (0. 0.) d 2 (2. 0.) ;
         grille = bas tran 1 (0. 1.) ;
         un = grille elem 1 ;
         autre = (5. 5.) d 1 (6. 5.) ;
         opti sort 'maillage.txt' ;
         sort grille ;
         g0 = grille ; oubl grille ; oubl un ;
         opti lect 'maillage.txt' ;
         lire grille ;
         si ((nbno grille) neg 6) ; erre 5 ; finsi ;
         si ((nbel grille) neg 2) ; erre 5 ; finsi ;
         si ((abs ((mesu grille) - 2.)) > 1.e-12) ; erre 5 ; finsi ;
         si ((nbel un) neg 1) ; erre 5 ; finsi ;
         si ((nbno (grille et un)) neg 6) ; erre 5 ; finsi ;
         si ((nbno (grille et g0)) neg 12) ; erre 5 ; finsi ;
         mess 'relu' ;",
    );
    assert!(out.contains("relu"), "{}", out);
    let text = std::fs::read_to_string(dir.join("maillage.txt")).unwrap();
    assert!(
        text.contains("MESH GRILLE 1")
            && text.contains("MESH UN 1")
            && !text.contains("BAS")
            && !text.contains("AUTRE"),
        "{}",
        text
    );
    let e = run(&dir, "opti lect 'maillage.txt' ; lire truc ;").unwrap_err();
    assert!(e.contains("holds no mesh named TRUC"), "{}", e);
}
