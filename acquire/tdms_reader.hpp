#pragma once
// NI TDMS recordings (LabVIEW, SignalExpress, FlexLogger, DAQmx logging;
// structure: acquire/tdms_structure.hpp).
//
// Channels are the numeric channels (integers, float, double, bool) of the
// recording's length (the longest one) and sample rate; a channel is named by
// its channel name, or `group/channel` when two groups share the name.
// Channels of other lengths or rates (e.g. decimated groups), strings and
// timestamps are set aside and listed in RecordingInfo::notes. Values are
// delivered as stored (integers not normalised: `full_scale_V` is volts per
// stored unit; NI scaling properties are not applied). The sample rate is
// 1 / `wf_increment` (the manifest's `sample_rate_hz` when no channel has
// one; it must not contradict the file), the start time `wf_start_offset`,
// the unit `unit_string` (else `NI_UnitDescription`), the wall-clock start
// `wf_start_time`. Values are streamed from the file, not held in memory.

#include <span>

#include "acquire/reader.hpp"

namespace fourbar {

/// True for the tag "TDSm" (or "TDSh", an index file, refused by the reader)
/// or the extension .tdms.
bool tdms_claims(const std::filesystem::path& file, std::span<const unsigned char> head);

std::unique_ptr<Reader> open_tdms_reader(const std::filesystem::path& file, const ReaderOptions& options);

}  // namespace fourbar
