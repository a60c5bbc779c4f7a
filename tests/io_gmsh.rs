//! Gmsh meshes written by Debian's gmsh 4.8 (tests/data/*.geo, committed
//! with the .msh files so these tests need no gmsh): both formats give the
//! same nodes, elements and physical groups, and LIRE 'GMSH' turns them
//! into a TABLE of MAILLAGE.

use gibi::fem::mesh::{ElemType, Mesh};
use gibi::io::gmsh::{self, GmshMesh};
use gibi::{FilePolicy, Interpreter, Value};
use std::path::PathBuf;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name)
}

fn read(name: &str) -> GmshMesh {
    gmsh::read(&data(name)).unwrap_or_else(|e| panic!("{}: {}", name, e))
}

/// (type, count) per part.
fn parts(m: &Mesh) -> Vec<(ElemType, usize)> {
    m.parts.iter().map(|p| (p.ty, p.len())).collect()
}

fn group(g: &GmshMesh, name: &str) -> Mesh {
    let p = g.groups.iter().find(|p| p.name.as_deref() == Some(name)).unwrap_or_else(|| panic!("no group {}", name));
    g.group_mesh(p.dim, p.tag)
}

#[test]
fn plate_quad4_both_formats() {
    for f in ["plate_quad4_v22.msh", "plate_quad4_v41.msh"] {
        let g = read(f);
        assert_eq!(g.coords.len(), 15, "{}", f);
        assert_eq!(parts(&g.all_mesh()), vec![(ElemType::Poi1, 1), (ElemType::Seg2, 6), (ElemType::Qua4, 8)], "{}", f);
        assert_eq!(parts(&group(&g, "PLATE")), vec![(ElemType::Qua4, 8)]);
        assert_eq!(parts(&group(&g, "BOTTOM")), vec![(ElemType::Seg2, 4)]);
        assert_eq!(parts(&group(&g, "LEFT")), vec![(ElemType::Seg2, 2)]);
        let corner = group(&g, "CORNER");
        assert_eq!(g.coords[corner.parts[0].conn[0]], [2.0, 1.0, 0.0]);
        // Every BOTTOM node lies on y = 0.
        assert!(group(&g, "BOTTOM").node_list().iter().all(|&n| g.coords[n][1] == 0.0));
    }
}

/// Mid-side nodes sit between the corners gibi's order puts them between.
fn check_midsides(g: &GmshMesh) {
    for p in &g.all_mesh().parts {
        let ring: &[usize] = match p.ty {
            ElemType::Seg3 => &[0, 1, 2],
            ElemType::Tri6 => &[0, 1, 2, 3, 4, 5, 0],
            ElemType::Qua8 => &[0, 1, 2, 3, 4, 5, 6, 7, 0],
            _ => continue,
        };
        for e in p.elems() {
            for w in ring.windows(3).step_by(2) {
                let (a, m, b) = (g.coords[e[w[0]]], g.coords[e[w[1]]], g.coords[e[w[2]]]);
                for k in 0..3 {
                    assert!((0.5 * (a[k] + b[k]) - m[k]).abs() < 1e-9, "{:?} element {:?}", p.ty, e);
                }
            }
        }
    }
}

#[test]
fn quadratic_elements_take_gibi_node_order() {
    for f in ["plate_tri6_v22.msh", "plate_tri6_v41.msh"] {
        let g = read(f);
        assert_eq!(g.coords.len(), 15);
        assert_eq!(parts(&group(&g, "PLATE")), vec![(ElemType::Tri6, 4)]);
        assert_eq!(parts(&group(&g, "BOTTOM")), vec![(ElemType::Seg3, 2)]);
        check_midsides(&g);
    }
    let g = read("plate_quad8_v41.msh");
    assert_eq!(g.coords.len(), 13);
    assert_eq!(parts(&group(&g, "PLATE")), vec![(ElemType::Qua8, 2)]);
    assert_eq!(parts(&group(&g, "TOP")), vec![(ElemType::Seg3, 2)]);
    check_midsides(&g);
}

#[test]
fn volumes_hexahedra_prisms_tetrahedra() {
    for f in ["block_3d_v22.msh", "block_3d_v41.msh"] {
        let g = read(f);
        assert_eq!(g.coords.len(), 39);
        assert_eq!(parts(&group(&g, "HEXA")), vec![(ElemType::Cub8, 8)]);
        assert_eq!(parts(&group(&g, "PRISM")), vec![(ElemType::Pri6, 12)]);
        let mut base = parts(&group(&g, "BASE"));
        base.sort();
        assert_eq!(base, vec![(ElemType::Tri3, 6), (ElemType::Qua4, 4)]);
        assert!(group(&g, "BASE").node_list().iter().all(|&n| g.coords[n][2] == 0.0));
    }
    let g = read("cube_tet_v41.msh");
    assert_eq!(g.coords.len(), 45);
    assert_eq!(parts(&group(&g, "CUBE")), vec![(ElemType::Tet4, 101)]);
    assert_eq!(parts(&group(&g, "BOTTOM")), vec![(ElemType::Tri3, 14)]);
}

#[test]
fn malformed_files_name_the_line() {
    let bad = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 0 x 0\n$EndNodes\n";
    assert_eq!(gmsh::parse(bad).unwrap_err().0, "line 7: expected a coordinate, found other text (1 character)");
    let missing = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n1 1 2 0 1 1 2\n$EndElements\n";
    assert_eq!(gmsh::parse(missing).unwrap_err().0, "line 10: element uses node 2, which $Nodes does not define");
    let pyramid = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Elements\n1\n1 7 0 1 2 3 4 5\n$EndElements\n";
    assert!(gmsh::parse(pyramid).unwrap_err().0.starts_with("line 6: Gmsh element type 7 (5-node pyramid)"));
    assert!(gmsh::parse("$MeshFormat\n4.1 1 8\n").unwrap_err().0.contains("binary"));
    assert!(gmsh::parse("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2\n").unwrap_err().0.contains("end of file"));
    assert!(gmsh::parse("hello").unwrap_err().0.contains("$MeshFormat"));
    assert!(gmsh::parse("").is_err());
}

fn run(deck: &str) -> Interpreter {
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(data(""))).build();
    if let Err(e) = gibi.run_str("deck", deck) {
        panic!("{}", e.render());
    }
    gibi
}

#[test]
fn lire_gmsh_returns_a_table_of_meshes() {
    let gibi = run("opti dime 2 ; t = lire 'GMSH' 'plate_quad4_v41.msh' ; \
         np = nbno (t . 'PLATE') ; ne = nbel (t . 'PLATE') ; nb = nbel (t . 'BOTTOM') ; \
         nt = nbel (t . 'TOUT') ; p = (t . 'CORNER') poin 1 ; x y = coor p ;");
    assert_eq!(gibi.get_f64("NP"), Some(15.0));
    assert_eq!(gibi.get_f64("NE"), Some(8.0));
    assert_eq!(gibi.get_f64("NB"), Some(4.0));
    assert_eq!(gibi.get_f64("NT"), Some(15.0));
    assert_eq!((gibi.get_f64("X"), gibi.get_f64("Y")), (Some(2.0), Some(1.0)));
    assert!(matches!(gibi.get("T"), Some(Value::Table(_))));
}

#[test]
fn lire_gmsh_refuses_depth_in_two_dimensions() {
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(data(""))).build();
    let e = gibi.run_str("deck", "opti dime 2 ; t = lire 'GMSH' 'block_3d_v41.msh' ;").unwrap_err();
    assert!(e.render().contains("has z = 1 but OPTI DIME is 2"), "{}", e.render());
    let e = gibi.run_str("deck", "t = lire 'GMSH' 'nowhere.msh' ;").unwrap_err();
    assert!(e.render().contains("cannot read"), "{}", e.render());
}

#[test]
fn truncated_or_garbled_files_never_panic() {
    for f in ["plate_quad4_v22.msh", "plate_tri6_v41.msh", "block_3d_v41.msh"] {
        let text = std::fs::read_to_string(data(f)).unwrap();
        for cut in (0..text.len()).step_by(7) {
            let _ = gmsh::parse(&text[..cut]);
        }
        // Replace one token at a time by something out of place.
        let words: Vec<&str> = text.split_whitespace().collect();
        for i in (0..words.len()).step_by(5) {
            for bad in ["-1", "99999", "$Nodes", "1e400"] {
                let mut w = words.clone();
                w[i] = bad;
                let _ = gmsh::parse(&w.join("\n"));
            }
        }
    }
}
