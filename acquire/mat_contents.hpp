#pragma once
// A MATLAB file read whole with libmatio, in this process: the recording's
// description and its channels (mat_reader.hpp says which variables become
// channels and where the sample rate comes from). A v5 file's structure is
// checked before libmatio reads it; a damaged v7.3 (HDF5) file can corrupt
// memory inside libhdf5. fourbar itself never calls this: open_mat_reader
// runs fourbar-read-mat (acquire/read_mat_main.cpp), which does; the library
// fourbar_mat_contents holds it (and libmatio) apart from fourbar_acquire.

#include <filesystem>
#include <vector>

#include "acquire/reader.hpp"

namespace fourbar {

struct MatContents {
  RecordingInfo info;
  std::vector<std::vector<double>> columns;  ///< per channel, info.frames values
};

/// The version of the 128-byte MATLAB header as libmatio's Mat_Open reads it
/// (bytes 124-125 in the byte order of the mark "IM"/"MI" at 126-127):
/// 0x0100 (v5, v6, v7), 0x0200 (v7.3: HDF5 with the header as its user
/// block), 0 without such a header (v4, or not a MATLAB file).
unsigned mat_header_version(const std::filesystem::path& file);

/// Reads `file` with libmatio. InputError naming the file when it is not a
/// recording fourbar can use, or damaged as far as fourbar can tell.
MatContents read_mat_contents(const std::filesystem::path& file, const ReaderOptions& options);

}  // namespace fourbar
