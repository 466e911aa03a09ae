//! The range of the scales a scenario may give the solver (a leaf the
//! readers and the checks of [`crate::input_scales`] share).

/// The range of the derived scales of a scenario (energies, forces,
/// lengths, masses, stiffnesses in SI units): at most `MAX_SCALE`, and the
/// ones the solver divides by at least `1 / MAX_SCALE`, so that the product
/// or quotient of any two stays a finite, nonzero double.
pub const MAX_SCALE: f64 = 1e150;
