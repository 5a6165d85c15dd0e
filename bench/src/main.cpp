// cable_bench: time one RK4 step of the same chain in cable_dynamics and in multibody engines.
// See bench/README.md for what is measured and how to read the tables.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "chain_spec.h"
#include "project_system.h"

namespace bench {

std::vector<Engine> engines() {
  std::vector<Engine> list;
#ifdef BENCH_HAVE_MUJOCO
  list.push_back({"MuJoCo", "ball joints (quaternions); MuJoCo's own RK4 (option integrator=\"RK4\", mj_step)", &makeMujoco});
#endif
#ifdef BENCH_HAVE_DART
  list.push_back({"DART",
                  "BallJoint (exp. coordinates); Skeleton::computeForwardDynamics() (ABA) in a hand-written RK4,\n"
                  "           positions moved by DART's Skeleton::integratePositions() from the step's start",
                  &makeDart});
#endif
#ifdef BENCH_HAVE_SIMBODY
  list.push_back({"Simbody",
                  "MobilizedBody::Ball (quaternions); realize(Stage::Acceleration) in a hand-written RK4,\n"
                  "           qdot = N(q) u from Simbody, quaternions renormalized once per step",
                  &makeSimbody});
#endif
#ifdef BENCH_HAVE_KDL
  list.push_back({"KDL", "3 revolute joints per link (X, Y, Z); ChainFdSolver_RNE in a hand-written RK4", &makeKdl});
#endif
  return list;
}

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kDriftTolerance = 1e-3;     ///< |E_end - E_start| / releasable energy
constexpr double kMismatchTolerance = 1e-4;  ///< derivative() of a second formulation vs the first

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

struct Options {
  std::vector<int> sizes{10, 30, 100, 300, 1000};
  int repetitions = 3;
  double target = 0.3;   ///< wall time to fill per repetition [s]
  double budget = 20.0;  ///< most wall time one cell (warm-up + all repetitions) may take [s]
  double build_budget = 60.0;  ///< most wall time building one engine's model may take [s]
  int agreement_steps = 500;
  std::vector<std::string> only;  ///< restrict to these columns (debugging)
};

/// One timed thing: a system's step(), or the project's derivative().
struct Column {
  std::string name;
  bool is_project = false;     ///< cable_dynamics' step (the denominator of the ratios)
  bool is_derivative = false;  ///< ChainDynamics::derivative() rather than a step
  std::string formulation;     ///< the project's columns: "paper" or "recursive"
  const Engine* engine = nullptr;
};

/// What one column measured at one n.
struct Cell {
  bool skipped = true;
  bool over_budget = false;    ///< skipped for time: larger n are skipped too
  bool healthy = true;         ///< no failed step, no engine warning during the timed steps
  std::string why;             ///< reason of a skip or a failure
  long ops = 0;                ///< steps (or derivative calls) per repetition
  std::vector<double> per_op;  ///< seconds per op, one per repetition
  double drift = 0.0;          ///< largest |E_end - E_start| / releasable energy over the repetitions
  double duration = 0.0;       ///< simulated time per repetition [s]
  bool failed_check = false;    ///< the model failed the correctness check: its time is not shown
  double median() const {
    std::vector<double> v = per_op;
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
  }
  double spread() const {  // (max - min) / median
    const auto [lo, hi] = std::minmax_element(per_op.begin(), per_op.end());
    return (*hi - *lo) / median();
  }
};

std::string formatNs(double s) {
  const long long ns = std::llround(s * 1e9);
  const std::string digits = std::to_string(ns);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string fixed(double v, int precision) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", precision, v);
  return buffer;
}

std::string scientific(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.1e", v);
  return buffer;
}

void printRow(const std::string& first, const std::vector<std::string>& cells, int first_width, int width) {
  std::printf("%-*s", first_width, first.c_str());
  for (const auto& c : cells) std::printf(" %*s", width, c.c_str());
  std::printf("\n");
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) items.push_back(item);
  return items;
}

Options parseOptions(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&](const char* key) -> const char* {
      const std::string prefix = std::string(key) + "=";
      return a.rfind(prefix, 0) == 0 ? argv[i] + prefix.size() : nullptr;
    };
    if (const char* v = value("--sizes")) {
      o.sizes.clear();
      for (const auto& s : split(v)) o.sizes.push_back(std::stoi(s));
    } else if (const char* v = value("--reps")) {
      o.repetitions = std::max(1, std::atoi(v));
    } else if (const char* v = value("--target")) {
      o.target = std::atof(v);
    } else if (const char* v = value("--budget")) {
      o.budget = std::atof(v);
    } else if (const char* v = value("--build-budget")) {
      o.build_budget = std::atof(v);
    } else if (const char* v = value("--agreement-steps")) {
      o.agreement_steps = std::atoi(v);
    } else if (const char* v = value("--only")) {
      o.only = split(v);
    } else {
      std::cerr << "usage: cable_bench [--sizes=10,30,100,300,1000] [--reps=3] [--target=0.3] [--budget=20]\n"
                   "                   [--build-budget=60] [--agreement-steps=500] [--only=COLUMN,...]\n";
      std::exit(a == "--help" || a == "-h" ? 0 : 2);
    }
  }
  return o;
}

std::string firstLine(const char* path, const char* prefix) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) {
      const std::size_t colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  }
  return "?";
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

/// Time per op predicted at n from the sizes measured before: the last time, scaled by the exponent
/// measured between the last two sizes (clamped to [1, 3]; 3, the worst here, after a single size).
/// Returns 0 when nothing was measured yet.
double predict(const std::map<int, double>& measured, int n) {
  if (measured.empty()) return 0.0;
  const auto last = std::prev(measured.end());
  double exponent = 3.0;
  if (measured.size() >= 2) {
    const auto before = std::prev(last);
    exponent = std::log(last->second / before->second) / std::log(static_cast<double>(last->first) / before->first);
    exponent = std::min(3.0, std::max(1.0, exponent));
  }
  return last->second * std::pow(static_cast<double>(n) / last->first, exponent);
}

}  // namespace
}  // namespace bench

int main(int argc, char** argv) {
  using namespace bench;
  const Options options = parseOptions(argc, argv);
  const Clock::time_point run_start = Clock::now();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const int reps = options.repetitions;

  // --- the columns ---------------------------------------------------------------------------------
  const std::vector<std::string> formulations = projectFormulations();
  const std::vector<Engine> engine_list = engines();
  const auto projectName = [](const std::string& f) { return "cd:" + f; };
  std::vector<Column> all_columns;
  for (const auto& f : formulations) all_columns.push_back({projectName(f), true, false, f, nullptr});
  for (const auto& e : engine_list) all_columns.push_back({e.name, false, false, "", &e});
  for (const auto& f : formulations) all_columns.push_back({"deriv " + projectName(f), false, true, f, nullptr});
  std::vector<Column> columns;
  for (const auto& c : all_columns) {
    if (options.only.empty() || std::find(options.only.begin(), options.only.end(), c.name) != options.only.end() ||
        c.is_project) {
      columns.push_back(c);
    }
  }

  std::printf("cable_dynamics speed benchmark: one RK4 step (dt = 1 ms, 4 forward-dynamics evaluations) of the same\n"
              "chain of n rigid links (3 rotational DOF each, fixed base, gravity, 10 kg load folded into the last\n"
              "link, in air, no springs, no contacts) in every system. Wall time, one thread, %d repetitions\n"
              "interleaved, median. CPU: %s; load average at start: %s\n",
              reps, firstLine("/proc/cpuinfo", "model name").c_str(), loadAverage().c_str());
  std::printf("cable_dynamics: %s\n",
              "simulation.formulation=paper and =recursive side by side: CableSimulator::step(), RK4");
  for (const auto& e : engine_list) std::printf("  %-8s %s\n", e.name.c_str(), e.how.c_str());
  std::printf("Per cell: >= %.2f s of timed steps per repetition; warm-up + %d repetitions <= %.0f s, else '-'.\n\n",
              options.target, reps, options.budget);

  std::map<int, std::vector<Cell>> results;  // results[n][column]
  std::vector<std::map<int, double>> measured(columns.size());  // median seconds per op, by n
  std::vector<std::map<int, double>> build_time(columns.size());  // seconds to build the model, by n
  std::vector<std::string> notes;
  std::vector<std::pair<std::string, double>> agreement;  // system, tip distance to the reference [m]
  std::map<int, std::map<std::string, double>> formulation_mismatch;  // n -> formulation -> relative x' difference
  int agreement_n = 0;
  int previous_n = 0;

  for (const int n : options.sizes) {
    const Clock::time_point size_start = Clock::now();
    std::vector<Cell>& cells = results[n];
    cells.assign(columns.size(), Cell());
    // The project's systems first: the spec (link properties, initial axes) comes from them.
    std::map<std::string, std::unique_ptr<ProjectSystem>> project;
    for (const auto& f : formulations) project[f] = std::make_unique<ProjectSystem>(n, f);
    const ProjectSystem& reference = *project[formulations.front()];
    const ChainSpec spec = makeSpec(reference.params(), reference.initialAxes());
    const double releasable = spec.releasableEnergy();

    std::vector<std::unique_ptr<System>> owned(columns.size());
    std::vector<System*> systems(columns.size(), nullptr);
    std::vector<std::function<void()>> ops(columns.size());

    // Per column: skip by the budget, build (engines only when not skipped; not timed), warm up and
    // measure a few ops, then choose the ops per repetition: >= target seconds each, and the whole
    // cell (warm-up + all repetitions) within the budget.
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const Column& col = columns[c];
      Cell& cell = cells[c];
      const std::string op = col.is_derivative ? "call" : "step";
      if (previous_n > 0 && results[previous_n][c].over_budget) {
        cell.over_budget = true;
        cell.why = "over the cell budget at n = " + std::to_string(previous_n) + " already";
        continue;
      }
      const double predicted = predict(measured[c], n);
      if ((reps + 1) * predicted > 1.5 * options.budget) {
        cell.over_budget = true;
        cell.why = "one " + op + " predicted at " + fixed(predicted, 1) + " s from the smaller sizes: warm-up + " +
                   std::to_string(reps) + " repetitions exceed the " + fixed(options.budget, 0) +
                   " s cell budget (not built, not probed)";
        continue;
      }
      const double predicted_build = predict(build_time[c], n);
      if (predicted_build > options.build_budget) {
        cell.over_budget = true;
        cell.why = "building the model predicted at " + fixed(predicted_build, 0) + " s from the smaller sizes, over the " +
                   fixed(options.build_budget, 0) + " s build budget (not built)";
        continue;
      }
      try {
        const Clock::time_point t0 = Clock::now();
        if (col.engine) {
          owned[c] = col.engine->make(spec);
          systems[c] = owned[c].get();
        } else {
          systems[c] = project[col.formulation].get();
        }
        if (col.is_derivative) {
          ProjectSystem* p = project[col.formulation].get();
          ops[c] = [p] { p->derivative(); };
        } else {
          System* s = systems[c];
          ops[c] = [s] { s->step(); };
        }
        const double built = seconds(t0, Clock::now());
        if (col.engine) build_time[c][n] = std::max(built, 1e-3);
        systems[c]->reset();
        long batch = 1;
        double per_op = 0.0, spent = 0.0;
        for (;;) {
          const Clock::time_point t1 = Clock::now();
          for (long i = 0; i < batch; ++i) ops[c]();
          const double t = seconds(t1, Clock::now());
          spent += t;
          per_op = t / batch;
          if (spent >= 0.05 || per_op * batch * 2 > options.budget / (reps + 1)) break;
          batch *= 2;
        }
        std::fprintf(stderr, "[bench] n = %d: %-18s built in %.1f s, warm-up %.3g s per %s\n", n, col.name.c_str(), built,
                     per_op, op.c_str());
        if ((reps + 1) * per_op > options.budget) {
          cell.over_budget = true;
          cell.why = "one " + op + " took " + fixed(per_op, 2) + " s: warm-up + " + std::to_string(reps) +
                     " repetitions exceed the " + fixed(options.budget, 0) + " s cell budget";
          continue;
        }
        const long wanted = static_cast<long>(std::ceil(options.target / per_op));
        const long allowed = static_cast<long>(std::floor((options.budget - spent) / (reps * per_op)));
        cell.ops = std::max(1L, std::min(wanted, allowed));
        cell.skipped = false;
      } catch (const std::exception& e) {
        cell.why = std::string("failed: ") + e.what();
      }
    }

    // Timed repetitions, the columns interleaved (the starting column rotates every repetition).
    for (int rep = 0; rep < reps; ++rep) {
      for (std::size_t i = 0; i < columns.size(); ++i) {
        const std::size_t c = (i + rep) % columns.size();
        Cell& cell = cells[c];
        if (cell.skipped) continue;
        try {
          System& s = *systems[c];
          s.reset();
          const double e0 = columns[c].is_derivative ? 0.0 : s.energy();
          const Clock::time_point t0 = Clock::now();
          for (long k = 0; k < cell.ops; ++k) ops[c]();
          const double t = seconds(t0, Clock::now());
          cell.per_op.push_back(t / cell.ops);
          if (!columns[c].is_derivative) {
            cell.healthy = cell.healthy && s.healthy();
            const double e1 = s.energy();
            cell.drift = std::max(cell.drift, std::abs(e1 - e0) / releasable);
            cell.duration = cell.ops * spec.dt;
          }
        } catch (const std::exception& e) {
          cell.skipped = true;
          cell.why = std::string("failed: ") + e.what();
        }
      }
    }
    // Two formulations: the same x' at the initial state? (Relative to the first formulation's largest
    // entry; the tolerance leaves room for the round-off of the O(n^3) Cholesky on an ill-conditioned
    // mass matrix. A mismatch beyond it disqualifies the other formulation at this n.)
    for (std::size_t f = 1; f < formulations.size(); ++f) {
      Eigen::VectorXd reference_rate, rate;
      double mismatch = std::numeric_limits<double>::infinity();
      if (project[formulations[0]]->derivativeAtStart(reference_rate) && project[formulations[f]]->derivativeAtStart(rate)) {
        mismatch = (rate - reference_rate).cwiseAbs().maxCoeff() / reference_rate.cwiseAbs().maxCoeff();
      }
      formulation_mismatch[n][formulations[f]] = mismatch;
      if (!(mismatch <= kMismatchTolerance)) {
        for (std::size_t c = 0; c < columns.size(); ++c) {
          if (columns[c].formulation == formulations[f] && !cells[c].skipped) cells[c].failed_check = true;
        }
      }
    }
    // A step that failed, or energy that drifted, disqualifies the system at this n: and with the
    // project, its derivative() column too (it times a function that computes something wrong).
    for (std::size_t c = 0; c < columns.size(); ++c) {
      Cell& cell = cells[c];
      if (cell.skipped || columns[c].is_derivative) continue;
      cell.failed_check = cell.failed_check || !cell.healthy || !(cell.drift < kDriftTolerance);
      if (cell.failed_check && columns[c].is_project) {
        for (std::size_t d = 0; d < columns.size(); ++d)
          if (columns[d].is_derivative && columns[d].formulation == columns[c].formulation) cells[d].failed_check = true;
      }
    }
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const Cell& cell = cells[c];
      if (!cell.skipped) measured[c][n] = cell.median();
      const std::string where = columns[c].name + " n=" + std::to_string(n) + ": ";
      if (!cell.why.empty()) notes.push_back(where + cell.why);
      if (systems[c] && !columns[c].is_derivative && !systems[c]->note().empty()) {
        notes.push_back(where + systems[c]->note());
      }
    }
    previous_n = n;

    // Light cross-check at the smallest size: the same motion in every system (tip after a fixed time).
    if (agreement_n == 0 && options.agreement_steps > 0 && systems[0]) {
      agreement_n = n;
      System& ref = *systems[0];
      ref.reset();
      for (int k = 0; k < options.agreement_steps; ++k) ref.step();
      const Eigen::Vector3d ref_tip = ref.tip();
      for (std::size_t c = 1; c < columns.size(); ++c) {
        if (!systems[c] || columns[c].is_derivative) continue;
        try {
          systems[c]->reset();
          for (int k = 0; k < options.agreement_steps; ++k) systems[c]->step();
          agreement.emplace_back(columns[c].name, (systems[c]->tip() - ref_tip).norm());
        } catch (const std::exception& e) {
          notes.push_back(columns[c].name + ": agreement run failed: " + e.what());
        }
      }
    }
    std::fprintf(stderr, "[bench] n = %d done in %.1f s\n", n, seconds(size_start, Clock::now()));
  }

  // --- tables ---------------------------------------------------------------------------------------
  const int w = 15;
  std::vector<std::string> header;
  for (const auto& c : columns) header.push_back(c.name);

  std::printf("1) Wall time per step [ns], median of %d; 'deriv' columns: one ChainDynamics::derivative() call.\n"
              "   '-': not run (budget, see the notes); 'failed': the model failed the correctness check (4)\n", reps);
  printRow("n", header, 6, w);
  for (const int n : options.sizes) {
    std::vector<std::string> row;
    for (const Cell& cell : results[n]) {
      row.push_back(cell.skipped ? "-" : cell.failed_check ? "failed" : formatNs(cell.median()));
    }
    printRow(std::to_string(n), row, 6, w);
  }

  std::printf("\n2) Ratio engine time / cable_dynamics time per step (> 1: cable_dynamics is faster)\n");
  std::vector<std::string> ratio_header;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (engine column, project column)
  for (std::size_t p = 0; p < columns.size(); ++p) {
    if (!columns[p].is_project) continue;
    for (std::size_t e = 0; e < columns.size(); ++e) {
      if (!columns[e].engine) continue;
      pairs.emplace_back(e, p);
      ratio_header.push_back(formulations.size() == 1 ? columns[e].name : columns[e].name + "/" + columns[p].formulation);
    }
  }
  printRow("n", ratio_header, 6, w);
  for (const int n : options.sizes) {
    std::vector<std::string> row;
    for (const auto& [e, p] : pairs) {
      const Cell &ce = results[n][e], &cp = results[n][p];
      row.push_back(ce.skipped || cp.skipped                ? "-"
                    : ce.failed_check || cp.failed_check ? "failed"
                                                         : fixed(ce.median() / cp.median(), 3));
    }
    printRow(std::to_string(n), row, 6, w);
  }

  std::printf("\n3) cable_dynamics: step time / derivative() time (4 calls per step, plus the step's own checks)\n");
  for (std::size_t p = 0; p < columns.size(); ++p) {
    if (!columns[p].is_project) continue;
    std::size_t d = p;
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c].is_derivative && columns[c].formulation == columns[p].formulation) d = c;
    std::printf("  %-13s", columns[p].name.c_str());
    for (const int n : options.sizes) {
      const Cell &cs = results[n][p], &cd = results[n][d];
      std::printf("  n=%d: %s", n,
                  cs.skipped || cd.skipped || d == p      ? "-"
                  : cs.failed_check || cd.failed_check ? "failed"
                                                       : fixed(cs.median() / cd.median(), 2).c_str());
    }
    std::printf("\n");
    for (const std::size_t c : {p, d}) {
      if (c == d && d == p) continue;
      const auto usable = [&](int n) { return results.count(n) && !results[n][c].skipped && !results[n][c].failed_check; };
      const bool both = usable(100) && usable(1000);
      std::printf("  %-13s  %s time(n=1000) / time(n=100) = %s\n", "", c == p ? "step:        " : "derivative():",
                  both ? fixed(results[1000][c].median() / results[100][c].median(), 1).c_str() : "- (not both measured)");
    }
  }
  std::printf("  (time(n=1000) / time(n=100) is 10 for O(n), 100 for O(n^2), 1000 for O(n^3))\n");

  std::printf("\n4) Correctness: largest |E_end - E_start| / releasable energy over the repetitions (must be < 1e-3;\n"
              "   releasable energy = E(start) - E(hanging at rest)); below: simulated time per repetition /\n"
              "   spread of the step time over the repetitions, (max - min) / median\n");
  std::vector<std::string> check_header;
  std::vector<std::size_t> check_columns;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].is_derivative) continue;
    check_columns.push_back(c);
    check_header.push_back(columns[c].name);
  }
  printRow("n", check_header, 6, 20);
  bool all_ok = true;
  for (const int n : options.sizes) {
    std::vector<std::string> row;
    for (const std::size_t c : check_columns) {
      const Cell& cell = results[n][c];
      if (cell.skipped) {
        row.push_back("-");
        continue;
      }
      const bool ok = cell.drift < kDriftTolerance && cell.healthy;
      all_ok = all_ok && ok;
      row.push_back(scientific(cell.drift) + (!cell.healthy ? " FAILED" : ok ? " ok" : " BAD"));
    }
    printRow(std::to_string(n), row, 6, 20);
    row.clear();
    for (const std::size_t c : check_columns) {
      const Cell& cell = results[n][c];
      row.push_back(cell.skipped ? "" : fixed(cell.duration, 3) + " s / " + fixed(100.0 * cell.spread(), 0) + "%");
    }
    printRow("", row, 6, 20);
  }
  for (std::size_t f = 1; f < formulations.size(); ++f) {
    std::printf("\n   derivative() at the initial state, %s vs %s: max |difference| / max |%s's| (must be <= 1e-4)\n  ",
                projectName(formulations[f]).c_str(), projectName(formulations[0]).c_str(), projectName(formulations[0]).c_str());
    for (const int n : options.sizes) {
      const double m = formulation_mismatch[n][formulations[f]];
      std::printf("   n=%d: %s%s", n, std::isfinite(m) ? scientific(m).c_str() : "derivative() failed",
                  m <= kMismatchTolerance ? " ok" : " BAD");
      all_ok = all_ok && m <= kMismatchTolerance;
    }
    std::printf("\n");
  }
  if (!agreement.empty()) {
    std::printf("\n   Same motion: tip position after %d steps (%.3g s) at n = %d, distance to %s's [m]:\n",
                options.agreement_steps, options.agreement_steps * 1e-3, agreement_n, columns[0].name.c_str());
    for (const auto& [name, d] : agreement) std::printf("     %-14s %.2e\n", name.c_str(), d);
  }
  std::printf("\nNotes:\n");
  if (notes.empty()) std::printf("  (none)\n");
  for (const auto& note : notes) std::printf("  %s\n", note.c_str());
  std::printf("\nCorrectness checks: %s. Load average at the end: %s. Benchmark wall time: %.0f s.\n",
              all_ok ? "all passed" : "SOME FAILED (see 4)", loadAverage().c_str(), seconds(run_start, Clock::now()));
  return all_ok ? 0 : 1;
}
