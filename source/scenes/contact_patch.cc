// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <limits>
#include <rsfcycle/ids.h>
#include <rsfcycle/scenes/contact_patch.h>

namespace rsfcycle
{
  namespace scenes
  {
    template <int dim>
    Point<dim>
    face_point(const typename Triangulation<dim>::face_iterator &face,
               const double                                      s,
               const double                                      t)
    {
      if constexpr (dim == 2)
        {
          (void)t;
          return Point<dim>((1 - s) * face->vertex(0) + s * face->vertex(1));
        }
      else
        return Point<dim>(
          (1 - s) * (1 - t) * face->vertex(0) + s * (1 - t) * face->vertex(1) +
          (1 - s) * t * face->vertex(2) + s * t * face->vertex(3));
    }


    template <int dim>
    void
    ContactPatch<dim>::build(
      const Triangulation<dim>                      &coarse,
      const std::function<bool(const Point<dim> &)> &inside,
      const unsigned int                             n_refinements)
    {
      std::vector<typename Triangulation<dim>::face_iterator> faces;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              face->boundary_id() == boundary_id::contact)
            faces.push_back(face);
      const double max_samples = 2e6;
      unsigned int n           = 1u << std::min(n_refinements + 1, 14u);
      while (n > 8 && faces.size() * std::pow(n + 1., dim - 1) > max_samples)
        n /= 2;
      const unsigned int n_strips = (dim == 3) ? n : 1;

      boxes.clear();
      for (const auto &face : faces)
        {
          const auto at = [&face](const double s, const double t) {
            return face_point<dim>(face, s, t);
          };
          const auto weakening = [&](const double s, const double t) {
            return inside(at(s, t));
          };
          for (unsigned int j = 0; j < n_strips; ++j)
            {
              const double t_lo = double(j) / n_strips,
                           t_hi = double(j + 1) / n_strips,
                           t    = 0.5 * (t_lo + t_hi);
              // the point where weakening changes between s0 and s1
              const auto boundary = [&](double s0, double s1) {
                const bool w0 = weakening(s0, t);
                for (unsigned int k = 0; k < 60; ++k)
                  {
                    const double m                    = 0.5 * (s0 + s1);
                    (weakening(m, t) == w0 ? s0 : s1) = m;
                  }
                return 0.5 * (s0 + s1);
              };
              const auto add = [&](const double s0, const double s1) {
                boxes.emplace_back(std::vector<Point<dim>>{
                  at(s0, t_lo), at(s1, t_lo), at(s0, t_hi), at(s1, t_hi)});
              };
              double start = 0, s_prior = 0;
              bool   weak = false;
              for (unsigned int i = 0; i <= n; ++i)
                {
                  const double s = double(i) / n;
                  const bool   w = weakening(s, t);
                  if (w && !weak)
                    start = (i == 0) ? 0. : boundary(s_prior, s);
                  if (!w && weak)
                    add(start, boundary(s_prior, s));
                  weak    = w;
                  s_prior = s;
                }
              if (weak)
                add(start, 1.);
            }
        }
      // flat in y = 0 (the contact's vertices are)
      for (auto &box : boxes)
        {
          box.get_boundary_points().first[1]  = 0;
          box.get_boundary_points().second[1] = 0;
        }
      tree = pack_rtree(boxes);
    }


    template <int dim>
    double
    ContactPatch<dim>::distance(const BoundingBox<dim> &box,
                                const double            margin) const
    {
      if (boxes.empty())
        return std::numeric_limits<double>::max();
      std::vector<BoundingBox<dim>> nearest;
      tree.query(boost::geometry::index::nearest(box, 1),
                 std::back_inserter(nearest));
      const auto &[q_lo, q_hi] = nearest.front().get_boundary_points();
      const auto &[lo, hi]     = box.get_boundary_points();
      const double gx = std::max({0., lo[0] - q_hi[0], q_lo[0] - hi[0]});
      const double gz =
        (dim == 3) ?
          std::max(
            {0., lo[dim - 1] - q_hi[dim - 1], q_lo[dim - 1] - hi[dim - 1]}) :
          0.;
      return std::hypot(std::max(0., std::hypot(gx, gz) - margin),
                        std::max({0., lo[1], -hi[1]}));
    }


    template Point<2>
    face_point<2>(const Triangulation<2>::face_iterator &, double, double);
    template Point<3>
    face_point<3>(const Triangulation<3>::face_iterator &, double, double);
    template class ContactPatch<2>;
    template class ContactPatch<3>;
  } // namespace scenes
} // namespace rsfcycle
