#include "text_format.hpp"

#include <sstream>

namespace cosmems::internal {

std::string Scientific(double value, int digits) {
  if (value == 0.0) return "0";
  std::ostringstream out;
  out.setf(std::ios::scientific, std::ios::floatfield);
  out.precision(digits - 1);
  out << value;
  return out.str();
}

std::string Significant(double value, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << value;
  return out.str();
}

std::string Vector(const Eigen::Vector3d& value) {
  return "[" + Scientific(value.x()) + ", " + Scientific(value.y()) + ", " + Scientific(value.z()) +
         "]";
}

}  // namespace cosmems::internal
