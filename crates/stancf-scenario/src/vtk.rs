//! ParaView output (`stancf run --vtk`): one VTK XML PolyData file per
//! written step, `vtk/cable_<k>.vtp`, with the cable (each line of a
//! system, with its id as the point data `line`) as a polyline sampled
//! at [`POINTS_PER_ELEMENT`] points per element and velocity, axial stress,
//! curvature and the material coordinate as point data; and `cable.pvd`,
//! the collection that gives each file its time. ASCII, so that any tool
//! (and a test) can read it back. Each file is written atomically; the
//! collection last, when the run ends. A system with bodies or rods also
//! gets `vtk/bodies_<k>.vtp` per written step (its rods, each body's axes
//! and the spokes to its points, as line cells) and `bodies.pvd`.

use crate::output::{write_atomic, Num};
use stancf::observe::cable_points;
use stancf::{Model, State};
use std::fmt::Write as _;
use std::io;
use std::path::{Path, PathBuf};

/// Points per element of the polyline: 16 follow a bend of the curvature a
/// SAC-3 element can carry to a fraction of a per cent of its radius.
pub const POINTS_PER_ELEMENT: usize = 16;

/// Writes the step files as the run goes and the collection at the end.
pub struct VtkWriter {
    dir: PathBuf,
    /// (t, file name relative to the output folder) of every step written.
    entries: Vec<(f64, String)>,
    /// The same of the bodies' files ([`VtkWriter::write_segments`]).
    body_entries: Vec<(f64, String)>,
}

/// A straight piece of a system's rigid parts in ParaView (`--vtk`,
/// `vtk/bodies_<k>.vtp`): a rod from end A to end B with its radius (for
/// ParaView's Tube filter), a body's axis from its reference point
/// (`axis` 1, 2, 3), or a spoke from its reference point to one of its
/// points; `body` the id of the body it belongs to (0: a fixed rod),
/// `rod` the rod's id (0: not a rod).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub a: [f64; 3],
    pub b: [f64; 3],
    pub body: i64,
    pub rod: i64,
    pub axis: i64,
    pub radius: f64,
}

impl VtkWriter {
    pub fn create(dir: &Path) -> io::Result<Self> {
        std::fs::create_dir_all(dir.join("vtk"))?;
        Ok(VtkWriter {
            dir: dir.to_path_buf(),
            entries: Vec::new(),
            body_entries: Vec::new(),
        })
    }

    /// One written step of a single cable.
    pub fn write(&mut self, model: &Model, state: &State) -> io::Result<()> {
        self.write_lines(state.t, &[(model, state)], None)
    }

    /// One written step of lines: one polyline per line (a system's, with
    /// the point data `line`, each point's line id from `ids`).
    pub fn write_lines(
        &mut self,
        t: f64,
        lines: &[(&Model, &State)],
        ids: Option<&[i64]>,
    ) -> io::Result<()> {
        let mut points = Vec::new();
        let mut ends = Vec::with_capacity(lines.len());
        let mut line_of_point = Vec::new();
        for (i, (model, state)) in lines.iter().enumerate() {
            points.extend(cable_points(model, state, POINTS_PER_ELEMENT));
            ends.push(points.len());
            line_of_point.resize(points.len(), ids.map_or(0, |ids| ids[i]));
        }
        let finite = points.iter().all(|p| {
            p.r.iter().chain(p.v.iter()).all(|x| x.is_finite())
                && p.axial_stress.is_finite()
                && p.curvature.is_finite()
        });
        if !finite {
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                format!("non-finite result at t = {t}"),
            ));
        }
        let n = points.len();
        let mut x = String::with_capacity(200 * n);
        polydata_head(&mut x, t, n, lines.len());
        x.push_str("<PointData Scalars=\"axial_stress\" Vectors=\"velocity\">\n");
        array3(&mut x, "velocity", points.iter().map(|p| p.v));
        array1(
            &mut x,
            "axial_stress",
            points.iter().map(|p| p.axial_stress),
        );
        array1(&mut x, "curvature", points.iter().map(|p| p.curvature));
        array1(&mut x, "s", points.iter().map(|p| p.s));
        if ids.is_some() {
            array1(&mut x, "line", line_of_point.iter().map(|&id| id as f64));
        }
        x.push_str("</PointData>\n<Points>\n");
        array3(&mut x, "position", points.iter().map(|p| p.r));
        x.push_str("</Points>\n<Lines>\n");
        x.push_str("<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
        for i in 0..n {
            write!(x, "{i} ").ok();
        }
        x.push_str("\n</DataArray>\n");
        let offsets: Vec<String> = ends.iter().map(|e| e.to_string()).collect();
        writeln!(
            x,
            "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">{}</DataArray>",
            offsets.join(" ")
        )
        .ok();
        x.push_str("</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n");
        let name = format!("cable_{:06}.vtp", self.entries.len());
        write_atomic(&self.dir.join("vtk"), &name, x.as_bytes())?;
        self.entries.push((t, format!("vtk/{name}")));
        Ok(())
    }

    /// One written step of a system's bodies and rods: `vtk/bodies_<k>.vtp`,
    /// one line cell per [`Segment`], with the cell data `body`, `rod`,
    /// `axis` and `radius`.
    pub fn write_segments(&mut self, t: f64, segments: &[Segment]) -> io::Result<()> {
        let finite = segments
            .iter()
            .all(|s| s.a.iter().chain(&s.b).all(|x| x.is_finite()) && s.radius.is_finite());
        if !finite {
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                format!("non-finite body or rod at t = {t}"),
            ));
        }
        let n = segments.len();
        let mut x = String::with_capacity(300 * n + 600);
        polydata_head(&mut x, t, 2 * n, n);
        x.push_str("<CellData Scalars=\"radius\">\n");
        array1(&mut x, "body", segments.iter().map(|s| s.body as f64));
        array1(&mut x, "rod", segments.iter().map(|s| s.rod as f64));
        array1(&mut x, "axis", segments.iter().map(|s| s.axis as f64));
        array1(&mut x, "radius", segments.iter().map(|s| s.radius));
        x.push_str("</CellData>\n<Points>\n");
        array3(&mut x, "position", segments.iter().flat_map(|s| [s.a, s.b]));
        x.push_str("</Points>\n<Lines>\n");
        x.push_str("<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
        for i in 0..2 * n {
            write!(x, "{i} ").ok();
        }
        x.push_str("\n</DataArray>\n");
        let offsets: Vec<String> = (1..=n).map(|k| (2 * k).to_string()).collect();
        writeln!(
            x,
            "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">{}</DataArray>",
            offsets.join(" ")
        )
        .ok();
        x.push_str("</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n");
        let name = format!("bodies_{:06}.vtp", self.body_entries.len());
        write_atomic(&self.dir.join("vtk"), &name, x.as_bytes())?;
        self.body_entries.push((t, format!("vtk/{name}")));
        Ok(())
    }

    /// The collections: `cable.pvd`, and `bodies.pvd` where bodies or
    /// rods were written.
    pub fn commit(self) -> io::Result<()> {
        if !self.body_entries.is_empty() {
            write_atomic(
                &self.dir,
                "bodies.pvd",
                collection(&self.body_entries).as_bytes(),
            )?;
        }
        write_atomic(&self.dir, "cable.pvd", collection(&self.entries).as_bytes())
    }
}

/// The head of a PolyData file of `points` points and `lines` line cells
/// at time t: the XML declaration, the time as field data (read by VTK
/// as TimeValue) and the piece's counts.
fn polydata_head(x: &mut String, t: f64, points: usize, lines: usize) {
    x.push_str("<?xml version=\"1.0\"?>\n");
    x.push_str(
        "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n",
    );
    writeln!(
        x,
        "<FieldData>\n<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" \
         format=\"ascii\">{}</DataArray>\n</FieldData>",
        Num(t)
    )
    .ok();
    writeln!(
        x,
        "<Piece NumberOfPoints=\"{points}\" NumberOfVerts=\"0\" NumberOfLines=\"{lines}\" \
         NumberOfStrips=\"0\" NumberOfPolys=\"0\">"
    )
    .ok();
}

/// A VTK collection of the files `entries` (time, file).
fn collection(entries: &[(f64, String)]) -> String {
    let mut x = String::from("<?xml version=\"1.0\"?>\n");
    x.push_str(
        "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n",
    );
    for (t, file) in entries {
        writeln!(
            x,
            "<DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{file}\"/>",
            Num(*t)
        )
        .ok();
    }
    x.push_str("</Collection>\n</VTKFile>\n");
    x
}

fn array1(x: &mut String, name: &str, values: impl Iterator<Item = f64>) {
    writeln!(
        x,
        "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">"
    )
    .ok();
    for v in values {
        write!(x, "{} ", Num(v)).ok();
    }
    x.push_str("\n</DataArray>\n");
}

fn array3(x: &mut String, name: &str, values: impl Iterator<Item = [f64; 3]>) {
    writeln!(
        x,
        "<DataArray type=\"Float64\" Name=\"{name}\" NumberOfComponents=\"3\" format=\"ascii\">"
    )
    .ok();
    for v in values {
        writeln!(x, "{} {} {}", Num(v[0]), Num(v[1]), Num(v[2])).ok();
    }
    x.push_str("</DataArray>\n");
}
