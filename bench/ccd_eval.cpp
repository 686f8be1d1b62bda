// Evaluates the continuous collision queries (kernel/collision/continuous_collision.h) on files in
// the format of ../shared/data/ccd (Continuous-Collision-Detection/Sample-Queries; see
// io/ccd_query_reader.h).
//
// Usage: ccd_eval FILE.csv...   (for example ../shared/data/ccd/*/*/*.csv)
// Prints: queries N, false negatives X, false positives Y, mean us/query Z (and the maximum).

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "io/ccd_query_reader.h"
#include "io/input_error.h"
#include "kernel/collision/continuous_collision.h"

int main(int argc, char** argv) {
  using namespace mechanist;
  if (argc < 2) {
    std::fprintf(stderr, "usage: ccd_eval FILE.csv...\n");
    return 2;
  }
  long queries = 0, false_negatives = 0, false_positives = 0, undecided = 0;
  double total_us = 0, max_us = 0;
  for (int i = 1; i < argc; ++i) {
    std::vector<CcdQuery> file;
    try {
      file = ReadCcdQueries(argv[i]);
    } catch (const InputError& e) {
      std::fprintf(stderr, "ccd_eval: %s\n", e.what());
      return 2;
    }
    for (const CcdQuery& q : file) {
      const auto& r = q.points;
      const auto start = std::chrono::steady_clock::now();
      const CcdAnswer answer = q.vertex_face
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
      false_negatives += q.colliding && !hit;
      false_positives += !q.colliding && hit;
    }
  }
  std::printf("queries %ld, false negatives %ld, false positives %ld, mean us/query %.2f\n",
              queries, false_negatives, false_positives, queries ? total_us / queries : 0.0);
  std::printf("max us/query %.1f, undecided at the time resolution %ld\n", max_us, undecided);
  return 0;
}
