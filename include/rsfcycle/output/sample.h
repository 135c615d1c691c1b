// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_sample_h
#define rsfcycle_output_sample_h

#include <array>
#include <rsfcycle/solvers/step_statistics.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * What is recorded of one accepted state: the slip rate and the
     * tangential displacement (up to two components) of every contact node,
     * the model's own time-series columns, and the solver counts of the
     * step that produced the state. The SEAS files (output::SeasFiles) also
     * need the friction stress and the state of every node and the rates
     * of the observation points: a model fills them when the SEAS files
     * are on (`Output/SEAS/Problem` given); else they may stay empty.
     */
    struct Sample
    {
      std::vector<double>                slip_rates;   // [m/s]
      std::vector<std::array<double, 2>> slip;         // [m]
      std::vector<double>                observations; // see Layout
      solvers::StepStatistics            statistics;
      /**
       * The slip rate's components (as those of slip) of every node [m/s]
       * (with the SEAS files of a 3D model).
       */
      std::vector<std::array<double, 2>> slip_rate_components;
      /** The friction stress |sigma_n| mu(V, alpha) + C of every node [Pa]. */
      std::vector<double> shear_stresses;
      /**
       * The effective normal stress (compression positive) of every node
       * [Pa], with the shear stresses; it changes with slip on a split
       * fault (the Green's-function method's normal coupling).
       */
      std::vector<double> normal_stresses;
      /** log10 of the state theta = L / V* exp(alpha) of every node [s]. */
      std::vector<double> log10_states;
      /** The time derivatives of the observations (body models). */
      std::vector<double> observation_rates;
      /** With Layout::pore_pressure: p of every node [Pa]. */
      std::vector<double> pore_pressures;
      /**
       * With Layout::darcy_velocity: q of every node [m/s], its components
       * along the fluid domain's axes (the second 0 in 2D).
       */
      std::vector<std::array<double, 2>> darcy_velocities;
    };

    /**
     * The fixed description of a model's records: the contact nodes'
     * along-base coordinates (and, in 3D, their z coordinates) in the order
     * of Sample::slip_rates, the names (with unit suffix) of the
     * observation columns of time-series.csv, the convergence rate v0 that
     * scales the event threshold, and how event times are found (at the
     * accepted step, or interpolated in log V between two steps; see
     * output::EventDetector); for the SEAS files, the nodes' lumped
     * quadrature weights (length or area of the contact each stands for)
     * and the names of the observation points whose displacement and rate
     * make surface-station files (none for the spring-slider), with the
     * number of components recorded at each.
     */
    struct Layout
    {
      std::vector<double>      positions;
      std::vector<double>      lateral_positions;
      std::vector<std::string> observation_names;
      std::vector<double>      weights;
      /**
       * The shear modulus of the body at every node [Pa] (the events'
       * moments; empty: none, as for the spring-slider).
       */
      std::vector<double>      shear_moduli;
      std::vector<std::string> station_names;
      /**
       * The columns recorded per observation point (Sample::observations
       * holds them point by point): 1, the displacement up, or dim, its
       * components along the mesh's x, y (, z).
       */
      unsigned int observation_components = 1;
      /** 3D: every node's position in the mesh's frame [m]. */
      std::vector<std::array<double, 3>> points;
      /** 3D: the mesh-frame directions of Sample::slip[k][0] and [1]. */
      std::array<std::array<double, 3>, 2> slip_axes{};
      double                               convergence_rate        = 1;
      bool                                 interpolate_event_times = false;
      /**
       * Whether the normal stress changes with slip (a split fault's
       * normal coupling): the SEAS files then record it.
       */
      bool normal_stress = false;
      /** Whether samples carry pore pressures and Darcy velocities. */
      bool pore_pressure = false, darcy_velocity = false;
    };
  } // namespace output
} // namespace rsfcycle

#endif
