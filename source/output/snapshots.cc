// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>
#include <filesystem>
#include <rsfcycle/ids.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/snapshots.h>
#include <sstream>

namespace rsfcycle
{
  namespace output
  {
    void
    declare_snapshot_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Output interval",
                        "10",
                        Double(0),
                        "Simulated time between snapshots (vtu, hdf5) [s]");
      prm.declare_entry("Event output interval",
                        "0.1",
                        Double(0),
                        "Simulated time between snapshots (vtu, hdf5) "
                        "during events [s]");
    }


    using namespace dealii;

    namespace
    {
      /** DataOutFaces restricted to the faces of one boundary (the fault). */
      template <int dim>
      class BoundaryFaces : public DataOutFaces<dim>
      {
      public:
        using FaceDescriptor = typename DataOutFaces<dim>::FaceDescriptor;

        explicit BoundaryFaces(const types::boundary_id id)
          : id(id)
        {}

        FaceDescriptor
        first_face() override
        {
          for (const auto &cell : this->triangulation->active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (is_selected(cell, f))
                return {cell, f};
          return {};
        }

        FaceDescriptor
        next_face(const FaceDescriptor &face) override
        {
          auto         cell = face.first;
          unsigned int f    = face.second + 1;
          while (cell != this->triangulation->end())
            {
              for (; f < cell->n_faces(); ++f)
                if (is_selected(cell, f))
                  return {cell, f};
              ++cell;
              while (cell != this->triangulation->end() && !cell->is_active())
                ++cell;
              f = 0;
            }
          return {};
        }

      private:
        bool
        is_selected(const typename Triangulation<dim>::cell_iterator &cell,
                    const unsigned int                                f) const
        {
          return cell->is_active() && cell->is_locally_owned() &&
                 cell->face(f)->at_boundary() &&
                 cell->face(f)->boundary_id() == id;
        }

        const types::boundary_id id;
      };

      /**
       * A DataOut or DataOutFaces whose built patches are mapped into an
       * output frame: points x -> c + Q x, the first `n_vectors` blocks of
       * dim data rows (vector fields) v -> Q v.
       */
      template <class Writer, int dim>
      class InFrame : public Writer
      {
      public:
        using Writer::Writer;

        void
        to_frame(const std::pair<Tensor<2, dim>, Point<dim>> &frame,
                 const unsigned int                           n_vectors)
        {
          const auto &[Q, c] = frame;
          for (auto &patch : this->patches)
            {
              for (auto &x : patch.vertices)
                x = c + Q * x;
              for (unsigned int b = 0; b < n_vectors; ++b)
                rotate(patch.data, b * dim, Q, Point<dim>());
              if (patch.points_are_available)
                rotate(patch.data, patch.data.n_rows() - dim, Q, c);
            }
        }

      private:
        /** Rows r .. r + dim - 1 of every column: x -> shift + Q x. */
        static void
        rotate(Table<2, float>      &data,
               const unsigned int    r,
               const Tensor<2, dim> &Q,
               const Point<dim>     &shift)
        {
          for (unsigned int j = 0; j < data.n_cols(); ++j)
            {
              Tensor<1, dim> x;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = data(r + d, j);
              x = shift + Q * x;
              for (unsigned int d = 0; d < dim; ++d)
                data(r + d, j) = x[d];
            }
        }
      };

      /** The base fields in the order of Snapshots::base_fields(). */
      enum Field
      {
        slip_rate,
        log_slip_rate,
        theta,
        mu,
        traction,
        normal_stress,
        rate_minus_v0,
        slip_um,
        n_fields
      };
    } // namespace


    template <int dim>
    Snapshots<dim>::Snapshots(const std::string      &dir,
                              const BodySource<dim>  &source,
                              const OutputParameters &output)
      : dir(dir)
      , source(source)
      , interval(output.output_interval)
      , event_interval(output.event_output_interval)
    {}


    template <int dim>
    const BodyState &
    Snapshots<dim>::body_of(const Record &record)
    {
      if (!source.body)
        return record.state_as<BodyState>();
      made = source.body(record);
      return made;
    }


    template <int dim>
    void
    Snapshots<dim>::start(const Record &record)
    {
      write_snapshot(body_of(record), record.t);
    }


    template <int dim>
    void
    Snapshots<dim>::write(const Record &record)
    {
      const double eps = 1e-12 * std::max(1., record.t);
      if (record.t >=
          last_output +
            (record.events->in_event() ? event_interval : interval) - eps)
        {
          write_snapshot(body_of(record), record.t);
          last_output = record.t;
        }
    }


    template <int dim>
    void
    Snapshots<dim>::finish(const Record &record)
    {
      if (last_time() < record.t)
        write_snapshot(body_of(record), record.t);
    }


    template <int dim>
    void
    Snapshots<dim>::save(boost::archive::binary_oarchive &archive) const
    {
      archive << n_snapshots << last_output;
      save_records(archive);
    }


    template <int dim>
    void
    Snapshots<dim>::load(boost::archive::binary_iarchive &archive)
    {
      archive >> n_snapshots >> last_output;
      load_records(archive);
    }


    template <int dim>
    void
    VtuSnapshots<dim>::save_records(
      boost::archive::binary_oarchive &archive) const
    {
      archive << records << fault_records;
    }


    template <int dim>
    void
    VtuSnapshots<dim>::load_records(boost::archive::binary_iarchive &archive)
    {
      archive >> records >> fault_records;
    }


    template <int dim>
    std::vector<la::Vector>
    Snapshots<dim>::base_fields(const BodyState &state) const
    {
      const auto             &discretisation = *source.discretisation;
      const auto             &contact        = *source.contact;
      const auto             &law            = *source.law;
      const double            v0             = source.convergence_rate;
      std::vector<la::Vector> field(
        n_fields, la::Vector(discretisation.scalar_partitioner));
      field[log_slip_rate]            = std::log10(1e-20);
      const auto               &nodes = contact.nodes();
      const std::vector<double> rates =
        state.slip_rate.empty() ? contact.slip_rates(state.v) : state.slip_rate;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          const auto &info = nodes[k];
          // the scalar dof of a vertex has the owner of its vector dofs
          const auto dof =
            discretisation.scalar_partitioner->global_to_local(info.scalar_dof);
          if (dof >= discretisation.scalar_partitioner->locally_owned_size())
            throw std::logic_error("snapshot: a contact node's scalar dof "
                                   "is owned by another rank");
          field[slip_rate].local_element(dof) = rates[k];
          field[log_slip_rate].local_element(dof) =
            std::log10(std::max(rates[k] / v0, 1e-20));
          field[theta].local_element(dof) =
            std::exp(info.params.log_theta(state.alpha[k]));
          field[mu].local_element(dof) =
            law.friction_coefficient(info.params, state.alpha[k], rates[k]);
          field[traction].local_element(dof) = state.shear_traction[k];
          field[normal_stress].local_element(dof) =
            state.normal_stress.empty() ? info.normal_force / info.weight :
                                          state.normal_stress[k];
          field[rate_minus_v0].local_element(dof) = rates[k] - v0;
          field[slip_um].local_element(dof) =
            1e6 * (state.slip.empty() ?
                     solvers::tangential_norm(contact.contact_set().nodes[k],
                                              state.u) :
                     state.slip[k]);
        }
      for (const Field f : {slip_rate,
                            theta,
                            mu,
                            traction,
                            normal_stress,
                            rate_minus_v0,
                            slip_um})
        discretisation.scalar_constraints.distribute(field[f]);
      for (auto &f : field)
        f.update_ghost_values();
      return field;
    }


    template <int dim>
    MPI_Comm
    Snapshots<dim>::communicator() const
    {
      return source.discretisation->triangulation.get_communicator();
    }


    template <int dim>
    std::string
    Snapshots<dim>::in_folder(const std::string &name) const
    {
      const std::filesystem::path path = dir + "/" + name;
      std::error_code             error;
      std::filesystem::create_directories(path.parent_path(), error);
      if (error)
        throw std::runtime_error(path.parent_path().string() + ": " +
                                 error.message());
      return path.string();
    }


    template <int dim>
    void
    Snapshots<dim>::write_snapshot(const BodyState &state, const double t)
    {
      TimerOutput::Scope            scope(*source.timer, "Output");
      const auto                   &discretisation = *source.discretisation;
      const std::vector<la::Vector> field          = base_fields(state);
      state.u.update_ghost_values();
      state.v.update_ghost_values();
      const auto &scalar_dofs = discretisation.scalar_dof_handler;

      InFrame<DataOut<dim>, dim> data_out;
      data_out.attach_dof_handler(discretisation.dof_handler);
      // vectors, or in the antiplane model the out-of-plane component
      const unsigned int n_components = discretisation.fe.n_components();
      const bool         vectors      = n_components == dim;
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          n_components,
          vectors ? DataComponentInterpretation::component_is_part_of_vector :
                    DataComponentInterpretation::component_is_scalar);
      const std::string suffix = vectors ? "" : "_out_of_plane";
      data_out.add_data_vector(
        state.u,
        std::vector<std::string>(n_components, "displacement" + suffix),
        DataOut<dim>::type_dof_data,
        interpretation);
      data_out.add_data_vector(state.v,
                               std::vector<std::string>(n_components,
                                                        "velocity" + suffix),
                               DataOut<dim>::type_dof_data,
                               interpretation);
      data_out.add_data_vector(scalar_dofs, field[slip_rate], "slip_rate");
      data_out.add_data_vector(scalar_dofs,
                               field[log_slip_rate],
                               "log10_slip_rate_over_v0");
      data_out.add_data_vector(scalar_dofs, field[theta], "state");
      data_out.add_data_vector(scalar_dofs, field[mu], "friction_coefficient");
      data_out.add_data_vector(scalar_dofs, field[traction], "shear_traction");
      data_out.add_data_vector(scalar_dofs,
                               field[normal_stress],
                               "normal_stress");
      const auto   &tria = discretisation.triangulation;
      Vector<float> subdomain(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        subdomain[cell->active_cell_index()] = cell->subdomain_id();
      data_out.add_data_vector(subdomain, "mpi_rank");
      Vector<float> material(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        material[cell->active_cell_index()] = cell->material_id();
      data_out.add_data_vector(material, "material_id");
      data_out.build_patches();
      data_out.to_frame(source.frame,
                        vectors ? 2 : 0); // displacement, velocity

      // The fault (contact faces) at the same times (the paper's figure 9
      // draws isolines of V - v0 on it).
      InFrame<BoundaryFaces<dim>, dim> fault(boundary_id::contact);
      fault.attach_dof_handler(scalar_dofs);
      fault.add_data_vector(field[rate_minus_v0], "slip_rate_minus_v0");
      fault.add_data_vector(field[log_slip_rate], "log10_slip_rate_over_v0");
      fault.add_data_vector(field[theta], "state");
      fault.add_data_vector(field[slip_um], "slip_um");
      fault.add_data_vector(field[traction], "shear_traction");
      fault.add_data_vector(field[normal_stress], "normal_stress");
      fault.add_data_vector(field[mu], "friction_coefficient");
      fault.build_patches();
      fault.to_frame(source.frame, 0);
      store(data_out, fault, t, n_snapshots);
      state.u.zero_out_ghost_values();
      state.v.zero_out_ghost_values();
      ++n_snapshots;
    }


    template <int dim>
    void
    VtuSnapshots<dim>::store(DataOutInterface<dim, dim>     &body,
                             DataOutInterface<dim - 1, dim> &fault,
                             const double                    t,
                             const unsigned int              number)
    {
      DataOutBase::VtkFlags flags;
      flags.time  = t;
      flags.cycle = number;
      // deal.II's default, zlib's best compression, made the snapshots
      // a tenth of the paper run's wall time; best_speed writes files
      // about 1.3x larger several times faster (ParaView reads both)
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      body.set_flags(flags);
      fault.set_flags(flags);
      const std::string n = Utilities::int_to_string(number, 5);
      records.emplace_back(t, write_pieces(body, "solution/solution-" + n));
      fault_records.emplace_back(t, write_pieces(fault, "fault/fault-" + n));
      if (is_root())
        {
          std::ostringstream pvd, fault_pvd;
          DataOutBase::write_pvd_record(pvd, records);
          replace_file(this->dir + "/solution.pvd", pvd.str());
          DataOutBase::write_pvd_record(fault_pvd, fault_records);
          replace_file(this->dir + "/fault.pvd", fault_pvd.str());
        }
    }


    /**
     * One rank: `stem`.vtu. N ranks: every rank writes its cells to
     * `stem`.RANK.vtu and the first rank `stem`.pvtu naming them. Returns
     * the name to record in the PVD file.
     */
    template <int dim>
    template <int patch_dim>
    std::string
    VtuSnapshots<dim>::write_pieces(
      const DataOutInterface<patch_dim, dim> &writer,
      const std::string                      &stem) const
    {
      const MPI_Comm     comm    = this->communicator();
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const auto         piece   = [&](const unsigned int r) {
        return n_ranks == 1 ?
                           stem + ".vtu" :
                           stem + "." + Utilities::int_to_string(r, 4) + ".vtu";
      };
      {
        std::ostringstream vtu;
        writer.write_vtu(vtu);
        write_file(this->in_folder(piece(rank)), vtu.str());
      }
      if (n_ranks == 1)
        return piece(0);
      if (rank == 0)
        {
          std::vector<std::string> pieces;
          const std::string folder = stem.substr(0, stem.find_last_of('/') + 1);
          for (unsigned int r = 0; r < n_ranks; ++r)
            pieces.push_back(piece(r).substr(folder.size()));
          std::ostringstream pvtu;
          writer.write_pvtu_record(pvtu, pieces);
          write_file(this->in_folder(stem + ".pvtu"), pvtu.str());
        }
      return stem + ".pvtu";
    }


    template class Snapshots<2>;
    template class Snapshots<3>;
    template class VtuSnapshots<2>;
    template class VtuSnapshots<3>;
  } // namespace output
} // namespace rsfcycle
