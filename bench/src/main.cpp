// cable_bench: time one RK4 step of the same chain in cable_dynamics and in multibody engines.
// See bench/README.md for what is measured and how to read the tables.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
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
  list.push_back({"MuJoCo", "ball joints (quaternions), MuJoCo's own RK4 (integrator=\"RK4\")", &makeMujoco});
#endif
#ifdef BENCH_HAVE_DART
  list.push_back({"DART", "BallJoint, computeForwardDynamics() in a hand-written RK4, positions by DART's integratePositions()",
                  &makeDart});
#endif
#ifdef BENCH_HAVE_SIMBODY
  list.push_back({"Simbody", "Ball mobilizers (quaternions), realize(Acceleration) in a hand-written RK4, qdot = N(q)u",
                  &makeSimbody});
#endif
#ifdef BENCH_HAVE_KDL
  list.push_back({"KDL", "3 revolute joints per link (X-Y-Z), ChainFdSolver_RNE in a hand-written RK4", &makeKdl});
#endif
  return list;
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

struct Options {
  std::vector<int> sizes{10, 30, 100, 300, 1000};
  int repetitions = 3;
  double target = 0.3;   ///< wall time to fill per cell [s]
  double budget = 20.0;  ///< most wall time one cell may take [s]
  int agreement_steps = 500;
};

/// One timed thing: a system's step(), or the project's derivative().
struct Column {
  std::string name;
  bool is_project = false;      ///< cable_dynamics' step (the denominator of the ratios)
  bool is_derivative = false;   ///< ChainDynamics::derivative() rather than a step
  std::string formulation;      ///< for the project's columns
};

/// What one column measured at one n.
struct Cell {
  bool skipped = true;
  bool over_budget = false;     ///< skipped for time: larger n are skipped too
  std::string why;              ///< reason of a skip or a failure
  long ops = 0;                 ///< steps (or derivative calls) per repetition
  std::vector<double> per_op;   ///< seconds per op, one per repetition
  double drift = 0.0;           ///< largest |E_end - E_start| / releasable energy over the repetitions
  double duration = 0.0;        ///< simulated time per repetition [s]
  std::string note;
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
  std::string digits = std::to_string(ns), out;
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

std::vector<int> parseSizes(const std::string& text) {
  std::vector<int> sizes;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) sizes.push_back(std::stoi(item));
  return sizes;
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
      o.sizes = parseSizes(v);
    } else if (const char* v = value("--reps")) {
      o.repetitions = std::max(1, std::atoi(v));
    } else if (const char* v = value("--target")) {
      o.target = std::atof(v);
    } else if (const char* v = value("--budget")) {
      o.budget = std::atof(v);
    } else if (const char* v = value("--agreement-steps")) {
      o.agreement_steps = std::atoi(v);
    } else {
      std::cerr << "usage: cable_bench [--sizes=10,30,100,300,1000] [--reps=3] [--target=0.3] [--budget=20]"
                   " [--agreement-steps=500]\n";
      std::exit(a == "--help" || a == "-h" ? 0 : 2);
    }
  }
  return o;
}

}  // namespace
}  // namespace bench

int main(int argc, char** argv) {
  using namespace bench;
  const Options options = parseOptions(argc, argv);
  const Clock::time_point run_start = Clock::now();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  // --- the columns ---------------------------------------------------------------------------------
  const std::vector<std::string> formulations = projectFormulations();
  const std::vector<Engine> engine_list = engines();
  const auto projectName = [](const std::string& f) { return f.empty() ? std::string("cable_dyn") : "cd:" + f; };
  std::vector<Column> columns;
  for (const auto& f : formulations) columns.push_back({projectName(f), true, false, f});
  for (const auto& e : engine_list) columns.push_back({e.name, false, false, ""});
  for (const auto& f : formulations) columns.push_back({"deriv " + projectName(f), false, true, f});

  std::printf("cable_dynamics speed benchmark: one RK4 step (dt = 1 ms, 4 forward-dynamics evaluations) of the\n"
              "same chain of n rigid links (3 rotational DOF each, fixed base, gravity, 10 kg load folded into\n"
              "the last link, in air, no springs). Wall time, single thread; %d repetitions interleaved, median.\n",
              options.repetitions);
  std::printf("cable_dynamics formulations: %s\n",
              formulations.size() == 1 ? "one (no simulation.formulation key: the present paper formulation)"
                                       : "paper and recursive (simulation.formulation)");
  for (const auto& e : engine_list) std::printf("  %-8s %s\n", e.name.c_str(), e.how.c_str());
  std::printf("Cell: >= %.2f s of steps per repetition, at most %.0f s; '-' = skipped (see notes).\n\n",
              options.target, options.budget);

  // results[n][column]
  std::map<int, std::vector<Cell>> results;
  std::map<int, double> releasable;
  std::vector<std::string> notes;
  std::vector<std::pair<std::string, double>> agreement;  // engine, largest tip deviation [m]
  int agreement_n = 0;
  std::vector<double> previous_time(columns.size(), 0.0);
  int previous_n = 0;

  for (const int n : options.sizes) {
    const Clock::time_point size_start = Clock::now();
    std::vector<Cell>& cells = results[n];
    cells.assign(columns.size(), Cell());
    // Build every system (not timed). The spec comes from the project: link properties and initial axes.
    std::map<std::string, std::unique_ptr<ProjectSystem>> project;
    for (const auto& f : formulations) {
      const Clock::time_point t0 = Clock::now();
      project[f] = std::make_unique<ProjectSystem>(n, f);
      std::fprintf(stderr, "[bench] n = %d: %s built in %.1f s\n", n, projectName(f).c_str(), seconds(t0, Clock::now()));
    }
    const ProjectSystem& reference = *project[formulations.front()];
    const ChainSpec spec = makeSpec(reference.params(), reference.initialAxes());
    releasable[n] = spec.releasableEnergy();
    std::vector<std::unique_ptr<System>> engine_systems;
    std::vector<System*> systems(columns.size(), nullptr);
    std::vector<std::function<void()>> ops(columns.size());
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const Column& col = columns[c];
      if (col.is_project || col.is_derivative) {
        ProjectSystem* p = project[col.formulation].get();
        systems[c] = p;
        ops[c] = col.is_derivative ? std::function<void()>([p] { p->derivative(); })
                                   : std::function<void()>([p] { p->step(); });
        continue;
      }
      const Engine& engine = *std::find_if(engine_list.begin(), engine_list.end(),
                                           [&](const Engine& e) { return e.name == col.name; });
      try {
        const Clock::time_point t0 = Clock::now();
        engine_systems.push_back(engine.make(spec));
        std::fprintf(stderr, "[bench] n = %d: %s built in %.1f s\n", n, col.name.c_str(), seconds(t0, Clock::now()));
        System* s = engine_systems.back().get();
        systems[c] = s;
        ops[c] = [s] { s->step(); };
      } catch (const std::exception& e) {
        cells[c].why = std::string("could not build: ") + e.what();
      }
    }

    // Calibration: warm up and measure the time per op on a few ops, then choose the ops per
    // repetition: >= target seconds each, and the whole cell (warm-up + all repetitions) <= budget.
    const int reps = options.repetitions;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      Cell& cell = cells[c];
      if (!systems[c]) continue;
      const char* op = columns[c].is_derivative ? "call" : "step";
      if (previous_n > 0 && results[previous_n][c].over_budget) {
        cell.over_budget = true;
        cell.why = "over the cell budget at n = " + std::to_string(previous_n) + " already";
        continue;
      }
      // Not even probed when the cubic extrapolation of the time measured at the previous size (cubic:
      // the worst scaling of any system here) says that a single op would exceed the cell's budget.
      if (previous_n > 0 && previous_time[c] > 0.0) {
        const double predicted = previous_time[c] * std::pow(static_cast<double>(n) / previous_n, 3.0);
        if (predicted > options.budget) {
          cell.over_budget = true;
          cell.why = "one " + std::string(op) + " predicted at " + fixed(predicted, 0) + " s (cubic from " +
                     fixed(previous_time[c], 3) + " s at n = " + std::to_string(previous_n) + ") > the " +
                     fixed(options.budget, 0) + " s cell budget: not probed";
          continue;
        }
      }
      try {
        systems[c]->reset();
        long batch = 1;
        double per_op = 0.0, spent = 0.0;
        for (;;) {
          const Clock::time_point t0 = Clock::now();
          for (long i = 0; i < batch; ++i) ops[c]();
          const double t = seconds(t0, Clock::now());
          spent += t;
          per_op = t / batch;
          if (spent >= 0.05 || per_op * batch * 2 > options.budget / (reps + 1)) break;
          batch *= 2;
        }
        std::fprintf(stderr, "[bench] n = %d: %s probed, %.3g s per %s\n", n, columns[c].name.c_str(), per_op, op);
        if ((reps + 1) * per_op > options.budget) {
          cell.over_budget = true;
          cell.why = "one " + std::string(op) + " took " + fixed(per_op, 2) + " s: warm-up + " + std::to_string(reps) +
                     " repetitions of one " + op + " would exceed the " + fixed(options.budget, 0) + " s cell budget";
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
    for (int rep = 0; rep < options.repetitions; ++rep) {
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
            const double e1 = s.energy();
            cell.drift = std::max(cell.drift, std::abs(e1 - e0) / releasable[n]);
            cell.duration = cell.ops * spec.dt;
          }
        } catch (const std::exception& e) {
          cell.skipped = true;
          cell.why = std::string("failed: ") + e.what();
        }
      }
    }
    for (std::size_t c = 0; c < columns.size(); ++c) {
      Cell& cell = cells[c];
      previous_time[c] = cell.skipped ? 0.0 : cell.median();
      if (systems[c] && !columns[c].is_derivative) cell.note = systems[c]->note();
      if (!cell.why.empty()) notes.push_back(columns[c].name + " n=" + std::to_string(n) + ": " + cell.why);
      if (!cell.note.empty()) notes.push_back(columns[c].name + " n=" + std::to_string(n) + ": " + cell.note);
    }
    previous_n = n;

    // Light cross-check at the smallest size: the same motion in every system (tip after a fixed time).
    if (agreement_n == 0 && options.agreement_steps > 0) {
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

  std::printf("1) Wall time per step [ns] (median of %d); last column(s): one ChainDynamics::derivative() call\n",
              options.repetitions);
  printRow("n", header, 6, w);
  for (const int n : options.sizes) {
    std::vector<std::string> row;
    for (const Cell& cell : results[n]) row.push_back(cell.skipped ? "-" : formatNs(cell.median()));
    printRow(std::to_string(n), row, 6, w);
  }

  std::printf("\n2) Ratio engine time / cable_dynamics time per step (> 1: cable_dynamics is faster)\n");
  std::vector<std::string> ratio_header;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (engine column, project column)
  for (std::size_t p = 0; p < columns.size(); ++p) {
    if (!columns[p].is_project) continue;
    for (std::size_t e = 0; e < columns.size(); ++e) {
      if (columns[e].is_project || columns[e].is_derivative) continue;
      pairs.emplace_back(e, p);
      ratio_header.push_back(formulations.size() == 1 ? columns[e].name : columns[e].name + "/" + columns[p].formulation);
    }
  }
  printRow("n", ratio_header, 6, w);
  for (const int n : options.sizes) {
    std::vector<std::string> row;
    for (const auto& [e, p] : pairs) {
      const Cell &ce = results[n][e], &cp = results[n][p];
      row.push_back(ce.skipped || cp.skipped ? "-" : fixed(ce.median() / cp.median(), 3));
    }
    printRow(std::to_string(n), row, 6, w);
  }

  std::printf("\n3) cable_dynamics: step / derivative() time (4 derivative calls per step plus the step's checks)\n");
  for (std::size_t p = 0; p < columns.size(); ++p) {
    if (!columns[p].is_project) continue;
    std::size_t d = 0;
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c].is_derivative && columns[c].formulation == columns[p].formulation) d = c;
    std::printf("  %-12s", columns[p].name.c_str());
    for (const int n : options.sizes) {
      const Cell &cs = results[n][p], &cd = results[n][d];
      std::printf("  n=%d: %s", n, cs.skipped || cd.skipped ? "-" : fixed(cs.median() / cd.median(), 2).c_str());
    }
    std::printf("\n");
    for (const std::size_t c : {p, d}) {
      const bool both = results.count(100) && results.count(1000) && !results[100][c].skipped && !results[1000][c].skipped;
      std::printf("  %-12s  %s time(n=1000) / time(n=100) = %s\n", "", c == p ? "step:        " : "derivative():",
                  both ? fixed(results[1000][c].median() / results[100][c].median(), 1).c_str() : "- (not both measured)");
    }
  }
  std::printf("  (time(n=1000) / time(n=100) is 10 for O(n), 100 for O(n^2), 1000 for O(n^3))\n");

  std::printf("\n4) Correctness: largest |E_end - E_start| / releasable energy over the repetitions (must be < 1e-3)\n"
              "   and simulated time per repetition [s] / step-time spread (max - min) / median over repetitions\n");
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
      const bool ok = cell.drift < 1e-3;
      all_ok = all_ok && ok;
      row.push_back(scientific(cell.drift) + (ok ? " ok" : " BAD"));
    }
    printRow(std::to_string(n), row, 6, 20);
    row.clear();
    for (const std::size_t c : check_columns) {
      const Cell& cell = results[n][c];
      row.push_back(cell.skipped ? "" : fixed(cell.duration, 3) + " s/" + fixed(100.0 * cell.spread(), 0) + "%");
    }
    printRow("", row, 6, 20);
  }
  if (!agreement.empty()) {
    std::printf("\n   Same motion: tip position after %d steps (%.1f s) at n = %d, distance to %s's:\n", options.agreement_steps,
                options.agreement_steps * 1e-3, agreement_n, columns[0].name.c_str());
    for (const auto& [name, d] : agreement) std::printf("     %-14s %.3g m\n", name.c_str(), d);
  }
  std::printf("\nNotes:\n");
  if (notes.empty()) std::printf("  (none)\n");
  for (const auto& note : notes) std::printf("  %s\n", note.c_str());
  std::printf("\nEnergy check: %s. Benchmark wall time: %.0f s.\n", all_ok ? "all passed" : "SOME FAILED",
              seconds(run_start, Clock::now()));
  return all_ok ? 0 : 1;
}
