// The core's C API for the browser build: solve a model from KEY=VALUE settings, hand back its rows or the CLI's one-line reason.
#include <exception>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "setting_lines.hpp"
#include "core/models/model.hpp"
#include "core/input/quoted_value.hpp"
#include "core/stop_flag.hpp"

namespace {

/// The page plays runs of a few periods: a run of more rows than this is a
/// mistake (dt far too small), refused rather than filling the tab's memory.
constexpr long long kMostRows = 2'000'000;

struct LastRun {
  std::string error;
  std::string columns;
  std::vector<double> rows;
  long long row_count = 0;
};
LastRun last;

void solve(const std::string& model_name, const std::vector<std::string>& settings) {
  const vibra::Parameters p = vibra::model_settings(model_name, settings);
  const std::unique_ptr<vibra::Trajectory> trajectory = vibra::find_model(model_name).build(p);
  const auto& columns = trajectory->info().columns;
  for (const auto& c : columns) last.columns += (last.columns.empty() ? "" : ",") + c;
  std::vector<double> row(columns.size());
  do {
    if (last.row_count == kMostRows)
      throw vibra::UsageError("the run has more than " + std::to_string(kMostRows) +
                              " steps, too many for the page: raise dt or lower T");
    trajectory->row(row);
    last.rows.insert(last.rows.end(), row.begin(), row.end());
    ++last.row_count;
    vibra::poll_stop(trajectory->index());
  } while (trajectory->advance());
}

}  // namespace

extern "C" {

/// Solves MODEL with one KEY=VALUE a line (as `vibra solve MODEL --set`
/// takes them). 0: the rows are ready; 2: bad input, 1: another fault, with
/// the reason in vibra_error().
int vibra_solve(const char* model, const char* settings) {
  last = LastRun{};
  int code = 2;
  try {
    solve(model ? model : "", vibra::web::lines_of(settings));
    return 0;
  } catch (const vibra::UsageError& e) {
    last.error = e.what();
  } catch (const vibra::SolutionError& e) {
    last.error = e.what();
  } catch (const std::exception& e) {
    last.error = e.what(), code = 1;
  }
  last = LastRun{vibra::one_line_message(last.error)};  // no rows of a run that failed
  return code;
}

const char* vibra_error() { return last.error.c_str(); }
/// The columns of the rows, comma-separated, e.g. "t,theta,omega,S,D".
const char* vibra_columns() { return last.columns.c_str(); }
int vibra_row_count() { return last.row_count; }
/// The rows one after another, each with one double per column.
const double* vibra_rows() { return last.rows.data(); }

}  // extern "C"
