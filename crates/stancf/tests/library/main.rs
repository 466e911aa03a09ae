//! The library's tests, one module per subject, in one test binary (one
//! build and one link for all of them: the test command's build on two
//! cores is dominated by per-binary work). Run one subject with
//! `cargo test --release -p stancf --test library <module>::`.

mod common;

mod added_mass;
mod added_mass_derivatives;
mod added_mass_systems;
mod axial_damping;
mod bodies_in_host_waves;
mod bodies_in_systems;
mod bodies_in_waves;
mod bodies_on_a_line;
mod body_statics;
mod broyden;
mod catenary_on_seabed;
mod clamped_at_bodies;
mod clamped_ends;
mod compression;
mod constrained_dynamics;
mod coupled_bodies;
mod coupled_tolerance;
mod coupling;
mod drag;
mod element_derivatives;
mod end_forces;
mod floating_rods;
mod free_cable;
mod galerkin;
mod grading;
mod highest_frequency;
mod host_waves;
mod joints;
mod line_failures;
mod lines_apart;
mod mhk_rm1_lines;
mod motion_tables;
mod moving_pins;
mod no_allocation;
mod parallel_elements;
mod pinned_bodies;
mod planar;
mod points_in_water;
mod points_on_the_bed;
mod quadrature_rank;
mod rigid_bodies;
mod rods_in_systems;
mod seabed;
mod statics;
mod step_assembly;
mod step_control;
mod step_halving;
mod step_unknowns;
mod system_momentum;
mod system_run;
mod system_statics;
mod systems;
mod viscoelastic;
mod viv;
mod watchdog;
mod water;
mod within_step;
