#include "io/csv.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "base/error.h"
#include "io/echo.h"
#include "io/json.h"

namespace tidepool::io {

std::vector<std::string> splitCsvLine(const std::string& text) {
  std::vector<std::string> out(1);
  bool inQuotes = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '"' && inQuotes && i + 1 < text.size() && text[i + 1] == '"')
      out.back() += text[++i];
    else if (ch == '"')
      inQuotes = !inQuotes;
    else if (ch == ',' && !inQuotes)
      out.emplace_back();
    else if (ch != '\r')
      out.back() += ch;
  }
  return out;
}

CsvTable::CsvTable(const std::filesystem::path& file) : m_file(file) {
  std::istringstream lines(readTextFile(file));
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (line.empty() || line == "\r") continue;
    std::vector<std::string> fields = splitCsvLine(line);
    if (m_header.empty()) {
      m_header = std::move(fields);
      continue;
    }
    if (fields.size() != m_header.size())
      throw Error(shownPath(file) + ":" + std::to_string(number) + ": " + std::to_string(fields.size()) +
                  " fields, the header has " + std::to_string(m_header.size()));
    m_cells.push_back(std::move(fields));
    m_lines.push_back(number);
  }
  if (m_cells.empty()) throw Error("'" + shownPath(file) + "' holds no rows");
}

bool CsvTable::has(const std::string& name) const {
  return std::find(m_header.begin(), m_header.end(), name) != m_header.end();
}

std::size_t CsvTable::column(const std::string& name) const {
  const auto it = std::find(m_header.begin(), m_header.end(), name);
  if (it == m_header.end()) throw Error("'" + shownPath(m_file) + "' has no column '" + printable(name) + "'");
  return std::size_t(it - m_header.begin());
}

const std::string& CsvTable::text(std::size_t row, const std::string& name) const { return m_cells[row][column(name)]; }

double CsvTable::number(std::size_t row, const std::string& name) const {
  const std::string& s = text(row, name);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || *end)
    throw Error(where(row) + ": " + printable(name) + " '" + printable(s) + "' is not a number");
  return v;
}

std::string CsvTable::where(std::size_t row) const { return shownPath(m_file) + ":" + std::to_string(m_lines[row]); }

}  // namespace tidepool::io
