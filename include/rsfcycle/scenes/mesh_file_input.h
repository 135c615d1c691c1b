// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_scenes_mesh_file_input_h
#define rsfcycle_scenes_mesh_file_input_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <map>
#include <rsfcycle/physics/scene.h>
#include <string>

namespace rsfcycle
{
  namespace scenes
  {
    using physics::Material;
    using physics::Scene;

    /**
     * The text entries of Scene = mesh-file (subsection "Mesh file"),
     * parsed and checked; every error throws std::invalid_argument with a
     * one-line message naming the entry.
     */
    namespace mesh_file_input
    {
      using namespace dealii;

      /** The subsection's name, the prefix of every message. */
      inline const std::string section = "Mesh file";

      /** Throw "Mesh file/ENTRY" + message. */
      [[noreturn]] void
      fail(const std::string &entry, const std::string &message);

      /** "(x, y[, z])" of the first n coordinates. */
      std::string
      format_point(const double *x, unsigned int n);

      /** "x, y[, z]": exactly dim components. */
      template <int dim>
      Tensor<1, dim>
      parse_vector(const std::string &text, const std::string &entry);

      /** "1: contact, 2: load": tag -> role, each tag with one role. */
      std::map<types::boundary_id, std::string>
      parse_roles(const std::string &text);

      /**
       * "10: density 900, bulk modulus 5e4, Poisson ratio 0.3, shear
       * viscosity 1e3, bulk viscosity 1e3; 11: ...": tag -> material,
       * every property given once and in range.
       */
      std::map<types::material_id, Material>
      parse_materials(const std::string &text);
    } // namespace mesh_file_input
  }   // namespace scenes
} // namespace rsfcycle

#endif
