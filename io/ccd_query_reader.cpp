#include "io/ccd_query_reader.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <string>

#include "io/input_error.h"
#include "kernel/collision/continuous_collision.h"

namespace mechanist {

std::vector<CcdQuery> ReadCcdQueries(const std::filesystem::path& path) {
  const std::string name = path.string();
  const bool vertex_face = name.find("vertex-face") != std::string::npos;
  if (!vertex_face && name.find("edge-edge") == std::string::npos) {
    throw InputError(name, "", 0, 0, "expected \"vertex-face\" or \"edge-edge\" in the path");
  }
  std::ifstream in(path);
  if (!in) throw InputError(name, "", 0, 0, "cannot read the file");
  std::vector<CcdQuery> queries;
  int row = 0, line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    if (cells.size() != 7) {
      throw InputError(name, "", line_number, 0,
                       fmt::format("expected 7 columns, found {}", cells.size()));
    }
    if (row % 8 == 0) {
      queries.emplace_back();
      queries.back().vertex_face = vertex_face;
    }
    CcdQuery& q = queries.back();
    try {
      q.points[row % 8] = {ExactRationalToDouble(cells[0], cells[1]),
                           ExactRationalToDouble(cells[2], cells[3]),
                           ExactRationalToDouble(cells[4], cells[5])};
    } catch (const std::invalid_argument& e) {
      throw InputError(name, "", line_number, 0, e.what());
    }
    if (cells[6] != "0" && cells[6] != "1") {
      throw InputError(name, "", line_number, 7,
                       fmt::format("expected 0 or 1, found \"{}\"", cells[6]));
    }
    q.colliding = cells[6] == "1";
    ++row;
  }
  if (row % 8 != 0) {
    throw InputError(name, "", line_number, 0,
                     fmt::format("{} rows, expected a multiple of 8", row));
  }
  return queries;
}

}  // namespace mechanist
