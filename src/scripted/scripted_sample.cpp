#include "cosmems/scripted/scripted_sample.hpp"

#include <fstream>
#include <iomanip>
#include <limits>
#include <locale>
#include <stdexcept>

namespace cosmems {

void WriteSamplesCsv(std::ostream& out, const std::vector<ScriptedSample>& samples) {
  out.imbue(std::locale::classic());
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  out << "time_s,x_m,y_m,z_m,fx_n,fy_n,fz_n\n";
  for (const ScriptedSample& s : samples) {
    out << s.time_s << ',' << s.position_m.x() << ',' << s.position_m.y() << ',' << s.position_m.z()
        << ',' << s.force_n.x() << ',' << s.force_n.y() << ',' << s.force_n.z() << '\n';
  }
}

void WriteSamplesCsv(const std::string& path, const std::vector<ScriptedSample>& samples) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  WriteSamplesCsv(out, samples);
  out.flush();
  if (!out) throw std::runtime_error(path + ": writing failed");
}

}  // namespace cosmems
