//! SORT 'MAT' assembles a RIGIDITE into a MatrixMarket file with a `.dofs`
//! companion; checked on two bars with a blocked end.

use gibi::solve::Kind;
use gibi::value::rigidity::{Block, CondRow, Rigidite, Subtype, Symmetry};
use gibi::{FilePolicy, Interpreter, Value};
use std::rc::Rc;

fn two_bars() -> Rigidite {
    let k = 1000.0;
    // One 2D bar element along x: only UX couples.
    let mut m = vec![0.0; 16];
    m[0] = k;
    m[2] = -k;
    m[8] = -k;
    m[10] = k;
    let dofs = vec![(0, "UX".to_string()), (0, "UY".to_string()), (1, "UX".to_string()), (1, "UY".to_string())];
    let block = Block {
        nodes_per_elem: 2,
        conn: vec![0, 1, 1, 2],
        duals: vec!["FX".into(), "FY".into(), "FX".into(), "FY".into()],
        dofs,
        mats: [m.clone(), m].concat(),
        symmetry: Symmetry::Symmetric,
    };
    let mut r = Rigidite::new(Subtype::Rigidite);
    r.blocks.push(block);
    r.conds.push(CondRow::new(3, vec![(0, "UX".into(), 1.0)], Kind::Equal));
    r.conds.push(CondRow::new(4, vec![(0, "UY".into(), 1.0)], Kind::Mini));
    r
}

#[test]
fn matrix_market_header_nnz_and_dofs() {
    let dir = std::env::temp_dir().join(format!("gibi_io_mtx_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.clone())).build();
    gibi.set("K", Value::Rigi(Rc::new(two_bars())));
    gibi.run_str("deck", "sort 'MAT' k 'mat/k.mtx' ;").unwrap_or_else(|e| panic!("{}", e.render()));

    let text = std::fs::read_to_string(dir.join("mat/k.mtx")).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("%%MatrixMarket matrix coordinate real general"));
    let body: Vec<&str> = lines.filter(|l| !l.starts_with('%')).collect();
    // 3 nodes × (UX, UY) + 2 multipliers; two 4×4 blocks sharing node 2's
    // 2×2 (16 + 16 − 4 = 28 entries, structural zeros kept) + 2 × 2 for the
    // conditions.
    assert_eq!(body[0], "8 8 32");
    assert_eq!(body.len(), 33);
    let entries: Vec<(usize, usize, f64)> = body[1..]
        .iter()
        .map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            (f[0].parse().unwrap(), f[1].parse().unwrap(), f[2].parse().unwrap())
        })
        .collect();
    let at = |i, j| entries.iter().find(|e| e.0 == i && e.1 == j).map(|e| e.2);
    assert_eq!(at(3, 3), Some(2000.0), "middle node UX gets both bars");
    assert_eq!(at(1, 5), None, "the two end nodes share no element");
    assert_eq!(at(2, 4), Some(0.0), "structural zeros of an element matrix stay");
    assert_eq!(at(7, 1), Some(1.0));
    assert_eq!(at(2, 8), Some(1.0));

    let dofs = std::fs::read_to_string(dir.join("mat/k.mtx.dofs")).unwrap();
    let rows: Vec<&str> = dofs.lines().skip(1).collect();
    assert_eq!(rows, vec!["1 1 UX", "2 1 UY", "3 2 UX", "4 2 UY", "5 3 UX", "6 3 UY", "7 4 LX EQUAL", "8 5 LX MINI"]);
}
