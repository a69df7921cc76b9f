#pragma once
// MATLAB recordings (.mat v5 — v6/v7, plain or compressed — and v7.3/HDF5)
// through libmatio. v4 files are refused (no header to check them against).
//
// Channels are the file's real numeric variables of the recording's length
// (the longest length found): a vector (1×N or N×1) is one channel named by
// the variable; a matrix is one channel per column (`data(:,1)`, 1-based as
// in MATLAB), its longer dimension taken as time. A variable named `t`,
// `time` or `time_s` of that length is the time axis (uniform to within half
// a sample) rather than a channel. Values are delivered as stored (integer
// classes are not normalised): `full_scale_V` is volts per stored unit.
// The sample rate: the manifest's `rate_variable` (a scalar variable in Hz),
// else its `sample_rate_hz`, else the time variable, else a scalar named
// `fs`, `Fs`, `sample_rate`, `sample_rate_hz`, `samplerate`, `SampleRate`
// or `rate`. Variables set aside (other lengths, structs, complex) are listed
// in RecordingInfo::notes. The file is read whole into memory at open, by
// the program fourbar-read-mat in a process of its own (mat_reader.cpp:
// a damaged file can corrupt libhdf5's memory; FOURBAR_READ_MAT in the
// environment names the program when it is not beside fourbar).

#include <span>

#include "acquire/reader.hpp"

namespace fourbar {

/// True for a MATLAB header ("MATLAB 5.0 MAT-file", "MATLAB 7.3 MAT-file")
/// or the extension .mat.
bool mat_claims(const std::filesystem::path& file, std::span<const unsigned char> head);

/// InputError naming the file when it is not a recording fourbar can use or
/// is damaged; RunError when fourbar-read-mat cannot be found or started.
std::unique_ptr<Reader> open_mat_reader(const std::filesystem::path& file, const ReaderOptions& options);

}  // namespace fourbar
