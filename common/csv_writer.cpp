#include "common/csv_writer.hpp"

#include <charconv>
#include <cmath>

#include "common/error.hpp"

namespace fourbar {

std::string format_double(double v) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

CsvWriter::CsvWriter(std::filesystem::path path, const std::vector<std::string>& comments,
                     std::vector<std::string> columns)
    : out_(std::move(path)), columns_(std::move(columns)) {
  for (const auto& c : comments) out_.stream() << "# " << c << '\n';
  for (std::size_t i = 0; i < columns_.size(); ++i) out_.stream() << (i ? "," : "") << columns_[i];
  out_.stream() << '\n';
}

void CsvWriter::check(std::span<const double> values, std::size_t expected) {
  if (values.size() != expected)
    throw RunError(out_.path().string() + ": internal error: row has " + std::to_string(values.size()) +
                   " values for " + std::to_string(expected) + " columns");
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw RunError(out_.path().string() + ": column '" + columns_[i] + "' row " + std::to_string(rows_ + 1) +
                     " is not finite; nothing was written");
}

void CsvWriter::row(std::span<const double> values) {
  check(values, columns_.size());
  line_.clear();
  char buf[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) line_ += ',';
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, values[i]);
    line_.append(buf, end);
  }
  line_ += '\n';
  out_.stream() << line_;
  ++rows_;
}

void CsvWriter::row(std::span<const double> values, const std::string& last_text) {
  check(values, columns_.size() - 1);
  line_.clear();
  char buf[32];
  for (double v : values) {
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    line_.append(buf, end);
    line_ += ',';
  }
  line_ += last_text;
  line_ += '\n';
  out_.stream() << line_;
  ++rows_;
}

void CsvWriter::text_row(std::span<const std::string> cells) {
  if (cells.size() != columns_.size())
    throw RunError(out_.path().string() + ": internal error: row has " + std::to_string(cells.size()) + " cells for " +
                   std::to_string(columns_.size()) + " columns");
  line_.clear();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) line_ += ',';
    if (cells[i].find_first_of(",\"\r\n") == std::string::npos) {
      line_ += cells[i];
      continue;
    }
    line_ += '"';
    for (char ch : cells[i]) line_ += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    line_ += '"';
  }
  line_ += '\n';
  out_.stream() << line_;
  ++rows_;
}

}  // namespace fourbar
