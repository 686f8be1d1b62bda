#include "io/occt/part21_work_library.h"

#include <Interface_Check.hxx>
#include <Interface_ParamType.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <StepData_FileRecognizer.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepReaderData.hxx>
#include <StepData_StepReaderTool.hxx>
#include <cassert>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "io/occt/part21_records.h"

namespace mechanist {
namespace {

Interface_ParamType ParamType(Part21Records::Kind kind) {
  switch (kind) {
    case Part21Records::Kind::kInteger:
      return Interface_ParamInteger;
    case Part21Records::Kind::kReal:
      return Interface_ParamReal;
    case Part21Records::Kind::kIdent:
      return Interface_ParamIdent;
    case Part21Records::Kind::kVoid:
      return Interface_ParamVoid;
    case Part21Records::Kind::kText:
      return Interface_ParamText;
    case Part21Records::Kind::kEnum:
      return Interface_ParamEnum;
    case Part21Records::Kind::kHexa:
      return Interface_ParamHexa;
    case Part21Records::Kind::kMisc:
      return Interface_ParamMisc;
    case Part21Records::Kind::kSub:
      return Interface_ParamSub;
  }
  return Interface_ParamMisc;
}

// Open CASCADE keeps the records' texts as C strings until the model is loaded (as
// StepFile_Read keeps its character pages), so they stay in the file's own buffer, each ended
// by a NUL written over the separator that follows it, and the `$n` names here: both must
// outlive the load.
class RecordTexts {
 public:
  RecordTexts(std::string* text, int max_sub) : text_(text) {
    subs_.reserve(static_cast<std::size_t>(max_sub) + 1);
    for (int n = 0; n <= max_sub; ++n) subs_.push_back("$" + std::to_string(n));
  }
  const char* Of(Part21Records::Span span) {
    assert(span.begin + span.size < text_->size());  // a separator follows every token
    (*text_)[span.begin + span.size] = '\0';
    return text_->c_str() + span.begin;
  }
  const char* Sub(int n) const { return subs_[static_cast<std::size_t>(n)].c_str(); }

 private:
  std::string* text_;
  std::vector<std::string> subs_;
};

// The records as StepData_StepReaderData, as StepFile_Read fills it.
Handle(StepData_StepReaderData) ReaderData(const Part21Records& records, RecordTexts* texts,
                                           const Handle(StepData_StepModel) & model) {
  Handle(StepData_StepReaderData) data = new StepData_StepReaderData(
      static_cast<int>(records.header_records), static_cast<int>(records.records.size()),
      static_cast<int>(records.params.size()), model->SourceCodePage());
  int number = 0;
  for (const Part21Records::Record& r : records.records) {
    ++number;
    const char* ident = r.sub > 0          ? texts->Sub(r.sub)
                        : r.ident.size > 0 ? texts->Of(r.ident)
                                           : "#0";
    const char* type = r.type.size > 0 ? texts->Of(r.type) : "/* (SUB) */";
    data->SetRecord(number, ident, type, r.count > 0 ? 1 : 0);
    for (std::size_t k = r.first; k < r.first + r.count; ++k) {
      const Part21Records::Param& p = records.params[k];
      data->AddStepParam(
          number, p.kind == Part21Records::Kind::kSub ? texts->Sub(p.sub) : texts->Of(p.text),
          ParamType(p.kind));
    }
    data->InitParams(number);
  }
  return data;
}

// The text of `name` when it is a regular file the scanner can take (under 4 GiB).
std::optional<std::string> FileText(const char* name) {
  std::error_code error;
  const std::filesystem::path path(name);
  if (!std::filesystem::is_regular_file(path, error)) return std::nullopt;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size >= std::numeric_limits<std::uint32_t>::max()) return std::nullopt;
  std::string text(static_cast<std::size_t>(size), '\0');
  std::ifstream in(path, std::ios::binary);
  if (!in.read(text.data(), static_cast<std::streamsize>(size))) return std::nullopt;
  return text;
}

// The model of a file whose whole text is `text`, loaded as StepFile_Read loads it, with its
// messages; null when the text is outside the scanner's subset.
Handle(StepData_StepModel)
    ScannedModel(std::string text, const Handle(StepData_Protocol) & protocol) {
  const std::optional<Part21Records> records = ReadPart21Records(text);
  if (!records || records->records.size() > INT_MAX || records->params.size() > INT_MAX) {
    return nullptr;
  }
  const Handle(StepData_StepModel) model = new StepData_StepModel;
  RecordTexts texts(&text, records->max_sub);
  const Handle(StepData_StepReaderData) data = ReaderData(*records, &texts, model);
  // StepFile_Read's own reports, word for word: faults in the records (none is known to arise
  // from records this scanner gives), then references the load could not resolve.
  const int record_fails = data->GlobalCheck()->NbFails();
  if (record_fails > 0) {
    Message::SendInfo() << "**** ERR StepFile : Incorrect Syntax : Fails Count : " << record_fails
                        << " ****";
  }
  StepData_StepReaderTool tool(data, protocol);
  tool.SetErrorHandle(Standard_True);
  const Handle(StepData_FileRecognizer) by_protocol;  // none: the protocol recognises
  tool.PrepareHeader(by_protocol);
  tool.Prepare(by_protocol);
  tool.LoadModel(model);
  if (model->Protocol().IsNull()) model->SetProtocol(protocol);
  if (const int unresolved = data->GlobalCheck()->NbFails() - record_fails; unresolved > 0) {
    Message::SendInfo() << "*** ERR StepReaderData : Unresolved Reference : Fails Count : "
                        << unresolved << " ***";
  }
  tool.Clear();
  return model;
}

}  // namespace

Part21WorkLibrary::Part21WorkLibrary() {
  SetDumpLabel(1);  // as Open CASCADE's STEP controller sets up its work library
}

Standard_Integer Part21WorkLibrary::ReadFile(Standard_CString name,
                                             Handle(Interface_InterfaceModel) & model,
                                             const Handle(Interface_Protocol) & protocol) const {
  const Handle(StepData_Protocol) step = Handle(StepData_Protocol)::DownCast(protocol);
  if (!step.IsNull()) {
    if (std::optional<std::string> text = FileText(name)) {
      // The text is freed before a fall back to Open CASCADE's parser.
      const Handle(StepData_StepModel) scanned = ScannedModel(std::move(*text), step);
      if (!scanned.IsNull()) {
        model = scanned;
        return 0;
      }
    }
  }
  return StepSelect_WorkLibrary::ReadFile(name, model, protocol);
}

}  // namespace mechanist
