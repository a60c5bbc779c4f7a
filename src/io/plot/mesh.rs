//! Meshes and nodal fields as pictures (Cast3M's `TRAC`).
//!
//! Plane meshes are drawn in their plane with axes and equal scales. Meshes
//! with depth are drawn in a fixed axonometric view (from +x, −y, +z, z
//! up), their boundary faces filled and sorted far to near (painter's
//! algorithm): enough to see a shape, with no display and no GPU.
//! A nodal field colours faces by linear interpolation of nodal values on
//! small sub-triangles; an element field colours each element (each skin
//! face of a volume) by its one value. Either comes with a colour bar on
//! the right.

use super::{colormap, range, render, Format, Paint, PALETTE};
use crate::fem::mesh::{Colour, ElemType, Mesh, Nodes};
use crate::io::{err, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::collections::HashMap;
use std::path::Path;

/// Values of a scalar at nodes, drawn on the elements of `mesh`.
#[derive(Debug, Clone, Default)]
pub struct NodalField {
    pub mesh: Mesh,
    pub values: HashMap<usize, f64>,
    pub name: String,
}

/// One value per element (an MCHAML averaged over each element's points):
/// `cells` holds the element type, its nodes and its value.
#[derive(Debug, Clone, Default)]
pub struct ElementField {
    pub cells: Vec<(ElemType, Vec<usize>, f64)>,
    pub name: String,
}

/// The field a picture colours.
#[derive(Debug, Clone)]
pub enum Field {
    Nodal(NodalField),
    Element(ElementField),
}

impl Field {
    fn name(&self) -> &str {
        match self {
            Field::Nodal(f) => &f.name,
            Field::Element(f) => &f.name,
        }
    }
    /// The nodes the field is drawn on.
    fn nodes(&self) -> Vec<usize> {
        match self {
            Field::Nodal(f) => f.mesh.node_list(),
            Field::Element(f) => f.cells.iter().flat_map(|c| c.1.iter().copied()).collect(),
        }
    }
}

#[derive(Debug, Clone)]
pub struct MeshPicture<'a> {
    pub nodes: &'a Nodes,
    /// Drawn as element edges, one colour per mesh unless its elements
    /// have their own (COUL).
    pub meshes: Vec<Mesh>,
    pub field: Option<Field>,
    pub title: String,
    /// Width of the element edges in pixels (Cast3M's OPTI EPTR); None
    /// for the default (2, and 1 for the outlines of filled faces).
    pub line_width: Option<u32>,
}

/// Draw meshes and an optional field and write an SVG or PNG file.
pub fn draw_mesh(p: &MeshPicture, format: Format, path: &Path) -> Result<()> {
    let field_nodes = p.field.as_ref().map(Field::nodes).unwrap_or_default();
    if p.meshes.iter().all(|m| m.n_elements() == 0) && field_nodes.is_empty() {
        return err("nothing to draw: the meshes are empty");
    }
    let mesh_nodes = p.meshes.iter().flat_map(|m| m.parts.iter().flat_map(|q| q.conn.iter().copied()));
    if let Some(n) = mesh_nodes.chain(field_nodes).find(|&n| n >= p.nodes.len()) {
        return err(format!("node {} is not in the node table", n + 1));
    }
    render(path, format, p)
}

/// Local node lists of the faces of a 3D element (outward normals).
fn faces(ty: ElemType) -> Vec<Vec<usize>> {
    // The element library's boundary faces: their node lists run round the
    // face, so a quadratic face draws as its 6- or 8-sided outline.
    crate::fem::shape::faces(ty).into_iter().map(|(_, f)| f).collect()
}

/// What a mesh shows: polygons (surface elements and boundary faces of
/// volumes, gibi's 2D node order already runs round the boundary),
/// polylines (line elements) and points.
#[derive(Default)]
struct Outline {
    polys: Vec<Vec<usize>>,
    lines: Vec<Vec<usize>>,
    points: Vec<usize>,
}

fn outline(m: &Mesh) -> Outline {
    let mut o = Outline::default();
    let mut count: HashMap<Vec<usize>, (usize, Vec<usize>)> = HashMap::new();
    for part in &m.parts {
        for e in part.elems() {
            match part.ty.dim() {
                0 => o.points.push(e[0]),
                1 => o.lines.push(e.to_vec()),
                2 => o.polys.push(e.to_vec()),
                _ => {
                    for f in &faces(part.ty) {
                        let face: Vec<usize> = f.iter().map(|&k| e[k]).collect();
                        let mut key = face.clone();
                        key.sort_unstable();
                        count.entry(key).or_insert((0, face)).0 += 1;
                    }
                }
            }
        }
    }
    // Interior faces are shared by two elements; the skin is seen once.
    let mut skin: Vec<_> = count.into_values().filter(|(n, _)| *n == 1).map(|(_, f)| f).collect();
    skin.sort();
    o.polys.extend(skin);
    o
}

/// The parts of a mesh grouped by colour, in order of first appearance.
fn by_colour(m: &Mesh) -> Vec<(Colour, Mesh)> {
    let mut out: Vec<(Colour, Mesh)> = Vec::new();
    for p in &m.parts {
        match out.iter_mut().find(|(c, _)| *c == p.colour) {
            Some((_, sub)) => sub.parts.push(p.clone()),
            None => out.push((p.colour, Mesh::single(p.clone()))),
        }
    }
    out
}

/// Screen coordinates and depth (larger is nearer).
struct View {
    deep: bool,
    right: [f64; 3],
    up: [f64; 3],
    back: [f64; 3],
}

impl View {
    fn new(deep: bool) -> View {
        let n = (1.0f64 + 1.6 * 1.6 + 1.2 * 1.2).sqrt();
        let back = [1.0 / n, -1.6 / n, 1.2 / n];
        // right = z × back, up = back × right.
        let r = [-back[1], back[0], 0.0];
        let rn = (r[0] * r[0] + r[1] * r[1]).sqrt();
        let right = [r[0] / rn, r[1] / rn, 0.0];
        let up = [
            back[1] * right[2] - back[2] * right[1],
            back[2] * right[0] - back[0] * right[2],
            back[0] * right[1] - back[1] * right[0],
        ];
        View { deep, right, up, back }
    }

    fn project(&self, x: [f64; 3]) -> (f64, f64, f64) {
        if !self.deep {
            return (x[0], x[1], 0.0);
        }
        let d = |a: [f64; 3]| a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
        (d(self.right), d(self.up), d(self.back))
    }
}

enum Prim {
    Poly { pts: Vec<(f64, f64)>, fill: Option<RGBColor>, stroke: Option<RGBColor> },
    Line { pts: Vec<(f64, f64)>, color: RGBColor, width: u32 },
    Dot { pt: (f64, f64), color: RGBColor },
}

impl MeshPicture<'_> {
    fn edge_width(&self) -> u32 {
        self.line_width.unwrap_or(2)
    }

    /// Everything to draw, in drawing order.
    fn prims(&self) -> (Vec<Prim>, Option<(f64, f64)>) {
        let deep = self.deep();
        let view = View::new(deep);
        let at = |n: usize| view.project(self.nodes.get(n));
        let mut prims: Vec<(f64, Prim)> = Vec::new();
        let mut vrange = None;
        if let Some(Field::Element(f)) = &self.field {
            vrange = true_range(f.cells.iter().map(|c| c.2));
            let (lo, hi) = vrange.unwrap_or((0.0, 1.0));
            let fill = |v: f64| match v.is_finite() {
                true => colormap(if hi > lo { (v - lo) / (hi - lo) } else { 0.5 }),
                false => RGBColor(200, 200, 200),
            };
            for (poly, v) in element_faces(&f.cells) {
                let depth = poly.iter().map(|&n| at(n).2).sum::<f64>() / poly.len() as f64;
                let mut pts: Vec<_> = poly.iter().map(|&n| (at(n).0, at(n).1)).collect();
                match poly.len() {
                    1 => prims.push((depth, Prim::Dot { pt: pts[0], color: fill(v) })),
                    2 => prims.push((depth, Prim::Line { pts, color: fill(v), width: 4 })),
                    _ => {
                        pts.push(pts[0]);
                        let stroke = Some(RGBColor(90, 90, 90));
                        prims.push((depth, Prim::Poly { pts, fill: Some(fill(v)), stroke }));
                    }
                }
            }
        }
        if let Some(Field::Nodal(f)) = &self.field {
            vrange = range(f.values.values().copied()).map(|(a, b)| {
                // `range` pads; the colour bar shows the true extremes.
                let pad = if b - a > 0.0 { (b - a) / 1.1 * 0.05 } else { 0.0 };
                (a + pad, b - pad)
            });
            let (lo, hi) = vrange.unwrap_or((0.0, 1.0));
            let scale = |v: f64| if hi > lo { (v - lo) / (hi - lo) } else { 0.5 };
            let o = outline(&f.mesh);
            // Finer colour steps on small meshes, bounded file size on big ones.
            let n_sub = match o.polys.len() {
                0..300 => 4,
                300..3000 => 2,
                _ => 1,
            };
            let val = |n: usize| f.values.get(&n).copied().unwrap_or(f64::NAN);
            for poly in &o.polys {
                let depth = poly.iter().map(|&n| at(n).2).sum::<f64>() / poly.len() as f64;
                for (pts, v) in subdivide(poly.iter().map(|&n| (at(n), val(n))).collect(), n_sub) {
                    let fill = if v.is_finite() { colormap(scale(v)) } else { RGBColor(200, 200, 200) };
                    prims.push((depth, Prim::Poly { pts, fill: Some(fill), stroke: None }));
                }
            }
            for line in &o.lines {
                for w in line.windows(2) {
                    let v = 0.5 * (val(w[0]) + val(w[1]));
                    let pts = w.iter().map(|&n| (at(n).0, at(n).1)).collect();
                    let depth = 0.5 * (at(w[0]).2 + at(w[1]).2);
                    prims.push((depth, Prim::Line { pts, color: colormap(scale(v)), width: 2 * self.edge_width() }));
                }
            }
            // A field drawn on its own nodes (no mesh given) is a cloud of
            // coloured points.
            for p in f.mesh.parts.iter().filter(|p| p.ty == ElemType::Poi1) {
                for &n in &p.conn {
                    let v = val(n);
                    let color = if v.is_finite() { colormap(scale(v)) } else { RGBColor(200, 200, 200) };
                    prims.push((at(n).2, Prim::Dot { pt: (at(n).0, at(n).1), color }));
                }
            }
        }
        // One colour per mesh, unless its elements have their own (COUL).
        let coloured = self.meshes.iter().enumerate().flat_map(|(i, m)| {
            by_colour(m)
                .into_iter()
                .map(move |(c, sub)| (c.rgb().map_or(PALETTE[i % PALETTE.len()], |[r, g, b]| RGBColor(r, g, b)), sub))
        });
        for (color, m) in coloured {
            let m = &m;
            let o = outline(m);
            for poly in &o.polys {
                let depth = poly.iter().map(|&n| at(n).2).sum::<f64>() / poly.len() as f64;
                let mut pts: Vec<_> = poly.iter().map(|&n| (at(n).0, at(n).1)).collect();
                pts.push(pts[0]);
                let fill = deep.then_some(RGBColor(245, 245, 240));
                prims.push((depth, Prim::Poly { pts, fill, stroke: Some(color) }));
            }
            for line in &o.lines {
                let depth = line.iter().map(|&n| at(n).2).sum::<f64>() / line.len() as f64;
                prims.push((
                    depth,
                    Prim::Line {
                        pts: line.iter().map(|&n| (at(n).0, at(n).1)).collect(),
                        color,
                        width: self.edge_width(),
                    },
                ));
            }
            for &n in &o.points {
                prims.push((at(n).2, Prim::Dot { pt: (at(n).0, at(n).1), color }));
            }
        }
        if deep {
            // Stable: equal depths keep field-then-mesh order.
            prims.sort_by(|a, b| a.0.total_cmp(&b.0));
        }
        (prims.into_iter().map(|(_, p)| p).collect(), vrange)
    }
}

/// The extremes of finite values (None when there is none).
fn true_range(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let r = values.filter(|v| v.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    (r.0 <= r.1).then_some(r)
}

/// What an element field shows, each with its element's value: points,
/// segments of line elements, surface elements, and the skin faces of
/// volume elements (an interior face is shared by two elements).
fn element_faces(cells: &[(ElemType, Vec<usize>, f64)]) -> Vec<(Vec<usize>, f64)> {
    let mut out = Vec::new();
    let mut count: HashMap<Vec<usize>, (usize, Vec<usize>, f64)> = HashMap::new();
    for (ty, e, v) in cells {
        match ty.dim() {
            0 => out.push((vec![e[0]], *v)),
            1 => out.extend(e.windows(2).map(|w| (w.to_vec(), *v))),
            2 => out.push((e.clone(), *v)),
            _ => {
                for f in &faces(*ty) {
                    let face: Vec<usize> = f.iter().map(|&k| e[k]).collect();
                    let mut key = face.clone();
                    key.sort_unstable();
                    count.entry(key).or_insert((0, face, *v)).0 += 1;
                }
            }
        }
    }
    let mut skin: Vec<_> = count.into_values().filter(|(n, ..)| *n == 1).map(|(_, f, v)| (f, v)).collect();
    skin.sort_by(|a, b| a.0.cmp(&b.0));
    out.extend(skin);
    out
}

/// Split a polygon with nodal values into small triangles (a fan from the
/// centroid, each fan triangle cut n×n) with the value at their centre.
fn subdivide(poly: Vec<((f64, f64, f64), f64)>, n: usize) -> Vec<(Vec<(f64, f64)>, f64)> {
    let k = poly.len() as f64;
    let c = poly.iter().fold((0.0, 0.0, 0.0), |a, ((x, y, _), v)| (a.0 + x / k, a.1 + y / k, a.2 + v / k));
    let mut out = Vec::new();
    for i in 0..poly.len() {
        let ((x1, y1, _), v1) = poly[i];
        let ((x2, y2, _), v2) = poly[(i + 1) % poly.len()];
        let corner = [(c.0, c.1, c.2), (x1, y1, v1), (x2, y2, v2)];
        // Barycentric point (a, b) on the sub-grid: a/n along c→1, b/n along c→2.
        let p = |a: f64, b: f64| {
            let (s, t) = (a / n as f64, b / n as f64);
            let w = [1.0 - s - t, s, t];
            let m = |f: fn(&(f64, f64, f64)) -> f64| w.iter().zip(&corner).map(|(w, q)| w * f(q)).sum::<f64>();
            (m(|q| q.0), m(|q| q.1), m(|q| q.2))
        };
        for a in 0..n {
            for b in 0..n - a {
                let (a, b) = (a as f64, b as f64);
                let mut tris = vec![[p(a, b), p(a + 1.0, b), p(a, b + 1.0)]];
                if a + b + 2.0 <= n as f64 {
                    tris.push([p(a + 1.0, b), p(a + 1.0, b + 1.0), p(a, b + 1.0)]);
                }
                for t in tris {
                    let v = (t[0].2 + t[1].2 + t[2].2) / 3.0;
                    out.push((t.iter().map(|q| (q.0, q.1)).collect(), v));
                }
            }
        }
    }
    out
}

fn bounds(prims: &[Prim]) -> Option<((f64, f64), (f64, f64))> {
    let pts = || {
        prims.iter().flat_map(|p| match p {
            Prim::Poly { pts, .. } | Prim::Line { pts, .. } => pts.clone(),
            Prim::Dot { pt, .. } => vec![*pt],
        })
    };
    Some((range(pts().map(|p| p.0))?, range(pts().map(|p| p.1))?))
}

/// Widen one range so that data units are square on a w×h pixel area.
fn square(x: (f64, f64), y: (f64, f64), w: f64, h: f64) -> ((f64, f64), (f64, f64)) {
    let (dx, dy) = (x.1 - x.0, y.1 - y.0);
    if dx / w > dy / h {
        let e = 0.5 * (dx * h / w - dy);
        (x, (y.0 - e, y.1 + e))
    } else {
        let e = 0.5 * (dy * w / h - dx);
        ((x.0 - e, x.1 + e), y)
    }
}

impl Paint for MeshPicture<'_> {
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> std::result::Result<(), String> {
        let s = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        root.fill(&WHITE).map_err(s)?;
        let (prims, vrange) = self.prims();
        let (xr, yr) = bounds(&prims).ok_or("no finite coordinate to draw")?;
        let (w, h) = root.dim_in_pixel();
        let (main, bar) =
            if self.field.is_some() { root.split_horizontally(w as i32 - 130) } else { (root.clone(), root.clone()) };
        let axes = !self.deep();
        let caption = if self.title.is_empty() { 0 } else { 35 };
        let (lx, ly) = if axes { (40, 70) } else { (0, 0) };
        let (mw, _) = main.dim_in_pixel();
        let (pw, ph) =
            ((mw as f64 - 40.0 - ly as f64).max(10.0), (h as f64 - 40.0 - lx as f64 - caption as f64).max(10.0));
        let (xr, yr) = square(xr, yr, pw, ph);
        let mut b = ChartBuilder::on(&main);
        b.margin(20).x_label_area_size(lx).y_label_area_size(ly);
        if !self.title.is_empty() {
            b.caption(&self.title, ("sans-serif", 22));
        }
        let mut chart = b.build_cartesian_2d(xr.0..xr.1, yr.0..yr.1).map_err(s)?;
        if axes {
            chart.configure_mesh().disable_mesh().draw().map_err(s)?;
        }
        for p in prims {
            match p {
                Prim::Poly { pts, fill, stroke } => {
                    if let Some(c) = fill {
                        chart.draw_series(std::iter::once(Polygon::new(pts.clone(), c.filled()))).map_err(s)?;
                    }
                    if let Some(c) = stroke {
                        let w = self.line_width.unwrap_or(1);
                        chart.draw_series(std::iter::once(PathElement::new(pts, c.stroke_width(w)))).map_err(s)?;
                    }
                }
                Prim::Line { pts, color, width } => {
                    chart.draw_series(std::iter::once(PathElement::new(pts, color.stroke_width(width)))).map_err(s)?;
                }
                Prim::Dot { pt, color } => {
                    chart.draw_series(std::iter::once(Circle::new(pt, 3, color.filled()))).map_err(s)?;
                }
            }
        }
        if let (Some(f), Some((lo, hi))) = (&self.field, vrange) {
            colour_bar(&bar, f.name(), lo, hi).map_err(s)?;
        }
        Ok(())
    }
}

impl MeshPicture<'_> {
    fn deep(&self) -> bool {
        let field = self.field.as_ref().map(Field::nodes).unwrap_or_default();
        let mut all = self.meshes.iter().flat_map(|m| m.node_list()).chain(field);
        all.any(|n| self.nodes.get(n)[2].abs() > 1e-12)
    }
}

/// A vertical scale from `lo` (bottom) to `hi` (top) with three labels.
fn colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    name: &str,
    lo: f64,
    hi: f64,
) -> std::result::Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let (_, h) = area.dim_in_pixel();
    let (top, bottom, x0, x1) = (60, h as i32 - 60, 10, 35);
    let steps = 100;
    for k in 0..steps {
        let y = |k: i32| bottom - (bottom - top) * k / steps;
        let c = colormap((k as f64 + 0.5) / steps as f64);
        area.draw(&Rectangle::new([(x0, y(k + 1)), (x1, y(k))], c.filled()))?;
    }
    area.draw(&Rectangle::new([(x0, top), (x1, bottom)], BLACK.stroke_width(1)))?;
    let font = ("sans-serif", 14).into_font();
    area.draw(&Text::new(name.to_string(), (x0, top - 30), font.clone()))?;
    for (f, y) in [(1.0, top), (0.5, (top + bottom) / 2), (0.0, bottom)] {
        let v = lo + f * (hi - lo);
        area.draw(&Text::new(format!("{:.3e}", v), (x1 + 5, y - 7), font.clone()))?;
    }
    Ok(())
}
