#include "acquire/uff_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "acquire/text_cells.hpp"
#include "common/error.hpp"
#include "common/number_text.hpp"

namespace fourbar {

namespace {

std::vector<std::string_view> tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    const std::size_t b = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

/// A Fortran number ("1.52588E-05", "1.5D-05", "+3"); nullopt when it is not one.
std::optional<double> number(std::string_view t) {
  t = trim_space(t);
  std::string buf(t);
  std::replace(buf.begin(), buf.end(), 'D', 'E');
  std::replace(buf.begin(), buf.end(), 'd', 'e');
  std::string_view v = buf;
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  double x = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || ec != std::errc() || end != v.data() + v.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

/// The fields of a fixed-format line: whitespace-separated when that gives
/// `count` numbers, else cut at `widths` (Fortran fields may touch: "-1.4E-02-1.7E-02").
std::optional<std::vector<double>> fields(std::string_view line, const std::vector<std::size_t>& widths) {
  std::vector<double> out;
  const auto t = tokens(line);
  if (t.size() == widths.size()) {
    for (auto s : t)
      if (auto v = number(s)) out.push_back(*v);
    if (out.size() == widths.size()) return out;
  }
  out.clear();
  std::size_t at = 0;
  for (std::size_t w : widths) {
    if (at >= line.size()) return std::nullopt;
    auto v = number(line.substr(at, w));
    if (!v) return std::nullopt;
    out.push_back(*v);
    at += w;
  }
  return out;
}

std::string unit_name(std::string_view label) {
  std::string u(trim_space(label));
  if (u == "NONE" || u == "none") return "";
  if (u == "m/s2" || u == "m/s**2" || u == "m/s\xC2\xB2" || u == "m s^-2" || u == "m/s^2") return "m/s^2";
  if (u == "G") return "g";
  return u;
}

struct Record {
  std::size_t number = 0;  ///< 1-based dataset-58 record
  std::size_t line = 0;    ///< line of its "58" line
  std::string name, unit, date;
  std::uint64_t count = 0;
  bool double_precision = false;
  double x_min = 0, dx = 0;
  std::vector<double> values;
};

class UffParser {
 public:
  UffParser(std::string bytes, std::string file) : b_(std::move(bytes)), f_(std::move(file)) {}

  std::vector<Record> records() {
    std::vector<Record> out;
    std::string_view l;
    while (next_line(l)) {
      if (trim_space(l) != "-1") {
        if (trim_space(l).empty()) continue;
        throw InputError(at() + ": '" + std::string(trim_space(l).substr(0, 40)) + "' where a UFF dataset delimiter '    -1' "
                         "belongs (not a universal file, or damaged)");
      }
      std::string_view head;
      if (!next_line(head)) break;  // a closing delimiter at the end
      const auto t = tokens(head);
      if (t.empty()) throw InputError(at() + ": a dataset without a number after its '-1' line (damaged file)");
      if (t[0] == "58" || t[0] == "58b") {
        out.push_back(read_58(t, out.size() + 1));
      } else {
        skip_dataset();
      }
    }
    return out;
  }

 private:
  std::string at() const { return f_ + ":" + std::to_string(line_); }

  bool next_line(std::string_view& l) {
    if (pos_ >= b_.size()) return false;
    std::size_t e = b_.find('\n', pos_);
    if (e == std::string::npos) e = b_.size();
    l = std::string_view(b_).substr(pos_, e - pos_);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    pos_ = e < b_.size() ? e + 1 : e;  // never past the end (a last line without a line end)
    ++line_;
    return true;
  }
  std::string_view header_line(const char* what) {
    std::string_view l;
    if (!next_line(l)) throw InputError(at() + ": the file ends inside the header of a dataset 58 (" + what + ")");
    return l;
  }
  void skip_dataset() {
    std::string_view l;
    while (next_line(l))
      if (trim_space(l) == "-1") return;
  }

  Record read_58(const std::vector<std::string_view>& head, std::size_t number_in_file) {
    Record r;
    r.number = number_in_file;
    r.line = line_;
    const std::string rec = f_ + ": dataset 58 record " + std::to_string(r.number) + " (line " + std::to_string(r.line) + ")";
    const bool binary = head[0] == "58b";
    bool big = false;
    std::uint64_t binary_bytes = 0;
    if (binary) {
      std::vector<double> h;
      for (std::size_t i = 1; i < head.size(); ++i)
        if (auto v = number(head[i])) h.push_back(*v);
      if (h.size() < 4 || (h[0] != 1 && h[0] != 2) || h[1] != 2 || h[3] < 0 || h[3] > 1e15)
        throw InputError(rec + ": a 58b header line that fourbar does not read (byte order 1 or 2, IEEE floating "
                         "point 2 and the byte count expected)");
      big = h[0] == 2;
      binary_bytes = static_cast<std::uint64_t>(h[3]);
    }
    const std::string id1(trim_space(header_line("ID line 1")));
    header_line("ID line 2");
    r.date = std::string(trim_space(header_line("ID line 3")));
    if (r.date == "NONE") r.date.clear();
    header_line("ID line 4");
    header_line("ID line 5");
    const std::string_view r6 = header_line("record 6");
    const auto f6 = tokens(r6);
    const auto function_type = f6.empty() ? std::nullopt : number(f6[0]);
    if (!function_type || (*function_type != 0 && *function_type != 1))
      throw InputError(rec + ": function type " + (f6.empty() ? std::string("(none)") : std::string(f6[0])) +
                       " in record 6 (fourbar reads time responses, type 1: spectra, FRFs and other functions are not "
                       "recordings); export the time history");
    auto r7 = fields(header_line("record 7"), {10, 10, 10, 13, 13, 13});
    if (!r7) throw InputError(rec + ": record 7 (data type, length, spacing, abscissa start and increment) is not 3 integers and 3 numbers");
    const double ordinate = (*r7)[0], count = (*r7)[1], spacing = (*r7)[2];
    r.x_min = (*r7)[3], r.dx = (*r7)[4];
    if (ordinate == 5 || ordinate == 6)
      throw InputError(rec + ": complex ordinate data (type " + format_double(ordinate) + "), which is not a recorded "
                       "time history; export the real signal");
    if (ordinate != 2 && ordinate != 4)
      throw InputError(rec + ": ordinate data type " + format_double(ordinate) + " (fourbar reads 2, real single, and 4, real double)");
    if (spacing != 1)
      throw InputError(rec + ": uneven abscissa spacing (record 7 spacing " + format_double(spacing) + "): fourbar needs "
                       "uniformly sampled data; export with even spacing");
    if (!(count >= 1) || count > 1e12 || count != std::floor(count))
      throw InputError(rec + ": " + format_double(count) + " values in record 7 (damaged file)");
    if (!(r.dx > 0) || !std::isfinite(1.0 / r.dx))
      throw InputError(rec + ": abscissa increment " + format_double(r.dx) + " in record 7 must be positive (damaged file)");
    r.count = static_cast<std::uint64_t>(count);
    const std::string_view r8 = header_line("record 8");
    if (const auto t8 = tokens(r8); !t8.empty())
      if (auto a = number(t8[0]); a && *a != 0 && *a != 17)
        throw InputError(rec + ": abscissa data type " + std::string(t8[0]) + " in record 8 (17 is time; 18 frequency, "
                         "19 rpm, 20 order): not a time history");
    const std::string_view r9 = header_line("record 9");
    r.unit = r9.size() > 47 ? unit_name(r9.substr(47, 20)) : "";
    header_line("record 10");
    header_line("record 11");
    const std::size_t size = ordinate == 2 ? 4 : 8;
    r.double_precision = size == 8;
    r.values.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(r.count, b_.size())));
    if (binary) {
      if (binary_bytes < r.count * size || b_.size() - pos_ < r.count * size)
        throw InputError(rec + ": " + std::to_string(r.count) + " values of " + std::to_string(size) + " bytes promised, "
                         "but " + (binary_bytes < r.count * size ? "the 58b header gives " + std::to_string(binary_bytes) + " bytes"
                                                                  : "the file ends first (cut short)"));
      for (std::uint64_t i = 0; i < r.count; ++i) {
        unsigned char v[8];
        for (std::size_t k = 0; k < size; ++k) v[k] = static_cast<unsigned char>(b_[pos_ + i * size + (big ? size - 1 - k : k)]);
        std::uint64_t u = 0;
        for (std::size_t k = size; k-- > 0;) u = u << 8 | v[k];
        double x;
        if (size == 4) {
          const auto bits = static_cast<std::uint32_t>(u);
          float f;
          std::memcpy(&f, &bits, 4);
          x = f;
        } else {
          std::memcpy(&x, &u, 8);
        }
        if (!std::isfinite(x))
          throw InputError(rec + ": value " + std::to_string(i + 1) + " is not finite; every sample must be a number");
        r.values.push_back(x);
      }
      pos_ += binary_bytes > b_.size() - pos_ ? b_.size() - pos_ : binary_bytes;
      // The delimiter follows the data, after a line end or not.
      if (pos_ < b_.size() && b_[pos_] == '\r') ++pos_;
      if (pos_ < b_.size() && b_[pos_] == '\n') ++pos_;
      std::string_view l;
      while (next_line(l) && trim_space(l).empty()) {
      }
      if (trim_space(l) != "-1") throw InputError(rec + ": no '    -1' line after its binary data (damaged file)");
    } else {
      const std::size_t width = size == 4 ? 13 : 20, per_line = size == 4 ? 6 : 4;
      std::string_view l;
      for (;;) {
        if (!next_line(l)) throw InputError(rec + ": the file ends before the record's closing '    -1' line (cut short)");
        if (trim_space(l) == "-1") break;
        const auto t = tokens(l);
        std::size_t parsed = 0;
        for (auto s : t)
          if (auto v = number(s)) r.values.push_back(*v), ++parsed;
        if (parsed != t.size()) {  // fields that touch: cut at the format's width
          r.values.resize(r.values.size() - parsed);
          for (std::size_t at = 0; at < l.size() && !trim_space(l.substr(at)).empty(); at += width) {
            auto v = number(l.substr(at, width));
            if (!v)
              throw InputError(at_line() + ": '" + std::string(trim_space(l.substr(at, width))) + "' is not a finite number "
                               "(dataset 58 record " + std::to_string(r.number) + ", " + std::to_string(per_line) +
                               " values of " + std::to_string(width) + " characters a line)");
            r.values.push_back(*v);
          }
        }
        if (r.values.size() > r.count)
          throw InputError(at_line() + ": more values than the " + std::to_string(r.count) + " record 7 of dataset 58 record " +
                           std::to_string(r.number) + " promises (damaged file)");
      }
      if (r.values.size() != r.count)
        throw InputError(rec + ": " + std::to_string(r.values.size()) + " values, but record 7 promises " +
                         std::to_string(r.count) + " (cut short or damaged)");
    }
    r.name = id1 == "NONE" ? "" : id1;
    if (r.name.empty()) {
      const std::string entity = r6.size() > 31 ? std::string(trim_space(r6.substr(31, 10))) : "";
      const auto t6 = tokens(r6.size() > 41 ? r6.substr(41) : std::string_view());
      r.name = entity.empty() || entity == "NONE" ? "record " + std::to_string(r.number)
                                                  : entity + (t6.size() >= 2 ? ":" + std::string(t6[0]) + ":" + std::string(t6[1]) : "");
    }
    return r;
  }
  std::string at_line() const { return at(); }

  std::string b_, f_;
  std::size_t pos_ = 0, line_ = 0;
};

/// Significant digits of the abscissa increment as printed in record 7 (E13.5: 6).
constexpr int kIncrementDigits = 6;

class UffReader final : public Reader {
 public:
  UffReader(const std::filesystem::path& file, const ReaderOptions& options) {
    const std::string f = file.string();
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(f + ": cannot open (check the path and permissions)");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto records = UffParser(std::move(bytes), f).records();
    if (records.empty())
      throw InputError(f + ": no dataset 58 (time history) in this universal file; export the time histories as dataset 58 or 58b");
    const Record& first = records.front();
    for (const auto& r : records) {
      const auto differs = [&](const char* what, const std::string& a, const std::string& b) {
        return InputError(f + ": dataset 58 record " + std::to_string(r.number) + " (line " + std::to_string(r.line) + ") has " +
                          what + " " + a + ", record 1 " + b + ": every record is a channel of one recording and must "
                          "share length, start and spacing; split the file");
      };
      if (r.count != first.count) throw differs("length", std::to_string(r.count), std::to_string(first.count));
      if (r.dx != first.dx) throw differs("abscissa increment", format_double(r.dx), format_double(first.dx));
      if (r.x_min != first.x_min) throw differs("abscissa start", format_double(r.x_min), format_double(first.x_min));
    }
    info_.file = file;
    info_.format = "UFF58";
    const auto doubles = std::count_if(records.begin(), records.end(), [](const Record& r) { return r.double_precision; });
    info_.sample_format = doubles == 0 ? "FLOAT" : doubles == static_cast<std::ptrdiff_t>(records.size()) ? "DOUBLE" : "MIXED";
    info_.channels = static_cast<int>(records.size());
    info_.frames = first.count;
    info_.start_time_s = first.x_min;
    info_.started_at = first.date;
    double rate = 1.0 / first.dx;
    // The increment is printed with 6 significant digits: a whole rate within that precision is the rate.
    const double whole = std::round(rate), precision = 0.5 * std::pow(10.0, 1 - kIncrementDigits) /
                                                       (first.dx / std::pow(10.0, std::floor(std::log10(first.dx))));
    if (whole > 0 && whole != rate && std::abs(whole - rate) <= precision * rate) {
      info_.notes.push_back("sample rate " + format_double(whole) + " Hz: the whole number nearest 1 / " +
                            format_double(first.dx) + " s (the file's increment, printed to 6 digits)");
      rate = whole;
    }
    if (options.sample_rate_hz && std::abs(*options.sample_rate_hz - rate) > precision * rate)
      throw InputError(f + ": the manifest's sample_rate_hz = " + format_double(*options.sample_rate_hz) +
                       " contradicts the file's " + format_double(rate) + " Hz (record 7's abscissa increment); "
                       "delete sample_rate_hz from the manifest");
    info_.sample_rate_hz = rate;
    bool any_unit = false;
    for (std::size_t i = 0; i < records.size(); ++i) {
      std::string name = records[i].name;
      for (std::size_t j = 0; j < i; ++j)
        if (records[j].name == name) name += " (record " + std::to_string(records[i].number) + ")";
      info_.channel_names.push_back(name);
      info_.channel_units.push_back(records[i].unit);
      any_unit = any_unit || !records[i].unit.empty();
      columns_.push_back(std::move(records[i].values));
    }
    if (!any_unit) info_.channel_units.clear();
  }

  std::size_t read(std::span<double> out) override {
    const std::size_t channels = columns_.size();
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(out.size() / channels, info_.frames - position_));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < channels; ++c) out[i * channels + c] = columns_[c][position_ + i];
    position_ += n;
    return n;
  }

  void rewind() override { position_ = 0; }

 private:
  std::vector<std::vector<double>> columns_;
  std::uint64_t position_ = 0;
};

}  // namespace

bool uff_claims(const std::filesystem::path& file, std::span<const unsigned char> head) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".uff" || ext == ".unv" || ext == ".uf") return true;
  const std::string_view h(reinterpret_cast<const char*>(head.data()), head.size());
  const std::size_t e = h.find('\n');
  return e != std::string_view::npos && trim_space(h.substr(0, e)) == "-1";
}

std::unique_ptr<Reader> open_uff_reader(const std::filesystem::path& file, const ReaderOptions& options) {
  return std::make_unique<UffReader>(file, options);
}

}  // namespace fourbar
