// SPDX-License-Identifier: LGPL-2.1-or-later
#include <rsfcycle/scenes/mesh_file.h>
#include <rsfcycle/scenes/scenes.h>
#include <rsfcycle/scenes/wedge.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace scenes
  {
    std::string
    scene_names()
    {
      return "wedge|mesh-file|spring-slider";
    }


    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      Wedge<2>::declare_parameters(prm);
      MeshFile<2>::declare_parameters(prm);
    }


    template <int dim>
    std::unique_ptr<physics::Scene<dim>>
    make_scene(const std::string &name, dealii::ParameterHandler &prm)
    {
      if (name == "wedge")
        return std::make_unique<Wedge<dim>>(prm);
      if (name == "mesh-file")
        return std::make_unique<MeshFile<dim>>(prm);
      throw std::invalid_argument("Scene = " + name + ": allowed are " +
                                  scene_names());
    }


    template std::unique_ptr<physics::Scene<2>>
    make_scene<2>(const std::string &, dealii::ParameterHandler &);
    template std::unique_ptr<physics::Scene<3>>
    make_scene<3>(const std::string &, dealii::ParameterHandler &);
  } // namespace scenes
} // namespace rsfcycle
