// Evaluates the continuous collision queries (kernel/continuous_collision.h) on files in the
// format of ../shared/data/ccd (Continuous-Collision-Detection/Sample-Queries): 8 rows per
// query, columns numerator/denominator of x, y, z and the ground truth; vertex-face rows
// v_t0, f0_t0, f1_t0, f2_t0, v_t1, f0_t1, f1_t1, f2_t1, edge-edge rows ea0_t0, ea1_t0, eb0_t0,
// eb1_t0, ea0_t1, ea1_t1, eb0_t1, eb1_t1. The kind comes from the path ("vertex-face" or
// "edge-edge").
//
// Usage: ccd_eval FILE.csv...   (for example ../shared/data/ccd/*/*/*.csv)
// Prints: queries N, false negatives X, false positives Y, mean us/query Z (and the maximum).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "kernel/continuous_collision.h"

int main(int argc, char** argv) {
  using namespace mechanist;
  if (argc < 2) {
    std::fprintf(stderr, "usage: ccd_eval FILE.csv...\n");
    return 2;
  }
  long queries = 0, false_negatives = 0, false_positives = 0, undecided = 0;
  double total_us = 0, max_us = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string path = argv[i];
    const bool vertex_face = path.find("vertex-face") != std::string::npos;
    if (!vertex_face && path.find("edge-edge") == std::string::npos) {
      std::fprintf(stderr, "ccd_eval: %s: expected \"vertex-face\" or \"edge-edge\" in the path\n",
                   path.c_str());
      return 2;
    }
    std::ifstream in(path);
    if (!in) {
      std::fprintf(stderr, "ccd_eval: %s: cannot read\n", path.c_str());
      return 2;
    }
    std::vector<Eigen::Vector3d> rows;
    std::vector<int> truth;
    std::string line;
    long line_number = 0;
    while (std::getline(in, line)) {
      ++line_number;
      if (line.empty() || line == "\r") continue;
      std::vector<std::string> cells;
      std::stringstream s(line);
      for (std::string cell; std::getline(s, cell, ',');) {
        if (!cell.empty() && cell.back() == '\r') cell.pop_back();
        cells.push_back(cell);
      }
      if (cells.size() != 7) {
        std::fprintf(stderr, "ccd_eval: %s:%ld: expected 7 columns, found %zu\n", path.c_str(),
                     line_number, cells.size());
        return 2;
      }
      try {
        rows.emplace_back(ExactRationalToDouble(cells[0], cells[1]),
                          ExactRationalToDouble(cells[2], cells[3]),
                          ExactRationalToDouble(cells[4], cells[5]));
      } catch (const std::exception& e) {
        std::fprintf(stderr, "ccd_eval: %s:%ld: %s\n", path.c_str(), line_number, e.what());
        return 2;
      }
      truth.push_back(std::stoi(cells[6]));
    }
    if (rows.size() % 8 != 0) {
      std::fprintf(stderr, "ccd_eval: %s: %zu rows, expected a multiple of 8\n", path.c_str(),
                   rows.size());
      return 2;
    }
    for (std::size_t q = 0; q < rows.size(); q += 8) {
      const auto* r = &rows[q];
      const auto start = std::chrono::steady_clock::now();
      const CcdAnswer answer = vertex_face
                                   ? VertexFaceCcd(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7])
                                   : EdgeEdgeCcd(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]);
      const double us =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
              .count();
      total_us += us;
      max_us = std::max(max_us, us);
      const bool hit = answer != CcdAnswer::kApart;
      undecided += answer == CcdAnswer::kMaybe;
      ++queries;
      false_negatives += truth[q] == 1 && !hit;
      false_positives += truth[q] == 0 && hit;
    }
  }
  std::printf("queries %ld, false negatives %ld, false positives %ld, mean us/query %.2f\n",
              queries, false_negatives, false_positives, queries ? total_us / queries : 0.0);
  std::printf("max us/query %.1f, undecided at the time resolution %ld\n", max_us, undecided);
  return 0;
}
