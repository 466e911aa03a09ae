//! Figures as PNG and SVG (plotters, no system libraries: the DejaVu Sans
//! font ships in `assets/fonts` under its free licence and is drawn with
//! ab_glyph).
//!
//! Three kinds of figure serve every plot of stancf: [`Lines`] (curves in
//! x-y, optionally with a log y axis or equal axes, e.g. cable shapes),
//! [`ColorMap`] (a scalar over a rectangle, with a colour bar: the
//! space-time map of axial stress, the paper's Fig. 4) and [`Bars`] (grouped
//! bars: the paper's Fig. 6). [`save`] renders a figure once into a PNG
//! buffer and once into an SVG string and writes both atomically.
//!
//! The figures of a run are drawn from its result files
//! ([`plot_results`]), never from the simulation in memory, so that
//! `stancf run --plot` and `stancf plot DIR` draw the same thing.

use crate::output::write_atomic;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::colors::colormaps::ViridisRGB;
use std::io;
use std::path::Path;
use std::sync::Once;

static FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
static REGISTER: Once = Once::new();
const FAMILY: &str = "sans-serif";

fn register_font() {
    REGISTER.call_once(|| {
        for style in [FontStyle::Normal, FontStyle::Bold] {
            plotters::style::register_font(FAMILY, style, FONT)
                .unwrap_or_else(|_| panic!("the bundled font is valid"));
        }
    });
}

/// A drawing error as text (plotters' error types differ by backend).
type DrawResult = Result<(), String>;

fn err<E: std::fmt::Debug>(e: E) -> String {
    format!("{e:?}")
}

/// Something that draws itself on any plotters backend.
pub trait Figure {
    /// Pixel size (PNG) and user-unit size (SVG).
    fn size(&self) -> (u32, u32) {
        (1000, 650)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult;
}

/// Writes `dir/name.png` and `dir/name.svg`.
pub fn save(figure: &impl Figure, dir: &Path, name: &str) -> io::Result<()> {
    register_font();
    let (w, h) = figure.size();
    let io_err = |e: String| io::Error::other(format!("{name}: {e}"));
    let mut pixels = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(err).map_err(io_err)?;
        figure.draw(&root).map_err(io_err)?;
        root.present().map_err(err).map_err(io_err)?;
    }
    write_figure(dir, &format!("{name}.png"), &encode_png(&pixels, w, h)?)?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(err).map_err(io_err)?;
        figure.draw(&root).map_err(io_err)?;
        root.present().map_err(err).map_err(io_err)?;
    }
    write_figure(dir, &format!("{name}.svg"), svg.as_bytes())
}

/// Writes one figure file atomically; an error names the file (e.g. a
/// folder in the way: "out/run/energy.png: is a folder, not a file") and
/// leaves no `.partial` behind.
fn write_figure(dir: &Path, file: &str, contents: &[u8]) -> io::Result<()> {
    let path = dir.join(file);
    let named = |e: io::Error| {
        let what = if path.is_dir() {
            "is a folder, not a file; move it away to draw the figure".to_string()
        } else {
            format!("cannot write the figure: {e}")
        };
        io::Error::new(e.kind(), format!("{}: {what}", path.display()))
    };
    if path.is_dir() {
        return Err(named(io::Error::from(io::ErrorKind::IsADirectory)));
    }
    write_atomic(dir, file, contents).map_err(|e| {
        let _ = std::fs::remove_file(dir.join(format!("{file}.partial")));
        named(e)
    })
}

fn encode_png(rgb: &[u8], w: u32, h: u32) -> io::Result<Vec<u8>> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, w, h);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let mut writer = enc.write_header().map_err(io::Error::other)?;
        writer.write_image_data(rgb).map_err(io::Error::other)?;
    }
    Ok(out)
}

/// The line colours, in order (distinguishable, colour-blind safe: the
/// Okabe-Ito palette).
pub const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
    RGBColor(240, 228, 66),
];

/// Colour k of a sequence of n ordered items (e.g. times): viridis.
pub fn sequential(k: usize, n: usize) -> RGBColor {
    let h = if n > 1 {
        k as f64 / (n - 1) as f64
    } else {
        0.0
    };
    // The last tenth of viridis is too light on white.
    ViridisRGB::get_color(0.9 * h)
}

/// One curve.
#[derive(Clone, Debug)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub color: RGBColor,
    pub dashed: bool,
    /// Markers at the points instead of (or besides) a line.
    pub markers: bool,
    pub width: u32,
}

impl Series {
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>, color: RGBColor) -> Self {
        Series {
            label: label.into(),
            points,
            color,
            dashed: false,
            markers: false,
            width: 2,
        }
    }
    pub fn dashed(mut self) -> Self {
        self.dashed = true;
        self
    }
    pub fn with_markers(mut self) -> Self {
        self.markers = true;
        self
    }
}

/// Curves in a plane.
#[derive(Clone, Debug)]
pub struct Lines {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    pub log_y: bool,
    /// Same scale on both axes (shapes).
    pub equal_axes: bool,
    /// Ticks only at whole numbers of x (iteration counts).
    pub integer_x: bool,
}

impl Lines {
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Lines {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            log_y: false,
            equal_axes: false,
            integer_x: false,
        }
    }

    fn ranges(&self, plot_w: f64, plot_h: f64) -> ((f64, f64), (f64, f64)) {
        let pts = self.series.iter().flat_map(|s| s.points.iter());
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for &(x, y) in pts {
            if !x.is_finite() || !y.is_finite() || (self.log_y && y <= 0.0) {
                continue;
            }
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if x0 > x1 {
            return ((0.0, 1.0), (if self.log_y { 1e-16 } else { 0.0 }, 1.0));
        }
        if self.log_y {
            return ((x0, pad_max(x0, x1)), (y0 / 3.0, y1 * 3.0));
        }
        let (mut xr, mut yr) = (pad(x0, x1), pad(y0, y1));
        // Room above the data for the legend (upper right; about 19 px a
        // label), so that it hides no curve; with equal axes (shapes) at
        // most a third of the height, which the shapes keep.
        let labels = self.series.iter().filter(|s| !s.label.is_empty()).count();
        let cap = if self.equal_axes { 0.35 } else { 0.6 };
        let legend = (19.0 * labels as f64 + 12.0).min(cap * plot_h);
        if labels > 0 {
            yr.1 += (yr.1 - yr.0) * legend / (plot_h - legend);
        }
        if self.equal_axes {
            // Units per pixel the same on both axes: widen the tighter one.
            let (sx, sy) = ((xr.1 - xr.0) / plot_w, (yr.1 - yr.0) / plot_h);
            if sx > sy {
                let c = 0.5 * (yr.0 + yr.1);
                let half = 0.5 * sx * plot_h;
                yr = (c - half, c + half);
            } else {
                let c = 0.5 * (xr.0 + xr.1);
                let half = 0.5 * sy * plot_w;
                xr = (c - half, c + half);
            }
        }
        (xr, yr)
    }
}

/// [a, b] with a 4 % margin (and a unit width if a = b).
fn pad(a: f64, b: f64) -> (f64, f64) {
    let w = b - a;
    if w <= 0.0 {
        let m = if a == 0.0 { 1.0 } else { 0.1 * a.abs() };
        return (a - m, b + m);
    }
    (a - 0.04 * w, b + 0.04 * w)
}

fn pad_max(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a + 1.0
    }
}

const CAPTION: u32 = 26;
const LABEL: u32 = 18;
const TICK: u32 = 15;

/// The title's font: 26 px, smaller for a long title so that it fits the
/// width (DejaVu Sans averages ~0.55 em per character).
fn caption_style(title: &str, width: u32) -> TextStyle<'static> {
    let fit = (width as f64 - 30.0) / (0.56 * title.chars().count().max(1) as f64);
    let size = (CAPTION as f64).min(fit).max(12.0);
    (FAMILY, size).into_font().into()
}

impl Figure for Lines {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        let (w, h) = root.dim_in_pixel();
        let (left, bottom) = (90u32, 60u32);
        let plot_w = (w - left - 30) as f64;
        let plot_h = (h - bottom - CAPTION - 30) as f64;
        let (xr, yr) = self.ranges(plot_w, plot_h);
        let mut builder = ChartBuilder::on(root);
        builder
            .caption(&self.title, caption_style(&self.title, w))
            .margin(15)
            .x_label_area_size(bottom)
            .y_label_area_size(left);
        if self.log_y {
            let mut chart = builder
                .build_cartesian_2d(xr.0..xr.1, (yr.0..yr.1).log_scale())
                .map_err(err)?;
            let integer_x = self.integer_x;
            let x_ticks = if integer_x {
                ((xr.1 - xr.0).round() as usize + 1).clamp(2, 12)
            } else {
                10
            };
            chart
                .configure_mesh()
                .x_desc(&self.x_label)
                .y_desc(&self.y_label)
                .axis_desc_style((FAMILY, LABEL))
                .label_style((FAMILY, TICK))
                .x_labels(x_ticks)
                .x_label_formatter(&|v| {
                    if !integer_x {
                        tick_on(*v, xr.1 - xr.0)
                    } else if (v - v.round()).abs() < 1e-9 {
                        format!("{}", v.round() as i64)
                    } else {
                        String::new()
                    }
                })
                .y_label_formatter(&|v| format!("{v:.0e}"))
                .light_line_style(WHITE.mix(0.0))
                .draw()
                .map_err(err)?;
            for s in &self.series {
                let pts: Vec<(f64, f64)> = s.points.iter().copied().filter(|p| p.1 > 0.0).collect();
                draw_series(&mut chart, s, pts)?;
            }
            legend(&mut chart)
        } else {
            let mut chart = builder
                .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
                .map_err(err)?;
            chart
                .configure_mesh()
                .x_desc(&self.x_label)
                .y_desc(&self.y_label)
                .axis_desc_style((FAMILY, LABEL))
                .label_style((FAMILY, TICK))
                .x_label_formatter(&|v| tick_on(*v, xr.1 - xr.0))
                .y_label_formatter(&|v| tick_on(*v, yr.1 - yr.0))
                .light_line_style(WHITE.mix(0.0))
                .draw()
                .map_err(err)?;
            for s in &self.series {
                draw_series(&mut chart, s, s.points.clone())?;
            }
            legend(&mut chart)
        }
    }
}

/// A tick label on an axis spanning `span`: a tick within 1e-9 of the
/// span of zero is 0 (tick positions computed as sums carry round-off),
/// however small the span (an energy balance of 1e-13 J).
pub fn tick_on(v: f64, span: f64) -> String {
    if v.abs() <= 1e-9 * span.abs() {
        "0".into()
    } else {
        tick(v)
    }
}

/// A number as a label: plain for moderate numbers, exponent form
/// otherwise.
pub fn tick(v: f64) -> String {
    let a = v.abs();
    // Round-off on a unit scale: -1.1e-16 is 0.
    if a < 1e-15 {
        "0".into()
    } else if !(1e-3..1e5).contains(&a) {
        // Three significant digits at most, so that neighbouring ticks
        // (1.06e6, 1.08e6) read apart: "1.1e6" twice would not.
        let s = format!("{v:.2e}");
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    } else {
        let s = format!("{v:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        s.to_string()
    }
}

fn draw_series<'a, DB: DrawingBackend + 'a, X, Y>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
    s: &Series,
    pts: Vec<(f64, f64)>,
) -> DrawResult
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let color = s.color;
    // Thick polylines get miter joints that overshoot at sharp turns: a
    // dense, jagged series (energies of an impact) is drawn one pixel wide
    // so that no spike appears that is not in the data.
    // A dashed series keeps its width: it is drawn over another to show
    // that the two coincide.
    let width = if pts.len() > 300 && !s.dashed {
        1
    } else {
        s.width
    };
    let style = ShapeStyle::from(&color).stroke_width(width);
    let label_style = style;
    // A lone point draws no line: it gets a marker (a static run's one
    // state).
    if s.markers || pts.len() == 1 {
        let anno = chart
            .draw_series(pts.iter().map(|&p| Circle::new(p, 3, color.filled())))
            .map_err(err)?;
        if !s.label.is_empty() {
            anno.label(s.label.clone())
                .legend(move |(x, y)| Circle::new((x + 10, y), 3, color.filled()));
        }
        if pts.len() > 1 {
            chart
                .draw_series(LineSeries::new(
                    pts,
                    ShapeStyle::from(&color.mix(0.5)).stroke_width(1),
                ))
                .map_err(err)?;
        }
        return Ok(());
    }
    let anno = if s.dashed {
        chart
            .draw_series(DashedLineSeries::new(pts, 8, 5, style))
            .map_err(err)?
    } else {
        chart
            .draw_series(LineSeries::new(pts, style))
            .map_err(err)?
    };
    if !s.label.is_empty() {
        anno.label(s.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], label_style));
    }
    Ok(())
}

fn legend<'a, DB: DrawingBackend + 'a, X, Y>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
) -> DrawResult
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.5))
        .label_font((FAMILY, TICK))
        .draw()
        .map_err(err)
}

mod bars;
mod colormap;
pub use bars::Bars;
pub use colormap::{diverging, ColorMap};

/// Panels of curves stacked top to bottom, each with its own y axis (the
/// energies above and the energy balance below, whose scales differ).
#[derive(Clone, Debug)]
pub struct Panels {
    pub panels: Vec<Lines>,
}

impl Figure for Panels {
    fn size(&self) -> (u32, u32) {
        (1000, 380 * self.panels.len().max(1) as u32)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        let areas = root.split_evenly((self.panels.len().max(1), 1));
        for (panel, area) in self.panels.iter().zip(areas.iter()) {
            panel.draw(area)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tick labels read apart (three significant digits in exponent form)
    /// and a small axis keeps its numbers: zero is snapped relative to the
    /// axis' span, not absolutely.
    #[test]
    fn ticks_read_apart_and_small_axes_keep_their_numbers() {
        assert_eq!(tick(1.06e6), "1.06e6");
        assert_eq!(tick(1.08e6), "1.08e6");
        assert_eq!(tick(1.1e6), "1.1e6");
        assert_eq!(tick(-8.35e6), "-8.35e6");
        assert_eq!(tick(0.0025), "0.0025");
        assert_eq!(tick_on(-5e-14, 3e-13), "-5e-14");
        assert_eq!(tick_on(-1.1e-16, 1.0), "0");
        assert_eq!(tick_on(2.0e-23, 3e-13), "0");
    }
}
