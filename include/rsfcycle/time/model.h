#ifndef rsfcycle_time_model_h
#define rsfcycle_time_model_h

#include <array>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <cstddef>
#include <ostream>
#include <rsfcycle/output/checkpoint.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace time
  {
    /** Counts of the algebraic solvers for one time step. */
    struct StepStatistics
    {
      unsigned int fixed_point_iterations = 0;
      unsigned int tnnmg_iterations       = 0;
      unsigned int linear_iterations      = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &fixed_point_iterations &tnnmg_iterations &linear_iterations;
      }
    };

    /**
     * What the run loop records of one accepted state: the slip rate and the
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
      StepStatistics                     statistics;
      /** The friction stress |sigma_n| mu(V, alpha) + C of every node [Pa]. */
      std::vector<double> shear_stresses;
      /** log10 of the state theta = L / V* exp(alpha) of every node [s]. */
      std::vector<double> log10_states;
      /** The time derivatives of the observations (body models). */
      std::vector<double> observation_rates;
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
     * make surface-station files (none for the spring-slider).
     */
    struct Layout
    {
      std::vector<double>      positions;
      std::vector<double>      lateral_positions;
      std::vector<std::string> observation_names;
      std::vector<double>      weights;
      std::vector<std::string> station_names;
      double                   convergence_rate        = 1;
      bool                     interpolate_event_times = false;
    };

    /**
     * A model that the generic run loop (RunLoop) advances: it knows the
     * model only through these verbs and through the Controller that makes
     * its steps (MODEL.md §4.3). The wedge (ProblemBase) and the
     * spring-slider are two models. What a model does not have (VTU
     * snapshots, solver work besides the accepted step) has a default that
     * does nothing.
     */
    template <typename State>
    class Model
    {
    public:
      virtual ~Model() = default;

      /** The state at t = 0. */
      virtual State
      initial_state() const = 0;

      /** Node positions and column names of the records. */
      virtual Layout
      layout() const = 0;

      /** What is recorded of an accepted state. */
      virtual Sample
      sample(const State &state) const = 0;

      /**
       * The solver work of every step attempted since the last call
       * (comparison steps and rejected attempts included), then reset.
       */
      virtual StepStatistics
      take_work()
      {
        return {};
      }

      /** Why the last step failed, for the message on step underflow. */
      virtual std::string
      last_failure() const
      {
        return {};
      }

      /**
       * The scene, mesh dimension, number of unknowns and MPI ranks written
       * into the header of a checkpoint: a checkpoint of another
       * discretisation is refused on resume.
       */
      virtual output::CheckpointIdentity
      checkpoint_identity() const = 0;

      /**
       * The lines of the log that describe the model (scene, mesh, solver).
       * The run loop prints them when the run starts: on resume, after the
       * checkpoint has been accepted, so that a refused resume leaves
       * log.txt as it was.
       */
      virtual void
      describe(std::ostream &log) const = 0;

      /** Whether the model writes snapshots (VTU) at all. */
      virtual bool
      writes_snapshots() const
      {
        return false;
      }

      /** Write a snapshot of the state at time t. */
      virtual void
      write_snapshot(const State &, double)
      {}

      /** Time of the last snapshot written (-1 if none). */
      virtual double
      last_snapshot_time() const
      {
        return -1;
      }

      /** What the model's writers keep (snapshot records) in a checkpoint. */
      virtual void
      save_output(boost::archive::binary_oarchive &) const
      {}
      virtual void
      load_output(boost::archive::binary_iarchive &)
      {}
    };
  } // namespace time
} // namespace rsfcycle

#endif
