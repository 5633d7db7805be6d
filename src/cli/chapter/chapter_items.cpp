// The chapter's table: every figure and exercise of chapter 1 with the vibra commands that answer it.
#include "cli/chapter/chapter_items.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/stop_flag.hpp"

namespace vibra::cli {

namespace {
// Notes where the book's text differs from what vibra computes (docs/misprints.md).
const char* const kStaggeredNote =
    "(1.100) prints the wrong velocity index: v^{n+1/2} is computed from v^{n-1/2}; and the start (1.106) "
    "v^{1/2} = V - 0.5 dt w^2 I holds only for the undamped linear spring: vibra starts with "
    "v^{1/2} = V + 0.5 dt (F(0) - f(V) - s(I))/m.";
const char* const kPendulumNote =
    "(1.124) has a sign error in the radial force balance: -S + m g cos(theta) = -m L theta'^2, so "
    "S = m g cos(theta) + m L theta'^2 (scaled S = omega^2 + cos(theta)).";

// Figures in order, then exercises in order: the chapter's order.
const std::vector<ChapterItem> kItems = {
    {ItemKind::figure,
     "1.1",
     "log-log error against dt, slopes 2 and 4",
     {{"analyze", "convergence", "undamped", "--compare", "scheme=centered,centered-adjusted", "--levels", "5", "-o",
       "figure_1_1.png"}}},
    {ItemKind::figure,
     "1.2",
     "exact and numerical, dt = 0.1 and 0.05",
     {{"plot", "undamped", "--compare", "dt=0.1,0.05", "--set", "periods=4", "--panels", "u", "-o", "figure_1_2.png"},
      {"solve", "undamped", "--set", "dt=0.1", "--set", "T=0.2"}}},
    {ItemKind::figure,
     "1.3",
     "empirical amplitude and period for dt = 0.1, 0.05, 0.01",
     {{"analyze", "empirical", "undamped", "--dt", "0.1,0.05,0.01", "-o", "figure_1_3.png"}}},
    {ItemKind::figure,
     "1.4",
     "w~(dt) and its approximation, w = 1",
     {{"analyze", "frequency", "--w", "1", "-o", "figure_1_4.png"}}},
    {ItemKind::figure,
     "1.5",
     "dt just above the stability limit: growth",
     {{"plot", "undamped", "--set", "dt=0.3184", "--set", "T=10", "--panels", "u,exact", "--allow-unstable", "-o",
       "figure_1_5.png"}}},
    {ItemKind::figure,
     "1.6",
     "dt = 2/w: a trough where the exact solution peaks",
     {{"plot", "undamped", "--set", "dt=1/pi", "--set", "T=2", "--panels", "u,exact", "-o", "figure_1_6.png"}}},
    {ItemKind::figure,
     "1.7",
     "Forward Euler, Backward Euler, Crank-Nicolson: phase plane and u(t)",
     {{"plot", "undamped", "--compare", "scheme=forward-euler,backward-euler,crank-nicolson", "--set", "dt=0.05",
       "--set", "periods=2", "--panels", "u,phase", "-o", "figure_1_7.png"}}},
    {ItemKind::figure,
     "1.8",
     "Forward Euler, Backward Euler, Crank-Nicolson: phase plane and u(t)",
     {{"plot", "undamped", "--compare", "scheme=forward-euler,backward-euler,crank-nicolson", "--set", "dt=0.05",
       "--set", "periods=2", "--panels", "u,phase", "-o", "figure_1_7.png"}}},
    {ItemKind::figure,
     "1.9",
     "RK2, RK4: phase plane and u(t)",
     {{"plot", "undamped", "--compare", "scheme=rk2,rk4", "--set", "dt=0.05", "--set", "periods=10", "--panels",
       "u,phase", "-o", "figure_1_9.png"}}},
    {ItemKind::figure,
     "1.10",
     "RK2, RK4: phase plane and u(t)",
     {{"plot", "undamped", "--compare", "scheme=rk2,rk4", "--set", "dt=0.05", "--set", "periods=10", "--panels",
       "u,phase", "-o", "figure_1_9.png"}}},
    {ItemKind::figure,
     "1.11",
     "Crank-Nicolson against RK2",
     {{"plot", "undamped", "--compare", "scheme=crank-nicolson,rk2", "--set", "dt=0.05", "--set", "periods=10",
       "--panels", "u", "-o", "figure_1_11.png"}}},
    {ItemKind::figure,
     "1.12",
     "u and v on a staggered mesh (a sketch)",
     {{"plot", "undamped", "--set", "scheme=staggered", "--set", "steps_per_period=8", "--set", "periods=2", "--panels",
       "u,v", "--annotate", "mesh", "-o", "figure_1_12.png"}},
     kStaggeredNote},
    {ItemKind::figure,
     "1.13",
     "amplitude errors of many solvers",
     {{"analyze", "amplitude", "--schemes", "rk3,rk4,crank-nicolson,ab2,ab3,backward2step", "--dt", "0.05", "--periods",
       "20", "-o", "figure_1_13.png"}}},
    {ItemKind::figure,
     "1.14",
     "amplitude errors of many solvers",
     {{"analyze", "amplitude", "--schemes", "rk3,rk4,crank-nicolson,ab2,ab3,backward2step", "--dt", "0.05", "--periods",
       "20", "-o", "figure_1_13.png"}}},
    {ItemKind::figure,
     "1.15",
     "amplitude errors of many solvers",
     {{"analyze", "amplitude", "--schemes", "rk3,rk4,crank-nicolson,ab2,ab3,backward2step", "--dt", "0.05", "--periods",
       "20", "-o", "figure_1_13.png"}}},
    {ItemKind::figure,
     "1.16",
     "a moving window over a long series",
     {{"render", "undamped", "--set", "periods=12", "--window", "4periods", "--at", "10", "-o", "figure_1_16.png"},
      {"render", "undamped", "--set", "periods=12", "--window", "4periods", "--size", "640x360", "-o",
       "figure_1_16.mp4"}},
     "The book writes its frames and joins them with ffmpeg -i tmp_%04d.png -r 6: the input rate belongs before -i, "
     "and players want 25 fps or more. vibra encodes the video itself, at 30 fps."},
    {ItemKind::figure, "1.17", "a body on a spring", {{"render", "spring", "--at", "2", "-o", "figure_1_17.png"}}},
    {ItemKind::figure,
     "1.18",
     "spring, dashpot and force",
     {{"render", "spring_dashpot", "--set", "b=0.3", "--set", "F=0.5*cos(t)", "--at", "6", "-o", "figure_1_18.png"}}},
    {ItemKind::figure,
     "1.19",
     "the sliding box",
     {{"render", "sliding_box", "--set", "mu=0.2", "--at", "5", "-o", "figure_1_19.png"}}},
    {ItemKind::figure,
     "1.20",
     "the pendulum",
     {{"render", "--layout", "fbd", "--at", "2", "-o", "figure_1_20.png"},
      {"render", "--layout", "fbd", "--size", "640x360", "-o", "figure_1_20.mp4"}},
     "Exercise 1.25's solution code draws the drag D with the wrong sign: D = -alpha |omega| omega along i_theta "
     "opposes the motion."},
    {ItemKind::figure,
     "1.21",
     "the pendulum's forces and geometry",
     {{"render", "pendulum", "--layout", "fbd", "--annotate", "geometry", "--at", "1", "-o", "figure_1_21.png"}},
     kPendulumNote},
    {ItemKind::figure,
     "1.22",
     "a wheel on a bumpy road",
     {{"render", "bumpy_road", "--set", "speed=20", "--at", "2", "-o", "figure_1_22.png"}}},
    {ItemKind::exercise,
     "1.1",
     "linear and quadratic u_e solve the discrete equations exactly (f fitted)",
     {{"solve", "vibration", "--set", "k=4", "--set", "F=2*0.3+4*(0.3*t^2+0.5*t+1)", "--set", "V=0.5", "--set",
       "dt=0.1", "--set", "T=1"}}},
    {ItemKind::exercise,
     "1.2",
     "the phase error grows linearly with the number of periods",
     {{"analyze", "empirical", "undamped", "--set", "steps_per_period=20", "--set", "periods=40", "--csv"}}},
    {ItemKind::exercise,
     "1.3",
     "the adjusted frequency w(1 - w²dt²/24) gives 4th order; dt = 0.1 over 80 periods",
     {{"analyze", "convergence", "undamped", "--compare", "scheme=centered,centered-adjusted", "--levels", "5"},
      {"plot", "undamped", "--compare", "scheme=centered,centered-adjusted", "--set", "dt=0.1", "--set", "periods=80",
       "--panels", "u", "-o", "exercise_1_3.png"}}},
    {ItemKind::exercise,
     "1.4",
     "does adaptivity (tolerance down to 1e-14) fix the phase error?",
     {{"plot", "undamped", "--compare", "scheme=centered,dopri5", "--set", "rtol=1e-14", "--set", "steps_per_period=20",
       "--set", "periods=40", "--panels", "u", "-o", "exercise_1_4.png"}}},
    {ItemKind::exercise,
     "1.5",
     "a Taylor polynomial for u¹ with V ≠ 0",
     {{"solve", "undamped", "--set", "V=1", "--set", "dt=0.1", "--set", "T=0.1"}}},
    {ItemKind::exercise,
     "1.6",
     "velocity Verlet and its rate",
     {{"analyze", "convergence", "undamped", "--set", "scheme=velocity-verlet", "--levels", "5"}}},
    {ItemKind::exercise,
     "1.7",
     "why w dt > pi makes no sense",
     {{"analyze", "frequency", "--w", "1"},
      {"solve", "undamped", "--set", "dt=0.3184", "--set", "T=5", "--allow-unstable", "--every", "4"}}},
    {ItemKind::exercise,
     "1.8",
     "E(p) = [DtDt cos]/u'' = 4 sin²(p/2)/p² and its Taylor polynomial",
     {{"analyze", "fd-accuracy", "-o", "exercise_1_8.png"}}},
    {ItemKind::exercise,
     "1.9",
     "the energy error's convergence rate",
     {{"analyze", "energy", "--schemes", "euler-cromer,crank-nicolson,rk4", "--T", "10", "--dt", "0.05,0.025,0.0125",
       "--rates"}},
     "The book's energy table divides by e_E^0, which is zero: the errors are divided by E(0). For Crank-Nicolson at "
     "dt = 0.0125 it prints 3.125e-3; the analytic value, which vibra gets, is 3.077e-3 (1 - sin^2(w~ dt)/(w dt)^2)."},
    {ItemKind::exercise,
     "1.10",
     "exact linear and quadratic solutions with damping",
     {{"solve", "vibration", "--set", "damping=quadratic", "--set", "b=0.4", "--set", "k=2", "--set", "V=-0.8", "--set",
       "I=0.3", "--set", "F=0.4*0.8*(-0.8)+2*(-0.8*t+0.3)", "--set", "dt=0.13", "--set", "T=1"}}},
    {ItemKind::exercise,
     "1.11",
     "test against the exact discrete solution I cos(w~ t_n)",
     {{"analyze", "frequency", "--w", "6.283185307179586", "--steps-per-period", "10,20"}}},
    {ItemKind::exercise,
     "1.12",
     "forced undamped spring A sin(phi t): exact solution, rate 2",
     {{"analyze", "convergence", "vibration", "--set", "k=4", "--set", "F=sin(3*t)", "--levels", "5"}}},
    {ItemKind::exercise,
     "1.13",
     "amplitude errors of RK3, RK4, CN, AB2, AB3, Backward2Step",
     {{"analyze", "amplitude", "--schemes", "rk3,rk4,crank-nicolson,ab2,ab3,backward2step", "--dt", "0.05", "--periods",
       "20", "-o", "exercise_1_13.png"}}},
    {ItemKind::exercise,
     "1.14",
     "a solver keeping three time levels, writing to file",
     {{"solve", "undamped", "--set", "periods=1000", "-o", "long.csv"}}},
    {ItemKind::exercise,
     "1.15",
     "the same for the general model; line-by-line plotting",
     {{"ascii", "vibration", "--set", "b=0.1", "--set", "periods=2", "--width", "50"}}},
    {ItemKind::exercise,
     "1.16",
     "Euler-Cromer for the general model: rate 1; against centered at dt = 0.9·2/w",
     {{"plot",      "vibration",
       "--set",     "m=4",
       "--set",     "damping=quadratic",
       "--set",     "b=0.2",
       "--set",     "s=2*u",
       "--set",     "dt=0.9*2/sqrt(0.5)",
       "--set",     "periods=6",
       "--compare", "scheme=centered,euler-cromer",
       "--panels",  "u",
       "-o",        "exercise_1_16.png"},
      {"analyze", "convergence", "vibration", "--set", "b=0.5", "--set", "k=4", "--set", "scheme=euler-cromer"}}},
    {ItemKind::exercise,
     "1.17",
     "DtDt as a forward-backward difference",
     {{"solve", "undamped", "--set", "scheme=euler-cromer-half", "--set", "dt=0.1", "--set", "T=0.3"}},
     "The book claims that fixing Euler-Cromer's first step keeps its rate at 1: with the half-step start v^{1/2} = V "
     "+ 0.5 dt a(I, V, 0) it is the centered scheme, rate 2 without damping."},
    {ItemKind::exercise,
     "1.18",
     "Euler-Cromer's exact discrete solution, equivalence with centered",
     {{"solve", "undamped", "--set", "scheme=staggered", "--set", "dt=0.1", "--set", "T=0.3"}}},
    {ItemKind::exercise,
     "1.19",
     "the solver as classes",
     {},
     "A design exercise: each scheme is a stepper class in src/core/schemes/ (docs/architecture.md); no command."},
    {ItemKind::exercise,
     "1.20",
     "a backward difference for damping: accuracy lost",
     {{"analyze", "convergence", "vibration", "--set", "b=0.5", "--set", "k=4", "--set", "scheme=backward-damping"}}},
    {ItemKind::exercise,
     "1.21",
     "forward-backward with quadratic damping equals the staggered scheme",
     {{"solve", "vibration", "--set", "damping=quadratic", "--set", "b=0.3", "--set", "scheme=staggered", "--set",
       "T=1"}},
     kStaggeredNote},
    {ItemKind::exercise,
     "1.22",
     "resonance: gamma = 5, 1.5, 1.1, 1 for three beta",
     {{"analyze", "resonance", "--beta", "0.005,0.05,0.2", "--gamma", "5,1.5,1.1,1", "--csv"}}},
    {ItemKind::exercise,
     "1.23",
     "sliding box with Coulomb friction: g(u), scaling, simulation",
     {{"plot", "sliding-box", "--compare", "alpha=0,1,2,4", "--panels", "friction,u", "-o", "springs.png"},
      {"solve", "sliding-box", "--set", "mu=0.2", "--set", "alpha=1", "--every", "20"}}},
    {ItemKind::exercise,
     "1.24",
     "bouncing ball: h(t), v(t)",
     {{"plot", "bouncing-ball", "--panels", "h,v", "--set", "periods=3", "-o", "exercise_1_24.png"},
      {"analyze", "bounces", "--set", "C_R=0.5", "--csv"}}},
    {ItemKind::exercise,
     "1.25",
     "pendulum theta, S, D; small Theta against the linear solution; Theta = 40°, alpha = 0.8",
     {{"plot", "pendulum", "--set", "Theta=40", "--set", "alpha=0.8", "-o", "exercise_1_25.png"},
      {"plot", "pendulum", "--set", "alpha=0", "--set", "Theta=5", "--panels", "theta,exact", "-o", "small_angle.png"}},
     "The book's solution code gives the drag D the wrong sign: D = -alpha |omega| omega along i_theta = (cos theta, "
     "sin theta) opposes the motion. And (1.124): S = m g cos(theta) + m L theta'^2."},
    {ItemKind::exercise,
     "1.26",
     "elastic pendulum: rest, vertical oscillation, demo",
     {{"solve", "elastic-pendulum", "--set", "Theta=0", "--set", "eps=0", "--set", "periods=1", "--every", "20"},
      {"plot", "elastic-pendulum", "--set", "Theta=0", "--set", "eps=0.1", "--panels", "y", "-o", "vertical.png"}},
     "The vertical case starts at (0, -eps), so y = -eps cos(sqrt(beta/(1 - beta)) t), not +eps."},
    {ItemKind::exercise,
     "1.27",
     "elastic pendulum with air drag",
     {{"plot", "elastic-pendulum", "--set", "Theta=40", "--set", "gamma=0.05", "-o", "drag.png"}},
     "The book's gamma lacks the factor pi: with A = pi R^2, gamma = L0 rho C_D pi R^2 / (2 m)."},
    {ItemKind::exercise,
     "1.28",
     "PEFRL; the orbit; Euler-Cromer, RK4, PEFRL errors; a billion orbits?",
     {{"analyze", "orbit", "--scheme", "euler-cromer", "--orbits", "10"},
      {"analyze", "orbit", "--scheme", "rk4", "--orbits", "10"},
      {"analyze", "orbit", "--scheme", "pefrl", "--orbits", "10"}}},
};
}  // namespace

const std::vector<ChapterItem>& chapter_items() { return kItems; }

std::string item_key(const ChapterItem& item) { return (item.kind == ItemKind::figure ? "fig" : "ex") + item.number; }

std::string item_name(const ChapterItem& item) {
  return (item.kind == ItemKind::figure ? "Figure " : "Exercise ") + item.number;
}

namespace {
/// The items one word of --only names: a number names a figure and an exercise.
std::vector<const ChapterItem*> items_named(const std::string& word) {
  std::vector<const ChapterItem*> found;
  for (const ChapterItem& item : kItems)
    if (word == item.number || word == item_key(item)) found.push_back(&item);
  if (found.empty())
    throw UsageError("--only " + word +
                     " names no figure or exercise: give numbers 1.1 to 1.28, or fig1.N / ex1.N, "
                     "comma-separated, e.g. --only 1.12,fig1.21");
  return found;
}
}  // namespace

std::vector<const ChapterItem*> select_items(const std::string& only) {
  std::vector<const ChapterItem*> chosen;
  if (only.empty()) {
    for (const ChapterItem& item : kItems) chosen.push_back(&item);
    return chosen;
  }
  std::vector<bool> wanted(kItems.size(), false);
  size_t start = 0;
  for (size_t words = 0; start <= only.size() && words < kItems.size() * 4; ++words) {
    throw_if_stop_requested();
    const size_t comma = std::min(only.find(',', start), only.size());
    for (const ChapterItem* item : items_named(only.substr(start, comma - start))) wanted[item - kItems.data()] = true;
    start = comma + 1;
  }
  if (start <= only.size()) throw UsageError("--only lists more items than the chapter has: name each once");
  for (size_t i = 0; i < kItems.size(); ++i)
    if (wanted[i]) chosen.push_back(&kItems[i]);
  return chosen;
}

std::string command_output(const std::vector<std::string>& args) {
  for (size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "-o" || args[i] == "--output") return args[i + 1];
  return "";
}

}  // namespace vibra::cli
