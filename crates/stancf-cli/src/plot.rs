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

static FONT: &[u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");
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
                        tick(*v)
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
                .x_label_formatter(&|v| tick(*v))
                .y_label_formatter(&|v| tick(*v))
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

/// A tick label: plain for moderate numbers, exponent form otherwise.
pub fn tick(v: f64) -> String {
    let a = v.abs();
    // Tick positions computed as sums carry round-off: -1.1e-16 is 0.
    if a < 1e-12 {
        "0".into()
    } else if !(1e-3..1e5).contains(&a) {
        format!("{v:.1e}")
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
    let width = if pts.len() > 300 { 1 } else { s.width };
    let style = ShapeStyle::from(&color).stroke_width(width);
    let label_style = style;
    if s.markers {
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
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
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
            .y_label_formatter(&|v| tick(*v))
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
            .y_label_formatter(&|v| tick(*v))
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
