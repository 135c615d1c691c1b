#ifndef rsfcycle_parameters_h
#define rsfcycle_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <rsfcycle/friction/laws.h>
#include <rsfcycle/output/seas_parameters.h>
#include <rsfcycle/time/theta_scheme.h>
#include <string>

namespace rsfcycle
{
  using dealii::ParameterHandler;

  /** Top level: which scene, in which dimension, for how long, where to. */
  struct RunParameters
  {
    unsigned int dimension         = 2;
    bool         antiplane         = false; // Displacement = antiplane
    std::string  scene             = "wedge";
    double       end_time          = 1000;
    unsigned int stop_after_events = 0;
    std::string  output_directory  = "output";
    bool         overwrite_output  = false;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Subsection "Mesh": refinement toward the seismogenic patch. */
  struct MeshParameters
  {
    /** How the cells to refine toward the patch are chosen. */
    enum class RefinementLaw
    {
      /** centre closer than `refinement_distance` x diameter */
      centre_distance,
      /** box within `refinement_band` + layers x shortest edge */
      band
    };

    unsigned int  global_refinements     = 3;
    unsigned int  local_refinements      = 4;
    RefinementLaw refinement_law         = RefinementLaw::centre_distance;
    double        refinement_distance    = 1.5;
    double        refinement_band        = 0;
    double        refinement_band_layers = 1;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Subsection "Time stepping": step-size control (MODEL.md §4.3). */
  struct TimeSteppingParameters
  {
    bool        adaptive           = true;
    std::string controller         = "local-extrapolation";
    bool        extrapolated_start = true;
    std::string step_sizes         = "ladder";
    double      doubling_threshold = 1;
    std::string error_norm         = "L2";
    double      tolerance          = 1e-5;
    double      initial_step       = 1e-2;
    double      minimum_step       = 1e-9;
    double      maximum_step       = 100;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Subsection "Solver": rate/state coupling, TNNMG, linear correction. */
  struct SolverParameters
  {
    /** The friction law of `State law` (friction/laws.h). */
    std::shared_ptr<const friction::Law> law = friction::make_law("ageing");
    std::string                          coupling              = "fixed-point";
    std::string                          dynamics              = "dynamic";
    double                               theta                 = 0.5;
    double                               fixed_point_tolerance = 1e-5;
    unsigned int                         max_fixed_point_iterations = 20;
    std::string                          linear_correction      = "multigrid";
    unsigned int                         smoothing_steps        = 3;
    unsigned int                         correction_cycles      = 1;
    double                               correction_tolerance   = 1e-2;
    double                               tnnmg_tolerance        = 1e-10;
    double                               inner_tolerance_factor = 0.3;
    unsigned int                         max_tnnmg_iterations   = 100;
    double                               truncation_ratio       = 1e10;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** The time step's scheme: `Theta` and whether `Dynamics` has inertia. */
    time::ThetaScheme
    scheme() const
    {
      return {theta, dynamics == "dynamic"};
    }
  };

  /** Subsection "Output": snapshots, profiles, events, progress. */
  struct OutputParameters
  {
    double       output_interval        = 10;
    double       event_output_interval  = 0.1;
    double       profile_interval       = 1;
    double       event_profile_interval = 0.005;
    double       event_threshold        = 10;
    double       progress_interval      = 10;
    bool         write_vtu              = true;
    double       transition_time        = 0;
    unsigned int transition_events      = 2;
    unsigned int checkpoint_steps       = 5000;
    double       checkpoint_minutes     = 10;
    /** The subsection Output/SEAS. */
    output::SeasParameters seas;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** All parameters of a run. */
  struct Parameters
  {
    RunParameters          run;
    MeshParameters         mesh;
    TimeSteppingParameters time_stepping;
    SolverParameters       solver;
    OutputParameters       output;

    /** Declare every entry, scenes' subsections included. */
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Checks across entries that the patterns cannot express; throws
     * std::invalid_argument with one line naming the entry, its value and
     * what is allowed.
     */
    void
    validate() const;
  };
} // namespace rsfcycle

#endif
