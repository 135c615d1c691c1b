// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_snapshots_h
#define rsfcycle_output_snapshots_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
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
     * What a model with a body on a mesh offers the snapshot writers
     * (output::Offer::body, with output::Field::body): its discretisation,
     * contact, friction law, convergence rate v0, the scene's output frame
     * x = c + Q p (Scene::output_frame()), the timer whose section "Output"
     * the snapshots count in, and how a record's state becomes a BodyState
     * (empty: the record's state is one).
     */
    template <int dim>
    struct BodySource
    {
      const physics::Discretisation<dim>    *discretisation   = nullptr;
      const physics::ContactQuadrature<dim> *contact          = nullptr;
      const friction::Law                   *law              = nullptr;
      double                                 convergence_rate = 1;
      std::pair<dealii::Tensor<2, dim>, dealii::Point<dim>> frame;
      dealii::TimerOutput                                  *timer = nullptr;
      std::function<BodyState(const Record &)>              body;
    };


    /**
     * The snapshots' entries in subsection Output (entered by the caller),
     * shared by every format: Output interval and Event output interval
     * (OutputParameters reads them).
     */
    void
    declare_snapshot_parameters(dealii::ParameterHandler &prm);


    /**
     * Snapshots of the body (displacement, velocity, material, MPI rank and
     * the friction fields on the base) and of the fault (the contact faces:
     * slip rate, state, slip, stresses), at t = 0, every `Output/Output
     * interval` (during events every `Event output interval`) and at the
     * end. Points and vector fields are written in the output frame. A
     * format is a class derived from this one that stores the two data sets
     * of a snapshot and keeps its records in checkpoints.
     */
    template <int dim>
    class Snapshots : public Writer
    {
    public:
      Snapshots(const std::string      &dir,
                const BodySource<dim>  &source,
                const OutputParameters &output);

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

    protected:
      /** Store snapshot `number` at time t: the body and the fault. */
      virtual void
      store(dealii::DataOutInterface<dim, dim>     &body,
            dealii::DataOutInterface<dim - 1, dim> &fault,
            double                                  t,
            unsigned int                            number) = 0;

      /** The format's records (file names, times) for a checkpoint. */
      virtual void
      save_records(boost::archive::binary_oarchive &archive) const = 0;
      virtual void
      load_records(boost::archive::binary_iarchive &archive) = 0;

      /** Time of the last snapshot (-1 if none). */
      virtual double
      last_time() const = 0;

      /**
       * The path of `name` (e.g. "solution/solution-00000.vtu") in the run
       * folder, whose subfolder is created if it is missing.
       */
      std::string
      in_folder(const std::string &name) const;

      /** The mesh's communicator. */
      MPI_Comm
      communicator() const;

      const std::string dir;

    private:
      /**
       * The body of a record: its state, or what the source makes of the
       * record (a model whose state is not a BodyState).
       */
      const BodyState &
      body_of(const Record &record);

      /** Build and store the snapshot of the state at time t. */
      void
      write_snapshot(const BodyState &state, double t);

      /** The friction fields on the base as scalar FE vectors. */
      std::vector<la::Vector>
      base_fields(const BodyState &state) const;

      const BodySource<dim> source;
      /** Simulated time between snapshots, outside and during events. */
      const double interval, event_interval;
      BodyState    made; // by source.body

      unsigned int n_snapshots = 0;
      double       last_output = 0;
    };


    /**
     * VTU snapshots (`Output/Writers = vtu`): solution.pvd with
     * solution/solution-N.vtu, fault.pvd with fault/fault-N.vtu; on N ranks
     * one .vtu per rank and a .pvtu naming them.
     */
    template <int dim>
    class VtuSnapshots : public Snapshots<dim>
    {
    public:
      using Snapshots<dim>::Snapshots;

      std::string
      name() const override
      {
        return "VTU snapshots";
      }

    protected:
      void
      store(dealii::DataOutInterface<dim, dim>     &body,
            dealii::DataOutInterface<dim - 1, dim> &fault,
            double                                  t,
            unsigned int                            number) override;

      void
      save_records(boost::archive::binary_oarchive &archive) const override;
      void
      load_records(boost::archive::binary_iarchive &archive) override;

      double
      last_time() const override
      {
        return records.empty() ? -1. : records.back().first;
      }

    private:
      /** Write a data set as one file per rank (and a .pvtu). */
      template <int patch_dim>
      std::string
      write_pieces(const dealii::DataOutInterface<patch_dim, dim> &writer,
                   const std::string                              &stem) const;

      std::vector<std::pair<double, std::string>> records, fault_records;
    };
  } // namespace output
} // namespace rsfcycle

#endif
