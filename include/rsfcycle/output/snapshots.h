// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_snapshots_h
#define rsfcycle_output_snapshots_h

#include <deal.II/base/timer.h>
#include <functional>
#include <rsfcycle/friction/law.h>
#include <rsfcycle/la.h>
#include <rsfcycle/output/writer.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/body_state.h>
#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/discretisation.h>
#include <string>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * VTU snapshots of the body (solution.pvd, solution/solution-N.vtu:
     * displacement, velocity, material and the friction fields on the base)
     * and of the fault (fault.pvd, fault/fault-N.vtu: the contact faces,
     * DataOutFaces), with their PVD records kept as members (and in
     * checkpoints): at t = 0, every `Output/Output interval` (during events
     * every `Event output interval`) and at the end. Points and vector
     * fields are written in the output frame x = c + Q p of the scene
     * (Scene::output_frame()). The continuum's own writer (ProblemBase::
     * writers(), with `Output/Write VTU`); it reads the BodyState of the
     * record.
     */
    template <int dim>
    class SnapshotWriter : public Writer
    {
    public:
      SnapshotWriter(
        const std::string                     &dir,
        const physics::Discretisation<dim>    &discretisation,
        const physics::ContactQuadrature<dim> &contact,
        const friction::Law                   &law,
        double                                 convergence_rate,
        const std::pair<dealii::Tensor<2, dim>, dealii::Point<dim>> &frame,
        const OutputParameters                                      &output,
        dealii::TimerOutput                                         &timer,
        std::function<BodyState(const Record &)>                     body = {});

      std::string
      name() const override
      {
        return "VTU snapshots";
      }

      void
      start(const Record &record) override;

      void
      write(const Record &record) override;

      void
      finish(const Record &record) override;

      void
      save(boost::archive::binary_oarchive &archive) const override;
      void
      load(boost::archive::binary_iarchive &archive) override;

    private:
      /**
       * The body of a record: its state, or what `body` makes of the
       * record (a model whose state is not a BodyState).
       */
      const BodyState &
      body_of(const Record &record);

      /** Write the snapshot of the state at time t. */
      void
      write_snapshot(const BodyState &state, double t);

      /** Time of the last snapshot (-1 if none). */
      double
      last_time() const
      {
        return records.empty() ? -1. : records.back().first;
      }

      /**
       * The path of `name` (e.g. "solution/solution-00000.vtu") in the run
       * folder, whose subfolder is created if it is missing.
       */
      std::string
      in_folder(const std::string &name) const;

      /** The friction fields on the base as scalar FE vectors. */
      std::vector<la::Vector>
      base_fields(const BodyState &state) const;

      /** Write a DataOut(Faces) as one file per rank (and a .pvtu). */
      template <class DataWriter>
      std::string
      write_pieces(const DataWriter &writer, const std::string &stem) const;

      const std::string                      dir;
      const physics::Discretisation<dim>    &discretisation;
      const physics::ContactQuadrature<dim> &contact;
      const friction::Law                   &law;
      const double                           v0;
      /** Q and c of the output frame. */
      const std::pair<dealii::Tensor<2, dim>, dealii::Point<dim>> frame;
      /** Simulated time between snapshots, outside and during events. */
      const double interval, event_interval;
      /** Times the snapshots in the section "Output". */
      dealii::TimerOutput                           &timer;
      const std::function<BodyState(const Record &)> body;
      BodyState                                      made; // by body

      std::vector<std::pair<double, std::string>> records, fault_records;
      unsigned int                                n_snapshots = 0;
      double                                      last_output = 0;
    };
  } // namespace output
} // namespace rsfcycle

#endif
