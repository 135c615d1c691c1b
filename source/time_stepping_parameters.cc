// SPDX-License-Identifier: LGPL-2.1-or-later
// The subsection Time stepping: its entries and their parsing.
#include <rsfcycle/parameters.h>

namespace rsfcycle
{
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Selection;

  void
  TimeSteppingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    prm.declare_entry(
      "Integrator",
      "implicit",
      Selection(Choice<Integrator>::pattern()),
      "How the model is advanced in time. implicit: the model's implicit "
      "step (Solver/Time scheme, with the rate/state coupling of "
      "Solver/Coupling), its step sizes chosen by Controller; arkode: "
      "SUNDIALS ARKODE (implicit, adaptive, relative tolerance = "
      "Tolerance) on the model's ODE, for models that are one (the "
      "spring-slider, with Cohesion = 0); it writes no checkpoints; "
      "runge-kutta: ARKODE's explicit Dormand-Prince 5(4) on the model's "
      "ODE (relative tolerance = Tolerance, steps between Minimum step and "
      "Maximum step, starting at Initial step), every accepted step a step "
      "of the run: the fault's ODE of Solver/Bulk = green-function, which "
      "takes implicit too (the implicit step on the fault's nodes); "
      "explicit: the volume method's explicit step (Solver/Dynamics = "
      "dynamic, inviscid materials: the Explicit scheme with the lumped "
      "mass, the friction solved node by node), every step Courant number "
      "x the mesh's stable step (shown in the log); implicit-explicit: "
      "implicit while the step the Controller allows is at least R "
      "explicit steps (Explicit steps per implicit step), explicit while it "
      "is shorter (inside events), back when a trial of up to 32 implicit "
      "steps reaches 2 R explicit steps "
      "(doc/model.md 8.3a; a model without an explicit step keeps the "
      "implicit one and says so in the log)");
    prm.declare_entry(
      "Courant number",
      "0.5",
      Double(1e-3, 1),
      "With Integrator = explicit or implicit-explicit: the explicit step as "
      "a fraction of the scheme's stable step (Explicit scheme: 3.745 or 2 "
      "over omega_max, the largest eigenvalue omega_max^2 of the lumped "
      "mass's inverse times the stiffness bounded from above cell by cell; "
      "a rupture front wants a few steps per cell, and the peak slip rate "
      "converges as the step falls below half the stable one) [-]");
    prm.declare_entry(
      "Explicit steps per implicit step",
      "16",
      Double(1, 1e6),
      "With Integrator = implicit-explicit: R, the explicit steps one "
      "implicit step must stand for before the run takes implicit steps "
      "(their error-controlled step at least R explicit steps; a trial "
      "succeeds at 2 R). Set it to about the cost of an implicit step over "
      "that of an explicit one: an implicit step solves the whole body a "
      "few times (tens of multigrid cycles), an explicit step applies the "
      "stiffness twice. 16 suits 2D meshes; a 3D mesh whose coarse "
      "multigrid level is large needs more (the timer table's TNNMG and "
      "Explicit step sections give the ratio) [-]");
    prm.declare_entry(
      "Explicit scheme",
      "noh-bathe",
      Selection(Choice<ExplicitScheme>::pattern()),
      "With Integrator = explicit or implicit-explicit: the explicit step's "
      "scheme. noh-bathe: Noh and Bathe's two sub-steps (p = 0.54; two "
      "stiffness products per step, stable up to 3.745/omega_max), second "
      "order, damping the shortest waves the mesh carries (at 0.8 of the "
      "stable limit they lose 36 % of their amplitude per period) and "
      "hardly the resolved ones (at a tenth of it 0.07 % per period); "
      "central-differences: Newmark's explicit member (one product, stable "
      "up to 2/omega_max), which keeps the discrete energy, so that the "
      "waves a mesh's coarse far field traps after an event ring undamped "
      "(doc/model.md 8.3a)");
    prm.declare_entry("Adaptive",
                      "true",
                      Bool(),
                      "Adaptive steps chosen by the Controller (true) or a "
                      "fixed step, the Initial step (false)");
    prm.declare_entry("Controller",
                      "local-extrapolation",
                      Selection(Choice<Controller>::pattern()),
                      "How adaptive steps are chosen. step-doubling: the "
                      "paper's controller (doc/model.md §4.3: two steps of "
                      "tau against one of 2 tau, one of tau against two of "
                      "tau/2, the step of tau accepted; 3 to 4 spatial "
                      "problems per step); local-extrapolation: one step of "
                      "tau against two of tau/2, the two half steps "
                      "accepted, tau doubled when the estimate allows (3 "
                      "spatial problems per two steps; doc/design.md)");
    prm.declare_entry("Extrapolated start",
                      "true",
                      Bool(),
                      "With Controller = local-extrapolation: start the "
                      "fixed-point iteration of every spatial problem from "
                      "the state and velocity extrapolated from the last "
                      "accepted steps (true) or from the old ones (false)");
    prm.declare_entry("Step sizes",
                      "ladder",
                      Selection("ladder|free"),
                      "With Controller = local-extrapolation: ladder keeps "
                      "every step size at Initial step x 2^k (halved on "
                      "rejection, doubled when 8 x estimate <= Doubling "
                      "threshold x Tolerance), so that step matrices, "
                      "factorisations and multigrid level matrices are "
                      "computed once per size and reused; free takes tau x "
                      "min(2, max(0.2, 0.9 (Tolerance/estimate)^(1/3))) "
                      "after every pair and rejection (new matrices for "
                      "every step size; "
                      "benchmarks/time-stepping/README.md compares both)");
    prm.declare_entry("Doubling threshold",
                      "1",
                      Double(1e-3, 8),
                      "With Controller = local-extrapolation and Step sizes "
                      "= ladder: after an accepted pair the step size is "
                      "doubled if 8 x its error estimate (the estimate of "
                      "the doubled step: it grows as tau^3) is at most this "
                      "factor x Tolerance [-]");
    prm.declare_entry("Error norm",
                      "L2",
                      Selection(Choice<ErrorNorm>::pattern()),
                      "The norm of the difference of two states (log state "
                      "per contact node) in the step-doubling error estimate "
                      "of the time step: L2 is the distance (14), the "
                      "area-weighted root mean square over the contact; max "
                      "is the largest difference at any contact node, which "
                      "does not dilute the error of a nucleation zone a few "
                      "cells wide (the fixed-point iteration always uses "
                      "(14)) [-]");
    prm.declare_entry("Tolerance",
                      "1e-5",
                      Double(1e-300, 1),
                      "Tolerance delta on the state distance (14) of the "
                      "adaptive controller (for step doubling: between one "
                      "step of tau and two of tau/2) [-]");
    prm.declare_entry("Initial step",
                      "1e-2",
                      Double(1e-300),
                      "First guess of the step size [s]");
    prm.declare_entry("Minimum step",
                      "1e-9",
                      Double(1e-300),
                      "Below this step size the run stops with a diagnosis "
                      "[s]");
    prm.declare_entry("Maximum step",
                      "100",
                      Double(1e-300),
                      "Upper bound of the step size [s]");
    prm.leave_subsection();
  }

  void
  TimeSteppingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    integrator         = Choice<Integrator>::parse(prm.get("Integrator"));
    adaptive           = prm.get_bool("Adaptive");
    controller         = Choice<Controller>::parse(prm.get("Controller"));
    extrapolated_start = prm.get_bool("Extrapolated start");
    ladder             = prm.get("Step sizes") == "ladder";
    doubling_threshold = prm.get_double("Doubling threshold");
    error_norm         = Choice<ErrorNorm>::parse(prm.get("Error norm"));
    tolerance          = prm.get_double("Tolerance");
    initial_step       = prm.get_double("Initial step");
    minimum_step       = prm.get_double("Minimum step");
    maximum_step       = prm.get_double("Maximum step");
    courant_number     = prm.get_double("Courant number");
    implicit_ratio     = prm.get_double("Explicit steps per implicit step");
    explicit_scheme = Choice<ExplicitScheme>::parse(prm.get("Explicit scheme"));
    prm.leave_subsection();
  }
} // namespace rsfcycle
