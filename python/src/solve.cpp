// vibra.solve and vibra.stream: the trajectory of a model written straight
// into memory that numpy then views, with the GIL released while it runs.
#include <algorithm>
#include <limits>
#include <vector>

#include "bindings.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/input/value_ranges.hpp"
#include "render/encode/huge_pages.hpp"

namespace vibra::python {

namespace {
// Steps between looks at Python's signal flag (Ctrl-C, a notebook's stop).
constexpr long long kSignalCheckSteps = 1 << 16;

std::unique_ptr<Trajectory> build(const std::string& model, const std::vector<std::string>& settings, long long every) {
  in_range("every", static_cast<double>(every), std::to_string(every));
  return find_model(model).build(model_settings(model, settings));
}

py::dict run_info(const std::string& model, const Trajectory& trajectory) {
  const TimeMesh& mesh = trajectory.info().mesh;
  py::dict info;
  info["model"] = model;
  info["scheme"] = std::string(scheme_info(mesh.scheme).name);
  info["dt"] = mesh.dt;
  info["T"] = mesh.T;
  info["steps"] = mesh.steps == SolutionStream<1>::unbounded ? py::object(py::float_(mesh.T)) : py::object(py::int_(mesh.steps));
  info["period"] = mesh.period;
  return info;
}

/// Writes every `every`-th sample (and the last) from the current one on into
/// the column-major `data` of `capacity` rows, until it is full or the run
/// ends (then `finished`). Runs without the GIL, taking it back now and then
/// to look for a signal. Returns the rows written.
size_t fill_rows(Trajectory& trajectory, long long every, double* data, size_t capacity, bool& finished) {
  const size_t width = trajectory.width();
  std::vector<double> row(width);
  size_t rows = 0;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    long long until_check = kSignalCheckSteps;
    long long phase = trajectory.index() % every;  // counted, not divided, per step
    while (rows < capacity) {
      if (phase == 0 || trajectory.done()) {
        trajectory.row(row);
        for (size_t c = 0; c < width; ++c) data[c * capacity + rows] = row[c];
        ++rows;
      }
      if (++phase == every) phase = 0;
      if (!trajectory.advance()) {
        finished = true;
        break;
      }
      if (--until_check == 0) {
        until_check = kSignalCheckSteps;
        py::gil_scoped_acquire acquire;
        if ((interrupted = PyErr_CheckSignals() != 0)) break;
      }
    }
  }
  if (interrupted) throw py::error_already_set();
  return rows;
}

/// Rows a whole run of `steps` steps gives with every `every`-th kept.
size_t row_count(long long steps, long long every) {
  return static_cast<size_t>(steps / every + 1 + (steps % every != 0));
}

/// An adaptive run takes as many steps as its tolerances need, not the
/// mesh's count (docs/schemes.md): its rows are gathered chunk by chunk
/// until the run ends, then laid out once.
py::array_t<double> adaptive_table(Trajectory& trajectory, long long every, size_t chunk) {
  const size_t width = trajectory.width();
  std::vector<std::vector<double>> columns(width);
  TableMemory buffer = allocate_table(chunk, width);
  for (bool finished = false; !finished;) {
    const size_t written = fill_rows(trajectory, every, buffer.get(), chunk, finished);
    for (size_t c = 0; c < width; ++c)
      columns[c].insert(columns[c].end(), buffer.get() + c * chunk, buffer.get() + c * chunk + written);
  }
  const size_t rows = columns[0].size();
  TableMemory data = allocate_table(rows, width);
  for (size_t c = 0; c < width; ++c) std::copy(columns[c].begin(), columns[c].end(), data.get() + c * rows);
  return owning_array(std::move(data), rows, width);
}

py::tuple solve(const std::string& model, const std::vector<std::string>& settings, long long every) {
  std::unique_ptr<Trajectory> trajectory = build(model, settings, every);
  const long long steps = trajectory->info().mesh.steps;
  if (steps == SolutionStream<1>::unbounded)
    throw UsageError("T=inf never ends: use vibra.stream for unbounded runs, or give a finite T");
  const size_t rows = row_count(steps, every), width = trajectory->width();
  if (rows > std::numeric_limits<size_t>::max() / sizeof(double) / width)
    throw UsageError("that is too many rows: raise every or dt, or lower T");
  if (trajectory->info().mesh.adaptive())
    return py::make_tuple(trajectory->info().columns, adaptive_table(*trajectory, every, std::min<size_t>(rows, 1 << 16)),
                          run_info(model, *trajectory));
  TableMemory data = allocate_table(rows, width);  // uninitialised: each element is written once
  bool finished = false;
  fill_rows(*trajectory, every, data.get(), rows, finished);
  return py::make_tuple(trajectory->info().columns, owning_array(std::move(data), rows, width),
                        run_info(model, *trajectory));
}

/// A run handed out in chunks, for runs too long to hold (T=inf).
class Stream {
 public:
  Stream(const std::string& model, const std::vector<std::string>& settings, long long every)
      : trajectory_(build(model, settings, every)), every_(every), info_(run_info(model, *trajectory_)) {}

  const std::vector<std::string>& columns() const { return trajectory_->info().columns; }
  py::dict info() const { return info_; }

  /// The next up to `rows` rows as a (rows, columns) array; None at the end.
  py::object next_chunk(long long rows) {
    // The table of ranges bounds a chunk: rows * columns * 8 bytes must neither
    // overflow nor ask for more than a few hundred MB at once.
    in_range("chunk", static_cast<double>(rows), std::to_string(rows));
    if (finished_) return py::none();
    const size_t width = trajectory_->width(), capacity = static_cast<size_t>(rows);
    TableMemory data = allocate_table(capacity, width);
    const size_t written = fill_rows(*trajectory_, every_, data.get(), capacity, finished_);
    py::array_t<double> chunk = owning_array(std::move(data), capacity, width);
    if (written == capacity) return chunk;
    // The last, short chunk: a view of its first rows (of the same buffer).
    return chunk[py::make_tuple(py::slice(0, written, 1), py::slice(0, width, 1))];
  }

 private:
  std::unique_ptr<Trajectory> trajectory_;
  long long every_;
  py::dict info_;
  bool finished_ = false;
};
}  // namespace

void FreeTable::operator()(double* data) const { render::free_huge_page_memory(data); }

TableMemory allocate_table(size_t rows, size_t columns) {
  return TableMemory(static_cast<double*>(render::allocate_huge_page_memory(rows * columns * sizeof(double))));
}

py::array_t<double> owning_array(TableMemory data, size_t rows, size_t columns) {
  double* pointer = data.release();
  py::capsule owner(pointer, [](void* p) { render::free_huge_page_memory(p); });
  const py::ssize_t row_stride = sizeof(double), column_stride = static_cast<py::ssize_t>(rows * sizeof(double));
  return py::array_t<double>({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)},
                             {row_stride, column_stride}, pointer, owner);
}

void bind_solve(py::module_& m) {
  m.def("solve", &solve, py::arg("model"), py::arg("settings"), py::arg("every"),
        "(columns, table, info): the whole run as a column-major (rows, columns) array");
  py::class_<Stream>(m, "Stream")
      .def(py::init<const std::string&, const std::vector<std::string>&, long long>(), py::arg("model"),
           py::arg("settings"), py::arg("every"))
      .def_property_readonly("columns", &Stream::columns)
      .def_property_readonly("info", &Stream::info)
      .def("next_chunk", &Stream::next_chunk, py::arg("rows"));
  m.def("models", [] {
    py::list out;
    for (const ModelDefinition& model : all_models()) {
      py::list keys;
      const Parameters parameters = model_parameters(model);
      for (const KeySpec& key : parameters.specs())
        keys.append(py::dict(py::arg("name") = key.name, py::arg("default") = key.default_value,
                             py::arg("unit") = key.unit, py::arg("meaning") = key.meaning));
      out.append(py::dict(py::arg("name") = model.name, py::arg("summary") = model.summary,
                          py::arg("columns") = model.columns, py::arg("keys") = keys));
    }
    return out;
  });
}

}  // namespace vibra::python
