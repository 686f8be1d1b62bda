// libFuzzer harness of the CCD query reader (../shared/data/ccd): the input is a query file;
// its first byte chooses vertex-face or edge-edge queries (the reader takes the kind from the
// path), and every query read is answered by both continuous collision tests.
#include "fuzz/fuzz_input.h"
#include "io/ccd_query_reader.h"
#include "kernel/collision/continuous_collision.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool vertex_face = data[0] % 2 == 0;
  const auto path = mechanist::fuzz::WriteInput(data + 1, size - 1,
                                                vertex_face ? "vertex-face.csv" : "edge-edge.csv");
  mechanist::fuzz::ExpectOnlyInputErrors([&] {
    for (const mechanist::CcdQuery& q : mechanist::ReadCcdQueries(path)) {
      const auto& p = q.points;
      if (q.vertex_face) {
        mechanist::VertexFaceCcd(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]);
      } else {
        mechanist::EdgeEdgeCcd(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]);
      }
    }
  });
  return 0;
}
