// SPDX-License-Identifier: LGPL-2.1-or-later
#include <functional>
#include <rsfcycle/scenes/mesh_file.h>
#include <rsfcycle/scenes/scenes.h>
#include <rsfcycle/scenes/wedge.h>
#include <stdexcept>
#include <vector>

namespace rsfcycle
{
  namespace scenes
  {
    namespace
    {
      /** A continuum scene's name, its subsection and its factories. */
      struct SceneType
      {
        std::string                                     name;
        std::function<void(dealii::ParameterHandler &)> declare;
        std::function<std::unique_ptr<physics::Scene<2>>(
          dealii::ParameterHandler &)>
          make_2d;
        std::function<std::unique_ptr<physics::Scene<3>>(
          dealii::ParameterHandler &)>
          make_3d;
      };

      /** The entry of scene class S in the list. */
      template <template <int> class S>
      SceneType
      scene(const std::string &name)
      {
        return {name,
                S<2>::declare_parameters,
                [](dealii::ParameterHandler &prm) {
                  return std::make_unique<S<2>>(prm);
                },
                [](dealii::ParameterHandler &prm) {
                  return std::make_unique<S<3>>(prm);
                }};
      }

      /** The list: one line per continuum scene. */
      const std::vector<SceneType> &
      scene_types()
      {
        static const std::vector<SceneType> list = {
          scene<Wedge>("wedge"), scene<MeshFile>("mesh-file")};
        return list;
      }
    } // namespace


    std::string
    scene_names()
    {
      std::string names;
      for (const auto &type : scene_types())
        names += type.name + "|";
      return names + "spring-slider";
    }


    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      for (const auto &type : scene_types())
        type.declare(prm);
    }


    template <int dim>
    std::unique_ptr<physics::Scene<dim>>
    make_scene(const std::string &name, dealii::ParameterHandler &prm)
    {
      for (const auto &type : scene_types())
        if (type.name == name)
          {
            if constexpr (dim == 2)
              return type.make_2d(prm);
            else
              return type.make_3d(prm);
          }
      throw std::invalid_argument("Scene = " + name + ": allowed are " +
                                  scene_names());
    }


    template std::unique_ptr<physics::Scene<2>>
    make_scene<2>(const std::string &, dealii::ParameterHandler &);
    template std::unique_ptr<physics::Scene<3>>
    make_scene<3>(const std::string &, dealii::ParameterHandler &);
  } // namespace scenes
} // namespace rsfcycle
