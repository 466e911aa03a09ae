//! The command line's tests, one module per subject, in one test binary
//! (one build and one link for all of them: the test command's build on
//! two cores is dominated by per-binary work). Run one subject with
//! `cargo test --release -p stancf-cli --test cli <module>::`.

mod common;

mod axial_damping;
mod bad_input;
mod bathymetry;
mod bodies;
mod bodies_in_waves;
mod clamped_lines;
mod compression;
mod constraint_routes;
mod coupled_bodies;
mod coupled_pinned;
mod coupled_rods;
mod coupling;
mod deck_currents;
mod deck_statics;
mod deck_waves;
mod decks_without_lines;
mod ea_curves;
mod external_loads;
mod extreme_values;
mod fast_farm;
mod figures_and_vtk;
mod force_tolerance;
mod grading;
mod hostile_inputs;
mod hostile_scenarios;
mod joints;
mod line_failures;
mod mesh_sections;
mod moordyn_driver;
mod moordyn_out;
mod motion_files;
mod output_files;
mod output_folder_safety;
mod output_interval;
mod pinned_rods;
mod reproduce;
mod result_folder;
mod rod_channels;
mod rod_refusals;
mod rods;
mod run_and_check;
mod seabed_friction;
mod solver_and_schemes;
mod step_halvings;
mod stiffness;
mod sweep;
mod sweep_systems;
mod system_bounds;
mod system_geometry;
mod system_summary;
mod systems;
mod time_loop;
mod viscoelastic;
mod viv;
mod watchdog;
mod water;
mod water_refusals;
