//! Contact: JEU (the gap of conditions measured from the geometry) and
//! IMPO (node-to-facet unilateral contact conditions). The geometry lives
//! in `fem::contact`; this file reads arguments and builds the objects.

use super::bc::mult_node;
use super::mesh::req_geo;
use super::{dofs, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::contact::{self, Pair};
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Chpoint, Nature, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "IMPO",
        signature: "IMPO POINT|MAIL1 MAIL2 | IMPO 'MAIL' ('SYME'|'MESC'|'FAIB') MAIL1 MAIL2 | IMPO 'BLOC' MAIL3 | IMPO 'IMPA' 'MAIT' LINE1 'ESCL' LINE2|POINT | IMPO 'IMPA' LINKS (('HEMI' r|'PLAT' w|'CONE' w 'ANGL' deg) 'VECT' POINT)",
        doc: "Unilateral contact of the nodes of MAIL1 against the oriented SEG2 line (2D) or TRI3 surface (3D) MAIL2, \
              which they must stay on the right-hand side of (the side of the TRI3 normal in 3D; a QUA4 counts as two TRI3): one RELA 'MINI'-like \
              condition per node of MAIL1 that projects onto MAIL2, with the nearest facet. Returns the gap field \
              (as DEPI gives it) and the conditions. 'MAIL' gives the contact elements of MODE 'CONTACT' instead, both \
              ways by default ('SYME'; slave node then facet: TRI3 in 2D, TET4 in 3D), one way with 'MESC' (the nodes \
              of MAIL2 against MAIL1), segment against segment with 'FAIB' (2D, QUA4 elements); 'BLOC' gives the gap \
              and conditions of a strong contact mesh. Nodes that project onto no facet get no condition. \
              'IMPA' (2D, explicit dynamics): with 'MAIT' 'ESCL', every link that may come into play (a TRI3 slave \
              node then master segment, or a SEG2 master node then projectile point); on such links, the equality \
              conditions on the approach speed of the links in contact on the current geometry (slave nodes \
              behind a master segment, or master nodes inside the projectile's nose), a positive multiplier \
              pushing them apart; ANNULE (EXIS gives FAUX) when none is.",
        example: "jeu0 cont = impo haut_bas sol ; u = reso (k et cont) (f et jeu0) ;",
        f: impo,
    },
    OpDef {
        name: "JEU",
        signature: "JEU RIGIDITE",
        doc: "The limits (FLX, as DEPI gives them) that make the conditions of RIGIDITE measure from the current \
              geometry: minus each condition applied to the node coordinates (UX←x, UY←y, UZ←z; UR←r, UZ←z in AXIS). \
              Unknowns that are not translations count for 0.",
        example: "u = reso (k et r) (f et (jeu r)) ;",
        f: jeu,
    },
];

/// Coordinate index of a translation unknown in the current mode.
fn coord_index(it: &Interp, comp: &str) -> Option<usize> {
    dofs::translations(it).iter().position(|c| *c == comp)
}

/// `−Σ c·x` for every condition, as a DEPI field on its multiplier node.
fn gaps(it: &Interp, rig: &Rigidite) -> Chpoint {
    let mut out = Chpoint::new(Nature::Discret);
    for c in &rig.conds {
        let ax: f64 = c
            .terms
            .iter()
            .filter_map(|(n, comp, coef)| coord_index(it, comp).map(|k| coef * it.nodes.get(*n)[k]))
            .sum();
        // `+ 0.0` turns −0 into 0, so that LIST shows no "-0.00000E+00".
        out.add(c.mult_node, "FLX", -ax + 0.0, true);
    }
    out
}

fn jeu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let rig = a.req::<Rc<Rigidite>>()?;
    if rig.conds.is_empty() {
        return Err(a.err("this RIGIDITE holds no condition"));
    }
    Ok(vec![Value::Chpo(Rc::new(gaps(it, &rig)))])
}

/// The facet type of the space dimension: what the master side is made of.
fn facet_type(it: &Interp, a: &Args) -> Result<ElemType> {
    match it.opts.dime {
        2 => Ok(ElemType::Seg2),
        3 => Ok(ElemType::Tri3),
        d => Err(a.err(format!("contact needs OPTI DIME 2 (SEG2 lines) or 3 (TRI3 surfaces), not {}", d))),
    }
}

/// The first element type of `m` that is not `want`, if any.
fn other_type(m: &Mesh, want: &[ElemType]) -> Option<ElemType> {
    m.parts.iter().map(|p| p.ty).find(|t| !want.contains(t))
}

/// `DEP1 RIG1 = IMPO M1 M2`: node-to-facet contact, one way (the nodes of
/// M1 against the facets of M2; Cast3M's 'SYME' both ways is not offered:
/// swap the meshes and add the RIGIDITEs). Choices, where impo.notice
/// leaves them open:
/// * each node takes the facet it projects onto with the smallest |gap|,
///   so a closed master contour pairs a node with the near side, not the
///   far one; a node that projects onto no facet (beyond the line's ends,
///   or in the wedge outside a convex corner) gets **no condition**: a
///   condition on a facet it does not face would measure a wrong gap;
/// * no distance cut-off: far nodes get conditions that stay inactive;
/// * the weights and the normal are frozen at the current geometry (small
///   displacements, like every condition of gibi); DEP1 is JEU of RIG1;
/// * a facet with no length or area is an error, not skipped silently.
///
/// The contact mesh of 'MAIL' lists each pair as a simplex (slave node,
/// then the facet's nodes: TRI3 in 2D, TET4 in 3D), a shape gibi already
/// knows and draws; Cast3M has a contact element type of its own, so the
/// mesh serves 'BLOC' and pictures, not MODE.
fn impo(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let form = a.keyword(&["MAIL", "BLOC", "ACTI", "IMPA"]);
    if form == Some("IMPA") {
        return super::impact::impa(it, a);
    }
    if let Some(k @ "ACTI") = form {
        return Err(a.err(format!("the option '{}' is not supported", k)));
    }
    let ft = facet_type(it, a)?;
    if form == Some("MAIL") {
        return impo_mail(it, a, ft);
    }
    let pairs = if form == Some("BLOC") {
        let m = a.req::<Rc<Mesh>>()?;
        bloc_pairs(it, a, &m, ft)?
    } else {
        let slave = req_geo(a)?;
        let master = a.req::<Rc<Mesh>>()?;
        one_way(it, a, &slave, &master, ft, ["the first mesh", "the second mesh"])?
    };
    if pairs.is_empty() {
        // Legal (bodies far apart sideways) but nearly always a mistake in
        // the orientation or the order of the meshes: say so.
        it.println("IMPO: warning: no node of the slave side projects onto the master side: no contact condition");
    }
    let rig = conditions(it, &pairs, ft.dim() + 1);
    let gap = gaps(it, &rig);
    Ok(vec![Value::Chpo(Rc::new(gap)), Value::Rigi(Rc::new(rig))])
}

/// The nodes of `slave` against the facets of `master`, each node with the
/// facet it projects onto (see `impo`).
/// `names`: how the error messages call the slave and the master meshes.
fn one_way(it: &Interp, a: &Args, slave: &Mesh, master: &Mesh, ft: ElemType, names: [&str; 2]) -> Result<Vec<Pair>> {
    let dim = ft.dim() + 1;
    // In 3D a QUA4 of the master side counts as two TRI3 (a b c, a c d),
    // which keep its orientation: surfaces made by DALL or FACE are QUA4.
    let allowed: &[ElemType] = if dim == 3 { &[ElemType::Tri3, ElemType::Qua4] } else { &[ElemType::Seg2] };
    if let Some(t) = other_type(master, allowed) {
        return Err(a.err(format!(
            "{} (the master side) must be made of {} elements in {}D, found {}",
            names[1],
            if dim == 3 { "TRI3 or QUA4" } else { "SEG2" },
            dim,
            t.name()
        )));
    }
    if let Some(t) = slave.parts.iter().map(|p| p.ty).find(|t| t.dim() >= dim) {
        return Err(a.err(format!(
            "{} (the slave side) must be points, lines{} in {}D, found {}",
            names[0],
            if dim == 3 { " or surfaces" } else { "" },
            dim,
            t.name()
        )));
    }
    // Each facet with the number of the master element it comes from.
    let mut facets: Vec<Vec<usize>> = Vec::new();
    let mut elem_of: Vec<usize> = Vec::new();
    for (e, el) in master.parts.iter().flat_map(|p| p.elems()).enumerate() {
        match el {
            [a, b, c, d] => {
                facets.extend([vec![*a, *b, *c], vec![*a, *c, *d]]);
                elem_of.extend([e, e]);
            }
            _ => {
                facets.push(el.to_vec());
                elem_of.push(e);
            }
        }
    }
    let refs: Vec<&[usize]> = facets.iter().map(|f| f.as_slice()).collect();
    contact::pairs(&it.nodes.coords, &slave.node_list(), &refs)
        .map_err(|i| a.err(format!("element {} of the master side has no length or area", elem_of[i] + 1)))
}

/// `IMPO 'MAIL' ('SYME'|'MESC'|'FAIB') M1 M2`: the contact elements, as
/// Cast3M makes them (impo.notice):
/// * by default (and 'SYME') both ways: the nodes of M2 against the facets
///   of M1, then the nodes of M1 against the facets of M2;
/// * 'MESC' one way: the nodes of M2 against the facets of M1;
/// * 'FAIB' (2D): segment against segment, one condition per pair of
///   facing segments, imposed on average over their overlap
///   (`fem::contact_weak`).
///
/// A strong element is a simplex, slave node then facet (TRI3 in 2D, TET4
/// in 3D); a weak one a QUA4 of the two segments (a b of M1, c d of M2).
/// Only facing pairs are kept (the nearest facet a node projects onto;
/// segments that overlap): Cast3M keeps every pair within the optional
/// distance and sorts them at each step, gibi sorts them here, on the
/// geometry of the call (small displacements). A distance criterion given
/// after the meshes is read and, as every pair kept faces the other side,
/// has no further use.
fn impo_mail(it: &mut Interp, a: &mut Args, ft: ElemType) -> Result<Vec<Value>> {
    let way = a.keyword(&["SYME", "MESC", "FAIB"]).unwrap_or("SYME");
    let m1 = req_geo(a)?;
    let m2 = req_geo(a)?;
    let _criterion = a.opt_num();
    if way == "FAIB" {
        if ft != ElemType::Seg2 {
            return Err(a.err("the weak form 'FAIB' is available in 2D (SEG2 lines) only"));
        }
        let segs = |m: &Mesh, which: &str| -> Result<Vec<[usize; 2]>> {
            if let Some(t) = other_type(m, &[ElemType::Seg2]) {
                return Err(a.err(format!(
                    "'FAIB': the {} line must be made of SEG2 elements, found {}",
                    which,
                    t.name()
                )));
            }
            Ok(m.parts.iter().flat_map(|p| p.elems()).map(|e| [e[0], e[1]]).collect())
        };
        let (s1, s2) = (segs(&m1, "first")?, segs(&m2, "second")?);
        let pairs = crate::fem::contact_weak::pairs(&it.nodes.coords, &s1, &s2);
        if pairs.is_empty() {
            it.println("IMPO: warning: no segment of the two lines faces the other: no contact element");
        }
        let conn = pairs.iter().flat_map(|p| p.nodes).collect();
        return Ok(vec![Value::Mesh(Rc::new(Mesh::single(Part::with(ElemType::Qua4, conn))))]);
    }
    let mut pairs = one_way(it, a, &m2, &m1, ft, ["the second mesh", "the first mesh"])?;
    if way == "SYME" {
        // With matching meshes a node facing a node gives the same
        // condition both ways: both elements are kept (as Cast3M keeps
        // them; the facets of both sides then carry the contact pressure)
        // and the solver keeps one of each pair of equal rows active.
        pairs.extend(one_way(it, a, &m1, &m2, ft, ["the first mesh", "the second mesh"])?);
    }
    if pairs.is_empty() {
        it.println("IMPO: warning: no node of either side projects onto the other: no contact element");
    }
    let ty = if ft == ElemType::Seg2 { ElemType::Tri3 } else { ElemType::Tet4 };
    let conn = pairs.iter().flat_map(|p| std::iter::once(p.slave).chain(p.facet.iter().copied())).collect();
    Ok(vec![Value::Mesh(Rc::new(Mesh::single(Part::with(ty, conn))))])
}

/// The pairs a contact mesh (IMPO 'MAIL') stands for: slave node first,
/// then the facet. The pairing is kept as given, so a node that has slid
/// past its facet's end is held by the facet's nearest edge.
fn bloc_pairs(it: &Interp, a: &Args, m: &Mesh, ft: ElemType) -> Result<Vec<Pair>> {
    let ce = if ft == ElemType::Seg2 { ElemType::Tri3 } else { ElemType::Tet4 };
    if let Some(t) = other_type(m, &[ce]) {
        return Err(a.err(format!(
            "'BLOC' reads a contact mesh made by IMPO 'MAIL' ({} elements in {}D), found {}",
            ce.name(),
            ft.dim() + 1,
            t.name()
        )));
    }
    let mut out = Vec::new();
    for (e, el) in m.parts.iter().flat_map(|p| p.elems()).enumerate() {
        let p = contact::project(&it.nodes.coords, el[0], &el[1..], false)
            .map_err(|_| a.err(format!("contact element {}: its facet has no length or area", e + 1)))?;
        out.push(p);
    }
    Ok(out)
}

/// One unilateral condition `Σ c·u ≥ −g0` per pair, its multiplier node on
/// the slave node.
fn conditions(it: &mut Interp, pairs: &[Pair], ndim: usize) -> Rigidite {
    let names = dofs::translations(it);
    let mut rig = Rigidite::new(Subtype::Blocage);
    for p in pairs {
        let terms = p.terms(ndim).into_iter().map(|(n, k, c)| (n, names[k].to_string(), c)).collect();
        let m = mult_node(it, p.slave);
        rig.conds.push(CondRow::new(m, terms, Kind::Mini));
    }
    rig
}
