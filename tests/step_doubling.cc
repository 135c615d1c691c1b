// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the generic step-doubling controller (doc/model.md §4.3) on the scalar
// ODE y' = -k(t) y, stepped by implicit Euler y -> y/(1 + k tau), and the
// distance |log y1 - log y2|, which behaves like the state distance (14):
//  - the distance between two steps of tau and one of 2 tau is
//    log((1 + 2x)/(1 + x)^2) ~ x^2, x = k tau, so with tolerance 1e-4 the
//    accepted steps are ~0.01/k (a power-of-two multiple of the initial
//    step 1e-3); printed: number of accepted steps, the final time
//    (exactly the end time), the smallest and largest step;
//  - a rate jump (k = 1 -> 1000 for t in [5, 5.2)) shrinks the step by
//    the ratio of the rates (printed: 1024, the power of two nearest
//    1000), and it grows back afterwards;
//  - a stepper that fails for tau > 0.05 is handled as "refine": the
//    accepted steps never exceed 0.05;
//  - a stepper that always fails ends in StepSizeUnderflow (no hang);
//  - reuse: stepper calls per accepted step are printed (about 4: R2, C,
//    F and G of the controller, R1 being reused).
#include "tests.h"

#include <algorithm>
#include <cmath>
#include <rsfcycle/time/step_doubling.h>

using rsfcycle::time::StepDoubling;

int
main()
{
  initlog(6);

  const auto rate = [](const double t) {
    return (t >= 5 && t < 5.2) ? 1000. : 1.;
  };
  unsigned int calls   = 0;
  const auto   stepper = [&](const double &y,
                           const double  t,
                           const double  tau) -> std::optional<double> {
    ++calls;
    // implicit Euler: first order, so the step-doubling distance is
    // ~ (k tau)^2 and the accepted steps scale like 1/k
    return y / (1. + rate(t) * tau);
  };
  const auto distance = [](const double &a, const double &b) {
    return std::abs(std::log(a / b));
  };

  {
    StepDoubling<double> controller(stepper, distance, 1e-4, 1e-3, 1e-12, 10.);
    double               y = 1, t = 0;
    unsigned int         steps = 0;
    double min_before = 1e300, max_before = 0, min_after = 1e300, max_after = 0;
    while (10. - t > 1e-12)
      {
        const double t0 = t;
        controller.advance(y, t, 10.);
        ++steps;
        const double tau = controller.last_step_size();
        if (t0 < 4.9)
          {
            min_before = std::min(min_before, tau);
            max_before = std::max(max_before, tau);
          }
        else if (t0 > 5.05 && t0 < 5.15)
          {
            min_after = std::min(min_after, tau);
            max_after = std::max(max_after, tau);
          }
      }
    dealii::deallog << "accepted steps: " << steps << ", final time " << t
                    << ", calls per step " << double(calls) / steps
                    << std::endl;
    dealii::deallog << "before the jump: tau in [" << min_before << ", "
                    << max_before << "], during the jump: [" << min_after
                    << ", " << max_after << "]" << std::endl;
    dealii::deallog
      << "ratio of typical steps ~ rate ratio 1000 (powers of two): "
      << max_before / max_after << std::endl;
  }

  {
    const auto failing = [&](const double &y,
                             const double  t,
                             const double  tau) -> std::optional<double> {
      if (tau > 0.05)
        return {};
      return stepper(y, t, tau);
    };
    StepDoubling<double> controller(failing, distance, 1e-2, 1., 1e-12, 10.);
    double               y = 1, t = 0, largest = 0;
    while (2. - t > 1e-12)
      {
        controller.advance(y, t, 2.);
        largest = std::max(largest, controller.last_step_size());
      }
    dealii::deallog << "failing above 0.05: largest accepted step " << largest
                    << ", y(2) = " << y << " (exact " << std::exp(-2.) << ")"
                    << std::endl;
  }

  {
    const auto always_failing =
      [](const double &, const double, const double) -> std::optional<double> {
      return {};
    };
    StepDoubling<double> controller(
      always_failing, distance, 1e-2, 1., 1e-6, 10.);
    double y = 1, t = 0;
    try
      {
        controller.advance(y, t, 1.);
        dealii::deallog << "no exception: wrong" << std::endl;
      }
    catch (const rsfcycle::time::StepSizeUnderflow &e)
      {
        dealii::deallog << "always failing: StepSizeUnderflow at t = " << t
                        << std::endl;
      }
  }
}
