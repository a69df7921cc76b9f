#pragma once
// The model-family check across a session's crank speeds.
//
// A structure's resonance (a link's bending mode, the accelerometer's mounted
// resonance) stays at its frequency in Hz whatever the crank speed; the
// clearance's own rhythm (the free flights between impacts) moves with the
// speed, in orders, and with e. A finding of compare/model_family.hpp that a
// recording at another speed of the same session does not show at the same
// Hz is therefore not a structure the model lacks but energy the model family
// has at other parameters: it is set aside (kept in the record as
// "moves_with_speed", said in the verdict) and the agreement is judged from
// the next finding, or over the whole band when none is left.
//
// "Shows at the same Hz": a recording whose crank speed differs by at least
// kOtherSpeedShare, whose check covers the finding's band, has a window
// overlapping that band standing kExcessRatio above its neighbours (the same
// threshold a finding needs). Measured (docs/verdict.md "Model family",
// across speeds): every finding on the ringing recordings of
// bench/model_family_check.sh's hold-out (40) and of the independent
// generator (8) has such a partner (the weakest partner window 9.7x); the
// false alarm at 137-177 Hz (350 rpm, 0.1016 mm, rigid) and the independent
// generator's 137-177 Hz finding at 350 rpm have none (partners at 1.7-3.2x).
// A session with one speed, or no other recording covering the band, keeps
// every finding: nothing can set it aside.

#include <vector>

#include <nlohmann/json.hpp>

namespace fourbar {

/// Crank speeds that differ by at least this share count as other speeds.
inline constexpr double kOtherSpeedShare = 0.1;

/// Over the session's records (each with "model_family" from
/// model_family_json, others left alone): set aside the findings no
/// recording at another speed confirms. Returns how many were set aside.
std::size_t set_aside_findings_that_move_with_speed(std::vector<nlohmann::json>& records);

}  // namespace fourbar
