#pragma once
// Universal File Format (UFF/UNV) time histories: dataset 58 (ASCII) and
// 58b (the same record with binary data), the exchange format of modal and
// vibration-test software.
//
// Every dataset 58/58b record of the file is one channel, in file order;
// other datasets (151 header, 164 units, geometry…) are skipped. A channel
// is named by its record's ID line 1 (else the response entity, node and
// direction of record 6); its unit is the ordinate units label of record 9
// (`m/s^2`, `g`, `Pa`, `V`, …; "m/s2", "m/s**2" and "m/s²" written
// `m/s^2`). Read: function type 1 (time response) or 0, even abscissa
// spacing, real single or double ordinates, little- or big-endian 58b data.
// Refused with an error naming the file, record and field: complex
// ordinates, uneven abscissa, a frequency abscissa or spectral function,
// records that differ in length, start or spacing. The sample rate is
// 1 / the abscissa increment, taken as the nearest whole number of Hz when
// that lies within the printed increment's precision (1.52588E-05 s →
// 65536 Hz, with a note); the start time the abscissa minimum; the date is
// ID line 3. The file is read whole into memory.

#include <span>

#include "acquire/reader.hpp"

namespace fourbar {

/// True for the extensions .uff, .unv and .uf, or a file that starts with a
/// UFF delimiter line "    -1".
bool uff_claims(const std::filesystem::path& file, std::span<const unsigned char> head);

std::unique_ptr<Reader> open_uff_reader(const std::filesystem::path& file, const ReaderOptions& options);

}  // namespace fourbar
