// CSV as the sweeps write it (RFC 4180 fields: quoted commas, doubled quotes), read back by
// `tidepool sweep --from-csv` and by the accuracy tables that "method": "auto" picks from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tidepool::io {

// One line split into fields: "a,\"b, c\",d" -> {a, "b, c", d}.
std::vector<std::string> splitCsvLine(const std::string& line);

// A CSV file with a header line, its cells looked up by column name. Errors name file and line.
class CsvTable {
 public:
  explicit CsvTable(const std::filesystem::path& file);  // throws Error (missing, ragged rows, no rows)

  std::size_t rows() const { return m_cells.size(); }
  bool has(const std::string& column) const;
  const std::string& text(std::size_t row, const std::string& column) const;  // throws Error: no such column
  double number(std::size_t row, const std::string& column) const;            // "nan"/"inf" allowed; throws on text
  std::string where(std::size_t row) const;                                   // "file.csv:7" (header is line 1)

 private:
  std::size_t column(const std::string& name) const;

  std::filesystem::path m_file;
  std::vector<std::string> m_header;
  std::vector<std::vector<std::string>> m_cells;
  std::vector<int> m_lines;  // file line of each row
};

}  // namespace tidepool::io
