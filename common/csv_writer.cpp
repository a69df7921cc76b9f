#include "common/csv_writer.hpp"

#include <cmath>

#include "common/error.hpp"
#include "common/json_text.hpp"

namespace fourbar {

std::filesystem::path csv_sidecar_path(const std::filesystem::path& csv) {
  std::filesystem::path p = csv;
  p += ".json";
  return p;
}

CsvWriter::CsvWriter(std::filesystem::path path, const std::vector<std::string>& comments,
                     std::vector<std::string> columns)
    : out_(std::move(path)), columns_(std::move(columns)) {
  for (const auto& c : comments) out_.stream() << "# " << c << '\n';
  line_.clear();
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) line_ += ',';
    append_text(columns_[i]);
  }
  out_.stream() << line_ << '\n';
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

void CsvWriter::append_text(const std::string& cell) {
  if (cell.find_first_of(",\"\r\n") == std::string::npos) {
    line_ += cell;
    return;
  }
  line_ += '"';
  for (char ch : cell) {
    if (ch == '"') line_ += '"';
    line_ += ch;
  }
  line_ += '"';
}

void CsvWriter::row(std::span<const double> values) {
  check(values, columns_.size());
  line_.clear();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) line_ += ',';
    append_double(line_, values[i]);
  }
  line_ += '\n';
  out_.stream() << line_;
  ++rows_;
}

void CsvWriter::row(std::span<const double> values, const std::string& last_text) {
  check(values, columns_.size() - 1);
  line_.clear();
  for (double v : values) {
    append_double(line_, v);
    line_ += ',';
  }
  append_text(last_text);
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
    append_text(cells[i]);
  }
  line_ += '\n';
  out_.stream() << line_;
  ++rows_;
}

void CsvWriter::describe_in_sidecar(nlohmann::json provenance) { sidecar_ = std::move(provenance); }

void CsvWriter::commit() {
  if (sidecar_) {
    const nlohmann::json j = {{"file", out_.path().filename().string()},
                              {"columns", columns_},
                              {"rows", rows_},
                              {"provenance", *sidecar_}};
    write_text_file(csv_sidecar_path(out_.path()), json_text(j, 2) + "\n");
  }
  out_.commit();
}

}  // namespace fourbar
