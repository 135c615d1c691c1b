// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the local-extrapolation controller (time/local_extrapolation.h) on
// the scalar ODE y' = -k(t) y, stepped by the trapezoidal rule
// y -> y (1 - k tau/2)/(1 + k tau/2) (second order, like the Newmark step),
// with the distance |log y1 - log y2|:
//  - the estimate (one step of tau against two of tau/2) is
//    (k tau)^3 / 16, and tau is doubled while 8 x estimate <= tolerance
//    (Doubling threshold 1; the same steps with 0.5), so with tolerance 1e-6
//    and k = 1 the pairs are 0.016 (a power of two times the initial step 1e-3;
//    estimate 2.6e-7), the accepted half steps 0.008; the rate jump k = 1 ->
//    1000 on [5, 5.2) shrinks them by ~1000 (printed: 1024) and they grow back;
//    the final time is exactly the end time;
//  - cost and accuracy against step doubling at the same tolerance, with
//    the same stepper, on k = 1: the trapezoidal error of one step is
//    tau^3 / 12 in log y. Local extrapolation takes 625 pairs of two half
//    steps of 0.008 (3 calls a pair: 1887 calls with the start-up), error
//    625 * 2 * 0.008^3 / 12 = 5.3e-5; step doubling accepts 625 steps of
//    0.016 (about 4 calls a step: 2505), error 625 * 0.016^3 / 12 = 2.1e-4;
//  - the guesses (Extrapolated start): every call after the first pair
//    gets one, and it agrees with the result to 1e-3 relative;
//  - memory(): a controller restored from the memory of another one in
//    the middle of a run continues it bitwise identically (checkpoints);
//  - a stepper that fails for tau > 0.05 only ever gets smaller steps
//    accepted; one that always fails ends in StepSizeUnderflow;
//  - free step sizes (Step sizes = free): tau -> tau min(2, 0.9
//    (tolerance/estimate)^(1/3)) settles where 0.9^3 x 16 x tolerance =
//    (k tau)^3, i.e. pairs of 0.9 (1.6e-5)^(1/3) = 0.022679 (half steps
//    0.011339) for k = 1 and 1000 x smaller (1.1339e-5) for k = 1000; on
//    k = 1 that is 10/0.022679 = 441 pairs (3 calls each), error
//    441 * 2 * 0.011339^3 / 12 = 1.07e-4.
#include "tests.h"

#include <algorithm>
#include <cmath>
#include <rsfcycle/time/local_extrapolation.h>
#include <rsfcycle/time/step_doubling.h>

using rsfcycle::time::LocalExtrapolation;
using rsfcycle::time::StepDoubling;

namespace
{
  double
  rate(const double t)
  {
    return (t >= 5 && t < 5.2) ? 1000. : 1.;
  }

  std::optional<double>
  trapezoid(const double y, const double t, const double tau)
  {
    const double x = rate(t) * tau / 2;
    return y * (1 - x) / (1 + x);
  }

  double
  distance(const double &a, const double &b)
  {
    return std::abs(std::log(a / b));
  }

  double
  combine(const std::array<const double *, 3> &s,
          const std::array<double, 3>         &w)
  {
    return w[0] * *s[0] + w[1] * *s[1] + w[2] * *s[2];
  }

  const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }
} // namespace

int
main()
{
  initlog(6);
  unsigned int calls = 0, guesses = 0;
  double       worst_guess = 0;
  const auto   stepper     = [&](const double &y,
                           const double  t,
                           const double  tau,
                           const double *guess) -> std::optional<double> {
    ++calls;
    const auto result = trapezoid(y, t, tau);
    if (guess != nullptr)
      {
        ++guesses;
        // only where the rate is smooth over the extrapolation
        if (t > 5.3 || t + tau < 4.9)
          worst_guess = std::max(worst_guess, std::abs(*guess / *result - 1));
      }
    return result;
  };

  {
    LocalExtrapolation<double> controller(
      stepper, distance, combine, true, true, 1., 1e-6, 1e-3, 1e-12, 10.);
    double       y = 1, t = 0;
    unsigned int steps = 0;
    double max_before = 0, min_during = 1e300, max_during = 0, max_after = 0;
    while (10. - t > 1e-12)
      {
        const double t0 = t;
        controller.advance(y, t, 10.);
        ++steps;
        const double tau = controller.last_step_size();
        if (t0 < 4.9)
          max_before = std::max(max_before, tau);
        else if (t0 > 5.05 && t0 < 5.15)
          {
            min_during = std::min(min_during, tau);
            max_during = std::max(max_during, tau);
          }
        else if (t0 > 8)
          max_after = std::max(max_after, tau);
      }
    dealii::deallog << "accepted steps: " << steps << ", final time " << t
                    << ", calls per step " << double(calls) / steps
                    << std::endl;
    dealii::deallog << "steps before the jump up to " << max_before
                    << ", during [" << min_during << ", " << max_during
                    << "], after up to " << max_after << std::endl;
    dealii::deallog << "ratio before / during: " << max_before / max_during
                    << std::endl;
    dealii::deallog << "guesses: " << guesses << " of " << calls
                    << " calls, all after the first pair: "
                    << yes_no(guesses + 3 >= calls)
                    << ", agree to 1e-3: " << yes_no(worst_guess < 1e-3)
                    << std::endl;
  }

  {
    // cost and accuracy against step doubling on the smooth problem k = 1
    const auto smooth = [](const double y, const double tau) {
      return y * (1 - tau / 2) / (1 + tau / 2);
    };
    unsigned int               le_calls = 0;
    LocalExtrapolation<double> controller(
      [&](const double &y0, const double, const double tau, const double *) {
        ++le_calls;
        return std::optional<double>(smooth(y0, tau));
      },
      distance,
      combine,
      true,
      true,
      1.,
      1e-6,
      1e-3,
      1e-12,
      10.);
    double       y = 1, t = 0;
    unsigned int steps = 0;
    while (10. - t > 1e-12)
      {
        controller.advance(y, t, 10.);
        ++steps;
      }
    const double error = std::abs(std::log(y) + 10.);

    unsigned int         sd_calls = 0;
    StepDoubling<double> doubling(
      [&](const double &y0, const double, const double tau) {
        ++sd_calls;
        return std::optional<double>(smooth(y0, tau));
      },
      distance,
      1e-6,
      1e-3,
      1e-12,
      10.);
    double       y_sd = 1, t_sd = 0;
    unsigned int sd_steps = 0;
    while (10. - t_sd > 1e-12)
      {
        doubling.advance(y_sd, t_sd, 10.);
        ++sd_steps;
      }
    const double sd_error = std::abs(std::log(y_sd) + 10.);
    dealii::deallog << "k = 1, tolerance 1e-6: local extrapolation "
                    << double(le_calls) / steps << " calls per step, "
                    << le_calls << " calls, |log y(10) + 10| = " << error
                    << "; step doubling " << double(sd_calls) / sd_steps
                    << " calls per step, " << sd_calls << " calls, error "
                    << sd_error << std::endl;
  }

  {
    // memory() and restore() in the middle of a run
    const auto plain =
      [](const double &y, const double t, const double tau, const double *) {
        return trapezoid(y, t, tau);
      };
    LocalExtrapolation<double> a(
      plain, distance, combine, true, true, 0.5, 1e-6, 1e-3, 1e-12, 10.);
    double y_a = 1, t_a = 0;
    for (unsigned int i = 0; i < 101; ++i) // odd: a half step is pending
      a.advance(y_a, t_a, 10.);
    LocalExtrapolation<double> b(
      plain, distance, combine, true, true, 0.5, 1e-6, 1., 1e-12, 10.);
    b.restore(a.memory());
    double y_b = y_a, t_b = t_a;
    while (10. - t_a > 1e-12)
      a.advance(y_a, t_a, 10.);
    while (10. - t_b > 1e-12)
      b.advance(y_b, t_b, 10.);
    dealii::deallog << "restored from memory(): identical: "
                    << yes_no(y_a == y_b && t_a == t_b) << std::endl;
  }

  {
    const auto failing = [](const double &y,
                            const double  t,
                            const double  tau,
                            const double *) -> std::optional<double> {
      if (tau > 0.05)
        return {};
      return trapezoid(y, t, tau);
    };
    LocalExtrapolation<double> controller(
      failing, distance, combine, true, true, 0.5, 1e-2, 1., 1e-12, 10.);
    double y = 1, t = 0, largest = 0;
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
    // free step sizes on the rate jump and on the smooth problem
    const auto plain =
      [](const double &y, const double t, const double tau, const double *) {
        return trapezoid(y, t, tau);
      };
    LocalExtrapolation<double> controller(
      plain, distance, combine, true, false, 1, 1e-6, 1e-3, 1e-12, 10.);
    double y = 1, t = 0, before = 0, during = 0;
    while (10. - t > 1e-12)
      {
        const double t0 = t;
        controller.advance(y, t, 10.);
        if (t0 > 4 && t0 < 4.9)
          before = controller.last_step_size();
        if (t0 > 5.1 && t0 < 5.15)
          during = controller.last_step_size();
      }
    dealii::deallog << "free step sizes: half steps before the jump " << before
                    << ", during " << during << ", final time " << t
                    << std::endl;

    unsigned int               n_calls = 0;
    LocalExtrapolation<double> smooth(
      [&](const double &y0, const double, const double tau, const double *) {
        ++n_calls;
        return std::optional<double>(y0 * (1 - tau / 2) / (1 + tau / 2));
      },
      distance,
      combine,
      true,
      false,
      1.,
      1e-6,
      1e-3,
      1e-12,
      10.);
    double       y_s = 1, t_s = 0;
    unsigned int steps = 0;
    while (10. - t_s > 1e-12)
      {
        smooth.advance(y_s, t_s, 10.);
        ++steps;
      }
    dealii::deallog << "free step sizes, k = 1: " << steps << " steps, "
                    << n_calls << " calls, |log y(10) + 10| = "
                    << std::abs(std::log(y_s) + 10.) << std::endl;
  }

  {
    const auto always_failing = [](const double &,
                                   const double,
                                   const double,
                                   const double *) -> std::optional<double> {
      return {};
    };
    LocalExtrapolation<double> controller(
      always_failing, distance, combine, true, true, 0.5, 1e-2, 1., 1e-6, 10.);
    double y = 1, t = 0;
    try
      {
        controller.advance(y, t, 1.);
        dealii::deallog << "no exception: wrong" << std::endl;
      }
    catch (const rsfcycle::time::StepSizeUnderflow &)
      {
        dealii::deallog << "always failing: StepSizeUnderflow at t = " << t
                        << std::endl;
      }
  }
}
