#include "io/modules/vtk/vtk_capture.h"

#include <cctype>
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

}  // namespace tg::io
