// Off-screen rendering under an X display (the test suite runs under xvfb-run): frames change
// only where moving parts are, clashes turn parts red, gaps show, and the encoders write
// playable files.

#include "viz/motion_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/load_assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "reasoning/analysis.h"
#include "reasoning/animation.h"
#include "reasoning/gap_search.h"
#include "reasoning/motion_run.h"
#include "viz/display.h"
#include "viz/png_encoder.h"
#include "viz/video_writer.h"

namespace mechanist {
namespace {

std::string Example(const std::string& name) {
  return std::string(MECHANIST_SOURCE_DIR) + "/examples/" + name + "/assembly.json";
}

struct Scene {
  Assembly assembly;
  Analysis analysis;
  Animation animation;
  Scene(const std::string& example, std::size_t frames, double amount)
      : assembly(LoadAssembly(Example(example))),
        analysis(Analyze(assembly)),
        animation(SampleRun(assembly, PlanRun(assembly, analysis, std::nullopt, amount), frames)) {}
};

RenderOptions Small() {
  RenderOptions options;
  options.width = 320;
  options.height = 240;
  options.feature_axes = false;
  return options;
}

constexpr int kTitleRows = 32;  // the title's band at the top (font height/32, 10 px margin)

bool Same(const Image& a, const Image& b, int x, int y) {
  return std::memcmp(a.At(x, y), b.At(x, y), 3) == 0;
}

bool Reddish(const std::uint8_t* p) { return p[0] > 100 && p[0] > 4 * p[1] && p[0] > 4 * p[2]; }

TEST(MotionRenderer, FramesChangeWhereTheMovingPartsAreAndNowhereElse) {
  ASSERT_TRUE(DisplayAvailable(nullptr)) << "the viz tests need an X display (xvfb-run)";
  Scene scene("robot_hand_worm", 5, 0.25);
  MotionRenderer renderer(scene.assembly, scene.analysis, scene.animation, Small());
  const Image first = renderer.Render(0);
  const Image last = renderer.Render(4);
  ASSERT_EQ(first.width, 320);
  ASSERT_EQ(first.height, 240);
  ASSERT_EQ(first.rgb.size(), 320u * 240u * 3u);
  // Where the moving parts can appear: their world boxes over all frames, projected.
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e9), hi = -lo;
  for (const AssemblyState& state : scene.animation.states) {
    for (std::size_t p = 0; p < scene.assembly.parts().size(); ++p) {
      if (scene.animation.run.paths[p].still()) continue;
      const Aabb box = WorldBox(scene.assembly, state, p);
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d corner((c & 1) ? box.max.x() : box.min.x(),
                                     (c & 2) ? box.max.y() : box.min.y(),
                                     (c & 4) ? box.max.z() : box.min.z());
        const Eigen::Vector2d pixel = renderer.PixelOf(corner);
        lo = lo.cwiseMin(pixel);
        hi = hi.cwiseMax(pixel);
      }
    }
  }
  lo.array() -= 3;  // antialiasing spreads an edge by a pixel or two
  hi.array() += 3;
  auto moving = [&](int x, int y) {
    return x >= lo.x() && x <= hi.x() && y >= lo.y() && y <= hi.y();
  };
  int changed_inside = 0, changed_outside = 0, ground_outside = 0, title_changed = 0;
  for (int y = 0; y < first.height; ++y) {
    for (int x = 0; x < first.width; ++x) {
      const bool same = Same(first, last, x, y);
      if (y < kTitleRows) {
        title_changed += !same;
        continue;
      }
      if (moving(x, y)) {
        changed_inside += !same;
        continue;
      }
      changed_outside += !same;
      const std::uint8_t* p = first.At(x, y);  // muted grey: a ground part, not the background
      ground_outside += std::abs(p[0] - p[1]) < 10 && p[0] < 200 && p[2] <= p[0] + 6;
    }
  }
  EXPECT_EQ(changed_outside, 0);
  EXPECT_GT(changed_inside, 100);
  EXPECT_GT(ground_outside, 500);  // the test sees ground parts that must not change
  EXPECT_GT(title_changed, 0);     // the driver's angle in the title
  // The same frame renders to the same pixels.
  EXPECT_EQ(renderer.Render(4).rgb, last.rgb);
}

TEST(MotionRenderer, APartTurnsRedFromItsFirstClashOn) {
  Scene scene("robot_hand_worm", 4, 0.3);
  const std::size_t wheel = *scene.assembly.FindPart("worm_wheel");
  scene.animation.clash_from[wheel] = scene.animation.s[2];
  MotionRenderer renderer(scene.assembly, scene.analysis, scene.animation, Small());
  auto red = [](const Image& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) n += Reddish(image.At(x, y));
    }
    return n;
  };
  EXPECT_EQ(red(renderer.Render(1)), 0);
  EXPECT_GT(red(renderer.Render(2)), 200);
  EXPECT_GT(red(renderer.Render(3)), 200);
}

TEST(MotionRenderer, FeatureAxesAndGapsShow) {
  Scene worm("robot_hand_worm", 1, 0.0);
  RenderOptions with_axes = Small();
  with_axes.feature_axes = true;
  const Image plain =
      MotionRenderer(worm.assembly, worm.analysis, worm.animation, Small()).Render(0);
  const Image axes =
      MotionRenderer(worm.assembly, worm.analysis, worm.animation, with_axes).Render(0);
  EXPECT_NE(plain.rgb, axes.rgb);

  Scene box("sealed_enclosure", 1, 0.0);
  GapSearchOptions options;
  options.voxel = 2.0;
  const TriangleMesh gaps = GapSurface(FindGaps(box.assembly, options));
  ASSERT_FALSE(gaps.faces.empty());
  auto blue = [](const Image& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const std::uint8_t* p = image.At(x, y);
        n += p[2] > 100 && p[2] > 2 * p[0];
      }
    }
    return n;
  };
  EXPECT_EQ(blue(MotionRenderer(box.assembly, box.analysis, box.animation, Small()).Render(0)), 0);
  EXPECT_GT(
      blue(MotionRenderer(box.assembly, box.analysis, box.animation, Small(), &gaps).Render(0)),
      500);
}

TEST(MotionRenderer, AFeaturesOnlyPartIsDrawnByItsAxesWhichTurnWithIt) {
  // A kinematic sketch: no part has a mesh. Even without the axes option, each part shows as
  // its feature axes, and the carrier's pin axis moves as the sun turns it.
  Scene sketch("planetary_differential_sketch", 2, 0.25);
  MotionRenderer renderer(sketch.assembly, sketch.analysis, sketch.animation, Small());
  const Image first = renderer.Render(0);
  const Image later = renderer.Render(1);
  int drawn = 0, changed = 0;
  for (int y = kTitleRows; y < first.height; ++y) {
    for (int x = 0; x < first.width; ++x) {
      const std::uint8_t* p = first.At(x, y);
      // Background is a vertical gradient: compare with the pixel at the row's far right.
      drawn += std::memcmp(p, first.At(first.width - 1, y), 3) != 0;
      changed += !Same(first, later, x, y);
    }
  }
  EXPECT_GT(drawn, 200);
  EXPECT_GT(changed, 20);
  if (const char* dir = std::getenv("MECHANIST_TEST_PICTURES")) {
    std::ofstream(std::filesystem::path(dir) / "sketch.png", std::ios::binary) << EncodePng(first);
  }
}

TEST(MotionRenderer, RefusesBadSizesAndExplainsAMissingDisplay) {
  Scene scene("robot_hand_worm", 1, 0.0);
  RenderOptions tiny = Small();
  tiny.width = 8;
  EXPECT_THROW(MotionRenderer(scene.assembly, scene.analysis, scene.animation, tiny),
               std::invalid_argument);
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display ? display : "";
  ::unsetenv("DISPLAY");
  std::string reason;
  EXPECT_FALSE(DisplayAvailable(&reason));
  EXPECT_NE(reason.find("xvfb-run"), std::string::npos) << reason;
  EXPECT_THROW(MotionRenderer(scene.assembly, scene.analysis, scene.animation, Small()),
               std::runtime_error);
  ::setenv("DISPLAY", saved.c_str(), 1);
  EXPECT_EQ(ParseView("top"), View::kTop);
  EXPECT_FALSE(ParseView("diagonal").has_value());
}

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

Image Gradient(int width, int height, int shift) {
  Image image{width, height,
              std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = static_cast<std::uint8_t>(i / 3 + shift);
  return image;
}

TEST(Encoders, PngHasItsSignatureAndSize) {
  const std::string png = EncodePng(Gradient(37, 21, 0));
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  auto big_endian = [&](std::size_t at) {
    return (std::uint8_t(png[at]) << 24) | (std::uint8_t(png[at + 1]) << 16) |
           (std::uint8_t(png[at + 2]) << 8) | std::uint8_t(png[at + 3]);
  };
  EXPECT_EQ(big_endian(16), 37);
  EXPECT_EQ(big_endian(20), 21);
}

TEST(Encoders, VideosAppearOnlyWhenFinished) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_video_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    auto ogg = MakeOggTheoraWriter(dir / "a.ogv", 10);
    for (int k = 0; k < 5; ++k) ogg->Add(Gradient(64, 48, 10 * k));
    ogg->Finish();
  }
  EXPECT_EQ(ReadFile(dir / "a.ogv").substr(0, 4), "OggS");
  ASSERT_TRUE(FfmpegAvailable()) << "the suite installs ffmpeg";
  {
    auto mp4 = MakeMp4Writer(dir / "a.mp4", 10);
    for (int k = 0; k < 5; ++k) mp4->Add(Gradient(65, 47, 10 * k));  // odd sizes are padded
    mp4->Finish();
  }
  EXPECT_EQ(ReadFile(dir / "a.mp4").substr(4, 4), "ftyp");
  {
    auto abandoned = MakeOggTheoraWriter(dir / "b.ogv", 10);
    abandoned->Add(Gradient(64, 48, 0));
  }
  {
    auto abandoned = MakeMp4Writer(dir / "b.mp4", 10);
    abandoned->Add(Gradient(64, 48, 0));
  }
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    ++files;
    EXPECT_NE(entry.path().stem(), "b") << entry.path();
  }
  EXPECT_EQ(files, 2u);
}

}  // namespace
}  // namespace mechanist
