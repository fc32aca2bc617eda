#include "sweep_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "atomic_file.hpp"
#include "csv_file.hpp"
#include "sweep_outputs.hpp"

namespace cosmems::internal {
namespace {

// A field as a file name: "frequencies_hz[0]" -> "frequencies_hz_0".
std::string Stem(const std::string& field) {
  std::string stem;
  for (const char c : field) {
    if (c == '[') stem += '_';
    if (c != '[' && c != ']') stem += c;
  }
  return stem;
}

// A gnuplot string: single quotes, an inner one doubled.
std::string Quoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

// A shell word: single quotes, an inner one closed, escaped and reopened.
std::string ShellWord(const std::string& text) {
  std::string word = "'";
  for (const char c : text) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return word + "'";
}

bool GnuplotFound() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

// The field's value and the rows' grid keys for every sample that ran and has it.
struct Point {
  std::vector<double> keys;
  double value;
};
std::vector<Point> Points(const std::vector<SweepRow>& rows, const std::string& field,
                          const std::vector<std::string>& keys) {
  std::vector<Point> points;
  for (const SweepRow& row : rows) {
    if (!row.ok()) continue;
    const std::optional<double> value = OutputValue(row.result, field);
    if (!value) continue;
    Point point{{}, *value};
    for (const std::string& key : keys) point.keys.push_back(row.parameters[key].get<double>());
    points.push_back(std::move(point));
  }
  return points;
}

}  // namespace

std::vector<std::string> DefaultPlotFields(const std::vector<SweepRow>& rows,
                                           const std::vector<SweepCondition>& conditions) {
  std::vector<std::string> fields;
  for (const SweepCondition& c : conditions) {
    if (std::find(fields.begin(), fields.end(), c.field()) == fields.end())
      fields.push_back(c.field());
  }
  if (!fields.empty()) return fields;
  for (const SweepRow& row : rows) {
    if (!row.ok()) continue;
    const auto outputs = NumericOutputs(row.result);
    for (std::size_t i = 0; i + 1 < outputs.size(); ++i) {
      if (outputs[i].first == "wall_time_s") return {outputs[i + 1].first};
    }
    break;
  }
  return fields;
}

std::vector<std::filesystem::path> WriteSweepPlots(const std::filesystem::path& directory,
                                                   const std::vector<SweepRow>& rows,
                                                   const SweepPlotRequest& request) {
  const bool histogram = request.random;
  const std::size_t grid = request.grid_keys.size();
  if (!histogram && grid != 1 && grid != 2) return {};
  const std::vector<std::string> keys = histogram ? std::vector<std::string>{} : request.grid_keys;
  const bool gnuplot = GnuplotFound();
  std::vector<std::filesystem::path> written;
  for (const std::string& field : request.fields) {
    const std::vector<Point> points = Points(rows, field, keys);
    if (points.empty()) continue;
    const std::string stem = "plot_" + Stem(field);
    const std::filesystem::path data = directory / (stem + ".dat");
    {
      std::ostringstream out;
      double previous = points.front().keys.empty() ? 0.0 : points.front().keys.front();
      for (const Point& p : points) {
        // A map's scans (one value of the first key each) are separated by a blank line.
        if (grid == 2 && !histogram && p.keys.front() != previous) out << "\n";
        if (!p.keys.empty()) previous = p.keys.front();
        for (const double k : p.keys) out << CsvFile::Number(k) << " ";
        out << CsvFile::Number(p.value) << "\n";
      }
      AtomicFile::WriteWhole(data, out.str());
    }
    std::ostringstream gp;
    // SI values span many decades: three digits and slanted ticks keep them apart. `png` names
    // the image unless the command line set it (the sweep draws into a temporary, below).
    gp << "set terminal pngcairo size 800,560 noenhanced\n"
       << "if (!exists(\"png\")) png = " << Quoted(stem + ".png") << "\n"
       << "set output png\n"
       << "set grid\nset format x '%.3g'\nset format y '%.3g'\nset xtics rotate by 30 right\n"
       << "set lmargin 12\nset bmargin 5\n";
    std::string bounds;
    for (const SweepCondition& c : request.conditions) {
      if (c.field() != field) continue;
      // The spec's bound: a vertical line on a histogram, a horizontal one on a curve.
      const std::string at = CsvFile::Number(c.bound());
      if (histogram) {
        gp << "set arrow from " << at << ", graph 0 to " << at
           << ", graph 1 nohead front lw 2 lc rgb 'red'\n";
      } else if (grid == 1) {
        gp << "set arrow from graph 0, first " << at << " to graph 1, first " << at
           << " nohead front lw 2 lc rgb 'red'\n";
      }
      bounds += (bounds.empty() ? "" : ", ") + c.text();
    }
    const std::string title = field + (bounds.empty() ? "" : "   (spec " + bounds + ")");
    gp << "set title " << Quoted(title) << "\n";
    if (histogram) {
      double lo = points.front().value, hi = lo;
      for (const Point& p : points) {
        lo = std::min(lo, p.value);
        hi = std::max(hi, p.value);
      }
      // About sqrt(n) bins, from 5 to 60.
      const int bins = std::clamp(static_cast<int>(std::ceil(std::sqrt(points.size()))), 5, 60);
      const double width = hi > lo ? (hi - lo) / bins : std::max(std::abs(lo), 1.0) * 1e-3;
      gp << "set xlabel " << Quoted(field) << "\nset ylabel 'samples'\n"
         << "set style fill solid 0.5\n"
         << "width = " << CsvFile::Number(width) << "\nlow = " << CsvFile::Number(lo) << "\n"
         << "bin(x) = low + width * (floor((x - low) / width) + 0.5)\n"
         << "plot " << Quoted(data.filename().string())
         << " using (bin($1)):(1.0) smooth frequency with boxes notitle\n";
    } else if (grid == 1) {
      gp << "set xlabel " << Quoted(keys[0]) << " offset 0,-1\nset ylabel " << Quoted(field) << "\n"
         << "plot " << Quoted(data.filename().string())
         << " using 1:2 with linespoints pt 7 notitle\n";
    } else {
      gp << "set xlabel " << Quoted(keys[0]) << " offset 0,-1\nset ylabel " << Quoted(keys[1])
         << "\n"
         << "set cblabel " << Quoted(field) << "\nset view map\n"
         << "splot " << Quoted(data.filename().string()) << " using 1:2:3 with pm3d notitle\n";
    }
    AtomicFile::WriteWhole(directory / (stem + ".gp"), gp.str());
    if (!gnuplot) continue;
    // gnuplot writes wherever `set output` says, through a symbolic link too: it draws into a
    // temporary of our making, which replaces the image once whole.
    AtomicFile png(directory / (stem + ".png"));
    const std::string set_png = "png = " + Quoted(png.temporary().filename().string());
    if (std::system(("cd " + ShellWord(directory.string()) + " && gnuplot -e " +
                     ShellWord(set_png) + " " + ShellWord(stem + ".gp") + " 2>/dev/null")
                        .c_str()) == 0) {
      png.Commit();
      written.push_back(directory / (stem + ".png"));
    }
  }
  return written;
}

}  // namespace cosmems::internal
