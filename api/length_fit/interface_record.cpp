#include "api/length_fit/interface_record.hpp"

#include <utility>

namespace slipfront::api {

const char* column_name(RecordColumn column) {
  switch (column) {
  case RecordColumn::time:
    return "time";
  case RecordColumn::slip_rate:
    return "slip_rate";
  case RecordColumn::contact_pressure:
    return "contact_pressure";
  case RecordColumn::frictional_stress:
    return "frictional_stress";
  }
  return "?";
}

const std::vector<double>& InterfaceRecord::column(RecordColumn c) const {
  switch (c) {
  case RecordColumn::time:
    return time;
  case RecordColumn::slip_rate:
    return slip_rate;
  case RecordColumn::contact_pressure:
    return contact_pressure;
  case RecordColumn::frictional_stress:
    break;
  }
  return frictional_stress;
}

std::vector<double>& InterfaceRecord::column(RecordColumn c) {
  return const_cast<std::vector<double>&>(std::as_const(*this).column(c));
}

std::string describe(const RecordError& e) {
  // Appended piece by piece ("literal" + string trips GCC 12's -Wrestrict here).
  std::string where;
  if (e.line > 0) {
    where.append("line ").append(std::to_string(e.line));
    if (!e.column.empty()) where.append(", column \"").append(e.column).append("\"");
  } else if (!e.column.empty()) {
    where.append("/").append(e.column);
    if (e.index >= 0) where.append("/").append(std::to_string(e.index));
  }
  if (where.empty()) return e.reason;
  return where.append(": ").append(e.reason);
}

RecordError error_at(const InterfaceRecord& record, RecordColumn column, std::size_t index,
                     std::string reason) {
  const RecordSource& s = record.source;
  RecordError e{s.column_names[std::size_t(column)], long(index), 0, std::move(reason)};
  if (index < s.line.size()) e.line = s.line[index];
  return e;
}

} // namespace slipfront::api
