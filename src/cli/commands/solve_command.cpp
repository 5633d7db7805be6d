// Registers vibra solve: a model's trajectory as CSV, streamed to standard output or a file.
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "cli/commands.hpp"
#include "cli/manuals/model_help.hpp"
#include "cli/option_checks.hpp"
#include "cli/wrote_message.hpp"
#include "core/csv_writer.hpp"
#include "core/error.hpp"
#include "render/output/output_error.hpp"
#include "render/output/output_path.hpp"
#include "render/output/standard_output.hpp"
#include "render/output/stop_signal.hpp"
#include "render/output/temporary_file.hpp"

namespace vibra::cli {

namespace {
struct SolveOptions {
  std::string model;
  std::vector<std::string> settings;
  std::string output;
  long long every = 1;
  bool energy = false;
  bool help = false;
  bool quiet = false;
};

void run_solve(const SolveOptions& o) {
  if (o.help || o.model.empty()) {
    print_model_help("Usage: vibra solve MODEL [--set KEY=VALUE]... [--output FILE] [--every K] [--energy]\n\n", o.model);
    if (!o.help) throw UsageError("vibra solve needs a MODEL, e.g. vibra solve pendulum");
    return;
  }
  if (o.every < 1) throw UsageError("--every must be >= 1");
  Parameters p = model_settings(o.model, o.settings);
  std::unique_ptr<Trajectory> trajectory = find_model(o.model).build(p);
  const TrajectoryInfo& info = trajectory->info();
  if (o.energy && !info.energy) throw UsageError("model " + o.model + " has no mechanical energy: drop --energy");
  std::vector<std::string> columns = info.columns;
  if (o.energy) columns.insert(columns.end(), {"E", "E_rel"});

  // Standard output, a pipe or a device takes the CSV as a stream; a file
  // (or a link's target) gets it through a temporary.
  const render::OutputTarget target = render::resolve_output(o.output.empty() ? "-" : o.output, "");
  std::optional<render::TemporaryFile> file;
  std::FILE* out = stdout;
  if (target.stream) {
    render::send_standard_output_to(target);
  } else {
    file.emplace(target.file);
    out = std::fopen(file->path().c_str(), "wb");
    if (!out) throw render::OutputError("cannot write '" + o.output + "': choose a writable path");
  }
  auto close = [&] {
    if (out != stdout) std::fclose(out), out = stdout;
  };
  try {
    CsvWriter csv(out, columns);
    std::vector<double> row(columns.size());
    const std::span<double> state(row.data(), trajectory->width());
    double E0 = 0;
    if (o.energy) {
      trajectory->row(state);
      E0 = info.energy(state).total();
    }
    do {
      if (trajectory->index() % o.every == 0 || trajectory->done()) {
        trajectory->row(state);
        if (o.energy) {
          const double E = info.energy(state).total();
          row[state.size()] = E, row[state.size() + 1] = relative_energy_change(E, E0);
        }
        csv.write(row);
      }
      poll_stop(trajectory->index());
    } while (!csv.failed() && trajectory->advance());
    if (!csv.flush()) {
      if (!file) render::standard_output_failed(csv.error());
      throw render::OutputError("writing '" + o.output + "' failed (disk full?): free space or choose another path");
    }
    if (file) {
      if (std::fclose(out) != 0)
        throw render::OutputError("writing '" + o.output + "' failed (disk full?): free space or choose another path");
      out = stdout;
      file->commit();
      say_wrote(o.quiet, target.shown());
    }
  } catch (...) {
    close();
    throw;
  }
}
}  // namespace

void add_solve_command(CLI::App& app) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* cmd = app.add_subcommand("solve", "Solve a model and print its trajectory as CSV");
  cmd->set_help_flag();  // our own help lists the model's keys
  cmd->add_flag("-h,--help", options->help, "List models, or a model's keys with units and defaults");
  cmd->add_option("MODEL", options->model, "Model name (vibra solve --help lists them)");
  cmd->add_option("--set", options->settings, "KEY=VALUE, repeatable (vibra solve MODEL --help lists keys)")
      ->allow_extra_args(false);
  add_output_option(*cmd, options->output, "CSV file, or a pipe or device (default: standard output)");
  cmd->add_option("--every", options->every, "Write every K-th step (the last step is always written)")
      ->check(ranged("--every"));
  cmd->add_flag("--energy", options->energy,
                "Append the energy E (scheme's own velocity) and E_rel = (E - E(0))/|E(0)|");
  add_allow_unstable_flag(*cmd);
  cmd->add_flag("-q,--quiet", options->quiet, "No message on stderr after writing a file");
  cmd->callback([options] { run_solve(*options); });
}

}  // namespace vibra::cli
