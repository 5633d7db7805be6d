#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/models/model.hpp"

namespace vibra::test {

/// A model's trajectory with the given KEY=VALUE settings.
inline std::unique_ptr<Trajectory> trajectory(const std::string& model, const std::vector<std::string>& settings) {
  Parameters p = model_parameters(find_model(model));
  for (const auto& s : settings) p.assign(s);
  return find_model(model).build(p);
}

/// All rows of a (short) trajectory.
inline std::vector<std::vector<double>> rows(Trajectory& t) {
  std::vector<std::vector<double>> out;
  do {
    out.emplace_back(t.width());
    t.row(out.back());
  } while (t.advance());
  return out;
}

inline std::string str(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace vibra::test
