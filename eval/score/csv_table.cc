#include "eval/score/csv_table.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "perception/logs/byte_order_mark.h"
#include "perception/logs/parse_number.h"
#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"

namespace plywood::eval {
namespace {

// Why `text` is not a finite number, in words.
std::string NotANumber(const std::string& text) {
  if (text.empty()) return "empty, expected a number";
  const double value = std::strtod(text.c_str(), nullptr);
  if (std::isnan(value) || std::isinf(value)) return "must be finite, got '" + text + "'";
  return "not a number: '" + text + "'";
}

}  // namespace

int CsvTable::Column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

void CsvTable::Fail(const CsvRow& row, const std::string& field, const std::string& what) const {
  throw sim::ConfigError(file + ":" + std::to_string(row.line_number), field, what);
}

double CsvTable::Number(const CsvRow& row, std::size_t column, const std::string& field) const {
  const std::string& text = row.fields.at(column);
  const std::optional<double> value = perception::ParseFiniteNumber(text);
  if (!value) Fail(row, field, NotANumber(text));
  return *value;
}

long CsvTable::Integer(const CsvRow& row, std::size_t column, const std::string& field) const {
  const std::string& text = row.fields.at(column);
  const std::optional<double> value = perception::ParseFiniteNumber(text);
  if (!value) Fail(row, field, NotANumber(text));
  if (*value != std::floor(*value) || std::abs(*value) > 1e15) {
    Fail(row, field, "expected a whole number, got '" + text + "'");
  }
  return static_cast<long>(*value);
}

CsvTable ReadCsv(const std::filesystem::path& path, const CsvReadOptions& options) {
  CsvTable table;
  table.file = path.string();
  if (!perception::IsRegularFile(path)) {
    throw sim::ConfigError(table.file, "", perception::WhyNotARegularFile(path));
  }
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw sim::ConfigError(table.file, "", "cannot read the file");

  std::size_t line = 1;
  // A UTF-8 byte-order mark (an editor's "UTF-8 with BOM") was read as part of the first column's
  // name: "\xEF\xBB\xBFscan: unknown column", the mark invisible in the message.
  std::size_t i =
      text.starts_with(perception::kUtf8ByteOrderMark) ? perception::kUtf8ByteOrderMark.size() : 0;
  bool have_header = !options.header;
  while (i < text.size()) {
    CsvRow row;
    row.line_number = line;
    if (options.comments && text[i] == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
      ++i, ++line;
      continue;
    }
    std::string field;
    bool quoted_field = false;
    for (;;) {
      if (i < text.size() && text[i] == '"' && field.empty() && !quoted_field) {
        quoted_field = true;
        ++i;
        for (;;) {
          if (i >= text.size()) {
            throw sim::ConfigError(table.file + ":" + std::to_string(row.line_number), "",
                                   "a quoted field is never closed");
          }
          if (text[i] == '"') {
            if (i + 1 < text.size() && text[i + 1] == '"') {
              field += '"';
              i += 2;
              continue;
            }
            ++i;
            break;
          }
          if (text[i] == '\n') ++line;
          field += text[i++];
        }
        continue;
      }
      const bool crlf =
          i < text.size() && text[i] == '\r' && (i + 1 == text.size() || text[i + 1] == '\n');
      if (i >= text.size() || text[i] == '\n' || crlf) {
        row.fields.push_back(std::move(field));
        if (i < text.size()) i += crlf ? 2 : 1;
        ++line;
        break;
      }
      if (text[i] == ',') {
        row.fields.push_back(std::move(field));
        field.clear();
        quoted_field = false;
        ++i;
        continue;
      }
      field += text[i++];
    }
    if (row.fields.size() == 1 && row.fields[0].empty() && !quoted_field) continue;  // blank
    if (!have_header) {
      table.header = row.fields;
      table.header_line = row.line_number;
      have_header = true;
      // A file separated by tabs or semicolons (a spreadsheet's export) read as one column whose
      // name was the whole header, tabs and all: "scan<TAB>extractor...: unknown column".
      if (row.fields.size() == 1 && !quoted_field &&
          row.fields[0].find_first_of("\t;") != std::string::npos) {
        const bool tabs = row.fields[0].find('\t') != std::string::npos;
        table.Fail(row, "header",
                   std::string("one column whose name holds ") + (tabs ? "tabs" : "semicolons") +
                       ": columns are separated by commas (RFC 4180); write the file with commas");
      }
      for (std::size_t c = 0; c < table.header.size(); ++c) {
        if (std::count(table.header.begin(), table.header.end(), table.header[c]) > 1) {
          table.Fail(row, table.header[c], "the header names this column twice");
        }
      }
      continue;
    }
    if (options.header && row.fields.size() != table.header.size()) {
      const bool short_row = row.fields.size() < table.header.size();
      table.Fail(row, short_row ? table.header[row.fields.size()] : "line",
                 "wrong column count: " + std::to_string(row.fields.size()) +
                     " fields, the header has " + std::to_string(table.header.size()));
    }
    table.rows.push_back(std::move(row));
  }
  if (table.rows.empty() && (options.rows_required || table.header.empty())) {
    throw sim::ConfigError(table.file, "",
                           table.header.empty() ? "empty file" : "no rows after the header");
  }
  return table;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace plywood::eval
