#include "acquire/csv_preamble.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "acquire/csv_units.hpp"
#include "acquire/text_cells.hpp"
#include "common/error.hpp"

namespace fourbar {

namespace {

constexpr std::size_t kScanLines = 400;  ///< lines searched for the header
constexpr std::size_t kDataRowsChecked = 3;

std::optional<double> number(std::string_view cell, bool decimal_comma) {
  std::string buf(trim_cell(cell));
  if (decimal_comma) std::replace(buf.begin(), buf.end(), ',', '.');
  std::string_view v = buf;
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  double x = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || ec != std::errc() || end != v.data() + v.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

bool blank_or_comment(std::string_view line) {
  const auto t = trim_cell(line);
  return t.empty() || t.front() == '#';
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

/// A units-row cell: a unit in brackets ("[V]", "(s)"), a common unit, or empty.
bool unit_like(std::string_view c) {
  c = trim_cell(c);
  if (c.size() >= 2 && ((c.front() == '[' && c.back() == ']') || (c.front() == '(' && c.back() == ')'))) return true;
  static const char* units[] = {"", "s", "ms", "us", "V", "mV", "uV", "A", "mA", "g", "m/s^2", "m/s2", "m/s\xC2\xB2",
                                "Pa", "kPa", "bar", "N", "Nm", "rpm", "Hz", "deg", "\xC2\xB0", "rad", "mm", "m", "K",
                                "degC", "%", "-"};
  return std::find(std::begin(units), std::end(units), c) != std::end(units);
}

struct Line {
  std::size_t number;
  std::string text;
};

/// True when `lines[from…]` hold (after blank and comment lines) data rows of
/// `cells` numeric cells: at least one, up to kDataRowsChecked checked.
bool data_rows_follow(const std::vector<Line>& lines, std::size_t from, std::size_t cells, char d) {
  std::size_t rows = 0;
  for (std::size_t i = from; i < lines.size() && rows < kDataRowsChecked; ++i) {
    if (blank_or_comment(lines[i].text)) continue;
    const auto c = split_cells(lines[i].text, d);
    if (c.size() != cells) return false;
    for (auto cell : c)
      if (!number(cell, d != ',')) return false;
    ++rows;
  }
  return rows > 0;
}

std::size_t next_content(const std::vector<Line>& lines, std::size_t from) {
  while (from < lines.size() && blank_or_comment(lines[from].text)) ++from;
  return from;
}

/// The sample rate or start a preamble line states, into `p`.
void read_preamble_line(const Line& l, char d, CsvPreamble& p) {
  std::string_view t = trim_cell(l.text);
  while (!t.empty() && t.front() == '#') t = trim_cell(t.substr(1));
  // "Key;value;unit", "Key: value unit" or "Key = value".
  std::vector<std::string_view> cells = split_cells(t, d);
  if (cells.size() < 2) {
    const std::size_t sep = t.find_first_of(":=");
    if (sep == std::string_view::npos) return;
    cells = {trim_cell(t.substr(0, sep)), trim_cell(t.substr(sep + 1))};
  }
  std::string key = lower(cells[0]);
  while (!key.empty() && (key.back() == ':' || key.back() == '=' || key.back() == ' ')) key.pop_back();
  const auto [bare, key_unit] = split_unit(key);
  static const char* rate_keys[] = {"sample rate", "sampling rate", "samplerate", "sample_rate", "sampling frequency",
                                    "sample frequency", "scan rate", "fs", "rate"};
  static const char* start_keys[] = {"start", "start time", "starttime", "start date", "start_time", "date",
                                     "trigger time", "recorded", "acquisition start", "date/time", "timestamp"};
  if (std::find(std::begin(rate_keys), std::end(rate_keys), bare) != std::end(rate_keys)) {
    std::string value(cells[1]), unit = key_unit.empty() ? (cells.size() > 2 ? lower(cells[2]) : "") : lower(key_unit);
    // "12800 Hz" in one cell.
    if (const std::size_t sp = value.find(' '); sp != std::string::npos && unit.empty())
      unit = lower(trim_cell(std::string_view(value).substr(sp + 1))), value.resize(sp);
    const auto v = number(value, true);
    const double scale = unit == "khz" ? 1e3 : (unit.empty() || unit == "hz" || unit == "s/s" || unit == "sps" || unit == "1/s") ? 1.0 : 0.0;
    if (v && *v > 0 && scale > 0) p.sample_rate_hz = *v * scale, p.rate_line = l.number;
  } else if (std::find(std::begin(start_keys), std::end(start_keys), bare) != std::end(start_keys) && p.started_at.empty()) {
    std::string value;
    for (std::size_t i = 1; i < cells.size(); ++i)
      if (!cells[i].empty()) value += (value.empty() ? "" : " ") + std::string(cells[i]);
    p.started_at = as_utf8(value);
  }
}

}  // namespace

char csv_delimiter(std::string_view header) {
  return header.find('\t') != std::string_view::npos ? '\t' : header.find(';') != std::string_view::npos ? ';' : ',';
}

CsvPreamble find_csv_header(std::istream& in, const std::string& file, std::optional<std::size_t> header_line) {
  std::vector<Line> lines;
  std::string text;
  const std::size_t scan = header_line ? std::max(*header_line + kDataRowsChecked + 2, kScanLines) : kScanLines;
  while (lines.size() < scan && std::getline(in, text)) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    lines.push_back({lines.size() + 1, std::move(text)});
    text.clear();
  }
  in.clear();
  in.seekg(0);
  CsvPreamble p;
  if (header_line) {
    if (*header_line < 1 || *header_line > lines.size())
      throw InputError(file + ": the manifest's header_line = " + std::to_string(*header_line) + " but the file has " +
                       std::to_string(lines.size()) + " lines; give the line number of the column names");
    if (blank_or_comment(lines[*header_line - 1].text))
      throw InputError(file + ":" + std::to_string(*header_line) + ": header_line names a blank or comment line; "
                       "give the line number of the column names");
    p.header_line = *header_line;
  } else {
    // The first row directly followed by data rows of as many cells; when the
    // row above it has as many cells, none a number, and this row holds only
    // units ("s;V;V"), that row is the header and this its units row.
    std::size_t previous = lines.size();
    for (std::size_t i = next_content(lines, 0); i < lines.size(); previous = i, i = next_content(lines, i + 1)) {
      const char d = csv_delimiter(lines[i].text);
      const auto cells = split_cells(lines[i].text, d);
      const auto numeric = static_cast<std::size_t>(
          std::count_if(cells.begin(), cells.end(), [&](std::string_view c) { return number(c, d != ',').has_value(); }));
      const std::size_t after = next_content(lines, i + 1);
      const bool data_follow = after < lines.size() && data_rows_follow(lines, after, cells.size(), d);
      if (data_follow && 2 * numeric >= cells.size()) break;  // a data row (a bad cell in it, say): no header below it
      if (!data_follow || numeric > 0) continue;             // column names are not numbers
      p.header_line = lines[i].number;
      if (previous < lines.size() && std::all_of(cells.begin(), cells.end(), unit_like)) {
        const auto above = split_cells(lines[previous].text, d);
        if (above.size() == cells.size() && is_units_row(above)) p.header_line = lines[previous].number;
      }
      break;
    }
    if (p.header_line == 0) {  // no data rows seen: the first row, as before (its errors name what is wrong)
      const std::size_t first = next_content(lines, 0);
      if (first < lines.size()) p.header_line = lines[first].number;
    }
  }
  if (p.header_line > 0) {
    const char d = csv_delimiter(lines[p.header_line - 1].text);
    for (std::size_t i = 0; i + 1 < p.header_line; ++i) {
      if (trim_cell(lines[i].text).empty()) continue;
      ++p.preamble_lines;
      read_preamble_line(lines[i], d, p);
    }
  }
  return p;
}

}  // namespace fourbar
