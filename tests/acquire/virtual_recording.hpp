#pragma once
// Test support: a virtual recording of the thesis rig written into a fresh
// folder, with every knob of the [recording] table reachable from code.

#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "virtual_rig/virtual_rig.hpp"
#include "support/temp_dir.hpp"

namespace fourbar::testing {

struct VirtualSetup {
  TempDir dir;
  Scene scene;
  RecordingSpec spec;

  explicit VirtualSetup(double rpm = 350.0) {
    const auto rig_file = dir.write("rig.toml", thesis_rig_toml());
    scene.rig = std::make_shared<const Rig>(load_rig(rig_file));
    scene.source = dir.path() / "scene.toml";
    scene.crank_speed_rad_s = units::rpm_to_rad_s(rpm);
    scene.start_angle_rad = units::deg_to_rad(40.0);
    spec.sample_rate_hz = 25600;
    spec.revolutions = 12;
    spec.sample_format = "pcm24";
    spec.full_scale_V = 10;
    spec.pulse.width_rad = units::deg_to_rad(10);
    spec.pulse.rise_s = 4.0 / spec.sample_rate_hz;
    add_sensor("coupler_t", ChannelRole::coupler_tangential, 309, 1);
    add_sensor("coupler_n", ChannelRole::coupler_normal, 309, -1);
    add_sensor("rocker_t", ChannelRole::rocker_tangential, 312, 1);
  }

  ChannelSpec& add_sensor(const std::string& name, ChannelRole role, double position_mm, double axis_sign) {
    ChannelSpec c;
    c.name = name;
    c.role = role;
    c.position_m = position_mm * 1e-3;
    c.axis_sign = axis_sign;
    c.volts_per_m_s2 = 0.01;
    c.index = static_cast<int>(spec.sensors.size());
    spec.sensors.push_back(c);
    return spec.sensors.back();
  }

  CrankDrive drive() const { return crank_drive(scene, spec); }

  VirtualRigResult write(const std::string& name, bool truth = true) const {
    const CrankDrive d = drive();
    const NominalMotionSource motion(scene.rig, d);
    VirtualRigOptions o;
    o.write_truth = truth;
    o.progress = false;
    return make_virtual_recording(scene, spec, d, motion, dir.path() / name, Provenance{"test", {}}, o);
  }
};

/// A CSV file (comment lines skipped) as a header and columns of numbers.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> columns;
  const std::vector<double>& operator[](const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return columns[i];
    throw std::runtime_error("no column " + name);
  }
  std::size_t rows() const { return columns.empty() ? 0 : columns[0].size(); }
};

inline CsvTable read_csv_table(const std::filesystem::path& p) {
  std::ifstream in(p);
  CsvTable t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::string cell;
    if (t.header.empty()) {
      while (std::getline(ss, cell, ',')) t.header.push_back(cell);
      t.columns.resize(t.header.size());
      continue;
    }
    for (std::size_t c = 0; std::getline(ss, cell, ','); ++c) t.columns[c].push_back(std::strtod(cell.c_str(), nullptr));
  }
  return t;
}

}  // namespace fourbar::testing
