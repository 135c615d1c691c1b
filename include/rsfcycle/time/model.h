// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_model_h
#define rsfcycle_time_model_h

#include <memory>
#include <ostream>
#include <rsfcycle/output/checkpoint.h>
#include <rsfcycle/output/sample.h>
#include <rsfcycle/output/writer.h>
#include <rsfcycle/output/writers.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace time
  {
    /**
     * A model that the simulator (simulator/simulator.h) runs: it knows the
     * model only through these verbs, and the integrator through what the
     * model gives it besides (time::ImplicitModel: an implicit step under
     * step-size control; time::OdeModel: an ODE for an ODE integrator). The
     * continuum (ProblemBase) and the spring-slider are models. What a
     * model does not have (outputs of its own, solver work besides the
     * accepted step) has a default that does nothing.
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
      virtual output::Layout
      layout() const = 0;

      /** What is recorded of an accepted state. */
      virtual output::Sample
      sample(const State &state) const = 0;

      /**
       * The scene, mesh dimension, number of unknowns and MPI ranks written
       * into the header of a checkpoint: a checkpoint of another
       * discretisation is refused on resume.
       */
      virtual output::CheckpointIdentity
      checkpoint_identity() const = 0;

      /**
       * The lines of the log that describe the model (scene, mesh, solver).
       * The simulator prints them when the run starts: on resume, after the
       * checkpoint has been accepted, so that a refused resume leaves
       * log.txt as it was.
       */
      virtual void
      describe(std::ostream &log) const = 0;

      /**
       * What the model offers the writers of `Output/Writers`
       * (output/writers.h): by default the contact's slip and stresses; a
       * model with a body on a mesh adds the body (the snapshots' source).
       */
      virtual output::Offer
      offer()
      {
        return {};
      }

      /**
       * The solver work of every step attempted since the last call
       * (comparison steps and rejected attempts included), then reset.
       */
      virtual solvers::StepStatistics
      take_work()
      {
        return {};
      }

      /**
       * A step has been accepted, and a checkpoint of it may be written:
       * forget what the next steps would take from earlier ones and a run
       * resumed from it could not have (a direct correction's factors), so
       * that a resumed run repeats the uninterrupted one bit for bit.
       */
      virtual void
      step_accepted()
      {}

      /** Why the last step failed, for the message on step underflow. */
      virtual std::string
      last_failure() const
      {
        return {};
      }
    };
  } // namespace time
} // namespace rsfcycle

#endif
