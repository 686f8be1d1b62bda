#include "io/internal/json_source.h"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <string>

#include "io/input_error.h"

namespace mechanist::internal {
namespace {

constexpr int kMaxDepth = 256;

class Parser {
 public:
  Parser(std::string_view text, JsonSource& out) : text_(text), out_(out) {}

  void ParseDocument() {
    SkipSpace();
    out_.root = ParseValue("", 0);
    SkipSpace();
    if (pos_ < text_.size()) {
      Fail(fmt::format("expected the end of the document, found {}", Describe()));
    }
  }

 private:
  [[noreturn]] void Fail(const std::string& message) const {
    throw InputError(out_.file, "", line_, column_, fmt::format("invalid JSON: {}", message));
  }

  std::string Describe() const {
    if (pos_ >= text_.size()) return "the end of the file";
    const auto c = static_cast<unsigned char>(text_[pos_]);
    if (c < 0x20) return "a control character";
    // A byte outside ASCII (a binary file, another encoding) as its code: the terminal
    // would show it as garbage or not at all.
    if (c > 0x7e) return fmt::format("the byte 0x{:02x}", c);
    return fmt::format("'{}'", static_cast<char>(c));
  }

  void Advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }

  void SkipSpace() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        Advance();
      } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
        while (pos_ < text_.size() && text_[pos_] != '\n') Advance();
      } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
        const int line = line_, column = column_;
        Advance();
        Advance();
        while (pos_ + 1 < text_.size() && !(text_[pos_] == '*' && text_[pos_ + 1] == '/')) {
          Advance();
        }
        if (pos_ + 1 >= text_.size()) {
          throw InputError(out_.file, "", line, column, "invalid JSON: unterminated /* comment");
        }
        Advance();
        Advance();
      } else {
        return;
      }
    }
  }

  bool Consume(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    for (std::size_t i = 0; i < word.size(); ++i) Advance();
    return true;
  }

  nlohmann::ordered_json ParseValue(const std::string& pointer, int depth) {
    if (depth > kMaxDepth) Fail(fmt::format("nesting deeper than {} levels", kMaxDepth));
    out_.positions[pointer] = {line_, column_};
    if (pos_ >= text_.size()) Fail("expected a value, found the end of the file");
    const char c = text_[pos_];
    if (c == '{') return ParseObject(pointer, depth);
    if (c == '[') return ParseArray(pointer, depth);
    if (c == '"') return ParseString();
    if (c == '-' || (c >= '0' && c <= '9')) return ParseNumber();
    if (Consume("true")) return true;
    if (Consume("false")) return false;
    if (Consume("null")) return nullptr;
    Fail(fmt::format("expected a value, found {}", Describe()));
  }

  nlohmann::ordered_json ParseObject(const std::string& pointer, int depth) {
    nlohmann::ordered_json object = nlohmann::ordered_json::object();
    Advance();
    SkipSpace();
    if (pos_ < text_.size() && text_[pos_] == '}') {
      Advance();
      return object;
    }
    while (true) {
      SkipSpace();
      if (pos_ >= text_.size() || text_[pos_] != '"') {
        Fail(fmt::format("expected a key in double quotes, found {}", Describe()));
      }
      const int key_line = line_, key_column = column_;
      const std::string key = ParseString();
      if (object.contains(key)) {
        throw InputError(out_.file, JoinPointer(pointer, key), key_line, key_column,
                         fmt::format("invalid JSON: duplicate key \"{}\"", key));
      }
      SkipSpace();
      if (pos_ >= text_.size() || text_[pos_] != ':') {
        Fail(fmt::format("expected ':', found {}", Describe()));
      }
      Advance();
      SkipSpace();
      object[key] = ParseValue(JoinPointer(pointer, key), depth + 1);
      SkipSpace();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        Advance();
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == '}') {
        Advance();
        return object;
      }
      Fail(fmt::format("expected ',' or '}}', found {}", Describe()));
    }
  }

  nlohmann::ordered_json ParseArray(const std::string& pointer, int depth) {
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    Advance();
    SkipSpace();
    if (pos_ < text_.size() && text_[pos_] == ']') {
      Advance();
      return array;
    }
    while (true) {
      SkipSpace();
      array.push_back(ParseValue(JoinPointer(pointer, std::to_string(array.size())), depth + 1));
      SkipSpace();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        Advance();
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == ']') {
        Advance();
        return array;
      }
      Fail(fmt::format("expected ',' or ']', found {}", Describe()));
    }
  }

  unsigned ParseHex4() {
    unsigned code = 0;
    for (int i = 0; i < 4; ++i) {
      if (pos_ >= text_.size() || !std::isxdigit(static_cast<unsigned char>(text_[pos_]))) {
        Fail(fmt::format("expected 4 hexadecimal digits after \\u, found {}", Describe()));
      }
      const char h = text_[pos_];
      code = code * 16 + (h <= '9' ? h - '0' : (h | 0x20) - 'a' + 10);
      Advance();
    }
    return code;
  }

  static void AppendUtf8(std::string& s, unsigned code) {
    if (code < 0x80) {
      s += static_cast<char>(code);
    } else if (code < 0x800) {
      s += static_cast<char>(0xC0 | (code >> 6));
      s += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      s += static_cast<char>(0xE0 | (code >> 12));
      s += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      s += static_cast<char>(0xF0 | (code >> 18));
      s += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      s += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  std::string ParseString() {
    std::string s;
    Advance();  // opening quote
    while (true) {
      if (pos_ >= text_.size()) Fail("unterminated string");
      const char c = text_[pos_];
      if (c == '"') {
        Advance();
        return s;
      }
      if (static_cast<unsigned char>(c) < 0x20) Fail("control character in a string");
      if (c != '\\') {
        s += c;
        Advance();
        continue;
      }
      Advance();
      if (pos_ >= text_.size()) Fail("unterminated string");
      const char e = text_[pos_];
      Advance();
      switch (e) {
        case '"':
          s += '"';
          break;
        case '\\':
          s += '\\';
          break;
        case '/':
          s += '/';
          break;
        case 'b':
          s += '\b';
          break;
        case 'f':
          s += '\f';
          break;
        case 'n':
          s += '\n';
          break;
        case 'r':
          s += '\r';
          break;
        case 't':
          s += '\t';
          break;
        case 'u': {
          unsigned code = ParseHex4();
          if (code >= 0xD800 && code <= 0xDBFF) {
            if (!Consume("\\u")) Fail("unpaired UTF-16 surrogate in a string");
            const unsigned low = ParseHex4();
            if (low < 0xDC00 || low > 0xDFFF) Fail("unpaired UTF-16 surrogate in a string");
            code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
          } else if (code >= 0xDC00 && code <= 0xDFFF) {
            Fail("unpaired UTF-16 surrogate in a string");
          }
          AppendUtf8(s, code);
          break;
        }
        default:
          Fail(fmt::format("invalid escape '\\{}' in a string", e));
      }
    }
  }

  nlohmann::ordered_json ParseNumber() {
    const std::size_t start = pos_;
    auto digits = [this] {
      std::size_t n = 0;
      while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
        Advance();
        ++n;
      }
      return n;
    };
    bool integral = true;
    if (text_[pos_] == '-') Advance();
    if (pos_ < text_.size() && text_[pos_] == '0') {
      Advance();
    } else if (digits() == 0) {
      Fail(fmt::format("expected digits in a number, found {}", Describe()));
    }
    if (pos_ < text_.size() && text_[pos_] == '.') {
      integral = false;
      Advance();
      if (digits() == 0) Fail(fmt::format("expected digits after '.', found {}", Describe()));
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      integral = false;
      Advance();
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) Advance();
      if (digits() == 0) Fail(fmt::format("expected digits in an exponent, found {}", Describe()));
    }
    const std::string literal(text_.substr(start, pos_ - start));
    if (integral) {
      errno = 0;
      char* end = nullptr;
      const long long value = std::strtoll(literal.c_str(), &end, 10);
      if (errno == 0) return value;
    }
    const double value = std::strtod(literal.c_str(), nullptr);
    return value;
  }

  std::string_view text_;
  JsonSource& out_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

JsonPosition JsonSource::PositionOf(const std::string& pointer) const {
  std::string p = pointer;
  while (true) {
    const auto it = positions.find(p);
    if (it != positions.end()) return it->second;
    if (p.empty()) return {};
    p.erase(p.rfind('/'));
  }
}

JsonSource ParseJson(std::string_view text, const std::string& file) {
  JsonSource source;
  source.file = file;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  Parser(text, source).ParseDocument();
  return source;
}

std::string JoinPointer(const std::string& pointer, std::string_view token) {
  std::string joined = pointer + "/";
  for (const char c : token) {
    if (c == '~') {
      joined += "~0";
    } else if (c == '/') {
      joined += "~1";
    } else {
      joined += c;
    }
  }
  return joined;
}

}  // namespace mechanist::internal
