// mechanist's Part 21 scanner (io/occt/part21_records.h, Part21WorkLibrary): its records in
// Open CASCADE's encoding, the edges of the subset it reads, and the oracle: Open CASCADE's
// own parser (StepFile_Read) on every STEP file of ../shared/data, the bad inputs, fixtures
// and faulty files gives the same models, checks and messages.
#include "io/occt/part21_records.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/occt/step_fixtures.h"

namespace mechanist {
namespace {

const std::filesystem::path kShared = MECHANIST_SHARED_DATA;
const std::filesystem::path kSource = MECHANIST_SOURCE_DIR;

std::string Wrapped(const std::string& data) {
  return "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\n"
         "FILE_NAME('x','2026-01-01',(''),(''),'','','');\n"
         "FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n" +
         data + "\nENDSEC;\nEND-ISO-10303-21;\n";
}

// A folder of this test process's own (ctest runs tests in parallel), removed at the end of
// the scope.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              fmt::format("mechanist_{}_{}", name, ::getpid())) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::string Slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The records as lines "IDENT TYPE: VALUE|KIND ...", idents and types as Open CASCADE gets them.
std::vector<std::string> Lines(const Part21Records& records, const std::string& text) {
  const auto of = [&](Part21Records::Span s) { return text.substr(s.begin, s.size); };
  std::vector<std::string> lines;
  for (const Part21Records::Record& r : records.records) {
    std::string line = r.sub > 0          ? fmt::format("${}", r.sub)
                       : r.ident.size > 0 ? of(r.ident)
                                          : "#0";
    line += " " + (r.type.size > 0 ? of(r.type) : "(SUB)") + ":";
    for (std::size_t k = r.first; k < r.first + r.count; ++k) {
      const Part21Records::Param& p = records.params[k];
      static constexpr const char* kKinds[] = {"int",  "real", "ident", "void", "text",
                                               "enum", "hexa", "misc",  "sub"};
      line += " " + (p.kind == Part21Records::Kind::kSub ? fmt::format("${}", p.sub) : of(p.text)) +
              "|" + kKinds[static_cast<int>(p.kind)];
    }
    lines.push_back(line);
  }
  return lines;
}

TEST(Part21Records, NestedListsAndComplexEntitiesAreRecordsAsOpenCascadeEncodesThem) {
  const std::string text =
      "ISO-10303-21; /* a comment */\nHEADER;\nFILE_DESCRIPTION(('a part'),'2;1');\nENDSEC;\n"
      "DATA;\n#1=CARTESIAN_POINT(''':V',(0.,-1.5E-3,2));\n"
      "#2 = MEASURE_REPRESENTATION_ITEM('x',LENGTH_MEASURE(2.),#1) ;\n"
      "#3=(A(.T.,*,$) B ( (\"0F\",(-1)) ));\nENDSEC;\nEND-ISO-10303-21;\nafter the end";
  const std::optional<Part21Records> records = ReadPart21Records(text);
  ASSERT_TRUE(records.has_value());
  EXPECT_EQ(records->header_records, 2u);
  EXPECT_EQ(records->max_sub, 2);
  const std::vector<std::string> expected = {
      "$1 (SUB): 'a part'|text",
      "#0 FILE_DESCRIPTION: $1|sub '2;1'|text",
      "$1 (SUB): 0.|real -1.5E-3|real 2|int",
      "#1 CARTESIAN_POINT: ''':V'|text $1|sub",
      "$1 LENGTH_MEASURE: 2.|real",
      "#2 MEASURE_REPRESENTATION_ITEM: 'x'|text $1|sub #1|ident",
      "#3 A: .T.|enum *|misc $|void",
      "$2 (SUB): -1|int",
      "$1 (SUB): \"0F\"|hexa $2|sub",
      "#0 B: $1|sub",
  };
  EXPECT_EQ(Lines(*records, text), expected);
}

TEST(Part21Records, UndefinedReferencesAreNamedByTheEntityThatHoldsThem) {
  // #2 refers to #1 (defined, written #01) and to #9 in a nested list; the complex #3 to #8 in its
  // second part's list; #5, after them, to #7 directly. The header's reference is not the data's.
  const std::string text =
      "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((#4),'2;1');\nENDSEC;\nDATA;\n"
      "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=POLYLINE('',(#01,#9));\n"
      "#3=(A(1) B((#8,#1)));\n#5=VERTEX_POINT('',#7);\nENDSEC;\nEND-ISO-10303-21;\n";
  const std::optional<Part21Records> records = ReadPart21Records(text);
  ASSERT_TRUE(records.has_value());
  std::vector<std::string> found;
  for (const Part21UndefinedReference& r : UndefinedReferences(*records, text)) {
    found.push_back(r.entity + " " + r.type + " -> " + r.missing);
  }
  EXPECT_EQ(found,
            (std::vector<std::string>{"#2 POLYLINE -> #9", "#3 A -> #8", "#5 VERTEX_POINT -> #7"}));
  // A whole file refers only to what it defines.
  const std::string whole = Slurp(kShared / "real/hinge_clamshell_build123d/clamshell_full.step");
  const std::optional<Part21Records> real = ReadPart21Records(whole);
  ASSERT_TRUE(real.has_value());
  EXPECT_TRUE(UndefinedReferences(*real, whole).empty());
}

TEST(Part21Records, NumbersAreSplitAsOpenCascadesScannerSplitsThem) {
  const std::string text = Wrapped("#1=A(-1E5,.5,1.,12,+3,-2.5E+07,1.2.3);");
  const std::optional<Part21Records> records = ReadPart21Records(text);
  ASSERT_TRUE(records.has_value());
  EXPECT_EQ(Lines(*records, text).back(),
            "#1 A: -1E5|real .5|real 1.|real 12|int +3|int -2.5E+07|real 1.2.3|real");
}

TEST(Part21Records, WhatItDoesNotReadIsLeftToOpenCascade) {
  const std::vector<std::string> outside = {
      "#1=A(1E5);",            // Open CASCADE reads 1 then a type E5
      "#1=A(1.5e3);",          // lower-case exponent: 1.5 then a type
      "#1=A(12AB);",           // a number then a type
      "#1=A(-);",              // a sign alone
      "#1=A(.);",              // a dot alone
      "#1=A('it's');",         // an apostrophe inside a text
      "#1=A('it'',1);",        // a doubled apostrophe before ','
      "#1=A('it' 's');",       // an apostrophe then a blank
      "#1=A('1''\",2');",      // a double quote after an apostrophe: the text ends there
      "#1=A('x' /* c */,1);",  // a comment after a text
      "#1=A('a\x01');",        // a control character in a text
      "#1=A(1,,2);",           // an empty parameter
      "#1=A(1)",               // no ';'
      "#1=A(1);/* unterminated",
      "/* it's */#1=A(1);",  // an apostrophe in a comment (a text to Open CASCADE)
      "#1=!USER(1);",        // a user-defined type
      "#1\n=A(1);",          // a line break before '=': not an entity name to Open CASCADE
      "&SCOPE #1=A(1); ENDSCOPE",
      "#1=A(\"0G\");",  // not hexadecimal
      "#1=A(.T);",      // an enum not closed
      std::string("#1=A(1);\0", 9),
      "#1=A(" + std::string(65, '(') + std::string(65, ')') + ");",  // nested past 64
  };
  for (const std::string& data : outside) {
    EXPECT_FALSE(ReadPart21Records(Wrapped(data)).has_value()) << data;
  }
  const std::string inside = "#1=A(" + std::string(64, '(') + std::string(64, ')') + ");";
  EXPECT_TRUE(ReadPart21Records(Wrapped(inside)).has_value());
  EXPECT_TRUE(ReadPart21Records(Wrapped("#1=A(1);")).has_value());
  for (const std::string& text :
       {std::string(), std::string("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=A(1);"),
        Wrapped("#1=A(1);").replace(0, 3, "STEP"), Wrapped("#1=A(1);\nENDSEC;\nDATA;\n#2=A(1);"),
        Wrapped(""), Wrapped("#1=ENDSCOPE(1);"), Wrapped("#1=A(ENDSCOPE(1));")}) {
    EXPECT_FALSE(ReadPart21Records(text).has_value()) << text;
  }
}

// The STEP files of ../shared/data (real exports from Onshape, Fusion 360, SolidWorks,
// Solid Edge, build123d; AS1).
std::vector<std::filesystem::path> SharedStepFiles() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kShared)) {
    std::string extension = entry.path().extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (entry.is_regular_file() && (extension == ".step" || extension == ".stp")) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(Part21Records, EveryRealExportIsInTheSubset) {
  const std::vector<std::filesystem::path> files = SharedStepFiles();
  ASSERT_GE(files.size(), 8u);
  for (const std::filesystem::path& file : files) {
    EXPECT_TRUE(ReadPart21Records(Slurp(file)).has_value()) << file;
  }
}

void ExpectSameModel(const std::filesystem::path& file) {
  SCOPED_TRACE(file.string());
  const testing::StepModelRead theirs = testing::ReadStepModel(file, false);
  const testing::StepModelRead ours = testing::ReadStepModel(file, true);
  EXPECT_EQ(ours.status, theirs.status);
  EXPECT_EQ(ours.entities, theirs.entities);
  EXPECT_EQ(ours.error_entities, theirs.error_entities);
  EXPECT_EQ(ours.unknown_entities, theirs.unknown_entities);
  EXPECT_EQ(ours.checks, theirs.checks);
  EXPECT_EQ(ours.messages, theirs.messages);
  EXPECT_TRUE(ours.written == theirs.written) << "the models written back differ";
}

// `data` as the data section of a file in `folder`, read both ways; `inside`: whether the
// scanner reads it (else Open CASCADE's parser does, for both).
void ExpectSameModelOf(const std::string& data, bool inside, const ScratchFolder& folder) {
  static int count = 0;
  const std::filesystem::path file = folder.path() / fmt::format("file{}.step", ++count);
  std::ofstream(file) << Wrapped(data);
  EXPECT_EQ(ReadPart21Records(Slurp(file)).has_value(), inside) << data;
  ExpectSameModel(file);
}

TEST(Part21WorkLibrary, ModelsAreOpenCascadesOnEverySharedStepFile) {
  for (const std::filesystem::path& file : SharedStepFiles()) {
    ExpectSameModel(file);
    EXPECT_GT(testing::ReadStepModel(file, true).entities, 100) << file;
  }
}

TEST(Part21WorkLibrary, ModelsChecksAndMessagesAreOpenCascadesOnBadAndFaultyFiles) {
  // Bad inputs: inside the subset, and outside it (read by Open CASCADE's parser both ways,
  // with its status and messages).
  for (const char* name : {"step_dangling_reference.step", "step_no_solid.step"}) {
    ASSERT_TRUE(ReadPart21Records(Slurp(kSource / "tests/data/bad" / name)).has_value());
    ExpectSameModel(kSource / "tests/data/bad" / name);
  }
  for (const char* name : {"step_truncated.step", "step_not_step.step", "step_header_only.step"}) {
    ASSERT_FALSE(ReadPart21Records(Slurp(kSource / "tests/data/bad" / name)).has_value());
    ExpectSameModel(kSource / "tests/data/bad" / name);
  }
  ExpectSameModel(kSource / "tests/data/bad/no_such_file.step");  // cannot be opened: -1
  const ScratchFolder folder("part21_faulty");
  ExpectSameModel(folder.path());  // a folder: not a regular file
  // Faulty files inside the subset, which Open CASCADE loads with checks and messages.
  for (const char* faulty : {
           "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=DIRECTION('',(0.,0.,1.));\n"
           "#3=AXIS2_PLACEMENT_3D('',#1,#2,#99);",  // a dangling reference
           "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#1=CARTESIAN_POINT('',(1.,0.,0.));",  // twice
           "#1=NOT_A_STEP_TYPE(1,'a');",                                              // unknown
           "#1=CARTESIAN_POINT('');",                            // too few parameters
           "#1=CARTESIAN_POINT('',(0.,'a',.T.));",               // wrong kinds
           "#1=DIRECTION('',(0.,0.,1.));\n#2=VECTOR('',#1,*);",  // '*' for a value
           // a list where a derived attribute's '*' is looked for (its `$1` read after loading)
           "#1=(LENGTH_UNIT() NAMED_UNIT((0)) SI_UNIT(.MILLI.,.METRE.));",
           "#1=A(('a',(1,2)),B(3));\n#2=(C(.T.,*,$) D((\"0F\",(-1))));",  // unknown, nested
       }) {
    ExpectSameModelOf(faulty, true, folder);
  }
  // Outside the subset: read by Open CASCADE's parser either way.
  for (const char* outside : {"", "#1=!USER_TYPE(1);", "#1=A('1''\",2');", "#1=A(1E5);"}) {
    ExpectSameModelOf(outside, false, folder);
  }
}

TEST(Part21WorkLibrary, ModelsAreOpenCascadesOnFilesItsWriterWrites) {
  const ScratchFolder folder("part21_written");
  const std::filesystem::path& dir = folder.path();
  testing::WriteSpurGearPairStep(dir / "spur.step", 12, 30, 2);
  testing::WriteBallBearingStep(dir / "bearing.step", 9);
  testing::WriteStepVariant(kShared / "step/as1_pe_203.stp", dir / "inches.step",
                            testing::StepVariant::kInches);
  for (const char* name : {"spur.step", "bearing.step", "inches.step"}) {
    ASSERT_TRUE(ReadPart21Records(Slurp(dir / name)).has_value()) << name;
    ExpectSameModel(dir / name);
  }
}

}  // namespace
}  // namespace mechanist
