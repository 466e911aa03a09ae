//! What a host gives a MoorDyn deck it opens (docs/interface.md,
//! "Coupling"): the water depth, the water density and gravity, as
//! OpenFAST passes them to MoorDyn-F before its init (`InitInp%WtrDepth`,
//! `rhoW`, `g`), so that a glue code's deck, which leaves them out, runs
//! in the host's sea. A value the deck gives is the deck's (the host's is
//! named in a note where they differ); a value neither gives falls to
//! MoorDyn's rules (the deepest point's depth, 1025 kg/m^3, 9.80665
//! m/s^2). `stancf run --water-depth` gives a depth the same way.

use super::water::WaterKeys;
use crate::moordyn::{Deck, SupportedOption};
use stancf::error::Sig;

/// The host's sea and gravity, and a farm's turbines; None where the host
/// says nothing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct HostEnvironment {
    /// m, positive.
    pub water_depth: Option<f64>,
    /// kg/m^3, positive.
    pub water_density: Option<f64>,
    /// m/s^2, the magnitude, positive.
    pub gravity: Option<f64>,
    /// The turbines' positions (m) of a FAST.Farm deck's `Turbine<n>`
    /// points, turbine n at index n - 1, as FAST.Farm gives them
    /// (`super::farm`); a scenario's `[farm]` wins.
    pub turbines: Option<Vec<[f64; 3]>>,
    /// The host sets the water's kinematics at the nodes while it steps
    /// the system (the coupling API: a deck's `WaveKin 1`, a scenario's
    /// `water.host_waves`, docs/method.md §12.1); a run without such a
    /// host runs those statically only.
    pub sets_waves: bool,
    /// The run's length (s), as OpenFAST passes MoorDyn-F its TMax
    /// (`InitInp%Tmax`): the elevation record of a WaterKin file's
    /// `WaveKinMod 1` is resampled over it
    /// (`super::moordyn_waterkin_waves`). A scenario that takes the deck
    /// gives its dynamic analysis' duration.
    pub run_length: Option<f64>,
}

impl HostEnvironment {
    /// None: a deck opened without a host.
    pub const NONE: HostEnvironment = HostEnvironment {
        water_depth: None,
        water_density: None,
        gravity: None,
        turbines: None,
        sets_waves: false,
        run_length: None,
    };

    /// Refused naming the quantity: a value that is not finite and
    /// positive.
    pub fn checked(&self) -> Result<&Self, String> {
        for (name, unit, v) in [
            ("water depth", "m", self.water_depth),
            ("water density", "kg/m^3", self.water_density),
            ("gravity", "m/s^2", self.gravity),
        ] {
            if let Some(v) = v {
                if !(v.is_finite() && v > 0.0) {
                    return Err(format!(
                        "the host's {name} is {v} {unit}; it must be positive and finite"
                    ));
                }
            }
        }
        let turbines = self.turbines.iter().flatten().enumerate();
        if let Some((k, p)) = turbines
            .clone()
            .find(|(_, p)| p.iter().any(|c| !c.is_finite()))
        {
            return Err(format!(
                "the host's turbine {} is at {p:?}; its position must be finite",
                k + 1
            ));
        }
        Ok(self)
    }

    /// The water keys the host gives (depth and density).
    pub(super) fn water_keys(&self) -> WaterKeys {
        WaterKeys {
            depth: self.water_depth,
            density: self.water_density,
            ..WaterKeys::default()
        }
    }

    /// The notes of `check` for `deck`: each host value used (the deck
    /// gives none) and each the deck overrides.
    pub(super) fn notes(&self, deck: &Deck) -> Vec<String> {
        let mut notes = Vec::new();
        for (option, what, unit, host) in [
            (
                SupportedOption::WaterDepth,
                "water depth",
                "m",
                self.water_depth,
            ),
            (
                SupportedOption::WaterDensity,
                "water density",
                "kg/m^3",
                self.water_density,
            ),
            (SupportedOption::Gravity, "gravity", "m/s^2", self.gravity),
        ] {
            let Some(host) = host else { continue };
            match deck.option(option) {
                None => notes.push(format!(
                    "OPTIONS: no {}: the host's {what}, {} {unit}",
                    option.name(),
                    Sig(host)
                )),
                Some(own) if own != host => {
                    let line = deck.option_at(option).map_or(0, |a| a.1);
                    notes.push(format!(
                        "line {line}: the deck's {} {} {unit} is used; the host's {what}, {} \
                         {unit}, is not",
                        option.name(),
                        Sig(own),
                        Sig(host)
                    ))
                }
                Some(_) => {}
            }
        }
        notes
    }
}
