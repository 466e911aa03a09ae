//! Regular Airy (linear) waves in water of finite depth
//! (docs/method.md §12.1, (W1)-(W8)).
//!
//! A wave of amplitude A, angular frequency w = 2 pi / T and heading beta
//! (from +x towards +y) over a flat seabed at z = -h has the phase
//!
//! ```text
//! theta = k (x cos beta + y sin beta) - w t + phi                 (W2)
//! ```
//!
//! the elevation eta = A cos theta, and the velocity potential of linear
//! theory. Its wave number k solves the dispersion relation (W1); the
//! flow below the still water level is (W4)-(W5), its gradients (W6)-(W7).
//! Points above z = 0 (in a crest) see the flow at z = 0, points below
//! the seabed the flow at z = -h (W8).

use crate::error::ModelError;
use std::f64::consts::PI;

/// One regular wave as given: elevation amplitude (m), period (s),
/// heading in degrees from +x towards +y, and phase in degrees (W2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AiryWave {
    pub amplitude: f64,
    pub period: f64,
    pub heading_deg: f64,
    pub phase_deg: f64,
}

/// The wave number k (rad/m) of angular frequency `omega` (rad/s) in water
/// of depth `depth` (m) under gravity `gravity` (m/s^2), solving the
/// finite-depth dispersion relation
///
/// ```text
/// w^2 = g k tanh(k h)                                              (W1)
/// ```
///
/// Written for y = k h and x = w^2 h / g it reads f(y) = y tanh y - x = 0,
/// f increasing and convex for y > 0, so Newton from Eckart's
/// approximation y0 = x / sqrt(tanh x) (within 5 % everywhere, exact in
/// both limits: y -> sqrt(x) shallow, y -> x deep) converges
/// monotonically and quadratically; it stops when the update is below
/// 1e-15 y, i.e. at round-off. `omega = 0` gives k = 0.
pub fn wave_number(omega: f64, depth: f64, gravity: f64) -> f64 {
    let x = omega * omega * depth / gravity;
    if x == 0.0 {
        return 0.0;
    }
    let mut y = x / x.tanh().sqrt();
    for _ in 0..50 {
        let tanh_y = y.tanh();
        // f'(y) = tanh y + y sech^2 y = tanh y + y (1 - tanh^2 y).
        let slope = tanh_y + y * (1.0 - tanh_y * tanh_y);
        let step = (y * tanh_y - x) / slope;
        y -= step;
        if step.abs() <= 1e-15 * y {
            break;
        }
    }
    y / depth
}

/// Above this k h the hyperbolic ratios (W3) are evaluated in their
/// exponential form: e^(-2 k h) < 4.3e-18 there, and cosh(k h) would
/// overflow beyond k h = 710.
const DEEP_WATER_KH: f64 = 20.0;

/// The depth factors of linear theory at height z (-h <= z <= 0):
///
/// ```text
/// C(z) = cosh(k (z + h)) / sinh(k h)
/// S(z) = sinh(k (z + h)) / sinh(k h)                               (W3)
/// ```
///
/// and, for k h > 20, the same ratios multiplied through by e^(-k h):
///
/// ```text
/// C = (e^(k z) + e^(-k (z + 2 h))) / (1 - e^(-2 k h))
/// S = (e^(k z) - e^(-k (z + 2 h))) / (1 - e^(-2 k h))
/// ```
///
/// an exact rewriting that cannot overflow (both exponents are <= 0).
fn depth_factors(k: f64, depth: f64, z: f64) -> (f64, f64) {
    let kh = k * depth;
    if kh > DEEP_WATER_KH {
        deep_water_depth_factors(k, depth, z)
    } else {
        let denominator = kh.sinh();
        let s = k * (z + depth);
        (s.cosh() / denominator, s.sinh() / denominator)
    }
}

/// (W3) in its exponential form, for any k h > 0.
fn deep_water_depth_factors(k: f64, depth: f64, z: f64) -> (f64, f64) {
    let denominator = -(-2.0 * k * depth).exp_m1();
    let rising = (k * z).exp();
    let reflected = (-k * (z + 2.0 * depth)).exp();
    (
        (rising + reflected) / denominator,
        (rising - reflected) / denominator,
    )
}

/// A regular wave ready to be evaluated: (W1) solved once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolvedWave {
    pub amplitude: f64,
    /// Angular frequency w = 2 pi / T (rad/s).
    pub omega: f64,
    /// Wave number from (W1) (rad/m).
    pub wave_number: f64,
    /// Unit direction of propagation (cos beta, sin beta).
    pub direction: [f64; 2],
    /// Phase phi in radians.
    pub phase: f64,
    /// Water depth h (m).
    pub depth: f64,
}

/// The flow of linear waves at a point, before any ramp: elevation above
/// the point, velocity, local acceleration du/dt and their gradients
/// `[i][j] = d(.)_i / d x_j`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WaveFlow {
    pub eta: f64,
    pub velocity: [f64; 3],
    pub acceleration: [f64; 3],
    pub velocity_gradient: [[f64; 3]; 3],
    pub acceleration_gradient: [[f64; 3]; 3],
    /// The dynamic pressure over the density, p_d / rho (m^2/s^2), and
    /// its gradient (W8a).
    pub pressure: f64,
    pub pressure_gradient: [f64; 3],
    /// The velocity potential Phi (m^2/s; its gradient is `velocity`): a
    /// ramp's share of the pressure (W12a).
    pub potential: f64,
}

impl SolvedWave {
    /// Checks the wave and solves (W1) for it. `key` names the wave in the
    /// error (`waves[2]`).
    pub fn new(wave: &AiryWave, depth: f64, gravity: f64, key: &str) -> Result<Self, ModelError> {
        let finite = [
            ("amplitude", wave.amplitude),
            ("period", wave.period),
            ("heading_deg", wave.heading_deg),
            ("phase_deg", wave.phase_deg),
        ];
        for (name, value) in finite {
            if !value.is_finite() {
                return Err(ModelError::invalid(
                    format!("{key}.{name}"),
                    format!("must be finite, got {value}"),
                ));
            }
        }
        if wave.amplitude < 0.0 {
            return Err(ModelError::invalid(
                format!("{key}.amplitude"),
                format!("must be >= 0 m, got {}", wave.amplitude),
            ));
        }
        if wave.period <= 0.0 {
            return Err(ModelError::invalid(
                format!("{key}.period"),
                format!("must be > 0 s, got {}", wave.period),
            ));
        }
        let omega = 2.0 * PI / wave.period;
        let heading = wave.heading_deg.to_radians();
        Ok(SolvedWave {
            amplitude: wave.amplitude,
            omega,
            wave_number: wave_number(omega, depth, gravity),
            direction: [heading.cos(), heading.sin()],
            phase: wave.phase_deg.to_radians(),
            depth,
        })
    }

    /// The phase theta (W2) at (x, y, t).
    pub fn phase_at(&self, x: f64, y: f64, t: f64) -> f64 {
        let [cos_beta, sin_beta] = self.direction;
        self.wave_number * (x * cos_beta + y * sin_beta) - self.omega * t + self.phase
    }

    /// Adds this wave's flow at `position` and time t to `flow`.
    ///
    /// With theta (W2), C and S (W3) at z_e = min(max(z, -h), 0) (W8) and
    /// e = (cos beta, sin beta, 0), the velocity potential
    /// Phi = (g A / w) cosh(k (z + h)) / cosh(k h) sin theta with (W1)
    /// gives u = grad Phi:
    ///
    /// ```text
    /// eta = A cos theta
    /// u_h = A w C cos theta e,         u_z = A w S sin theta         (W4)
    /// ```
    ///
    /// and the local acceleration a = du/dt (d theta/dt = -w):
    ///
    /// ```text
    /// a_h = A w^2 C sin theta e,       a_z = -A w^2 S cos theta      (W5)
    /// ```
    ///
    /// With d theta/dx_j = k e_j and dC/dz = k S, dS/dz = k C:
    ///
    /// ```text
    /// du_h/dx_j = -A w C sin theta k e e_j,  du_h/dz = A w k S cos theta e
    /// du_z/dx_j =  A w S cos theta k e_j,    du_z/dz = A w k C sin theta  (W6)
    /// da_h/dx_j =  A w^2 C cos theta k e e_j, da_h/dz = A w^2 k S sin theta e
    /// da_z/dx_j =  A w^2 S sin theta k e_j,   da_z/dz = -A w^2 k C cos theta (W7)
    /// ```
    ///
    /// (j = x, y). Outside -h <= z <= 0 the flow is constant in z (W8), so
    /// there the z column of the gradients is zero.
    ///
    /// The dynamic pressure of linear theory, p_d = -rho dPhi/dt, over the
    /// density, with cosh(k (z + h)) / cosh(k h) = C tanh(k h) = C w^2 /
    /// (g k) by (W1):
    ///
    /// ```text
    /// p_d / rho = g A cosh(k (z + h)) / cosh(k h) cos theta = A (w^2 / k) C cos theta
    /// grad (p_d / rho) = (-A w^2 C sin theta e_h, A w^2 S cos theta)      (W8a)
    /// ```
    ///
    /// so that -grad p_d / rho is the local acceleration (W5), as the
    /// linearized Euler equation says; and the potential itself,
    /// Phi = (A w / k) C sin theta.
    pub fn add_flow(&self, position: &[f64; 3], t: f64, flow: &mut WaveFlow) {
        let h = self.depth;
        let z = position[2];
        let inside = (-h..=0.0).contains(&z);
        let z_evaluated = z.clamp(-h, 0.0);
        let (sin_theta, cos_theta) = self.phase_at(position[0], position[1], t).sin_cos();
        let (c, s) = depth_factors(self.wave_number, h, z_evaluated);
        let a = self.amplitude;
        let w = self.omega;
        let k = self.wave_number;
        let e = [self.direction[0], self.direction[1], 0.0];
        let dz = if inside { 1.0 } else { 0.0 };

        flow.eta += a * cos_theta;
        let u_h = a * w * c * cos_theta;
        let u_z = a * w * s * sin_theta;
        let a_h = a * w * w * c * sin_theta;
        let a_z = -a * w * w * s * cos_theta;
        // Horizontal derivatives of the horizontal and vertical parts (W6, W7).
        let du_h_dx = -a * w * c * sin_theta * k;
        let du_z_dx = a * w * s * cos_theta * k;
        let da_h_dx = a * w * w * c * cos_theta * k;
        let da_z_dx = a * w * w * s * sin_theta * k;
        // Vertical derivatives, zero outside the water column (W8).
        let du_h_dz = dz * a * w * k * s * cos_theta;
        let du_z_dz = dz * a * w * k * c * sin_theta;
        let da_h_dz = dz * a * w * w * k * s * sin_theta;
        let da_z_dz = -dz * a * w * w * k * c * cos_theta;
        for i in 0..2 {
            flow.velocity[i] += u_h * e[i];
            flow.acceleration[i] += a_h * e[i];
            for j in 0..2 {
                flow.velocity_gradient[i][j] += du_h_dx * e[i] * e[j];
                flow.acceleration_gradient[i][j] += da_h_dx * e[i] * e[j];
            }
            flow.velocity_gradient[i][2] += du_h_dz * e[i];
            flow.acceleration_gradient[i][2] += da_h_dz * e[i];
            flow.velocity_gradient[2][i] += du_z_dx * e[i];
            flow.acceleration_gradient[2][i] += da_z_dx * e[i];
        }
        let head = a * w * w / k;
        flow.pressure += head * c * cos_theta;
        flow.potential += a * w / k * c * sin_theta;
        for i in 0..2 {
            flow.pressure_gradient[i] -= a * w * w * c * sin_theta * e[i];
        }
        flow.pressure_gradient[2] += dz * a * w * w * s * cos_theta;
        flow.velocity[2] += u_z;
        flow.acceleration[2] += a_z;
        flow.velocity_gradient[2][2] += du_z_dz;
        flow.acceleration_gradient[2][2] += da_z_dz;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const G: f64 = 9.80665;

    #[test]
    fn deep_water_waves_obey_the_deep_water_dispersion() {
        // k h = 161: tanh(k h) = 1 in floating point, so (W1) is k = w^2/g.
        for period in [2.0, 5.0, 8.0] {
            let omega = 2.0 * PI / period;
            let k = wave_number(omega, 1000.0, G);
            let deep = omega * omega / G;
            assert!(
                ((k - deep) / deep).abs() < 4.0 * f64::EPSILON,
                "T {period}: {k} vs {deep}"
            );
        }
    }

    #[test]
    fn shallow_water_waves_travel_at_the_shallow_water_speed() {
        // w / (k sqrt(g h)) = sqrt(tanh(y)/y) = 1 - y^2/6 + 19 y^4/360 + O(y^6)
        // for y = k h; at y ~ 0.01 the remainder is ~1e-12.
        let depth = 10.0;
        let omega = 0.01 * (G / depth).sqrt();
        let k = wave_number(omega, depth, G);
        let y = k * depth;
        assert!((y - 0.01).abs() < 1e-4, "k h = {y}");
        let ratio = omega / (k * (G * depth).sqrt());
        let series = 1.0 - y * y / 6.0 + 19.0 * y.powi(4) / 360.0;
        assert!((ratio - series).abs() < y.powi(6), "{ratio} vs {series}");
        assert!((1.0 - ratio - y * y / 6.0).abs() < y.powi(4));
    }

    #[test]
    fn the_wave_number_solves_the_dispersion_relation_to_round_off() {
        // From k h = 2e-4 to 1e5: the residual of (W1) relative to w^2.
        let mut worst: f64 = 0.0;
        for depth in [0.5, 5.0, 50.0, 500.0] {
            for i in 0..60 {
                let omega = 1e-3 * 1.2f64.powi(i);
                let k = wave_number(omega, depth, G);
                let residual = (omega * omega - G * k * (k * depth).tanh()) / (omega * omega);
                worst = worst.max(residual.abs());
            }
        }
        assert!(worst < 1e-14, "worst relative residual {worst:e}");
    }

    #[test]
    fn the_exponential_depth_factors_equal_the_hyperbolic_ones() {
        // (W3) both ways where cosh does not overflow: the same numbers to
        // a few ulps of e^(k z) (the hyperbolic form rounds sinh and cosh).
        for kh in [0.5f64, 3.0, 15.0, 20.0, 40.0] {
            let depth: f64 = 30.0;
            let k = kh / depth;
            for zf in [0.0, -0.1, -0.5, -0.9, -1.0] {
                let z = zf * depth;
                let hyperbolic = {
                    let d = kh.sinh();
                    ((k * (z + depth)).cosh() / d, (k * (z + depth)).sinh() / d)
                };
                let exponential = deep_water_depth_factors(k, depth, z);
                let scale = hyperbolic.0.abs();
                assert!(
                    (hyperbolic.0 - exponential.0).abs() < 1e-14 * scale,
                    "C at kh {kh} z {z}"
                );
                assert!(
                    (hyperbolic.1 - exponential.1).abs() < 1e-14 * scale,
                    "S at kh {kh} z {z}"
                );
            }
        }
        // And far beyond overflow of cosh the exponential form stays finite:
        // C(0) = S(0) = 1 (= coth(kh) to round-off).
        let (c, s) = depth_factors(2000.0 / 30.0, 30.0, 0.0);
        assert_eq!((c, s), (1.0, 1.0));
    }

    #[test]
    fn a_wave_with_a_non_positive_period_is_refused_naming_it() {
        let wave = AiryWave {
            amplitude: 1.0,
            period: -3.0,
            heading_deg: 0.0,
            phase_deg: 0.0,
        };
        let err = SolvedWave::new(&wave, 50.0, G, "waves[1]").unwrap_err();
        assert_eq!(err.key, "waves[1].period");
        let wave = AiryWave {
            amplitude: -1.0,
            period: 3.0,
            ..wave
        };
        assert_eq!(
            SolvedWave::new(&wave, 50.0, G, "w").unwrap_err().key,
            "w.amplitude"
        );
    }
}
