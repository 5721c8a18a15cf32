#pragma once
// What VTK says while it reads, caught instead of printed. VTK reports many
// read errors only through its global output window (vtkGenericWarningMacro
// in the legacy reader, the XML parser's errors), never through the reader's
// ErrorEvent, and then returns whatever its arrays held: zeros or
// uninitialised memory. A read is only trusted when VTK said nothing.
#include <string>

#include <vtkSmartPointer.h>

class vtkOutputWindow;

namespace tg::io {

// For one read: every VTK error and warning goes to first() instead of the
// terminal; the previous output window and warning display come back after.
class VtkMessageCapture {
 public:
  VtkMessageCapture();
  ~VtkMessageCapture();
  VtkMessageCapture(const VtkMessageCapture&) = delete;
  VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;
  // The first error or warning, on one line without VTK's file:line prefix;
  // empty when VTK said nothing.
  std::string first() const;

 private:
  vtkSmartPointer<vtkOutputWindow> previous_, window_;
  int previousDisplay_;
};

// "ERROR: In /path/vtkX.cxx, line 12\nvtkX (0x55..): what\n\n" -> "VTK: what".
std::string cleanVtkMessage(const std::string& text);

}  // namespace tg::io
