//! [`Bars`]: grouped bars, one group per category and one bar per series
//! (the paper's Fig. 6; a static system's end tensions).

use super::{
    caption_style, err, legend, tick_on, DrawResult, Figure, FAMILY, LABEL, PALETTE, TICK,
};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Grouped bars: one group per category, one bar per series.
#[derive(Clone, Debug)]
pub struct Bars {
    pub title: String,
    pub y_label: String,
    pub categories: Vec<String>,
    /// (label, one value per category).
    pub series: Vec<(String, Vec<f64>)>,
}

impl Figure for Bars {
    fn size(&self) -> (u32, u32) {
        (1100, 650)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        let n = self.categories.len();
        let k = self.series.len().max(1);
        let top = self
            .series
            .iter()
            .flat_map(|s| s.1.iter())
            .copied()
            .filter(|v| v.is_finite())
            .fold(0.0f64, f64::max);
        let top = if top > 0.0 { 1.15 * top } else { 1.0 };
        let categories = self.categories.clone();
        let (w, _) = root.dim_in_pixel();
        let mut chart = ChartBuilder::on(root)
            .caption(&self.title, caption_style(&self.title, w))
            .margin(15)
            .x_label_area_size(60)
            .y_label_area_size(90)
            .build_cartesian_2d(-0.5..n as f64 - 0.5, 0.0..top)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_x_mesh()
            .x_labels(n)
            .light_line_style(WHITE.mix(0.0))
            .x_label_formatter(&|v| {
                let i = v.round();
                if (v - i).abs() < 1e-6 && i >= 0.0 && (i as usize) < categories.len() {
                    categories[i as usize].clone()
                } else {
                    String::new()
                }
            })
            .y_desc(&self.y_label)
            .axis_desc_style((FAMILY, LABEL))
            .label_style((FAMILY, TICK))
            .y_label_formatter(&|v| tick_on(*v, top))
            .draw()
            .map_err(err)?;
        let width = 0.8 / k as f64;
        for (si, (label, values)) in self.series.iter().enumerate() {
            let color = PALETTE[si % PALETTE.len()];
            let bars = values
                .iter()
                .enumerate()
                .filter(|(_, v)| v.is_finite())
                .map(|(c, &v)| {
                    let x = c as f64 - 0.4 + si as f64 * width;
                    Rectangle::new([(x, 0.0), (x + 0.92 * width, v)], color.filled())
                });
            chart
                .draw_series(bars)
                .map_err(err)?
                .label(label.clone())
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 6), (x + 14, y + 6)], color.filled())
                });
        }
        legend(&mut chart)
    }
}
