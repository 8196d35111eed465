#include "app/probe_log.h"

#include <cstdio>

#include "base/error.h"
#include "io/echo.h"

namespace tidepool {

ProbeLog::ProbeLog(std::filesystem::path file) : m_file(std::move(file)), m_out(m_file) {
  if (!m_out) throw Error("cannot write the probes to '" + io::printable(m_file.string()) + "'");
}

void ProbeLog::write(std::uint64_t frame, double time, const ProbeReadings& readings) {
  if (!readings.error.empty()) throw Error(readings.error);
  if (!m_started) {
    m_columns = readings.columns;
    m_out << "time_s,frame";
    for (const std::string& c : m_columns) m_out << "," << c;
    m_out << "\n";
    m_started = true;
  } else if (readings.columns != m_columns) {
    throw Error("the probes changed during the export: probes.csv keeps the columns of its first row");
  }
  char cell[40];
  std::snprintf(cell, sizeof cell, "%.9g", time);
  m_out << cell << "," << frame;
  for (double v : readings.values) {
    std::snprintf(cell, sizeof cell, "%.9g", v);
    m_out << "," << cell;
  }
  m_out << "\n";
  if (!m_out) throw Error("cannot write the probes to '" + io::printable(m_file.string()) + "'");
}

}  // namespace tidepool
