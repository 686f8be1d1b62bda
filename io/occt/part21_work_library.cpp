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
#include <fstream>
#include <string>
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
// by a NUL written over the separator that follows it.
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
Handle(StepData_StepReaderData) ReaderData(const Part21Records& records, std::string* text,
                                           const Handle(StepData_StepModel) & model) {
  RecordTexts texts(text, records.max_sub);
  Handle(StepData_StepReaderData) data = new StepData_StepReaderData(
      static_cast<int>(records.header_records), static_cast<int>(records.records.size()),
      static_cast<int>(records.params.size()), model->SourceCodePage());
  int number = 0;
  for (const Part21Records::Record& r : records.records) {
    ++number;
    const char* ident = r.sub > 0 ? texts.Sub(r.sub) : r.ident.size > 0 ? texts.Of(r.ident) : "#0";
    const char* type = r.type.size > 0 ? texts.Of(r.type) : "/* (SUB) */";
    data->SetRecord(number, ident, type, r.count > 0 ? 1 : 0);
    for (std::size_t k = r.first; k < r.first + r.count; ++k) {
      const Part21Records::Param& p = records.params[k];
      data->AddStepParam(number,
                         p.kind == Part21Records::Kind::kSub ? texts.Sub(p.sub) : texts.Of(p.text),
                         ParamType(p.kind));
    }
    data->InitParams(number);
  }
  return data;
}

}  // namespace

Standard_Integer Part21WorkLibrary::ReadFile(Standard_CString name,
                                             Handle(Interface_InterfaceModel) & model,
                                             const Handle(Interface_Protocol) & protocol) const {
  const Handle(StepData_Protocol) step = Handle(StepData_Protocol)::DownCast(protocol);
  std::ifstream in(name, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
  if (step.IsNull() || size < 0) return StepSelect_WorkLibrary::ReadFile(name, model, protocol);
  std::string text(static_cast<std::size_t>(size), '\0');
  if (!in.seekg(0).read(text.data(), size)) {
    return StepSelect_WorkLibrary::ReadFile(name, model, protocol);
  }
  const std::optional<Part21Records> records = ReadPart21Records(text);
  if (!records || records->records.size() > INT_MAX || records->params.size() > INT_MAX) {
    return StepSelect_WorkLibrary::ReadFile(name, model, protocol);
  }
  const Handle(StepData_StepModel) step_model = new StepData_StepModel;
  const Handle(StepData_StepReaderData) data = ReaderData(*records, &text, step_model);
  // Faulty records (a duplicated entity name): Open CASCADE's parser reads it again and says so.
  const int record_fails = data->GlobalCheck()->NbFails();
  if (record_fails > 0) return StepSelect_WorkLibrary::ReadFile(name, model, protocol);

  StepData_StepReaderTool tool(data, step);
  tool.SetErrorHandle(Standard_True);
  const Handle(StepData_FileRecognizer) by_protocol;  // none: the protocol recognises
  tool.PrepareHeader(by_protocol);
  tool.Prepare(by_protocol);
  tool.LoadModel(step_model);
  if (step_model->Protocol().IsNull()) step_model->SetProtocol(step);
  // StepFile_Read's own report of unresolved references, word for word.
  if (const int unresolved = data->GlobalCheck()->NbFails(); unresolved > 0) {
    Message::SendInfo() << "*** ERR StepReaderData : Unresolved Reference : Fails Count : "
                        << unresolved << " ***";
  }
  tool.Clear();
  model = step_model;
  return 0;
}

}  // namespace mechanist
