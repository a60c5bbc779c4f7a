//! Nodes and meshes as plain data.
//!
//! Cast3M keeps one global table of nodes: a POINT object *is* a node, and
//! meshes list node numbers. Two meshes that share a point share the node,
//! which is how `ET` glues parts together and how conditions reach the
//! unknowns of a structure. We keep the same model: [`Nodes`] is the table
//! (owned by the interpreter's store), [`Mesh`] holds connectivity only.

pub use super::colour::Colour;
use std::collections::HashSet;

/// Element geometries known to the mesher and the element library.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ElemType {
    Poi1,
    Seg2,
    Seg3,
    Tri3,
    Tri6,
    Qua4,
    Qua8,
    Cub8,
    Tet4,
    Pri6,
    /// Pyramid: its base quadrangle, then its apex (VOLU puts them on the
    /// quadrangles of a closed surface).
    Pyr5,
    /// Quadratic volumes: nodes of the bottom face around its contour
    /// (as QUA8/TRI6), then the mid-height nodes of the vertical edges
    /// (under each bottom corner in turn), then the top face as the bottom.
    Cu20,
    Pr15,
    /// Joint elements (RACC, LIAI): the nodes of a face on side 1, then
    /// the facing nodes of side 2 in the same order.
    Rac2,
    Rac3,
    Lia3,
    Lia4,
    /// Relation elements (Cast3M's MULT, made by RAFF): a hanging node,
    /// then the nodes of the coarser side it lies on: a SEG2 (`Mult3`), a
    /// SEG3 (`Mult4`) or a QUA4 face (`Mult5`). They carry no mechanics:
    /// MODE keeps them aside and RELA of the model ties the hanging node
    /// to that side. Not in `ALL`: they have no reference element.
    Mult3,
    Mult4,
    Mult5,
}

impl ElemType {
    /// Every geometry, in Cast3M's usual listing order.
    pub const ALL: [ElemType; 17] = [
        ElemType::Poi1,
        ElemType::Seg2,
        ElemType::Seg3,
        ElemType::Tri3,
        ElemType::Tri6,
        ElemType::Qua4,
        ElemType::Qua8,
        ElemType::Cub8,
        ElemType::Tet4,
        ElemType::Pri6,
        ElemType::Pyr5,
        ElemType::Cu20,
        ElemType::Pr15,
        ElemType::Rac2,
        ElemType::Rac3,
        ElemType::Lia3,
        ElemType::Lia4,
    ];

    /// Number of nodes of one element.
    pub fn nodes(self) -> usize {
        match self {
            ElemType::Poi1 => 1,
            ElemType::Seg2 => 2,
            ElemType::Seg3 => 3,
            ElemType::Tri3 => 3,
            ElemType::Tri6 => 6,
            ElemType::Qua4 => 4,
            ElemType::Qua8 => 8,
            ElemType::Cub8 => 8,
            ElemType::Tet4 => 4,
            ElemType::Pri6 => 6,
            ElemType::Pyr5 => 5,
            ElemType::Cu20 => 20,
            ElemType::Pr15 => 15,
            ElemType::Rac2 => 4,
            ElemType::Rac3 | ElemType::Lia3 => 6,
            ElemType::Lia4 => 8,
            ElemType::Mult3 => 3,
            ElemType::Mult4 => 4,
            ElemType::Mult5 => 5,
        }
    }

    /// Topological dimension (0 point, 1 line, 2 surface, 3 volume).
    pub fn dim(self) -> usize {
        match self {
            ElemType::Poi1 | ElemType::Mult3 | ElemType::Mult4 | ElemType::Mult5 => 0,
            ElemType::Seg2 | ElemType::Seg3 | ElemType::Rac2 | ElemType::Rac3 => 1,
            ElemType::Tri3 | ElemType::Tri6 | ElemType::Qua4 | ElemType::Qua8 | ElemType::Lia3 | ElemType::Lia4 => 2,
            ElemType::Cub8 | ElemType::Tet4 | ElemType::Pri6 | ElemType::Pyr5 | ElemType::Cu20 | ElemType::Pr15 => 3,
        }
    }

    /// Cast3M's 4-letter name.
    pub fn name(self) -> &'static str {
        match self {
            ElemType::Poi1 => "POI1",
            ElemType::Seg2 => "SEG2",
            ElemType::Seg3 => "SEG3",
            ElemType::Tri3 => "TRI3",
            ElemType::Tri6 => "TRI6",
            ElemType::Qua4 => "QUA4",
            ElemType::Qua8 => "QUA8",
            ElemType::Cub8 => "CUB8",
            ElemType::Tet4 => "TET4",
            ElemType::Pri6 => "PRI6",
            ElemType::Pyr5 => "PYR5",
            ElemType::Cu20 => "CU20",
            ElemType::Pr15 => "PR15",
            ElemType::Rac2 => "RAC2",
            ElemType::Rac3 => "RAC3",
            ElemType::Lia3 => "LIA3",
            ElemType::Lia4 => "LIA4",
            ElemType::Mult3 | ElemType::Mult4 | ElemType::Mult5 => "MULT",
        }
    }

    /// The face geometry of one side of a joint element.
    pub fn joint_face(self) -> Option<ElemType> {
        match self {
            ElemType::Rac2 => Some(ElemType::Seg2),
            ElemType::Rac3 => Some(ElemType::Seg3),
            ElemType::Lia3 => Some(ElemType::Tri3),
            ElemType::Lia4 => Some(ElemType::Qua4),
            _ => None,
        }
    }

    /// Parse a Cast3M element name (exact 4 letters).
    /// The side a relation element's hanging node lies on.
    pub fn tie_side(self) -> Option<ElemType> {
        match self {
            ElemType::Mult3 => Some(ElemType::Seg2),
            ElemType::Mult4 => Some(ElemType::Seg3),
            ElemType::Mult5 => Some(ElemType::Qua4),
            _ => None,
        }
    }

    pub fn from_name(s: &str) -> Option<ElemType> {
        ElemType::ALL.into_iter().find(|t| t.name() == s)
    }
}

/// The global node table. Coordinates are always stored in 3D; the unused
/// ones are 0. The last field is the local density (`OPTI DENS`), which
/// Cast3M stores with every point and DROI uses to grade meshes.
#[derive(Debug, Clone, Default)]
pub struct Nodes {
    pub coords: Vec<[f64; 3]>,
    pub density: Vec<f64>,
    /// The numbers shown for the nodes (TASS renumbers).
    pub numbering: super::node_numbering::NodeNumbering,
}

impl Nodes {
    /// Add a node and return its number.
    pub fn push(&mut self, x: [f64; 3], density: f64) -> usize {
        self.coords.push(x);
        self.density.push(density);
        self.coords.len() - 1
    }

    pub fn len(&self) -> usize {
        self.coords.len()
    }

    pub fn is_empty(&self) -> bool {
        self.coords.is_empty()
    }

    pub fn get(&self, i: usize) -> [f64; 3] {
        self.coords[i]
    }
}

/// Elements of one geometry and one colour, connectivity stored flat
/// (`conn[e * ty.nodes() + k]` is node k of element e).
#[derive(Debug, Clone)]
pub struct Part {
    pub ty: ElemType,
    pub conn: Vec<usize>,
    /// The colour of these elements (COUL); operators that build new
    /// elements give the default colour, those that copy elements keep it.
    pub colour: Colour,
}

/// The same elements are the same part whatever their colour: a model
/// finds its material by its mesh, and colouring a mesh for a picture
/// must not change the mechanics.
/// The connectivity of the elements of `p` not yet in `mesh`. A
/// procedure that grows a mesh one element at a time (`m = m ET e` in a
/// loop) would hash the whole mesh at every step: a few elements are
/// looked for by comparison instead, many through a set of the mesh's.
fn new_elements(mesh: &Mesh, p: &Part) -> Vec<usize> {
    let n = p.ty.nodes();
    let same = || mesh.parts.iter().filter(|q| q.ty == p.ty).flat_map(|q| q.conn.chunks(n));
    if p.len() <= 8 {
        let mut new: Vec<usize> = Vec::with_capacity(p.conn.len());
        let mut present = vec![false; p.len()];
        for e in same() {
            for (k, f) in p.conn.chunks(n).enumerate() {
                // The first node settles almost every comparison.
                if !present[k] && e[0] == f[0] && e == f {
                    present[k] = true;
                }
            }
        }
        for (f, _) in p.conn.chunks(n).zip(&present).filter(|(_, here)| !**here) {
            new.extend_from_slice(f);
        }
        return new;
    }
    let existing: rustc_hash::FxHashSet<&[usize]> = same().collect();
    p.conn.chunks(n).filter(|e| !existing.contains(e)).flatten().copied().collect()
}

impl PartialEq for Part {
    fn eq(&self, other: &Part) -> bool {
        self.ty == other.ty && self.conn == other.conn
    }
}

impl Part {
    pub fn new(ty: ElemType) -> Self {
        Part::with(ty, Vec::new())
    }

    /// A part of the default colour.
    pub fn with(ty: ElemType, conn: Vec<usize>) -> Self {
        Part { ty, conn, colour: Colour::default() }
    }

    pub fn len(&self) -> usize {
        self.conn.len() / self.ty.nodes()
    }

    pub fn is_empty(&self) -> bool {
        self.conn.is_empty()
    }

    pub fn elem(&self, e: usize) -> &[usize] {
        let n = self.ty.nodes();
        &self.conn[e * n..(e + 1) * n]
    }

    pub fn elems(&self) -> impl Iterator<Item = &[usize]> {
        self.conn.chunks(self.ty.nodes())
    }
}

/// A mesh: one or more parts, each of a single element type. A mesh of
/// points is a POI1 part. Element order is significant (COTE, POIN n, EXTR
/// of element fields all count elements), so parts keep insertion order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    pub parts: Vec<Part>,
}

impl Mesh {
    pub fn single(part: Part) -> Self {
        Mesh { parts: vec![part] }
    }

    /// A POI1 mesh of the given nodes.
    pub fn points(nodes: &[usize]) -> Self {
        Mesh::single(Part::with(ElemType::Poi1, nodes.to_vec()))
    }

    pub fn n_elements(&self) -> usize {
        self.parts.iter().map(Part::len).sum()
    }

    /// Distinct nodes in order of first appearance.
    pub fn node_list(&self) -> Vec<usize> {
        let mut seen = HashSet::new();
        let mut out = Vec::new();
        for p in &self.parts {
            for &n in &p.conn {
                if seen.insert(n) {
                    out.push(n);
                }
            }
        }
        out
    }

    /// Union (Cast3M `ET`): elements of the same type and colour are
    /// concatenated and elements already present (same type, same nodes
    /// in the same order, whatever their colour) are not repeated. A new
    /// colour of an existing type starts a part right after that type's
    /// last part, so elements are numbered as in Cast3M, where colours are
    /// kept per element.
    pub fn union(&self, other: &Mesh) -> Mesh {
        let mut out = self.clone();
        for p in &other.parts {
            let last = out.parts.iter().rposition(|q| q.ty == p.ty);
            let Some(last) = last else {
                out.parts.push(p.clone());
                continue;
            };
            let new = new_elements(&out, p);
            match out.parts.iter_mut().find(|q| q.ty == p.ty && q.colour == p.colour) {
                Some(q) => q.conn.extend(new),
                None if !new.is_empty() => out.parts.insert(last + 1, Part { ty: p.ty, conn: new, colour: p.colour }),
                None => {}
            }
        }
        out
    }

    /// Union as `ET` orders it without 'TELQUEL' (et.notice): the line
    /// parts are joined so that the path stays continuous, so operands
    /// whose lines lead into the other's go first; failing that, a mesh of
    /// several parts goes before a mesh of one.
    pub fn union_continuous(&self, other: &Mesh) -> Mesh {
        let ends = |m: &Mesh| {
            let seg: Vec<&Part> = m.parts.iter().filter(|p| p.ty == ElemType::Seg2).collect();
            match (seg.first(), seg.last()) {
                (Some(f), Some(l)) if !f.conn.is_empty() && !l.conn.is_empty() => {
                    Some((f.conn[0], l.conn[l.conn.len() - 1]))
                }
                _ => None,
            }
        };
        let other_first = match (ends(self), ends(other)) {
            (Some((s0, s1)), Some((o0, o1))) if o1 == s0 && s1 != o0 => true,
            (Some((_, s1)), Some((o0, _))) if s1 == o0 => false,
            _ => self.parts.len() == 1 && other.parts.len() > 1,
        };
        if other_first {
            other.union(self)
        } else {
            self.union(other)
        }
    }

    /// The elements of one colour (ELEM by colour), in their order.
    pub fn of_colour(&self, colour: Colour) -> Mesh {
        let parts = self.parts.iter().filter(|p| p.colour == colour).cloned().collect();
        Mesh { parts }
    }

    /// The same elements in one colour (COUL).
    pub fn coloured(&self, colour: Colour) -> Mesh {
        let mut out = Mesh::default();
        for p in &self.parts {
            out = out.union(&Mesh::single(Part { colour, ..p.clone() }));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn union_keeps_shared_nodes_and_drops_repeated_elements() {
        let a = Mesh::single(Part::with(ElemType::Seg2, vec![0, 1]));
        let b = Mesh::single(Part::with(ElemType::Seg2, vec![1, 2, 0, 1]));
        let u = a.union(&b);
        assert_eq!(u.n_elements(), 2);
        assert_eq!(u.node_list(), vec![0, 1, 2]);
    }

    #[test]
    fn union_keeps_colours_apart_in_element_order() {
        let red = Colour::from_name("ROUG").unwrap();
        let a = Mesh::single(Part::with(ElemType::Seg2, vec![0, 1]));
        let b = Mesh::single(Part::with(ElemType::Poi1, vec![5]));
        let c = Mesh::single(Part::with(ElemType::Seg2, vec![1, 2, 0, 1])).coloured(red);
        let u = a.union(&b).union(&c);
        let tys: Vec<_> = u.parts.iter().map(|p| (p.ty, p.colour.name(), p.conn.clone())).collect();
        assert_eq!(
            tys,
            vec![
                (ElemType::Seg2, "DEFA", vec![0, 1]),
                (ElemType::Seg2, "ROUG", vec![1, 2]),
                (ElemType::Poi1, "DEFA", vec![5])
            ]
        );
        // Colouring merges the parts of one type again.
        assert_eq!(u.coloured(red).parts.len(), 2);
    }
}
