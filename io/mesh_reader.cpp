#include "io/mesh_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "io/input_error.h"
#include "io/internal/memory_budget.h"
#include "kernel/support/ascii_lower.h"

namespace mechanist {
namespace {

constexpr std::int64_t kMaxVertices = std::numeric_limits<std::int32_t>::max();

/// Throws InputError for one file; line and column are 1-based, 0 when not applicable.
class Source {
 public:
  explicit Source(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void Fail(int line, int column, const std::string& message) const {
    throw InputError(file_, "", line, column, message);
  }

 private:
  std::string file_;
};

/// `text` quoted for a message; binary garbage is shortened and made printable.
std::string Quote(std::string_view text) {
  constexpr std::size_t kMaxShown = 40;
  std::string quoted = "'";
  for (char c : text.substr(0, kMaxShown)) {
    const auto byte = static_cast<unsigned char>(c);
    quoted += (byte < 0x20 || byte == 0x7f) ? '?' : c;
  }
  if (text.size() > kMaxShown) quoted += "...";
  return quoted + "'";
}

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r'; }

/// `text` without a leading '+' sign, which text formats allow and from_chars rejects.
std::string_view WithoutPlus(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '+' && text[1] != '-') text.remove_prefix(1);
  return text;
}

/// A number written in a text format. Values out of double's range become infinite or
/// denormal, which callers reject or keep.
std::optional<double> ParseReal(std::string_view text) {
  text = WithoutPlus(text);
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ptr != end) return std::nullopt;
  if (ec == std::errc::result_out_of_range) return std::strtod(std::string(text).c_str(), nullptr);
  if (ec != std::errc()) return std::nullopt;
  return value;
}

std::optional<std::int64_t> ParseInteger(std::string_view text) {
  text = WithoutPlus(text);
  std::int64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ptr != end || ec != std::errc()) return std::nullopt;
  return value;
}

/// Splits text into lines ending in "\n", "\r\n" or a lone "\r", numbered from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {
    // Editors on Windows may prepend a UTF-8 byte order mark.
    if (text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;
  }

  /// Advances to the next line; false at the end of the text.
  bool Next() {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find_first_of("\r\n", pos_);
    if (end == std::string_view::npos) end = text_.size();
    line_ = text_.substr(pos_, end - pos_);
    pos_ = end;
    if (pos_ < text_.size() && text_[pos_] == '\r') ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '\n') ++pos_;
    ++number_;
    return true;
  }

  std::string_view line() const { return line_; }
  /// The current line's number; the last line's after the end, 0 for an empty text.
  int number() const { return number_; }
  /// Byte offset just past the current line's end of line.
  std::size_t offset() const { return pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::string_view line_;
  int number_ = 0;
};

/// A whitespace-separated word and where it starts. `text` is empty at the end of a line or
/// of the data.
struct Token {
  std::string_view text;
  int line = 0;
  int column = 0;
};

/// `token` for a message: quoted, or "end of line" when there is none.
std::string Found(const Token& token) {
  return token.text.empty() ? "end of line" : Quote(token.text);
}

/// The words of one line.
class LineTokens {
 public:
  LineTokens() = default;
  LineTokens(std::string_view line, int number) : line_(line), number_(number) {}

  Token Next() {
    while (pos_ < line_.size() && IsSpace(line_[pos_])) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < line_.size() && !IsSpace(line_[pos_])) ++pos_;
    return {line_.substr(start, pos_ - start), number_, pos_ > start ? int(start) + 1 : 0};
  }

 private:
  std::string_view line_;
  int number_ = 0;
  std::size_t pos_ = 0;
};

/// The line without a '#' comment.
std::string_view StripComment(std::string_view line) { return line.substr(0, line.find('#')); }

/// Advances `lines` to the next line with words outside comments and splits it into `tokens`;
/// false at the end of the text.
bool NextDataLine(LineReader& lines, LineTokens& tokens) {
  while (lines.Next()) {
    const std::string_view data = StripComment(lines.line());
    if (std::all_of(data.begin(), data.end(), IsSpace)) continue;
    tokens = LineTokens(data, lines.number());
    return true;
  }
  return false;
}

/// Reads "x y z" from `tokens`; `what` completes "expected 3 numbers ...". Later words
/// (a homogeneous w, colours) are left unread.
Eigen::Vector3d ReadPoint(LineTokens& tokens, const std::string& what, const Source& source) {
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) {
    const Token token = tokens.Next();
    const std::optional<double> value = ParseReal(token.text);
    if (!value) {
      source.Fail(token.line, token.column,
                  fmt::format("expected 3 numbers {}, found {}", what, Found(token)));
    }
    if (!std::isfinite(*value)) {
      source.Fail(
          token.line, token.column,
          fmt::format("expected a finite coordinate {}, found {}", what, Quote(token.text)));
    }
    p[i] = *value;
  }
  return p;
}

/// Appends the polygon as a fan of triangles around its first vertex.
void AddFan(const std::vector<std::int32_t>& polygon, std::vector<TriangleMesh::Face>& faces) {
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    faces.push_back({polygon[0], polygon[i], polygon[i + 1]});
  }
}

/// A value of type T stored in `bytes` with the given byte order.
template <class T>
T Load(const char* bytes, bool big_endian) {
  std::array<char, sizeof(T)> raw;
  std::memcpy(raw.data(), bytes, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
  return std::bit_cast<T>(raw);
}

// ---------------------------------------------------------------------------------------------
// STL

/// Merges vertices with identical coordinates into one index: STL stores every triangle's
/// corners separately, and the kernel needs shared vertices to see edges. An open-addressing
/// table with linear probing keeps this fast for millions of corners.
class VertexWelder {
 public:
  VertexWelder(std::vector<Eigen::Vector3d>& vertices, std::size_t expected) : vertices_(vertices) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    slots_.assign(capacity, -1);
  }

  /// The index of the vertex at `p` (finite), added when new.
  std::int32_t Add(const Eigen::Vector3d& p, const Source& source) {
    for (std::size_t slot = Hash(p) & (slots_.size() - 1);;
         slot = (slot + 1) & (slots_.size() - 1)) {
      const std::int32_t index = slots_[slot];
      if (index < 0) break;
      if (vertices_[index] == p) return index;
    }
    if (static_cast<std::int64_t>(vertices_.size()) >= kMaxVertices) {
      source.Fail(0, 0, fmt::format("too many distinct vertices (more than {})", kMaxVertices));
    }
    const auto index = static_cast<std::int32_t>(vertices_.size());
    vertices_.push_back(p);
    if (2 * vertices_.size() > slots_.size()) {
      Rehash(2 * slots_.size());
    } else {
      Insert(index);
    }
    return index;
  }

 private:
  static std::size_t Hash(const Eigen::Vector3d& p) {
    std::uint64_t h = 0;
    for (int i = 0; i < 3; ++i) {
      // Adding +0.0 turns -0.0 into +0.0, which compares equal and must hash equal.
      h = (h ^ std::bit_cast<std::uint64_t>(p[i] + 0.0)) * 0x9E3779B97F4A7C15ull;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h);
  }

  void Insert(std::int32_t index) {
    std::size_t slot = Hash(vertices_[index]) & (slots_.size() - 1);
    while (slots_[slot] >= 0) slot = (slot + 1) & (slots_.size() - 1);
    slots_[slot] = index;
  }

  void Rehash(std::size_t capacity) {
    slots_.assign(capacity, -1);
    for (std::size_t i = 0; i < vertices_.size(); ++i) Insert(static_cast<std::int32_t>(i));
  }

  std::vector<Eigen::Vector3d>& vertices_;
  std::vector<std::int32_t> slots_;  ///< vertex index, or -1 for a free slot
};

TriangleMesh ReadBinaryStl(std::string_view data, std::uint32_t count, const Source& source) {
  constexpr std::size_t kHeaderSize = 84, kRecordSize = 50, kCornersOffset = 12;
  TriangleMesh mesh;
  mesh.faces.reserve(count);
  // A closed mesh has about half as many vertices as triangles.
  VertexWelder welder(mesh.vertices, count / 2 + 3);
  for (std::size_t t = 0; t < count; ++t) {
    const char* record = data.data() + kHeaderSize + t * kRecordSize + kCornersOffset;
    TriangleMesh::Face face;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d p;
      for (int i = 0; i < 3; ++i) p[i] = Load<float>(record + 4 * (3 * k + i), false);
      if (!p.allFinite()) {
        source.Fail(
            0, 0,
            fmt::format("expected finite coordinates, found a non-finite one in triangle {} "
                        "(counting from 0) of the binary STL",
                        t));
      }
      face[k] = welder.Add(p, source);
    }
    mesh.faces.push_back(face);
  }
  return mesh;
}

TriangleMesh ReadAsciiStl(std::string_view data, const Source& source) {
  // What each state accepts next, for the messages.
  enum State { kOutside, kSolid, kFacet, kLoop, kLoopClosed };
  static constexpr std::array<const char*, 5> kExpected = {
      "'solid'", "'facet' or 'endsolid'", "'outer loop'", "'vertex' or 'endloop'", "'endfacet'"};
  TriangleMesh mesh;
  VertexWelder welder(mesh.vertices, data.size() / 200);
  std::vector<std::int32_t> polygon;
  State state = kOutside;
  LineReader lines(data);
  while (lines.Next()) {
    LineTokens tokens(lines.line(), lines.number());
    const Token keyword = tokens.Next();
    if (keyword.text.empty()) continue;
    const std::string word = AsciiLower(keyword.text);
    if (state == kOutside && word == "solid") {
      state = kSolid;  // the rest of the line is the solid's name
    } else if (state == kSolid && word == "facet") {
      state = kFacet;  // the normal is ignored: orientation comes from the vertex order
    } else if (state == kSolid && word == "endsolid") {
      state = kOutside;
    } else if (state == kFacet && word == "outer") {
      const Token loop = tokens.Next();
      if (AsciiLower(loop.text) != "loop") {
        source.Fail(loop.line, loop.column,
                    fmt::format("expected 'loop' after 'outer', found {}", Found(loop)));
      }
      polygon.clear();
      state = kLoop;
    } else if (state == kLoop && word == "vertex") {
      polygon.push_back(welder.Add(ReadPoint(tokens, "after 'vertex'", source), source));
    } else if (state == kLoop && word == "endloop") {
      if (polygon.size() < 3) {
        source.Fail(keyword.line, keyword.column,
                    fmt::format("expected at least 3 vertices in a facet's loop, found {}",
                                polygon.size()));
      }
      AddFan(polygon, mesh.faces);
      state = kLoopClosed;
    } else if (state == kLoopClosed && word == "endfacet") {
      state = kSolid;
    } else {
      source.Fail(keyword.line, keyword.column,
                  fmt::format("expected {}, found {}", kExpected[state], Quote(keyword.text)));
    }
  }
  if (state != kOutside) {
    const std::string missing = state == kSolid ? "'endsolid'" : kExpected[state];
    source.Fail(lines.number(), 0,
                fmt::format("expected {}, found end of file (truncated?)", missing));
  }
  return mesh;
}

/// True when `data` looks like text: binary STL triangle records (and their count) contain
/// control bytes, ASCII STL does not. The first 64 KiB decide, so huge files scan quickly.
bool LooksLikeText(std::string_view data) {
  const std::string_view start = data.substr(0, 64 * 1024);
  return std::none_of(start.begin(), start.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return (byte < 0x20 && !IsSpace(c) && c != '\n') || byte == 0x7f;
  });
}

TriangleMesh ReadStl(std::string_view data, const Source& source) {
  constexpr std::uint64_t kHeaderSize = 84, kRecordSize = 50;
  // A binary header may begin with "solid" like ASCII, so the size decides first.
  std::optional<std::uint32_t> count;
  if (data.size() >= kHeaderSize) {
    count = Load<std::uint32_t>(data.data() + 80, false);
    if (kHeaderSize + kRecordSize * *count == data.size()) {
      return ReadBinaryStl(data, *count, source);
    }
  }
  if (LooksLikeText(data)) return ReadAsciiStl(data, source);
  if (!count) {
    source.Fail(
        0, 0,
        fmt::format("expected a binary STL of at least 84 bytes (header and triangle count) "
                    "or an ASCII STL, found {} bytes of binary data",
                    data.size()));
  }
  source.Fail(
      0, 0,
      fmt::format("binary STL declares {} triangles, which take {} bytes, but the file has {} "
                  "bytes (truncated or corrupt)",
                  *count, kHeaderSize + kRecordSize * *count, data.size()));
}

// ---------------------------------------------------------------------------------------------
// OBJ

TriangleMesh ReadObj(std::string_view data, const Source& source) {
  TriangleMesh mesh;
  std::vector<std::int32_t> polygon;
  // Positive indices may refer to vertices listed later; the largest such one is checked
  // against the final count.
  std::optional<Token> forward_reference;
  std::int64_t largest_forward = 0;
  LineReader lines(data);
  while (lines.Next()) {
    LineTokens tokens(StripComment(lines.line()), lines.number());
    const Token keyword = tokens.Next();
    if (keyword.text == "v") {
      if (static_cast<std::int64_t>(mesh.vertices.size()) >= kMaxVertices) {
        source.Fail(keyword.line, keyword.column, "too many vertices");
      }
      mesh.vertices.push_back(ReadPoint(tokens, "after 'v'", source));
    } else if (keyword.text == "f") {
      const auto count = static_cast<std::int64_t>(mesh.vertices.size());
      polygon.clear();
      for (Token token = tokens.Next(); !token.text.empty(); token = tokens.Next()) {
        // "v", "v/vt", "v//vn" or "v/vt/vn": only the position index matters.
        const std::optional<std::int64_t> index =
            ParseInteger(token.text.substr(0, token.text.find('/')));
        if (!index || *index == 0) {
          source.Fail(token.line, token.column,
                      fmt::format("expected a vertex index (a non-zero integer, optionally with "
                                  "/texture/normal indices) after 'f', found {}",
                                  Quote(token.text)));
        }
        const std::int64_t resolved = *index < 0 ? count + *index : *index - 1;
        if (resolved < 0 || resolved >= kMaxVertices) {
          source.Fail(token.line, token.column,
                      fmt::format("vertex index {} is out of range: {} vertices precede it", *index,
                                  count));
        }
        if (resolved >= count && resolved + 1 > largest_forward) {
          largest_forward = resolved + 1;
          forward_reference = token;
        }
        polygon.push_back(static_cast<std::int32_t>(resolved));
      }
      if (polygon.size() < 3) {
        source.Fail(
            keyword.line, keyword.column,
            fmt::format("expected at least 3 vertex indices after 'f', found {}", polygon.size()));
      }
      AddFan(polygon, mesh.faces);
    }
    // Other records (vt, vn, g, o, s, usemtl, l, count headers...) carry no geometry we need.
  }
  if (forward_reference && largest_forward > static_cast<std::int64_t>(mesh.vertices.size())) {
    source.Fail(forward_reference->line, forward_reference->column,
                fmt::format("vertex index {} is out of range: the file has {} vertices",
                            largest_forward, mesh.vertices.size()));
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// OFF

/// A count in a header: a non-negative integer no larger than the kernel can index.
std::int64_t ReadCount(const Token& token, const std::string& what, const Source& source) {
  const std::optional<std::int64_t> count = ParseInteger(token.text);
  if (!count || *count < 0 || *count > kMaxVertices) {
    source.Fail(token.line, token.column,
                fmt::format("expected {} (a non-negative integer), found {}", what, Found(token)));
  }
  return *count;
}

TriangleMesh ReadOff(std::string_view data, const Source& source) {
  LineReader lines(data);
  LineTokens tokens;
  if (!NextDataLine(lines, tokens)) {
    source.Fail(lines.number(), 0,
                "expected 'OFF' and the vertex, face and edge counts, found only comments");
  }
  Token first = tokens.Next();
  if (first.text.ends_with("OFF")) {
    const std::string_view prefix = first.text.substr(0, first.text.size() - 3);
    if (prefix.find_first_of("4n") != std::string_view::npos) {
      source.Fail(
          first.line, first.column,
          fmt::format("only three-dimensional OFF is supported, found {}", Quote(first.text)));
    }
    if (prefix.find_first_not_of("STCN") != std::string_view::npos) {
      source.Fail(first.line, first.column,
                  fmt::format("expected 'OFF', found {}", Quote(first.text)));
    }
    first = tokens.Next();
    if (first.text == "BINARY") {
      source.Fail(first.line, first.column, "binary OFF is not supported; write it as text");
    }
    // The counts follow on the header line or on the next line.
    if (first.text.empty()) {
      if (!NextDataLine(lines, tokens)) {
        source.Fail(lines.number(), 0,
                    "expected the vertex, face and edge counts, found end of file");
      }
      first = tokens.Next();
    }
  } else if (!ParseInteger(first.text)) {
    source.Fail(first.line, first.column,
                fmt::format("expected 'OFF' or the vertex, face and edge counts, found {}",
                            Quote(first.text)));
  }
  const std::int64_t vertex_count = ReadCount(first, "the vertex count", source);
  const std::int64_t face_count = ReadCount(tokens.Next(), "the face count", source);
  // The edge count is often wrong and is not needed.

  TriangleMesh mesh;
  mesh.vertices.reserve(std::min<std::size_t>(vertex_count, data.size() / 6));
  for (std::int64_t i = 0; i < vertex_count; ++i) {
    if (!NextDataLine(lines, tokens)) {
      source.Fail(lines.number(), 0,
                  fmt::format("expected {} vertices, found {} before the end of the file",
                              vertex_count, i));
    }
    mesh.vertices.push_back(ReadPoint(tokens, fmt::format("for vertex {}", i), source));
  }

  std::vector<std::int32_t> polygon;
  // Faces beyond the declared count are read too: each face line says how long it is.
  for (std::int64_t f = 0;; ++f) {
    if (!NextDataLine(lines, tokens)) {
      if (f < face_count) {
        source.Fail(
            lines.number(), 0,
            fmt::format("expected {} faces, found {} before the end of the file", face_count, f));
      }
      break;
    }
    const Token size_token = tokens.Next();
    const std::optional<std::int64_t> size = ParseInteger(size_token.text);
    if (!size || *size < 3) {
      source.Fail(size_token.line, size_token.column,
                  fmt::format("expected the number of vertices of face {} (an integer of at least "
                              "3), found {}",
                              f, Quote(size_token.text)));
    }
    polygon.clear();
    for (std::int64_t k = 0; k < *size; ++k) {
      const Token token = tokens.Next();
      const std::optional<std::int64_t> index = ParseInteger(token.text);
      if (!index) {
        source.Fail(token.line, token.column,
                    fmt::format("expected {} vertex indices for face {}, found {}", *size, f,
                                Found(token)));
      }
      if (*index < 0 || *index >= vertex_count) {
        source.Fail(token.line, token.column,
                    fmt::format("vertex index {} is out of range: the file has {} vertices", *index,
                                vertex_count));
      }
      polygon.push_back(static_cast<std::int32_t>(*index));
    }
    AddFan(polygon, mesh.faces);  // colour values after the indices are ignored
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// PLY

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

std::optional<PlyType> ParsePlyType(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, PlyType>, 16> kNames = {{
      {"char", PlyType::kInt8},
      {"int8", PlyType::kInt8},
      {"uchar", PlyType::kUint8},
      {"uint8", PlyType::kUint8},
      {"short", PlyType::kInt16},
      {"int16", PlyType::kInt16},
      {"ushort", PlyType::kUint16},
      {"uint16", PlyType::kUint16},
      {"int", PlyType::kInt32},
      {"int32", PlyType::kInt32},
      {"uint", PlyType::kUint32},
      {"uint32", PlyType::kUint32},
      {"float", PlyType::kFloat32},
      {"float32", PlyType::kFloat32},
      {"double", PlyType::kFloat64},
      {"float64", PlyType::kFloat64},
  }};
  for (const auto& [spelling, type] : kNames) {
    if (spelling == name) return type;
  }
  return std::nullopt;
}

bool IsInteger(PlyType type) { return type != PlyType::kFloat32 && type != PlyType::kFloat64; }

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;    ///< a list's item type
  std::optional<PlyType> length_type;  ///< set for a list
};

struct PlyElement {
  std::string name;
  std::int64_t count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;  ///< of the "element" line
};

struct PlyHeader {
  enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian };
  Format format = Format::kAscii;
  std::vector<PlyElement> elements;
  LineReader lines;  ///< at the "end_header" line: the data follows
};

PlyType ToPlyType(const Token& token, const Source& source) {
  const std::optional<PlyType> type = ParsePlyType(token.text);
  if (!type) {
    source.Fail(token.line, token.column,
                fmt::format("expected a PLY type (char, uchar, short, ushort, int, uint, float, "
                            "double or int8 ... float64), found {}",
                            Found(token)));
  }
  return *type;
}

PlyHeader ReadPlyHeader(std::string_view data, const Source& source) {
  PlyHeader header{PlyHeader::Format::kAscii, {}, LineReader(data)};
  LineReader& lines = header.lines;
  {
    lines.Next();
    LineTokens tokens(lines.line(), lines.number());
    const Token magic = tokens.Next();
    if (magic.text != "ply") {
      source.Fail(1, magic.column,
                  fmt::format("expected 'ply' on the first line, found {}", Found(magic)));
    }
  }
  bool has_format = false;
  for (;;) {
    if (!lines.Next()) {
      source.Fail(lines.number(), 0, "expected 'end_header', found end of file");
    }
    LineTokens tokens(lines.line(), lines.number());
    const Token keyword = tokens.Next();
    if (keyword.text == "end_header") break;
    if (keyword.text.empty() || keyword.text == "comment" || keyword.text == "obj_info") continue;
    if (keyword.text == "format") {
      const Token format = tokens.Next();
      if (format.text == "ascii") {
        header.format = PlyHeader::Format::kAscii;
      } else if (format.text == "binary_little_endian") {
        header.format = PlyHeader::Format::kBinaryLittleEndian;
      } else if (format.text == "binary_big_endian") {
        header.format = PlyHeader::Format::kBinaryBigEndian;
      } else {
        source.Fail(format.line, format.column,
                    fmt::format("expected 'ascii', 'binary_little_endian' or "
                                "'binary_big_endian', found {}",
                                Found(format)));
      }
      has_format = true;
    } else if (keyword.text == "element") {
      const Token name = tokens.Next();
      if (name.text.empty()) {
        source.Fail(keyword.line, 0, "expected an element name after 'element', found end of line");
      }
      for (const PlyElement& element : header.elements) {
        if (element.name == name.text) {
          source.Fail(name.line, name.column,
                      fmt::format("element {} is declared twice", Quote(name.text)));
        }
      }
      const std::int64_t count = ReadCount(
          tokens.Next(), fmt::format("the number of {} elements", Quote(name.text)), source);
      header.elements.push_back({std::string(name.text), count, {}, keyword.line});
    } else if (keyword.text == "property") {
      if (header.elements.empty()) {
        source.Fail(keyword.line, keyword.column, "expected 'element' before the first 'property'");
      }
      PlyProperty property;
      Token type = tokens.Next();
      if (type.text == "list") {
        const Token length_type = tokens.Next();
        property.length_type = ToPlyType(length_type, source);
        if (!IsInteger(*property.length_type)) {
          source.Fail(length_type.line, length_type.column,
                      fmt::format("expected an integer type for a list's length, found {}",
                                  Quote(length_type.text)));
        }
        type = tokens.Next();
      }
      property.type = ToPlyType(type, source);
      const Token name = tokens.Next();
      if (name.text.empty()) {
        source.Fail(keyword.line, 0, "expected a property name after its type, found end of line");
      }
      property.name = name.text;
      header.elements.back().properties.push_back(std::move(property));
    } else {
      source.Fail(keyword.line, keyword.column,
                  fmt::format("expected 'format', 'element', 'property', 'comment' or "
                              "'end_header', found {}",
                              Quote(keyword.text)));
    }
  }
  if (!has_format) source.Fail(lines.number(), 0, "expected a 'format' line before 'end_header'");
  return header;
}

/// Which value of the PLY data is being read, for messages.
struct PlyPlace {
  const PlyElement& element;
  std::int64_t index;
  const PlyProperty& property;
};

std::string Describe(const PlyPlace& place) {
  return fmt::format("property {} of {} {}", Quote(place.property.name), place.element.name,
                     place.index);
}

/// The values of an ASCII PLY body, as whitespace-separated words.
class PlyAsciiValues {
 public:
  PlyAsciiValues(const LineReader& lines, const Source& source) : lines_(lines), source_(source) {}

  double Real(PlyType type, const PlyPlace& place) {
    if (IsInteger(type)) return static_cast<double>(Integer(type, place));
    const Token& token = Next(place);
    const std::optional<double> value = ParseReal(token.text);
    if (!value) {
      source_.Fail(
          token.line, token.column,
          fmt::format("expected a number for {}, found {}", Describe(place), Quote(token.text)));
    }
    return *value;
  }

  std::int64_t Integer(PlyType, const PlyPlace& place) {
    const Token& token = Next(place);
    const std::optional<std::int64_t> value = ParseInteger(token.text);
    if (!value) {
      source_.Fail(
          token.line, token.column,
          fmt::format("expected an integer for {}, found {}", Describe(place), Quote(token.text)));
    }
    return *value;
  }

  /// Fails at the value read last.
  [[noreturn]] void Fail(const std::string& message) const {
    source_.Fail(last_.line, last_.column, message);
  }

  /// Fails when words follow the last element: the header's counts do not match the data.
  void Finish() {
    const Token token = NextToken();
    if (!token.text.empty()) {
      source_.Fail(
          token.line, token.column,
          fmt::format("expected the end of the data after the elements the header declares, "
                      "found {} (are the element counts right?)",
                      Quote(token.text)));
    }
  }

 private:
  Token NextToken() {
    for (;;) {
      const Token token = tokens_.Next();
      if (!token.text.empty()) return token;
      if (!lines_.Next()) return {{}, lines_.number(), 0};
      tokens_ = LineTokens(lines_.line(), lines_.number());
    }
  }

  const Token& Next(const PlyPlace& place) {
    last_ = NextToken();
    if (last_.text.empty()) {
      source_.Fail(
          last_.line, 0,
          fmt::format("expected {}, found end of file (the header declares {} {} elements)",
                      Describe(place), place.element.count, place.element.name));
    }
    return last_;
  }

  LineReader lines_;
  LineTokens tokens_;
  Token last_;
  const Source& source_;
};

/// The values of a binary PLY body.
class PlyBinaryValues {
 public:
  PlyBinaryValues(std::string_view data, std::size_t offset, bool big_endian, const Source& source)
      : data_(data), offset_(offset), big_endian_(big_endian), source_(source) {}

  double Real(PlyType type, const PlyPlace& place) {
    switch (type) {
      case PlyType::kInt8:
        return Load<std::int8_t>(Take(1, place), big_endian_);
      case PlyType::kUint8:
        return Load<std::uint8_t>(Take(1, place), big_endian_);
      case PlyType::kInt16:
        return Load<std::int16_t>(Take(2, place), big_endian_);
      case PlyType::kUint16:
        return Load<std::uint16_t>(Take(2, place), big_endian_);
      case PlyType::kInt32:
        return Load<std::int32_t>(Take(4, place), big_endian_);
      case PlyType::kUint32:
        return Load<std::uint32_t>(Take(4, place), big_endian_);
      case PlyType::kFloat32:
        return Load<float>(Take(4, place), big_endian_);
      case PlyType::kFloat64:
        return Load<double>(Take(8, place), big_endian_);
    }
    return 0.0;  // unreachable: the switch covers every type
  }

  /// PLY integers have at most 32 bits, which a double holds exactly.
  std::int64_t Integer(PlyType type, const PlyPlace& place) {
    return static_cast<std::int64_t>(Real(type, place));
  }

  /// Fails at the value read last.
  [[noreturn]] void Fail(const std::string& message) const {
    source_.Fail(0, 0, fmt::format("{} (binary data, byte offset {})", message, last_));
  }

  /// Bytes after the last element cannot be told from padding, so they are allowed.
  void Finish() {}

 private:
  const char* Take(std::size_t size, const PlyPlace& place) {
    if (data_.size() - offset_ < size) {
      source_.Fail(0, 0,
                   fmt::format("expected {} at byte offset {}, found end of file (the header "
                               "declares {} {} elements; truncated?)",
                               Describe(place), offset_, place.element.count, place.element.name));
    }
    last_ = offset_;
    offset_ += size;
    return data_.data() + last_;
  }

  std::string_view data_;
  std::size_t offset_;
  std::size_t last_ = 0;
  bool big_endian_;
  const Source& source_;
};

/// What a property means to the mesh.
enum class PlyRole { kNone, kX, kY, kZ, kFaceIndices };

/// The roles of `element`'s properties; fails when a vertex or face element lacks what the
/// mesh needs.
std::vector<PlyRole> PlyRoles(const PlyElement& element, const Source& source) {
  std::vector<PlyRole> roles(element.properties.size(), PlyRole::kNone);
  if (element.name == "vertex") {
    constexpr std::array<std::pair<const char*, PlyRole>, 3> kAxes = {
        {{"x", PlyRole::kX}, {"y", PlyRole::kY}, {"z", PlyRole::kZ}}};
    for (const auto& [name, role] : kAxes) {
      const char* axis = name;  // clang 14 cannot capture a binding
      const auto it = std::find_if(element.properties.begin(), element.properties.end(),
                                   [axis](const PlyProperty& p) { return p.name == axis; });
      if (it == element.properties.end() || it->length_type) {
        source.Fail(element.line, 0,
                    fmt::format("expected a scalar property '{}' in element 'vertex', found {}",
                                name, it == element.properties.end() ? "none" : "a list"));
      }
      roles[it - element.properties.begin()] = role;
    }
  } else if (element.name == "face") {
    const auto it = std::find_if(element.properties.begin(), element.properties.end(),
                                 [](const PlyProperty& p) {
                                   return p.name == "vertex_indices" || p.name == "vertex_index";
                                 });
    if (it == element.properties.end() || !it->length_type || !IsInteger(it->type)) {
      source.Fail(element.line, 0,
                  fmt::format("expected a list property 'vertex_indices' (or 'vertex_index') of "
                              "an integer type in element 'face', found {}",
                              it == element.properties.end() ? "none"
                              : !it->length_type             ? "a scalar"
                                                             : "a list of reals"));
    }
    roles[it - element.properties.begin()] = PlyRole::kFaceIndices;
  }
  return roles;
}

template <class Values>
TriangleMesh ReadPlyBody(const PlyHeader& header, Values& values, std::size_t data_size,
                         const Source& source) {
  std::int64_t vertex_count = 0;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex") vertex_count = element.count;
  }
  TriangleMesh mesh;
  std::vector<std::int32_t> polygon;
  for (const PlyElement& element : header.elements) {
    const std::vector<PlyRole> roles = PlyRoles(element, source);
    const bool is_vertex = element.name == "vertex";
    // Declared counts may lie; every element takes at least one byte.
    if (is_vertex) mesh.vertices.reserve(std::min<std::size_t>(element.count, data_size));
    for (std::int64_t i = 0; i < element.count; ++i) {
      Eigen::Vector3d p;
      for (std::size_t k = 0; k < roles.size(); ++k) {
        const PlyProperty& property = element.properties[k];
        const PlyPlace place{element, i, property};
        if (!property.length_type) {
          const double value = values.Real(property.type, place);
          if (roles[k] == PlyRole::kNone) continue;
          if (!std::isfinite(value)) {
            values.Fail(fmt::format("expected a finite coordinate for {}, found {}",
                                    Describe(place), std::to_string(value)));
          }
          p[static_cast<int>(roles[k]) - static_cast<int>(PlyRole::kX)] = value;
          continue;
        }
        const std::int64_t length = values.Integer(*property.length_type, place);
        if (length < 0) {
          values.Fail(
              fmt::format("expected a list length for {}, found {}", Describe(place), length));
        }
        if (roles[k] != PlyRole::kFaceIndices) {
          for (std::int64_t j = 0; j < length; ++j) values.Real(property.type, place);
          continue;
        }
        if (length < 3) {
          values.Fail(
              fmt::format("expected at least 3 vertex indices for face {}, found {}", i, length));
        }
        polygon.clear();
        for (std::int64_t j = 0; j < length; ++j) {
          const std::int64_t index = values.Integer(property.type, place);
          if (index < 0 || index >= vertex_count) {
            values.Fail(
                fmt::format("vertex index {} of face {} is out of range: the file has {} vertices",
                            index, i, vertex_count));
          }
          polygon.push_back(static_cast<std::int32_t>(index));
        }
        AddFan(polygon, mesh.faces);
      }
      if (is_vertex) mesh.vertices.push_back(p);
    }
  }
  values.Finish();
  return mesh;
}

TriangleMesh ReadPly(std::string_view data, const Source& source) {
  const PlyHeader header = ReadPlyHeader(data, source);
  if (header.format == PlyHeader::Format::kAscii) {
    PlyAsciiValues values(header.lines, source);
    return ReadPlyBody(header, values, data.size(), source);
  }
  PlyBinaryValues values(data, header.lines.offset(),
                         header.format == PlyHeader::Format::kBinaryBigEndian, source);
  return ReadPlyBody(header, values, data.size(), source);
}

// ---------------------------------------------------------------------------------------------

std::string ReadFile(const std::filesystem::path& path, const Source& source) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) source.Fail(0, 0, "file not found");
  if (std::filesystem::is_directory(status)) {
    source.Fail(0, 0, "expected a mesh file, found a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) source.Fail(0, 0, "cannot open the file for reading");
  if (const auto shortfall = internal::MemoryShortfall(
          internal::ReadingNeed(path, internal::kMeshBytesPerFileByte), "a mesh file")) {
    source.Fail(0, 0, *shortfall);
  }
  std::string data(std::filesystem::file_size(path, error), '\0');
  if (error || !in.read(data.data(), static_cast<std::streamsize>(data.size()))) {
    source.Fail(0, 0, "cannot read the file");
  }
  return data;
}

}  // namespace

TriangleMesh ReadMesh(const std::filesystem::path& path) {
  const Source source(path.string());
  const std::string extension = AsciiLower(path.extension().string());
  TriangleMesh (*reader)(std::string_view, const Source&) = nullptr;
  if (extension == ".stl") {
    reader = ReadStl;
  } else if (extension == ".obj") {
    reader = ReadObj;
  } else if (extension == ".ply") {
    reader = ReadPly;
  } else if (extension == ".off") {
    reader = ReadOff;
  } else if (extension == ".step" || extension == ".stp") {
    source.Fail(0, 0,
                "a STEP file is read by ReadStep, not as a mesh: give it to a command or "
                "name it as a part's mesh in an assembly file");
  } else {
    source.Fail(0, 0,
                fmt::format("{}; supported: .stl, .obj, .ply, .off",
                            extension.empty() ? "the file name has no extension"
                                              : fmt::format("unsupported mesh file extension {}",
                                                            Quote(extension))));
  }
  const std::string data = ReadFile(path, source);
  if (data.empty()) source.Fail(0, 0, "expected a mesh, found an empty file");
  TriangleMesh mesh = reader(data, source);
  if (mesh.faces.empty()) {
    source.Fail(0, 0,
                fmt::format("expected a mesh with faces, found {} vertices and no faces",
                            mesh.vertices.size()));
  }
  return mesh;
}

}  // namespace mechanist
