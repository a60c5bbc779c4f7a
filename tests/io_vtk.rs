//! SORT 'VTK' writes ParaView files that read back as written: parsed here
//! with quick-xml, arrays decoded from base64.

use base64::Engine;
use gibi::fem::mesh::Mesh;
use gibi::io::vtk::Grid;
use gibi::value::model::{Mchaml, MchamlZone};
use gibi::value::{Chpoint, Nature};
use gibi::{FilePolicy, Interpreter, Value};
use quick_xml::events::Event;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

/// A fresh directory for one test's files.
fn scratch(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gibi_io_vtk_{}_{}", std::process::id(), test));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// An XML element: tag, attributes, text.
#[derive(Debug)]
struct El {
    tag: String,
    attrs: HashMap<String, String>,
    text: String,
}

fn parse(path: &Path) -> Vec<El> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {}", path.display(), e));
    let mut r = quick_xml::Reader::from_str(&text);
    let mut out: Vec<El> = Vec::new();
    loop {
        match r.read_event().expect("well-formed XML") {
            Event::Start(e) | Event::Empty(e) => {
                let attrs = e
                    .attributes()
                    .map(|a| {
                        let a = a.unwrap();
                        let k = String::from_utf8_lossy(a.key.as_ref()).to_string();
                        (k, String::from_utf8_lossy(&a.value).to_string())
                    })
                    .collect();
                out.push(El {
                    tag: String::from_utf8_lossy(e.name().as_ref()).to_string(),
                    attrs,
                    text: String::new(),
                });
            }
            Event::Text(t) => {
                if let Some(last) = out.last_mut() {
                    last.text.push_str(String::from_utf8_lossy(&t).trim());
                }
            }
            Event::Eof => break,
            _ => {}
        }
    }
    out
}

/// The values of a binary Float64 DataArray (UInt64 byte-count header).
fn floats(el: &El) -> Vec<f64> {
    let bytes = base64::engine::general_purpose::STANDARD.decode(&el.text).unwrap();
    let n = u64::from_le_bytes(bytes[..8].try_into().unwrap()) as usize;
    assert_eq!(n, bytes.len() - 8, "byte count header of {:?}", el.attrs.get("Name"));
    bytes[8..].chunks(8).map(|c| f64::from_le_bytes(c.try_into().unwrap())).collect()
}

fn array<'a>(els: &'a [El], name: &str) -> &'a El {
    els.iter()
        .find(|e| e.tag == "DataArray" && e.attrs.get("Name").map(String::as_str) == Some(name))
        .unwrap_or_else(|| panic!("no DataArray {}", name))
}

fn piece(els: &[El]) -> (usize, usize) {
    let p = els.iter().find(|e| e.tag == "Piece").unwrap();
    (p.attrs["NumberOfPoints"].parse().unwrap(), p.attrs["NumberOfCells"].parse().unwrap())
}

const PLATE: &str = "opti dime 2 elem qua4 ; p1 = 0. 0. ; p2 = 2. 0. ; p3 = 2. 1. ; p4 = 0. 1. ; \
    s = dall (droi 4 p1 p2) (droi 2 p2 p3) (droi 4 p3 p4) (droi 2 p4 p1) ;";

/// A 2D plate, a displacement field u = (0.1 x, -0.2 y) and a constant
/// two-component element field, bound as S, U and SIG.
fn plate(dir: &Path) -> (Interpreter, Rc<Mesh>) {
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.to_path_buf())).build();
    gibi.run_str("plate", PLATE).unwrap();
    let Some(Value::Mesh(s)) = gibi.get("S") else { panic!("S is not a mesh") };
    let nodes = s.node_list();
    let xy: Vec<[f64; 3]> = nodes.iter().map(|&n| gibi.point_coords(&Value::Point(n)).unwrap()).collect();
    let entries = nodes.iter().zip(&xy).flat_map(|(&n, x)| [(n, "UX", 0.1 * x[0]), (n, "UY", -0.2 * x[1])]);
    gibi.set("U", Value::Chpo(Rc::new(Chpoint::from_entries(Nature::Diffus, entries))));
    let ne = s.n_elements();
    let zone = MchamlZone {
        mesh: (*s).clone(),
        element: "QUA4".into(),
        comps: vec!["SMXX".into(), "SMYY".into()],
        values: (0..ne).map(|e| vec![vec![e as f64, 1.0], vec![e as f64 + 2.0, 3.0]]).collect(),
        ..Default::default()
    };
    gibi.set("SIG", Value::Mchaml(Rc::new(Mchaml { subtype: "CONTRAINTES".into(), zones: vec![zone] })));
    (gibi, s)
}

#[test]
fn point_vectors_and_cell_averages_read_back() {
    let dir = scratch("fields");
    let (mut gibi, s) = plate(&dir);
    gibi.run_str("sort", "opti sort 'out/plate' ; sort 'VTK' s u 'DEPL' sig 'SIGMA' (coor 1 s) 'X' ;").unwrap();
    let els = parse(&dir.join("out/plate.vtu"));
    assert_eq!(els[0].tag, "VTKFile");
    assert_eq!(els[0].attrs["type"], "UnstructuredGrid");
    assert_eq!(piece(&els), (15, 8));
    assert_eq!(s.node_list().len(), 15);

    let depl = array(&els, "DEPL");
    assert_eq!(depl.attrs["NumberOfComponents"], "3");
    assert_eq!((depl.attrs["ComponentName0"].as_str(), depl.attrs["ComponentName2"].as_str()), ("UX", "UZ"));
    let points = floats(array(&els, "Points"));
    let u = floats(depl);
    assert_eq!(u.len(), 45);
    for k in 0..15 {
        let (x, y) = (points[3 * k], points[3 * k + 1]);
        assert!((u[3 * k] - 0.1 * x).abs() < 1e-12 && (u[3 * k + 1] + 0.2 * y).abs() < 1e-12);
        assert_eq!(u[3 * k + 2], 0.0, "UZ is written 0 in 2D so Warp By Vector works");
    }
    let xs = floats(array(&els, "X"));
    assert_eq!(array(&els, "X").attrs["NumberOfComponents"], "1");
    assert!(xs.iter().zip(points.chunks(3)).all(|(v, p)| (v - p[0]).abs() < 1e-12));

    let sig = array(&els, "SIGMA");
    assert_eq!(sig.attrs["NumberOfComponents"], "2");
    let v = floats(sig);
    assert_eq!(v.len(), 16);
    for e in 0..8 {
        assert_eq!((v[2 * e], v[2 * e + 1]), (e as f64 + 1.0, 2.0), "per-element average of element {}", e);
    }
    // Cells: 8 QUA4 (VTK type 9), offsets 4, 8, …
    let types = base64::engine::general_purpose::STANDARD.decode(&array(&els, "types").text).unwrap();
    assert_eq!(&types[8..], &[9u8; 8]);
}

#[test]
fn repeated_sort_with_time_writes_a_pvd_collection() {
    let dir = scratch("pvd");
    let (mut gibi, _) = plate(&dir);
    let deck = "opti sort 'res/run' ; sort 'VTK' s u 'U' 'TEMPS' 0.5 ; sort 'VTK' s u 'U' 'TEMPS' 1.25 ;";
    gibi.run_str("sort", deck).unwrap();
    for f in ["res/run_0000.vtu", "res/run_0001.vtu"] {
        assert_eq!(piece(&parse(&dir.join(f))), (15, 8), "{}", f);
    }
    let pvd = parse(&dir.join("res/run.pvd"));
    let sets: Vec<(f64, &str)> = pvd
        .iter()
        .filter(|e| e.tag == "DataSet")
        .map(|e| (e.attrs["timestep"].parse().unwrap(), e.attrs["file"].as_str()))
        .collect();
    assert_eq!(sets, vec![(0.5, "run_0000.vtu"), (1.25, "run_0001.vtu")]);
    // A new OPTI SORT name starts a new collection.
    gibi.run_str("sort2", "opti sort 'res/other' ; sort 'VTK' s 'TEMPS' 3. ;").unwrap();
    let pvd = parse(&dir.join("res/other.pvd"));
    assert_eq!(pvd.iter().filter(|e| e.tag == "DataSet").count(), 1);
}

#[test]
fn contact_results_are_point_fields() {
    let dir = scratch("contact");
    let (_gibi, s) = plate(&dir);
    let mut nodes = gibi::fem::mesh::Nodes::default();
    for _ in 0..20 {
        nodes.push([0.0; 3], 1.0);
    }
    let mut grid = Grid::new(&s, &nodes).unwrap();
    let bottom: Vec<usize> = s.node_list().into_iter().take(3).collect();
    grid.add_contact(&bottom, &[true, false, true], &[0.0, 0.01, 0.0], &[5.0, 0.0, 2.0]).unwrap();
    assert!(grid.add_contact(&bottom, &[true], &[0.0], &[1.0]).is_err());
    let path = dir.join("contact.vtu");
    grid.write(&path).unwrap();
    let els = parse(&path);
    let st = floats(array(&els, "contact_status"));
    assert_eq!(&st[..3], &[1.0, 0.0, 1.0]);
    assert!(st[3].is_nan(), "no condition on the other nodes");
    assert_eq!(&floats(array(&els, "contact_pressure"))[..3], &[5.0, 0.0, 2.0]);
    assert_eq!(&floats(array(&els, "contact_gap"))[..3], &[0.0, 0.01, 0.0]);
}

#[test]
fn sort_errors_are_worded() {
    let dir = scratch("errors");
    let (mut gibi, _) = plate(&dir);
    let e = gibi.run_str("e1", "sort 'VTK' u 'U' ;").unwrap_err().render();
    assert!(e.contains("SORT: expected MAILLAGE"), "{}", e);
    let e = gibi.run_str("e2", "sort 'VTK' s 'NAME' ;").unwrap_err().render();
    assert!(e.contains("follows no CHPOINT or MCHAML"), "{}", e);
    let e = gibi.run_str("e3", "sort 'XYZ' s ;").unwrap_err().render();
    assert!(e.contains("expected one of VTK MAT"), "{}", e);
    // Without file access the host's policy speaks.
    let mut closed = Interpreter::new();
    closed.run_str("p", PLATE).unwrap();
    let e = closed.run_str("e4", "sort 'VTK' s ;").unwrap_err().render();
    assert!(e.contains("not allowed by the host"), "{}", e);
}

#[test]
fn gmsh_volumes_and_quadratic_surfaces_export() {
    let dir = scratch("gmsh");
    let data = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    for (f, dime, cells, types) in [
        ("block_3d_v41.msh", 3, 30, vec![9u8, 5, 12, 13]),
        ("plate_tri6_v41.msh", 2, 6, vec![21, 22]),
        ("plate_quad8_v41.msh", 2, 4, vec![21, 23]),
    ] {
        std::fs::copy(data.join(f), dir.join(f)).unwrap();
        let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.clone())).build();
        let deck =
            format!("opti dime {} ; t = lire 'GMSH' '{}' ; opti sort '{}' ; sort 'VTK' (t . 'TOUT') ;", dime, f, f);
        gibi.run_str("deck", &deck).unwrap_or_else(|e| panic!("{}", e.render()));
        let els = parse(&dir.join(format!("{}.vtu", f)));
        assert_eq!(piece(&els).1, cells, "{}", f);
        let mut t = base64::engine::general_purpose::STANDARD.decode(&array(&els, "types").text).unwrap()[8..].to_vec();
        t.dedup();
        assert_eq!(t, types, "{}", f);
    }
}

/// `SORT 'VTK'` of a PASAPAS table: one .pvd with every saved step at its
/// time, each with the displacements, stresses and contact fields of that
/// step (a block through a gap onto a support: open, then closed).
#[test]
fn pasapas_table_writes_every_saved_step() {
    let dir = scratch("pasapas");
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.clone())).build();
    let deck = "opti dime 2 elem qua4 mode plan cont echo 0 ;
        bas = (0. 1.e-3) droi 2 (1. 1.e-3) ; blk = bas tran 2 (0. 1.) ; haut = blk cote 3 ;
        sup = (2. 0.) droi 3 (-1. 0.) ;
        mo = (mode blk mecanique elastique) et (mode (impo 'MAIL' bas sup) 'CONTACT') ;
        clh = bloq haut 'UY' ;
        t = tabl ; t . 'MODELE' = mo ; t . 'CARACTERISTIQUES' = mate mo 'YOUN' 1.e3 'NU' 0.2 ;
        t . 'BLOCAGES_MECANIQUES' = (bloq sup 'DEPL') et clh et (bloq (blk cote 4) 'UX') ;
        t . 'CHARGEMENT' = char 'DIMP' (depi clh -2.e-3) (evol manu (prog 0. 1.) (prog 0. 1.)) ;
        t . 'TEMPS_CALCULES' = prog 0.25 0.5 0.75 1. ; t . 'TEMPS_SAUVES' = prog 0.25 1. ;
        pasapas t ;
        opti sort 'res/steps' ; sort 'VTK' t ;";
    gibi.run_str("pasapas", deck).unwrap();
    let pvd = parse(&dir.join("res/steps.pvd"));
    let sets: Vec<(f64, &str)> = pvd
        .iter()
        .filter(|e| e.tag == "DataSet")
        .map(|e| (e.attrs["timestep"].parse().unwrap(), e.attrs["file"].as_str()))
        .collect();
    assert_eq!(sets, vec![(0.0, "steps_0000.vtu"), (0.25, "steps_0001.vtu"), (1.0, "steps_0002.vtu")]);
    // The block's 9 nodes and 4 elements (the support is no cell).
    let last = parse(&dir.join("res/steps_0002.vtu"));
    assert_eq!(piece(&last), (9, 4));
    // Pushed by 2e-3 through a 1e-3 gap: the bottom is at -1e-3, the
    // stress uniform, -E 1e-3 / 1, and so is the pressure on the bottom.
    let depl = floats(array(&last, "DEPL"));
    let uy_min = depl.chunks(3).map(|v| v[1]).fold(f64::INFINITY, f64::min);
    assert!((uy_min + 2.0e-3).abs() < 1e-12, "{uy_min}");
    // SIGMA: SMXX SMYY SMZZ SMXY per cell.
    let sig = floats(array(&last, "SIGMA"));
    assert_eq!(sig.len(), 16);
    assert!(sig.chunks(4).all(|s| (s[1] + 1.0).abs() < 1e-9 && s[0].abs() < 1e-9), "{sig:?}");
    let st = floats(array(&last, "contact_status"));
    assert_eq!(st.iter().filter(|s| **s == 1.0).count(), 3, "{st:?}");
    let p = floats(array(&last, "contact_pressure"));
    assert!(p.iter().filter(|v| !v.is_nan()).all(|v| (v - 1.0).abs() < 1e-9), "{p:?}");
    let open = parse(&dir.join("res/steps_0001.vtu"));
    assert!(floats(array(&open, "contact_status")).iter().all(|s| s.is_nan() || *s == 0.0));
}
