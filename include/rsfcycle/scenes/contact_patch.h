// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_scenes_contact_patch_h
#define rsfcycle_scenes_contact_patch_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/rtree.h>
#include <functional>
#include <vector>

namespace rsfcycle
{
  namespace scenes
  {
    using namespace dealii;

    /**
     * The point (s, t) in [0, 1]^(dim-1) of a coarse boundary face: linear
     * between its vertices in 2D, bilinear in 3D.
     */
    template <int dim>
    Point<dim>
    face_point(const typename Triangulation<dim>::face_iterator &face,
               double                                            s,
               double                                            t);

    /**
     * A part of the contact (boundary id `contact`, in y = 0 of the
     * rotated frame) given by a predicate on its points, as flat boxes,
     * and the distance of a box to it as Scene::distance_to_patch()
     * defines it. Used by scenes whose patch is a function (mesh-file: the
     * rate-weakening part, b - a > 0).
     */
    template <int dim>
    class ContactPatch
    {
    public:
      /**
       * Each coarse contact face is cut into n strips (3D; 2D: one), n
       * twice the number of cells `n_refinements` can put along an edge
       * (capped at 2e6 samples in all); along each strip's centre line the
       * predicate is sampled at n + 1 points and the ends of every run
       * where it holds are found by bisection, so that in 2D the patch is
       * exact (to rounding) wherever the predicate changes once between
       * samples; in 3D the strips are the boxes of those runs.
       */
      void
      build(const Triangulation<dim>                      &coarse,
            const std::function<bool(const Point<dim> &)> &inside,
            unsigned int                                   n_refinements);

      /**
       * The distance of the box from the contact's plane (above it, or
       * below it: the other side of a split fault) and its in-plane gap to
       * the nearest patch box, reduced by `margin`, combined as for the
       * wedge; the largest double if the patch is empty.
       */
      double
      distance(const BoundingBox<dim> &box, double margin) const;

    private:
      std::vector<BoundingBox<dim>> boxes;
      RTree<BoundingBox<dim>>       tree;
    };
  } // namespace scenes
} // namespace rsfcycle

#endif
