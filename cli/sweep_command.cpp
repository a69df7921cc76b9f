// `fourbar sweep SWEEP.toml [--out FILE] [--jobs N]`: a clearance × rpm × e × μ
// grid over a base clearance scene, written as one table (the analogue of
// thesis Figs 7.10 and 7.11). The points run on every core, or over the ranks
// of an MPI job (cluster/case_queue.hpp); each finished point is journaled so
// an interrupted sweep resumes where it stopped (sweep_journal.hpp).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <tuple>

#include "cli/command.hpp"
#include "cluster/case_queue.hpp"
#include "cluster/mpi_session.hpp"
#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/progress.hpp"
#include "common/provenance.hpp"
#include "common/units.hpp"
#include "common/version.hpp"
#include "sim/studies/sweep.hpp"
#include "sim/studies/sweep_journal.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

constexpr const char* kSweepDetails = R"(Runs the clearance model over a grid and writes one CSV row per grid point.

Sweep file keys:
  scene                 base scene (model = "clearance": three-mode or compliant), relative to the sweep file
  radial_mm             array of radial clearances in mm (default: the scene's)
  crank_speed_rpm       array of crank speeds in rpm (default: the scene's)
  restitution           array of coefficients of restitution (default: the scene's)
  friction_coefficient  array of Coulomb mu (base scene stick-slip or compliant)
  revolutions           turns counted per grid point (default 20, as the report's model)
  skip_revolutions      start-up turns run first and not counted (default 20, the
                        report's warm-up); fewer: a note says the counts hold the
                        transient after the start

Columns: radial_mm, crank_speed_rpm, restitution, friction_coefficient,
impacts_per_rev (n), impacts_per_rev_standard_error (the spread over the
counted turns / sqrt(turns), times sqrt(tau) for turns that are correlated,
tau their integrated autocorrelation time; docs/sweep.md),
sum_normal_impulse_per_rev_Ns (SigmaF),
sum_normal_impulse_per_rev_standard_error_Ns, impact_index_Ns
(I_n = SigmaF/n, 0 when n = 0), contact_losses_per_rev, following_share,
energy_residual_rel, max_penetration_rel, status ("ok" or "failed"), error
(why a point failed; its statistics are then empty). The table's provenance
(version, command, input files) is in OUT.json beside it.

Each finished point is appended to OUT.journal at once. A sweep that was
interrupted (Ctrl-C, a killed job, a lost node) and is started again with the
same inputs takes the finished points from the journal and computes only the
rest; the journal is removed when the table is written.

On a cluster: start it under mpirun or srun, one rank per core (e.g.
`mpirun -np 64 fourbar sweep big.toml`); rank 0 hands out one point at a time
and writes the table, identical to a run on one machine. docs/cluster.md has
a Slurm script and how to size the job.

Exit status: 0 every point computed; 1 the table was written but some points
failed (each named on stderr, status "failed" in the table), or the run
failed; 2 bad arguments or sweep file (nothing written).)";

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// What a journal must have been made from to be reused: the version, the
/// three input files and the grid itself.
std::string inputs_fingerprint(const std::string& sweep_file, const Scene& base, const std::vector<SweepPoint>& points,
                               const SweepGrid& grid) {
  std::string text = std::string(kVersion) + "\n" + file_bytes(sweep_file) + "\n" + file_bytes(base.source) + "\n" +
                     file_bytes(base.rig->source) + "\n" + std::to_string(grid.revolutions) + " " +
                     std::to_string(grid.skip_revolutions) + "\n";
  for (const SweepPoint& p : points) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%a %a %a %a\n", p.radial_clearance_m, p.crank_speed_rad_s, p.restitution,
                  p.friction_coefficient);
    text += buf;
  }
  return fingerprint_of(text);
}

void write_table(const std::filesystem::path& out_path, const Provenance& prov, const std::vector<SweepPoint>& points) {
  CsvWriter csv(out_path, prov.csv_comment_lines(),
                {"radial_mm", "crank_speed_rpm", "restitution", "friction_coefficient", "impacts_per_rev",
                 "impacts_per_rev_standard_error", "sum_normal_impulse_per_rev_Ns",
                 "sum_normal_impulse_per_rev_standard_error_Ns", "impact_index_Ns", "contact_losses_per_rev",
                 "following_share", "energy_residual_rel", "max_penetration_rel", "status", "error"});
  for (const SweepPoint& p : points) {
    const double values[] = {units::m_to_mm(p.radial_clearance_m),
                             units::rad_s_to_rpm(p.crank_speed_rad_s),
                             p.restitution,
                             p.friction_coefficient,
                             p.impacts_per_rev,
                             p.impacts_per_rev_standard_error,
                             p.sum_normal_impulse_per_rev_Ns,
                             p.sum_normal_impulse_per_rev_standard_error_Ns,
                             p.impact_index_Ns,
                             p.contact_losses_per_rev,
                             p.following_share,
                             p.energy_residual_rel,
                             p.max_penetration_rel};
    std::vector<std::string> cells;
    for (std::size_t k = 0; k < std::size(values); ++k)
      cells.push_back(p.failed() && k >= 4 ? std::string() : k < 2 ? format_input_decimal(values[k]) : format_double(values[k]));
    cells.push_back(p.failed() ? "failed" : "ok");
    cells.push_back(p.error);
    csv.text_row(cells);
  }
  csv.describe_in_sidecar(prov.to_json());
  csv.commit();
}

}  // namespace

int run_sweep(const Invocation& inv) {
  std::string sweep_file, out_file;
  // Signed, so that "--jobs -1" is refused instead of wrapping round to 4294967295.
  long long jobs = std::max(1u, std::thread::hardware_concurrency());
  bool quiet = false, csv_comments = false;
  po::options_description opts("options");
  opts.add_options()("sweep", po::value(&sweep_file)->required(), "sweep file (TOML)")(
      "out,o", po::value(&out_file), "output table (default: out/<sweep name>.csv)")(
      "jobs,j", po::value(&jobs), "threads (default: all cores; under MPI each rank runs one point at a time)");
  add_csv_comments_option(opts, csv_comments);
  add_quiet_option(opts, quiet);
  po::positional_options_description pos;
  pos.add("sweep", 1);
  po::variables_map vm;
  if (!parse_arguments("sweep", "SWEEP.toml [--out FILE] [--jobs N] [--csv-comments]", kSweepDetails, opts, pos, inv, vm)) return 0;
  if (jobs < 1 || jobs > 4096) throw InputError("sweep: --jobs " + std::to_string(jobs) + " must be between 1 and 4096");

  // Every rank reads and checks the inputs (so a bad file fails on all of
  // them alike); only rank 0 writes.
  Scene base;
  const SweepGrid grid = load_sweep(sweep_file, base);
  std::vector<SweepPoint> points = sweep_points(grid);
  const MpiSession& mpi = MpiSession::get();
  auto compute = [&](std::size_t i) {
    SweepPoint p = points[i];
    compute_sweep_point(base, grid, p);
    return encode_sweep_result(p);
  };
  if (!mpi.leader()) {
    run_case_queue({}, 1, compute, {});
    return 0;
  }

  // Counts from the start transient or from few turns are said, not left to be found out.
  const SweepGrid defaults;
  if (grid.skip_revolutions < defaults.skip_revolutions)
    std::cerr << "fourbar: note: sweep: " << sweep_file << ": skip_revolutions = " << grid.skip_revolutions
              << ": the counted turns start within the transient after the start (the report's model runs "
              << defaults.skip_revolutions << " warm-up turns first); its figures are not the steady response\n";
  if (grid.revolutions < defaults.revolutions)
    std::cerr << "fourbar: note: sweep: " << sweep_file << ": " << grid.revolutions
              << " counted turns per point (the report's model averages " << defaults.revolutions
              << "): see the _standard_error columns for how uncertain each figure is\n";
  if (out_file.empty()) out_file = (std::filesystem::path("out") / std::filesystem::path(sweep_file).stem()).string() + ".csv";
  const std::filesystem::path out_path(out_file);
  if (out_path.has_parent_path()) ensure_output_dir(out_path.parent_path());
  SweepJournal journal(out_path.string() + ".journal", inputs_fingerprint(sweep_file, base, points, grid),
                       points.size());
  if (journal.discarded_stale())
    std::cerr << "fourbar: sweep: " << journal.path().string()
              << " is from other inputs (the sweep, scene or rig changed); starting over\n";
  std::vector<std::size_t> todo;
  std::size_t resumed = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto it = journal.finished().find(i);
    if (it != journal.finished().end() && decode_sweep_result(it->second, points[i])) ++resumed;
    else todo.push_back(i);
  }

  // Handed out long cases first, so that the queue's tail, where a rank may
  // wait for the last case of another, is a short case. A case's cost is not
  // known before it runs; what makes one long is more impacts and rebounds
  // per turn: a higher restitution, then a higher crank speed, then more
  // friction, then a smaller clearance (measured on the 24-point grid of
  // bench/sweep_scaling.sh: the e = 0.8 points take 1.5-2.5x the e = 0.2
  // ones). The table is written in the grid's order whatever the order of
  // computing, and each point's numbers do not depend on it.
  std::stable_sort(todo.begin(), todo.end(), [&](std::size_t a, std::size_t b) {
    const SweepPoint &p = points[a], &q = points[b];
    auto key = [](const SweepPoint& x) {
      return std::tuple(-x.restitution, -std::abs(x.crank_speed_rad_s), -x.friction_coefficient, x.radial_clearance_m);
    };
    return key(p) < key(q);
  });
  Progress progress("sweep", todo.size(), !quiet);
  std::size_t finished = 0;
  const CaseQueueStats stats =
      run_case_queue(todo, static_cast<unsigned>(jobs), compute, [&](std::size_t i, std::string&& result) {
        journal.append(i, result);
        if (!decode_sweep_result(result, points[i]))
          throw RunError("sweep: internal error: point " + std::to_string(i) + " came back unreadable");
        progress.update(++finished);
      });
  progress.finish();

  write_table(out_path, Provenance{inv.command_line, {sweep_file, base.source, base.rig->source}, csv_comments}, points);
  journal.remove();

  constexpr std::size_t kFailuresNamed = 10;  // the rest are in the table
  std::size_t failed = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].failed() && ++failed <= kFailuresNamed) {
      std::cerr << "fourbar: sweep: point " << i + 1 << " (radial " << format_number(units::m_to_mm(points[i].radial_clearance_m))
                << " mm, " << format_number(units::rad_s_to_rpm(points[i].crank_speed_rad_s)) << " rpm, e "
                << format_number(points[i].restitution) << ", mu " << format_number(points[i].friction_coefficient)
                << ") failed: " << points[i].error << "\n";
    }
  if (failed > kFailuresNamed)
    std::cerr << "fourbar: sweep: and " << failed - kFailuresNamed << " more failed points (status \"failed\" in "
              << out_path.string() << ")\n";
  std::cout << "wrote " << out_path.string() << " (" << points.size() << " grid points of the "
            << (base.clearance.model == ClearanceKind::compliant ? "compliant" : "three-mode") << " model, "
            << grid.revolutions << " counted turns each";
  if (resumed > 0) std::cout << "; " << resumed << " from the journal of an interrupted run";
  std::cout << "; " << todo.size() << " computed on ";
  if (stats.ranks > 1) std::cout << mpi.describe();
  else std::cout << stats.threads << (stats.threads == 1 ? " thread" : " threads");
  if (failed > 0) std::cout << "; " << failed << " failed";
  std::cout << ")\n";
  return failed > 0 ? 1 : 0;
}

}  // namespace fourbar::cli
