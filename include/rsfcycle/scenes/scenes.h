// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_scenes_scenes_h
#define rsfcycle_scenes_scenes_h

#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <rsfcycle/physics/scene.h>
#include <string>

namespace rsfcycle
{
  namespace scenes
  {
    /**
     * The continuum scenes by name (a list of names, subsections and
     * factories). A new scene is a class in scenes/ and one line in the
     * list of source/scenes/scenes.cc; nothing outside scenes/ changes.
     */

    /** Names of the scenes (the spring-slider too), as a Selection. */
    std::string
    scene_names();

    /** Declare the subsection of every continuum scene. */
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * The continuum scene (geometry, materials, friction) of the given name,
     * reading its subsection of prm.
     */
    template <int dim>
    std::unique_ptr<physics::Scene<dim>>
    make_scene(const std::string &name, dealii::ParameterHandler &prm);
  } // namespace scenes
} // namespace rsfcycle

#endif
