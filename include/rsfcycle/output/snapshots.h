#ifndef rsfcycle_output_snapshots_h
#define rsfcycle_output_snapshots_h

#include <rsfcycle/friction/contact_quadrature.h>
#include <rsfcycle/la.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/time/newmark_step.h>
#include <string>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * VTU snapshots of the body (solution.pvd, solution/solution-N.vtu:
     * displacement, velocity, material and the friction fields on the base) and
     * of the fault (fault.pvd, fault/fault-N.vtu: the contact faces,
     * DataOutFaces), with their PVD records kept as members (and in
     * checkpoints). Points and vector fields are written in the output
     * frame x = c + Q p of the scene (Scene::output_frame()).
     */
    template <int dim>
    class SnapshotWriter
    {
    public:
      SnapshotWriter(
        const std::string                      &dir,
        const physics::Discretisation<dim>     &discretisation,
        const friction::ContactQuadrature<dim> &contact,
        const friction::Law                    &law,
        double                                  convergence_rate,
        const std::pair<dealii::Tensor<2, dim>, dealii::Point<dim>> &frame);

      /** Write the snapshot of the state at time t. */
      void
      write(const BodyState &state, double t);

      /** Time of the last snapshot (-1 if none). */
      double
      last_time() const
      {
        return records.empty() ? -1. : records.back().first;
      }

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &n_snapshots &records &fault_records;
      }

    private:
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
      template <class Writer>
      std::string
      write_pieces(const Writer &writer, const std::string &stem) const;

      const std::string                       dir;
      const physics::Discretisation<dim>     &discretisation;
      const friction::ContactQuadrature<dim> &contact;
      const friction::Law                    &law;
      const double                            v0;
      /** Q and c of the output frame. */
      const std::pair<dealii::Tensor<2, dim>, dealii::Point<dim>> frame;

      std::vector<std::pair<double, std::string>> records, fault_records;
      unsigned int                                n_snapshots = 0;
    };
  } // namespace output
} // namespace rsfcycle

#endif
