//! STL (stereolithography) triangle soups, read in ASCII or binary and
//! written in binary, through the `stl_io` crate: a maintained reader of
//! both variants rather than another hand-written parser.
//!
//! STL stores single-precision coordinates: a round trip keeps about seven
//! significant digits. Vertices with identical coordinates are merged on
//! reading (the crate indexes them), so the triangles share their nodes.

use super::{err, read_file, write_file, IoError, Result};
use std::path::Path;

/// Triangles on a list of vertices.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Triangles {
    pub coords: Vec<[f64; 3]>,
    pub tris: Vec<[usize; 3]>,
}

/// Header (80 bytes) and triangle count (4 bytes) of a binary STL.
const BINARY_HEADER: usize = 84;
/// Normal, three vertices (12 f32) and the attribute count (u16).
const BINARY_FACET: usize = 50;

/// Read an ASCII or binary STL file. Format errors do not name the path:
/// the caller names the file as its user wrote it.
pub fn read(path: &Path) -> Result<Triangles> {
    parse(&read_file(path)?)
}

/// Parse STL bytes. Errors name the facet (never the file's text).
pub fn parse(bytes: &[u8]) -> Result<Triangles> {
    let ascii = bytes.starts_with(b"solid ") && !binary_size_matches(bytes);
    if !ascii {
        check_binary_size(bytes)?;
    }
    let mut cursor = std::io::Cursor::new(bytes);
    let reader =
        stl_io::create_stl_reader(&mut cursor).map_err(|e| IoError(format!("not an STL file ({})", e.kind())))?;
    let mut out = Triangles::default();
    let mut index = std::collections::HashMap::new();
    for (n, t) in reader.enumerate() {
        let t = t.map_err(|e| match e.kind() {
            std::io::ErrorKind::UnexpectedEof => IoError(format!("the file ends inside facet {}", n + 1)),
            _ => IoError(format!("facet {} is malformed (expected 'facet normal', 'outer loop', three 'vertex x y z', 'endloop', 'endfacet')", n + 1)),
        })?;
        let mut tri = [0; 3];
        for (k, v) in t.vertices.iter().enumerate() {
            if v.0.iter().any(|c| !c.is_finite()) {
                return err(format!("facet {} has a non-finite coordinate", n + 1));
            }
            let key = v.0.map(f32::to_bits);
            let next = out.coords.len();
            tri[k] = *index.entry(key).or_insert(next);
            if tri[k] == next {
                out.coords.push(v.0.map(f64::from));
            }
        }
        out.tris.push(tri);
    }
    Ok(out)
}

/// Some binary files start with "solid " too: a size that matches the
/// binary layout exactly decides.
fn binary_size_matches(bytes: &[u8]) -> bool {
    bytes.len() >= BINARY_HEADER && bytes.len() == BINARY_HEADER + BINARY_FACET * binary_count(bytes)
}

fn binary_count(bytes: &[u8]) -> usize {
    u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize
}

fn check_binary_size(bytes: &[u8]) -> Result<()> {
    if bytes.len() < BINARY_HEADER {
        return err(format!(
            "not an STL file: neither ASCII (first line 'solid name') nor binary (at least {} bytes, found {})",
            BINARY_HEADER,
            bytes.len()
        ));
    }
    let n = binary_count(bytes);
    let want = BINARY_HEADER as u64 + BINARY_FACET as u64 * n as u64;
    if bytes.len() as u64 != want {
        return err(format!(
            "binary STL: its header announces {} triangles ({} bytes) but the file has {} bytes",
            n,
            want,
            bytes.len()
        ));
    }
    Ok(())
}

/// Write triangles as a binary STL, each with its unit normal (zero for a
/// degenerate triangle).
pub fn write(path: &Path, t: &Triangles) -> Result<()> {
    let facets: Vec<stl_io::Triangle> = t
        .tris
        .iter()
        .map(|tri| {
            let [a, b, c] = tri.map(|i| t.coords[i]);
            let (u, v) = (sub(b, a), sub(c, a));
            let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let n = if len > 0.0 { n.map(|c| c / len) } else { [0.0; 3] };
            stl_io::Triangle {
                normal: stl_io::Normal::new(n.map(|c| c as f32)),
                vertices: [a, b, c].map(|p| stl_io::Vertex::new(p.map(|c| c as f32))),
            }
        })
        .collect();
    if u32::try_from(facets.len()).is_err() {
        return err(format!("{}: too many triangles for STL ({})", path.display(), facets.len()));
    }
    let mut bytes = Vec::with_capacity(BINARY_HEADER + BINARY_FACET * facets.len());
    stl_io::write_stl(&mut bytes, facets.iter()).map_err(|e| IoError(format!("cannot encode STL: {}", e)))?;
    write_file(path, &bytes)
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ascii_facets_share_vertices() {
        let text =
            b"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n\
facet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n";
        let t = parse(text).unwrap();
        assert_eq!(t.coords.len(), 4);
        assert_eq!(t.tris, vec![[0, 1, 2], [1, 3, 2]]);
    }

    #[test]
    fn errors_name_the_facet_not_the_text() {
        let text = b"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex SECRET 0 0\n";
        let e = parse(text).unwrap_err().0;
        assert!(e.contains("facet 1") && !e.contains("SECRET"), "{}", e);
        let e = parse(&[0u8; 90]).unwrap_err().0;
        assert!(e.contains("90 bytes"), "{}", e);
        assert!(parse(b"").is_err());
    }
}
