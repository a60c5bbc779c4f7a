//! TRAC and DESS draw SVG and PNG files with no display, and decks written
//! for Cast3M's graphics (device words, options) run unchanged.

use gibi::value::model::{Curve, Evolution};
use gibi::value::{Chpoint, Nature};
use gibi::{FilePolicy, Interpreter, Value};
use std::path::{Path, PathBuf};
use std::rc::Rc;

fn scratch(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gibi_io_plot_{}_{}", std::process::id(), test));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

const PLATE: &str = "opti dime 2 elem qua4 ; p1 = 0. 0. ; p2 = 2. 0. ; p3 = 2. 1. ; p4 = 0. 1. ; \
    s = dall (droi 8 p1 p2) (droi 4 p2 p3) (droi 8 p3 p4) (droi 4 p4 p1) ;";

fn session(dir: &Path) -> Interpreter {
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.to_path_buf())).build();
    run(&mut gibi, PLATE);
    // A bending-like displacement u = (-0.05 x y, 0.02 x²).
    let Some(Value::Mesh(s)) = gibi.get("S") else { panic!() };
    let entries: Vec<_> = s
        .node_list()
        .into_iter()
        .flat_map(|n| {
            let x = gibi.point_coords(&Value::Point(n)).unwrap();
            [(n, "UX", -0.05 * x[0] * x[1]), (n, "UY", 0.02 * x[0] * x[0])]
        })
        .collect();
    gibi.set("U", Value::Chpo(Rc::new(Chpoint::from_entries(Nature::Diffus, entries.iter().map(|e| (e.0, e.1, e.2))))));
    gibi
}

fn run(gibi: &mut Interpreter, deck: &str) {
    if let Err(e) = gibi.run_str("deck", deck) {
        panic!("{}", e.render());
    }
}

fn assert_svg(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {}", path.display(), e));
    assert!(text.starts_with("<svg") || text.starts_with("<?xml"), "{} starts {:?}", path.display(), &text[..20]);
    assert!(text.trim_end().ends_with("</svg>"));
    text
}

fn assert_png(path: &Path) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {}", path.display(), e));
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{}", path.display());
    assert!(bytes.len() > 5000, "{} is only {} bytes", path.display(), bytes.len());
}

#[test]
fn trac_of_meshes_and_fields_in_svg_then_png() {
    let dir = scratch("trac");
    let mut gibi = session(&dir);
    run(&mut gibi, "trac s ; trac 'PSC' (s et (s plus u)) 'TITR' 'deformed' ; trac (coor 1 s) s 'CACH' ;");
    let plain = assert_svg(&dir.join("gibi_trac_1.svg"));
    assert!(plain.matches("<polyline").count() + plain.matches("<path").count() >= 32, "one outline per element");
    assert!(assert_svg(&dir.join("gibi_trac_2.svg")).contains("deformed"));
    let field = assert_svg(&dir.join("gibi_trac_3.svg"));
    assert!(field.contains("SCAL") && field.contains("0.000e0") && field.contains("2.000e0"), "colour bar labels");
    run(&mut gibi, "opti trac 'PNG' ; trac u s ; opti trac X ; trac s ;");
    assert_png(&dir.join("gibi_trac_4.png"));
    assert_svg(&dir.join("gibi_trac_5.svg"));
    run(&mut gibi, "opti sort 'figs/plate' ; opti trac 'PNG' ; trac (s plus u) ;");
    assert_png(&dir.join("figs/plate.png"));
}

/// OPTI EPTR is the width of the drawn lines, OPTI FTRA names the picture
/// file (Cast3M's PostScript file: gibi writes the SVG beside its name).
#[test]
fn opti_eptr_and_ftra_shape_the_pictures() {
    let dir = scratch("eptr");
    let mut gibi = session(&dir);
    let l = "opti dime 2 ; q1 = 0. 0. ; q2 = 1. 0. ; l = droi 2 q1 q2 ;";
    run(&mut gibi, &format!("{} trac l ; opti eptr 5 ; trac l ;", l));
    let thin = assert_svg(&dir.join("gibi_trac_1.svg"));
    let thick = assert_svg(&dir.join("gibi_trac_2.svg"));
    assert!(thin.contains("stroke-width=\"2\"") && !thin.contains("stroke-width=\"5\""));
    assert!(thick.contains("stroke-width=\"5\""), "EPTR 5 draws 5-pixel lines");
    run(&mut gibi, "opti trac 'PSC' ftra 'figs/mesh.ps' ; trac l ;");
    assert!(assert_svg(&dir.join("figs/mesh.svg")).contains("stroke-width=\"5\""));
}

/// Decks draw arrows with `TRAC (VECT u ...) s`: the picture has the mesh
/// (gibi draws no arrows), and the deck goes on.
#[test]
fn trac_of_vect_draws_the_mesh() {
    let dir = scratch("vect");
    let mut gibi = session(&dir);
    run(&mut gibi, "v = vect u 10. 'UX' 'UY' 'ROUG' ; trac v s 'TITR' 'arrows' ; w = vect u ;");
    assert!(assert_svg(&dir.join("gibi_trac_1.svg")).contains("arrows"));
}

#[test]
fn trac_of_a_volume_mesh() {
    let dir = scratch("trac3d");
    let data = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/block_3d_v41.msh");
    std::fs::copy(data, dir.join("block.msh")).unwrap();
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.clone())).build();
    run(&mut gibi, "opti dime 3 ; t = lire 'GMSH' 'block.msh' ; opti trac 'PNG' ; trac (t . 'TOUT') ; trac (coor 3 (t . 'TOUT')) (t . 'TOUT') ;");
    assert_png(&dir.join("gibi_trac_1.png"));
    assert_png(&dir.join("gibi_trac_2.png"));
}

/// Quadratic volumes draw their skin: a block of two CU20 shows its 10
/// outer faces, the shared face hidden.
#[test]
fn trac_of_quadratic_volumes_draws_their_skin() {
    let dir = scratch("trac_quad3d");
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.clone())).build();
    let s = "p1 = 0. 0. 0. ; p2 = 2. 0. 0. ; p3 = 2. 1. 0. ; p4 = 0. 1. 0. ;";
    run(&mut gibi, &format!("opti dime 3 elem cu20 ; {} s = dall (droi 2 p1 p2) (droi 1 p2 p3) (droi 2 p3 p4) (droi 1 p4 p1) ; v = s volu tran 1 (0. 0. 1.) ; trac v ;", s));
    let cu20 = assert_svg(&dir.join("gibi_trac_1.svg"));
    assert_eq!(cu20.matches("<polygon").count() + cu20.matches("<path").count(), 10, "{}", cu20);
}

#[test]
fn dess_of_curves() {
    let dir = scratch("dess");
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.clone())).build();
    let x: Vec<f64> = (0..=20).map(|i| i as f64 * 0.05).collect();
    let curve = |legend: &str, f: fn(f64) -> f64| Curve {
        legend: legend.into(),
        x_name: "displacement".into(),
        y_name: "force".into(),
        x: x.clone(),
        y: x.iter().map(|&v| f(v)).collect(),
    };
    let ev = Evolution { curves: vec![curve("linear", |v| 3.0 * v), curve("contact", |v| (v - 0.4).max(0.0) * 10.0)] };
    gibi.set("EV", Value::Evol(Rc::new(ev)));
    run(&mut gibi, "titr 'load path' ; dess ev 'XBOR' 0. 1. 'LEGE' ; opti trac 'PNG' ; dess ev ;");
    let svg = assert_svg(&dir.join("gibi_trac_1.svg"));
    assert!(svg.contains("load path") && svg.contains("contact") && svg.contains("displacement"));
    assert_png(&dir.join("gibi_trac_2.png"));
}

#[test]
fn drawing_without_file_access_is_a_no_op_and_bad_calls_are_errors() {
    let mut gibi = Interpreter::new();
    run(&mut gibi, &format!("{} trac s ; trac 'X' s ;", PLATE));
    let e = gibi.run_str("e", "trac 'PSC' ;").unwrap_err().render();
    assert!(e.contains("TRAC: expected MAILLAGE, CHPOINT or MCHAML"), "{}", e);
    let e = gibi.run_str("e", "dess ;").unwrap_err().render();
    assert!(e.contains("DESS: expected EVOLUTIO"), "{}", e);
    // A field alone is drawn on its own nodes: no error either.
    run(&mut gibi, "trac (coor 1 s) ;");
}

#[test]
fn dess_of_curves_joined_with_et() {
    let dir = scratch("dess_et");
    let mut gibi = Interpreter::builder().files(FilePolicy::Under(dir.clone())).build();
    run(
        &mut gibi,
        "x = prog 0. 1. 2. ; ev1 = evol 'MANU' 'LEGE' 'first' 'time' x 'load' (prog 0. 1. 4.) ; \
         ev2 = evol 'MANU' 'LEGE' 'second' 'time' x 'load' (prog 0. 2. 1.) ; dess (ev1 et ev2) ;",
    );
    let svg = assert_svg(&dir.join("gibi_trac_1.svg"));
    assert!(svg.contains("first") && svg.contains("second"), "both legends are drawn");
}

#[test]
fn trac_draws_elements_in_their_colour() {
    let dir = scratch("coul");
    let mut gibi = session(&dir);
    run(&mut gibi, "trac ((s coul roug) et ((s plus (3. 0.)) coul vert)) ;");
    let svg = assert_svg(&dir.join("gibi_trac_1.svg"));
    // ROUG and VERT as fem::colour draws them, one stroke per element.
    assert_eq!(svg.matches("stroke=\"#DC0000\"").count(), 32, "red elements");
    assert_eq!(svg.matches("stroke=\"#00A000\"").count(), 32, "green elements");
}

/// `TRAC mo (vmis mo sig)`: each element coloured by its value (the mean
/// of its points), the model as support, a colour bar with the true
/// extremes. Objects TRAC cannot draw are errors, not a bare mesh.
#[test]
fn trac_of_an_element_field() {
    let dir = scratch("mchaml");
    let mut gibi = session(&dir);
    run(
        &mut gibi,
        "opti mode plan cont ; mo = mode s mecanique elastique isotrope ; ma = mate mo youn 1000. nu 0.3 ; \
         cl = (bloq 'DEPL' (s poin proc p1)) et (bloq 'UX' (s poin proc p4)) ; k = (rigi mo ma) et cl ; \
         u = reso k (forc 'FY' -1. p3) ; sig = sigm mo ma u ; vm = vmis mo sig ; trac mo vm ;",
    );
    let svg = assert_svg(&dir.join("gibi_trac_1.svg"));
    let vm: Rc<gibi::value::Mchaml> = gibi.get_as("VM").unwrap();
    let means: Vec<f64> =
        vm.zones[0].values.iter().map(|e| e.iter().map(|p| p[0]).sum::<f64>() / e.len() as f64).collect();
    let (lo, hi) = means.iter().fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    assert!(svg.contains("SCAL") && svg.contains(&format!("{:.3e}", hi)) && svg.contains(&format!("{:.3e}", lo)));
    let fills: Vec<&str> = svg.lines().filter(|l| l.starts_with("<polygon")).collect();
    assert_eq!(fills.len(), 32, "one filled polygon per element");
    let mut colours: Vec<&str> = fills.iter().filter_map(|l| l.split("fill=\"").nth(1)).collect();
    colours.sort();
    colours.dedup();
    assert!(colours.len() >= 10, "elements coloured by value: {:?}", colours);
    // Several components: the picture names the one drawn.
    run(&mut gibi, "trac sig mo ;");
    assert!(assert_svg(&dir.join("gibi_trac_2.svg")).contains("SMXX (+3 more)"));
    for (deck, want) in [
        ("trac k ;", "TRAC cannot draw a RIGIDITE"),
        ("trac (evol manu 'X' (prog 0. 1.) 'Y' (prog 0. 1.)) ;", "drawn by DESS"),
        ("trac mo vm sig ;", "one field at a time"),
        ("trac u s vm ;", "one field at a time"),
    ] {
        let e = gibi.run_str("e", deck).unwrap_err().render();
        assert!(e.contains(want), "{}: {}", deck, e);
    }
}

/// A field drawn on the mesh written before it (`TRAC s chpo`), or alone
/// on its own nodes as coloured dots.
#[test]
fn trac_of_a_field_after_its_mesh_or_alone() {
    let dir = scratch("field_forms");
    let mut gibi = session(&dir);
    run(&mut gibi, "trac s (exco u 'UX') ; trac (exco u 'UY') ;");
    let after = assert_svg(&dir.join("gibi_trac_1.svg"));
    assert!(after.contains("SCAL") && after.contains("-1.000e-1"), "the field's colour bar");
    let alone = assert_svg(&dir.join("gibi_trac_2.svg"));
    assert!(alone.contains("SCAL") && alone.matches("<circle").count() >= 45, "a dot at each of the field's nodes");
}
