#include "common/format.hpp"

#include <sstream>

namespace fourbar {

std::string format_number(double value, int significant_digits) {
  std::ostringstream os;
  os.precision(significant_digits);
  os << value;
  return os.str();
}

}  // namespace fourbar
