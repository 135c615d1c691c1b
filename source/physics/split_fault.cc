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
    } // namespace


    template <int dim>
    void
    tie_split_fault(const Discretisation<dim> &discretisation,
                    GlobalSystem              &system)
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
      const unsigned int         n = system.n();
      std::vector<unsigned char> kind(n, tie_none);
      std::vector<unsigned int>  partner(n, 0);
      const unsigned int normal_component = discretisation.normal_component();
      // per + tangential dof: its node's + normal dof and outward normal
      std::map<unsigned int, std::pair<unsigned int, double>> normal_of;
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
                normal_of[a] = {p.dofs[normal_component], p.outward};
            }
        }
      for (unsigned int k = 0; k < minus.size(); ++k)
        if (!taken[k])
          throw std::invalid_argument(
            refused + "the fault-opposite node at " + position(minus[k], dim) +
            " has no contact or creep node at its position; the two sides "
            "need the same nodes");

      // u_j = sum over (l, T_jl) of forward(j) of T_jl u~_l, and
      // u~ of new dof k gathers the rows (i, T_ik) of backward(k)
      const auto forward = [&](const unsigned int j) {
        return tie_terms(kind[j], partner[j], j);
      };
      const auto backward = [&](const unsigned int k) -> Terms {
        switch (kind[k])
          {
            case tie_slip:
              return {{k, 0.5}, {partner[k], -0.5}};
            case tie_mean:
              return {{partner[k], 1.}, {k, 1.}};
            case tie_normal:
              return {{k, 1.}, {partner[k], 1.}};
            case tie_gone:
              return {};
            default:
              return {{k, 1.}};
          }
      };

      // K~ = T^T K T, row by row
      std::vector<std::size_t>  row_start(1, 0);
      std::vector<unsigned int> columns;
      std::vector<double>       values;
      Terms                     row;
      for (unsigned int k = 0; k < n; ++k)
        {
          row.clear();
          if (kind[k] == tie_gone)
            row.emplace_back(k, 1.);
          for (const auto &[i, t_ik] : backward(k))
            for (std::size_t e = system.row_begin(i); e < system.row_end(i);
                 ++e)
              for (const auto &[l, t_jl] : forward(system.columns[e]))
                row.emplace_back(l, t_ik * system.values[e] * t_jl);
          std::sort(row.begin(), row.end(), [](const auto &x, const auto &y) {
            return x.first < y.first;
          });
          for (std::size_t e = 0; e < row.size(); ++e)
            if (e > 0 && row[e].first == columns.back())
              values.back() += row[e].second;
            else
              {
                columns.push_back(row[e].first);
                values.push_back(row[e].second);
              }
          row_start.push_back(columns.size());
        }

      // f~ = T^T f; the prescribed dofs in the new unknowns
      // (the tangential force on the + side is the shear prestress, the
      // fault's internal traction: it acts on the - side too, opposite;
      // GreenFault refuses gravity with a split fault)
      std::vector<double> pair_force = system.force;
      for (unsigned int a = 0; a < n; ++a)
        if (kind[a] == tie_slip)
          pair_force[partner[a]] -= system.force[a];
      std::vector<double> force(n, 0.), velocity = system.fixed_velocity;
      std::vector<bool>   fixed = system.fixed;
      for (unsigned int k = 0; k < n; ++k)
        for (const auto &[i, t_ik] : backward(k))
          force[k] += t_ik * pair_force[i];
      for (unsigned int a = 0; a < n; ++a)
        {
          const unsigned int b   = partner[a];
          const auto        &v   = system.fixed_velocity;
          const auto        &fix = system.fixed;
          if (kind[a] == tie_slip)
            {
              if (!fix[a] && fix[b])
                throw std::invalid_argument(
                  refused +
                  "a fault-opposite node is prescribed (load-opposite) "
                  "where its contact node is free; prescribe both sides or "
                  "neither");
              velocity[a] = fix[b] ? v[a] - v[b] : 2 * v[a];
              velocity[b] = fix[b] ? 0.5 * (v[a] + v[b]) : 0.;
            }
          else if (kind[a] == tie_normal)
            {
              fixed[a]    = fix[a] || fix[b];
              velocity[a] = fix[a] ? v[a] : v[b];
              fixed[b]    = true;
              velocity[b] = 0;
            }
        }

      // the observation rows in the new unknowns
      for (auto &observation : system.observations)
        {
          ObservationRow tied;
          for (const auto &[j, w] : observation)
            for (const auto &[l, t_jl] : forward(j))
              tied.emplace_back(l, w * t_jl);
          observation = std::move(tied);
        }

      // the normal force on each contact dof's node (+ side): the other
      // side's push against the outward normal n, -n (K u)_c of the
      // untied stiffness's row c (the + side's cells alone), in u~
      system.normal_rows.clear();
      if (!normal_of.empty())
        for (const unsigned int a : system.contact_dofs)
          {
            const auto [c, outward] = normal_of.at(a);
            ObservationRow normal_row;
            for (std::size_t e = system.row_begin(c); e < system.row_end(c);
                 ++e)
              for (const auto &[l, t_jl] : forward(system.columns[e]))
                normal_row.emplace_back(l, -outward * system.values[e] * t_jl);
            system.normal_rows.push_back(std::move(normal_row));
          }

      system.tie_kind       = std::move(kind);
      system.tie_partner    = std::move(partner);
      system.row_start      = std::move(row_start);
      system.columns        = std::move(columns);
      system.values         = std::move(values);
      system.force          = std::move(force);
      system.fixed          = std::move(fixed);
      system.fixed_velocity = std::move(velocity);
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
  } // namespace physics
} // namespace rsfcycle
