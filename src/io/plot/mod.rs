//! Pictures without a display: meshes, deformed meshes, nodal fields and
//! curves, written as SVG or PNG files with `plotters`.
//!
//! Text in PNG files is drawn with DejaVu Sans embedded in the binary (the
//! `dejavu` crate), registered with plotters' `ab_glyph` backend: no system
//! font, fontconfig or display is ever looked up, so a headless CI machine
//! draws exactly what a desktop does.

mod curve;
mod mesh;

pub use curve::{draw_curves, Curve, CurvePicture};
pub use mesh::{draw_mesh, ElementField, Field, MeshPicture, NodalField};

use super::{write_file, IoError, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Image format of a picture.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Svg,
    Png,
}

impl Format {
    /// The file extension, without the dot.
    pub fn ext(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Png => "png",
        }
    }
}

const SIZE: (u32, u32) = (800, 600);

fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // The font is a valid TTF shipped by the crate; if registering ever
        // failed, text drawing reports the error instead.
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular());
    });
}

/// Something that can draw itself on any plotters backend.
trait Paint {
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> std::result::Result<(), String>;
}

/// Draw on a drawing area of the chosen format and write the file.
fn render(path: &Path, format: Format, f: &impl Paint) -> Result<()> {
    register_font();
    let fail = |e: String| IoError(format!("cannot draw {}: {}", path.display(), e));
    match format {
        Format::Svg => {
            let mut text = String::new();
            {
                let root = SVGBackend::with_string(&mut text, SIZE).into_drawing_area();
                f.paint(&root).map_err(fail)?;
                root.present().map_err(|e| fail(e.to_string()))?;
            }
            write_file(path, text.as_bytes())
        }
        Format::Png => {
            let mut rgb = vec![0u8; (SIZE.0 * SIZE.1 * 3) as usize];
            {
                let root = BitMapBackend::with_buffer(&mut rgb, SIZE).into_drawing_area();
                f.paint(&root).map_err(fail)?;
                root.present().map_err(|e| fail(e.to_string()))?;
            }
            write_file(path, &encode_png(&rgb, SIZE)?)
        }
    }
}

/// RGB8 pixels → PNG bytes (the `png` crate, without the `image` tree).
fn encode_png(rgb: &[u8], (w, h): (u32, u32)) -> Result<Vec<u8>> {
    let mut out = Vec::new();
    let fail = |e: png::EncodingError| IoError(format!("cannot encode PNG: {}", e));
    {
        let mut enc = png::Encoder::new(&mut out, w, h);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let mut writer = enc.write_header().map_err(fail)?;
        writer.write_image_data(rgb).map_err(fail)?;
        writer.finish().map_err(fail)?;
    }
    Ok(out)
}

/// A padded range that is never empty (plotters needs min < max).
fn range(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) =
        values.filter(|v| v.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    if lo > hi {
        return None;
    }
    let pad = if hi > lo { 0.05 * (hi - lo) } else { 0.5 * lo.abs().max(1.0) };
    Some((lo - pad, hi + pad))
}

/// Blue → cyan → green → yellow → red, the usual Cast3M iso-value scale.
fn colormap(t: f64) -> RGBColor {
    let stops = [(0, 0, 255), (0, 255, 255), (0, 200, 0), (255, 255, 0), (255, 0, 0)];
    let t = if t.is_finite() { t.clamp(0.0, 1.0) } else { 0.0 };
    let x = t * (stops.len() - 1) as f64;
    let i = (x.floor() as usize).min(stops.len() - 2);
    let f = x - i as f64;
    let mix = |a: u8, b: u8| (a as f64 + f * (b as f64 - a as f64)).round() as u8;
    let (a, b) = (stops[i], stops[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Colours of successive meshes or curves.
const PALETTE: [RGBColor; 6] = [
    RGBColor(0, 0, 0),
    RGBColor(200, 30, 30),
    RGBColor(30, 90, 200),
    RGBColor(20, 140, 40),
    RGBColor(200, 120, 0),
    RGBColor(130, 40, 160),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_never_empty() {
        assert_eq!(range([2.0, 2.0].into_iter()), Some((1.0, 3.0)));
        assert_eq!(range([f64::NAN].into_iter()), None);
        assert_eq!(colormap(0.0), RGBColor(0, 0, 255));
        assert_eq!(colormap(1.0), RGBColor(255, 0, 0));
    }
}
