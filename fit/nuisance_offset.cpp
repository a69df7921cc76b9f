#include "fit/nuisance_offset.hpp"

#include <algorithm>
#include <stdexcept>

namespace fourbar {

ProfiledOffset profile_shared_offset(std::span<const double> residuals, std::span<const double> variances, double sigma) {
  if (residuals.size() != variances.size())
    throw std::invalid_argument("profile_shared_offset: residuals and variances differ in length");
  if (!(sigma >= 0)) throw std::invalid_argument("profile_shared_offset: sigma must be 0 or more");
  ProfiledOffset out;
  double sw = 0, swd = 0;
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    const double w = 1.0 / std::max(variances[i], 1e-12);
    sw += w, swd += w * residuals[i];
  }
  // σ = 0: no offset allowed (η̂ = 0, the plain χ²).
  out.eta = sigma > 0 && sw > 0 ? swd / (sw + 1.0 / (sigma * sigma)) : 0.0;
  out.prior_chi2 = sigma > 0 ? out.eta * out.eta / (sigma * sigma) : 0.0;
  out.chi2 = out.prior_chi2;
  out.terms.reserve(residuals.size());
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    const double d = residuals[i] - out.eta;
    out.terms.push_back(d * d / std::max(variances[i], 1e-12));
    out.chi2 += out.terms.back();
  }
  return out;
}

}  // namespace fourbar
