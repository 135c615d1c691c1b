// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>
#include <rsfcycle/format.h>
#include <rsfcycle/friction/laws.h>
#include <rsfcycle/parameters.h>
#include <stdexcept>

namespace rsfcycle
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  void
  RunParameters::declare_parameters(ParameterHandler  &prm,
                                    const std::string &scene_names)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Integer(2, 3),
                      "Space dimension: 2 (plane strain, or antiplane with "
                      "Displacement = antiplane) or 3");
    prm.declare_entry("Displacement",
                      "vector",
                      Selection("vector|antiplane"),
                      "vector: every component of the displacement (plane "
                      "strain in 2D); antiplane (Dimension = 2, Scene = "
                      "mesh-file): only the component out of the mesh's "
                      "plane, one unknown per node, scalar elasticity with "
                      "the shear modulus, shear viscosity and density; "
                      "in-plane gravity does not load it, so the contact's "
                      "normal stress must be prescribed (Mesh file/Friction/"
                      "Normal stress), and the load velocity is one number "
                      "(out of the plane)");
    prm.declare_entry("Scene",
                      "wedge",
                      Selection(scene_names),
                      "The physical set-up; its parameters are in the "
                      "subsection of the same name");
    prm.declare_entry("End time", "1000", Double(0), "Simulated time span [s]");
    prm.declare_entry("Stop after events",
                      "0",
                      Integer(0),
                      "End the run, before End time, at the end of this "
                      "many events (0: run to End time)");
    prm.declare_entry("Output directory",
                      "output",
                      Anything(),
                      "Run folder for parameters.prm, log, CSV and VTU files");
    prm.declare_entry("Overwrite output",
                      "false",
                      Bool(),
                      "Allow writing into a run folder that holds an earlier "
                      "run (the command-line flag --force does the same)");
  }

  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    dimension         = prm.get_integer("Dimension");
    antiplane         = prm.get("Displacement") == "antiplane";
    scene             = prm.get("Scene");
    end_time          = prm.get_double("End time");
    stop_after_events = prm.get_integer("Stop after events");
    output_directory  = prm.get("Output directory");
    overwrite_output  = prm.get_bool("Overwrite output");
    if (output_directory.empty())
      throw std::invalid_argument("Output directory: must not be empty");
  }


  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Global refinements",
                      "3",
                      Integer(0, 12),
                      "Uniform refinements of the coarse mesh");
    prm.declare_entry("Local refinements",
                      "4",
                      Integer(0, 16),
                      "Further refinements toward the seismogenic patch");
    prm.declare_entry(
      "Refinement law",
      "centre distance",
      Selection(Choice<RefinementLaw>::pattern()),
      "How the local refinements choose the cells to refine toward the "
      "seismogenic patch. centre distance: a cell is refined when its centre "
      "is closer to the patch than `Refinement distance` times its diameter "
      "(the refined zone shrinks with the level; flat cells, as in the "
      "wedge's coarse mesh, make it many cells thick). band: a cell is "
      "refined when it meets the patch widened by `Refinement band` along "
      "the base, or is closer to it than `Refinement band layers` times its "
      "shortest edge, so that the finest cells cover the patch and the band "
      "and the coarser ones grow outward in layers");
    prm.declare_entry("Refinement distance",
                      "1.5",
                      Double(0),
                      "With Refinement law = centre distance: in every local "
                      "refinement, cells whose centre is closer to the patch "
                      "than this multiple of their diameter are refined [-]");
    prm.declare_entry("Refinement band",
                      "0",
                      Double(0),
                      "With Refinement law = band: the seismogenic patch is "
                      "widened by this distance along the base (beyond its "
                      "ends and lateral edges, not into the body) and the "
                      "cells on the widened patch get the finest level [m]; "
                      "0 gives the finest cells to the patch alone");
    prm.declare_entry("Refinement band layers",
                      "1",
                      Double(0),
                      "With Refinement law = band: a cell that does not touch "
                      "the widened patch is refined when it is closer to it "
                      "than this many of its shortest edges, so that every "
                      "level adds about this many layers of cells of its size "
                      "around the finer ones [-]");
    prm.leave_subsection();
  }

  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    global_refinements = prm.get_integer("Global refinements");
    local_refinements  = prm.get_integer("Local refinements");
    refinement_law = Choice<RefinementLaw>::parse(prm.get("Refinement law"));
    refinement_distance    = prm.get_double("Refinement distance");
    refinement_band        = prm.get_double("Refinement band");
    refinement_band_layers = prm.get_double("Refinement band layers");
    prm.leave_subsection();
  }


  void
  SolverParameters::declare_parameters(ParameterHandler  &prm,
                                       const std::string &schemes)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry("Time scheme",
                      "theta",
                      Selection(schemes),
                      "The time discretisation of the implicit step. theta: "
                      "the one-step theta scheme of Theta (0.5: the "
                      "paper's trapezoidal Newmark scheme (15)); "
                      "generalized-alpha: the scheme of Chung and Hulbert "
                      "(1993) with Spectral radius, second order with "
                      "numerical damping of the modes much stiffer than the "
                      "step only, for Dynamics = dynamic");
    prm.declare_entry("State law",
                      "ageing",
                      Selection(friction::law_names()),
                      "The friction law: the regularised coefficient (2) "
                      "with the state evolving by the ageing law (4), the "
                      "slip law, or the quadratic law of Perrin, Rice and "
                      "Zheng (1995), theta' = 1 - (theta V / 2 L)^2");
    prm.declare_entry("Coupling",
                      "fixed-point",
                      Selection(Choice<Coupling>::pattern()),
                      "Rate/state coupling: the fixed-point iteration (18) "
                      "or explicit decoupling (state from the old velocity)");
    prm.declare_entry("Dynamics",
                      "dynamic",
                      Selection(Choice<Dynamics>::pattern()),
                      "dynamic: Newmark with inertia (15); quasi-static: "
                      "without the mass term; quasi-dynamic: without the mass "
                      "term and with the radiation damping eta V added to the "
                      "friction on every contact node (eta of the scene, by "
                      "default sqrt(G rho) of the material at the node)");
    prm.declare_entry("Mass matrix",
                      "consistent",
                      Selection("consistent|lumped"),
                      "With Dynamics = dynamic: the mass matrix as assembled "
                      "(consistent) or every cell's lumped to the diagonal of "
                      "its row sums (lumped: the explicit step's mass, which "
                      "Time stepping/Integrator = explicit and "
                      "implicit-explicit need, so that both steps solve the "
                      "same equations)");
    prm.declare_entry(
      "Bulk",
      "volume",
      Selection(Choice<Bulk>::pattern()),
      "volume: the implicit step over the mesh (TNNMG); green-function: "
      "the fault's Green's functions from the mesh (doc/model.md §8.1) and "
      "the fault's ODE by Time stepping/Integrator = runge-kutta, or the "
      "implicit step on the fault's nodes (Integrator = implicit): "
      "quasi-dynamic, elastic, prescribed normal stress, constant load");
    prm.declare_entry(
      "Green operator file",
      "",
      Anything(),
      "Solver/Bulk = green-function: the file green-operator.bin of an "
      "earlier run on the same mesh, material, boundary roles, loads and "
      "observation points (friction, normal stress and radiation damping "
      "may differ), reused instead of computing the operator; a relative "
      "path is looked up beside the .prm first. A file written for another "
      "set-up, damaged or of another format is refused before anything is "
      "written. Empty: compute the operator (every run writes it to its "
      "run folder)");
    prm.declare_entry(
      "Green operator storage",
      "automatic",
      Selection(Choice<GreenStorage>::pattern()),
      "Solver/Bulk = green-function: how the operator S (n x n for n "
      "contact nodes) is kept and applied at every right-hand side. dense: "
      "n^2 numbers, a vectorised product; h-matrix: compressed as a "
      "hierarchical matrix (hmat-oss, ACA+) to Green compression "
      "tolerance, storage and product about n log n (at 1600 nodes: 6 % of "
      "the numbers and a third of the product's time); automatic: h-matrix "
      "from 1000 contact nodes on, dense below (where compression gains "
      "nothing). The operator file holds the dense S either way");
    prm.declare_entry(
      "Green compression tolerance",
      "1e-6",
      Double(1e-14, 1e-1),
      "Solver/Bulk = green-function with an H-matrix: the relative "
      "tolerance [-] of the low-rank blocks (ACA+ and its recompression); "
      "the product's relative error is of this order or below (the run's "
      "log reports it for two test slips). 1e-6 changes BP1-QD's event "
      "times by less than 1e-4 relative (benchmarks/green-function)");
    prm.declare_entry(
      "Green compression precision",
      "double",
      Selection("double|single"),
      "Solver/Bulk = green-function with an H-matrix: the numbers the "
      "H-matrix stores and its product's arithmetic. double; single: "
      "computed in double, stored in float, for half the memory and a "
      "product about twice as fast once the H-matrix outgrows the caches "
      "(BP5 at 500 m; benchmarks/seas-bp5), at a rounding error of about "
      "1e-7 per number, so it needs Green compression tolerance >= 1e-5 "
      "[-]");
    prm.declare_entry(
      "Theta",
      "0.5",
      Double(0.5, 1),
      "theta of the time step: u_{n+1} = u_n + tau ((1 - theta) v_n + "
      "theta v_{n+1}), and the same for the velocity from the acceleration "
      "and for the slip rate of the state update. 0.5: the paper's Newmark "
      "scheme (15), second order, no numerical damping (modes much stiffer "
      "than the step, such as Kelvin-Voigt relaxation after an earthquake "
      "in a km-scale model, then change sign from step to step). 1: "
      "backward Euler, first order, damps them within a step. Between: "
      "first order, damping in between [-]");
    prm.declare_entry(
      "Spectral radius",
      "0.8",
      Double(0, 1),
      "rho_inf of Time scheme = generalized-alpha: the amplification per "
      "step of a mode much stiffer than the step (high-frequency "
      "dissipation). 1: the trapezoidal rule, no dissipation; 0: such modes "
      "vanish in one step; the modes that the step resolves are damped at "
      "third order only [-]");
    prm.declare_entry("Fixed-point tolerance",
                      "1e-5",
                      Double(1e-300, 1),
                      "epsilon of the stopping criterion (19) [-]");
    prm.declare_entry("Maximum fixed-point iterations",
                      "20",
                      Integer(1, 1000),
                      "A step whose fixed point needs more is rejected and "
                      "halved");
    prm.declare_entry("Linear correction",
                      "multigrid",
                      Selection(Choice<LinearCorrection>::pattern()),
                      "Linear correction of TNNMG: geometric multigrid on the "
                      "mesh levels (preconditioning CG on the truncated "
                      "system), direct (sparse Cholesky with a Schur "
                      "complement on the contact; one MPI rank), or amg "
                      "(Trilinos ML, preconditioning CG). A split fault "
                      "(Mesh file/Boundary roles: fault-opposite) needs "
                      "direct or amg");
    prm.declare_entry(
      "Direct factor reuse",
      "false",
      Bool(),
      "With Linear correction = direct: false solves exactly, with a "
      "Cholesky factor of the unknowns off the contact per step size and "
      "a dense Schur complement on the contact dofs (fast for up to a few "
      "hundred contact dofs); true factorises the whole truncated Newton "
      "matrix and keeps the factor of each step size within a time step "
      "as the preconditioner of CG for the next matrices, which differ "
      "only in the friction's Hessian, factorising again when Linear "
      "correction cycles iterations do not reduce the residual by Linear "
      "correction tolerance (for long faults: the dense Schur complement's "
      "cost grows as the cube of the contact dofs) [true/false]");
    prm.declare_entry("Direct fallback",
                      "false",
                      Bool(),
                      "A spatial problem whose TNNMG solve with the linear "
                      "correction above does not converge within Maximum "
                      "TNNMG iterations is solved again, from where it "
                      "stopped, with the direct correction before the step "
                      "is refused (one MPI rank): for meshes whose wide "
                      "refined zone stalls the multigrid correction at "
                      "large steps, while it stays the faster one at small "
                      "steps [true/false]");
    prm.declare_entry("Multigrid smoothing steps",
                      "3",
                      Integer(1, 100),
                      "Gauss-Seidel sweeps before and after the coarse "
                      "correction of the V-cycle (nu1 = nu2)");
    prm.declare_entry(
      "Coarse factor reuse size",
      "10000",
      Integer(0),
      "Multigrid coarse levels with at least this many dofs keep their "
      "direct factorisation across TNNMG iterations while every contact "
      "node's diagonal stays within half of the factorised value (a new "
      "step size, a truncated node or a larger change of the friction "
      "Hessian factorises again); smaller coarse levels are factorised in "
      "every linear correction. The coarse solve is a preconditioner, so "
      "the solution is the same to the TNNMG tolerance; a 3D coarse level "
      "of 40,000 dofs takes about a second to factorise [dofs]");
    prm.declare_entry("Linear correction cycles",
                      "1",
                      Integer(1, 1000),
                      "Multigrid (or AMG) cycles per linear correction at "
                      "most, each one CG iteration");
    prm.declare_entry("Linear correction tolerance",
                      "1e-2",
                      Double(0, 1),
                      "A linear correction stops early when the residual of "
                      "the truncated Newton system fell by this factor [-]");
    prm.declare_entry("TNNMG tolerance",
                      "1e-10",
                      Double(1e-300, 1),
                      "Stop TNNMG when the energy norm of the update, relative "
                      "to that of the iterate, is below this; with an "
                      "adaptive step at most a tenth of Time stepping/"
                      "Tolerance, or the step-size control sees the solver's "
                      "error and takes needlessly small steps (the implicit "
                      "step of Bulk = green-function stops its fault solver "
                      "the same way) [-]");
    prm.declare_entry("Inner tolerance factor",
                      "0.3",
                      Double(0, 1),
                      "Inexact fixed-point iteration: TNNMG stops in "
                      "fixed-point iteration k at the relative change "
                      "max(TNNMG tolerance, factor * d_{k-1}), d_{k-1} the "
                      "state distance (14) of the previous iteration and "
                      "d_0 = 1, so early iterations are solved loosely and "
                      "the last ones to TNNMG tolerance (0: always TNNMG "
                      "tolerance; explicit coupling always uses it) [-]");
    prm.declare_entry("Maximum TNNMG iterations",
                      "100",
                      Integer(1, 100000),
                      "A spatial problem that needs more counts as failed");
    prm.declare_entry("Truncation ratio",
                      "1e10",
                      Double(1),
                      "Contact nodes whose friction Hessian exceeds this "
                      "multiple of the diagonal of A are truncated [-]");
    prm.leave_subsection();
  }

  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    law                 = friction::make_law(prm.get("State law"));
    time_scheme         = prm.get("Time scheme");
    coupling            = Choice<Coupling>::parse(prm.get("Coupling"));
    dynamics            = Choice<Dynamics>::parse(prm.get("Dynamics"));
    lumped_mass         = prm.get("Mass matrix") == "lumped";
    bulk                = Choice<Bulk>::parse(prm.get("Bulk"));
    green_operator_file = prm.get("Green operator file");
    green_storage =
      Choice<GreenStorage>::parse(prm.get("Green operator storage"));
    green_compression_tolerance = prm.get_double("Green compression tolerance");
    green_single_precision = prm.get("Green compression precision") == "single";
    theta                  = prm.get_double("Theta");
    spectral_radius        = prm.get_double("Spectral radius");
    fixed_point_tolerance  = prm.get_double("Fixed-point tolerance");
    max_fixed_point_iterations =
      prm.get_integer("Maximum fixed-point iterations");
    linear_correction =
      Choice<LinearCorrection>::parse(prm.get("Linear correction"));
    direct_fallback        = prm.get_bool("Direct fallback");
    direct_factor_reuse    = prm.get_bool("Direct factor reuse");
    smoothing_steps        = prm.get_integer("Multigrid smoothing steps");
    coarse_reuse_size      = prm.get_integer("Coarse factor reuse size");
    correction_cycles      = prm.get_integer("Linear correction cycles");
    correction_tolerance   = prm.get_double("Linear correction tolerance");
    tnnmg_tolerance        = prm.get_double("TNNMG tolerance");
    inner_tolerance_factor = prm.get_double("Inner tolerance factor");
    max_tnnmg_iterations   = prm.get_integer("Maximum TNNMG iterations");
    truncation_ratio       = prm.get_double("Truncation ratio");
    prm.leave_subsection();
  }


  void
  OutputParameters::declare_parameters(ParameterHandler  &prm,
                                       const std::string &writers)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Event threshold",
                      "10",
                      Double(1e-300),
                      "An event is where the maximum slip rate exceeds this "
                      "multiple of the convergence rate v0 [-]");
    prm.declare_entry("Event merge time",
                      "0",
                      Double(0),
                      "A rise above the event threshold at most this long "
                      "after an event's end continues that event instead "
                      "of starting a new one, e.g. the ringing after a fully "
                      "dynamic rupture; 0 keeps every rise a new event [s]");
    prm.declare_entry("Progress interval",
                      "10",
                      Double(0),
                      "Wall-clock time between progress lines [s]");
    prm.declare_entry(
      "Writers",
      "time series, base profile, events, vtu",
      dealii::Patterns::MultipleSelection(writers),
      "The outputs of the run, a comma-separated list (doc/output.md). time "
      "series: time-series.csv, a row per accepted step; base profile: "
      "base-profile.csv, the contact's slip rates; events: events.csv and "
      "summary.txt; seas: the SEAS files of Output/SEAS (needs its "
      "Benchmark or Problem); vtu: VTU snapshots of the body and the fault "
      "(solution.pvd, fault.pvd) every Output interval; hdf5: the same "
      "snapshots as HDF5 with XDMF indices (solution.xdmf, fault.xdmf), one "
      "file per snapshot for any number of ranks. vtu and hdf5 need a body "
      "on a mesh (not the spring-slider)");
    prm.declare_entry("Checkpoint steps",
                      "5000",
                      Integer(0),
                      "Write checkpoint.bin every this many accepted steps "
                      "(0: never) [-]");
    prm.declare_entry(
      "Checkpoint minutes",
      "10",
      Double(0),
      "Write checkpoint.bin every this many minutes of wall-clock time as "
      "well (0: never) [min]; it is also written at the end, on "
      "SIGINT/SIGTERM and when the step size underflows");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    output_interval        = prm.get_double("Output interval");
    event_output_interval  = prm.get_double("Event output interval");
    profile_interval       = prm.get_double("Profile interval");
    event_profile_interval = prm.get_double("Event profile interval");
    event_threshold        = prm.get_double("Event threshold");
    event_merge_time       = prm.get_double("Event merge time");
    progress_interval      = prm.get_double("Progress interval");
    writers         = dealii::Utilities::split_string_list(prm.get("Writers"));
    transition_time = prm.get_double("Transition time");
    transition_events  = prm.get_integer("Transition events");
    checkpoint_steps   = prm.get_integer("Checkpoint steps");
    checkpoint_minutes = prm.get_double("Checkpoint minutes");
    seas.parse_parameters(prm);
    prm.leave_subsection();
  }


  void
  Parameters::declare_parameters(ParameterHandler  &prm,
                                 const std::string &scene_names,
                                 const std::string &scheme_names,
                                 const std::string &writer_names)
  {
    RunParameters::declare_parameters(prm, scene_names);
    MeshParameters::declare_parameters(prm);
    TimeSteppingParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm, scheme_names);
    OutputParameters::declare_parameters(prm, writer_names);
  }

  void
  Parameters::parse_parameters(ParameterHandler &prm)
  {
    run.parse_parameters(prm);
    mesh.parse_parameters(prm);
    time_stepping.parse_parameters(prm);
    solver.parse_parameters(prm);
    output.parse_parameters(prm);
  }

} // namespace rsfcycle
