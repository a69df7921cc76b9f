#pragma once
// Private to the linkage simulator (included only by its .cpp files): the
// per-run state of LinkageSimulator::Impl and the declarations of its
// stages, as the three-mode simulator's simulator_state.hpp. Each stage is
// defined in the file that owns its concept:
//   linkage_equations.cpp  state conversion, the ODE with its quadratures
//                          and witnesses, the energy books
//   linkage_contacts.cpp   per-joint contact onset and release, the open
//                          contacts' peaks, contact and free-flight times
//   linkage_simulator.cpp  starts, samples, the main loop, the public API

#include <array>
#include <cstddef>
#include <vector>

#include "mechanism/kinematics.hpp"
#include "sim/integrate/linkage_integrator.hpp"
#include "sim/linkage/linkage_dynamics.hpp"
#include "sim/linkage/linkage_scales.hpp"
#include "sim/linkage/linkage_simulator.hpp"
#include "sim/record/local_clock.hpp"

namespace fourbar {

struct LinkageSimulator::Impl final : LinkageOde {
  Impl(const LinkageModel& m, const CrankMotion& c);

  // ---- the model and the integrator (fixed for the run)
  const LinkageModel& model;
  const CrankMotion& crank;
  int n;          ///< coordinates q
  bool dry;       ///< no lubricant film: 4 quadratures a clearance joint, else 5
  int per_joint;
  std::size_t size;  ///< the integrated state: q, q̇ (scaled), crank work, the joints' books, modal loss
  LinkageIntegrator integ;
  LinkageWorkspace rhs_ws;  ///< rhs()'s, kept: the mass matrix's block profile (block_cholesky.hpp) carries over

  // ---- scales of the state (linkage_scales.hpp), set by prepare()
  double w = 1, delta = 1, energy = 1, force = 1;
  LinkageScales scales;
  std::array<double, kMaxFull> pos_scale{}, rate_scale{};

  // ---- time: local time t from the clock's origin, the segment's start
  LocalClock clock;
  double t = 0, seg_start = 0;
  double absolute(double time) const { return clock.absolute(time); }
  double local(double abs_time) const { return clock.local(abs_time); }

  // ---- the nominal motion at the last few times asked (the right-hand side
  // and the witnesses ask for the same instants)
  struct Entry {
    double origin = 0, time = 0;
    bool valid = false;
    NominalMotion motion;
  };
  mutable std::array<Entry, 4> cache{};
  mutable std::size_t next_entry = 0;
  const NominalMotion& nominal_at(double time) const;

  // ---- per-joint open contact
  struct Episode {
    bool active = false;
    int phase = 0;  ///< 0 approach, 1 restitution, 2 sustained (the first cycle is over)
    double chi = 0, onset_abs = 0, loss_at_onset = 0;
    LinkageContact rec;
  };
  std::array<Episode, kJoints> ep{};
  std::vector<double> track_state;  ///< pairs_at()'s interpolated state

  // ---- outputs
  std::vector<double> sample_times;
  std::vector<LinkSensor> sensors;
  std::size_t next_sample = 0;
  std::vector<LinkageSample> samples;
  std::vector<LinkageContact> contacts;
  LinkageDiagnostics diag;
  std::vector<LinkageStepTrace>* trace = nullptr;

  // ---- the state's layout
  std::size_t work_index() const { return static_cast<std::size_t>(2 * n); }
  /// Quadrature base of the k-th clearance joint: contact loss, friction loss, impulse n, impulse t, (film).
  std::size_t quad(std::size_t k) const { return work_index() + 1 + k * static_cast<std::size_t>(per_joint); }
  /// The modal damping's dissipation (elastic links only), after the joints' quadratures.
  std::size_t modal_loss_index() const { return quad(model.clearance_joints().size()); }
  /// A clearance joint's position among the model's clearance joints.
  std::size_t slot(int joint) const;

  // ---- linkage_equations.cpp
  void coordinates(double time, const double* y, LinkageCoordinates& c) const;
  std::array<double, kJoints> chis(const LinkageWorkspace& ws) const;
  void evaluate(double time, const double* y, LinkageCoordinates& c, LinkageWorkspace& ws) const;
  void rhs(double time, const double* y, double* dy) override;
  /// The penetration over the clearance, (|e| − ξ)/ξ, per clearance joint,
  /// from the bodies' positions only (CVODE calls this after every step).
  void witnesses(double time, const double* y, double* g) override;
  std::vector<double> state_at(double time);
  double total_energy(const LinkageCoordinates& c, const LinkageWorkspace& ws) const;
  double losses(const std::vector<double>& y) const;
  void check_energy(double time, const std::vector<double>& y);

  // ---- linkage_contacts.cpp
  /// Joint j's pair (geometry and relative velocity) at the state y.
  PairState pair_of_state(int j, double time, const double* y) const;
  void onset(int j, double time, std::vector<double>& y);
  void release(int j, double time, const std::vector<double>& y);
  /// The clearance pairs (geometry, relative velocity, forces) at `time`.
  const std::array<PairState, kJoints>& pairs_at(double time, LinkageWorkspace& ws);
  /// Peak force, penetration and the end of the first compression–restitution
  /// cycle of each open contact, from the pairs at the step's end and, while an
  /// impact's first cycle is open, at mid-step too (each evaluated once). A
  /// sustained contact (phase 2) is smooth on the step's scale: step ends only.
  void track(double ta, double tb);
  void book_interval(double ta, double tb);

  // ---- linkage_simulator.cpp
  void prepare(double t0);
  void begin(const LinkageStart& s);
  LinkageSample sample(double abs_time);
  void emit_samples(double up_to);
  void restart(double time, const std::vector<double>& y);
  void advance_to(double abs_end);
};

}  // namespace fourbar
