// SPDX-License-Identifier: LGPL-2.1-or-later
// The two sides of a split fault tied in the gathered system
// (physics/split_fault.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <limits>
#include <map>
#include <rsfcycle/format.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/la.h>
#include <rsfcycle/physics/split_fault.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace physics
  {
    namespace
    {
      const std::string refused = "Mesh file/Boundary roles: ";

      /**
       * A vertex of the fault: position, dofs per component, hanging, and
       * the sign of its side's outward normal along the normal component
       * (y of the rotated frame, where the fault lies).
       */
      struct FaultVertex
      {
        std::array<double, 3>       x = {{0., 0., 0.}};
        std::array<unsigned int, 3> dofs;
        unsigned int                n_components = 0;
        bool                        hanging      = false;
        double                      outward      = 0;
      };

      /** +1 on the contact and creep faces, -1 on fault-opposite, else 0. */
      template <class FaceIterator>
      int
      fault_side(const FaceIterator &face)
      {
        if (!face->at_boundary())
          return 0;
        const auto id = face->boundary_id();
        return (id == boundary_id::contact || id == boundary_id::creep) ? 1 :
               id == boundary_id::fault_opposite                        ? -1 :
                                                                          0;
      }


      /** Positions (x, y, z; z = 0 in 2D) sorted lexicographically. */
      using Positions = std::vector<std::array<double, 3>>;

      /**
       * The index of the first position of `sorted` within `tolerance` of x
       * in every coordinate that `accept(index)` takes; sorted.size() if
       * none.
       */
      template <class Accept>
      std::size_t
      find_position(const Positions             &sorted,
                    const std::array<double, 3> &x,
                    const double                 tolerance,
                    const Accept                &accept)
      {
        const std::array<double, 3> low = {
          {x[0] - tolerance, -std::numeric_limits<double>::max(), 0.}};
        for (auto k = std::lower_bound(sorted.begin(), sorted.end(), low) -
                      sorted.begin();
             k < static_cast<long>(sorted.size()) &&
             sorted[k][0] <= x[0] + tolerance;
             ++k)
          if (std::abs(sorted[k][1] - x[1]) <= tolerance &&
              std::abs(sorted[k][2] - x[2]) <= tolerance && accept(k))
            return k;
        return sorted.size();
      }


      /**
       * The fault's vertices of one side (+: contact and creep faces, -:
       * fault-opposite faces) of every rank, each once.
       */
      template <int dim>
      std::vector<FaultVertex>
      fault_vertices(const Discretisation<dim> &discretisation, const bool plus)
      {
        // (n_components, hanging, x, y, z, dof 0, 1, 2, outward) as
        // doubles for the gather
        std::vector<std::array<double, 9>> local;
        const unsigned int n_components = discretisation.fe.n_components();
        for (const auto &cell :
             discretisation.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              {
                if (fault_side(face) != (plus ? 1 : -1))
                  continue;
                const double outward =
                  face->center()[1] > cell->center()[1] ? 1. : -1.;
                for (const unsigned int v : face->vertex_indices())
                  {
                    std::array<double, 9> entry = {
                      {0., 0., 0., 0., 0., -1., -1., -1., outward}};
                    entry[0] = n_components;
                    for (unsigned int d = 0; d < dim; ++d)
                      entry[2 + d] = face->vertex(v)[d];
                    for (unsigned int c = 0; c < n_components; ++c)
                      entry[5 + c] = face->vertex_dof_index(v, c);
                    entry[1] =
                      discretisation.hanging_constraints.is_constrained(
                        face->vertex_dof_index(v, 0)) ?
                        1. :
                        0.;
                    local.push_back(entry);
                  }
              }
        std::map<unsigned int, FaultVertex> by_dof;
        for (const auto &entry :
             la::all_gather(discretisation.triangulation.get_communicator(),
                            local))
          {
            FaultVertex vertex;
            vertex.n_components = static_cast<unsigned int>(entry[0]);
            vertex.hanging      = entry[1] != 0;
            vertex.outward      = entry[8];
            for (unsigned int d = 0; d < 3; ++d)
              vertex.x[d] = entry[2 + d];
            for (unsigned int c = 0; c < vertex.n_components; ++c)
              vertex.dofs[c] = static_cast<unsigned int>(entry[5 + c]);
            by_dof.emplace(vertex.dofs[0], vertex);
          }
        std::vector<FaultVertex> vertices;
        for (const auto &[dof, vertex] : by_dof)
          vertices.push_back(vertex);
        return vertices;
      }


      std::string
      position(const FaultVertex &vertex, const int dim)
      {
        std::string text = "(";
        for (int d = 0; d < dim; ++d)
          text += (d > 0 ? ", " : "") + format_number(vertex.x[d]);
        return text + ")";
      }
      using Terms = std::vector<std::pair<unsigned int, double>>;

      /**
       * Row j of T (u = T u~): the tied unknowns l and weights T_jl that
       * make dof j of the kind `kind` with partner `partner`.
       */
      Terms
      tie_terms(const unsigned char kind,
                const unsigned int  partner,
                const unsigned int  j)
      {
        switch (kind)
          {
            case tie_slip:
              return {{j, 0.5}, {partner, 1.}};
            case tie_mean:
              return {{partner, -0.5}, {j, 1.}};
            case tie_gone:
              return {{partner, 1.}};
            default:
              return {{j, 1.}};
          }
      }

      Terms
      forward_terms(const FaultTie &tie, const unsigned int j)
      {
        return tie_terms(tie.kind[j], tie.partner[j], j);
      }

      /** Column k of T: the dofs i and weights T_ik (K~ = T^T K T). */
      Terms
      backward_terms(const FaultTie &tie, const unsigned int k)
      {
        const unsigned int partner = tie.partner[k];
        switch (tie.kind[k])
          {
            case tie_slip:
              return {{k, 0.5}, {partner, -0.5}};
            case tie_mean:
              return {{partner, 1.}, {k, 1.}};
            case tie_normal:
              return {{k, 1.}, {partner, 1.}};
            case tie_gone:
              return {};
            default:
              return {{k, 1.}};
          }
      }

      const std::string refused_opposite_load =
        refused + "a fault-opposite node is prescribed (load-opposite) "
                  "where its contact node is free; prescribe both sides or "
                  "neither";
    } // namespace


    template <int dim>
    FaultTie
    pair_fault_sides(const Discretisation<dim> &discretisation,
                     const unsigned int         n)
    {
      const auto plus  = fault_vertices(discretisation, true);
      auto       minus = fault_vertices(discretisation, false);

      // pair by position (both sides lie in y = 0 of the rotated frame)
      double extent = 0;
      for (const auto &vertex : plus)
        for (unsigned int d = 0; d < 3; ++d)
          extent = std::max(extent, std::abs(vertex.x[d]));
      const double tolerance = 1e-9 * std::max(extent, 1.);
      std::sort(minus.begin(), minus.end(), [](const auto &a, const auto &b) {
        return a.x < b.x;
      });
      Positions minus_positions;
      for (const auto &vertex : minus)
        minus_positions.push_back(vertex.x);
      std::vector<bool> taken(minus.size(), false);

      // per dof: its part in the pairs and its partner
      FaultTie tie;
      tie.kind.assign(n, tie_none);
      tie.partner.assign(n, 0);
      auto              &kind             = tie.kind;
      auto              &partner          = tie.partner;
      const unsigned int normal_component = discretisation.normal_component();
      for (const auto &p : plus)
        {
          const std::size_t k =
            find_position(minus_positions,
                          p.x,
                          tolerance,
                          [&taken](const std::size_t i) { return !taken[i]; });
          if (k == minus.size())
            throw std::invalid_argument(
              refused + "the fault node at " + position(p, dim) +
              " (rotated frame) has no node of a fault-opposite face at "
              "its position; the two sides need the same nodes");
          taken[k]      = true;
          const auto &m = minus[k];
          if (p.hanging != m.hanging)
            throw std::invalid_argument(
              refused + "the fault node at " + position(p, dim) +
              " hangs on one side only: the two sides of the fault are "
              "refined differently");
          if (p.hanging)
            continue; // (its parents are paired)
          for (unsigned int c = 0; c < p.n_components; ++c)
            {
              const unsigned int a = p.dofs[c], b = m.dofs[c];
              kind[a]    = c == normal_component ? tie_normal : tie_slip;
              kind[b]    = c == normal_component ? tie_gone : tie_mean;
              partner[a] = b;
              partner[b] = a;
              if (c != normal_component && normal_component < p.n_components)
                tie.normal_of[a] = {p.dofs[normal_component], p.outward};
            }
        }
      for (unsigned int k = 0; k < minus.size(); ++k)
        if (!taken[k])
          throw std::invalid_argument(
            refused + "the fault-opposite node at " + position(minus[k], dim) +
            " has no contact or creep node at its position; the two sides "
            "need the same nodes");
      return tie;
    }


    void
    tie_matrix(const FaultTie            &tie,
               std::vector<std::size_t>  &row_start,
               std::vector<unsigned int> &columns,
               std::vector<double>       &values)
    {
      const unsigned int        n = row_start.size() - 1;
      std::vector<std::size_t>  new_start(1, 0);
      std::vector<unsigned int> new_columns;
      std::vector<double>       new_values;
      Terms                     row;
      for (unsigned int k = 0; k < n; ++k)
        {
          row.clear();
          if (tie.kind[k] == tie_gone)
            row.emplace_back(k, 1.);
          for (const auto &[i, t_ik] : backward_terms(tie, k))
            for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
              for (const auto &[l, t_jl] : forward_terms(tie, columns[e]))
                row.emplace_back(l, t_ik * values[e] * t_jl);
          std::sort(row.begin(), row.end(), [](const auto &x, const auto &y) {
            return x.first < y.first;
          });
          for (std::size_t e = 0; e < row.size(); ++e)
            if (e > 0 && row[e].first == new_columns.back())
              new_values.back() += row[e].second;
            else
              {
                new_columns.push_back(row[e].first);
                new_values.push_back(row[e].second);
              }
          new_start.push_back(new_columns.size());
        }
      row_start = std::move(new_start);
      columns   = std::move(new_columns);
      values    = std::move(new_values);
    }


    std::vector<double>
    tie_force(const FaultTie &tie, const std::vector<double> &force)
    {
      // (the tangential force on the + side is the shear prestress, the
      // fault's internal traction: it acts on the - side too, opposite;
      // both methods refuse gravity with a split fault)
      const unsigned int  n          = force.size();
      std::vector<double> pair_force = force, tied(n, 0.);
      for (unsigned int a = 0; a < n; ++a)
        if (tie.kind[a] == tie_slip)
          pair_force[tie.partner[a]] -= force[a];
      for (unsigned int k = 0; k < n; ++k)
        for (const auto &[i, t_ik] : backward_terms(tie, k))
          tied[k] += t_ik * pair_force[i];
      return tied;
    }


    ObservationRow
    tie_row(const FaultTie &tie, const ObservationRow &row)
    {
      ObservationRow tied;
      for (const auto &[j, w] : row)
        for (const auto &[l, t_jl] : forward_terms(tie, j))
          tied.emplace_back(l, w * t_jl);
      return tied;
    }


    std::vector<ObservationRow>
    normal_force_rows(const FaultTie                  &tie,
                      const std::vector<std::size_t>  &row_start,
                      const std::vector<unsigned int> &columns,
                      const std::vector<double>       &values,
                      const std::vector<unsigned int> &contact_dofs)
    {
      // -n (K u)_c of the untied stiffness's row c (the + side's cells
      // alone), in u~
      std::vector<ObservationRow> rows;
      if (!tie.normal_of.empty())
        for (const unsigned int a : contact_dofs)
          {
            const auto [c, outward] = tie.normal_of.at(a);
            ObservationRow row;
            for (std::size_t e = row_start[c]; e < row_start[c + 1]; ++e)
              for (const auto &[l, t_jl] : forward_terms(tie, columns[e]))
                row.emplace_back(l, -outward * values[e] * t_jl);
            rows.push_back(std::move(row));
          }
      return rows;
    }


    void
    tie_prescribed(const FaultTie      &tie,
                   std::vector<bool>   &fixed,
                   std::vector<double> &values)
    {
      const std::vector<bool>   fix = fixed;
      const std::vector<double> v   = values;
      for (unsigned int a = 0; a < fix.size(); ++a)
        {
          const unsigned int b = tie.partner[a];
          if (tie.kind[a] == tie_slip)
            {
              if (!fix[a] && fix[b])
                throw std::invalid_argument(refused_opposite_load);
              // creep: the two plates' difference, +v - (-v)
              values[a] = fix[b] ? v[a] - v[b] : 2 * v[a];
              values[b] = fix[b] ? 0.5 * (v[a] + v[b]) : 0.;
            }
          else if (tie.kind[a] == tie_normal)
            {
              fixed[a]  = fix[a] || fix[b];
              values[a] = fix[a] ? v[a] : v[b];
              fixed[b]  = true;
              values[b] = 0;
            }
        }
    }


    template <int dim>
    void
    tie_split_fault(const Discretisation<dim> &discretisation,
                    GlobalSystem              &system)
    {
      FaultTie tie = pair_fault_sides(discretisation, system.n());

      // the normal force on each contact dof's node (+ side): the other
      // side's push against the outward normal n
      system.normal_rows = normal_force_rows(tie,
                                             system.row_start,
                                             system.columns,
                                             system.values,
                                             system.contact_dofs);
      // K~ = T^T K T, f~ = T^T f, the observation rows in u~
      tie_matrix(tie, system.row_start, system.columns, system.values);
      system.force = tie_force(tie, system.force);
      for (auto &observation : system.observations)
        observation = tie_row(tie, observation);

      // the prescribed dofs in the new unknowns
      tie_prescribed(tie, system.fixed, system.fixed_velocity);
      system.tie_kind    = std::move(tie.kind);
      system.tie_partner = std::move(tie.partner);
    }


    void
    untie_split_fault(const GlobalSystem &system, std::vector<double> &u)
    {
      const std::vector<double> tied = u;
      for (unsigned int j = 0; j < u.size(); ++j)
        {
          u[j] = 0;
          for (const auto &[l, t_jl] :
               tie_terms(system.tie_kind[j], system.tie_partner[j], j))
            u[j] += t_jl * tied[l];
        }
    }


    void
    untie_split_fault(const FaultTie &tie, la::Vector &u)
    {
      // the rank's dofs; a partner on another rank is a ghost
      // (Discretisation::tie_fault_sides())
      u.update_ghost_values();
      const la::Vector tied        = u;
      const auto      &partitioner = *u.get_partitioner();
      for (unsigned int l = 0; l < partitioner.locally_owned_size(); ++l)
        {
          const auto j = partitioner.local_to_global(l);
          if (tie.kind[j] == tie_none)
            continue;
          double value = 0;
          for (const auto &[k, t_jk] : forward_terms(tie, j))
            value += t_jk * tied.local_element(partitioner.global_to_local(k));
          u.local_element(l) = value;
        }
      u.update_ghost_values();
    }


    template <int dim>
    void
    refine_fault_sides_alike(Triangulation<dim> &triangulation)
    {
      const MPI_Comm comm = triangulation.get_communicator();
      for (unsigned int round = 0; round < 20; ++round)
        {
          // the vertices of every rank's active fault faces, per side
          std::vector<std::array<double, 4>> local;
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto &face : cell->face_iterators())
                if (const int side = fault_side(face); side != 0)
                  for (const unsigned int v : face->vertex_indices())
                    {
                      std::array<double, 4> entry = {{double(side), 0, 0, 0}};
                      for (unsigned int d = 0; d < dim; ++d)
                        entry[1 + d] = face->vertex(v)[d];
                      local.push_back(entry);
                    }
          std::array<Positions, 2> vertices;
          double                   extent = 1;
          for (const auto &entry : la::all_gather(comm, local))
            {
              vertices[entry[0] > 0 ? 0 : 1].push_back(
                {{entry[1], entry[2], entry[3]}});
              for (unsigned int d = 1; d < 4; ++d)
                extent = std::max(extent, std::abs(entry[d]));
            }
          const double tolerance = 1e-9 * extent;
          for (auto &list : vertices)
            std::sort(list.begin(), list.end());
          const auto is_vertex = [&](const Positions  &list,
                                     const Point<dim> &centre) {
            std::array<double, 3> x = {{0., 0., 0.}};
            for (unsigned int d = 0; d < dim; ++d)
              x[d] = centre[d];
            return find_position(list, x, tolerance, [](std::size_t) {
                     return true;
                   }) < list.size();
          };
          // a face whose centre is a vertex of the other side: refine it
          bool flagged = false;
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto &face : cell->face_iterators())
                if (const int side = fault_side(face);
                    side != 0 &&
                    is_vertex(vertices[side > 0 ? 1 : 0], face->center()))
                  {
                    cell->set_refine_flag();
                    flagged = true;
                  }
          if (Utilities::MPI::max(flagged ? 1 : 0, comm) == 0)
            return;
          triangulation.execute_coarsening_and_refinement();
        }
      throw std::runtime_error(
        "the two sides of the split fault are still refined differently after "
        "20 rounds of matching");
    }


    template void
    refine_fault_sides_alike(Triangulation<2> &);
    template void
    refine_fault_sides_alike(Triangulation<3> &);
    template void
    tie_split_fault(const Discretisation<2> &, GlobalSystem &);
    template void
    tie_split_fault(const Discretisation<3> &, GlobalSystem &);
    template FaultTie
    pair_fault_sides(const Discretisation<2> &, unsigned int);
    template FaultTie
    pair_fault_sides(const Discretisation<3> &, unsigned int);
  } // namespace physics
} // namespace rsfcycle
