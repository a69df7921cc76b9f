#pragma once
// Link angular acceleration from a link-mounted accelerometer, and the link's
// angular speed squared from a normal (centripetal) channel. Thesis §7.2,
// eq. 7.2.1-6 (coupler) and 7.2.2-1 (rocker), derived in full here.
//
// Derivation (link frame and mount: see sensor_mount.hpp). The sensor point
// P = J + r·u + h·n on a link of angle θ, speed ω, acceleration α, whose first
// joint J accelerates with a_J (coupler: the crank pin, a_A = l2(α2·n2 −
// ω2²·u2); rocker: the fixed pivot, a_J = 0), accelerates with
//   a_P = a_J + r(α·n − ω²·u) + h(−α·u − ω²·n).
// The sensor measures specific force f = a_P − g_vec = a_P + g·ŷ (gravity −y),
// along its axis with sign s:
//   tangential  m_t = s·[a_J·n + r·α − h·ω² + g·cos θ]
//   normal      m_n = s·[a_J·u − r·ω² − h·α + g·sin θ]
// so   α  = (s·m_t − a_J·n + h·ω² − g·cos θ) / r
//      ω² = (a_J·u − h·α + g·sin θ − s·m_n) / r.
// For the coupler a_A·n3 = l2[α2·cos(θ2−θ3) − ω2²·sin(θ2−θ3)] and
// a_A·u3 = −l2[α2·sin(θ2−θ3) + ω2²·cos(θ2−θ3)]. θ3, θ4 (and ω3, ω4 where the
// offset h needs them) come from the nominal mechanism at the measured crank
// angle and speed; the crank speed and acceleration are taken per sample.
//
// The thesis (eq. 7.2.1-6) prints α3 = [l2·ω2²·sin(θ2−θ3) − (a_B)_t]/l3: the
// special case r = l3, h = 0, α2 = 0 (constant crank speed), g = 0 (no gravity
// term), with s = −1 — although its own steps 7.2.1-3 to -5 define (a_B)_t as
// a_B·n3, i.e. s = +1, so the printed sign of (a_B)_t contradicts them; the
// sensing direction must be stated, here it is `axis_sign`. Eq. 7.2.2-1
// (α4 = a_Bt/l4) is the rocker case r = l4, s = +1, without gravity.
// Gravity is not small: g/l3 = 32 rad/s² against an α3 RMS of
// 209 rad/s² for the thesis rig at 350 rpm.

#include <span>
#include <vector>

#include "analyze/link_motion.hpp"
#include "analyze/sensor_mount.hpp"

namespace fourbar {

/// Forward model: the reading (m/s², DC-coupled) of the sensor for a link
/// motion (any ω, α; e.g. the nominal one, or a measured/simulated one).
double sensor_reading(const Rig& rig, const ResolvedMount& mount, const SensedLinkMotion& motion);

/// α of the sensed link from one tangential reading (DC-coupled, m/s²), the
/// link's angle (and ω, for the offset term) taken from `nominal`.
double angular_acceleration_from_tangential(const Rig& rig, const ResolvedMount& mount, const SensedLinkMotion& nominal,
                                            double reading_m_s2);

/// ω² of the sensed link from one normal reading; `link_alpha_rad_s2` is only
/// used when the sensor is offset from the link line (h ≠ 0).
double angular_speed_squared_from_normal(const Rig& rig, const ResolvedMount& mount, const SensedLinkMotion& nominal,
                                         double reading_m_s2, double link_alpha_rad_s2);

/// Whole channel: α per sample from a tangential channel (DC-coupled or
/// restored with `restore_dc_coupled_reading`), with the nominal track of the
/// mount's link. Throws InputError when the mount is bad, the mount is not
/// tangential, or lengths differ. `alpha_rad_s2` may alias `reading_m_s2`.
void angular_acceleration_from_tangential(const Rig& rig, const AccelerometerMount& mount,
                                          std::span<const SensedLinkMotion> nominal, std::span<const double> reading_m_s2,
                                          std::span<double> alpha_rad_s2);

/// Whole channel: ω² per sample from a normal channel. `link_alpha_rad_s2`
/// may be empty when the sensor is on the link line (h = 0). With an
/// AC-coupled normal channel the mean of ω² is not observed (the sensor's
/// high-pass removed it); only its variation is.
void angular_speed_squared_from_normal(const Rig& rig, const AccelerometerMount& mount,
                                       std::span<const SensedLinkMotion> nominal, std::span<const double> reading_m_s2,
                                       std::span<const double> link_alpha_rad_s2, std::span<double> omega_sq_rad2_s2);

/// For an AC-coupled (piezo) channel: undoes the sensor's first-order
/// high-pass exactly (see ac_coupling.hpp) and sets the constant it removed
/// from the model: the record mean of the reading's known part (a_J, gravity,
/// offset terms at the nominal link motion) plus r·(mean α), the mean α
/// following from ω_end − ω_start of the nominal mechanism at the measured
/// end states (≈ 0 for whole revolutions). For a DC-coupled mount (corner 0)
/// copies the reading. `restored_m_s2` may alias `reading_m_s2`.
void restore_dc_coupled_reading(const Rig& rig, const AccelerometerMount& mount, std::span<const SensedLinkMotion> nominal,
                                double sample_rate_hz, std::span<const double> reading_m_s2,
                                std::span<double> restored_m_s2);

/// Restore (AC-coupled mount) and convert in one pass, the nominal motion
/// read from a table at the measured crank states (`crank`, one per sample):
/// α for a tangential mount, ω² for a normal one (`link_alpha_rad_s2` as in
/// angular_speed_squared_from_normal). Equals restore_dc_coupled_reading
/// followed by the conversion — the conversion is affine in the reading, so
/// the restored constant is added to the result at the end — with one table
/// read per sample and no per-sample memory. `out` may alias `reading_m_s2`.
void convert_reading(const Rig& rig, const AccelerometerMount& mount, const LinkTable& table, const CrankTrack& crank,
                     double sample_rate_hz, std::span<const double> reading_m_s2,
                     std::span<const double> link_alpha_rad_s2, std::span<double> out);

/// The thesis conversion as printed (eq. 7.2.1-6 coupler, 7.2.2-1 rocker),
/// for comparison: sensor assumed at the far joint (r = l), constant crank
/// speed, no gravity term; the sensing sign made explicit (`axis_sign`):
/// coupler α3 = [s·m + l2·ω2²·sin(θ2−θ3)]/l3, rocker α4 = s·m/l4.
void thesis_angular_acceleration(const Rig& rig, SensedLink link, int axis_sign, double crank_speed_rad_s,
                                 std::span<const double> crank_angle_rad, std::span<const double> reading_m_s2,
                                 std::span<double> alpha_rad_s2);

}  // namespace fourbar
