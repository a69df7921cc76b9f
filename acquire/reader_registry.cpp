// The registry of recording formats. A further format is one new reader file
// and one line in the table below.

#include <array>
#include <fstream>

#include "acquire/csv_reader.hpp"
#include "acquire/mat_reader.hpp"
#include "acquire/reader.hpp"
#include "acquire/sndfile_reader.hpp"
#include "acquire/tdms_reader.hpp"
#include "acquire/uff_reader.hpp"
#include "common/error.hpp"

namespace fourbar {

std::span<const ReaderFormat> reader_formats() {
  static constexpr std::array table{
      ReaderFormat{"audio", "WAV, W64, RF64, FLAC, CAF, AIFF (libsndfile; 16/24/32-bit integer, float, double)",
                   sndfile_claims, open_sndfile_reader},
      ReaderFormat{"matlab", "MATLAB .mat v5/v7/v7.3 (libmatio): numeric variables or matrix columns as channels",
                   mat_claims, open_mat_reader},
      ReaderFormat{"tdms", "NI TDMS (.tdms, versions 4712/4713): numeric channels of the longest length, wf_increment as the rate",
                   tdms_claims, open_tdms_reader},
      ReaderFormat{"uff58", "Universal File Format dataset 58/58b time histories (.uff, .unv): each record a channel",
                   uff_claims, open_uff_reader},
      ReaderFormat{"text", "CSV/TSV text (.csv, .tsv, .txt): header row, optional units row, optional time column, ',' ';' or tab",
                   csv_claims, open_csv_reader},
  };
  return table;
}

std::unique_ptr<Reader> open_recording(const std::filesystem::path& file, const ReaderOptions& options) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError(file.string() + ": no such file (check the path)");
  std::array<unsigned char, 64> head{};
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open (check the permissions)");
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  const std::span<const unsigned char> got(head.data(), static_cast<std::size_t>(in.gcount()));
  if (got.empty()) throw InputError(file.string() + ": the file is empty");
  for (const auto& f : reader_formats())
    if (f.claims(file, got)) return f.open(file, options);
  std::string known;
  for (const auto& f : reader_formats()) known += std::string(known.empty() ? "" : "; ") + std::string(f.description);
  throw InputError(file.string() + ": unknown recording format (neither its content nor its extension '" +
                   file.extension().string() + "' matches: " + known + "); convert it to one of these");
}

}  // namespace fourbar
