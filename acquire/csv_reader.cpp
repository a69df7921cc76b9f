#include "acquire/csv_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "acquire/csv_preamble.hpp"
#include "acquire/csv_units.hpp"
#include "acquire/text_cells.hpp"
#include "common/error.hpp"
#include "common/number_text.hpp"
#include "common/toml_section.hpp"

namespace fourbar {

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "'" : ", '") + n + "'";
  return s;
}

bool is_skipped(std::string_view line) {
  const std::string_view t = trim_cell(line);
  return t.empty() || t.front() == '#';
}

/// Seconds per unit of a time column, or 0 when `name` is not a time column.
double time_column_unit_s(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  static const std::regex seconds(R"((t|time)(_s|\s*\[s\]|\s*\(s\))?)"), millis(R"((t|time)(_ms|\s*\[ms\]|\s*\(ms\)))");
  if (std::regex_match(name, seconds)) return 1.0;
  if (std::regex_match(name, millis)) return 1e-3;
  return 0.0;
}

class CsvReader final : public Reader {
 public:
  CsvReader(const std::filesystem::path& file, const ReaderOptions& options) : file_(file) {
    info_.file = file;
    info_.format = "CSV";
    info_.sample_format = "TEXT";
    open_stream();
    // Header: the first row followed by data rows of as many cells, below any
    // preamble (or the manifest's header_line); the first line that is
    // neither blank nor a comment when no data rows follow one.
    const CsvPreamble preamble = find_csv_header(in_, file.string(), options.header_line);
    std::string line;
    while (std::getline(in_, line)) {
      ++line_no_;
      strip_cr(line);
      if (line_no_ == preamble.header_line) break;
      line.clear();
    }
    if (line.empty()) throw InputError(file.string() + ": no header row (the file is empty or only comments)");
    header_line_ = line_no_;
    delimiter_ = csv_delimiter(line);
    for (auto cell : split_cells(line, delimiter_)) names_.push_back(as_utf8(cell));
    for (std::size_t c = 0; c < names_.size(); ++c) {
      if (names_[c].empty())
        throw InputError(where(header_line_, c) + ": empty column name in the header row; name every column");
      for (std::size_t d = 0; d < c; ++d)
        if (names_[d] == names_[c])
          throw InputError(where(header_line_, c) + ": column name '" + names_[c] + "' appears twice in the header");
    }
    // Units: in the header (`coupler_t [V]`) or a row of units under it.
    std::vector<std::string> bare, units;
    for (const auto& n : names_) {
      auto [name, unit] = split_unit(n);
      bare.push_back(std::move(name)), units.push_back(std::move(unit));
    }
    std::streampos after_header = in_.tellg();
    while (std::getline(in_, line)) {
      ++line_no_;
      strip_cr(line);
      if (is_skipped(line)) {
        after_header = in_.tellg();
        continue;
      }
      const auto cells = split_cells(line, delimiter_);
      const bool short_cells = std::all_of(cells.begin(), cells.end(), [](std::string_view c) { return c.size() <= 24; });
      if (cells.size() == names_.size() && short_cells && is_units_row(cells)) {
        for (std::size_t c = 0; c < cells.size(); ++c)
          if (auto u = unit_cell(cells[c]); !u.empty()) units[c] = as_utf8(u);
        units_line_ = line_no_;
      } else {
        in_.clear();
        in_.seekg(after_header);
        --line_no_;
      }
      break;
    }
    if (units_line_ == 0) {  // nothing consumed but blank or comment lines: count them back
      in_.clear();
      in_.seekg(after_header);
    }
    // Time column: named by the manifest, else recognised by its name.
    if (options.time_column) {
      auto it = std::find(names_.begin(), names_.end(), *options.time_column);
      if (it == names_.end()) it = std::find(bare.begin(), bare.end(), *options.time_column) - bare.begin() + names_.begin();
      if (it == names_.end()) {
        std::string hint;
        if (auto m = closest_match(*options.time_column, names_)) hint = " (did you mean '" + *m + "'?)";
        throw InputError(file.string() + ":" + std::to_string(header_line_) + ": the manifest's time_column '" +
                         *options.time_column + "' is not in the header" + hint + "; its columns: " + joined(names_));
      }
      time_col_ = static_cast<int>(it - names_.begin());
      const std::size_t c = static_cast<std::size_t>(time_col_);
      const double u = time_column_unit_s(units[c].empty() ? names_[c] : bare[c] + "_" + units[c]);
      time_unit_s_ = u > 0 ? u : 1.0;
    } else {
      for (std::size_t c = 0; c < names_.size() && time_col_ < 0; ++c)  // `time [ms]`, or `time` over `ms`
        if (double u = time_column_unit_s(units[c].empty() ? names_[c] : bare[c] + "_" + units[c]); u > 0)
          time_col_ = static_cast<int>(c), time_unit_s_ = u;
    }
    bool any_unit = false;
    for (std::size_t c = 0; c < names_.size(); ++c)
      if (static_cast<int>(c) != time_col_) {
        info_.channel_names.push_back(bare[c]);
        info_.channel_units.push_back(units[c]);
        any_unit = any_unit || !units[c].empty();
      }
    if (!any_unit) info_.channel_units.clear();
    for (std::size_t c = 0; c < info_.channel_names.size(); ++c)
      for (std::size_t d = 0; d < c; ++d)
        if (info_.channel_names[c] == info_.channel_names[d])
          throw InputError(file.string() + ":" + std::to_string(header_line_) + ": two columns are named '" +
                           info_.channel_names[c] + "' once their units are set aside; name every column differently");
    info_.channels = static_cast<int>(info_.channel_names.size());
    if (info_.channels == 0) throw InputError(file.string() + ": only a time column; the recording needs channels");
    data_start_ = in_.tellg();
    data_start_line_ = line_no_;

    // Count the rows and read the first two and the last times (cells are
    // checked when the rows are read).
    std::string first, last;
    std::size_t first_line = 0, last_line = 0, line_no = line_no_;
    std::uint64_t rows = 0;
    while (std::getline(in_, line)) {
      ++line_no;
      if (is_skipped(line)) continue;
      if (rows == 0) first = line, first_line = line_no;
      last = std::move(line);
      last_line = line_no;
      ++rows;
    }
    if (rows == 0) throw InputError(file.string() + ": a header but no data rows");
    info_.frames = rows;
    if (options.sample_rate_hz) {
      if (!(*options.sample_rate_hz > 0) || !std::isfinite(*options.sample_rate_hz))
        throw InputError(file.string() + ": sample rate " + std::to_string(*options.sample_rate_hz) +
                         " Hz from the manifest must be positive");
      info_.sample_rate_hz = *options.sample_rate_hz;
      uniform_check_ = false;
      if (preamble.sample_rate_hz && std::abs(*preamble.sample_rate_hz - info_.sample_rate_hz) > 1e-9 * info_.sample_rate_hz)
        throw InputError(file.string() + ": the manifest's sample_rate_hz = " + format_double(info_.sample_rate_hz) +
                         " contradicts the preamble's " + format_double(*preamble.sample_rate_hz) + " Hz (line " +
                         std::to_string(preamble.rate_line) + "); delete sample_rate_hz from the manifest");
    } else if (time_col_ >= 0) {
      if (rows < 2) throw InputError(file.string() + ": one data row: the time column cannot give a sample rate");
      strip_cr(first), strip_cr(last);
      const double t0 = time_of(first, first_line), tn = time_of(last, last_line);
      if (!(tn > t0))
        throw InputError(file.string() + ": the time column '" + names_[time_col_] +
                         "' does not increase (first " + std::to_string(t0) + ", last " + std::to_string(tn) +
                         "): zero sample rate; fix the time column or give sample_rate_hz in the manifest");
      info_.sample_rate_hz = static_cast<double>(rows - 1) / (tn - t0);
      info_.start_time_s = t0;
      if (preamble.sample_rate_hz) {  // the stated rate, exact, when the time column agrees to half a sample
        const double stated = *preamble.sample_rate_hz;
        if (std::abs((tn - t0) - static_cast<double>(rows - 1) / stated) > 0.5 / stated)
          throw InputError(file.string() + ":" + std::to_string(preamble.rate_line) + ": the preamble states " +
                           format_double(stated) + " Hz but the time column '" + names_[time_col_] + "' spans " +
                           format_double(tn - t0) + " s over " + std::to_string(rows - 1) + " intervals (" +
                           format_double(info_.sample_rate_hz) + " Hz); one of them is wrong: fix it, or give "
                           "sample_rate_hz in the manifest");
        info_.sample_rate_hz = stated;
      }
    } else if (preamble.sample_rate_hz) {
      info_.sample_rate_hz = *preamble.sample_rate_hz;
      uniform_check_ = false;
    } else {
      throw InputError(file.string() + ": no time column (name one 'time_s', or set time_column), no sample rate in a "
                       "preamble above the header ('Sample rate;12800;Hz') and the manifest gives no sample_rate_hz; "
                       "add one of them");
    }
    info_.started_at = preamble.started_at;
    if (preamble.preamble_lines > 0) {
      std::string n = "column names on line " + std::to_string(header_line_) + ", below " +
                      std::to_string(preamble.preamble_lines) + " preamble line" + (preamble.preamble_lines == 1 ? "" : "s");
      if (preamble.sample_rate_hz)
        n += "; sample rate " + format_double(*preamble.sample_rate_hz) + " Hz from line " + std::to_string(preamble.rate_line);
      if (!preamble.started_at.empty()) n += "; start " + preamble.started_at;
      info_.notes.push_back(n);
    }
    rewind();
  }

  std::size_t read(std::span<double> out) override {
    const auto channels = static_cast<std::size_t>(info_.channels);
    const std::size_t want = out.size() / channels;
    std::size_t got = 0;
    std::string line;
    while (got < want && std::getline(in_, line)) {
      ++line_no_;
      strip_cr(line);
      if (is_skipped(line)) continue;
      const auto cells = split_cells(line, delimiter_);
      if (cells.size() != names_.size())
        throw InputError(file_.string() + ":" + std::to_string(line_no_) + ": " + std::to_string(cells.size()) +
                         " cells but the header has " + std::to_string(names_.size()) +
                         " columns (a truncated or damaged row); fix or delete the row");
      std::size_t k = 0;
      for (std::size_t c = 0; c < cells.size(); ++c) {
        const double v = parse(cells[c], line_no_, c);
        if (static_cast<int>(c) == time_col_) {
          if (uniform_check_) check_time(v * time_unit_s_, line_no_, c);
        } else {
          out[got * channels + k++] = v;
        }
      }
      ++got;
      ++row_;
    }
    return got;
  }

  void rewind() override {
    in_.clear();
    in_.seekg(data_start_);
    line_no_ = data_start_line_;
    row_ = 0;
  }

 private:
  void open_stream() {
    in_.open(file_, std::ios::binary);
    if (!in_) throw InputError(file_.string() + ": cannot open (check the path and permissions)");
  }
  static void strip_cr(std::string& line) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
  }
  std::string where(std::size_t line, std::size_t column) const {
    std::string s = file_.string() + ":" + std::to_string(line) + ":" + std::to_string(column + 1);
    if (column < names_.size()) s += " (column '" + names_[column] + "')";
    return s;
  }
  double parse(std::string_view cell, std::size_t line, std::size_t column) const {
    std::string buf;
    if (delimiter_ != ',' && cell.find(',') != std::string_view::npos) {
      buf.assign(cell);
      std::replace(buf.begin(), buf.end(), ',', '.');
      cell = buf;
    }
    if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
    double v = 0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
    if (cell.empty() || ec != std::errc() || end != cell.data() + cell.size() || !std::isfinite(v))
      throw InputError(where(line, column) + ": '" + std::string(cell) + "' is not a finite number" +
                       (cell.empty() ? std::string(" (empty cell)") : std::string()) +
                       "; every sample must be a number (fix or cut the row)");
    return v;
  }
  double time_of(const std::string& line, std::size_t line_no) const {
    const auto cells = split_cells(line, delimiter_);
    if (static_cast<std::size_t>(time_col_) >= cells.size())
      throw InputError(file_.string() + ":" + std::to_string(line_no) +
                       ": row has fewer cells than the header (a truncated or damaged row); fix or delete it");
    return parse(cells[static_cast<std::size_t>(time_col_)], line_no, static_cast<std::size_t>(time_col_)) *
           time_unit_s_;
  }
  void check_time(double t, std::size_t line, std::size_t column) {
    const double expected = info_.start_time_s + static_cast<double>(row_) / info_.sample_rate_hz;
    const double step = row_ > 0 ? (t - previous_time_) * info_.sample_rate_hz : 1.0;
    previous_time_ = t;
    if (std::abs(t - expected) > 0.5 / info_.sample_rate_hz || std::abs(step - 1.0) > 0.5) {
      std::ostringstream os;
      os.precision(10);
      os << where(line, column) << ": time " << t << " s is not uniform: sampling at " << info_.sample_rate_hz
         << " Hz puts this row at " << expected << " s (a gap, a repeat or jitter of more than half a sample); "
         << "acquire needs uniformly sampled rows";
      throw InputError(os.str());
    }
  }

  std::filesystem::path file_;
  std::ifstream in_;
  std::vector<std::string> names_;
  char delimiter_ = ',';
  int time_col_ = -1;
  double time_unit_s_ = 1.0;
  bool uniform_check_ = true;
  std::streampos data_start_{};
  std::size_t header_line_ = 0, units_line_ = 0, data_start_line_ = 0, line_no_ = 0;
  std::uint64_t row_ = 0;
  double previous_time_ = 0;
};

}  // namespace

bool csv_claims(const std::filesystem::path& file, std::span<const unsigned char>) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".csv" || ext == ".tsv" || ext == ".txt";
}

std::unique_ptr<Reader> open_csv_reader(const std::filesystem::path& file, const ReaderOptions& options) {
  return std::make_unique<CsvReader>(file, options);
}

}  // namespace fourbar
