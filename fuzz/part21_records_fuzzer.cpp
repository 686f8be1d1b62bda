// libFuzzer harness of mechanist's Part 21 scanner alone (io/occt/part21_records.h): any bytes
// give records or nothing, without reading outside them (AddressSanitizer), and the records it
// gives hold together: every text inside the input and apart from the others, with a character
// of no text after it (where Part21WorkLibrary writes its NUL), every record's parameters inside
// the list, every `$n` named by max_sub; every undefined reference is held by an entity.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <vector>

#include "io/occt/part21_records.h"

namespace {

void Require(bool holds) {
  if (!holds) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::optional<mechanist::Part21Records> records = mechanist::ReadPart21Records(text);
  if (!records) return 0;
  using Span = mechanist::Part21Records::Span;
  std::vector<Span> texts;
  Require(records->header_records <= records->records.size());
  for (const mechanist::Part21Records::Record& r : records->records) {
    Require(r.sub >= 0 && r.sub <= records->max_sub);
    if (r.ident.size > 0) texts.push_back(r.ident);
    if (r.type.size > 0) texts.push_back(r.type);
    Require(std::size_t{r.first} + r.count <= records->params.size());
  }
  for (const mechanist::Part21Records::Param& p : records->params) {
    if (p.kind == mechanist::Part21Records::Kind::kSub) {
      Require(p.sub >= 1 && p.sub <= records->max_sub);
    } else {
      Require(p.text.size > 0);
      texts.push_back(p.text);
    }
  }
  // Each text's end (its NUL's place) lies before the next text and inside the input.
  std::sort(texts.begin(), texts.end(), [](Span a, Span b) { return a.begin < b.begin; });
  for (std::size_t k = 0; k < texts.size(); ++k) {
    const std::size_t end = std::size_t{texts[k].begin} + texts[k].size;
    Require(end < (k + 1 < texts.size() ? std::size_t{texts[k + 1].begin} : size));
  }
  // Each undefined reference is a reference, held by an entity.
  for (const mechanist::Part21UndefinedReference& u :
       mechanist::UndefinedReferences(*records, text)) {
    Require(u.entity.size() > 1 && u.entity[0] == '#' && u.missing.size() > 1 &&
            u.missing[0] == '#');
  }
  return 0;
}
