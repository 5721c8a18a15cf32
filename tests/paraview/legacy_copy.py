"""The kitten (or any VTK XML dataset) as a legacy binary .vtk, for pvbatch.

usage: legacy_copy.py IN.vtu OUT.vtk
ParaView 5.11's own VTK cannot read XML files with appended data under
Debian 12's libexpat1 2.5.0-1+deb12u2 (expat's reparse deferral; VTK issue
19258): "Error parsing XML ... not well-formed (invalid token)". Debian's
VTK 9.1 (python3-vtk9), which the CLI reads with, can; a legacy copy holds
the same arrays, read the same by both.
"""
import sys

from vtkmodules.vtkIOLegacy import vtkDataSetWriter
from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader

r = vtkXMLGenericDataObjectReader()
r.SetFileName(sys.argv[1])
r.Update()
data = r.GetOutput()
if data is None or data.GetNumberOfPoints() == 0:
    sys.exit("legacy_copy.py: %s: read no points" % sys.argv[1])
w = vtkDataSetWriter()
w.SetFileName(sys.argv[2])
w.SetInputData(data)
w.SetFileTypeToBinary()
if not w.Write():
    sys.exit("legacy_copy.py: %s: could not be written" % sys.argv[2])
