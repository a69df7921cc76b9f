// The dynamic-size CVODE wrapper: an exception thrown by the problem inside a
// CVODE callback comes out of step() as the same exception (never unwinding
// through CVODE's C frames, never swallowed into a generic flag).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "sim/integrate/linkage_integrator.hpp"

namespace fourbar {
namespace {

/// y' = −y on [0, ∞), whose right-hand side fails once t passes `fail_after_s`.
class FailingDecay : public LinkageOde {
 public:
  explicit FailingDecay(double fail_after_s) : fail_after_s_(fail_after_s) {}
  void rhs(double t, const double* y, double* dydt) override {
    if (t > fail_after_s_) throw RunError("the problem failed at t = " + std::to_string(t));
    dydt[0] = -y[0];
  }
  void witnesses(double, const double*, double*) override {}

 private:
  double fail_after_s_;
};

TEST(LinkageIntegrator, AnExceptionInTheRightHandSideComesOutOfStep) {
  FailingDecay ode(0.5);
  LinkageIntegrator integrator(1e-8, 1, 1, 0);
  integrator.reset(ode, 0.0, {1.0});
  double t = 0;
  bool thrown = false;
  try {
    for (int i = 0; i < 100000 && t < 1.0; ++i) t = integrator.step(1.0).end;
  } catch (const RunError& e) {
    thrown = true;
    EXPECT_NE(std::string(e.what()).find("the problem failed"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(thrown) << "reached t = " << t;
  EXPECT_LE(t, 0.5 + 1e-12);
}

TEST(LinkageIntegrator, DecayMatchesTheClosedFormWhenNothingFails) {
  FailingDecay ode(10.0);
  LinkageIntegrator integrator(1e-10, 1, 1, 0);
  integrator.reset(ode, 0.0, {1.0});
  double t = 0;
  while (t < 1.0) t = integrator.step(1.0).end;
  std::vector<double> y;
  integrator.interpolate(1.0, y);
  EXPECT_NEAR(y[0], std::exp(-1.0), 1e-8);
}

}  // namespace
}  // namespace fourbar
