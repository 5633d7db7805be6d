// Solver benchmark (issue: the numerical core): steps per second and peak
// memory for the pendulum with quadratic damping, for vibra's steppers beside
// hand-written C++ loops of the same formulas and the book's Python loop, in
// one run. Each case runs in a child process so its peak memory is its own.
//
//   solver_bench [--steps N] [--csv-steps N] [--peer PATH/solver_loop.py]
//
// The peer is bench/peers/solver_loop.py of this source tree by default.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>

#include "core/csv_writer.hpp"
#include "core/models/model.hpp"

using namespace vibra;

namespace {
constexpr double kTheta = 40 * M_PI / 180, kAlpha = 0.8, kDt = 2 * M_PI / 60;

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::unique_ptr<Trajectory> pendulum(const std::string& scheme, long long steps) {
  Parameters p = model_parameters(find_model("pendulum"));
  p.assign("scheme=" + scheme);
  p.assign("Theta=40");
  p.assign("alpha=0.8");
  p.assign("dt=2*pi/60");
  p.assign("T=" + std::to_string(steps) + "*2*pi/60");
  return find_model("pendulum").build(p);
}

/// The centered scheme with quadratic damping (1.82), written out by hand.
double hand_centered(long long steps) {
  double u_prev = kTheta, u = kTheta - 0.5 * kDt * kDt * std::sin(kTheta), sum = 0;
  for (long long n = 1; n < steps; ++n) {
    const double jump = kAlpha * std::abs(u - u_prev);
    const double next = (2 * u - u_prev + jump * u - kDt * kDt * std::sin(u)) / (1 + jump);
    u_prev = u, u = next;
    sum += u;
  }
  return sum;
}

/// Classical RK4 for theta' = omega, omega' = -sin(theta) - alpha |omega| omega, by hand.
double hand_rk4(long long steps) {
  double th = kTheta, om = 0, sum = 0, h = kDt;
  auto a = [](double x, double v) { return -std::sin(x) - kAlpha * std::abs(v) * v; };
  for (long long n = 0; n < steps; ++n) {
    const double a1 = a(th, om);
    const double x2 = th + 0.5 * h * om, v2 = om + 0.5 * h * a1, a2 = a(x2, v2);
    const double x3 = th + 0.5 * h * v2, v3 = om + 0.5 * h * a2, a3 = a(x3, v3);
    const double x4 = th + h * v3, v4 = om + h * a3, a4 = a(x4, v4);
    th += h / 6 * (om + 2 * v2 + 2 * v3 + v4);
    om += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    sum += th;
  }
  return sum;
}

/// vibra's stepper streamed to an observer that only sums (nothing stored).
double vibra_to_nothing(const std::string& scheme, long long steps) {
  auto t = pendulum(scheme, steps);
  auto& typed = dynamic_cast<SecondOrderTrajectory<1>&>(*t);
  double sum = 0;
  typed.stream().for_each([&](const Sample<1>& s) {
    sum += s.u[0];
    return true;
  });
  return sum;
}

/// vibra's full `solve` path: rows through the type-erased trajectory into CSV.
double vibra_to_csv(const std::string& scheme, long long steps) {
  auto t = pendulum(scheme, steps);
  const std::string path = "/tmp/vibra_solver_bench_" + std::to_string(getpid()) + ".csv";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  {
    CsvWriter csv(f, t->info().columns);
    std::vector<double> row(t->width());
    do {
      t->row(row);
      csv.write(row);
    } while (t->advance());
    csv.flush();
  }
  std::fclose(f);
  std::remove(path.c_str());
  return 0;
}

struct Result {
  double seconds;
  long peak_kib;
};

/// Runs `work` in a child; returns its wall time and peak resident memory.
Result measure(const std::function<double()>& work) {
  int fds[2];
  if (pipe(fds) != 0) std::exit(1);
  pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const double start = now();
    volatile double sink = work();
    (void)sink;
    const double elapsed = now() - start;
    if (write(fds[1], &elapsed, sizeof elapsed) != sizeof elapsed) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  double elapsed = -1;
  if (read(fds[0], &elapsed, sizeof elapsed) != sizeof elapsed) elapsed = -1;
  close(fds[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  return {elapsed, usage.ru_maxrss};
}

void report(const char* name, long long steps, const Result& r, double reference_seconds = 0) {
  std::printf("%-34s %12lld %10.1f %9.2f %10ld", name, steps, steps / r.seconds / 1e6, 1e9 * r.seconds / steps,
              r.peak_kib);
  if (reference_seconds > 0) std::printf("   %.2fx the hand-written loop", r.seconds / reference_seconds);
  std::printf("\n");
  std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
  long long steps = 100'000'000, csv_steps = 10'000'000;
  std::string peer = VIBRA_PEERS_DIR "/solver_loop.py";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--steps")) steps = std::atoll(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--csv-steps")) csv_steps = std::atoll(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--peer")) peer = argv[i + 1];
  }
  std::printf("pendulum, quadratic damping (alpha = 0.8, Theta = 40 deg, dt = 2 pi/60)\n");
  std::printf("%-34s %12s %10s %9s %10s\n", "case", "steps", "Msteps/s", "ns/step", "peak KiB");
  const Result hand_c = measure([&] { return hand_centered(steps); });
  report("hand-written centered loop", steps, hand_c);
  const Result hand_r = measure([&] { return hand_rk4(steps); });
  report("hand-written rk4 loop", steps, hand_r);
  for (const char* scheme : {"centered", "euler-cromer", "rk4", "pefrl"}) {
    const Result r = measure([&] { return vibra_to_nothing(scheme, steps); });
    const std::string name = std::string("vibra ") + scheme + " -> nothing";
    const double reference = !std::strcmp(scheme, "centered") ? hand_c.seconds : !std::strcmp(scheme, "rk4") ? hand_r.seconds : 0;
    report(name.c_str(), steps, r, reference);
  }
  for (const char* scheme : {"centered", "rk4"}) {
    const Result r = measure([&] { return vibra_to_csv(scheme, csv_steps); });
    report((std::string("vibra ") + scheme + " -> CSV file").c_str(), csv_steps, r);
  }
  // Memory must not grow with the run: the same case at 1/100 of the steps.
  const Result small = measure([&] { return vibra_to_nothing("rk4", steps / 100); });
  report("vibra rk4 -> nothing (1/100 steps)", steps / 100, small);

  if (access(peer.c_str(), R_OK) == 0) {
    const long long peer_steps = 1'000'000;
    const std::string command = "/usr/bin/python3 " + peer + " --steps " + std::to_string(peer_steps);
    const Result r = measure([&] { return double(std::system((command + " 2>/dev/null").c_str())); });
    report("Python peer (book's loop, process)", peer_steps, r);
    const Result ours = measure([&] { return vibra_to_nothing("centered", peer_steps); });
    std::printf("vibra centered is %.0fx the Python loop's steps/s (whole process for Python)\n",
                r.seconds / ours.seconds);
  } else {
    std::printf("(Python peer not found at %s: pass --peer PATH)\n", peer.c_str());
  }
  return 0;
}
