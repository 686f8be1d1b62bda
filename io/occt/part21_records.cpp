#include "io/occt/part21_records.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_set>
#include <utility>

namespace mechanist {
namespace {

using Kind = Part21Records::Kind;
using Param = Part21Records::Param;
using Record = Part21Records::Record;
using Span = Part21Records::Span;

bool IsDigit(char c) { return c >= '0' && c <= '9'; }
bool IsUpper(char c) { return c >= 'A' && c <= 'Z'; }
bool IsLetter(char c) { return IsUpper(c) || (c >= 'a' && c <= 'z'); }
bool IsWordChar(char c) { return IsLetter(c) || IsDigit(c) || c == '_'; }
bool IsSpace(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }
bool IsHexDigit(char c) { return IsDigit(c) || (c >= 'A' && c <= 'F'); }
// A character of a text other than its apostrophes, as read here: printable ASCII, tabs and
// line breaks, and the bytes from 0x80 (UTF-8 and Latin-1 names). Other control characters
// are left to Open CASCADE's parser, to be safe: its scanners have read them differently.
bool IsTextChar(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u >= 0x20 && u <= 0x7E) || u >= 0x80 || c == '\t' || c == '\n' || c == '\r';
}

// [begin, end) of the text (shorter than 4 GiB).
Span SpanOf(std::size_t begin, std::size_t end) {
  return {static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end - begin)};
}

// The scanner. Each member that reads returns false when the text leaves the subset.
class Scanner {
 public:
  // Room for the records and parameters real exports have for their size (the robot hand has
  // a record per 36 bytes and a parameter per 12), so that the lists are seldom moved: moving
  // them and touching fresh pages took most of the scan's time.
  explicit Scanner(std::string_view text) : text_(text), open_(kMaxDepth + 1) {
    out_.records.reserve(text.size() / 32);
    out_.params.reserve(text.size() / 10);
  }

  std::optional<Part21Records> Read() {
    if (text_.size() >= std::numeric_limits<std::uint32_t>::max()) return std::nullopt;
    if (!Keyword("ISO-10303-21;") || !Keyword("HEADER;")) return std::nullopt;
    while (!Keyword("ENDSEC;")) {
      if (!Instance(Span{}, /*complex=*/false) || !Expect(';')) return std::nullopt;
    }
    out_.header_records = out_.records.size();
    if (!Keyword("DATA;")) return std::nullopt;
    while (!Keyword("ENDSEC;")) {
      if (!Entity()) return std::nullopt;
    }
    // Open CASCADE's grammar wants an entity at least: it reports an empty data section.
    if (out_.records.size() == out_.header_records) return std::nullopt;
    // Open CASCADE's scanner ignores whatever follows the end keyword.
    if (!Keyword("END-ISO-10303-21;")) return std::nullopt;
    return std::move(out_);
  }

 private:
  static constexpr int kMaxDepth = 64;

  char Peek() const { return at_ < text_.size() ? text_[at_] : '\0'; }

  // Skips blanks and comments. A comment holding an apostrophe or a keyword (which older Open
  // CASCADE scanners saw inside comments: a text, ISO-10303-21; or ENDSTEP;) is left to Open
  // CASCADE's parser, to be safe.
  bool SkipSpace() {
    for (;;) {
      while (at_ < text_.size() && IsSpace(text_[at_])) ++at_;
      if (text_.compare(at_, 2, "/*") != 0) return true;
      const std::size_t end = text_.find("*/", at_ + 2);
      if (end == std::string_view::npos) return false;
      const std::string_view comment = text_.substr(at_ + 2, end - at_ - 2);
      if (comment.find('\'') != std::string_view::npos ||
          comment.find("ISO") != std::string_view::npos ||
          comment.find("ENDSTEP") != std::string_view::npos) {
        return false;
      }
      at_ = end + 2;
    }
  }

  bool Keyword(std::string_view keyword) {
    if (!SkipSpace() || text_.compare(at_, keyword.size(), keyword) != 0) return false;
    at_ += keyword.size();
    return true;
  }

  bool Expect(char c) {
    if (!SkipSpace() || Peek() != c) return false;
    ++at_;
    return true;
  }

  // `[a-zA-Z][a-zA-Z0-9_]*` at the current place; empty for ENDSCOPE, a keyword to Open
  // CASCADE's scanner.
  Span Word() {
    const std::size_t begin = at_;
    if (!IsLetter(Peek())) return {};
    while (at_ < text_.size() && IsWordChar(text_[at_])) ++at_;
    if (text_.substr(begin, at_ - begin) == "ENDSCOPE") return {};
    return SpanOf(begin, at_);
  }

  // `#7 = TYPE(...);` or `#7 = (A(...) B(...));`. Open CASCADE's scanner takes `#7` as an
  // entity's name only when blanks on the same line and `=` follow it.
  bool Entity() {
    if (!SkipSpace() || Peek() != '#') return false;
    const std::size_t begin = at_++;
    while (at_ < text_.size() && IsDigit(text_[at_])) ++at_;
    const Span ident = SpanOf(begin, at_);
    if (ident.size < 2) return false;
    while (Peek() == ' ' || Peek() == '\t') ++at_;
    if (Peek() != '=') return false;
    ++at_;
    if (!SkipSpace()) return false;
    if (Peek() != '(') return Instance(ident, /*complex=*/false) && Expect(';');
    ++at_;
    return Instance(ident, /*complex=*/true) && Expect(')') && Expect(';');
  }

  // `TYPE(...)`, or the parts of a complex entity up to its closing parenthesis: the first
  // named `ident`, the others unnamed.
  bool Instance(Span ident, bool complex) {
    do {
      if (!SkipSpace()) return false;
      const Span type = Word();
      if (type.size == 0 || !SkipSpace() || Peek() != '(') return false;
      next_sub_ = 1;
      if (!List(Record{ident, 0, type}, 0)) return false;
      ident = Span{};
      if (!SkipSpace()) return false;
    } while (complex && Peek() != ')');
    return true;
  }

  // The list at '(' as `record`'s parameters; the record is appended when the list closes,
  // after the records of the lists nested in it.
  bool List(Record record, int depth) {
    if (depth > kMaxDepth) return false;
    ++at_;  // '('
    std::vector<Param>& params = open_[depth];
    params.clear();
    if (!SkipSpace()) return false;
    if (Peek() == ')') {
      ++at_;
    } else {
      for (;;) {
        if (!Parameter(depth, &params) || !SkipSpace()) return false;
        const char c = Peek();
        ++at_;
        if (c == ')') break;
        if (c != ',' || !SkipSpace()) return false;
      }
    }
    record.first = static_cast<std::uint32_t>(out_.params.size());
    record.count = static_cast<std::uint32_t>(params.size());
    out_.params.insert(out_.params.end(), params.begin(), params.end());
    out_.records.push_back(record);
    return true;
  }

  bool Parameter(int depth, std::vector<Param>* params) {
    const char c = Peek();
    if (c == '(' || IsLetter(c)) {
      Span type;
      if (c != '(') {
        type = Word();
        if (type.size == 0 || !SkipSpace() || Peek() != '(') return false;
      }
      const int sub = next_sub_++;
      if (sub > out_.max_sub) out_.max_sub = sub;
      if (!List(Record{Span{}, sub, type}, depth + 1)) return false;
      params->push_back({Kind::kSub, Span{}, sub});
      return true;
    }
    const std::size_t begin = at_;
    Kind kind;
    switch (c) {
      case '#':
        ++at_;
        while (at_ < text_.size() && IsDigit(text_[at_])) ++at_;
        if (at_ - begin < 2) return false;
        kind = Kind::kIdent;
        break;
      case '\'':
        if (!Text()) return false;
        kind = Kind::kText;
        break;
      case '"':
        ++at_;
        while (at_ < text_.size() && IsHexDigit(text_[at_])) ++at_;
        if (at_ - begin < 2 || Peek() != '"') return false;
        ++at_;
        kind = Kind::kHexa;
        break;
      case '*':
        ++at_;
        kind = Kind::kMisc;
        break;
      case '$':
        ++at_;
        kind = Kind::kVoid;
        break;
      case '.':
        if (IsUpper(text_.size() > at_ + 1 ? text_[at_ + 1] : '\0') ||
            text_.compare(at_, 2, "._") == 0) {
          ++at_;
          while (at_ < text_.size() &&
                 (IsUpper(text_[at_]) || IsDigit(text_[at_]) || text_[at_] == '_'))
            ++at_;
          if (Peek() != '.') return false;
          ++at_;
          kind = Kind::kEnum;
          break;
        }
        [[fallthrough]];
      default:
        if (!Number(&kind)) return false;
    }
    params->push_back({kind, SpanOf(begin, at_), 0});
    return true;
  }

  // A text. Open CASCADE's scanner ends a text at an apostrophe followed by blanks and line
  // breaks, then ',' or ')' (EndsText); elsewhere only doubled apostrophes (one apostrophe of
  // the text) are read here.
  bool Text() {
    ++at_;
    for (;;) {
      while (at_ < text_.size() && text_[at_] != '\'') {
        if (!IsTextChar(text_[at_])) return false;
        ++at_;
      }
      if (at_ >= text_.size()) return false;
      ++at_;
      if (EndsText()) return true;
      if (Peek() != '\'') return false;
      ++at_;
      if (EndsText()) return false;  // "''," ends or doubles: the scanners' rules differ
    }
  }

  // Whether the apostrophe before the current place ends a text to Open CASCADE's scanner:
  // blanks, line breaks and double quotes (its rule's class holds them), then ',' or ')'.
  bool EndsText() const {
    std::size_t next = at_;
    while (next < text_.size() && (text_[next] == ' ' || text_[next] == '\n' ||
                                   text_[next] == '\r' || text_[next] == '"')) {
      ++next;
    }
    return next < text_.size() && (text_[next] == ',' || text_[next] == ')');
  }

  // A number as Open CASCADE's scanner splits them (flex, longest match, the first rule on a
  // tie): `[-+0-9][0-9]*` an integer, `[-+.0-9][.0-9]+` a real, and with `E[-+0-9][0-9]*`
  // after that a real too. Tokens without a digit ("-", "..") and `1E5` (which it reads as 1
  // then E5) are left to it.
  bool Number(Kind* kind) {
    const std::size_t begin = at_;
    const char first = Peek();
    if (!(first == '-' || first == '+' || first == '.' || IsDigit(first))) return false;
    ++at_;
    bool dot = first == '.';
    bool digit = IsDigit(first);
    while (at_ < text_.size() && (IsDigit(text_[at_]) || text_[at_] == '.')) {
      dot = dot || text_[at_] == '.';
      digit = digit || IsDigit(text_[at_]);
      ++at_;
    }
    if (!digit) return false;
    const bool run = at_ - begin >= 2;  // the real rules need two characters before 'E'
    if (Peek() == 'E') {
      if (!run) return false;
      ++at_;
      if (Peek() == '-' || Peek() == '+') ++at_;
      if (!IsDigit(Peek())) return false;
      while (at_ < text_.size() && IsDigit(text_[at_])) ++at_;
      *kind = Kind::kReal;
      return true;
    }
    *kind = dot ? Kind::kReal : Kind::kInteger;
    return true;
  }

  std::string_view text_;
  std::size_t at_ = 0;
  int next_sub_ = 1;
  std::vector<std::vector<Param>> open_;  // the parameters of the open lists, by depth
  Part21Records out_;
};

}  // namespace

std::optional<Part21Records> ReadPart21Records(std::string_view text) {
  return Scanner(text).Read();
}

std::vector<Part21UndefinedReference> UndefinedReferences(const Part21Records& records,
                                                          std::string_view text) {
  const auto of = [&](Part21Records::Span s) { return text.substr(s.begin, s.size); };
  // The digits of `#0123` that name the entity (`123`), of any length, as keys.
  const auto number = [&](Part21Records::Span s) {
    const std::string_view digits = of(s).substr(1);
    return digits.substr(std::min(digits.find_first_not_of('0'), digits.size() - 1));
  };
  std::unordered_set<std::string_view> defined;
  for (std::size_t r = records.header_records; r < records.records.size(); ++r) {
    if (records.records[r].ident.size > 0) defined.insert(number(records.records[r].ident));
  }
  // A record's nested lists come before it, and a complex entity's further parts after its
  // first, without an ident: the references met are held until the record they belong to.
  std::vector<Part21UndefinedReference> undefined;
  std::size_t pending = 0;  // undefined[pending, end) await their entity
  const Part21Records::Record* entity = nullptr;
  for (std::size_t r = records.header_records; r < records.records.size(); ++r) {
    const Part21Records::Record& record = records.records[r];
    for (std::uint32_t k = record.first; k < record.first + record.count; ++k) {
      const Part21Records::Param& p = records.params[k];
      if (p.kind == Part21Records::Kind::kIdent && !defined.count(number(p.text))) {
        undefined.push_back({"", "", std::string(of(p.text))});
      }
    }
    if (record.sub > 0) continue;
    if (record.ident.size > 0) entity = &record;
    for (; entity && pending < undefined.size(); ++pending) {
      undefined[pending].entity = of(entity->ident);
      undefined[pending].type = of(entity->type);
    }
  }
  return undefined;
}

}  // namespace mechanist
