#include "io/vtk_capture.h"

#include <cctype>
#include <limits>
#include <sstream>

#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

namespace tg::io {
namespace {

class CaptureWindow : public vtkOutputWindow {
 public:
  static CaptureWindow* New();
  vtkTypeMacro(CaptureWindow, vtkOutputWindow)
  void DisplayText(const char* t) override { keep(t); }
  void DisplayErrorText(const char* t) override { keep(t); }
  void DisplayWarningText(const char* t) override { keep(t); }
  void DisplayGenericWarningText(const char* t) override { keep(t); }
  void DisplayDebugText(const char*) override {}
  std::string first;

 private:
  void keep(const char* text) {
    if (first.empty() && text) first = cleanVtkMessage(text);
  }
};
vtkStandardNewMacro(CaptureWindow);

// num_get that also takes [+-]nan and [+-]inf(inity), case-insensitive.
class NonFiniteNumGet : public std::num_get<char> {
 protected:
  iter_type do_get(iter_type in, iter_type end, std::ios_base& io, std::ios_base::iostate& err,
                   float& v) const override {
    return real(in, end, io, err, v);
  }
  iter_type do_get(iter_type in, iter_type end, std::ios_base& io, std::ios_base::iostate& err,
                   double& v) const override {
    return real(in, end, io, err, v);
  }
  iter_type do_get(iter_type in, iter_type end, std::ios_base& io, std::ios_base::iostate& err,
                   long double& v) const override {
    return real(in, end, io, err, v);
  }

 private:
  template <class T>
  iter_type real(iter_type in, iter_type end, std::ios_base& io, std::ios_base::iostate& err, T& v) const {
    bool negative = false;
    if (in != end && (*in == '-' || *in == '+')) {
      negative = *in == '-';
      ++in;
    }
    const auto lower = [](char c) { return char(std::tolower(static_cast<unsigned char>(c))); };
    if (in != end && (lower(*in) == 'n' || lower(*in) == 'i')) {
      std::string word;
      for (; in != end && std::isalpha(static_cast<unsigned char>(*in)) && word.size() < 9; ++in) word += lower(*in);
      err = in == end ? std::ios_base::eofbit : std::ios_base::goodbit;
      if (word == "nan") v = std::numeric_limits<T>::quiet_NaN();
      else if (word == "inf" || word == "infinity") v = negative ? -std::numeric_limits<T>::infinity()
                                                                 : std::numeric_limits<T>::infinity();
      else err |= std::ios_base::failbit;
      return in;
    }
    if (in != end && (*in == '-' || *in == '+')) {  // a second sign
      err = std::ios_base::failbit;
      return in;
    }
    in = std::num_get<char>::do_get(in, end, io, err, v);
    if (negative) v = -v;
    return in;
  }
};

}  // namespace

std::string cleanVtkMessage(const std::string& text) {
  std::istringstream in(text);
  std::string line, msg;
  while (std::getline(in, line)) {
    // An ErrorEvent's text has the location glued to the message.
    if (const auto at = line.find(": In "); at != std::string::npos) {
      const auto next = line.find(", line ", at);
      std::size_t e = next == std::string::npos ? line.size() : next + 7;
      while (e < line.size() && std::isdigit(static_cast<unsigned char>(line[e]))) ++e;
      line.erase(0, e);
    }
    if (const auto p = line.find("): "); p != std::string::npos && line.find(" (0x") < p) line.erase(0, p + 3);
    if (!line.empty()) msg += (msg.empty() ? "" : " ") + line;
  }
  return msg.empty() ? std::string("VTK reported a problem") : "VTK: " + msg;
}

VtkMessageCapture::VtkMessageCapture()
    : previous_(vtkOutputWindow::GetInstance()),
      window_(vtkSmartPointer<CaptureWindow>::New()),
      previousDisplay_(vtkObject::GetGlobalWarningDisplay()) {
  vtkOutputWindow::SetInstance(window_);
  vtkObject::GlobalWarningDisplayOn();  // off, VTK would not report them at all
}

VtkMessageCapture::~VtkMessageCapture() {
  vtkOutputWindow::SetInstance(previous_);
  vtkObject::SetGlobalWarningDisplay(previousDisplay_);
}

std::string VtkMessageCapture::first() const { return static_cast<CaptureWindow*>(window_.Get())->first; }

NonFiniteNumbers::NonFiniteNumbers()
    : previous_(std::locale::global(std::locale(std::locale::classic(), new NonFiniteNumGet))) {}

NonFiniteNumbers::~NonFiniteNumbers() { std::locale::global(previous_); }

}  // namespace tg::io
