#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace plywood::eval {

// A CSV file as read by the file scorers: RFC 4180 fields (quoted fields may hold commas, quotes
// doubled, line breaks), LF or CRLF line ends; blank lines are skipped. Every problem is a
// sim::ConfigError "FILE:LINE: FIELD: what is wrong" (exit code 2 in the app).
struct CsvRow {
  std::size_t line_number = 0;  // where the row starts in the file
  std::vector<std::string> fields;
};

struct CsvTable {
  std::string file;                 // as named in messages
  std::vector<std::string> header;  // empty when read without a header
  std::size_t header_line = 0;
  std::vector<CsvRow> rows;

  // Index of a header column, or -1.
  int Column(const std::string& name) const;

  // A field as a finite number / integer. @throws sim::ConfigError naming the file, the row's
  // line and `field` (the column's name).
  double Number(const CsvRow& row, std::size_t column, const std::string& field) const;
  long Integer(const CsvRow& row, std::size_t column, const std::string& field) const;
  [[noreturn]] void Fail(const CsvRow& row, const std::string& field,
                         const std::string& what) const;
};

struct CsvReadOptions {
  bool header = true;         // the first row names the columns; every row must have as many fields
  bool comments = false;      // lines starting with '#' are skipped (files made by other tools)
  bool rows_required = true;  // a file with no rows (after the header) is an error
};

// @throws sim::ConfigError for an unreadable or empty file (see rows_required), an unterminated
// quote, and (with a header) a header of one unquoted column holding tabs or semicolons (a file
// with another separator), a row with a different number of fields or a repeated column name.
CsvTable ReadCsv(const std::filesystem::path& path, const CsvReadOptions& options = {});

// `text` as one CSV field: quoted (quotes doubled) when it holds a comma, a quote or a line break.
std::string CsvField(const std::string& text);

}  // namespace plywood::eval
