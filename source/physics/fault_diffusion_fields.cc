// SPDX-License-Identifier: LGPL-2.1-or-later
// FaultDiffusion's fields at a point and a time: the Q1 interpolant of the
// state, the recovered gradient, the well's pressure, the stored volume.
#include <algorithm>
#include <cmath>
#include <rsfcycle/physics/fault_diffusion.h>
#include <stdexcept>
#include <string>

namespace rsfcycle
{
  namespace physics
  {
    template <int plane_dim>
    bool
    FaultDiffusion<plane_dim>::contains(const Point<plane_dim> &x) const
    {
      for (unsigned int d = 0; d < plane_dim; ++d)
        if (!(std::abs(x[d]) <= parameters.half_width * (1 + 1e-12)))
          return false;
      return true;
    }


    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::check_point(const Point<plane_dim> &x,
                                           const double            t) const
    {
      if (!contains(x))
        throw std::domain_error("FaultDiffusion: the point is outside the "
                                "fluid domain (at t = " +
                                std::to_string(t) + " s)");
    }


    /** The cell of x on the uniform mesh and the bilinear weights. */
    template <int plane_dim>
    double
    FaultDiffusion<plane_dim>::interpolate(const Vector<double>   &nodal,
                                           const Point<plane_dim> &x) const
    {
      const double h = 2 * parameters.half_width / n_cells;
      std::array<unsigned int, plane_dim> cell;
      std::array<double, plane_dim>       xi;
      for (unsigned int d = 0; d < plane_dim; ++d)
        {
          const double s = (x[d] + parameters.half_width) / h;
          const double c = std::min(std::max(std::floor(s), 0.), n_cells - 1.);
          cell[d]        = static_cast<unsigned int>(c);
          xi[d]          = s - c;
        }
      double value = 0;
      for (unsigned int corner = 0; corner < (1u << plane_dim); ++corner)
        {
          double       weight = 1;
          unsigned int index = 0, stride = 1;
          for (unsigned int d = 0; d < plane_dim; ++d)
            {
              const unsigned int bit = (corner >> d) & 1;
              weight *= bit ? xi[d] : 1 - xi[d];
              index += (cell[d] + bit) * stride;
              stride *= n_cells + 1;
            }
          value += weight * nodal(node_dof[index]);
        }
      return value;
    }


    template <int plane_dim>
    double
    FaultDiffusion<plane_dim>::value(const Point<plane_dim> &x,
                                     const double            t) const
    {
      check_point(x, t);
      return interpolate(state_at(t), x);
    }


    /**
     * The nodal gradient of the state y: the lumped L2 projection, and on
     * the boundary what the boundary condition says, where the projection
     * is one-sided and first order: no flux, the normal component zero; a
     * fixed pressure, the tangential components zero and the normal one
     * extrapolated linearly from the two nodes inside.
     */
    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::recover_gradient(const Vector<double> &y) const
    {
      Vector<double> p(dof_handler.n_dofs());
      std::copy(y.begin(), y.begin() + p.size(), p.begin());
      for (unsigned int d = 0; d < plane_dim; ++d)
        {
          cached_gradient[d].reinit(p.size());
          gradient[d].vmult(cached_gradient[d], p);
        }
      const bool no_flux =
        parameters.boundary == FaultDiffusionParameters::Boundary::no_flux;
      const unsigned int n_per_line = n_cells + 1;
      for (unsigned int node = 0; node < node_dof.size(); ++node)
        {
          std::array<unsigned int, plane_dim> i;
          unsigned int                        n_walls = 0;
          for (unsigned int d = 0, rest = node; d < plane_dim; ++d)
            {
              i[d] = rest % n_per_line;
              rest /= n_per_line;
              n_walls += (i[d] == 0 || i[d] == n_cells);
            }
          for (unsigned int d = 0, stride = 1; d < plane_dim;
               ++d, stride *= n_per_line)
            {
              const bool wall = i[d] == 0 || i[d] == n_cells;
              auto      &g    = cached_gradient[d];
              if (no_flux ? wall : n_walls > (wall ? 1u : 0u))
                g(node_dof[node]) = 0;
              else if (wall && n_cells >= 2)
                {
                  const unsigned int in1 =
                    i[d] == 0 ? node + stride : node - stride;
                  const unsigned int in2 =
                    i[d] == 0 ? node + 2 * stride : node - 2 * stride;
                  g(node_dof[node]) = 2 * g(node_dof[in1]) - g(node_dof[in2]);
                }
            }
        }
      cached_gradient_valid = true;
    }


    template <int plane_dim>
    Tensor<1, plane_dim>
    FaultDiffusion<plane_dim>::darcy_velocity(const Point<plane_dim> &x,
                                              const double            t) const
    {
      check_point(x, t);
      const Vector<double> &y = state_at(t);
      if (!cached_gradient_valid)
        recover_gradient(y);
      const double mobility = parameters.permeability / parameters.viscosity;
      Tensor<1, plane_dim> q;
      for (unsigned int d = 0; d < plane_dim; ++d)
        q[d] = -mobility * interpolate(cached_gradient[d], x);
      return q;
    }


    template <int plane_dim>
    double
    FaultDiffusion<plane_dim>::well_pressure(const double t) const
    {
      if (parameters.source != FaultDiffusionParameters::Source::well)
        throw std::logic_error("FaultDiffusion: no well");
      return state_at(t)(n_unknowns - 1);
    }


    template <int plane_dim>
    double
    FaultDiffusion<plane_dim>::stored_volume(const double t) const
    {
      return storage * state_at(t);
    }


    template bool
    FaultDiffusion<1>::contains(const Point<1> &) const;
    template void
    FaultDiffusion<1>::check_point(const Point<1> &, double) const;
    template double
    FaultDiffusion<1>::interpolate(const Vector<double> &,
                                   const Point<1> &) const;
    template double
    FaultDiffusion<1>::value(const Point<1> &, double) const;
    template void
    FaultDiffusion<1>::recover_gradient(const Vector<double> &) const;
    template Tensor<1, 1>
    FaultDiffusion<1>::darcy_velocity(const Point<1> &, double) const;
    template double
    FaultDiffusion<1>::well_pressure(double) const;
    template double
    FaultDiffusion<1>::stored_volume(double) const;
    template bool
    FaultDiffusion<2>::contains(const Point<2> &) const;
    template void
    FaultDiffusion<2>::check_point(const Point<2> &, double) const;
    template double
    FaultDiffusion<2>::interpolate(const Vector<double> &,
                                   const Point<2> &) const;
    template double
    FaultDiffusion<2>::value(const Point<2> &, double) const;
    template void
    FaultDiffusion<2>::recover_gradient(const Vector<double> &) const;
    template Tensor<1, 2>
    FaultDiffusion<2>::darcy_velocity(const Point<2> &, double) const;
    template double
    FaultDiffusion<2>::well_pressure(double) const;
    template double
    FaultDiffusion<2>::stored_volume(double) const;
  } // namespace physics
} // namespace rsfcycle
