//! [`ColorMap`]: a scalar over a rectangle of cells with a colour bar (the
//! space-time map of axial stress, the paper's Fig. 4), and its colour
//! scales (viridis, or blue - white - red centred on zero).

use super::{caption_style, err, tick_on, DrawResult, Figure, FAMILY, LABEL, TICK};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::colors::colormaps::ViridisRGB;

/// A scalar field over a rectangle of cells, with a colour bar.
#[derive(Clone, Debug)]
pub struct ColorMap {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub value_label: String,
    /// Cell edges (n + 1 and m + 1 values).
    pub x_edges: Vec<f64>,
    pub y_edges: Vec<f64>,
    /// values[i][j]: cell i along x, j along y; NaN leaves a cell blank.
    pub values: Vec<Vec<f64>>,
    /// A diverging map centred on zero (signed quantities such as stress)
    /// instead of viridis.
    pub diverging: bool,
    /// Clip the colour scale at this quantile of |value| when the largest
    /// value is more than twice it (a few spikes would otherwise wash out
    /// the map); the colour bar says so.
    pub clip_quantile: Option<f64>,
}

/// Blue - white - red for v in [-1, 1].
pub fn diverging(v: f64) -> RGBColor {
    let v = v.clamp(-1.0, 1.0);
    let (lo, hi) = ((33.0, 102.0, 172.0), (178.0, 24.0, 43.0));
    let mix = |a: f64, b: f64, t: f64| (a + (b - a) * t).round() as u8;
    if v < 0.0 {
        let t = -v;
        RGBColor(
            mix(255.0, lo.0, t),
            mix(255.0, lo.1, t),
            mix(255.0, lo.2, t),
        )
    } else {
        RGBColor(
            mix(255.0, hi.0, v),
            mix(255.0, hi.1, v),
            mix(255.0, hi.2, v),
        )
    }
}

impl ColorMap {
    /// The colour scale's range, and whether it clips.
    fn value_range(&self) -> ((f64, f64), bool) {
        let vals = self
            .values
            .iter()
            .flatten()
            .copied()
            .filter(|v| v.is_finite());
        let (lo, hi) = vals.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
        if lo > hi {
            return ((-1.0, 1.0), false);
        }
        if self.diverging {
            let m = lo.abs().max(hi.abs()).max(f64::MIN_POSITIVE);
            if let Some(q) = self.clip_quantile {
                let mut mags: Vec<f64> = self
                    .values
                    .iter()
                    .flatten()
                    .filter(|v| v.is_finite())
                    .map(|v| v.abs())
                    .collect();
                mags.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
                let p = mags[((mags.len() - 1) as f64 * q).round() as usize];
                if p > 0.0 && m > 2.0 * p {
                    return ((-p, p), true);
                }
            }
            ((-m, m), false)
        } else if hi > lo {
            ((lo, hi), false)
        } else {
            ((lo - 1.0, hi + 1.0), false)
        }
    }

    fn color(&self, v: f64, range: (f64, f64)) -> RGBColor {
        if self.diverging {
            diverging(v / range.1)
        } else {
            ViridisRGB::get_color(((v - range.0) / (range.1 - range.0)).clamp(0.0, 1.0))
        }
    }
}

impl Figure for ColorMap {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        let (w, _) = root.dim_in_pixel();
        let titled = root
            .titled(&self.title, caption_style(&self.title, w))
            .map_err(err)?;
        let (main, bar) = titled.split_horizontally(w - 190);
        let (range, clipped) = self.value_range();
        let bar_label = if clipped {
            format!("{} (clipped)", self.value_label)
        } else {
            self.value_label.clone()
        };
        let (x0, x1) = (self.x_edges[0], *self.x_edges.last().expect("edges"));
        let (y0, y1) = (self.y_edges[0], *self.y_edges.last().expect("edges"));
        let mut chart = ChartBuilder::on(&main)
            .margin(15)
            .x_label_area_size(60)
            .y_label_area_size(90)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .axis_desc_style((FAMILY, LABEL))
            .label_style((FAMILY, TICK))
            .x_label_formatter(&|v| tick_on(*v, x1 - x0))
            .y_label_formatter(&|v| tick_on(*v, y1 - y0))
            .draw()
            .map_err(err)?;
        let mut cells = Vec::new();
        for (i, col) in self.values.iter().enumerate() {
            for (j, &v) in col.iter().enumerate() {
                if v.is_finite() {
                    cells.push(Rectangle::new(
                        [
                            (self.x_edges[i], self.y_edges[j]),
                            (self.x_edges[i + 1], self.y_edges[j + 1]),
                        ],
                        self.color(v, range).filled(),
                    ));
                }
            }
        }
        chart.draw_series(cells).map_err(err)?;
        // The colour bar: 100 bands over the value range.
        let mut cb = ChartBuilder::on(&bar)
            .margin_top(15)
            .margin_bottom(75)
            .margin_right(10)
            .y_label_area_size(120)
            .build_cartesian_2d(0.0..1.0, range.0..range.1)
            .map_err(err)?;
        cb.configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_desc(&bar_label)
            .axis_desc_style((FAMILY, LABEL))
            .label_style((FAMILY, TICK))
            .y_label_formatter(&|v| tick_on(*v, range.1 - range.0))
            .draw()
            .map_err(err)?;
        let n = 100;
        let dv = (range.1 - range.0) / n as f64;
        cb.draw_series((0..n).map(|k| {
            let a = range.0 + k as f64 * dv;
            Rectangle::new(
                [(0.0, a), (1.0, a + dv)],
                self.color(a + 0.5 * dv, range).filled(),
            )
        }))
        .map_err(err)?;
        Ok(())
    }
}
