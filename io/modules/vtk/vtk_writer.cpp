#include <vtkDataSetWriter.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>

#include "io/core/format_impl.h"

namespace tg::io {
namespace {

vtkSmartPointer<vtkFloatArray> tensorArray(const TensorField& f) {
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName("tensors");
  a->SetNumberOfComponents(9);
  a->SetNumberOfTuples(vtkIdType(f.size()));
  for (std::size_t i = 0; i < f.size(); ++i) {
    const float* t = &f.tensors[6 * i];
    const float m[9] = {t[0], t[1], t[2], t[1], t[3], t[4], t[2], t[4], t[5]};
    a->SetTypedTuple(vtkIdType(i), m);
  }
  return a;
}

}  // namespace

std::string impl::encodeVtk(const TensorField& f, const std::string& path) {
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  vtkSmartPointer<vtkDataSet> ds;
  if (ext == "vti") {
    if (!f.grid || std::size_t(f.grid->dims[0]) * f.grid->dims[1] * f.grid->dims[2] != f.size())
      throw std::runtime_error("writeVtk: " + path + ": .vti needs a complete grid");
    auto img = vtkSmartPointer<vtkImageData>::New();
    img->SetDimensions(f.grid->dims);
    img->SetSpacing(f.grid->spacing);
    img->SetOrigin(f.grid->origin);
    img->SetDirectionMatrix(f.grid->directions);
    ds = img;
  } else {
    auto pts = vtkSmartPointer<vtkPoints>::New();
    pts->SetDataTypeToFloat();
    pts->SetNumberOfPoints(vtkIdType(f.size()));
    for (std::size_t i = 0; i < f.size(); ++i) pts->SetPoint(vtkIdType(i), &f.positions[3 * i]);
    if (ext == "vtp") {
      auto pd = vtkSmartPointer<vtkPolyData>::New();
      pd->SetPoints(pts);
      ds = pd;
    } else {
      auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
      ug->SetPoints(pts);
      ds = ug;
    }
  }
  ds->GetPointData()->SetTensors(tensorArray(f));
  // VTK's writers lose the error of their last buffered write, so they write
  // into memory and writeVtk puts the bytes in the file through AtomicFile's
  // checks.
  int ok = 0;
  std::string bytes;
  if (ext == "vtk") {
    auto w = vtkSmartPointer<vtkDataSetWriter>::New();
    w->WriteToOutputStringOn();
    w->SetFileTypeToBinary();
    w->SetInputData(ds);
    ok = w->Write();
    bytes = w->GetOutputStdString();
  } else if (ext == "vti" || ext == "vtu" || ext == "vtp") {
    vtkSmartPointer<vtkXMLWriter> w;
    if (ext == "vti") w = vtkSmartPointer<vtkXMLImageDataWriter>::New();
    else if (ext == "vtu") w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    else w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->WriteToOutputStringOn();
    w->SetInputData(ds);
    w->SetDataModeToAppended();
    w->SetCompressorTypeToZLib();
    ok = w->Write();
    bytes = w->GetOutputString();
  } else {
    throw std::runtime_error("writeVtk: " + path + ": unknown extension");
  }
  if (!ok || bytes.empty()) throw std::runtime_error("writeVtk: " + path + ": VTK writer failed");
  return bytes;
}

}  // namespace tg::io
