//! The catenary network's unknowns (free points, free bodies and the
//! bodies riding with them at joints) and its imbalance G (docs/method.md §11.6,
//! (M32a)): each free point's load, its lines' catenary end forces and
//! the seabed's push; each free body's (and its riders', §15.14) weight,
//! buoyancy, constant loads and moment and its lines' end forces, in
//! force and moment about its centre; the heading springs of assemblies
//! that turn freely about the vertical. Newton on G is `balance.rs`.

use super::seed::{end_positions_at, seed_shape_capped};
use super::{End, System};
use crate::body::pose::Pose;

/// The body that free body b hangs from through its joints, at their
/// top (b itself when it hangs from none).
pub(super) fn joint_root(system: &System, mut b: usize) -> usize {
    for _ in 0..system.bodies().len() {
        match system.joint_parent(b) {
            Some(parent) => b = parent,
            None => break,
        }
    }
    b
}

/// Body c's pose when it rides with body `root` at `pose`: as it is
/// given relative to the root's given pose.
fn rider_pose(system: &System, root: usize, (r, rotation): Pose, c: usize) -> Pose {
    use crate::body::pose::rotate;
    use crate::vec3::{add, mat3_mul, mat3_transpose, sub};
    let (b0, c0) = (&system.bodies()[root], &system.bodies()[c]);
    let back = mat3_transpose(&b0.rotation);
    let turned = mat3_mul(&back, &c0.rotation);
    let offset = rotate(&back, sub(c0.position, b0.position));
    (
        add(r, rotate(&rotation, offset)),
        mat3_mul(&rotation, &turned),
    )
}

/// The unknowns of (M32a): the free points' coordinates (3 each), then
/// the free bodies' centres and rotation vectors (6 each).
#[derive(Clone)]
pub(super) struct Network {
    pub free: Vec<usize>,
    pub bodies: Vec<usize>,
    /// The bodies hanging at joints from body k (at any depth), riding
    /// with it ([`rider_pose`]).
    pub riders: Vec<Vec<usize>>,
    /// Body k's heading spring (N m/rad) where its assembly turns freely
    /// about the vertical ([`super::body_holds::yaw_hold`]).
    pub yaw_springs: Vec<Option<f64>>,
    /// The largest EA the lines' closed forms take (infinite: their own):
    /// the softened network of the stiffness continuation (§11.6).
    pub ea_cap: f64,
}

impl Network {
    pub(super) fn size(&self) -> usize {
        3 * self.free.len() + 6 * self.bodies.len()
    }

    /// The unknowns where the system puts the points and bodies.
    pub(super) fn start(&self, system: &System, positions: &[[f64; 3]]) -> Vec<f64> {
        let mut x: Vec<f64> = self.free.iter().flat_map(|&p| positions[p]).collect();
        for &b in &self.bodies {
            let body = &system.bodies()[b];
            let mut centre = body.point(body.inertia.centre_of_mass);
            // A body floating on its rods alone starts at its draft.
            if let Some(z) = super::body_holds::floating_height(system, b) {
                centre[2] += z - body.position[2];
            }
            x.extend(centre);
            x.extend([0.0; 3]);
        }
        x
    }

    /// Body k's reference point and rotation at x.
    pub(super) fn pose(&self, system: &System, x: &[f64], k: usize) -> Pose {
        let body = &system.bodies()[self.bodies[k]];
        let o = 3 * self.free.len() + 6 * k;
        let phi = [x[o + 3], x[o + 4], x[o + 5]];
        let rotation = crate::vec3::mat3_mul(&crate::body::rotation::exp_map(phi), &body.rotation);
        let arm = crate::body::pose::rotate(&rotation, body.inertia.centre_of_mass);
        (crate::vec3::sub([x[o], x[o + 1], x[o + 2]], arm), rotation)
    }

    /// Body k and its riders, each with its pose at x.
    pub(super) fn members(&self, system: &System, x: &[f64], k: usize) -> Vec<(usize, Pose)> {
        let (b, pose) = (self.bodies[k], self.pose(system, x, k));
        std::iter::once((b, pose))
            .chain(
                self.riders[k]
                    .iter()
                    .map(|&c| (c, rider_pose(system, b, pose, c))),
            )
            .collect()
    }

    /// The network's body k of which body b is a member, if any.
    pub(super) fn holding(&self, b: usize) -> Option<usize> {
        (0..self.bodies.len()).find(|&k| self.bodies[k] == b || self.riders[k].contains(&b))
    }

    /// Writes the free points' and the bodies' (and riders') points'
    /// positions at x.
    pub(super) fn place(&self, system: &System, x: &[f64], positions: &mut [[f64; 3]]) {
        for (k, &p) in self.free.iter().enumerate() {
            positions[p] = [x[3 * k], x[3 * k + 1], x[3 * k + 2]];
        }
        for k in 0..self.bodies.len() {
            for (b, (r, rotation)) in self.members(system, x, k) {
                for &(p, local) in system.body_points(b) {
                    positions[p] = crate::body::pose::point(r, &rotation, local);
                }
            }
        }
    }
}

/// G(x) of (M32a) with the free points and bodies at `x` (the points
/// written into `positions`), and the scale of the forces at play (the
/// largest load or end force); None if a line has a non-finite force.
pub(super) fn imbalance(
    system: &System,
    net: &Network,
    positions: &mut [[f64; 3]],
    x: &[f64],
) -> Option<(Vec<f64>, f64)> {
    let free = &net.free;
    net.place(system, x, positions);
    let mut g = vec![0.0; x.len()];
    let mut scale = 0.0f64;
    // Where a force at point p goes: a free point's 3 rows, or a body's
    // force and its moment about the body's centre (k, its centre).
    let mut centres = Vec::with_capacity(net.bodies.len());
    for k in 0..net.bodies.len() {
        let o = 3 * free.len() + 6 * k;
        let mut root_centre = None;
        for (b, pose) in net.members(system, x, k) {
            let body = &system.bodies()[b];
            let centre = crate::body::pose::point(pose.0, &pose.1, body.inertia.centre_of_mass);
            let about = *root_centre.get_or_insert(centre);
            add_body_loads(system, b, pose, (o, about), &mut g, &mut scale);
        }
        centres.push(root_centre.expect("a body"));
        // The rotation vector is global (R = exp([phi]) R_0): the heading
        // is its vertical component.
        if let Some(k_yaw) = net.yaw_springs[k] {
            g[o + 5] -= k_yaw * x[o + 5];
        }
    }
    let body_of = |p: usize| system.points()[p].body().and_then(|b| net.holding(b));
    let slot = |p: usize| free.iter().position(|&q| q == p);
    for (k, &p) in free.iter().enumerate() {
        let mut f = system.point_load(p);
        if let Some(water) = &system.points()[p].water {
            let drag = water.static_force(&positions[p]).force;
            for c in 0..3 {
                f[c] += drag[c];
            }
        }
        let bed = bed_reaction(system, p, positions[p]);
        for c in 0..3 {
            g[3 * k + c] += f[c] + bed[c];
            scale = scale.max(f[c].abs());
        }
    }
    for (li, line) in system.lines().iter().enumerate() {
        let ends: Vec<(usize, usize)> = line
            .ends
            .iter()
            .enumerate()
            .filter_map(|(end, e)| match e {
                End::Point(p) if slot(*p).is_some() || body_of(*p).is_some() => Some((end, *p)),
                _ => None,
            })
            .collect();
        if ends.is_empty() {
            continue;
        }
        let (a, b) = end_positions_at(system, li, positions);
        let shape = seed_shape_capped(system, li, a, b, net.ea_cap);
        for (end, p) in ends {
            let f = shape.end_force(end);
            if f.iter().any(|v| !v.is_finite()) {
                return None;
            }
            if let Some(k) = slot(p) {
                for c in 0..3 {
                    g[3 * k + c] += f[c];
                    scale = scale.max(f[c].abs());
                }
            } else if let Some(k) = body_of(p) {
                let o = 3 * free.len() + 6 * k;
                add_at(
                    &mut g,
                    o,
                    f,
                    crate::vec3::sub(positions[p], centres[k]),
                    &mut scale,
                );
            }
        }
    }
    Some((g, scale.max(f64::MIN_POSITIVE)))
}

/// Adds body b's own loads at `pose` to the rows at o of the network's
/// body whose centre is `about` (b's own, or that of the body it rides
/// with): its weight and buoyancy at its centre of mass, its constant
/// loads and moment, its rods' buoyancy (B20).
fn add_body_loads(
    system: &System,
    b: usize,
    (r, rotation): Pose,
    (o, about): (usize, [f64; 3]),
    g: &mut [f64],
    scale: &mut f64,
) {
    let body = &system.bodies()[b];
    let centre = crate::body::pose::point(r, &rotation, body.inertia.centre_of_mass);
    let (volume, density) = body
        .water
        .as_ref()
        .map_or((0.0, 0.0), |w| (w.volume, w.density));
    let net_weight = system
        .gravity()
        .map(|gc| (body.inertia.mass - density * volume) * gc);
    let mut loads = vec![(net_weight, centre)];
    for &(f, local) in &body.loads {
        loads.push((f, crate::body::pose::point(r, &rotation, local)));
    }
    for (f, at) in loads {
        add_at(g, o, f, crate::vec3::sub(at, about), scale);
    }
    for c in 0..3 {
        g[o + 3 + c] += body.moment[c];
    }
    if let Some(water) = body.water.as_ref().filter(|w| !w.rods.is_empty()) {
        let ctx = crate::body::terms::Context {
            mass: 0.0,
            inertia_at_centre: &[[0.0; 3]; 3],
            centre_of_mass: body.inertia.centre_of_mass,
            rotation_a: &rotation,
            loads: &[],
            water: Some(water),
            time: crate::body::flow::FlowTime::Steady,
        };
        // Its force at its centre, with its moment about it.
        let (f, m) = ctx.buoyancy_at(centre);
        add_at(g, o, f, crate::vec3::sub(centre, about), scale);
        for c in 0..3 {
            g[o + 3 + c] += m[c];
        }
    }
}

/// The most the lines at a free point may pull with (their end forces
/// and weights in water), as a fraction of its imbalance, for
/// [`slide_slack_points`] to slide it: lines that light hold the point
/// only once one of them is nearly straight (its sag under its weight a
/// fraction of a per cent of its length when it carries the load).
const SLACK_PULL: f64 = 1e-2;

/// Slides each free point that its lines hardly pull (every line at it
/// slack, none straight, and next to weightless in water, end forces and weights
/// within [`SLACK_PULL`] of the point's imbalance: the network's closed
/// forms give it next to no stiffness, so Newton on (M32a) has no
/// direction to move it in) along its imbalance G_p (its load and the bed's push),
/// within the bed's tangent plane where G_p pushes into the bed it
/// rests on, to where the first of its lines is straight between its
/// ends, stopping on the bed where the slide meets it and sliding on
/// along it (docs/method.md (M32e)):
///
/// ```text
///   P' = P + s d,   s = min over lines j > 0 of |P + s d - A_j| = L_j,   d = G_t / |G_t|
/// ```
///
/// (A_j the line's other end, L_j its length). The point then hangs on a
/// line that pulls, and Newton takes it the rest of the way. MoorDyn's
/// seafloor.txt: a 10 kg point on a bed of slope 0.2, its neutrally
/// buoyant 32 m line slack, slides 16.9 m down the slope.
pub(super) fn slide_slack_points(system: &System, net: &Network, positions: &mut [[f64; 3]]) {
    // The imbalance at the points as given (its own copy: the network's
    // start places bodies' points where their poses are not returned).
    let x = net.start(system, positions);
    let Some((g, _)) = imbalance(system, net, &mut positions.to_vec(), &x) else {
        return;
    };
    for (k, &p) in net.free.iter().enumerate() {
        let load = crate::vec3::norm([g[3 * k], g[3 * k + 1], g[3 * k + 2]]);
        // What the lines at p can pull with: their end forces there and
        // their weights in water; a line already straight pulls as its
        // stretch says, and Newton sees it.
        let mut pull = 0.0;
        let mut others = Vec::new();
        let mut straight = false;
        for (li, end) in system.attachments(p) {
            let (a, b) = end_positions_at(system, li, positions);
            let shape = seed_shape_capped(system, li, a, b, f64::INFINITY);
            let model = &system.lines()[li].model;
            let weight = model.material.section().rho_a
                * crate::vec3::norm(model.gravity)
                * model.cable.length;
            pull += crate::vec3::norm(shape.end_force(end)) + weight.abs();
            let other = if end == 0 { b } else { a };
            straight |= crate::vec3::norm(crate::vec3::sub(a, b)) >= model.cable.length;
            others.push((other, model.cable.length));
        }
        if others.is_empty() || straight || pull > SLACK_PULL * load {
            continue;
        }
        let imbalance = [g[3 * k], g[3 * k + 1], g[3 * k + 2]];
        let mut at = positions[p];
        // Along the imbalance, on the bed where the point rests on it; a
        // point above the bed that would pass through it stops there and
        // slides on along it.
        for _ in 0..2 {
            let Some(d) = slide_direction(imbalance, bed_under(system, p, at)) else {
                break;
            };
            let s = first_straight(at, d, &others);
            if !s.is_finite() {
                break;
            }
            match bed_crossing(system, p, at, d, s) {
                Some(s_bed) => at = crate::vec3::add(at, crate::vec3::scale(s_bed, d)),
                None => {
                    at = crate::vec3::add(at, crate::vec3::scale(s, d));
                    break;
                }
            }
        }
        positions[p] = at;
    }
}

/// The unit direction a point slides in under `imbalance`: along it, or
/// along its part in the bed's tangent plane where it pushes into the
/// bed of normal `bed` the point rests on; None where that is zero.
fn slide_direction(imbalance: [f64; 3], bed: Option<[f64; 3]>) -> Option<[f64; 3]> {
    let mut d = imbalance;
    if let Some(n) = bed {
        let into = crate::vec3::dot(d, n);
        if into < 0.0 {
            d = crate::vec3::sub(d, crate::vec3::scale(into, n));
        }
    }
    let size = crate::vec3::norm(d);
    (size > 0.0 && size.is_finite()).then(|| crate::vec3::scale(1.0 / size, d))
}

/// The distance s > 0 along unit `d` from `at` at which the first of the
/// lines (their other ends and lengths) is straight, |at + s d - A| = L;
/// infinite if none.
fn first_straight(at: [f64; 3], d: [f64; 3], others: &[([f64; 3], f64)]) -> f64 {
    others
        .iter()
        .filter_map(|&(other, length)| {
            let r = crate::vec3::sub(at, other);
            let half_b = crate::vec3::dot(r, d);
            let c = crate::vec3::dot(r, r) - length * length;
            let disc = half_b * half_b - c;
            (disc >= 0.0).then(|| -half_b + disc.sqrt())
        })
        .filter(|&s| s > 0.0)
        .fold(f64::INFINITY, f64::min)
}

/// Where a point above the bed (of a line at p) sliding from `at` along
/// `d` meets it before `s_end`: the distance, by bisection of the
/// penetration (to 1e-12 of the slide); None if the point rests on the
/// bed already or is above it at `s_end`.
fn bed_crossing(system: &System, p: usize, at: [f64; 3], d: [f64; 3], s_end: f64) -> Option<f64> {
    let (li, _) = system.attachments(p).next()?;
    let model = &system.lines()[li].model;
    let bed = &model.seabed.as_ref()?.seabed;
    let depth = |s: f64| bed.penetration(&crate::vec3::add(at, crate::vec3::scale(s, d)));
    if bed_under(system, p, at).is_some() || depth(s_end) < 0.0 {
        return None;
    }
    let (mut above, mut below) = (0.0, s_end);
    while below - above > 1e-12 * s_end {
        let mid = 0.5 * (above + below);
        if depth(mid) < 0.0 {
            above = mid;
        } else {
            below = mid;
        }
    }
    Some(below)
}

/// The normal of the bed under free point p at `at` where p rests on it
/// (within 1e-6 of its lines' length above it, the digits a deck gives
/// positions to, or in it): the bed of a line attached there.
fn bed_under(system: &System, p: usize, at: [f64; 3]) -> Option<[f64; 3]> {
    system.attachments(p).find_map(|(li, _)| {
        let model = &system.lines()[li].model;
        let bed = model.seabed.as_ref()?;
        (bed.seabed.penetration(&at) >= -1e-6 * model.cable.length)
            .then(|| bed.seabed.normal_at(&at))
    })
}

/// The seabed's push on free point p at `at` when it is below the bed of
/// a line attached there: the catenaries of (M32a) do not see the bed,
/// and a free point between a line on the bed and one that lifts it
/// (a lazy wave's touchdown) would sink through it; the bed holds it as
/// it holds a length of that line lying there, kBot d L per metre of
/// penetration along the bed's normal ((W42) without its ramp).
fn bed_reaction(system: &System, p: usize, at: [f64; 3]) -> [f64; 3] {
    let mut push = [0.0; 3];
    for (li, _) in system.attachments(p) {
        let model = &system.lines()[li].model;
        let Some(bed) = &model.seabed else { continue };
        let depth = bed.seabed.penetration(&at);
        if depth > 0.0 {
            let k = bed.seabed.stiffness * bed.diameter * model.cable.length;
            let f = crate::vec3::scale(k * depth, bed.seabed.normal_at(&at));
            if crate::vec3::norm(f) > crate::vec3::norm(push) {
                push = f;
            }
        }
    }
    push
}

/// Adds force f at `arm` from a body's centre to the body's rows at o:
/// the force, then its moment arm x f.
fn add_at(g: &mut [f64], o: usize, f: [f64; 3], arm: [f64; 3], scale: &mut f64) {
    let m = crate::vec3::cross(arm, f);
    for c in 0..3 {
        g[o + c] += f[c];
        g[o + 3 + c] += m[c];
        *scale = scale.max(f[c].abs());
    }
}
