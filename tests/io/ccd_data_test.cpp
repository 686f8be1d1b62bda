// Every query of the public continuous collision data (../shared/data/ccd, exact ground
// truth): no false negative.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/ccd_query_reader.h"
#include "io/input_error.h"
#include "kernel/collision/continuous_collision.h"

namespace mechanist {
namespace {

// As measured, no false positive either; at most a couple of queries undecided at the time
// resolution.
TEST(ContinuousCollisionData, EveryQueryOfTheSampleSetIsAnsweredWithoutFalseNegatives) {
  int queries = 0, false_negatives = 0, false_positives = 0, maybe = 0;
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(std::string(MECHANIST_SHARED_DATA) + "/ccd")) {
    if (entry.path().extension() != ".csv") continue;
    for (const CcdQuery& q : ReadCcdQueries(entry.path())) {
      const auto& r = q.points;
      const CcdAnswer a = q.vertex_face
                              ? VertexFaceCcd(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7])
                              : EdgeEdgeCcd(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]);
      ++queries;
      maybe += a == CcdAnswer::kMaybe;
      false_negatives += q.colliding && a == CcdAnswer::kApart;
      false_positives += !q.colliding && a == CcdAnswer::kContact;
      EXPECT_FALSE(q.colliding && a == CcdAnswer::kApart) << entry.path() << " query " << queries;
    }
  }
  EXPECT_EQ(queries, 2824);
  EXPECT_EQ(false_negatives, 0);
  EXPECT_EQ(false_positives, 0) << "a proven contact where the data says none";
  EXPECT_LE(maybe, 2);
}

TEST(CcdQueryReader, BadRowsNameTheFileAndLine) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_ccd";
  std::filesystem::create_directories(dir / "vertex-face");
  const auto file = dir / "vertex-face" / "bad.csv";
  std::ofstream(file) << "0,1,0,1,0,1,0\n1,3,0,1,0,1,0\n";
  try {
    ReadCcdQueries(file);
    ADD_FAILURE() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not exactly a double"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ReadCcdQueries(dir / "other.csv"), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mechanist
