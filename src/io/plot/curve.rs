//! Curves y(x) on one chart (Cast3M's `DESS` of an EVOLUTIO).

use super::{range, render, Format, Paint, PALETTE};
use crate::io::{err, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

#[derive(Debug, Clone, Default, PartialEq)]
pub struct Curve {
    /// Legend text (no legend entry when empty).
    pub label: String,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

#[derive(Debug, Clone, Default, PartialEq)]
pub struct CurvePicture {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub curves: Vec<Curve>,
    /// Width of the curves in pixels (Cast3M's OPTI EPTR); None for 2.
    pub line_width: Option<u32>,
}

/// Draw the curves on one chart and write an SVG or PNG file.
pub fn draw_curves(p: &CurvePicture, format: Format, path: &Path) -> Result<()> {
    if p.curves.iter().all(|c| c.x.is_empty()) {
        return err("nothing to draw: the curves have no points");
    }
    if let Some(c) = p.curves.iter().find(|c| c.x.len() != c.y.len()) {
        return err(format!("curve '{}' has {} abscissae for {} ordinates", c.label, c.x.len(), c.y.len()));
    }
    render(path, format, p)
}

impl Paint for CurvePicture {
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> std::result::Result<(), String> {
        let s = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        root.fill(&WHITE).map_err(s)?;
        let xs = || self.curves.iter().flat_map(|c| c.x.iter().copied());
        let ys = || self.curves.iter().flat_map(|c| c.y.iter().copied());
        let ((x0, x1), (y0, y1)) = match (range(xs()), range(ys())) {
            (Some(x), Some(y)) => (x, y),
            _ => return Err("no finite value to draw".into()),
        };
        let mut builder = ChartBuilder::on(root);
        builder.margin(15).x_label_area_size(45).y_label_area_size(80);
        if !self.title.is_empty() {
            builder.caption(&self.title, ("sans-serif", 22));
        }
        let mut chart = builder.build_cartesian_2d(x0..x1, y0..y1).map_err(s)?;
        chart
            .configure_mesh()
            .light_line_style(RGBColor(235, 235, 235))
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .draw()
            .map_err(s)?;
        let width = self.line_width.unwrap_or(2);
        for (i, c) in self.curves.iter().enumerate() {
            let color = PALETTE[i % PALETTE.len()];
            let pts: Vec<(f64, f64)> =
                c.x.iter().zip(&c.y).filter(|(x, y)| x.is_finite() && y.is_finite()).map(|(x, y)| (*x, *y)).collect();
            let series = chart.draw_series(LineSeries::new(pts, color.stroke_width(width))).map_err(s)?;
            if !c.label.is_empty() {
                series
                    .label(c.label.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(width)));
            }
        }
        if self.curves.iter().any(|c| !c.label.is_empty()) {
            chart.configure_series_labels().background_style(WHITE.mix(0.85)).border_style(BLACK).draw().map_err(s)?;
        }
        Ok(())
    }
}
