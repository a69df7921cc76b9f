// `fourbar fit` as a user runs it: a backwards box is bad input naming the
// option (exit 2, nothing written); a session of nominal recordings has no
// clearance effect above its noise and is not fitted (exit 1, said plainly).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_rig_scene.hpp"

namespace fourbar {
namespace {

std::string nominal_scene(double rpm, int seed) {
  return "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nmodel = \"nominal\"\ncrank_speed_rpm = " +
         std::to_string(rpm) + R"(
outputs = ["alpha3_rad_s2"]
[recording]
sample_rate_hz = 12800
revolutions = 20
noise_snr_db = 30.0
seed = )" + std::to_string(seed) + R"(
[recording.pulse]
angle_deg = 0.0
)" + testing::tangential_sensors_toml(289.0, 292.0);
}

class FitCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir;
    int seed = 1;
    for (double rpm : {250.0, 350.0}) {
      const std::string name = "nominal_" + std::to_string(static_cast<int>(rpm));
      dir_->write("make/" + name + ".toml", nominal_scene(rpm, seed++));
      // The manifest needs a clearance for the fit to get as far as the noise check.
      const auto r = testing::record_virtual(dir_->path() / "make" / (name + ".toml"), dir_->path() / "session" / (name + ".flac"));
      ASSERT_EQ(r.status, 0) << r.err;
    }
  }
  static void TearDownTestSuite() { delete dir_; }
  static testing::TempDir* dir_;
};
testing::TempDir* FitCommand::dir_ = nullptr;

TEST_F(FitCommand, BackwardsBoxIsBadInputNamingIt) {
  const auto out = dir_->path() / "out_box";
  const auto r = testing::run_fourbar("fit " + (dir_->path() / "session").string() + " --restitution 0.9:0.1 --out " +
                                      out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("fourbar: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--restitution"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "fit.json"));
  const auto m = testing::run_fourbar("fit " + (dir_->path() / "session").string() + " --friction 0.3");
  EXPECT_EQ(m.status, 2) << m.err;
  EXPECT_NE(m.err.find("LOW:HIGH"), std::string::npos) << m.err;
}

TEST_F(FitCommand, NominalRecordingsAreNotFitted) {
  const auto out = dir_->path() / "out_nominal";
  // The nominal scenes' manifests carry the rig's clearance (the model did not use it).
  const auto r = testing::run_fourbar("fit " + (dir_->path() / "session").string() + " -q --out " + out.string());
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("no clearance effect measurable above the noise floor"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "fit.json"));
}

// A small recovery (the full table is bench/fit_recovery.sh): one recording
// at the large clearance made with e = 0.2 (smooth), a wrong prior e = 0.95
// in session.toml; the e-only fit must find e well away from the prior, with
// the truth inside its interval, and a χ² far below the prior's.
/// A session of one recording at the large clearance made with e = 0.2
/// (smooth), with a wrong prior e = 0.95 in session.toml.
void write_clearance_session(testing::TempDir& dir) {
  dir.write("make/rec.toml", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nmodel = \"clearance\"\n"
            R"(crank_speed_rpm = 350
outputs = ["alpha3_rad_s2"]
[clearance]
radial_mm = 0.254
restitution = 0.2
contact = "smooth"
tolerance = 1e-8
[recording]
sample_rate_hz = 12800
revolutions = 16
noise_snr_db = 30.0
seed = 5
[recording.pulse]
angle_deg = 0.0
)" + testing::tangential_sensors_toml(289.0, 292.0));
  const auto made = testing::record_virtual(dir.path() / "make" / "rec.toml", dir.path() / "session" / "rec.flac");
  ASSERT_EQ(made.status, 0) << made.err;
  dir.write("session/session.toml", "[theory]\nrestitution = 0.95\ncontact = \"smooth\"\n");
}

TEST(FitRecovery, SmallSessionFindsRestitutionAwayFromWrongPrior) {
  testing::TempDir dir;
  write_clearance_session(dir);
  const auto out = dir.path() / "fit";
  const auto r = testing::run_fourbar("fit " + (dir.path() / "session").string() + " --smooth --turns 24 -q --out " +
                                      out.string());
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  std::ifstream in(out / "fit.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& e = j["parameters"]["restitution"];
  EXPECT_LE(e["low"].get<double>(), 0.2) << j.dump(1);
  EXPECT_GE(e["high"].get<double>(), 0.2) << j.dump(1);
  EXPECT_LT(e["high"].get<double>(), 0.8) << "the wrong prior 0.95 is not excluded: " << j.dump(1);
  EXPECT_LT(j["chi2"].get<double>(), 0.25 * j["chi2_prior"].get<double>()) << j.dump(1);
  EXPECT_EQ(j["recordings"].size(), 1u);
  EXPECT_GT(j["evaluations"].get<int>(), 10);
}

// Under mpirun the fit's simulations are spread over the ranks (rank 0
// searches and hands them out, the others compute): fit.json equals the
// serial fit's bit for bit, but for the run's own account (time, ranks,
// command line). A cheap fit: e and mu, 2 + 8 turns per simulation.
TEST(FitMpi, RanksGiveTheSerialFitBitForBit) {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "mpirun is not installed (Debian package openmpi-bin; scripts/install-deps.sh installs it)";
  testing::TempDir dir;
  write_clearance_session(dir);
  const std::string args = " fit " + (dir.path() / "session").string() + " --turns 8 --warmup 2 -q --out ";
  const auto serial = testing::run_fourbar(args.substr(1) + (dir.path() / "serial").string() + " --jobs 1");
  ASSERT_EQ(serial.status, 0) << serial.out << serial.err;
  // As the MPI sweep test: root allowed in a container; no leak check of Open
  // MPI's runtime under the sanitizer build.
  const std::string cmd = "ASAN_OPTIONS=${ASAN_OPTIONS}:detect_leaks=0 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                          "OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none "
                          "mpirun --oversubscribe -np 3 " FOURBAR_EXE + args + (dir.path() / "ranks").string() + " >" +
                          (dir.path() / "mpi.out").string() + " 2>&1";
  const int raw = std::system(cmd.c_str());
  const std::string said = testing::read_file(dir.path() / "mpi.out");
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << said;
  EXPECT_EQ(said.find("fit: analysing"), std::string::npos) << "-q on every rank: " << said;
  EXPECT_EQ(said.find("wrote"), said.rfind("wrote")) << "only rank 0 writes: " << said;

  auto read = [&](const char* run) {
    std::ifstream in(dir.path() / run / "fit.json");
    return nlohmann::json::parse(in);
  };
  nlohmann::json a = read("serial"), b = read("ranks");
  EXPECT_EQ(a["mpi_ranks"], 1);
  EXPECT_EQ(b["mpi_ranks"], 3);
  EXPECT_EQ(a["simulations_on_rank_0"], a["simulations"]);
  EXPECT_LT(b["simulations_on_rank_0"].get<int>(), b["simulations"].get<int>()) << "the other ranks computed none";
  EXPECT_GT(a["simulations"].get<int>(), 30);
  for (const char* run_only : {"command_line", "seconds", "cpu_seconds", "seconds_per_simulation", "threads",
                               "mpi_ranks", "simulations_on_rank_0", "simulation_cpu_seconds",
                               "simulation_idle_wall_seconds"})
    a.erase(run_only), b.erase(run_only);
  // nlohmann writes doubles with the digits that read back to the same
  // double: equal text is equal bits.
  EXPECT_EQ(a.dump(1), b.dump(1));
}

}  // namespace
}  // namespace fourbar
