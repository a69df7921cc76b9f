#include "sim/drive/tabulated_crank.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "common/error.hpp"

namespace fourbar {

struct TabulatedCrank::Spline {
  boost::math::interpolators::cardinal_cubic_b_spline<double> s;
};

TabulatedCrank::TabulatedCrank(std::vector<double> t, std::vector<double> a, double w_start, double w_end)
    : spline_(std::make_unique<Spline>()) {
  if (t.size() < 4 || t.size() != a.size()) throw InputError("crank table: at least 4 samples of time and angle");
  t0_ = t.front();
  h_ = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  if (!(h_ > 0)) throw InputError("crank table: times must ascend");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::abs(t[i] - (t0_ + h_ * static_cast<double>(i))) > 1e-9 * h_ * static_cast<double>(t.size()))
      throw InputError("crank table: sample " + std::to_string(i) + " off the uniform time grid (spacing " +
                       std::to_string(h_) + " s)");
    if (!std::isfinite(a[i])) throw InputError("crank table: angle of sample " + std::to_string(i) + " not finite");
  }
  n_ = t.size();
  spline_->s = boost::math::interpolators::cardinal_cubic_b_spline<double>(a.begin(), a.end(), t0_, h_, w_start,
                                                                           w_end);
}

TabulatedCrank::~TabulatedCrank() = default;

std::unique_ptr<TabulatedCrank> TabulatedCrank::from_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot read the crank table (give an existing CSV file)");
  std::string line;
  std::getline(in, line);
  if (line.rfind("time_s,crank_rad,crank_rad_s", 0) != 0)
    throw InputError(file.string() + ": line 1 must be the header time_s,crank_rad,crank_rad_s");
  std::vector<double> t, a, w;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    std::istringstream row(line);
    double v[3];
    char comma = 0;
    if (!(row >> v[0] >> comma >> v[1] >> comma >> v[2]) || !std::isfinite(v[0]) || !std::isfinite(v[1]) ||
        !std::isfinite(v[2]))
      throw InputError(file.string() + ": line " + std::to_string(number) +
                       " is not three finite numbers time_s,crank_rad,crank_rad_s");
    t.push_back(v[0]);
    a.push_back(v[1]);
    w.push_back(v[2]);
  }
  if (t.size() < 4) throw InputError(file.string() + ": fewer than 4 crank samples");
  auto c = std::make_unique<TabulatedCrank>(t, a, w.front(), w.back());
  c->speeds_ = w;
  return c;
}

CrankState TabulatedCrank::at(double time) const {
  const double tend = end_time_s();
  if (time <= tend) {
    const double x = std::max(time, t0_);
    if (time < t0_) return {spline_->s(t0_), 0.0, 0.0};
    return {spline_->s(x), spline_->s.prime(x), spline_->s.double_prime(x)};
  }
  const double w = spline_->s.prime(tend);
  return {spline_->s(tend) + w * (time - tend), w, 0.0};
}

double TabulatedCrank::time_at_angle(double angle) const {
  const double a0 = at(t0_).angle_rad;
  const double s = angle >= a0 ? 1.0 : -1.0;
  double lo = t0_;
  for (std::size_t i = 1; i < n_; ++i) {
    double hi = t0_ + h_ * static_cast<double>(i);
    if (s * (at(hi).angle_rad - angle) >= 0) {
      for (int k = 0; k < 100; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (s * (at(mid).angle_rad - angle) >= 0) hi = mid;
        else lo = mid;
      }
      return hi;
    }
    lo = hi;
  }
  throw RunError("crank table: the crank never reaches " + std::to_string(angle) + " rad");
}

}  // namespace fourbar
