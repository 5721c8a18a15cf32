"""Renders a dataset's point tensors with the plugin in pvbatch; the tests'
and the benchmark's one ParaView driver.

  pvbatch render_glyphs.py --plugin SO --input FILE --output PNG
          [--size W H] [--eye X Y Z --look-at X Y Z --up X Y Z --fov DEG]
          [--glyph N] [--gamma G] [--scale-mode N] [--scale S] [--color N]
          [--slice-normal X Y Z --slice-origin X Y Z] [--background R G B]
          [--select X0 Y0 X1 Y1 ... --select-cells X0 Y0 X1 Y1 ...
           --selection-out TXT]
          [--scalar-bar] [--legend-out TXT] [--cell-tensors] [--nan-every K]
          [--multiblock] [--as-six] [--merge-blocks]
          [--set PROPERTY VALUE ...] [--view-set PROPERTY VALUE ...] [--mask-array NAME]
          [--tensors NAME] [--color-by NAME] [--color-by-cells NAME] [--lut-points V R G B ...] [--lut-range LO HI]
          [--rescale LO HI --rescaled-output PNG] [--uploads-out TXT]
          [--representations-out TXT]
  pvbatch render_glyphs.py --input FILE --write-blocks VTM [--second-without-tensors]
  pvbatch render_glyphs.py --input FILE --write-height VTU

Under mpiexec, --redistribute spreads the dataset's cells over the ranks
(or give a partitioned .pvtu); each rank draws its own glyphs and IceT
composites the ranks' images by depth. Each rank reads the file itself and
keeps its run of cells: ParaView's RedistributeDataSet moves data between
ranks as appended XML, which ParaView 5.11 cannot parse under Debian 12's
current libexpat1 (tests/paraview/legacy_copy.py). --slice adds a ParaView slice of the same
dataset, drawn as a surface, to check that the two mix by depth.

--select selects the surface points in a rectangle of display pixels
(origin bottom left, corners inclusive) as ParaView's "Select Points On"
does, after the screenshot, --select-cells the surface cells ("Select Cells
On"); --selection-out lists what each rectangle selected, "points K ID" or
"cells K ID" per line (K counts each kind's rectangles from 0); on a composite
input "blockpoints K FLATINDEX ID".

--write-blocks splits the input's points into two point-only blocks (the
first half of the point ids, then the rest, with their point data) and writes
them as a multiblock .vtm (--second-without-tensors: the second block
without its tensor array); nothing is drawn. --merge-blocks shows ParaView's
Merge Blocks of the input instead of the input.

--set sets a property of the representation (a number, after the options
above), --view-set one of the view; --mask-array picks the point array the
glyphs' mask reads (TensorGlyphMask), --tensors the point array of tensors,
--color-by colours the display by a point array (ParaView's ColorBy);
without it the display is Solid Color (ParaView colours a new display by
the active scalars, which the glyphs would then follow), so that the glyphs
show their own colours (TensorGlyphColorMode); --color-by-cells colours by
a cell array NAME made from the point array (PointDatatoCellData). --lut-points sets the lookup
table's RGBPoints (RGB space, not discretised), --lut-range its range;
--rescale rescales it after the first screenshot and saves another to
--rescaled-output; --uploads-out writes the glyph record uploads after
each screenshot ("uploads K N"). --write-height writes the input with a
point array "height" (each point's y) added, for the CLI and pvbatch to
colour by; nothing is drawn. --representations-out writes the
representation types ParaView offers for the input ("offered NAME" per
line) and whether the input passes the glyphs' input domain ("in_domain 0|1").

--scalar-bar shows ParaView's scalar bar of the glyphs' colour legend (the
representation's TensorGlyphColorLegend* properties) on the right;
--legend-out writes that legend and the MD range of the input's tensors,
computed here on its own, one "KEY VALUES..." line each.
"""
import argparse
import math
import sys

from paraview import selection, servermanager, simple


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin")
    ap.add_argument("--input", required=True)
    ap.add_argument("--output")
    ap.add_argument("--write-blocks", metavar="VTM")
    ap.add_argument("--second-without-tensors", action="store_true")
    ap.add_argument("--merge-blocks", action="store_true")
    ap.add_argument("--size", type=int, nargs=2, default=[400, 300])
    ap.add_argument("--eye", type=float, nargs=3)
    ap.add_argument("--look-at", type=float, nargs=3)
    ap.add_argument("--up", type=float, nargs=3, default=[0, 1, 0])
    ap.add_argument("--fov", type=float, default=30.0)
    ap.add_argument("--glyph", type=int, default=0)
    ap.add_argument("--gamma", type=float, default=3.0)
    ap.add_argument("--scale-mode", type=int, default=2)
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--color", type=int, default=0)
    ap.add_argument("--slice-normal", type=float, nargs=3)
    ap.add_argument("--slice-origin", type=float, nargs=3)
    ap.add_argument("--no-glyphs", action="store_true")
    ap.add_argument("--redistribute", action="store_true",
                    help="spread the dataset's cells over the MPI ranks, each rank reading its own")
    ap.add_argument("--fxaa", action="store_true")
    ap.add_argument("--cell-tensors", action="store_true",
                    help="move the tensors to cell data (PointDatatoCellData) and pick that cell array")
    ap.add_argument("--multiblock", action="store_true", help="show the dataset as a block of a multiblock")
    ap.add_argument("--as-six", action="store_true",
                    help="give the tensors as 6 components in VTK's order XX YY ZZ XY YZ XZ")
    ap.add_argument("--nan-every", type=int, metavar="K",
                    help="set the first component of every K-th point's tensor to NaN")
    ap.add_argument("--select", type=int, nargs=4, action="append", default=[])
    ap.add_argument("--select-cells", type=int, nargs=4, action="append", default=[])
    ap.add_argument("--selection-out")
    ap.add_argument("--scalar-bar", action="store_true")
    ap.add_argument("--legend-out")
    ap.add_argument("--background", type=float, nargs=3, default=[0.08, 0.08, 0.10])
    ap.add_argument("--set", nargs=2, action="append", default=[], metavar=("PROPERTY", "VALUE"))
    ap.add_argument("--view-set", nargs=2, action="append", default=[], metavar=("PROPERTY", "VALUE"))
    ap.add_argument("--representations-out")
    ap.add_argument("--glyph-path-out", help="write the glyph path the frame drew on (TensorGlyphPath)")
    ap.add_argument("--mask-array")
    ap.add_argument("--tensors")
    ap.add_argument("--color-by")
    ap.add_argument("--color-by-cells", metavar="NAME",
                    help="give the point data as cell data too (PointDatatoCellData) and colour by cell array NAME")
    ap.add_argument("--lut-points", type=float, nargs="+")
    ap.add_argument("--lut-range", type=float, nargs=2)
    ap.add_argument("--rescale", type=float, nargs=2)
    ap.add_argument("--rescaled-output")
    ap.add_argument("--uploads-out")
    ap.add_argument("--write-height", metavar="VTU")
    a = ap.parse_args()
    if a.write_blocks:
        write_blocks(a.input, a.write_blocks, a.second_without_tensors)
        return
    if a.write_height:
        write_height(a.input, a.write_height)
        return
    if not a.plugin or not a.output:
        sys.exit("render_glyphs.py: --plugin and --output are required")

    simple.LoadPlugin(a.plugin, remote=False, ns=globals())
    reader = simple.OpenDataFile(a.input)
    if reader is None:
        sys.exit("render_glyphs.py: %s: ParaView has no reader for it" % a.input)
    if a.redistribute:
        reader = simple.ProgrammableFilter(Input=reader)
        reader.Script = "\n".join([
            "from vtkmodules.vtkCommonCore import vtkIdList",
            "from vtkmodules.vtkFiltersCore import vtkExtractCells",
            "from vtkmodules.vtkIOLegacy import vtkDataSetReader",
            "from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader",
            "from vtkmodules.vtkParallelCore import vtkMultiProcessController",
            "c = vtkMultiProcessController.GetGlobalController()",
            "rank, size = (c.GetLocalProcessId(), c.GetNumberOfProcesses()) if c else (0, 1)",
            "r = vtkDataSetReader() if %r.endswith('.vtk') else vtkXMLGenericDataObjectReader()" % a.input,
            "r.SetFileName(%r)" % a.input, "r.Update()", "d = r.GetOutput()", "n = d.GetNumberOfCells()",
            "ids = vtkIdList()",
            "for i in range(rank * n // size, (rank + 1) * n // size): ids.InsertNextId(i)",
            "e = vtkExtractCells()", "e.SetInputData(d)", "e.SetCellList(ids)", "e.Update()",
            "self.GetOutput().ShallowCopy(e.GetOutput())"])
    if a.as_six:
        reader = simple.ProgrammableFilter(Input=reader)
        reader.Script = "\n".join([
            "from vtkmodules.vtkCommonCore import vtkDoubleArray",
            "out = self.GetOutput()", "out.ShallowCopy(self.GetInput())",
            "t = out.GetPointData().GetTensors()", "s = vtkDoubleArray()", "s.SetName(t.GetName())",
            "s.SetNumberOfComponents(6)", "s.SetNumberOfTuples(t.GetNumberOfTuples())",
            "for i in range(t.GetNumberOfTuples()):",
            "    v = t.GetTuple9(i)",
            "    s.SetTuple6(i, v[0], v[4], v[8], v[1], v[5], v[2])",
            "out.GetPointData().SetTensors(s)"])
    if a.multiblock:
        reader = simple.GroupDatasets(Input=[reader])
    if a.merge_blocks:
        reader = simple.MergeBlocks(Input=reader)
        if hasattr(reader, "MergePoints"):
            reader.MergePoints = 0  # the blocks' points as they are, in block order
    if a.nan_every:
        reader = simple.ProgrammableFilter(Input=reader)
        reader.Script = "\n".join([
            "out = self.GetOutput()", "out.ShallowCopy(self.GetInput())",
            "t = out.GetPointData().GetTensors()", "c = t.NewInstance()", "c.DeepCopy(t)",
            "for i in range(0, c.GetNumberOfTuples(), %d):" % a.nan_every,
            "    c.SetComponent(i, 0, float('nan'))",
            "out.GetPointData().SetTensors(c)"])
    if a.cell_tensors:
        reader = simple.PointDatatoCellData(Input=reader)
        reader.PassPointData = 0
    if a.color_by_cells:
        reader = simple.PointDatatoCellData(Input=reader)
        reader.PassPointData = 1
    view = simple.CreateRenderView()
    view.ViewSize = a.size
    view.OrientationAxesVisibility = 0
    # FXAA (on in Debian's defaults) smooths edges after compositing; the
    # CLI's picture has none, and the comparison is pixel by pixel.
    view.UseFXAA = 1 if a.fxaa else 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = a.background
    for name, value in a.view_set:
        setattr(view, name, number(value))
    if not a.no_glyphs:
        disp = simple.Show(reader, view)
        # Before the glyphs update, as a user colours the surface first.
        if a.color_by_cells:
            simple.ColorBy(disp, ("CELLS", a.color_by_cells))
        elif a.color_by not in (None, "NONE"):
            simple.ColorBy(disp, ("POINTS", a.color_by))
        elif disp.ColorArrayName[1]:  # ColorBy None fails on a display coloured by nothing
            simple.ColorBy(disp, None)
        if a.color_by not in (None, "NONE"):
            lut = simple.GetColorTransferFunction(a.color_by)
            if a.lut_points:
                lut.ColorSpace = "RGB"
                lut.Discretize = 0
                lut.RGBPoints = a.lut_points
            if a.lut_range:
                lut.AutomaticRescaleRangeMode = "Never"
                lut.RescaleTransferFunction(a.lut_range[0], a.lut_range[1])
        disp.SetRepresentationType("Tensor Glyphs (ray cast)")
        disp.TensorGlyphKind = a.glyph
        disp.TensorGlyphGamma = a.gamma
        disp.TensorGlyphScaleMode = a.scale_mode
        disp.TensorGlyphScaleFactor = a.scale
        disp.TensorGlyphColorMode = a.color
        if a.tensors:
            disp.TensorGlyphTensors = ["POINTS", a.tensors]
        if a.mask_array:
            disp.TensorGlyphMask = ["POINTS", a.mask_array]
        for name, value in a.set:
            setattr(disp, name, number(value))
        if a.representations_out:
            write_representations(disp, reader, a.representations_out)
        if a.cell_tensors:
            names = [k for k in reader.CellData.keys() if reader.CellData[k].GetNumberOfComponents() in (6, 9)]
            disp.TensorGlyphTensors = ["CELLS", names[0]]
    if a.slice_normal:
        sl = simple.Slice(Input=reader)
        sl.SliceType = "Plane"
        sl.SliceType.Origin = a.slice_origin
        sl.SliceType.Normal = a.slice_normal
        sdisp = simple.Show(sl, view)
        sdisp.SetRepresentationType("Surface")
        simple.ColorBy(sdisp, None)
        sdisp.AmbientColor = sdisp.DiffuseColor = [0.9, 0.9, 0.9]
    # paraview.simple resets the camera on a view's first render: render
    # once, then place the camera.
    simple.Render(view)
    if a.eye:
        view.CameraPosition = a.eye
        view.CameraFocalPoint = a.look_at
        view.CameraViewUp = a.up
        view.CameraViewAngle = a.fov
    else:
        view.ResetCamera()
    simple.Render(view)
    if a.scalar_bar or a.legend_out:
        legend = show_legend(disp, view, a.scalar_bar)
        simple.Render(view)
    simple.SaveScreenshot(a.output, view, ImageResolution=a.size)
    uploads = [record_uploads(disp)] if a.uploads_out else []
    if a.rescale:
        lut = simple.GetColorTransferFunction(a.color_by)
        lut.AutomaticRescaleRangeMode = "Never"
        lut.RescaleTransferFunction(a.rescale[0], a.rescale[1])
        simple.Render(view)
        simple.SaveScreenshot(a.rescaled_output, view, ImageResolution=a.size)
        if a.uploads_out:
            uploads.append(record_uploads(disp))
    if a.uploads_out:
        with open(a.uploads_out, "w") as f:
            for k, n in enumerate(uploads):
                f.write("uploads %d %d\n" % (k, n))
    if a.glyph_path_out:
        disp.UpdatePropertyInformation()
        with open(a.glyph_path_out, "w") as f:
            f.write("glyph_path %s\n" % disp.GetPropertyValue("TensorGlyphPath"))
    if a.legend_out:
        legend["md_range_of_input"] = md_range(reader)
        with open(a.legend_out, "w") as f:
            for key, values in legend.items():
                if key != "title":
                    f.write(" ".join([key] + ["%.17g" % v for v in values]) + "\n")
    if a.select or a.select_cells:
        with open(a.selection_out, "w") as f:
            for kind, rects in (("points", a.select), ("cells", a.select_cells)):
                for k, rect in enumerate(rects):
                    for flat, pid in select_ids(reader, view, rect, kind):
                        if flat is None:
                            f.write("%s %d %d\n" % (kind, k, pid))
                        else:
                            f.write("block%s %d %d %d\n" % (kind, k, flat, pid))


def number(text):
    """An int where the text is one, else a float ("nan" too)."""
    try:
        return int(text)
    except ValueError:
        return float(text)


def write_representations(disp, source, path):
    """The representation types offered for the input, and whether the input
    passes the glyph representation's own input domain ("input_array")."""
    glyphs = servermanager.ProxyManager().SMProxyManager.NewProxy(
        "representations", "TensorGlyphRayCastRepresentation")
    domain = glyphs.GetProperty("Input").GetDomain("input_array")
    with open(path, "w") as f:
        for name in disp.Representation.Available:
            f.write("offered %s\n" % name)
        f.write("in_domain %d\n" % domain.IsInDomain(source.SMProxy, 0))
    glyphs.UnRegister(None)


def show_legend(disp, view, visible):
    """ParaView's lookup table and scalar bar for the glyphs' colours: what a
    user does in the Python shell to label the glyphs."""
    disp.UpdatePropertyInformation()
    # Information properties: read with GetPropertyValue.
    title = disp.GetPropertyValue("TensorGlyphColorLegendTitle")
    points = list(disp.GetPropertyValue("TensorGlyphColorLegendRGBPoints"))
    legend = {"title": title, "range": list(disp.GetPropertyValue("TensorGlyphColorLegendRange")),
              "rgb_points": points}
    if not title:
        return legend
    lut = simple.GetColorTransferFunction(title)
    lut.ColorSpace = "RGB"
    lut.Discretize = 0
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RGBPoints = points
    lut.ScalarRangeInitialized = 1
    bar = simple.GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = [0.8, 0.1]
    bar.ScalarBarLength = 0.8
    bar.DrawTickMarks = 0
    bar.DrawTickLabels = 0
    bar.Visibility = 1 if visible else 0
    legend["lut_range"] = [lut.RGBPoints[0], lut.RGBPoints[-4]]
    return legend


def md_range(reader):
    """The input's mean diffusivity (trace / 3) range over points with finite
    tensors: the range the MD colour mode must map."""
    data = servermanager.Fetch(reader)
    tensors = data.GetPointData().GetTensors()
    if tensors is None:
        sys.exit("render_glyphs.py: the input has no active point tensors")
    nc = tensors.GetNumberOfComponents()
    lo, hi = math.inf, -math.inf
    for i in range(tensors.GetNumberOfTuples()):
        t = tensors.GetTuple(i)
        if not all(math.isfinite(v) for v in t):
            continue
        md = (t[0] + t[4] + t[8]) / 3.0 if nc == 9 else (t[0] + t[1] + t[2]) / 3.0
        lo, hi = min(lo, md), max(hi, md)
    return [lo, hi]


def select_ids(source, view, rect, kind):
    """The point or cell ids ParaView's surface selection in `rect` yields."""
    simple.ClearSelection(source)
    if kind == "points":
        selection.SelectSurfacePoints(Rectangle=rect, View=view)
    else:
        selection.SelectSurfaceCells(Rectangle=rect, View=view)
    ids = []
    found = source.SMProxy.GetSelectionInput(0)
    if found is None:
        return ids
    app = servermanager._getPyProxy(found)
    for node in (app.Input if app.GetXMLName() == "AppendSelections" else [app]):
        if node.FieldType != kind[:-1].upper():
            sys.exit("render_glyphs.py: unexpected selection of %s" % node.FieldType)
        v = list(node.IDs)
        if node.GetXMLName() == "IDSelectionSource":
            ids += [(None, i) for i in v[1::2]]  # (process, id) pairs
        elif node.GetXMLName() == "CompositeDataIDSelectionSource":
            ids += list(zip(v[0::3], v[2::3]))  # (flat index, process, id) triples
        else:
            sys.exit("render_glyphs.py: unexpected selection %s" % node.GetXMLName())
    return sorted(set(ids), key=lambda t: (-1 if t[0] is None else t[0], t[1]))


def record_uploads(disp):
    """How many times the glyph records went to the GPU."""
    disp.UpdatePropertyInformation()
    return int(disp.GetPropertyValue("TensorGlyphRecordUploads"))


def write_height(path, out):
    """The input with a point array "height" (each point's y) added."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    data = servermanager.Fetch(simple.OpenDataFile(path))
    h = vtkDoubleArray()
    h.SetName("height")
    h.SetNumberOfTuples(data.GetNumberOfPoints())
    for i in range(data.GetNumberOfPoints()):
        h.SetValue(i, data.GetPoint(i)[1])
    data.GetPointData().AddArray(h)
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(out)
    w.SetInputData(data)
    # Inline, not appended: ParaView 5.11 cannot read appended XML data back
    # under Debian 12's current libexpat1 (tests/paraview/legacy_copy.py).
    w.SetDataModeToBinary()
    if not w.Write():
        sys.exit("render_glyphs.py: %s: could not be written" % out)


def write_blocks(path, vtm, second_without_tensors=False):
    """The input's points split in two point-only blocks, written as a .vtm."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter
    data = servermanager.Fetch(simple.OpenDataFile(path))
    n = data.GetNumberOfPoints()
    blocks = vtkMultiBlockDataSet()
    for b, (lo, hi) in enumerate(((0, n // 2), (n // 2, n))):
        part = vtkPolyData()
        pts = vtkPoints()
        pts.SetDataType(data.GetPoints().GetDataType())
        part.GetPointData().CopyAllocate(data.GetPointData(), hi - lo)
        for i in range(lo, hi):
            pts.InsertNextPoint(data.GetPoint(i))
            part.GetPointData().CopyData(data.GetPointData(), i, i - lo)
        part.SetPoints(pts)
        tensors = part.GetPointData().GetTensors()
        if b == 1 and second_without_tensors and tensors is not None:
            part.GetPointData().RemoveArray(tensors.GetName())
        blocks.SetBlock(b, part)
    w = vtkXMLMultiBlockDataWriter()
    w.SetFileName(vtm)
    w.SetInputData(blocks)
    w.SetDataModeToBinary()  # inline, as write_height
    if not w.Write():
        sys.exit("render_glyphs.py: %s: could not be written" % vtm)


if __name__ == "__main__":
    main()
