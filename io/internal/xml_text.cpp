#include "io/internal/xml_text.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

namespace mechanist::internal {

std::string XmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string XmlComment(std::string_view text) {
  std::string body = XmlEscape(text);
  for (std::size_t at = body.find("--"); at != std::string::npos; at = body.find("--", at)) {
    body.insert(at + 1, " ");
  }
  return fmt::format("<!-- {} -->", body);
}

std::string Number(double value) {
  if (std::abs(value) < 1e-15) return "0";
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", value);
  return text;
}

std::string Numbers(const Eigen::Vector3d& v) {
  return fmt::format("{} {} {}", Number(v.x()), Number(v.y()), Number(v.z()));
}

}  // namespace mechanist::internal
