//! The library's system from a [`SystemScenario`]: every line a cable
//! model of its line type's section under its loads (gravity, and in
//! water the water's load and the seabed), every point and body a
//! library point and body, and the seed of the static solve
//! (docs/method.md §11.6).

use super::system_parts::{LineType, PointType, SystemPoint, SystemScenario};
use super::water::Water;
use stancf::body::{BodyWater, RigidInertia};
use stancf::system::{Body, BodyKind, End, Line, LineSection, Point, PointKind, System};
use stancf::vec3::norm;
use stancf::water::{LineInWater, Morison};
use stancf::{Cable, Load, Model, ModelError, ModelOptions};
use std::sync::Arc;

/// The loads a line model is built with.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Loads {
    /// Gravity on the line's mass, and in water the water's load (its
    /// buoyancy, drag and inertia) and the seabed: the system simulated.
    Full,
    /// Gravity scaled to the line's wet weight, nothing else: the system
    /// whose elastic catenaries seed the static solve.
    WetWeight,
}

pub use stancf::system::EI_FACTOR;

impl SystemScenario {
    /// The static solve's settings: the analysis's, with what the
    /// seabed's friction holds at the equilibrium (`[water.seabed]
    /// static_friction`, docs/method.md §12.2).
    pub fn static_settings(&self) -> stancf::StaticSettings {
        let mut settings = self.analysis.static_settings();
        if let Some(w) = &self.water {
            settings.seabed_friction = w.seabed.static_friction;
        }
        settings
    }

    /// The bending stiffness line i is simulated with: its type's EI, or
    /// for EI = 0 (chain, wire rope) the core's c w L^3
    /// ([`stancf::system::LineSection::bending_stiffness`],
    /// docs/method.md §11.7, (M33)) with w its (wet) weight per length.
    pub fn bending_stiffness(&self, line: usize) -> f64 {
        let l = &self.lines[line];
        let t = &self.line_types[l.line_type];
        let g = self.gravity.iter().map(|g| g * g).sum::<f64>().sqrt();
        section(t).bending_stiffness(t.ei, l.length, g, self.wet_weight_fraction(t))
    }

    /// The axial damping BA (N s) line i is simulated with: its type's
    /// `ba`, or for `ba` < 0 MoorDyn's damping ratio with the line's
    /// element length ([`stancf::system::LineSection::axial_damping`],
    /// docs/method.md §2.10, (M36)).
    pub fn axial_damping(&self, line: usize) -> f64 {
        let l = &self.lines[line];
        let t = &self.line_types[l.line_type];
        section(t).axial_damping(t.ba, l.length / l.elements as f64)
    }

    /// The fraction of a line's weight left in the scenario's water (1 in
    /// air; [`stancf::system::LineSection::wet_weight_fraction`]).
    pub fn wet_weight_fraction(&self, t: &LineType) -> f64 {
        section(t).wet_weight_fraction(self.water.as_ref().map(|w| w.density))
    }

    /// The library's system: the lines' models (their reference shapes
    /// straight between their end points) and the points.
    pub fn system(&self) -> Result<System, ModelError> {
        self.system_with(Loads::Full)
    }

    /// The system whose lines' catenaries seed the static solve: the
    /// system itself in air; in water, its lines under their wet weight
    /// (their wet weight (m - rho_w A) g: the weight a fully submerged line
    /// hangs by; [`stancf::system::SystemStatics::seeded`]).
    pub fn seed_system(&self) -> Result<System, ModelError> {
        match self.water {
            None => self.system_with(Loads::Full),
            Some(_) => self.system_with(Loads::WetWeight),
        }
    }

    fn system_with(&self, loads: Loads) -> Result<System, ModelError> {
        let water = match (&self.water, loads) {
            (Some(w), Loads::Full) => Some(Arc::new(w.library(norm(self.gravity))?)),
            _ => None,
        };
        let points: Vec<Point> = self
            .points
            .iter()
            .map(|p| library_point(p, self.water.as_ref(), water.as_ref(), self.gravity))
            .collect();
        let lines = self
            .lines
            .iter()
            .enumerate()
            .map(|(i, l)| {
                let model = self
                    .line_model(i, &points, loads, water.as_ref())
                    .map_err(|e| e.under(&format!("lines[{i}]")))?;
                let ends = l.ends.map(|e| e.map_or(End::Loose, End::Point));
                let mut line = Line { model, ends };
                for (end, d) in l.clamps.iter().enumerate() {
                    if let Some(d) = d {
                        line = line
                            .clamped(end, *d)
                            .map_err(|e| e.under(&format!("lines[{i}]")))?;
                    }
                }
                Ok(line)
            })
            .collect::<Result<Vec<_>, ModelError>>()?;
        let bodies = (0..self.bodies.len())
            .map(|b| self.library_body(b, water.as_ref()))
            .collect();
        let system = System::with_bodies(lines, points, bodies, self.gravity)
            .map_err(|e| super::rods::rod_error(self, e))?;
        // A host that sets the waves is asked in MoorDyn's order.
        match &self.water {
            Some(w) if w.host_waves && water.is_some() => {
                system.with_host_order(super::host_order::host_order(self))
            }
            _ => Ok(system),
        }
    }

    /// The library's body: in water, a free body's volume, added mass and
    /// drag with the water's density; a steady uniform current as the
    /// body's own (its added mass then sees the water's velocity,
    /// docs/method.md §15.6), any other flow (waves, a current that varies
    /// with depth or that a ramp starts) as the sea the body is in
    /// (`water`, the lines' sea: §15.15); its rods (a free rod's body: the
    /// rod), which the core folds in; a pinned rod's body's pin. The
    /// static seed's system (no `water`) sees the steady uniform current.
    fn library_body(&self, i: usize, water: Option<&Arc<stancf::water::Water>>) -> Body {
        let b = &self.bodies[i];
        if let Some(axis) = b.connector_axis {
            return Body::connector(b.position, axis);
        }
        let (kind, inertia) = match b.kind {
            super::BodyType::Free => (
                BodyKind::Free,
                RigidInertia::principal(b.mass, b.centre_of_mass, b.moments),
            ),
            // A fixed body's inertia is not used (its points are fixed),
            // nor a coupled body's (the host's; its points are coupled).
            super::BodyType::Fixed => (
                BodyKind::Fixed,
                RigidInertia::principal(0.0, [0.0; 3], [0.0; 3]),
            ),
            super::BodyType::Coupled => (
                BodyKind::Coupled,
                RigidInertia::principal(0.0, [0.0; 3], [0.0; 3]),
            ),
        };
        let mut body = Body::new(kind, b.position, b.rotation(), inertia);
        body.velocity = b.velocity;
        body.angular_velocity = b.angular_velocity;
        if b.force != [0.0; 3] {
            body.loads.push((b.force, [0.0; 3]));
        }
        body.moment = b.moment;
        // A coupled body's water is its rods' (its own volume, Ca and CdA
        // are zero, as MoorDyn zeroes them): what they push the host with.
        body.water = match (&self.water, b.kind) {
            (Some(w), super::BodyType::Free | super::BodyType::Coupled) => Some(BodyWater {
                density: w.density,
                volume: b.volume,
                added_mass_coefficients: b.ca,
                drag_areas: b.drag_areas,
                rotational_drag_areas: b.rotational_drag_areas,
                current: match steady_uniform_current(w) {
                    Some(c) => c,
                    None if water.is_some() => [0.0; 3],
                    None => super::bodies::uniform_current(w).unwrap_or([0.0; 3]),
                },
                rods: Vec::new(),
                // The system's g, set with the rods (System::with_bodies).
                gravity: 0.0,
                sea: match (steady_uniform_current(w), water) {
                    (None, Some(lw)) => Some(Arc::new(lw.sea.clone())),
                    _ => None,
                },
                external: external_of(b),
                host: None,
            }),
            // In air, a free body's external loads in a water of density 0
            // (they are carried with the water's loads, docs/method.md
            // §15.21).
            (None, super::BodyType::Free) if !external_of(b).is_zero() => Some(BodyWater {
                external: external_of(b),
                ..BodyWater::default()
            }),
            _ => None,
        };
        body.rods = super::rods::rods_of_body(self, i);
        body.pin = super::rods::pin_of_body(self, i);
        // A CoupledPinned body: its reference point on the host's point.
        if let Some(point) = b.host_pin {
            body.pin = Some(stancf::system::Pin {
                local: [0.0; 3],
                point,
            });
        }
        // A rod at a joint starts moving with its host's point there.
        if let Some((h, local)) = super::rods::joint_host(self, i) {
            let host = &self.bodies[h];
            let arm = stancf::body::pose::rotate(&host.rotation(), local);
            body.velocity = stancf::vec3::add(
                host.velocity,
                stancf::vec3::cross(host.angular_velocity, arm),
            );
        }
        body
    }

    /// Line i's cable model: its type's section over the area pi d^2 / 4,
    /// its reference straight from end A toward end B (from a loose end A
    /// down along gravity to B), under `loads` ([`Loads`]; `water` the
    /// library's water of [`Loads::Full`]). The start shapes are the
    /// library's ([`stancf::system::straight_states`],
    /// [`stancf::system::catenary_states`]).
    fn line_model(
        &self,
        i: usize,
        points: &[Point],
        loads: Loads,
        water: Option<&Arc<stancf::water::Water>>,
    ) -> Result<Model, ModelError> {
        let l = &self.lines[i];
        let t = &self.line_types[l.line_type];
        let at = |e: Option<usize>| e.map(|p| points[p].state_at(0.0).0);
        let down = if self.gravity == [0.0; 3] {
            [0.0, 0.0, -1.0]
        } else {
            self.gravity
        };
        let (origin, direction) = match (at(l.ends[0]), at(l.ends[1])) {
            (Some(a), Some(b)) => (a, std::array::from_fn(|k| b[k] - a[k])),
            (Some(a), None) => (a, down),
            (None, Some(b)) => {
                let n = down.iter().map(|c| c * c).sum::<f64>().sqrt();
                (std::array::from_fn(|k| b[k] - l.length * down[k] / n), down)
            }
            (None, None) => unreachable!("a line has an attached end (checked on reading)"),
        };
        let direction = if direction == [0.0; 3] {
            down
        } else {
            direction
        };
        let cable = Cable::straight(l.length, l.elements, l.element_type)
            .with_origin(origin)
            .with_direction(direction)
            .with_grading(l.grading.clone());
        // A viscoelastic line's BA is its law's static dashpot (§2.11).
        let law = super::visco_types::line_law(t, self.axial_damping(i), l.tmax0);
        let kelvin_voigt = if law.is_some() {
            0.0
        } else {
            self.axial_damping(i)
        };
        let material = section(t)
            .material(self.bending_stiffness(i))
            .with_axial_damping(kelvin_voigt);
        let options = ModelOptions {
            measures: self.measures,
            space_points: self.analysis.space_points,
        };
        let scale = match loads {
            Loads::Full => 1.0,
            Loads::WetWeight => self.wet_weight_fraction(t),
        };
        let acceleration = self.gravity.map(|g| g * scale);
        let mut line_loads = if acceleration == [0.0; 3] {
            vec![]
        } else {
            vec![Load::Gravity { acceleration }]
        };
        if let Some(w) = &self.water {
            if let Some(fluid) = water {
                line_loads.push(Load::Water(LineInWater::new(Arc::clone(fluid), morison(t))));
            }
            // The seed's lines see the bed too: they start resting on it.
            line_loads.push(Load::Seabed(w.seabed_contact(t.diameter)));
        }
        let mut model = Model::new(cable, material, options, line_loads)?;
        if let Some(curve) = &t.ea_curve {
            model = model.with_axial_curve(Arc::clone(curve))?;
        }
        if let Some(law) = law {
            model = model.with_viscoelastic(law)?;
        }
        // The VIV lift acts in water (docs/method.md §12.7), in dynamics.
        if let (Some(viv), Some(_)) = (&t.viv, water) {
            model = model.with_viv(viv.clone())?;
        }
        Ok(if t.compression {
            model
        } else {
            model.without_compression()
        })
    }
}

/// A line type's Morison coefficients as the deck or `[[line_types]]`
/// gives them (MoorDyn's Cd on d, CdAx on pi d, Ca, CaAx).
fn morison(t: &LineType) -> Morison {
    Morison {
        diameter: t.diameter,
        cd_normal: t.cd_normal,
        cd_axial: t.cd_axial,
        ca_normal: t.ca_normal,
        ca_axial: t.ca_axial,
    }
}

/// The library's point (a point on a body where the body puts it at
/// t = 0). In water (`fluid`: the library's water) a free
/// point carries its volume's buoyancy, drag on its CdA, the fluid's
/// inertia and its added mass Ca rho_w V (docs/method.md §12.6); for the
/// wet-weight seed (water given, `fluid` None) its buoyancy is a constant
/// force -rho_w V g.
fn library_point(
    p: &SystemPoint,
    water: Option<&Water>,
    fluid: Option<&Arc<stancf::water::Water>>,
    gravity: [f64; 3],
) -> Point {
    match p.kind {
        PointType::Fixed => Point::fixed(p.position),
        // At its position at t = 0 already: the lines' models start there.
        // Its mass, force and volume become the body's (the core folds
        // them, docs/method.md §15.8).
        PointType::Body { body, local } => {
            let (mass, force, water) = own_loads(p, water, fluid, gravity, false);
            Point {
                position: p.position,
                mass,
                force,
                water,
                ..Point::on_body(body, local)
            }
        }
        PointType::Coupled => Point::coupled(p.position, p.motion.clone()),
        PointType::Free => {
            let (mass, force, water) = own_loads(p, water, fluid, gravity, true);
            Point {
                kind: PointKind::Free,
                position: p.position,
                mass,
                force,
                water,
                damping: p.damping,
            }
        }
    }
}

/// A body's external loads at its reference point (MoorDyn-F's EXTERNAL
/// LOADS): its force in body axes and its damping (a global force is one
/// of its constant loads).
fn external_of(b: &super::SystemBody) -> stancf::body::BodyExternal {
    stancf::body::BodyExternal {
        body_force: b.body_force,
        global: b.damping,
        body: b.body_damping,
    }
}

/// A point's own mass, force and water: in water (`fluid`) its volume's
/// buoyancy, drag and added mass (a free point's always, `always`; a
/// body's point's only if it has any); for the wet-weight seed (water
/// given, `fluid` None) its buoyancy as a constant force -rho_w V g.
fn own_loads(
    p: &SystemPoint,
    water: Option<&Water>,
    fluid: Option<&Arc<stancf::water::Water>>,
    gravity: [f64; 3],
    always: bool,
) -> (f64, [f64; 3], Option<stancf::water::PointInWater>) {
    let in_water = fluid
        .filter(|_| always || p.volume != 0.0 || p.drag_area != 0.0 || p.ca != 0.0)
        .map(|f| stancf::water::PointInWater {
            water: Arc::clone(f),
            volume: p.volume,
            drag_area: p.drag_area,
            ca: p.ca,
            host: None,
        });
    let buoyancy = match (water, &in_water) {
        (Some(w), None) => w.density * p.volume,
        _ => 0.0,
    };
    let force = std::array::from_fn(|k| p.force[k] - buoyancy * gravity[k]);
    (p.mass, force, in_water)
}

/// The core's section of a line type (A = pi d^2 / 4 of its diameter).
fn section(t: &LineType) -> LineSection {
    LineSection {
        area: t.area(),
        mass_per_length: t.mass_per_length,
        ea: t.ea,
    }
}

/// The water's current if the only flow is a steady current the same at
/// every depth (zero in still water): no waves, no current ramp. None
/// where a body must see the sea's flow where it is (§15.15).
fn steady_uniform_current(w: &super::water::Water) -> Option<[f64; 3]> {
    // A host's waves are the sea's, whose flow the body takes (W2h).
    let waves = !w.waves.is_empty() || w.jonswap.is_some() || w.host_waves;
    let ramped = w.current.as_ref().is_some_and(|c| c.ramp > 0.0);
    if waves || ramped {
        return None;
    }
    super::bodies::uniform_current(w)
}
